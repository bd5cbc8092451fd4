#define _POSIX_C_SOURCE 200809L
#include "importer.h"

#include <dlfcn.h>
#include <stdarg.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- the library ---- */

bool api_load(fmi2_api *api, const char *library, char *error, size_t size)
{
    memset(api, 0, sizeof *api);
    api->handle = dlopen(library, RTLD_NOW | RTLD_LOCAL);
    if (!api->handle) {
        snprintf(error, size, "dlopen(%s) failed: %s", library, dlerror());
        return false;
    }
    /* dlsym returns an object pointer; it is copied bytewise into the function pointer, the
     * portable way POSIX allows. */
#define FMI2_LOOK_UP(name)                                                                         \
    {                                                                                              \
        void *symbol = dlsym(api->handle, "fmi2" #name);                                           \
        if (!symbol) {                                                                             \
            snprintf(error, size, "%s does not export fmi2%s", library, #name);                    \
            api_unload(api);                                                                       \
            return false;                                                                          \
        }                                                                                          \
        memcpy(&api->name, &symbol, sizeof symbol);                                                \
    }
    FMI2_CS_FUNCTIONS(FMI2_LOOK_UP)
    FMI2_ME_FUNCTIONS(FMI2_LOOK_UP)
#undef FMI2_LOOK_UP
    return true;
}

void api_unload(fmi2_api *api)
{
    if (api->handle) dlclose(api->handle);
    memset(api, 0, sizeof *api);
}

/* ---- modelDescription.xml ----
 * Not a general XML parser: it finds the tags it needs and reads their attributes, which is
 * all a modelDescription.xml written by this project (no entities in names, no CDATA) needs. */

static char *read_file(const char *path, char *error, size_t size)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(error, size, "cannot open %s", path);
        return NULL;
    }
    char *text = NULL;
    size_t length = 0, capacity = 0;
    for (;;) {
        if (length + 4096 + 1 > capacity) {
            capacity = capacity ? 2 * capacity : 65536;
            char *bigger = realloc(text, capacity);
            if (!bigger) break;
            text = bigger;
        }
        size_t got = fread(text + length, 1, capacity - length - 1, f);
        length += got;
        if (got == 0) break;
    }
    fclose(f);
    if (text) text[length] = '\0';
    return text;
}

/* The attribute `name` of the tag that starts at tag (at '<') and ends at the next '>'.
 * Returns false when absent. */
static bool attribute(const char *tag, const char *name, char *value, size_t size)
{
    const char *p = tag + 1;
    while (*p && *p != ' ' && *p != '\t' && *p != '\n' && *p != '\r' && *p != '>') p++;
    for (;;) {
        while (*p == ' ' || *p == '\t' || *p == '\n' || *p == '\r') p++;
        if (!*p || *p == '>' || *p == '/') return false;
        const char *key = p;
        while (*p && *p != '=' && *p != '>' && *p != ' ') p++;
        size_t key_length = (size_t)(p - key);
        if (*p != '=') return false;
        p++;
        char quote = *p;
        if (quote != '"' && quote != '\'') return false;
        const char *start = ++p;
        while (*p && *p != quote) p++;
        if (!*p) return false;
        if (key_length == strlen(name) && !strncmp(key, name, key_length)) {
            size_t n = (size_t)(p - start);
            if (n >= size) n = size - 1;
            memcpy(value, start, n);
            value[n] = '\0';
            return true;
        }
        p++;
    }
}

/* The next tag named `name` at or after from (and before limit, when limit is not NULL). */
static const char *find_tag(const char *from, const char *name, const char *limit)
{
    size_t n = strlen(name);
    for (const char *p = strchr(from, '<'); p && (!limit || p < limit); p = strchr(p + 1, '<')) {
        if (!strncmp(p + 1, name, n) && strchr(" \t\r\n/>", p[1 + n])) return p;
    }
    return NULL;
}

static bool number(const char *tag, const char *name, double *value)
{
    char text[64];
    if (!attribute(tag, name, text, sizeof text)) return false;
    char *end;
    *value = strtod(text, &end);
    return end != text;
}

const char *const fmi3_type_names[T3_TYPES] = {"Float32", "Float64", "Int8",   "UInt8", "Int16",
                                               "UInt16",  "Int32",   "UInt32", "Int64", "UInt64",
                                               "Boolean", "String",  "Binary", "Clock"};

static md_variable *next_variable(model_description *md, size_t *capacity)
{
    if (md->count == *capacity) {
        *capacity = *capacity ? 2 * *capacity : 64;
        md_variable *bigger = realloc(md->variables, *capacity * sizeof *bigger);
        if (!bigger) return NULL;
        md->variables = bigger;
    }
    md_variable *v = &md->variables[md->count];
    memset(v, 0, sizeof *v);
    return v;
}

/* What both versions write alike: causality, variability; min, max, start and unit on the tag
 * of the type (FMI 2.0: the child element, FMI 3.0: the variable itself). */
static void read_common(md_variable *v, const char *variable, const char *type_tag)
{
    char text[64] = "";
    if (!attribute(variable, "causality", text, sizeof text)) strcpy(text, "local");
    v->causality = !strcmp(text, "parameter") ? CAUS_PARAMETER
                   : !strcmp(text, "input")   ? CAUS_INPUT
                   : !strcmp(text, "output")  ? CAUS_OUTPUT
                                              : CAUS_OTHER;
    v->fixed = attribute(variable, "variability", text, sizeof text) && !strcmp(text, "fixed");
    if (!type_tag) return;
    v->has_min = number(type_tag, "min", &v->min);
    v->has_max = number(type_tag, "max", &v->max);
    if (v->kind == KIND_BOOLEAN) {
        v->has_start = attribute(type_tag, "start", text, sizeof text);
        v->start = v->has_start && (!strcmp(text, "true") || !strcmp(text, "1"));
    } else {
        v->has_start = number(type_tag, "start", &v->start);
    }
    v->is_cycle = !strcmp(v->name, "cycleTime");
    v->is_time = v->kind == KIND_REAL && !v->is_cycle &&
                 attribute(type_tag, "unit", text, sizeof text) && !strcmp(text, "s");
}

static bool read_variables2(model_description *md, const char *xml, const char *path, char *error,
                            size_t size)
{
    size_t capacity = 0;
    for (const char *sv = find_tag(xml, "ScalarVariable", NULL); sv;
         sv = find_tag(sv + 1, "ScalarVariable", NULL)) {
        md_variable *v = next_variable(md, &capacity);
        if (!v) return false;
        double vr;
        if (!attribute(sv, "name", v->name, sizeof v->name) || !number(sv, "valueReference", &vr)) {
            snprintf(error, size, "%s: a ScalarVariable without name or valueReference", path);
            return false;
        }
        v->vr = (uint32_t)vr;
        const char *end = find_tag(sv, "/ScalarVariable", NULL);
        static const char *const kinds[] = {"Real", "Integer", "Boolean", "String"};
        v->kind = KIND_OTHER;
        const char *type_tag = NULL;
        for (int k = 0; k < 4 && !type_tag; k++) {
            type_tag = find_tag(sv, kinds[k], end);
            if (type_tag) v->kind = (var_kind)k;
        }
        v->type = (int)v->kind;
        read_common(v, sv, type_tag);
        md->count++;
    }
    return true;
}

/* FMI 3.0: the variables are the elements of <ModelVariables>, named after their type. */
static bool read_variables3(model_description *md, const char *xml, const char *path, char *error,
                            size_t size)
{
    const char *from = find_tag(xml, "ModelVariables", NULL);
    const char *to = from ? find_tag(from, "/ModelVariables", NULL) : NULL;
    if (!from || !to) {
        snprintf(error, size, "%s: no <ModelVariables>", path);
        return false;
    }
    size_t capacity = 0;
    for (const char *tag = strchr(from + 1, '<'); tag && tag < to; tag = strchr(tag + 1, '<')) {
        int type = -1;
        for (int t = 0; t < T3_TYPES && type < 0; t++) {
            size_t n = strlen(fmi3_type_names[t]);
            if (!strncmp(tag + 1, fmi3_type_names[t], n) && strchr(" \t\r\n/>", tag[1 + n]))
                type = t;
        }
        if (type < 0) continue;
        char causality[32] = "";
        if (attribute(tag, "causality", causality, sizeof causality) &&
            !strcmp(causality, "independent"))
            continue; /* time: not a variable of the block */
        md_variable *v = next_variable(md, &capacity);
        if (!v) return false;
        double vr;
        if (!attribute(tag, "name", v->name, sizeof v->name) ||
            !number(tag, "valueReference", &vr)) {
            snprintf(error, size, "%s: a %s without name or valueReference", path,
                     fmi3_type_names[type]);
            return false;
        }
        v->vr = (uint32_t)vr;
        v->type = type;
        v->single = type == T3_FLOAT32;
        v->kind = type == T3_FLOAT32 || type == T3_FLOAT64 ? KIND_REAL
                  : type == T3_BOOLEAN                     ? KIND_BOOLEAN
                  : type == T3_STRING                      ? KIND_STRING
                  : type <= T3_UINT64                      ? KIND_INTEGER
                                                           : KIND_OTHER;
        read_common(v, tag, tag);
        md->count++;
    }
    md->event_indicators = 0;
    for (const char *e = find_tag(xml, "EventIndicator", NULL); e;
         e = find_tag(e + 1, "EventIndicator", NULL))
        md->event_indicators++;
    return true;
}

bool md_read(model_description *md, const char *path, char *error, size_t size)
{
    memset(md, 0, sizeof *md);
    char *xml = read_file(path, error, size);
    if (!xml) return false;
    bool ok = false;
    const char *root = find_tag(xml, "fmiModelDescription", NULL);
    if (!root || !attribute(root, "fmiVersion", md->fmi_version, sizeof md->fmi_version)) {
        snprintf(error, size, "%s: no fmiModelDescription with fmiVersion", path);
        goto done;
    }
    md->version = md->fmi_version[0] == '3' ? 3 : 2;
    const char *cs = find_tag(root, "CoSimulation", NULL);
    if (!cs ||
        !attribute(root, md->version == 3 ? "instantiationToken" : "guid", md->guid,
                   sizeof md->guid) ||
        !attribute(cs, "modelIdentifier", md->identifier, sizeof md->identifier)) {
        snprintf(error, size, "%s: no fmiModelDescription with %s and CoSimulation", path,
                 md->version == 3 ? "instantiationToken" : "guid");
        goto done;
    }
    const char *me = find_tag(root, "ModelExchange", NULL);
    if (!me || !attribute(me, "modelIdentifier", md->me_identifier, sizeof md->me_identifier))
        md->me_identifier[0] = '\0';
    if (!number(root, "numberOfEventIndicators", &md->event_indicators)) md->event_indicators = -1;
    if (!(md->version == 3 ? read_variables3 : read_variables2)(md, xml, path, error, size))
        goto done;
    ok = md->count > 0;
    if (!ok) snprintf(error, size, "%s: no variables", path);
done:
    free(xml);
    if (!ok) md_free(md);
    return ok;
}

void md_free(model_description *md)
{
    free(md->variables);
    md->variables = NULL;
    md->count = 0;
}

/* ---- callbacks ---- */

static atomic_long live_blocks;
static atomic_long log_messages;
static _Thread_local long failing_allocation; /* 0: none; n: the n-th next one fails */

long live_allocations(void) { return atomic_load(&live_blocks); }
long total_log_messages(void) { return atomic_load(&log_messages); }
void fail_allocation_after(long n) { failing_allocation = n; }

const log_entry *log_get(const log_record *log, int index)
{
    if (index < 0 || index >= log->total || log->total - index > LOG_KEEP) return NULL;
    return &log->kept[index % LOG_KEEP];
}

static void copy_text(char *to, size_t size, const char *from)
{
    snprintf(to, size, "%s", from ? from : "(NULL)");
}

/* An FMI Library based importer reads '#' in a formatted message as the start of a variable
 * reference (#r12#, #i3#, ...) and "##" as a literal '#' (FMI 2.0, 2.1.5). This does the same
 * with the formatted text in place: "##" becomes '#'; any other '#' is what such an importer
 * would report as "Expected type specification character", counted and marked in the text. */
static atomic_long malformed_messages;

static void read_references(char *text, size_t size)
{
    char out[sizeof((log_entry *)0)->text];
    size_t n = 0;
    bool malformed = false;
    for (const char *c = text; *c && n + 1 < sizeof out; c++) {
        if (*c == '#') {
            if (c[1] != '#')
                malformed = true;
            else
                c++;
        }
        out[n++] = *c;
    }
    out[n] = '\0';
    if (malformed) atomic_fetch_add(&malformed_messages, 1);
    snprintf(text, size, "%s%s", malformed ? "MALFORMED (a lone '#'): " : "", out);
}

long malformed_log_messages(void) { return atomic_load(&malformed_messages); }

static atomic_long hash_messages, doubled_hash_messages;

long hash_log_messages(void) { return atomic_load(&hash_messages); }
long doubled_hash_log_messages(void) { return atomic_load(&doubled_hash_messages); }

void log_store3(log_record *log, int status, const char *category, const char *message)
{
    atomic_fetch_add(&log_messages, 1);
    if (message && strchr(message, '#')) atomic_fetch_add(&hash_messages, 1);
    if (message && strstr(message, "##")) atomic_fetch_add(&doubled_hash_messages, 1);
    if (!log) return;
    log_entry *entry = &log->kept[log->total % LOG_KEEP];
    entry->status = (fmi2Status)status;
    copy_text(entry->category, sizeof entry->category, category);
    entry->instance[0] = '\0';
    copy_text(entry->text, sizeof entry->text, message);
    log->total++;
}

void harness_logger(fmi2ComponentEnvironment env, fmi2String instance, fmi2Status status,
                    fmi2String category, fmi2String message, ...)
{
    atomic_fetch_add(&log_messages, 1);
    log_record *log = env;
    if (!log) return;
    log_entry *entry = &log->kept[log->total % LOG_KEEP];
    entry->status = status;
    copy_text(entry->category, sizeof entry->category, category);
    copy_text(entry->instance, sizeof entry->instance, instance);
    if (message) {
        va_list args;
        va_start(args, message);
        vsnprintf(entry->text, sizeof entry->text, message, args);
        va_end(args);
        read_references(entry->text, sizeof entry->text);
    } else {
        copy_text(entry->text, sizeof entry->text, NULL);
    }
    log->total++;
}

void *harness_allocate(size_t count, size_t size)
{
    if (failing_allocation > 0 && --failing_allocation == 0) return NULL;
    void *memory = calloc(count, size); /* FMI 2.0 asks for zeroed memory, as calloc */
    if (memory) atomic_fetch_add(&live_blocks, 1);
    return memory;
}

void harness_free(void *memory)
{
    if (!memory) return;
    atomic_fetch_sub(&live_blocks, 1);
    free(memory);
}

fmi2CallbackFunctions harness_callbacks(log_record *log)
{
    fmi2CallbackFunctions callbacks = {
        .logger = harness_logger,
        .allocateMemory = harness_allocate,
        .freeMemory = harness_free,
        .stepFinished = NULL,
        .componentEnvironment = log,
    };
    return callbacks;
}
