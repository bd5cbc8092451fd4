/* LGF_SawToothCI: its interface (modelDescription/LGF_SawToothCI.xml is generated from it),
 * the table every signal generator shares (iec/signal_generator.h). */
#include "blocks/LGF_SawToothCI/block.c"

LGF_SIGNAL_MODEL(lgf_saw_tooth_ci, "LGF_SawToothCI", "{36dd6a91-9d54-4924-a094-36d4b44335b8}",
                 "Siemens LGF_SawToothCI (LGF V5.1, block V3.0.x): a periodic sawtooth, from "
                 "-amplitude up to +amplitude over a period, on the cyclic-interrupt grid in "
                 "float32 as on the PLC. One PLC call every cycleTime.");
