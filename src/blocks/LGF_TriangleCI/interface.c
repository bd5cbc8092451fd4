/* LGF_TriangleCI: its interface (modelDescription/LGF_TriangleCI.xml is generated from it),
 * the table every signal generator shares (iec/signal_generator.h). */
#include "blocks/LGF_TriangleCI/block.c"

LGF_SIGNAL_MODEL(lgf_triangle_ci, "LGF_TriangleCI", "{1be13078-b503-4b1e-8e2a-f0280090b795}",
                 "Siemens LGF_TriangleCI (LGF V5.1, block V3.0.x): a periodic triangle between "
                 "-amplitude and +amplitude, on the cyclic-interrupt grid in float32 as on the "
                 "PLC. One PLC call every cycleTime.");
