/* S7's date and time types as the C that lgf_fmus.scl generates computes with them
 * (docs/scl.md §3.1, §3.6): DTL, DATE (days since 1990-01-01 in 16 bits), TIME_OF_DAY (ms since
 * midnight), their conversions, T_ADD, T_SUB and T_DIFF of a DTL and the comparison of DTLs.
 * Calendar arithmetic of the proleptic Gregorian calendar, written here from its rules (a year
 * of 365 days, a leap day every 4 years except the centuries not divisible by 400). Part of
 * every compiled FMU's sources/. */
#ifndef LGF_SCL_DATES_H
#define LGF_SCL_DATES_H

#include <stdbool.h>
#include <stdint.h>

/* DTL: S7's date and time of 12 bytes (WEEKDAY 1 = Sunday ... 7 = Saturday). */
typedef struct {
    uint16_t YEAR;
    uint8_t MONTH;
    uint8_t DAY;
    uint8_t WEEKDAY;
    uint8_t HOUR;
    uint8_t MINUTE;
    uint8_t SECOND;
    uint32_t NANOSECOND;
} scl_dtl;

#define SCL_NS_PER_DAY INT64_C(86400000000000)
#define SCL_MS_PER_DAY 86400000
/* DATE counts days from 1990-01-01, which is 7305 days after 1970-01-01 */
#define SCL_DATE_EPOCH_DAYS 7305
/* the last DTL of an S7-1500, DTL#2262-04-11-23:47:16.854775807: INT64_MAX ns after 1970 */
#define SCL_DTL_LAST_YEAR 2262

static inline bool scl_leap(int64_t year)
{
    return (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
}

static inline int scl_month_days(int64_t year, int month)
{
    static const uint8_t days[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    return days[month - 1] + (month == 2 && scl_leap(year));
}

/* The leap days of the years 1 .. year (year >= 0). */
static inline int64_t scl_leap_days(int64_t year) { return year / 4 - year / 100 + year / 400; }

/* The days from 1970-01-01 to year-month-day (year >= 1970, month 1 .. 12): 365 a year, the leap
 * days of the years before it, the days of its months before month and of that month before day. */
static inline int64_t scl_days_of(int64_t year, int month, int day)
{
    int64_t days = 365 * (year - 1970) + scl_leap_days(year - 1) - scl_leap_days(1969);
    for (int m = 1; m < month; m++) days += scl_month_days(year, m);
    return days + day - 1;
}

/* The DTL of a time in ns since 1970-01-01 00:00 (>= 0): the year from an estimate of at most one
 * too small (a year has at most 366 days), the month and day counted off, WEEKDAY from the day
 * count (1970-01-01 was a Thursday, WEEKDAY 5). */
static inline scl_dtl scl_dtl_of(int64_t ns)
{
    scl_dtl t;
    int64_t days = ns / SCL_NS_PER_DAY;
    int64_t in_day = ns % SCL_NS_PER_DAY;
    int64_t year = 1970 + days / 366;
    while (scl_days_of(year + 1, 1, 1) <= days) year++;
    int64_t rest = days - scl_days_of(year, 1, 1);
    int month = 1;
    while (rest >= scl_month_days(year, month)) rest -= scl_month_days(year, month++);
    t.YEAR = (uint16_t)year;
    t.MONTH = (uint8_t)month;
    t.DAY = (uint8_t)(rest + 1);
    t.WEEKDAY = (uint8_t)((days + 4) % 7 + 1);
    t.HOUR = (uint8_t)(in_day / INT64_C(3600000000000));
    t.MINUTE = (uint8_t)(in_day / INT64_C(60000000000) % 60);
    t.SECOND = (uint8_t)(in_day / 1000000000 % 60);
    t.NANOSECOND = (uint32_t)(in_day % 1000000000);
    return t;
}

/* Whether a DTL holds a date and time of its range (WEEKDAY is not looked at, as S7 takes a DTL's
 * value without it), and then its ns since 1970 in *ns. */
static inline bool scl_dtl_ns(const scl_dtl *t, int64_t *ns)
{
    if (t->YEAR < 1970 || t->YEAR > SCL_DTL_LAST_YEAR || t->MONTH < 1 || t->MONTH > 12 ||
        t->DAY < 1 || t->DAY > scl_month_days(t->YEAR, t->MONTH) || t->HOUR > 23 ||
        t->MINUTE > 59 || t->SECOND > 59 || t->NANOSECOND > 999999999)
        return false;
    int64_t days = scl_days_of(t->YEAR, t->MONTH, t->DAY);
    int64_t seconds = (int64_t)t->HOUR * 3600 + t->MINUTE * 60 + t->SECOND;
    /* the days of the last year beyond INT64_MAX ns: 2262-04-11 is day 106751 */
    if (days > INT64_MAX / SCL_NS_PER_DAY) return false;
    int64_t in_day = seconds * 1000000000 + t->NANOSECOND;
    if (days * SCL_NS_PER_DAY > INT64_MAX - in_day) return false;
    *ns = days * SCL_NS_PER_DAY + in_day;
    return true;
}

/* DTL = DTL, <, ... (docs/scl.md §3.4): the members from YEAR to NANOSECOND, WEEKDAY left out;
 * for two valid DTLs the order of their times. -1, 0 or 1. */
static inline int scl_dtl_compare(scl_dtl a, scl_dtl b)
{
    int64_t x[7] = {a.YEAR, a.MONTH, a.DAY, a.HOUR, a.MINUTE, a.SECOND, a.NANOSECOND};
    int64_t y[7] = {b.YEAR, b.MONTH, b.DAY, b.HOUR, b.MINUTE, b.SECOND, b.NANOSECOND};
    for (int i = 0; i < 7; i++)
        if (x[i] != y[i]) return x[i] < y[i] ? -1 : 1;
    return 0;
}

/* T_ADD and T_SUB of a DTL and a TIME (and DTL + TIME, DTL - TIME): the DTL that many ms later
 * (earlier). An invalid DTL, or a result outside DTL#1970-01-01 ... DTL#2262-04-11-23:47:16.854775807,
 * gives DTL#1970-01-01-00:00:00 (docs/scl.md §3.6: Decision; the CPU reports it on ENO). */
static inline scl_dtl scl_dtl_add(scl_dtl t, int64_t ms)
{
    int64_t ns;
    int64_t delta = ms * 1000000; /* |ms| < 2^31: fits */
    if (!scl_dtl_ns(&t, &ns) || (delta < 0 && ns < -delta) || (delta > 0 && ns > INT64_MAX - delta))
        return scl_dtl_of(0);
    return scl_dtl_of(ns + delta);
}

/* T_DIFF of two DTLs (and DTL - DTL): IN1 - IN2 as a TIME, in whole ms towards zero; 0 for an
 * invalid DTL or a difference beyond the TIME range, as Siemens documents T_DIFF's error (OUT 0,
 * ENO FALSE; docs/behaviour.md §18.3). */
static inline int32_t scl_t_diff(scl_dtl in1, scl_dtl in2)
{
    int64_t a, b;
    if (!scl_dtl_ns(&in1, &a) || !scl_dtl_ns(&in2, &b)) return 0;
    int64_t ms = (a - b) / 1000000; /* both >= 0: no overflow; C divides towards zero */
    return ms < INT32_MIN || ms > INT32_MAX ? 0 : (int32_t)ms;
}

/* DTL_TO_DATE: the days from 1990-01-01 of the DTL's date; DTL_TO_TOD: the ms since midnight of
 * its time of day (its nanoseconds truncated to ms). An invalid DTL, or one before 1990 or after
 * D#2169-06-06 (the 65535th day) for a DATE, gives 0 (docs/scl.md §3.6: Decision). */
static inline uint16_t scl_dtl_to_date(scl_dtl t)
{
    int64_t ns;
    if (!scl_dtl_ns(&t, &ns)) return 0;
    int64_t days = ns / SCL_NS_PER_DAY - SCL_DATE_EPOCH_DAYS;
    return days < 0 || days > UINT16_MAX ? 0 : (uint16_t)days;
}

static inline uint32_t scl_dtl_to_tod(scl_dtl t)
{
    int64_t ns;
    if (!scl_dtl_ns(&t, &ns)) return 0;
    return (uint32_t)(ns % SCL_NS_PER_DAY / 1000000);
}

/* DATE_TO_DTL: the DTL of the day at 00:00:00 (with its WEEKDAY). */
static inline scl_dtl scl_date_to_dtl(uint16_t date)
{
    return scl_dtl_of(((int64_t)date + SCL_DATE_EPOCH_DAYS) * SCL_NS_PER_DAY);
}

#endif
