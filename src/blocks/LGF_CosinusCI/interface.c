/* LGF_CosinusCI: its interface (modelDescription/LGF_CosinusCI.xml is generated from it),
 * the table every signal generator shares (iec/signal_generator.h). */
#include "blocks/LGF_CosinusCI/block.c"

LGF_SIGNAL_MODEL(lgf_cosinus_ci, "LGF_CosinusCI", "{e49bfd2b-acaa-4222-a21d-f08cec9b9d4a}",
                 "Siemens LGF_CosinusCI (LGF V5.1, block V3.0.x): a cosine of amplitude around "
                 "offset, on the cyclic-interrupt grid in float32 as on the PLC. One PLC call "
                 "every cycleTime.");
