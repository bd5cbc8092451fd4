/* LGF_CosinusCI: a cosine of amplitude around offset (docs/behaviour.md §6). */
#ifndef LGF_COSINUS_CI_H
#define LGF_COSINUS_CI_H

#include "iec/signal_generator.h"

static void lgf_cosinus_ci_call(lgf_signal *block, const plc_call *call);

#endif
