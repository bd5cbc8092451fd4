/* Writes a block's modelDescription.xml, or its interface as JSON (for the documentation), from
 * its interface table (a bundled block's written from its interface.toml). A host program, built
 * per block by CMake from a file that includes the block's interface.c and then this file:
 *
 *     describe xml    > modelDescription/<Block>.xml        FMI 2.0 (make descriptions)
 *     describe xml3   > modelDescription/fmi3/<Block>.xml   FMI 3.0
 *     describe build3 > sources/buildDescription.xml        of the FMI 3.0 FMU
 *     describe json   > <Block>.json                        the interface, for the documentation
 *     describe json3  > fmi3/<Block>.json                   the same with FMI 3.0's types
 *
 * Start values come from the block's own init, so the XML and the binary cannot disagree. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/core.c"

/* The shortest text that reads back as the same double. */
static const char *number(double value, char *text, size_t size)
{
    if (value == floor(value) && fabs(value) < 1e15) {
        snprintf(text, size, "%.0f", value);
        return text;
    }
    for (int digits = 1; digits <= 17; digits++) {
        snprintf(text, size, "%.*g", digits, value);
        if (strtod(text, NULL) == value) break;
    }
    return text;
}

/* text with the characters XML attributes and JSON strings cannot hold as they are. */
static void put_escaped(const char *text, int json)
{
    for (const char *c = text; *c; c++) {
        if (json && (*c == '"' || *c == '\\'))
            printf("\\%c", *c);
        else if (!json && *c == '&')
            fputs("&amp;", stdout);
        else if (!json && *c == '<')
            fputs("&lt;", stdout);
        else if (!json && *c == '>')
            fputs("&gt;", stdout);
        else if (!json && *c == '"')
            fputs("&quot;", stdout);
        else
            putchar(*c);
    }
}

/* An array element's description: "{i}" is its index, "{i+1}" the next one. */
static void put_description(const model_variable *v, uint32_t index, int json)
{
    char text[512] = "";
    size_t n = 0;
    for (const char *c = v->description; *c && n + 12 < sizeof text;) {
        if (!strncmp(c, "{i}", 3))
            n += (size_t)snprintf(text + n, sizeof text - n, "%u", (unsigned)index), c += 3;
        else if (!strncmp(c, "{i+1}", 5))
            n += (size_t)snprintf(text + n, sizeof text - n, "%u", (unsigned)index + 1), c += 5;
        else
            text[n++] = *c++;
    }
    text[n] = '\0';
    put_escaped(text, json);
}

/* FMI integers carry no unit: a UDINT's unit is in its description. */
static const char *unit_of(const model_variable *v)
{
    if (var_is_integer(v->type)) return NULL;
    if (v->unit) return v->unit;
    return v->type == VAR_TIME || v->type == VAR_CYCLE ? "s" : NULL;
}

static const char *fmi2_type(var_type t)
{
    return t == VAR_BOOL       ? "Boolean"
           : var_is_integer(t) ? "Integer"
           : var_is_string(t)  ? "String"
                               : "Real";
}

static const char *const iec_names[] = {
    [VAR_CYCLE] = "cycle",    [VAR_LREAL] = "LREAL", [VAR_TIME] = "TIME",
    [VAR_INT] = "INT",        [VAR_WORD] = "WORD",   [VAR_REAL] = "REAL",
    [VAR_UDINT] = "UDINT",    [VAR_BOOL] = "BOOL",   [VAR_DINT] = "DINT",
    [VAR_UINT] = "UINT",      [VAR_SINT] = "SINT",   [VAR_USINT] = "USINT",
    [VAR_BYTE] = "BYTE",      [VAR_DWORD] = "DWORD", [VAR_STRING] = "STRING",
    [VAR_WSTRING] = "WSTRING"};

/* A string variable's start value, as UTF-8 escaped for XML (json 0) or JSON: a control
 * character as a character reference (the compiler takes tab, LF and CR only, which XML 1.0
 * allows), or \u00XX. */
static void put_string_start(fmu_image *image, const model_variable *v, uint32_t index, int json)
{
    char text[CORE_STRING_UTF8], one[2] = {0, 0};
    core_element e = {v, index};
    core_string_to_utf8(core_field(image, &e), text);
    for (const char *c = text; *c; c++) {
        if ((unsigned char)*c < 0x20 && json)
            printf("\\u%04x", (unsigned)(unsigned char)*c);
        else if ((unsigned char)*c < 0x20)
            printf("&#x%X;", (unsigned)(unsigned char)*c);
        else
            one[0] = *c, put_escaped(one, json);
    }
}

static const char *causality_of(const model_variable *v)
{
    return v->role == ROLE_INPUT    ? "input"
           : v->role == ROLE_OUTPUT ? "output"
           : v->role == ROLE_LOCAL  ? "local"
                                    : "parameter";
}

static const char *variability_of(const model_variable *v)
{
    return v->role == ROLE_FIXED_PARAMETER     ? "fixed"
           : v->role == ROLE_TUNABLE_PARAMETER ? "tunable"
                                               : "discrete";
}

/* The scalar variables in the order of the XML: the table's order, with the elements of
 * arrays of one struct (setpoints[i].outputValue, setpoints[i].time) interleaved. */
typedef struct {
    const model_variable *var;
    uint32_t index;
} scalar;

static size_t scalars(scalar *out, size_t max)
{
    size_t n = 0;
    for (size_t i = 0; i < lgf_model.variable_count;) {
        const model_variable *v = &lgf_model.variables[i];
        size_t members = 1;
        while (v->member && i + members < lgf_model.variable_count &&
               lgf_model.variables[i + members].member &&
               !strcmp(lgf_model.variables[i + members].name, v->name))
            members++;
        for (uint32_t k = 0; k < v->count; k++)
            for (size_t m = 0; m < members && n < max; m++) out[n++] = (scalar){v + m, k};
        i += members;
    }
    return n;
}

/* A compiled SCL block's name may hold & < > " (a quoted name of TIA, docs/scl.md §2). */
/* A number variable's start value as XML and JSON write it: true or false for a Boolean, else
 * the shortest number text. */
static void put_number_start(fmu_image *image, const model_variable *v, uint32_t index)
{
    char text[32];
    core_element e = {v, index};
    double start = core_read_number(image, &e);
    if (v->type == VAR_BOOL)
        printf("%s", start ? "true" : "false");
    else
        printf("%s", number(start, text, sizeof text));
}

static void put_name(const scalar *s)
{
    put_escaped(s->var->name, 0);
    if (s->var->member) printf("[%u]%s", (unsigned)s->index, s->var->member);
}

static bool has_unit(const char *unit, const scalar *all, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (unit_of(all[i].var) && !strcmp(unit_of(all[i].var), unit)) return true;
    return false;
}

/* The parts both FMI versions write alike: units, log categories, the default experiment. */
static void write_common(fmu_image *image, const scalar *all, size_t n)
{
    char a[32], b[32];
    printf("  <UnitDefinitions>\n");
    static const struct {
        const char *name, *base;
    } units[] = {{"s", "s=\"1\""},
                 {"ms", "s=\"1\" factor=\"0.001\""},
                 {"1/s", "s=\"-1\""},
                 {"Hz", "s=\"-1\""}};
    for (size_t u = 0; u < sizeof units / sizeof units[0]; u++)
        if (has_unit(units[u].name, all, n))
            printf("    <Unit name=\"%s\"><BaseUnit %s/></Unit>\n", units[u].name, units[u].base);
    printf("  </UnitDefinitions>\n\n");
    printf("  <LogCategories>\n"
           "    <Category name=\"logStatusWarning\" description=\"Warnings: rounded or truncated "
           "parameters, block error codes in status\"/>\n"
           "    <Category name=\"logStatusDiscard\" description=\"Requests the FMU cannot serve, "
           "e.g. a status kind fmi2Get*Status cannot provide\"/>\n"
           "    <Category name=\"logStatusError\" description=\"Rejected calls: the function, the "
           "variable and the allowed values\"/>\n"
           "    <Category name=\"logAll\" description=\"A trace: the PLC calls each step "
           "executes\"/>\n"
           "  </LogCategories>\n\n");
    printf("  <DefaultExperiment startTime=\"0\" stopTime=\"%s\" stepSize=\"%s\"/>\n\n",
           number(lgf_model.stop_time, a, sizeof a), number(image->cycle_us / 1e6, b, sizeof b));
}

static void write_xml(fmu_image *image, const scalar *all, size_t n)
{
    char a[32];
    bool structured = false;
    for (size_t i = 0; i < n; i++) structured |= all[i].var->member != NULL;
    printf("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<fmiModelDescription\n"
           "  fmiVersion=\"2.0\"\n  modelName=\"%s\"\n  guid=\"%s\"\n  description=\"",
           lgf_model.identifier, lgf_model.guid);
    put_escaped(lgf_model.description, 0);
    printf("\"\n  generationTool=\"lgf-fmus\"\n  variableNamingConvention=\"%s\"\n"
           "  numberOfEventIndicators=\"0\">\n\n",
           structured ? "structured" : "flat");
    /* Both interfaces in one binary (docs/behaviour.md §1.11): the block is a sampled system
     * without continuous states, whose calls are time events in Model Exchange. */
    printf("  <ModelExchange\n    modelIdentifier=\"%s\"\n"
           "    completedIntegratorStepNotNeeded=\"true\"\n"
           "    canGetAndSetFMUstate=\"true\"\n    canSerializeFMUstate=\"true\"\n"
           "    canNotUseMemoryManagementFunctions=\"false\"\n"
           "    providesDirectionalDerivative=\"false\">\n"
           "    <SourceFiles>\n      <File name=\"%s.c\"/>\n    </SourceFiles>\n"
           "  </ModelExchange>\n\n",
           lgf_model.identifier, lgf_model.identifier);
    printf("  <CoSimulation\n    modelIdentifier=\"%s\"\n"
           "    canHandleVariableCommunicationStepSize=\"true\"\n"
           "    canGetAndSetFMUstate=\"true\"\n    canSerializeFMUstate=\"true\"\n"
           "    canNotUseMemoryManagementFunctions=\"false\"\n    canInterpolateInputs=\"false\"\n"
           "    maxOutputDerivativeOrder=\"0\"\n    providesDirectionalDerivative=\"false\">\n"
           "    <SourceFiles>\n      <File name=\"%s.c\"/>\n    </SourceFiles>\n"
           "  </CoSimulation>\n\n",
           lgf_model.identifier, lgf_model.identifier);
    write_common(image, all, n);
    printf("  <ModelVariables>\n");
    for (size_t i = 0; i < n; i++) {
        const scalar *s = &all[i];
        const model_variable *v = s->var;
        printf("    <!-- %zu --><ScalarVariable name=\"", i + 1);
        put_name(s);
        printf(
            "\" valueReference=\"%u\" causality=\"%s\" variability=\"%s\"%s\n      description=\"",
            (unsigned)(v->vr + s->index), causality_of(v), variability_of(v),
            var_is_computed(v->role) ? " initial=\"calculated\""
            : v->role == ROLE_INPUT  ? ""
                                     : " initial=\"exact\"");
        put_description(v, s->index, 0);
        printf("\">\n      <%s", fmi2_type(v->type));
        if (unit_of(v)) printf(" unit=\"%s\"", unit_of(v));
        bool ranged = v->type != VAR_BOOL && !var_is_string(v->type); /* a string: its length */
        if (ranged && isfinite(v->min)) printf(" min=\"%s\"", number(v->min, a, sizeof a));
        /* fmi2Integer is 32 bits signed: a UDINT reaches 2147483647 through FMI 2.0 */
        double max =
            v->type == VAR_UDINT || v->type == VAR_DWORD ? fmin(v->max, 2147483647.0) : v->max;
        if (ranged && isfinite(max)) printf(" max=\"%s\"", number(max, a, sizeof a));
        if (!var_is_computed(v->role) && var_is_string(v->type)) {
            printf(" start=\"");
            put_string_start(image, v, s->index, 0);
            printf("\"");
        } else if (!var_is_computed(v->role)) {
            printf(" start=\"");
            put_number_start(image, v, s->index);
            printf("\"");
        }
        printf("/>\n    </ScalarVariable>\n");
    }
    /* Every output depends on every input: a call reads them all. No dependenciesKind: the
     * kinds other than "dependent" name linear factors of Real knowns, which these are not. */
    printf("  </ModelVariables>\n\n  <ModelStructure>\n");
    /* The schema wants at least one Unknown in <Outputs> and <InitialUnknowns>: a block without
     * outputs (compiled SCL may have none) leaves both elements out. */
    bool any_output = false;
    for (size_t i = 0; i < n; i++) any_output |= all[i].var->role == ROLE_OUTPUT;
    if (any_output) {
        printf("    <Outputs>\n");
        for (size_t i = 0; i < n; i++) {
            if (all[i].var->role != ROLE_OUTPUT) continue;
            printf("      <Unknown index=\"%zu\" dependencies=\"", i + 1);
            const char *separator = "";
            for (size_t k = 0; k < n; k++)
                if (all[k].var->role == ROLE_INPUT)
                    printf("%s%zu", separator, k + 1), separator = " ";
            printf("\"/>\n");
        }
        printf("    </Outputs>\n    <InitialUnknowns>\n");
        for (size_t i = 0; i < n; i++)
            if (all[i].var->role == ROLE_OUTPUT) printf("      <Unknown index=\"%zu\"/>\n", i + 1);
        printf("    </InitialUnknowns>\n");
    }
    printf("  </ModelStructure>\n</fmiModelDescription>\n");
}

/* ---- FMI 3.0 (docs/behaviour.md §7): the same table with the PLC's own integer widths ---- */

static const char *fmi3_type(var_type t)
{
    return t == VAR_BOOL      ? "Boolean"
           : t == VAR_INT     ? "Int16"
           : t == VAR_WORD    ? "UInt16"
           : t == VAR_UDINT   ? "UInt32"
           : t == VAR_DWORD   ? "UInt32"
           : t == VAR_DINT    ? "Int32"
           : t == VAR_UINT    ? "UInt16"
           : t == VAR_SINT    ? "Int8"
           : t == VAR_USINT   ? "UInt8"
           : t == VAR_BYTE    ? "UInt8"
           : t == VAR_REAL    ? "Float32"
           : var_is_string(t) ? "String"
                              : "Float64";
}

static void write_xml3(fmu_image *image, const scalar *all, size_t n)
{
    char a[32];
    bool structured = false;
    for (size_t i = 0; i < n; i++) structured |= all[i].var->member != NULL;
    printf("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<fmiModelDescription\n"
           "  fmiVersion=\"3.0\"\n  modelName=\"%s\"\n  instantiationToken=\"%s\"\n"
           "  description=\"",
           lgf_model.identifier, lgf_model.guid);
    put_escaped(lgf_model.description, 0);
    printf("\"\n  generationTool=\"lgf-fmus\"\n  variableNamingConvention=\"%s\">\n\n",
           structured ? "structured" : "flat");
    printf("  <ModelExchange\n    modelIdentifier=\"%s\"\n    canGetAndSetFMUState=\"true\"\n"
           "    canSerializeFMUState=\"true\"\n    needsCompletedIntegratorStep=\"false\"/>\n\n",
           lgf_model.identifier);
    printf("  <CoSimulation\n    modelIdentifier=\"%s\"\n    canGetAndSetFMUState=\"true\"\n"
           "    canSerializeFMUState=\"true\"\n"
           "    canHandleVariableCommunicationStepSize=\"true\"\n    hasEventMode=\"false\"/>\n\n",
           lgf_model.identifier);
    write_common(image, all, n);
    printf("  <ModelVariables>\n"
           "    <Float64 name=\"time\" valueReference=\"%u\" causality=\"independent\" "
           "variability=\"continuous\" unit=\"s\"\n      description=\"Simulation time\"/>\n",
           TIME_VR);
    for (size_t i = 0; i < n; i++) {
        const scalar *s = &all[i];
        const model_variable *v = s->var;
        printf("    <%s name=\"", fmi3_type(v->type));
        put_name(s);
        printf("\" valueReference=\"%u\" causality=\"%s\" variability=\"%s\"%s",
               (unsigned)(v->vr + s->index), causality_of(v), variability_of(v),
               var_is_computed(v->role) ? " initial=\"calculated\""
               : v->role == ROLE_INPUT  ? ""
                                        : " initial=\"exact\"");
        if (unit_of(v)) printf(" unit=\"%s\"", unit_of(v));
        bool ranged = v->type != VAR_BOOL && !var_is_string(v->type); /* a string: its length */
        if (ranged && isfinite(v->min)) printf(" min=\"%s\"", number(v->min, a, sizeof a));
        if (ranged && isfinite(v->max)) printf(" max=\"%s\"", number(v->max, a, sizeof a));
        if (var_is_string(v->type)) { /* FMI 3.0: a String's start is an element */
            printf("\n      description=\"");
            put_description(v, s->index, 0);
            printf("\">\n");
            if (!var_is_computed(v->role)) {
                printf("      <Start value=\"");
                put_string_start(image, v, s->index, 0);
                printf("\"/>\n");
            }
            printf("    </String>\n");
            continue;
        }
        if (!var_is_computed(v->role)) {
            printf(" start=\"");
            put_number_start(image, v, s->index);
            printf("\"");
        }
        printf("\n      description=\"");
        put_description(v, s->index, 0);
        printf("\"/>\n");
    }
    /* FMI 3.0 names the knowns by value reference. */
    printf("  </ModelVariables>\n\n  <ModelStructure>\n");
    for (size_t i = 0; i < n; i++) {
        if (all[i].var->role != ROLE_OUTPUT) continue;
        printf("    <Output valueReference=\"%u\" dependencies=\"",
               (unsigned)(all[i].var->vr + all[i].index));
        const char *separator = "";
        for (size_t k = 0; k < n; k++)
            if (all[k].var->role == ROLE_INPUT)
                printf("%s%u", separator, (unsigned)(all[k].var->vr + all[k].index)),
                    separator = " ";
        printf("\"/>\n");
    }
    for (size_t i = 0; i < n; i++)
        if (all[i].var->role == ROLE_OUTPUT)
            printf("    <InitialUnknown valueReference=\"%u\"/>\n",
                   (unsigned)(all[i].var->vr + all[i].index));
    printf("  </ModelStructure>\n</fmiModelDescription>\n");
}

/* sources/buildDescription.xml of the FMI 3.0 FMU: the one translation unit. */
static void write_build_description(void)
{
    printf("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
           "<fmiBuildDescription fmiVersion=\"3.0\">\n"
           "  <BuildConfiguration modelIdentifier=\"%s\">\n"
           "    <SourceFileSet language=\"C99\">\n"
           "      <SourceFile name=\"%s.c\"/>\n"
           "      <IncludeDirectory name=\".\"/>\n"
           "    </SourceFileSet>\n"
           "  </BuildConfiguration>\n"
           "</fmiBuildDescription>\n",
           lgf_model.identifier, lgf_model.identifier);
}

/* The interface for the documentation generator: the table as it is (arrays as one entry),
 * with IEC types, units, ranges, start values and the original names; the FMI types and ranges
 * of FMI <version> (a UDINT or DWORD stops at 2147483647 in FMI 2.0, as its modelDescription). */
static void write_json(fmu_image *image, int version)
{
    char a[32];
    printf("{\n  \"modelIdentifier\": \"%s\",\n  \"guid\": \"%s\",\n  \"description\": \"",
           lgf_model.identifier, lgf_model.guid);
    put_escaped(lgf_model.description, 1);
    printf("\",\n  \"variables\": [\n");
    for (size_t i = 0; i < lgf_model.variable_count; i++) {
        const model_variable *v = &lgf_model.variables[i];
        fputs("    {\"name\": \"", stdout);
        put_escaped(v->name, 1);
        printf("%s\", \"vr\": %u, \"count\": %u, \"type\": \"%s\", "
               "\"iec\": \"%s\", \"causality\": \"%s\", \"variability\": \"%s\", \"unit\": \"%s\"",
               v->member ? "[i]" : "", (unsigned)v->vr, (unsigned)v->count,
               version == 3 ? fmi3_type(v->type) : fmi2_type(v->type), iec_names[v->type],
               causality_of(v), variability_of(v), unit_of(v) ? unit_of(v) : "");
        if (v->member) printf(", \"member\": \"%s\"", v->member);
        bool ranged = v->type != VAR_BOOL && !var_is_string(v->type); /* a string: its length */
        if (ranged && isfinite(v->min)) printf(", \"min\": %s", number(v->min, a, sizeof a));
        double max = version == 2 && (v->type == VAR_UDINT || v->type == VAR_DWORD)
                         ? fmin(v->max, 2147483647.0)
                         : v->max;
        if (ranged && isfinite(max)) printf(", \"max\": %s", number(max, a, sizeof a));
        if (!var_is_computed(v->role)) {
            printf(", \"start\": [");
            for (uint32_t k = 0; k < v->count; k++) {
                if (var_is_string(v->type)) {
                    printf("%s\"", k ? ", " : "");
                    put_string_start(image, v, k, 1);
                    printf("\"");
                    continue;
                }
                printf("%s", k ? ", " : "");
                put_number_start(image, v, k);
            }
            printf("]");
        }
        if (v->original) {
            printf(", \"original\": \"");
            put_escaped(v->original, 1);
            printf("\"");
        }
        printf(", \"description\": \"");
        put_escaped(v->description, 1);
        printf("\"}%s\n", i + 1 < lgf_model.variable_count ? "," : "");
    }
    printf("  ]\n}\n");
}

int main(int argc, char **argv)
{
    fmu_image *image = calloc(1, sizeof(fmu_image) + lgf_model.data_size);
    if (!image) return 1;
    core_image_reset(image);
    static scalar all[4096];
    size_t n = scalars(all, sizeof all / sizeof all[0]);
    if (argc == 2 && !strcmp(argv[1], "xml"))
        write_xml(image, all, n);
    else if (argc == 2 && !strcmp(argv[1], "xml3"))
        write_xml3(image, all, n);
    else if (argc == 2 && !strcmp(argv[1], "build3"))
        write_build_description();
    else if (argc == 2 && !strcmp(argv[1], "json"))
        write_json(image, 2);
    else if (argc == 2 && !strcmp(argv[1], "json3"))
        write_json(image, 3);
    else {
        fprintf(stderr, "usage: %s xml|xml3|build3|json|json3\n", argv[0]);
        return 2;
    }
    return ferror(stdout) ? 1 : 0;
}
