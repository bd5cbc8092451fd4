/* LGF_PulseRelay: an impulse relay / toggle flip-flop with set and reset (docs/behaviour.md
 * §11). */
#ifndef LGF_PULSE_RELAY_H
#define LGF_PULSE_RELAY_H

#include "iec/iec.h"

typedef struct {
    /* inputs */
    bool trigger;
    bool set;
    bool reset;
    /* output */
    bool out;
    /* statics: the relay's state and the edge memories, all FALSE before the first call */
    bool statOut;
    bool triggerOld;
    bool setOld;
    bool resetOld;
} lgf_pulse_relay;

#endif
