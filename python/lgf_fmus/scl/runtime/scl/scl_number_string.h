/* S7's conversions between character strings and numbers for the C that lgf_fmus.scl generates
 * (docs/scl.md §3.5 [S7-VAL-STRG], [S7-STRG-VAL], [DEC-NUMBER-STRING]): VAL_STRG and STRG_VAL
 * with the FORMAT word, P, SIZE and PREC as Siemens' S7-1200 system manual documents them
 * ("String and character": STRG_VAL, VAL_STRG, the ENO conditions and the tables of examples),
 * and <integer>_TO_STRING, STRING_TO_<integer>. An error leaves OUT as the manual says (a string
 * unchanged, a number 0); the CPU's ENO is not modelled (docs/scl.md [DEC-ENO]). Our own code,
 * part of every compiled FMU's sources/. */
#ifndef LGF_SCL_NUMBER_STRING_H
#define LGF_SCL_NUMBER_STRING_H

#include <stdbool.h>
#include <stdint.h>

#include "scl/scl_string.h"

/* The bits of FORMAT (S7-1200 system manual, "Format of the VAL_STRG instruction", "Format of
 * the STRG_VAL instruction"); a FORMAT with any other bit set is illegal. */
#define SCL_FORMAT_COMMA 0x1u       /* r: ',' is the decimal point, '.' the thousands separator */
#define SCL_FORMAT_EXPONENTIAL 0x2u /* f: exponential notation */
#define SCL_FORMAT_SIGN 0x4u        /* s: '+' before a value >= 0 too */
#define SCL_FORMAT_ILLEGAL 0xFFF8u

/* The longest text of an integer VAL_STRG writes: a sign, PREC (a USInt) + 1 digits, the point */
#define SCL_NUMBER_TEXT 260

/* The text of an integer in fixed point: <sign><digits without leading zeros>, and with PREC >
 * 0 the point or comma before the last PREC digits ("If the parameter IN value is an integer,
 * then PREC specifies the location of the decimal point": 123 with PREC 1 is 12.3, 0 with PREC
 * 2 is 0.00). Its length. */
static inline int scl_integer_text(char *text, int64_t value, int prec, unsigned format)
{
    char digits[24];
    int n = 0;
    uint64_t magnitude = value < 0 ? UINT64_C(0) - (uint64_t)value : (uint64_t)value;
    do {
        digits[n++] = (char)('0' + magnitude % 10);
        magnitude /= 10;
    } while (magnitude != 0);
    int length = 0;
    if (value < 0) {
        text[length++] = '-';
    } else if (format & SCL_FORMAT_SIGN) {
        text[length++] = '+';
    }
    /* the digits as written, with zeros before them up to the one left of the point */
    int shown = n > prec ? n : prec + 1;
    for (int i = shown - 1; i >= 0; i--) {
        if (i == prec - 1 && prec > 0) text[length++] = (format & SCL_FORMAT_COMMA) ? ',' : '.';
        text[length++] = i < n ? digits[i] : '0';
    }
    return length;
}

/* VAL_STRG's writing of a text of n characters into *out (its declared maximum length max) at
 * position p (1-based), right-justified in SIZE characters (leading spaces), or as it is for SIZE
 * 0 ("the characters overwrite at position P in the OUT string without limitation"); from a P
 * beyond the current length, spaces up to P and the text appended. The characters of OUT from P
 * on are replaced, those after them stay; the current length grows where the text reaches past
 * it. Errors leave *out unchanged: P = 0, a text longer than SIZE, SIZE characters from P beyond
 * the maximum length; with SIZE 0, the text is cut at the maximum length ("The conversion ends if
 * the maximum OUT string length is reached"), and a P beyond it is an error (docs/scl.md
 * [DEC-VAL-STRG]). */
static inline void scl_val_strg_place(scl_string *out, int max, const char *text, int n,
                                      int64_t size, int64_t p)
{
    if (p < 1 || p > max || (size > 0 && n > size)) return;
    int64_t width = size > 0 ? size : n;
    if (p - 1 + width > max) {
        if (size > 0) return;
        width = max - (p - 1);
        n = (int)width;
    }
    int first = (int)(p - 1);
    for (int i = out->len; i < first; i++) out->data[i] = ' ';
    int spaces = (int)width - n;
    for (int i = 0; i < spaces; i++) out->data[first + i] = ' ';
    for (int i = 0; i < n; i++) out->data[first + spaces + i] = (unsigned char)text[i];
    int end = first + (int)width;
    if (end > out->len) out->len = (uint16_t)end;
    out->max = (uint16_t)max;
}

/* VAL_STRG(IN := an integer, SIZE, PREC, FORMAT, P, OUT => *out): an illegal FORMAT, or a SIZE
 * other than 0 not greater than PREC ("Parameter SIZE must be greater than parameter PREC"),
 * leave *out unchanged. An integer is written in fixed point whatever the notation bit
 * (docs/scl.md [DEC-VAL-STRG]). */
static inline void scl_val_strg_integer(scl_string *out, int max, int64_t value, int64_t size,
                                        int64_t prec, uint16_t format, int64_t p)
{
    if ((format & SCL_FORMAT_ILLEGAL) != 0 || (size != 0 && size <= prec)) return;
    char text[SCL_NUMBER_TEXT];
    int n = scl_integer_text(text, value, (int)prec, format);
    scl_val_strg_place(out, max, text, n, size, p);
}

/* A number read from a string: whether one was, its integer part (saturated at the limits of 64
 * bits) and the 1-based position of the first character after it. */
typedef struct {
    bool ok;
    bool negative;
    bool huge; /* beyond the 64-bit range */
    uint64_t whole;
    int64_t next;
} scl_number_read;

/* STRG_VAL's reading from position p (1-based) of s: leading spaces skipped, a sign, digits with
 * the thousands separators left of the decimal point ignored, the decimal point and the digits
 * after it, and in exponential notation an exponent (e or E, a sign, digits); it ends at the
 * first character that does not continue the number (S7-1200 system manual, STRG_VAL: "Rules
 * for STRG_VAL conversion" and its table of examples: "00123AB" is 123, "1.23E-4" is 1.23
 * unless in exponential notation, "12,345.67" with the comma as the point is 12.345). No digit
 * ("A123", "++123", "+-123"), P = 0 or P beyond the current length ("", the ENO conditions):
 * not ok. The integer part is that of the number's value: its digits moved by the exponent,
 * the fraction dropped ("123.45" to an Int is 123). */
static inline scl_number_read scl_read_number(scl_string s, uint16_t format, int64_t p)
{
    scl_number_read r = {0};
    if ((format & SCL_FORMAT_ILLEGAL) != 0 || p < 1 || p > s.len) return r;
    uint16_t point = (format & SCL_FORMAT_COMMA) ? ',' : '.';
    uint16_t separator = (format & SCL_FORMAT_COMMA) ? '.' : ',';
    int i = (int)(p - 1);
    while (i < s.len && s.data[i] == ' ') i++;
    if (i < s.len && (s.data[i] == '+' || s.data[i] == '-')) r.negative = s.data[i++] == '-';
    /* the digits, and where the point stands among them */
    uint8_t digits[SCL_STRING_CAPACITY];
    int count = 0, before = -1;
    for (; i < s.len; i++) {
        uint16_t c = s.data[i];
        if (c >= '0' && c <= '9') {
            digits[count++] = (uint8_t)(c - '0');
        } else if (c == separator && before < 0) {
            continue;
        } else if (c == point && before < 0) {
            before = count;
        } else {
            break;
        }
    }
    if (count == 0) return r;
    if (before < 0) before = count;
    int64_t exponent = 0;
    if ((format & SCL_FORMAT_EXPONENTIAL) && i < s.len && (s.data[i] == 'e' || s.data[i] == 'E')) {
        int j = i + 1;
        bool minus = false;
        if (j < s.len && (s.data[j] == '+' || s.data[j] == '-')) minus = s.data[j++] == '-';
        if (j < s.len && s.data[j] >= '0' && s.data[j] <= '9') {
            for (; j < s.len && s.data[j] >= '0' && s.data[j] <= '9'; j++) {
                if (exponent < 100000) exponent = exponent * 10 + (s.data[j] - '0');
            }
            exponent = minus ? -exponent : exponent;
            i = j;
        }
    }
    /* the integer part: the digits left of the point once the exponent has moved it */
    int64_t left = before + exponent;
    for (int64_t k = 0; k < left; k++) {
        uint64_t d = k < count ? digits[k] : 0;
        if (r.whole > (UINT64_MAX - d) / 10) {
            r.huge = true;
            break;
        }
        r.whole = r.whole * 10 + d;
    }
    r.ok = true;
    r.next = i + 1;
    return r;
}

/* STRG_VAL into an integer of the range low .. high: the integer part of the number read, 0
 * where none is or it is beyond the range ("12345" to a SInt: 0, "The converted number value is
 * too large for the specified OUT data type"); *next (where given) the position after the
 * number, unchanged on an error (docs/scl.md [DEC-STRG-VAL]). */
static inline int64_t scl_strg_val_integer(scl_string s, uint16_t format, int64_t p, uint16_t *next,
                                           int64_t low, int64_t high)
{
    scl_number_read r = scl_read_number(s, format, p);
    if (!r.ok || r.huge) return 0;
    uint64_t limit = r.negative ? (uint64_t)0 - (uint64_t)low : (uint64_t)high;
    if (r.whole > limit) return 0;
    if (next != NULL) *next = (uint16_t)r.next;
    return r.negative ? (int64_t)(UINT64_C(0) - r.whole) : (int64_t)r.whole;
}

/* <integer>_TO_STRING: the sign ('-', or '+' for a value >= 0) and the digits without leading
 * zeros (docs/scl.md [DEC-NUMBER-STRING]). */
static inline scl_string scl_integer_to_string(int64_t value)
{
    char text[SCL_NUMBER_TEXT];
    int n = scl_integer_text(text, value, 0, SCL_FORMAT_SIGN);
    return scl_string_of(text, n);
}

/* STRING_TO_<integer>: STRG_VAL of the whole string in FORMAT 16#0000, 0 where it reads no
 * number or one beyond the range low .. high (docs/scl.md [DEC-NUMBER-STRING]). */
static inline int64_t scl_string_to_integer(scl_string s, int64_t low, int64_t high)
{
    return scl_strg_val_integer(s, 0, 1, NULL, low, high);
}

#endif
