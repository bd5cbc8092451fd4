/* LGF_SawToothCI: a periodic sawtooth: rises from -amplitude to +amplitude over periode, then
 * falls back (docs/behaviour.md §6). */
#ifndef LGF_SAW_TOOTH_CI_H
#define LGF_SAW_TOOTH_CI_H

#include "iec/signal_generator.h"

static void lgf_saw_tooth_ci_call(lgf_signal *block, const plc_call *call);

#endif
