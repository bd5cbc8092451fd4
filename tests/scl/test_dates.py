"""S7's date and time types (docs/scl.md §3.1, §3.4, §3.6): DTL as an input, output, constant,
start value, ARRAY element and STRUCT member, DATE and TIME_OF_DAY, T_ADD, T_SUB, T_DIFF, the
comparison of DTLs and the conversions between them. Every expected value is counted here by hand
from the calendar (days per month, leap years), never taken from the compiler's output."""

from __future__ import annotations

from tests.scl.driver import compile_text, compiled, once, run_cs

DATES = """
FUNCTION "NextDay" : DTL   // a DTL in and out of an FC, passed whole
   VAR_INPUT
      t : DTL;
   END_VAR
BEGIN
    #NextDay := #t + T#1d;
END_FUNCTION

FUNCTION_BLOCK "Dates"
   VAR_INPUT
      d : DTL;
      n : DInt;
   END_VAR
   VAR_OUTPUT
      next : DTL;
      prev : DTL;
      fcNext : DTL;
      back : DTL;
      clear : DTL;
      days : DInt;
      ms : DInt;
      litDays : DInt;
      before : Bool;
      same : Bool;
      morning : Bool;
      span : Time;
      far : Time;
      leapDay : USInt;
      leapWeekday : USInt;
      memberYear : UInt;
   END_VAR
   VAR
      table : Array[0..1] of DTL := [DTL#2000-02-29-12:00:00];
      pair : Struct
         first : DTL;
         count : Int;
      END_STRUCT;
   END_VAR
   VAR CONSTANT
      LIMIT : DTL := DTL#1990-01-01-00:00:00;
      CLEAR_TIME : DTL;
   END_VAR
BEGIN
    #next := #d + T#1d;
    #prev := T_SUB(IN1 := #d, IN2 := T#1s);
    #fcNext := "NextDay"(t := #d);
    #back := DATE_TO_DTL(DINT_TO_DATE(#n));
    #clear := #CLEAR_TIME;
    #days := DATE_TO_DINT(DTL_TO_DATE(#d));
    #ms := TOD_TO_DINT(DTL_TO_TOD(#d));
    #litDays := DATE_TO_DINT(D#2024-01-01);
    #before := #d < #LIMIT;
    #same := #d = #d + T#0s;
    #morning := DTL_TO_TIME_OF_DAY(#d) < TOD#12:00:00;
    #span := T_DIFF(IN1 := #d, IN2 := #d - T#20d);
    #far := T_DIFF(IN1 := #d, IN2 := #LIMIT);
    #leapDay := #table[0].DAY;
    #leapWeekday := #table[0].WEEKDAY;
    #pair.first := T_ADD(IN1 := #LIMIT, IN2 := T#1d);
    #memberYear := #pair.first.YEAR;
END_FUNCTION_BLOCK
"""

FIELDS = ("YEAR", "MONTH", "DAY", "WEEKDAY", "HOUR", "MINUTE", "SECOND", "NANOSECOND")


def dtl(name: str, row: dict) -> tuple:
    return tuple(row[f"{name}.{m}"] for m in FIELDS)


def given(*values) -> dict:
    """The input d: YEAR, MONTH, DAY, HOUR, MINUTE, SECOND, NANOSECOND (WEEKDAY not given)."""
    names = [m for m in FIELDS if m != "WEEKDAY"]
    return {f"d.{m}": v for m, v in zip(names, values)}


dates = compiled(DATES, "Dates")


# docs/scl.md rules: [S7-TYPE-DTL] [S7-DTL-OP] [S7-T-ADD] [S7-DTL-CONV] [S7-TYPE-DATE]
def test_a_leap_day_afternoon(dates):
    """d = 2024-02-29 13:45:30.250. 1990-01-01 to 2024-01-01: 34 years of 365 days and the 8
    leap days of 1992 ... 2020, 12418 days; then 31 (January) + 28 days: 12477. Its time of
    day: 13 h 45 min 30.250 s = 49530250 ms. 2024-01-01 was a Monday, so 2024-03-01, 60 days
    later, a Friday (WEEKDAY 6); 2024-02-29 a Thursday (5)."""
    out = once(dates, given(2024, 2, 29, 13, 45, 30, 250_000_000, 0))
    assert out["days"] == 34 * 365 + 8 + 31 + 28 == 12477
    assert out["ms"] == (13 * 3600 + 45 * 60 + 30) * 1000 + 250 == 49530250
    assert out["litDays"] == 12418
    assert dtl("next", out) == (2024, 3, 1, 6, 13, 45, 30, 250_000_000)
    assert dtl("fcNext", out) == dtl("next", out)
    assert dtl("prev", out) == (2024, 2, 29, 5, 13, 45, 29, 250_000_000)
    assert (out["before"], out["same"], out["morning"]) == (False, True, False)
    assert out["span"] == 20 * 86400.0  # T#20d (a TIME output is in s): within the TIME range
    assert out["far"] == 0  # 34 years: beyond the TIME range


# docs/scl.md rules: [S7-DTL-START] [S7-TYPE-DTL]
def test_dtl_start_values_constants_and_members(dates):
    """A DTL constant without a value is DTL#1970-01-01-00:00:00, a Thursday (WEEKDAY 5);
    DTL#2000-02-29-12:00:00 as an ARRAY element's start value gets its WEEKDAY, a Tuesday (3);
    1990-01-01 + T#1d into a STRUCT member is 1990-01-02."""
    out = once(dates, given(2024, 2, 29, 13, 45, 30, 250_000_000, 0))
    assert dtl("clear", out) == (1970, 1, 1, 5, 0, 0, 0, 0)
    assert (out["leapDay"], out["leapWeekday"]) == (29, 3)
    assert out["memberYear"] == 1990


# docs/scl.md rules: [S7-DTL-CONV]
def test_date_to_dtl_from_the_first_to_the_last_date(dates):
    """DATE 0 is 1990-01-01, a Monday (WEEKDAY 2); DATE 65535, the last one, is 2169-06-06: 179
    years of 365 days and the 44 leap days of 1992 ... 2168 (2100 is none) are 65379 days to
    2169-01-01, and 31 + 28 + 31 + 30 + 31 + 5 = 156 more; 65535 = 7 * 9362 + 1 days after a
    Monday is a Tuesday (3)."""
    assert 179 * 365 + 44 + 156 == 65535
    first = once(dates, {**given(2024, 1, 1, 0, 0, 0, 0, 0), "n": 0})
    assert dtl("back", first) == (1990, 1, 1, 2, 0, 0, 0, 0)
    last = once(dates, {**given(2024, 1, 1, 0, 0, 0, 0, 0), "n": 65535})
    assert dtl("back", last) == (2169, 6, 6, 3, 0, 0, 0, 0)


# docs/scl.md rules: [DEC-DTL-INVALID]
def test_an_invalid_dtl(dates):
    """2023-02-29 does not exist: DTL + TIME gives DTL#1970-01-01-00:00:00, DTL_TO_DATE and
    DTL_TO_TOD 0, T_DIFF 0 (Siemens: OUT 0 for an invalid DTL)."""
    out = once(dates, given(2023, 2, 29, 10, 0, 0, 0, 0))
    assert dtl("next", out) == (1970, 1, 1, 5, 0, 0, 0, 0)
    assert (out["days"], out["ms"], out["span"]) == (0, 0, 0)


CLOCK = """
FUNCTION_BLOCK "Clock"
   VAR_OUTPUT
      ns : UDInt;
      second : USInt;
   END_VAR
   VAR_TEMP
      now : DTL;
   END_VAR
BEGIN
    RD_LOC_T(#now);   // the DTL alone, as TIA writes it too
    #ns := #now.NANOSECOND;
    #second := #now.SECOND;
END_FUNCTION_BLOCK
"""


# docs/scl.md rules: [S7-CLOCK]
def test_the_clock_counts_whole_ms(tmp_path):
    """A cycle of 1.5 ms: the clock reads 0, 1, 3, 4, 6 ms after the start (truncated)."""
    fmu = compile_text(tmp_path, CLOCK, "Clock")
    rows = run_cs(fmu, 1500, {}, {}, [(1500, {})] * 4)
    assert [r["ns"] for r in rows] == [0, 1_000_000, 3_000_000, 4_000_000, 6_000_000]
    assert {r["second"] for r in rows} == {0}
