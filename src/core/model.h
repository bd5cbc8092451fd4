/* What a block tells the core and the FMI front-ends about itself: its interface table (the
 * names, value references, types, causalities, variabilities, ranges, units and descriptions of
 * its variables, from which modelDescription/<Block>.xml is generated, start values coming from
 * the block's own init), its statics, its data and its call. A block's interface.c fills one
 * `lgf_model`: a bundled block's is written from its interface.toml, the one place its
 * interface is described (tools/interface.py), a compiled block's by the SCL compiler. No FMI
 * types appear here.
 *
 * An FMU is one translation unit: interface.c includes its block's C file and defines
 * `lgf_model`; the FMU's source file then includes it and a front-end (fmi2/fmi2.c or
 * fmi3/fmi3.c). So every symbol but the FMI entry points (fmi2* or fmi3*) is static, and several
 * source-code FMUs link into one program (docs/behaviour.md §1.10). */
#ifndef LGF_MODEL_H
#define LGF_MODEL_H

#include <math.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "iec/iec.h"

/* Storage in the block and how FMI sees it (docs/behaviour.md §1.4, §7): the FMI 2.0 type, then
 * the FMI 3.0 one. */
typedef enum {
    VAR_CYCLE, /* the layer's call period: Real / Float64 s <-> whole µs (docs/behaviour.md §1.1) */
    VAR_LREAL, /* double   <-> Real / Float64 */
    VAR_TIME,  /* iec_time <-> Real / Float64 seconds, rounded to the nearest ms */
    VAR_INT,   /* iec_int  <-> Integer / Int16 */
    VAR_WORD,  /* iec_word <-> Integer / UInt16 */
    VAR_REAL,  /* float    <-> Real / Float32: the nearest float32 is stored; ±Inf allowed */
    VAR_UDINT, /* uint32_t <-> Integer / UInt32 (FMI 2.0: up to 2147483647) */
    VAR_DINT,  /* int32_t  <-> Integer / Int32 */
    VAR_UINT,  /* uint16_t <-> Integer / UInt16 */
    VAR_SINT,  /* int8_t   <-> Integer / Int8 */
    VAR_USINT, /* uint8_t  <-> Integer / UInt8 */
    VAR_BYTE,  /* uint8_t  <-> Integer / UInt8 (a bit string: 16#.. in texts) */
    VAR_DWORD, /* uint32_t <-> Integer / UInt32 (FMI 2.0: up to 2147483647, as UDINT) */
    /* core_string <-> String / String in UTF-8: S7's STRING[max] (characters 0 to 255) and
     * WSTRING[max] (0 to 16#FFFF), max the row's .max; compiled SCL only (docs/scl.md §3.1) */
    VAR_STRING,
    VAR_WSTRING,
    VAR_BOOL /* bool     <-> Boolean / Boolean; the last, as it sizes the type tables */
} var_type;

/* A STRING or WSTRING as S7 lays it out: its maximum length, its current length, its
 * characters (a STRING's in the low byte); the layout of the SCL runtime's scl_string. */
#define CORE_STRING_CAPACITY 254
typedef struct {
    uint16_t max;
    uint16_t len;
    uint16_t data[CORE_STRING_CAPACITY];
} core_string;

static inline bool var_is_string(var_type t) { return t == VAR_STRING || t == VAR_WSTRING; }

/* The PLC's integers and bit strings: an FMI 2.0 Integer, an FMI 3.0 integer of their own width. */
static inline bool var_is_integer(var_type t)
{
    return t == VAR_INT || t == VAR_WORD || t == VAR_UDINT || t == VAR_DINT || t == VAR_UINT ||
           t == VAR_SINT || t == VAR_USINT || t == VAR_BYTE || t == VAR_DWORD;
}

typedef enum {
    ROLE_FIXED_PARAMETER,   /* settable until ExitInitializationMode (fmi2 or fmi3) */
    ROLE_TUNABLE_PARAMETER, /* settable at any time */
    ROLE_INPUT,
    ROLE_OUTPUT, /* never settable */
    /* a static of the block, visible for debugging (FMI causality local): read like an output,
     * never settable; no bundled block has one, the SCL compiler's blocks do (docs/scl.md §4) */
    ROLE_LOCAL
} var_role;

/* Whether the block computes the variable: an output or a local, which the importer reads and
 * never sets, and which has no start value. */
static inline bool var_is_computed(var_role role)
{
    return role == ROLE_OUTPUT || role == ROLE_LOCAL;
}

typedef struct {
    uint32_t vr;        /* value reference; an array uses vr ... vr + count - 1 */
    const char *name;   /* FMI name, or for an array the part before "[i]" */
    const char *member; /* for an array the part after "[i]", else NULL */
    var_type type;
    var_role role;
    size_t offset;   /* in the block's data (none for VAR_CYCLE: CYCLE_TIME_ROW) */
    uint32_t count;  /* 1, or the array length */
    size_t stride;   /* bytes from one array element to the next */
    double min, max; /* allowed values in FMI units */
    /* For an array, "{i}" stands for the element's index and "{i+1}" for the next one. */
    const char *description;
    const char *unit;     /* NULL: "s" for TIME and the cycle, none otherwise */
    const char *original; /* the name in TIA Portal where it differs, or why there is none */
} model_variable;

/* How a value is written into a serialized FMU state: little endian, at an offset aligned to
 * its size (docs/behaviour.md §1.9: field by field, not a memory dump). */
typedef enum {
    FIELD_BOOL, /* one byte, 0 or 1 */
    FIELD_INT8,
    FIELD_UINT8,
    FIELD_INT16,
    FIELD_UINT16,
    FIELD_INT32,
    FIELD_UINT32,
    FIELD_FLOAT32, /* an IEEE single */
    FIELD_INT64,
    FIELD_REAL,  /* an IEEE double; NaN is refused on restore, as no run produces it */
    FIELD_RESULT /* an IEEE double the block computes from LREAL inputs, where ±Inf can give NaN */
} field_type;

/* A static of the block (memory that is neither a parameter, an input nor an output). */
typedef struct {
    const char *name;
    field_type type;
    size_t offset;
} model_static;

typedef struct {
    const char *identifier; /* modelIdentifier */
    const char *guid;
    const char *description;
    double stop_time; /* of the default experiment: long enough to show the block working */
    const model_variable *variables;
    size_t variable_count;
    const model_static *statics;
    size_t static_count;
    size_t data_size;
    /* The PLC truncates the period to this many µs (LGF_RampCI counts whole ms); a period that
     * is not a multiple is accepted with a warning (docs/behaviour.md §4.2). */
    int32_t cycle_granularity_us;
    /* What the original reports for an invalid cycle period, named when cycleTime is refused
     * (docs/behaviour.md §1.7); NULL for a block without such codes. */
    const char *cycle_codes;
    void (*init)(void *data);                       /* start values, statics cleared */
    void (*call)(void *data, const plc_call *call); /* one PLC call */
    /* Rules that involve more than one variable or the statics. Returns NULL when the data is
     * valid, else writes one sentence naming the variable and the allowed values into msg. */
    const char *(*check)(const void *data, char *msg, size_t size);
    /* Rules on the statics alone (what every call leaves behind), in the form of check: no set
     * can break them, as no static is settable, so they are checked on a restored state only,
     * not on every set (run by each set, LGF_FloatingAverage's made its sets cost 1.5-2x those
     * of a block without a check). */
    const char *(*state_check)(const void *data, char *msg, size_t size);
    /* Whether the last call failed, in the form of check: NULL when it did not, else one
     * sentence saying why in msg. A failed call ends the step or event with an error, and the
     * instance is then in the error state (FMI 2.0 2.1.3, FMI 3.0 2.2.3). Only the SCL
     * compiler's blocks fail a call (its cycle watchdog, docs/scl.md §4); NULL for the bundled
     * blocks, whose calls cannot fail. */
    const char *(*fault)(const void *data, char *msg, size_t size);
    /* The block's `status` output and the meaning of its error codes, for the log. */
    iec_word (*status)(const void *data);
    const char *(*status_text)(iec_word status);
} model;

/* FMI 3.0 declares the independent variable, time, under this value reference (no block's
 * table uses it). */
#define TIME_VR 1000000u

/* Where a scalar variable lives in the block's data, for a designated initializer. */
#define AT(block_, field_) .offset = offsetof(block_, field_), .count = 1

/* The row of the parameter cycleTime (docs/behaviour.md §1.1), value reference 0: it lives in the
 * clock, not in the block's data, so it has no offset; 1 µs or 1 ms (min_, in s) up to 60 s. */
#define CYCLE_TIME_ROW(min_, original_, description_)                                              \
    {.vr = 0,                                                                                      \
     .name = "cycleTime",                                                                          \
     .type = VAR_CYCLE,                                                                            \
     .role = ROLE_FIXED_PARAMETER,                                                                 \
     .count = 1,                                                                                   \
     .min = (min_),                                                                                \
     .max = 60.0,                                                                                  \
     .original = (original_),                                                                      \
     .description = (description_)}

/* The cycleTime rows that blocks share: of a block called by any OB once per cycle (which uses
 * its cycle, or does not), and of a cyclic-interrupt block whose cycle replaces callOB. */
#define OB_CYCLE_TIME_ROW                                                                          \
    CYCLE_TIME_ROW(1e-6, "none: the period of the calling OB",                                     \
                   "Period of the calling OB: the block is called once per cycleTime; held "       \
                   "in whole µs, 1 µs to 60 s")
#define OB_CYCLE_TIME_ROW_UNUSED                                                                   \
    CYCLE_TIME_ROW(1e-6, "none: the period of the calling OB",                                     \
                   "Period of the calling OB: the block is called once per cycleTime (it does "    \
                   "not use its cycle); held in whole µs, 1 µs to 60 s")
#define CI_CYCLE_TIME_ROW                                                                          \
    CYCLE_TIME_ROW(1e-6, "none: replaces callOB",                                                  \
                   "Period of the calling cyclic-interrupt OB (replaces callOB); held in whole "   \
                   "µs, 1 µs to 60 s")

#define STATIC(block_, field_, type_) {#field_, (type_), offsetof(block_, field_)}

/* ---- the vocabulary of a block's interface.c ----
 *
 * tools/interface.py writes each bundled block's interface.c from its interface.toml with the
 * macros below (docs/developing.md, Adding a block), and the SCL compiler its blocks' with some
 * of them: they read the names an interface.c defines by convention, `block` (the typedef of its
 * struct), `variables`, `statics`, `init` and `call`. */

/* The core sees a block's data as void *, a block's init and call take its struct: these shims
 * convert, for the block whose functions are prefix_##_init and prefix_##_call. A block whose
 * init the model takes from elsewhere (the signal generators' lgf_signal_init_data) has the
 * call's alone. */
#define BLOCK_CALL(prefix_)                                                                        \
    static void call(void *data, const plc_call *plc) { prefix_##_call(data, plc); }
#define BLOCK_FUNCTIONS(prefix_)                                                                   \
    static void init(void *data) { prefix_##_init(data); }                                         \
    BLOCK_CALL(prefix_)

/* model.status and model.status_text of a block with a WORD output `status`: its error codes
 * and their texts for the log, as STATUS_TEXT rows; any other code is normal operation, which the
 * log does not name (BLOCK_STATUS() for a block without error codes). texts[0] only lets the list
 * be empty. */
typedef struct {
    iec_word code;
    const char *text;
} model_status_text;
#define STATUS_TEXT(code_, text_) {(code_), (text_)}
#define BLOCK_STATUS(...)                                                                          \
    static iec_word status(const void *data) { return ((const block *)data)->status; }             \
    static const char *status_text(iec_word code)                                                  \
    {                                                                                              \
        static const model_status_text texts[] = {{0, NULL}, __VA_ARGS__};                         \
        for (size_t i = 1; i < sizeof texts / sizeof texts[0]; i++)                                \
            if (texts[i].code == code) return texts[i].text;                                       \
        return NULL;                                                                               \
    }

/* A row of the interface table: its value reference, FMI name, field in the block's struct,
 * type, causality and range in FMI units, then its description, after which any other field
 * the row sets follows as a designated initializer (.unit = "1/s", .original = "..."). */
#define NAMED_ROW(vr_, name_, field_, type_, role_, min_, max_, ...)                               \
    {.vr = (vr_),                                                                                  \
     .name = (name_),                                                                              \
     .type = (type_),                                                                              \
     .role = (role_),                                                                              \
     AT(block, field_),                                                                            \
     .min = (min_),                                                                                \
     .max = (max_),                                                                                \
     .description = __VA_ARGS__}
/* The row whose FMI name is its field's (configuration.disableLimits too): NAMED_ROW for a name
 * the field cannot have (a C keyword: single, continue). Below, such rows of a type's whole
 * range for each type and causality that a block uses. */
#define ROW(vr_, field_, type_, role_, min_, max_, ...)                                            \
    NAMED_ROW(vr_, #field_, field_, type_, role_, min_, max_, __VA_ARGS__)
#define BOOL_INPUT(vr_, field_, ...) ROW(vr_, field_, VAR_BOOL, ROLE_INPUT, 0, 1, __VA_ARGS__)
#define BOOL_OUTPUT(vr_, field_, ...) ROW(vr_, field_, VAR_BOOL, ROLE_OUTPUT, 0, 1, __VA_ARGS__)
#define INT_INPUT(vr_, field_, ...)                                                                \
    ROW(vr_, field_, VAR_INT, ROLE_INPUT, -32768, 32767, __VA_ARGS__)
#define INT_OUTPUT(vr_, field_, ...)                                                               \
    ROW(vr_, field_, VAR_INT, ROLE_OUTPUT, -32768, 32767, __VA_ARGS__)
#define LREAL_INPUT(vr_, field_, ...)                                                              \
    ROW(vr_, field_, VAR_LREAL, ROLE_INPUT, -INFINITY, INFINITY, __VA_ARGS__)
#define LREAL_OUTPUT(vr_, field_, ...)                                                             \
    ROW(vr_, field_, VAR_LREAL, ROLE_OUTPUT, -INFINITY, INFINITY, __VA_ARGS__)
/* REAL: the nearest float32 of the value set is stored */
#define REAL_INPUT(vr_, field_, ...)                                                               \
    ROW(vr_, field_, VAR_REAL, ROLE_INPUT, -INFINITY, INFINITY, __VA_ARGS__)
/* TIME: a signed 32-bit number of ms, in s: an input is set within ±2147483.647 (docs/
 * behaviour.md §1.4), an output may reach T#-24D_20H_31M_23S_648MS as well. */
#define TIME_MAX_S 2147483.647
#define TIME_INPUT(vr_, field_, ...)                                                               \
    ROW(vr_, field_, VAR_TIME, ROLE_INPUT, -TIME_MAX_S, TIME_MAX_S, __VA_ARGS__)
#define TIME_OUTPUT(vr_, field_, ...)                                                              \
    ROW(vr_, field_, VAR_TIME, ROLE_OUTPUT, -2147483.648, TIME_MAX_S, __VA_ARGS__)

/* The rows of a table of points, setpoints[i].member_ for i below count_, at vr_ + i (the FMI
 * names setpoints[i].member_): a tunable parameter each. */
#define SETPOINTS_ROW(vr_, member_, type_, count_, min_, max_, ...)                                \
    {.vr = (vr_),                                                                                  \
     .name = "setpoints",                                                                          \
     .member = "." #member_,                                                                       \
     .type = (type_),                                                                              \
     .role = ROLE_TUNABLE_PARAMETER,                                                               \
     .offset = offsetof(block, setpoints[0].member_),                                              \
     .count = (count_),                                                                            \
     .stride = sizeof(((block *)NULL)->setpoints[0]),                                              \
     .min = (min_),                                                                                \
     .max = (max_),                                                                                \
     .description = __VA_ARGS__}

/* The output of the blocks that call system functions of the PLC, none of which the FMU calls;
 * the original V3.0.1 spells it subfunctionStatus. */
#define SUBFUNCTION_STATUS_ROW(vr_)                                                                \
    ROW(vr_, subFunctionStatus, VAR_WORD, ROLE_OUTPUT, 0, 65535,                                   \
        "WORD: status of called system functions; always 0 in the FMU (original V3.0.1 name: "     \
        "subfunctionStatus)",                                                                      \
        .original = "subfunctionStatus")

/* The statics of an IEC timer (iec/timer.h) that the block keeps in field_. */
#define TIMER_STATICS(field_)                                                                      \
    STATIC(block, field_.in, FIELD_BOOL), STATIC(block, field_.running, FIELD_BOOL),               \
        STATIC(block, field_.pt, FIELD_INT32), STATIC(block, field_.start_us, FIELD_INT64)

/* The input enable of LGF_SimpleSmoothingFB and LGF_DifferenceQuotientFB (iec/history.h). */
#define HISTORY_ENABLE_INPUT(vr_)                                                                  \
    BOOL_INPUT(vr_, enable,                                                                        \
               "TRUE: the block works; rising edge: start again with an empty buffer (LGF "        \
               "default FALSE, FMU start true)")

/* The block's lgf_model: its modelIdentifier, GUID and the default experiment's stop time, then
 * its description, after which the fields it sets beyond its variables, its data and its
 * functions follow (BLOCK_STATICS, the cycle, .check = check, BLOCK_STATUS_FIELDS; a field
 * left out, as .check of a block without one, is NULL). */
#define BLOCK_MODEL(identifier_, guid_, stop_time_, ...)                                           \
    static const model lgf_model = {.identifier = (identifier_),                                   \
                                    .guid = (guid_),                                               \
                                    .stop_time = (stop_time_),                                     \
                                    .variables = variables,                                        \
                                    .variable_count = sizeof variables / sizeof variables[0],      \
                                    .data_size = sizeof(block),                                    \
                                    .init = init,                                                  \
                                    .call = call,                                                  \
                                    .description = __VA_ARGS__}

/* The statics of a block that has any (an FC has none). */
#define BLOCK_STATICS .statics = statics, .static_count = sizeof statics / sizeof statics[0]

/* The cycle of a block that is no cyclic-interrupt block: any period in whole µs, and no status
 * codes of the original for an invalid one; a cyclic-interrupt block's: the PLC's grain of its
 * period and the codes. */
#define NO_CYCLE_CODES .cycle_granularity_us = 1, .cycle_codes = NULL
#define CI_CYCLE(granularity_us_, codes_)                                                          \
    .cycle_granularity_us = (granularity_us_), .cycle_codes = (codes_)

/* model.status and model.status_text of a block with BLOCK_STATUS. */
#define BLOCK_STATUS_FIELDS .status = status, .status_text = status_text

#endif
