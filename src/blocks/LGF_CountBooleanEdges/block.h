/* LGF_CountBooleanEdges: counts the rising edges of trigger within a monitoring time and
 * classifies them as single, double, long or several edges (docs/behaviour.md §12). */
#ifndef LGF_COUNT_BOOLEAN_EDGES_H
#define LGF_COUNT_BOOLEAN_EDGES_H

#include <stddef.h>

#include "iec/iec.h"
#include "iec/timer.h"

typedef struct {
    /* inputs */
    bool trigger;
    iec_time monitorTime;
    /* outputs (double and long are C keywords, hence the underscores) */
    bool single_;
    bool double_;
    bool long_;
    bool severalEdges;
    uint8_t noOfEdges; /* USINT */
    /* statics */
    bool triggerPrevious; /* the edge memory, FALSE before the first call */
    bool resultShown;     /* a result has been shown since the count was last cleared */
    uint8_t edges;        /* USINT: the edges counted */
    iec_timer statTimer;  /* the TP of the monitoring time (docs/behaviour.md §1.12) */
} lgf_count_boolean_edges;

#endif
