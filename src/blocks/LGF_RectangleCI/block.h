/* LGF_RectangleCI: a periodic rectangle: offset + amplitude for half a period, then offset -
 * amplitude (docs/behaviour.md §6). */
#ifndef LGF_RECTANGLE_CI_H
#define LGF_RECTANGLE_CI_H

#include "iec/signal_generator.h"

#endif
