/* LGF_CosinusCI: a cosine of amplitude around offset (docs/behaviour.md §6). */
#ifndef LGF_COSINUS_CI_H
#define LGF_COSINUS_CI_H

#include "iec/signal_generator.h"

#endif
