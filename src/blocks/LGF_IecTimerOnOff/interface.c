/* LGF_IecTimerOnOff: its interface table (modelDescription/LGF_IecTimerOnOff.xml is generated
 * from it). */
#include "blocks/LGF_IecTimerOnOff/block.c"
#include "core/model.h"

typedef lgf_iec_timer_on_off block;

static const model_variable variables[] = {
    OB_CYCLE_TIME_ROW,
    BOOL_INPUT(1, in, "Input signal to delay (LGF default FALSE, FMU start TRUE)"),
    TIME_INPUT(2, timeOnDelay,
               "TIME: on delay, rounded to whole ms; taken at each rising edge of in, a "
               "negative value acts as 0 (LGF default T#0s, FMU start 0.1 s)"),
    TIME_INPUT(3, timeOffDelay,
               "TIME: off delay, rounded to whole ms; taken when the on-delayed signal "
               "falls, a negative value acts as 0 (LGF default T#0s, FMU start 0.2 s)"),
    BOOL_OUTPUT(4, out,
                "Delayed input signal: TRUE timeOnDelay after in rises, FALSE timeOffDelay "
                "after it falls"),
};

BLOCK_FUNCTIONS(lgf_iec_timer_on_off)

BLOCK_CHECK(lgf_iec_timer_on_off)

static const model_static statics[] = {
    TIMER_STATICS(statTon),
    TIMER_STATICS(statTof),
};

BLOCK_MODEL("LGF_IecTimerOnOff", "{7a119cc3-6235-4d1e-b036-1f1d24c5f83d}", 3,
            "Siemens LGF_IecTimerOnOff (Library of General Functions): an IEC TON followed by an "
            "IEC TOF, so out follows in with an on delay and an off delay. One PLC call "
            "every cycleTime. Start values differ from the LGF defaults (FALSE, T#0s, T#0s) "
            "so that the FMU shows the on delay at once: out TRUE from 0.1 s on.",
            BLOCK_STATICS, NO_CYCLE_CODES, .check = check);
