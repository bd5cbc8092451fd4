/* Runs a scenario script through the FMI 2.0 API of one FMU binary and prints every result
 * exactly, so that the same script can be run against binaries/linux64/<id>.so (natively) and
 * binaries/win64/<id>.dll (under wine) and the two outputs compared byte for byte
 * (tests/test_win64.py writes the scripts).
 *
 *     scenario_runner <library> < script
 *
 * The script has one command per line; numbers of type Real are the 16 hex digits of the
 * IEEE 754 bit pattern, so no decimal conversion of the C library is involved:
 *     guid <guid>                  instantiate <name>          free
 *     setup <t0>                   enter                       exit          terminate
 *     real <vr> <bits>             int <vr> <decimal>          bool <vr> <0|1>
 *     output real|int|bool <vr> <name>   (printed after exit and after every step)
 *     step <t> <h>                 save | restore | reserialize  (FMU state)
 * Every FMI command prints one line with the fmi2Status it returned; the logger prints the
 * status and category of each message (not its text, whose number formatting is the C
 * library's business). Exit code 0 unless the script or the library cannot be used. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi2FunctionTypes.h"

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

static int load(const char *path, fmi2_api *api)
{
    struct { const char *name; void *slot; } table[] = {
        {"fmi2Instantiate", &api->instantiate},
        {"fmi2FreeInstance", &api->free_instance},
        {"fmi2SetupExperiment", &api->setup_experiment},
        {"fmi2EnterInitializationMode", &api->enter_initialization},
        {"fmi2ExitInitializationMode", &api->exit_initialization},
        {"fmi2Terminate", &api->terminate},
        {"fmi2SetReal", &api->set_real},
        {"fmi2SetInteger", &api->set_integer},
        {"fmi2SetBoolean", &api->set_boolean},
        {"fmi2GetReal", &api->get_real},
        {"fmi2GetInteger", &api->get_integer},
        {"fmi2GetBoolean", &api->get_boolean},
        {"fmi2DoStep", &api->do_step},
        {"fmi2GetFMUstate", &api->get_state},
        {"fmi2SetFMUstate", &api->set_state},
        {"fmi2FreeFMUstate", &api->free_state},
        {"fmi2SerializedFMUstateSize", &api->serialized_size},
        {"fmi2SerializeFMUstate", &api->serialize},
        {"fmi2DeSerializeFMUstate", &api->deserialize},
    };
#ifdef _WIN32
    HMODULE library = LoadLibraryA(path);
#else
    void *library = dlopen(path, RTLD_NOW | RTLD_LOCAL);
#endif
    if (!library) {
        fprintf(stderr, "cannot load %s\n", path);
        return 0;
    }
    for (size_t i = 0; i < sizeof table / sizeof table[0]; i++) {
#ifdef _WIN32
        void (*function)(void) = (void (*)(void))GetProcAddress(library, table[i].name);
#else
        void (*function)(void);
        void *symbol = dlsym(library, table[i].name);
        memcpy(&function, &symbol, sizeof function); /* POSIX: dlsym results are callable */
#endif
        if (!function) {
            fprintf(stderr, "%s does not export %s\n", path, table[i].name);
            return 0;
        }
        memcpy(table[i].slot, &function, sizeof function);
    }
    return 1;
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

static int parse_bits(const char *text, double *value)
{
    uint64_t bits = 0;
    if (!text || strlen(text) != 16) return 0;
    for (const char *p = text; *p; p++) {
        const char *digit = strchr("0123456789abcdef", *p);
        if (!digit || !*p) return 0;
        bits = bits << 4 | (uint64_t)(digit - "0123456789abcdef");
    }
    memcpy(value, &bits, sizeof bits);
    return 1;
}

static void logger(fmi2ComponentEnvironment env, fmi2String name, fmi2Status status,
                   fmi2String category, fmi2String message, ...)
{
    (void)env;
    (void)name;
    (void)message;
    printf("  log %d %s\n", (int)status, category ? category : "(null)");
}

#define MAX_OUTPUTS 64

typedef struct {
    char kind; /* 'r', 'i', 'b' */
    fmi2ValueReference vr;
    char name[64];
} output;

static void print_outputs(const fmi2_api *api, fmi2Component c, const output *outputs, int count)
{
    for (int k = 0; k < count; k++) {
        const output *o = &outputs[k];
        fmi2Status status;
        uint64_t bits = 0;
        int digits = 8;
        if (o->kind == 'r') {
            fmi2Real value = 0;
            status = api->get_real(c, &o->vr, 1, &value);
            memcpy(&bits, &value, sizeof bits);
            digits = 16;
        } else if (o->kind == 'i') {
            fmi2Integer value = 0;
            status = api->get_integer(c, &o->vr, 1, &value);
            bits = (uint32_t)value;
        } else {
            fmi2Boolean value = 0;
            status = api->get_boolean(c, &o->vr, 1, &value);
            bits = (uint32_t)value;
        }
        printf(" %s=", o->name);
        print_hex(bits, digits);
        if (status != fmi2OK) printf("(status %d)", (int)status);
    }
    printf("\n");
}

int main(int argc, char **argv)
{
#ifdef _WIN32
    _setmode(_fileno(stdout), _O_BINARY); /* "\n", not "\r\n": the outputs are compared */
#endif
    setvbuf(stdout, NULL, _IOFBF, 1 << 16);
    fmi2_api api;
    if (argc != 2 || !load(argv[1], &api)) {
        fprintf(stderr, "usage: scenario_runner <FMU binary> < script\n");
        return 2;
    }
    const fmi2CallbackFunctions callbacks = {logger, calloc, free, NULL, NULL};
    static char guid[128];
    fmi2Component c = NULL;
    fmi2FMUstate saved = NULL;
    output outputs[MAX_OUTPUTS];
    int output_count = 0, line_number = 0;
    char line[512];

    while (fgets(line, sizeof line, stdin)) {
        line_number++;
        char *command = strtok(line, " \t\r\n");
        if (!command || command[0] == '#') continue;
        char *a = strtok(NULL, " \t\r\n"), *b = strtok(NULL, " \t\r\n");
        char *d = strtok(NULL, " \t\r\n");
        int status = -1;
        double x = 0, y = 0;
        if (!strcmp(command, "guid") && a) {
            snprintf(guid, sizeof guid, "%s", a);
            continue;
        } else if (!strcmp(command, "output") && a && b && d && output_count < MAX_OUTPUTS) {
            output *o = &outputs[output_count++];
            o->kind = a[0];
            o->vr = (fmi2ValueReference)strtoul(b, NULL, 10);
            snprintf(o->name, sizeof o->name, "%s", d);
            continue;
        } else if (!strcmp(command, "instantiate") && a) {
            c = api.instantiate(a, fmi2CoSimulation, guid, "", &callbacks, fmi2False, fmi2False);
            status = c ? fmi2OK : fmi2Error;
        } else if (!c) {
            fprintf(stderr, "line %d: no instance\n", line_number);
            return 2;
        } else if (!strcmp(command, "free")) {
            if (saved) api.free_state(c, &saved);
            api.free_instance(c);
            c = NULL;
            status = fmi2OK;
        } else if (!strcmp(command, "setup") && parse_bits(a, &x)) {
            status = api.setup_experiment(c, fmi2False, 0.0, x, fmi2False, 0.0);
        } else if (!strcmp(command, "enter")) {
            status = api.enter_initialization(c);
        } else if (!strcmp(command, "exit")) {
            status = api.exit_initialization(c);
        } else if (!strcmp(command, "terminate")) {
            status = api.terminate(c);
        } else if (!strcmp(command, "real") && a && parse_bits(b, &x)) {
            fmi2ValueReference vr = (fmi2ValueReference)strtoul(a, NULL, 10);
            status = api.set_real(c, &vr, 1, &x);
        } else if (!strcmp(command, "int") && a && b) {
            fmi2ValueReference vr = (fmi2ValueReference)strtoul(a, NULL, 10);
            fmi2Integer value = (fmi2Integer)strtol(b, NULL, 10);
            status = api.set_integer(c, &vr, 1, &value);
        } else if (!strcmp(command, "bool") && a && b) {
            fmi2ValueReference vr = (fmi2ValueReference)strtoul(a, NULL, 10);
            fmi2Boolean value = b[0] == '1';
            status = api.set_boolean(c, &vr, 1, &value);
        } else if (!strcmp(command, "step") && parse_bits(a, &x) && parse_bits(b, &y)) {
            status = api.do_step(c, x, y, fmi2True);
        } else if (!strcmp(command, "save")) {
            if (saved) api.free_state(c, &saved);
            status = api.get_state(c, &saved);
        } else if (!strcmp(command, "restore")) {
            status = api.set_state(c, saved);
        } else if (!strcmp(command, "reserialize")) {
            /* the saved state through a byte buffer and back */
            size_t size = 0;
            status = api.serialized_size(c, saved, &size);
            unsigned char *bytes = malloc(size ? size : 1);
            if (status == fmi2OK) status = api.serialize(c, saved, (fmi2Byte *)bytes, size);
            if (status == fmi2OK) status = api.deserialize(c, (fmi2Byte *)bytes, size, &saved);
            free(bytes);
        } else {
            fprintf(stderr, "line %d: cannot read the command\n", line_number);
            return 2;
        }
        /* after the call, so that its log lines come first */
        printf("%s%s%s%s%s -> %d", command, a ? " " : "", a ? a : "", b ? " " : "", b ? b : "", status);
        if (c && (!strcmp(command, "exit") || !strcmp(command, "step") || !strcmp(command, "restore")))
            print_outputs(&api, c, outputs, output_count);
        else
            printf("\n");
    }
    if (c) api.free_instance(c);
    fflush(stdout);
    return 0;
}
