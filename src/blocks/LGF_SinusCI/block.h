/* LGF_SinusCI: a sine of amplitude around offset (docs/behaviour.md §6). */
#ifndef LGF_SINUS_CI_H
#define LGF_SINUS_CI_H

#include "iec/signal_generator.h"

#endif
