#include "blocks/LGF_PulseRelay/block.h"

#include <string.h>

static void lgf_pulse_relay_init(lgf_pulse_relay *block)
{
    /* The LGF defaults: every input FALSE (docs/behaviour.md §11.1: with no input connected no
     * start value could make the output move after the first call). */
    memset(block, 0, sizeof *block);
}

static void lgf_pulse_relay_call(lgf_pulse_relay *block, const plc_call *call)
{
    (void)call; /* the block has no time of its own */
    /* docs/behaviour.md §11.2, in this order, so that reset wins over set and set over
     * trigger when they rise in the same call. */
    if (iec_rising_edge(&block->triggerOld, block->trigger)) block->statOut = !block->statOut;
    if (iec_rising_edge(&block->setOld, block->set)) block->statOut = true;
    if (iec_rising_edge(&block->resetOld, block->reset)) block->statOut = false;
    block->out = block->statOut;
}
