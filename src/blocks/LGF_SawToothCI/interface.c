/* LGF_SawToothCI: its interface (modelDescription/LGF_SawToothCI.xml is generated from it),
 * the table every signal generator shares (iec/signal_generator.h). */
#include "blocks/LGF_SawToothCI/block.c"

BLOCK_CALL(lgf_saw_tooth_ci)

static const model lgf_model = {
    .identifier = "LGF_SawToothCI",
    .guid = "{36dd6a91-9d54-4924-a094-36d4b44335b8}",
    .description = "Siemens LGF_SawToothCI (LGF V5.1, block V3.0.x): a periodic sawtooth, from "
                   "-amplitude up to +amplitude over a period, on the cyclic-interrupt grid in "
                   "float32 as on the PLC. One PLC call every cycleTime.",
    .call = call,
    LGF_SIGNAL_MODEL,
};
