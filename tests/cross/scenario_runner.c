/* Runs a scenario script through the FMI 2.0 or FMI 3.0 API of one FMU binary and prints every
 * result exactly, so that the same script can be run against the binary of one platform
 * natively and against that of another under an emulator, and the two outputs compared byte for
 * byte: binaries/linux64/<id>.so and binaries/win64/<id>.dll under wine (tests/test_win64.py),
 * binaries/x86_64-linux/<id>.so and binaries/aarch64-linux/<id>.so under qemu
 * (tests/test_aarch64.py). The library's entry points say which FMI version it is.
 *
 *     scenario_runner <library> < script
 *
 * The script has one command per line; floating-point numbers are the hex digits of their
 * IEEE 754 bit pattern (16 for a double, 8 for a float32), so no decimal conversion of the C
 * library is involved:
 *     guid <guid or instantiationToken>     instantiate <name>          free
 *     setup <t0> [<stop time>]    enter     exit        terminate
 *     <type> <vr> <value>         sets one variable; <type> is real, int, bool (FMI 2.0) or
 *                                 float64, float32, int8, uint8, int16, uint16, int32,
 *                                 uint32, bool (FMI 3.0);
 *                                 integers in decimal (converted to the type as C converts)
 *     output <type> <vr> <name>   printed after exit, restore and every step
 *     step <t> <h>                save | restore | reserialize  (FMU state)
 *     scenario <name>             printed as it is: marks where a scenario begins
 * Every FMI command prints one line with the status it returned (an FMI 3.0 doStep also the
 * flags it set, if any); the logger prints the status and category of each message (not its
 * text, whose number formatting is the C library's business). In FMI 3.0, setup only notes the
 * times for enter (fmi3EnterInitializationMode). Exit code 0 unless the script or the library
 * cannot be used. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi2FunctionTypes.h"
#include "fmi3FunctionTypes.h"

#ifdef _WIN32
#include <fcntl.h>
#include <io.h>
#include <windows.h>
#else
#include <dlfcn.h>
#endif

typedef struct {
    fmi2InstantiateTYPE *instantiate;
    fmi2FreeInstanceTYPE *free_instance;
    fmi2SetupExperimentTYPE *setup_experiment;
    fmi2EnterInitializationModeTYPE *enter_initialization;
    fmi2ExitInitializationModeTYPE *exit_initialization;
    fmi2TerminateTYPE *terminate;
    fmi2SetRealTYPE *set_real;
    fmi2SetIntegerTYPE *set_integer;
    fmi2SetBooleanTYPE *set_boolean;
    fmi2GetRealTYPE *get_real;
    fmi2GetIntegerTYPE *get_integer;
    fmi2GetBooleanTYPE *get_boolean;
    fmi2DoStepTYPE *do_step;
    fmi2GetFMUstateTYPE *get_state;
    fmi2SetFMUstateTYPE *set_state;
    fmi2FreeFMUstateTYPE *free_state;
    fmi2SerializedFMUstateSizeTYPE *serialized_size;
    fmi2SerializeFMUstateTYPE *serialize;
    fmi2DeSerializeFMUstateTYPE *deserialize;
} fmi2_api;

typedef struct {
    fmi3InstantiateCoSimulationTYPE *instantiate;
    fmi3FreeInstanceTYPE *free_instance;
    fmi3EnterInitializationModeTYPE *enter_initialization;
    fmi3ExitInitializationModeTYPE *exit_initialization;
    fmi3TerminateTYPE *terminate;
    fmi3SetFloat64TYPE *set_float64;
    fmi3SetFloat32TYPE *set_float32;
    fmi3SetInt16TYPE *set_int16;
    fmi3SetUInt16TYPE *set_uint16;
    fmi3SetUInt32TYPE *set_uint32;
    fmi3SetInt32TYPE *set_int32;
    fmi3SetInt8TYPE *set_int8;
    fmi3SetUInt8TYPE *set_uint8;
    fmi3SetBooleanTYPE *set_boolean;
    fmi3GetFloat64TYPE *get_float64;
    fmi3GetFloat32TYPE *get_float32;
    fmi3GetInt16TYPE *get_int16;
    fmi3GetUInt16TYPE *get_uint16;
    fmi3GetUInt32TYPE *get_uint32;
    fmi3GetInt32TYPE *get_int32;
    fmi3GetInt8TYPE *get_int8;
    fmi3GetUInt8TYPE *get_uint8;
    fmi3GetBooleanTYPE *get_boolean;
    fmi3DoStepTYPE *do_step;
    fmi3GetFMUStateTYPE *get_state;
    fmi3SetFMUStateTYPE *set_state;
    fmi3FreeFMUStateTYPE *free_state;
    fmi3SerializedFMUStateSizeTYPE *serialized_size;
    fmi3SerializeFMUStateTYPE *serialize;
    fmi3DeserializeFMUStateTYPE *deserialize;
} fmi3_api;

static int version; /* 2 or 3: the FMI version of the library */
static fmi2_api f2;
static fmi3_api f3;

typedef struct {
    const char *name;
    void *slot;
} entry;

#ifdef _WIN32
typedef HMODULE library_handle;
#else
typedef void *library_handle;
#endif

static void (*symbol(library_handle library, const char *name))(void)
{
#ifdef _WIN32
    return (void (*)(void))GetProcAddress(library, name);
#else
    void (*function)(void);
    void *found = dlsym(library, name);
    memcpy(&function, &found, sizeof function); /* POSIX: dlsym results are callable */
    return function;
#endif
}

static int load_table(library_handle library, const char *path, const entry *table, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        void (*function)(void) = symbol(library, table[i].name);
        if (!function) {
            fprintf(stderr, "%s does not export %s\n", path, table[i].name);
            return 0;
        }
        memcpy(table[i].slot, &function, sizeof function);
    }
    return 1;
}

static int load(const char *path)
{
    const entry table2[] = {
        {"fmi2Instantiate", &f2.instantiate},
        {"fmi2FreeInstance", &f2.free_instance},
        {"fmi2SetupExperiment", &f2.setup_experiment},
        {"fmi2EnterInitializationMode", &f2.enter_initialization},
        {"fmi2ExitInitializationMode", &f2.exit_initialization},
        {"fmi2Terminate", &f2.terminate},
        {"fmi2SetReal", &f2.set_real},
        {"fmi2SetInteger", &f2.set_integer},
        {"fmi2SetBoolean", &f2.set_boolean},
        {"fmi2GetReal", &f2.get_real},
        {"fmi2GetInteger", &f2.get_integer},
        {"fmi2GetBoolean", &f2.get_boolean},
        {"fmi2DoStep", &f2.do_step},
        {"fmi2GetFMUstate", &f2.get_state},
        {"fmi2SetFMUstate", &f2.set_state},
        {"fmi2FreeFMUstate", &f2.free_state},
        {"fmi2SerializedFMUstateSize", &f2.serialized_size},
        {"fmi2SerializeFMUstate", &f2.serialize},
        {"fmi2DeSerializeFMUstate", &f2.deserialize},
    };
    const entry table3[] = {
        {"fmi3InstantiateCoSimulation", &f3.instantiate},
        {"fmi3FreeInstance", &f3.free_instance},
        {"fmi3EnterInitializationMode", &f3.enter_initialization},
        {"fmi3ExitInitializationMode", &f3.exit_initialization},
        {"fmi3Terminate", &f3.terminate},
        {"fmi3SetFloat64", &f3.set_float64},
        {"fmi3SetFloat32", &f3.set_float32},
        {"fmi3SetInt16", &f3.set_int16},
        {"fmi3SetUInt16", &f3.set_uint16},
        {"fmi3SetUInt32", &f3.set_uint32},
        {"fmi3SetInt32", &f3.set_int32},
        {"fmi3SetInt8", &f3.set_int8},
        {"fmi3SetUInt8", &f3.set_uint8},
        {"fmi3SetBoolean", &f3.set_boolean},
        {"fmi3GetFloat64", &f3.get_float64},
        {"fmi3GetFloat32", &f3.get_float32},
        {"fmi3GetInt16", &f3.get_int16},
        {"fmi3GetUInt16", &f3.get_uint16},
        {"fmi3GetUInt32", &f3.get_uint32},
        {"fmi3GetInt32", &f3.get_int32},
        {"fmi3GetInt8", &f3.get_int8},
        {"fmi3GetUInt8", &f3.get_uint8},
        {"fmi3GetBoolean", &f3.get_boolean},
        {"fmi3DoStep", &f3.do_step},
        {"fmi3GetFMUState", &f3.get_state},
        {"fmi3SetFMUState", &f3.set_state},
        {"fmi3FreeFMUState", &f3.free_state},
        {"fmi3SerializedFMUStateSize", &f3.serialized_size},
        {"fmi3SerializeFMUState", &f3.serialize},
        {"fmi3DeserializeFMUState", &f3.deserialize},
    };
#ifdef _WIN32
    library_handle library = LoadLibraryA(path);
#else
    library_handle library = dlopen(path, RTLD_NOW | RTLD_LOCAL);
#endif
    if (!library) {
        fprintf(stderr, "cannot load %s\n", path);
        return 0;
    }
    version = symbol(library, "fmi3InstantiateCoSimulation") ? 3 : 2;
    if (version == 3) return load_table(library, path, table3, sizeof table3 / sizeof table3[0]);
    return load_table(library, path, table2, sizeof table2 / sizeof table2[0]);
}

static void print_hex(uint64_t bits, int digits)
{
    char text[17];
    for (int i = digits - 1; i >= 0; i--) {
        text[i] = "0123456789abcdef"[bits & 0xf];
        bits >>= 4;
    }
    fwrite(text, 1, (size_t)digits, stdout);
}

/* `digits` lower-case hex digits, exactly */
static int parse_hex(const char *text, int digits, uint64_t *bits)
{
    *bits = 0;
    if (!text || strlen(text) != (size_t)digits) return 0;
    for (const char *p = text; *p; p++) {
        const char *digit = strchr("0123456789abcdef", *p);
        if (!digit) return 0;
        *bits = *bits << 4 | (uint64_t)(digit - "0123456789abcdef");
    }
    return 1;
}

static int parse_bits(const char *text, double *value)
{
    uint64_t bits;
    if (!parse_hex(text, 16, &bits)) return 0;
    memcpy(value, &bits, sizeof bits);
    return 1;
}

static void logger2(fmi2ComponentEnvironment env, fmi2String name, fmi2Status status,
                    fmi2String category, fmi2String message, ...)
{
    (void)env;
    (void)name;
    (void)message;
    printf("  log %d %s\n", (int)status, category ? category : "(null)");
}

static void logger3(fmi3InstanceEnvironment env, fmi3Status status, fmi3String category,
                    fmi3String message)
{
    (void)env;
    (void)message;
    printf("  log %d %s\n", (int)status, category ? category : "(null)");
}

/* The variable types of the scripts, and the FMI version each belongs to (0: both). */
typedef enum {
    T_REAL,
    T_INT,
    T_BOOL,
    T_FLOAT64,
    T_FLOAT32,
    T_INT16,
    T_UINT16,
    T_UINT32,
    T_INT32,
    T_INT8,
    T_UINT8
} kind;
static const struct {
    const char *name;
    int version;
} kinds[] = {
    [T_REAL] = {"real", 2},       [T_INT] = {"int", 2},         [T_BOOL] = {"bool", 0},
    [T_FLOAT64] = {"float64", 3}, [T_FLOAT32] = {"float32", 3}, [T_INT16] = {"int16", 3},
    [T_UINT16] = {"uint16", 3},   [T_UINT32] = {"uint32", 3},   [T_INT32] = {"int32", 3},
    [T_INT8] = {"int8", 3},       [T_UINT8] = {"uint8", 3},
};

static int kind_of(const char *name)
{
    for (size_t k = 0; name && k < sizeof kinds / sizeof kinds[0]; k++)
        if (!strcmp(name, kinds[k].name) && (!kinds[k].version || kinds[k].version == version))
            return (int)k;
    return -1;
}

/* Sets one variable from the script's text; -1 if the text cannot be read. */
static int set_value(void *c, int k, const char *vr_text, const char *text)
{
    const fmi3ValueReference vr = (fmi3ValueReference)strtoul(vr_text, NULL, 10);
    const fmi2ValueReference vr2 = (fmi2ValueReference)vr;
    const long long integer = text ? strtoll(text, NULL, 10) : 0;
    uint64_t bits;
    if (k == T_REAL || k == T_FLOAT64) {
        double x;
        if (!parse_bits(text, &x)) return -1;
        return k == T_REAL ? f2.set_real(c, &vr2, 1, &x) : f3.set_float64(c, &vr, 1, &x, 1);
    }
    if (k == T_FLOAT32) {
        float x;
        uint32_t low;
        if (!parse_hex(text, 8, &bits)) return -1;
        low = (uint32_t)bits;
        memcpy(&x, &low, sizeof x);
        return f3.set_float32(c, &vr, 1, &x, 1);
    }
    if (!text) return -1;
    if (k == T_INT) {
        fmi2Integer x = (fmi2Integer)integer;
        return f2.set_integer(c, &vr2, 1, &x);
    }
    if (k == T_INT16) {
        fmi3Int16 x = (fmi3Int16)integer;
        return f3.set_int16(c, &vr, 1, &x, 1);
    }
    if (k == T_UINT16) {
        fmi3UInt16 x = (fmi3UInt16)integer;
        return f3.set_uint16(c, &vr, 1, &x, 1);
    }
    if (k == T_UINT32) {
        fmi3UInt32 x = (fmi3UInt32)integer;
        return f3.set_uint32(c, &vr, 1, &x, 1);
    }
    if (k == T_INT32) {
        fmi3Int32 x = (fmi3Int32)integer;
        return f3.set_int32(c, &vr, 1, &x, 1);
    }
    if (k == T_INT8) {
        fmi3Int8 x = (fmi3Int8)integer;
        return f3.set_int8(c, &vr, 1, &x, 1);
    }
    if (k == T_UINT8) {
        fmi3UInt8 x = (fmi3UInt8)integer;
        return f3.set_uint8(c, &vr, 1, &x, 1);
    }
    if (version == 2) {
        fmi2Boolean x = text[0] == '1';
        return f2.set_boolean(c, &vr2, 1, &x);
    }
    fmi3Boolean x = text[0] == '1';
    return f3.set_boolean(c, &vr, 1, &x, 1);
}

/* Gets one variable as its bit pattern: 16 hex digits for a double, else 8 (integers as their
 * 32-bit two's complement). */
static int get_value(void *c, int k, fmi3ValueReference vr, uint64_t *bits, int *digits)
{
    const fmi2ValueReference vr2 = (fmi2ValueReference)vr;
    int status;
    *bits = 0;
    *digits = 8;
    if (k == T_REAL || k == T_FLOAT64) {
        double x = 0;
        status = k == T_REAL ? f2.get_real(c, &vr2, 1, &x) : f3.get_float64(c, &vr, 1, &x, 1);
        memcpy(bits, &x, sizeof x);
        *digits = 16;
    } else if (k == T_FLOAT32) {
        float x = 0;
        uint32_t low;
        status = f3.get_float32(c, &vr, 1, &x, 1);
        memcpy(&low, &x, sizeof low);
        *bits = low;
    } else if (k == T_INT) {
        fmi2Integer x = 0;
        status = f2.get_integer(c, &vr2, 1, &x);
        *bits = (uint32_t)x;
    } else if (k == T_INT16) {
        fmi3Int16 x = 0;
        status = f3.get_int16(c, &vr, 1, &x, 1);
        *bits = (uint32_t)(int32_t)x;
    } else if (k == T_UINT16) {
        fmi3UInt16 x = 0;
        status = f3.get_uint16(c, &vr, 1, &x, 1);
        *bits = x;
    } else if (k == T_UINT32) {
        fmi3UInt32 x = 0;
        status = f3.get_uint32(c, &vr, 1, &x, 1);
        *bits = x;
    } else if (k == T_INT32) {
        fmi3Int32 x = 0;
        status = f3.get_int32(c, &vr, 1, &x, 1);
        *bits = (uint32_t)x;
    } else if (k == T_INT8) {
        fmi3Int8 x = 0;
        status = f3.get_int8(c, &vr, 1, &x, 1);
        *bits = (uint32_t)(int32_t)x;
    } else if (k == T_UINT8) {
        fmi3UInt8 x = 0;
        status = f3.get_uint8(c, &vr, 1, &x, 1);
        *bits = x;
    } else if (version == 2) {
        fmi2Boolean x = 0;
        status = f2.get_boolean(c, &vr2, 1, &x);
        *bits = (uint32_t)x;
    } else {
        fmi3Boolean x = 0;
        status = f3.get_boolean(c, &vr, 1, &x, 1);
        *bits = x;
    }
    return status;
}

#define MAX_OUTPUTS 64

typedef struct {
    int kind;
    fmi3ValueReference vr;
    char name[64];
} output;

static void print_outputs(void *c, const output *outputs, int count)
{
    for (int k = 0; k < count; k++) {
        uint64_t bits;
        int digits;
        int status = get_value(c, outputs[k].kind, outputs[k].vr, &bits, &digits);
        printf(" %s=", outputs[k].name);
        print_hex(bits, digits);
        if (status != 0) printf("(status %d)", status);
    }
    printf("\n");
}

/* The FMU state commands: save, restore, reserialize (the saved state through a byte buffer and
 * back); -1 for another command. */
static int state_command(void *c, const char *command, void **saved)
{
    if (!strcmp(command, "save")) {
        if (*saved) version == 2 ? f2.free_state(c, saved) : f3.free_state(c, saved);
        return version == 2 ? f2.get_state(c, saved) : f3.get_state(c, saved);
    }
    if (!strcmp(command, "restore"))
        return version == 2 ? f2.set_state(c, *saved) : f3.set_state(c, *saved);
    if (strcmp(command, "reserialize")) return -1;
    size_t size = 0;
    int status =
        version == 2 ? f2.serialized_size(c, *saved, &size) : f3.serialized_size(c, *saved, &size);
    unsigned char *bytes = malloc(size ? size : 1);
    if (status == 0)
        status = version == 2 ? f2.serialize(c, *saved, (fmi2Byte *)bytes, size)
                              : f3.serialize(c, *saved, bytes, size);
    if (status == 0)
        status = version == 2 ? f2.deserialize(c, (const fmi2Byte *)bytes, size, saved)
                              : f3.deserialize(c, bytes, size, saved);
    free(bytes);
    return status;
}

/* One doStep; an FMI 3.0 one also prints the flags it set, if it set any. */
static int do_step(void *c, double t, double h)
{
    if (version == 2) return f2.do_step(c, t, h, fmi2True);
    fmi3Boolean event = fmi3False, stop = fmi3False, early = fmi3False;
    fmi3Float64 last = t + h;
    int status = f3.do_step(c, t, h, fmi3True, &event, &stop, &early, &last);
    if (event || stop || early) {
        uint64_t bits;
        memcpy(&bits, &last, sizeof bits);
        printf("  flags event %d terminate %d early return %d at ", event, stop, early);
        print_hex(bits, 16);
        printf("\n");
    }
    return status;
}

int main(int argc, char **argv)
{
#ifdef _WIN32
    _setmode(_fileno(stdout), _O_BINARY); /* "\n", not "\r\n": the outputs are compared */
#endif
    setvbuf(stdout, NULL, _IOFBF, 1 << 16);
    if (argc != 2 || !load(argv[1])) {
        fprintf(stderr, "usage: scenario_runner <FMU binary> < script\n");
        return 2;
    }
    const fmi2CallbackFunctions callbacks = {logger2, calloc, free, NULL, NULL};
    static char guid[128];
    void *c = NULL, *saved = NULL;
    double start = 0, stop = 0;
    int stop_defined = 0;
    output outputs[MAX_OUTPUTS];
    int output_count = 0, line_number = 0;
    char line[512];

    while (fgets(line, sizeof line, stdin)) {
        line_number++;
        char *command = strtok(line, " \t\r\n");
        if (!command || command[0] == '#') continue;
        char *a = strtok(NULL, " \t\r\n"), *b = strtok(NULL, " \t\r\n");
        char *d = strtok(NULL, " \t\r\n");
        int status = -1, k = kind_of(command);
        double x = 0, y = 0;
        if (!strcmp(command, "guid") && a) {
            snprintf(guid, sizeof guid, "%s", a);
            continue;
        } else if (!strcmp(command, "scenario") && a) {
            printf("scenario %s\n", a);
            continue;
        } else if (!strcmp(command, "output") && kind_of(a) >= 0 && b && d &&
                   output_count < MAX_OUTPUTS) {
            output *o = &outputs[output_count++];
            o->kind = kind_of(a);
            o->vr = (fmi3ValueReference)strtoul(b, NULL, 10);
            snprintf(o->name, sizeof o->name, "%s", d);
            continue;
        } else if (!strcmp(command, "instantiate") && a) {
            output_count = 0; /* each instance declares its outputs after instantiate */
            c = version == 2 ? f2.instantiate(a, fmi2CoSimulation, guid, "", &callbacks, fmi2False,
                                              fmi2False)
                             : f3.instantiate(a, guid, NULL, fmi3False, fmi3False, fmi3False,
                                              fmi3False, NULL, 0, NULL, logger3, NULL);
            status = c ? 0 : 3;
        } else if (!c) {
            fprintf(stderr, "line %d: no instance\n", line_number);
            return 2;
        } else if (!strcmp(command, "free")) {
            if (saved) version == 2 ? f2.free_state(c, &saved) : f3.free_state(c, &saved);
            version == 2 ? f2.free_instance(c) : f3.free_instance(c);
            c = NULL;
            status = 0;
        } else if (!strcmp(command, "setup") && parse_bits(a, &start) &&
                   (!b || parse_bits(b, &stop))) {
            stop_defined = b != NULL;
            status = version == 3
                         ? 0
                         : f2.setup_experiment(c, fmi2False, 0.0, start, stop_defined, stop);
        } else if (!strcmp(command, "enter")) {
            status = version == 2 ? f2.enter_initialization(c)
                                  : f3.enter_initialization(c, fmi3False, 0.0, start,
                                                            stop_defined != 0, stop);
        } else if (!strcmp(command, "exit")) {
            status = version == 2 ? f2.exit_initialization(c) : f3.exit_initialization(c);
        } else if (!strcmp(command, "terminate")) {
            status = version == 2 ? f2.terminate(c) : f3.terminate(c);
        } else if (k >= 0 && a && (status = set_value(c, k, a, b)) >= 0) {
            /* set */
        } else if (!strcmp(command, "step") && parse_bits(a, &x) && parse_bits(b, &y)) {
            status = do_step(c, x, y);
        } else if ((status = state_command(c, command, &saved)) >= 0) {
            /* FMU state */
        } else {
            fprintf(stderr, "line %d: cannot read the command\n", line_number);
            return 2;
        }
        /* after the call, so that its log lines come first */
        printf("%s%s%s%s%s -> %d", command, a ? " " : "", a ? a : "", b ? " " : "", b ? b : "",
               status);
        if (c &&
            (!strcmp(command, "exit") || !strcmp(command, "step") || !strcmp(command, "restore")))
            print_outputs(c, outputs, output_count);
        else
            printf("\n");
    }
    if (c) version == 2 ? f2.free_instance(c) : f3.free_instance(c);
    fflush(stdout);
    return 0;
}
