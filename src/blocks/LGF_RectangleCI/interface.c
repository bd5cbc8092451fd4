/* LGF_RectangleCI: its interface (modelDescription/LGF_RectangleCI.xml is generated from it),
 * the table every signal generator shares (iec/signal_generator.h). */
#include "blocks/LGF_RectangleCI/block.c"

LGF_SIGNAL_MODEL(lgf_rectangle_ci, "LGF_RectangleCI", "{3eced841-79b6-4d0e-b42c-eec47fe8a2e0}",
                 "Siemens LGF_RectangleCI (LGF V5.1, block V3.0.x): a periodic rectangle, offset +"
                 " amplitude for half a period, then offset - amplitude, on the cyclic-interrupt "
                 "grid in float32 as on the PLC. One PLC call every cycleTime.");
