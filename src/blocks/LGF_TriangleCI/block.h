/* LGF_TriangleCI: a periodic triangle between -amplitude and +amplitude (docs/behaviour.md
 * §6). */
#ifndef LGF_TRIANGLE_CI_H
#define LGF_TRIANGLE_CI_H

#include "iec/signal_generator.h"

#endif
