/* LGF_SawToothCI: a periodic sawtooth: rises from -amplitude to +amplitude over periode, then
 * falls back (docs/behaviour.md §6). */
#ifndef LGF_SAW_TOOTH_CI_H
#define LGF_SAW_TOOTH_CI_H

#include "iec/signal_generator.h"

#endif
