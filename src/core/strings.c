/* Get and set of the String variables (VAR_STRING, VAR_WSTRING: S7's STRING[n] and WSTRING[n]
 * of compiled SCL, docs/scl.md §3.1), in UTF-8 as FMI passes strings: a STRING's characters
 * are the codes 0 to 255 (U+0000 to U+00FF), a WSTRING's 0 to 16#FFFF. A set is refused, and
 * the instance left as it was, for a value longer than the variable's maximum length, a
 * character outside its codes, or text that is no UTF-8 (docs/behaviour.md §1.7). */

/* The longest UTF-8 of a string: 3 bytes a character, and the terminating 0. */
#define CORE_STRING_UTF8 (CORE_STRING_CAPACITY * 3 + 1)

/* s as UTF-8 into text (CORE_STRING_UTF8 bytes). */
static void core_string_to_utf8(const core_string *s, char *text)
{
    size_t n = 0;
    unsigned len = s->len <= CORE_STRING_CAPACITY ? s->len : CORE_STRING_CAPACITY;
    for (unsigned i = 0; i < len; i++) {
        unsigned c = s->data[i];
        if (c < 0x80) {
            text[n++] = (char)c;
        } else if (c < 0x800) {
            text[n++] = (char)(0xC0 | c >> 6);
            text[n++] = (char)(0x80 | (c & 0x3F));
        } else {
            text[n++] = (char)(0xE0 | c >> 12);
            text[n++] = (char)(0x80 | (c >> 6 & 0x3F));
            text[n++] = (char)(0x80 | (c & 0x3F));
        }
    }
    text[n] = '\0';
}

/* The next character of UTF-8 text at *at, advancing *at; -1 where the bytes are no UTF-8 (a
 * stray or missing continuation byte, an overlong form, a surrogate). */
static long core_next_utf8(const unsigned char *text, size_t *at)
{
    unsigned char b = text[*at];
    int more = b < 0x80             ? 0
               : (b & 0xE0) == 0xC0 ? 1
               : (b & 0xF0) == 0xE0 ? 2
               : (b & 0xF8) == 0xF0 ? 3
                                    : -1;
    if (more < 0) return -1;
    long c = more == 0 ? b : more == 1 ? b & 0x1F : more == 2 ? b & 0x0F : b & 0x07;
    for (int k = 1; k <= more; k++) {
        unsigned char next = text[*at + (size_t)k];
        if ((next & 0xC0) != 0x80) return -1;
        c = c << 6 | (next & 0x3F);
    }
    static const long least[] = {0, 0x80, 0x800, 0x10000};
    if (c < least[more] || c > 0x10FFFF || (c >= 0xD800 && c <= 0xDFFF)) return -1;
    *at += (size_t)more + 1;
    return c;
}

/* Why text cannot be v's value (a sentence into why), or NULL; the characters into s when it
 * can (s may be NULL: check only). */
static const char *core_string_refusal(const model_variable *v, const char *text, core_string *s,
                                       char *why, size_t size)
{
    long top = v->type == VAR_STRING ? 0xFF : 0xFFFF;
    size_t at = 0, count = 0;
    while (text[at]) {
        long c = core_next_utf8((const unsigned char *)text, &at);
        if (c < 0) {
            snprintf(why, size, "the text is no UTF-8 at byte %llu", (unsigned long long)at + 1);
            return why;
        }
        if (c > top) {
            snprintf(why, size, "its character U+%04lX is beyond a %s's (U+0000 to U+%04lX)", c,
                     v->type == VAR_STRING ? "STRING" : "WSTRING", top);
            return why;
        }
        if (s && count < CORE_STRING_CAPACITY) s->data[count] = (uint16_t)c;
        count++;
    }
    if (count > (size_t)v->max) {
        snprintf(why, size, "it has %llu characters, more than its %s[%.0f] holds",
                 (unsigned long long)count, v->type == VAR_STRING ? "STRING" : "WSTRING", v->max);
        return why;
    }
    if (s) s->len = (uint16_t)count, s->max = (uint16_t)v->max;
    return NULL;
}

/* Whether a restored string is one a run can leave: its lengths the variable's, its
 * characters within its codes. */
static bool core_string_is_valid(const model_variable *v, const core_string *s)
{
    if (s->max != (uint16_t)v->max || s->len > s->max) return false;
    for (unsigned i = 0; i < s->len; i++)
        if (v->type == VAR_STRING && s->data[i] > 0xFF) return false;
    return true;
}

static lgf_status core_set_strings(instance *inst, const char *function, const fmi_types *types,
                                   int kind, const uint32_t vr[], size_t nvr,
                                   const char *const values[])
{
    if (!core_arrays_given(inst, function, vr, nvr, values)) return STATUS_ERROR;
    core_element e = {NULL, 0};
    char why[256], name[64];
    for (size_t i = 0; i < nvr; i++) {
        const model_variable *v = core_variable(inst, vr[i]);
        if (!v || types->kind_of[v->type] != kind || core_set_refusal(inst, v, 0) != SET_ALLOWED) {
            core_refuse_set(inst, function, types, kind, vr[i], 0);
            return STATUS_ERROR;
        }
        core_find(inst, vr[i], &e);
        if (!values[i]) {
            core_log(inst, STATUS_ERROR, "%s: the value of %s is NULL; the value was not applied.",
                     function, core_name_of(&e, name, sizeof name));
            return STATUS_ERROR;
        }
        if (core_string_refusal(v, values[i], NULL, why, sizeof why)) {
            core_log(inst, STATUS_ERROR,
                     "%s: %s = \"%.40s\" is refused: %s; the value was not applied.", function,
                     core_name_of(&e, name, sizeof name), values[i], why);
            return STATUS_ERROR;
        }
    }
    fmu_image *image = inst->image, *saved = inst->scratch;
    if (lgf_model.check) core_copy_fields(inst, saved, image, vr, nvr);
    for (size_t i = 0; i < nvr; i++) {
        core_find(inst, vr[i], &e);
        core_string_refusal(e.var, values[i], core_field(image, &e), why, sizeof why);
    }
    if (!core_check_set(inst, function, vr, nvr)) return STATUS_ERROR;
    return STATUS_OK;
}

/* The values as UTF-8 in the instance's buffer, valid until the next get of strings. */
static lgf_status core_get_strings(instance *inst, const char *function, const fmi_types *types,
                                   int kind, const uint32_t vr[], size_t nvr, const char *values[])
{
    if (!core_arrays_given(inst, function, vr, nvr, values)) return STATUS_ERROR;
    if (nvr > inst->text_count) {
        char *text = core_allocate(inst, nvr * CORE_STRING_UTF8);
        if (!text) {
            core_log(inst, STATUS_ERROR, "%s: out of memory.", function);
            return STATUS_ERROR;
        }
        core_release(inst, inst->text);
        inst->text = text, inst->text_count = nvr;
    }
    const fmu_image *outputs = core_outputs_to_get(inst, nvr);
    for (size_t i = 0; i < nvr; i++) {
        core_element e;
        if (!core_resolve(inst, function, types, kind, vr[i], &e)) return STATUS_ERROR;
        const fmu_image *image = var_is_computed(e.var->role) ? outputs : inst->image;
        char *text = inst->text + i * CORE_STRING_UTF8;
        core_string_to_utf8(core_field(image, &e), text);
        values[i] = text;
    }
    return STATUS_OK;
}
