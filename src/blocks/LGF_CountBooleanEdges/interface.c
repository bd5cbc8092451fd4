/* LGF_CountBooleanEdges: its interface table (modelDescription/LGF_CountBooleanEdges.xml is
 * generated from it) and statics. */
#include "blocks/LGF_CountBooleanEdges/block.c"
#include "core/model.h"

typedef lgf_count_boolean_edges block;

static const model_variable variables[] = {
    OB_CYCLE_TIME_ROW,
    BOOL_INPUT(1, trigger,
               "Signal whose rising edges are counted; LGF default FALSE, FMU start TRUE"),
    TIME_INPUT(2, monitorTime,
               "TIME: time to monitor and count edges, started by the first edge (an S7 "
               "TP: taken at that edge; negative counts as 0), rounded to whole ms; LGF "
               "default T#0s, FMU start 0.7 s"),
    NAMED_ROW(3, "single", single_, VAR_BOOL, ROLE_OUTPUT, 0, 1,
              "One edge in the monitoring time, trigger FALSE at its end"),
    NAMED_ROW(4, "double", double_, VAR_BOOL, ROLE_OUTPUT, 0, 1,
              "Two edges in the monitoring time"),
    NAMED_ROW(5, "long", long_, VAR_BOOL, ROLE_OUTPUT, 0, 1,
              "One edge in the monitoring time, trigger still TRUE at its end"),
    BOOL_OUTPUT(6, severalEdges, "Three or more edges in the monitoring time"),
    ROW(7, noOfEdges, VAR_USINT, ROLE_OUTPUT, 0, 255,
        "USINT: number of edges in the monitoring time, while a result is shown "
        "(else 0); the count wraps from 255 to 0"),
};

BLOCK_FUNCTIONS(lgf_count_boolean_edges)

BLOCK_CHECK(lgf_count_boolean_edges)

static const model_static statics[] = {
    STATIC(block, triggerPrevious, FIELD_BOOL),
    STATIC(block, resultShown, FIELD_BOOL),
    STATIC(block, edges, FIELD_UINT8),
    TIMER_STATICS(statTimer),
};

BLOCK_MODEL("LGF_CountBooleanEdges", "{4a4269b5-014b-4355-8fee-ab20209596b5}", 3,
            "Siemens LGF_CountBooleanEdges (LGF V5.1, block V1.0.0): counts the rising "
            "edges of trigger within monitorTime from the first edge and shows single, "
            "double, long (one edge, trigger held) or severalEdges when the time is over. "
            "One PLC call every cycleTime. Start values: trigger TRUE, monitorTime 0.7 s, "
            "so long is TRUE from 0.7 s.",
            BLOCK_STATICS, NO_CYCLE_CODES, .check = check);
