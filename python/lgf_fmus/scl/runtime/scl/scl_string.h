/* S7's character strings for the C that lgf_fmus.scl generates (docs/scl.md §3.1 [S7-STRING],
 * §3.5): STRING[n] and WSTRING[n] as S7 lays them out, the maximum length, the current length
 * and the characters (one uint16_t each, so that both widths share one type and one set of
 * functions), and the string functions of S7 with the results of their edge cases as Siemens'
 * S7-1200/1500 system manual documents them ("String and character" instructions: a negative or
 * zero L or P gives the empty string, a P beyond the string appends, a result longer than its
 * target is cut at the target's maximum length). Part of every compiled FMU's sources/. */
#ifndef LGF_SCL_STRING_H
#define LGF_SCL_STRING_H

#include <stdbool.h>
#include <stdint.h>

#include "core/model.h"

/* the longest STRING of S7, and the longest WSTRING of the compiler's subset */
#define SCL_STRING_CAPACITY CORE_STRING_CAPACITY

/* the core's layout (src/core/model.h), which reads and writes a string of the FMU's interface:
 * the maximum length (the declared STRING[n]), the current length, the characters */
typedef core_string scl_string;

/* Whether a string restored from an FMU state is one a run leaves: its maximum length the
 * declared one, its current length within it. */
static inline bool scl_string_is_valid(const scl_string *s, int max)
{
    return s->max == max && s->len <= max;
}

/* A value of n characters (n at most SCL_STRING_CAPACITY), all 0. */
static inline scl_string scl_string_sized(int64_t n)
{
    scl_string s = {0};
    s.max = SCL_STRING_CAPACITY;
    s.len = (uint16_t)(n < 0 ? 0 : n > SCL_STRING_CAPACITY ? SCL_STRING_CAPACITY : n);
    return s;
}

/* A literal of a STRING: its characters' codes as bytes. */
static inline scl_string scl_string_of(const char *bytes, int n)
{
    scl_string s = scl_string_sized(n);
    for (int i = 0; i < s.len; i++) s.data[i] = (unsigned char)bytes[i];
    return s;
}

/* A literal of a WSTRING with characters beyond 16#FF. */
static inline scl_string scl_wstring_of(const uint16_t *codes, int n)
{
    scl_string s = scl_string_sized(n);
    for (int i = 0; i < s.len; i++) s.data[i] = codes[i];
    return s;
}

/* A CHAR or WCHAR as a string of one character (S7's implicit CHAR -> STRING). */
static inline scl_string scl_string_char(uint16_t c)
{
    scl_string s = scl_string_sized(1);
    s.data[0] = c;
    return s;
}

/* to := from for a target of max characters: cut at max, as S7 assigns a longer string; the
 * characters beyond the new current length stay as they were, as in the CPU's memory. */
static inline void scl_string_store(scl_string *to, scl_string from, int max)
{
    int n = from.len < max ? from.len : max;
    to->max = (uint16_t)max;
    to->len = (uint16_t)n;
    for (int i = 0; i < n; i++) to->data[i] = from.data[i];
}

/* S7's comparison: character by character by their codes, the first that differs decides;
 * where one string is the start of the other, the longer is the greater. <0, 0, >0. */
static inline int scl_string_compare(scl_string a, scl_string b)
{
    int n = a.len < b.len ? a.len : b.len;
    for (int i = 0; i < n; i++) {
        if (a.data[i] != b.data[i]) return a.data[i] < b.data[i] ? -1 : 1;
    }
    return a.len < b.len ? -1 : a.len > b.len ? 1 : 0;
}

/* The characters first .. first + count - 1 (0-based, within s) of s. */
static inline scl_string scl_string_part(scl_string s, int64_t first, int64_t count)
{
    scl_string r = scl_string_sized(count);
    for (int i = 0; i < r.len; i++) r.data[i] = s.data[first + i];
    return r;
}

static inline int16_t scl_len(scl_string s) { return (int16_t)s.len; }

/* CONCAT: IN1 then IN2, cut at SCL_STRING_CAPACITY. */
static inline scl_string scl_concat(scl_string a, scl_string b)
{
    scl_string r = a;
    r.max = SCL_STRING_CAPACITY;
    for (int i = 0; i < b.len && r.len < SCL_STRING_CAPACITY; i++) r.data[r.len++] = b.data[i];
    return r;
}

/* LEFT: the first L characters; L <= 0: empty, L beyond the length: all. */
static inline scl_string scl_left(scl_string s, int64_t l)
{
    return scl_string_part(s, 0, l <= 0 ? 0 : l > s.len ? s.len : l);
}

/* RIGHT: the last L characters; L <= 0: empty, L beyond the length: all. */
static inline scl_string scl_right(scl_string s, int64_t l)
{
    int64_t n = l <= 0 ? 0 : l > s.len ? s.len : l;
    return scl_string_part(s, s.len - n, n);
}

/* MID: L characters from position P (1-based); L or P <= 0 or P beyond the length: empty; to
 * the end where fewer than L remain. */
static inline scl_string scl_mid(scl_string s, int64_t l, int64_t p)
{
    if (l <= 0 || p <= 0 || p > s.len) return scl_string_sized(0);
    int64_t rest = s.len - (p - 1);
    return scl_string_part(s, p - 1, l < rest ? l : rest);
}

/* FIND: the position (1-based) of the first IN2 in IN1, 0 where there is none (also for an
 * empty IN2, docs/scl.md §3.5 [DEC-STRING-FIND]). */
static inline int16_t scl_find(scl_string a, scl_string b)
{
    if (b.len == 0) return 0;
    for (int i = 0; i + b.len <= a.len; i++) {
        int j = 0;
        while (j < b.len && a.data[i + j] == b.data[j]) j++;
        if (j == b.len) return (int16_t)(i + 1);
    }
    return 0;
}

/* REPLACE: the L characters of IN1 from position P replaced by IN2; L < 0 or P <= 0: empty;
 * P beyond IN1: IN2 appended; fewer than L characters from P: those replaced; L = 0: IN2
 * inserted before position P. */
static inline scl_string scl_replace(scl_string a, scl_string b, int64_t l, int64_t p)
{
    if (l < 0 || p <= 0) return scl_string_sized(0);
    if (p > a.len) return scl_concat(a, b);
    int64_t rest = a.len - (p - 1);
    int64_t cut = l < rest ? l : rest;
    scl_string r = scl_concat(scl_string_part(a, 0, p - 1), b);
    return scl_concat(r, scl_string_part(a, p - 1 + cut, rest - cut));
}

/* INSERT: IN2 after the P-th character of IN1; P < 0: empty; P = 0: before the first; P
 * beyond IN1: appended. */
static inline scl_string scl_insert(scl_string a, scl_string b, int64_t p)
{
    if (p < 0) return scl_string_sized(0);
    if (p >= a.len) return scl_concat(a, b);
    return scl_concat(scl_concat(scl_string_part(a, 0, p), b), scl_string_part(a, p, a.len - p));
}

/* DELETE: L characters from position P removed; L < 0 or P <= 0: empty; L = 0 or P beyond
 * the string: unchanged; to the end where fewer than L remain. */
static inline scl_string scl_delete(scl_string s, int64_t l, int64_t p)
{
    if (l < 0 || p <= 0) return scl_string_sized(0);
    if (p > s.len || l == 0) return s;
    return scl_replace(s, scl_string_sized(0), l, p);
}

#endif
