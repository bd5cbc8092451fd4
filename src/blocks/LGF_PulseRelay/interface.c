/* LGF_PulseRelay: its interface table (modelDescription/LGF_PulseRelay.xml is generated from
 * it) and statics. */
#include "blocks/LGF_PulseRelay/block.c"
#include "core/model.h"

typedef lgf_pulse_relay block;

static const model_variable variables[] = {
    OB_CYCLE_TIME_ROW,
    BOOL_INPUT(1, trigger, "Rising edge: invert out (toggle); LGF default FALSE, FMU start FALSE"),
    BOOL_INPUT(2, set,
               "Rising edge: out := TRUE (prior to trigger); LGF default FALSE, FMU start "
               "FALSE"),
    BOOL_INPUT(3, reset,
               "Rising edge: out := FALSE (prior to set and trigger); LGF default FALSE, "
               "FMU start FALSE"),
    BOOL_OUTPUT(4, out, "Output signal: the state of the relay"),
};

BLOCK_FUNCTIONS(lgf_pulse_relay)

static const model_static statics[] = {
    STATIC(block, statOut, FIELD_BOOL),
    STATIC(block, triggerOld, FIELD_BOOL),
    STATIC(block, setOld, FIELD_BOOL),
    STATIC(block, resetOld, FIELD_BOOL),
};

BLOCK_MODEL("LGF_PulseRelay", "{a7bc6531-037e-4ba1-bce7-ac6903c6df9b}", 10,
            "Siemens LGF_PulseRelay (LGF V5.1, block V3.0.1): impulse relay / toggle "
            "flip-flop; each rising edge of trigger inverts out, a rising edge of set "
            "sets it, a rising edge of reset resets it (reset before set before "
            "trigger). One PLC call every cycleTime. Start values: the LGF defaults.",
            BLOCK_STATICS, NO_CYCLE_CODES);
