/* LGF_SinusCI: its interface (modelDescription/LGF_SinusCI.xml is generated from it),
 * the table every signal generator shares (iec/signal_generator.h). */
#include "blocks/LGF_SinusCI/block.c"

LGF_SIGNAL_MODEL(lgf_sinus_ci, "LGF_SinusCI", "{cadea0a8-ec1b-4c69-9f5c-f8350a81d023}",
                 "Siemens LGF_SinusCI (LGF V5.1, block V3.0.x): a sine of amplitude around offset,"
                 " on the cyclic-interrupt grid in float32 as on the PLC. One PLC call every "
                 "cycleTime.");
