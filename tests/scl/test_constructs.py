"""Each construct and rule of the subset (docs/scl.md §3) in a small FB of its own kind, compiled
and run call by call; every expected value is computed here by hand from the rule (or with
NumPy's float32 for a REAL sum), never taken from the compiler's output. One FB per group keeps
the C compiler's share of the suite small."""

from __future__ import annotations

import math

import numpy as np
import pytest

from tests.scl.driver import calls, compile_text, compiled, once, run_cs, unpacked

CYCLE_US = 100_000


ARITHMETIC = """
FUNCTION_BLOCK "Arithmetic"
VERSION : 0.1
   VAR_INPUT
      a : Int;
      b : Int;
      da : DInt;
      db : DInt;
      ud : UDInt;
      w1 : Word;
      w2 : Word;
      r1 : Real;
      r2 : Real;
      l1 : LReal;
   END_VAR
   VAR_OUTPUT
      sumInt : Int;
      difInt : Int;
      mulInt : Int;
      divInt : Int;
      modInt : Int;
      negInt : Int;
      absInt : Int;
      mixed : DInt;
      sumDInt : DInt;
      sumUDInt : UDInt;
      wAnd : Word;
      wOr : Word;
      wXor : Word;
      wNot : Word;
      sumReal : Real;
      divReal : Real;
      sqrtReal : Real;
      sinReal : Real;
      cosReal : Real;
      mixedLReal : LReal;
      less : Bool;
      equal : Bool;
      logic : Bool;
      minInt : Int;
      maxReal : Real;
      limited : Int;
      selected : Int;
      compound : DInt;
      scaled : DInt;
      commented : Int;
      nanFirst : Real;
      nanSecond : Real;
      precedence : Int;
   END_VAR
BEGIN
    #sumInt := #a + #b;
    #difInt := #a - #b;
    #mulInt := #a * #b;
    #divInt := #a / #b;
    #modInt := #a MOD #b;
    #negInt := -#a;
    #absInt := ABS(#a);
    #mixed := #a + #da;          // INT + DINT runs in DINT (docs/scl.md §3.2)
    #sumDInt := #da + #db;
    #sumUDInt := #ud + UDINT#4294967295;
    #wAnd := #w1 AND #w2;
    #wOr := #w1 OR #w2;
    #wXor := #w1 XOR #w2;
    #wNot := NOT #w1;
    #sumReal := #r1 + #r2;
    #divReal := #r1 / #r2;
    #sqrtReal := SQRT(#r1);
    #sinReal := SIN(#r1);
    #cosReal := COS(#r2);
    #mixedLReal := #r1 + #l1;    // REAL widened to LREAL first
    #less := #a < #b;
    #equal := #a = #b;
    #logic := #a > 0 AND NOT (#b > 0) OR #a = #b XOR TRUE;
    #minInt := MIN(IN1 := #a, IN2 := #b, IN3 := 5);
    #maxReal := MAX(IN1 := #r1, IN2 := #r2);
    #limited := LIMIT(MN := 0, IN := #a, MX := 100);
    #selected := SEL(G := #a > #b, IN0 := #a, IN1 := #b);
    #compound := #da;
    #compound += 10;
    #compound -= #db;
    #scaled := #da;
    #scaled *= 3;
    #scaled /= #db;
    #nanFirst := MAX(IN1 := #r1 - #r1, IN2 := #r2);   // r1 = Inf: Inf - Inf is NaN
    #nanSecond := MIN(IN1 := #r2, IN2 := #r1 - #r1);
    #commented := #a // a comment after an operand, not a division
        + 1 (* between *) * /* any two tokens */ 2;
    #precedence := 2 + 3 * #a MOD 4 - -#b;
END_FUNCTION_BLOCK
"""


arithmetic = compiled(ARITHMETIC, "Arithmetic")


# docs/scl.md rules: [S7-CONV-1] [S7-CONV-2] [S7-WRAP-1]
def test_integer_arithmetic_wraps_as_on_the_s7(arithmetic):
    """docs/behaviour.md §1.4: INT and DINT wrap in two's complement; UDINT modulo 2^32."""
    out = once(arithmetic, {"a": 32767, "b": 1, "da": 2147483647, "db": 1, "ud": 1})
    assert out["sumInt"] == -32768
    assert out["difInt"] == 32766
    assert out["mixed"] == 32767 + 2147483647 - 2**32  # DINT wraps too
    assert out["sumDInt"] == -(2**31)
    assert out["sumUDInt"] == 0
    out = once(arithmetic, {"a": 300, "b": 300})
    assert out["mulInt"] == 90000 - 65536
    out = once(arithmetic, {"a": -32768, "b": -1, "da": 1})
    assert out["negInt"] == -32768  # -(-32768) wraps
    assert out["absInt"] == -32768
    assert out["divInt"] == -32768  # -32768 / -1 = 32768 wraps
    assert out["mixed"] == -32767  # INT + DINT in DINT: no INT wrap


# docs/scl.md rules: [S7-DIV-1] [DEC-DIV-0]
def test_division_truncates_and_mod_keeps_the_dividends_sign(arithmetic):
    """docs/scl.md §3.3: / truncates towards zero, MOD has the dividend's sign, /0 and MOD 0 give
    0 (Decision)."""
    assert once(arithmetic, {"a": 7, "b": 2})["divInt"] == 3
    out = once(arithmetic, {"a": -7, "b": 2})
    assert (out["divInt"], out["modInt"]) == (-3, -1)
    out = once(arithmetic, {"a": 7, "b": 0})
    assert (out["divInt"], out["modInt"]) == (0, 0)


# docs/scl.md rules: [S7-OP-BITS]
def test_bit_strings(arithmetic):
    out = once(arithmetic, {"w1": 0x00FF, "w2": 0x0FF0})
    assert (out["wAnd"], out["wOr"], out["wXor"], out["wNot"]) == (0x00F0, 0x0FFF, 0x0F0F, 0xFF00)


# docs/scl.md rules: [S7-CONV-2] [S7-REAL-1] [S7-FN-1]
def test_real_is_float32_op_by_op_and_lreal_double(arithmetic):
    """docs/behaviour.md §1.4: each REAL operation rounded to float32; REAL + LREAL in double."""
    out = once(arithmetic, {"r1": 0.1, "r2": 0.2, "l1": 0.2})
    r1, r2 = np.float32(0.1), np.float32(0.2)
    assert out["sumReal"] == float(r1 + r2)
    assert out["sumReal"] != 0.1 + 0.2  # not a double sum rounded once
    assert out["divReal"] == float(r1 / r2)
    assert out["sqrtReal"] == float(np.sqrt(r1))
    assert out["mixedLReal"] == float(r1) + 0.2
    # SIN and COS of a REAL: the float32 of the exact value (docs/behaviour.md §6.2)
    assert out["sinReal"] == float(np.float32(math.sin(float(r1))))
    assert out["cosReal"] == float(np.float32(math.cos(float(r2))))
    out = once(arithmetic, {"r1": 1.0, "r2": 0.0})
    assert out["divReal"] == math.inf  # IEEE, as on the CPU


# docs/scl.md rules: [S7-OP-PRIO]
def test_comparisons_logic_and_precedence(arithmetic):
    out = once(arithmetic, {"a": 1, "b": 2})
    assert (out["less"], out["equal"]) == (True, False)
    # SCL precedence: NOT, comparisons, AND, XOR, OR: (a>0 AND NOT b>0) OR ((a=b) XOR TRUE)
    assert out["logic"] is True
    out = once(arithmetic, {"a": 2, "b": 2})
    assert out["logic"] is False  # (T AND F) OR (T XOR T)
    out = once(arithmetic, {"a": 5, "b": -3})
    # 2 + ((3 * 5) MOD 4) - (-(-3)) = 2 + 3 - 3
    assert out["precedence"] == 2


# docs/scl.md rules: [S7-FN-1]
def test_min_max_limit_sel(arithmetic):
    out = once(arithmetic, {"a": 7, "b": 9, "r1": -0.5, "r2": 2.5})
    assert out["minInt"] == 5
    assert out["maxReal"] == 2.5
    assert out["limited"] == 7
    assert out["selected"] == 7  # G FALSE: IN0
    out = once(arithmetic, {"a": 300, "b": -4})
    assert (out["minInt"], out["limited"], out["selected"]) == (-4, 100, -4)
    assert once(arithmetic, {"a": -3})["limited"] == 0


# docs/scl.md rules: [DEC-MINMAX]
def test_a_tie_of_max_gives_the_first_and_nan_loses(arithmetic):
    """docs/scl.md §3.5 (Decision): MAX(-0.0, 0.0) is -0.0, MAX(0.0, -0.0) 0.0; a NaN argument
    loses to a number, on either side of MAX and MIN (IEEE maxNum, minNum)."""
    first = once(arithmetic, {"r1": -0.0, "r2": 0.0})["maxReal"]
    assert first == 0.0 and math.copysign(1.0, first) == -1.0
    first = once(arithmetic, {"r1": 0.0, "r2": -0.0})["maxReal"]
    assert math.copysign(1.0, first) == 1.0
    out = once(arithmetic, {"r1": math.inf, "r2": 2.5})  # r1 - r1 is NaN
    assert (out["nanFirst"], out["nanSecond"]) == (2.5, 2.5)


# docs/scl.md rules: [DEC-DIV-0] [S7-ASSIGN]
def test_compound_assignment(arithmetic):
    """docs/scl.md §3.4: x op= e is x := x op e, with the rules of op."""
    out = once(arithmetic, {"da": 5, "db": 2})
    assert out["compound"] == 13  # 5 + 10 - 2
    assert out["scaled"] == 7  # 5 * 3 = 15, 15 / 2 truncated
    out = once(arithmetic, {"da": -7, "db": 2})
    assert out["scaled"] == -10  # -21 / 2 towards zero
    # 2147483647 * 3 = 6442450941 wraps in DINT to 6442450941 - 2^32 = 2147483645
    assert once(arithmetic, {"da": 2147483647, "db": 1})["scaled"] == 2147483645
    assert once(arithmetic, {"da": 9, "db": 0})["scaled"] == 0  # / 0 gives 0 (§3.3)


def test_comments_stand_between_any_two_tokens(arithmetic):
    """docs/scl.md §2: // after an operand ends the line, it is no division; (* *) and /* */
    between an operator and its operands."""
    assert once(arithmetic, {"a": 4})["commented"] == 6  # 4 + 1 * 2


CONVERSIONS = """
FUNCTION_BLOCK "Conversions"
   VAR_INPUT
      r : Real;
      l : LReal;
      i : Int;
      d : DInt;
      w : Word;
   END_VAR
   VAR_OUTPUT
      realToInt : Int;
      lrealToDInt : DInt;
      truncated : DInt;
      intToWord : Word;
      wordToInt : Int;
      dintToInt : Int;
      dintToReal : Real;
      lrealToReal : Real;
      timeToDInt : DInt;
      dintToTime : Time;
      boolToInt : Int;
      intToBool : Bool;
      hex : Word;
      binary : Int;
      octal : Int;
      underscores : DInt;
      typedReal : Real;
      typedInt : Int;
      time1 : Time;
      time2 : Time;
      time3 : Time;
      timeSum : Time;
      timeScaled : Time;
      widened : LReal;
   END_VAR
   VAR
      statTime : Time := T#1s200ms;
   END_VAR
BEGIN
    #realToInt := REAL_TO_INT(#r);
    #lrealToDInt := LREAL_TO_DINT(IN := #l);
    #truncated := TRUNC(#l);
    #intToWord := INT_TO_WORD(#i);
    #wordToInt := WORD_TO_INT(#w);
    #dintToInt := DINT_TO_INT(#d);
    #dintToReal := DINT_TO_REAL(#d);
    #lrealToReal := LREAL_TO_REAL(#l);
    #timeToDInt := TIME_TO_DINT(#statTime);
    #dintToTime := DINT_TO_TIME(#d);
    #boolToInt := BOOL_TO_INT(#i > 0);
    #intToBool := INT_TO_BOOL(#i);
    #hex := 16#8200;
    #binary := 2#1010;
    #octal := 8#17;
    #underscores := 1_000_000;
    #typedReal := REAL#1.5;
    #typedInt := INT#-5;
    #time1 := T#1s200ms;
    #time2 := T#-5s;
    #time3 := TIME#1h2m3s4ms;
    #timeSum := #statTime + T#800ms - T#1s;
    #timeScaled := #statTime * 3 / 2;
    #widened := #i;
END_FUNCTION_BLOCK
"""


conversions = compiled(CONVERSIONS, "Conversions")


@pytest.mark.parametrize(
    "value, expected",
    [(2.5, 2), (3.5, 4), (-2.5, -2), (-0.5, 0), (1.4999999, 1), (1e6, 32767), (-1e6, -32768)],
)
# docs/scl.md rules: [S7-CONV-ROUND] [DEC-CONV-LIMIT]
def test_real_to_int_rounds_halves_to_even_and_limits(conversions, value, expected):
    """docs/behaviour.md §6.2: to the nearest, halves to even; docs/scl.md §3.3 (Decision):
    beyond the range, the range's limit."""
    assert once(conversions, {"r": value})["realToInt"] == expected


# docs/scl.md rules: [S7-CONV-BITS]
def test_conversions(conversions):
    out = once(conversions, {"l": -2.7, "i": -1, "w": 0x8000, "d": 70000})
    assert out["lrealToDInt"] == -3
    assert out["truncated"] == -2
    assert out["intToWord"] == 65535
    assert out["wordToInt"] == -32768
    assert out["dintToInt"] == 70000 - 65536
    assert out["lrealToReal"] == float(np.float32(-2.7))
    assert out["timeToDInt"] == 1200
    assert out["dintToTime"] == 70.0  # 70000 ms
    assert (out["boolToInt"], out["intToBool"]) == (0, True)
    assert out["widened"] == -1.0
    out = once(conversions, {"d": 16777217, "i": 3})
    assert out["dintToReal"] == 16777216.0  # the nearest REAL, halves to even
    assert (out["boolToInt"], out["intToBool"]) == (1, True)
    assert once(conversions, {"i": 0})["intToBool"] is False


# docs/scl.md rules: [S7-LIT-1] [S7-LIT-2]
def test_literals(conversions):
    out = once(conversions, {})
    assert (out["hex"], out["binary"], out["octal"]) == (0x8200, 10, 15)
    assert out["underscores"] == 1_000_000
    assert (out["typedReal"], out["typedInt"]) == (1.5, -5)
    assert (out["time1"], out["time2"], out["time3"]) == (1.2, -5.0, 3723.004)


# docs/scl.md rules: [S7-TIME-1]
def test_time_arithmetic(conversions):
    out = once(conversions, {})
    assert out["timeSum"] == 1.0  # 1200 + 800 - 1000 ms
    assert out["timeScaled"] == 1.8  # 1200 * 3 / 2 ms


FLOW = """
FUNCTION_BLOCK "Flow"
   VAR_INPUT
      n : Int;
   END_VAR
   VAR_OUTPUT
      sum : DInt;
      down : Int;
      exited : Int;
      odd : DInt;
      whiled : Int;
      repeated : Int;
      cased : Int;
      branch : Int;
      edgeLoop : Int;
      caseExit : Int;
      calls : DInt;
      temp : Int;
      afterReturn : Int;
   END_VAR
   VAR
      i : Int;
      k : Int;
      statCalls : DInt;
   END_VAR
   VAR_TEMP
      tempCount : Int;
   END_VAR
   VAR CONSTANT
      LIMIT_HIGH : Int := 32767;
   END_VAR
BEGIN
    REGION loops
        #sum := 0;
        ;  // an empty statement
        FOR #i := 1 TO #n DO
            #sum += #i;
        END_FOR;
        #down := 0;
        FOR #i := 10 TO 1 BY -2 DO
            #down := #down + 1;
        END_FOR;
        FOR #i := 1 TO 100 DO
            #exited := #i;
            IF #i >= 3 THEN
                EXIT;
            END_IF;
        END_FOR;
        #odd := 0;
        FOR #i := 1 TO #n DO
            IF #i MOD 2 = 0 THEN
                CONTINUE;
            END_IF;
            #odd := #odd + #i;
        END_FOR;
        #k := 0;
        WHILE #k < #n DO
            #k += 3;
        END_WHILE;
        #whiled := #k;
        #k := 0;
        REPEAT
            #k += 1;
        UNTIL #k >= #n
        END_REPEAT;
        #repeated := #k;
        #edgeLoop := 0;
        FOR #i := 32760 TO #LIMIT_HIGH DO   // ends at the type's limit (docs/scl.md §3.4)
            #edgeLoop += 1;
        END_FOR;
        #caseExit := 0;
        FOR #i := 1 TO 10 DO
            CASE #i OF
                4:
                    EXIT;                   // leaves the FOR, not only the CASE
                ELSE
                    #caseExit := #i;
            END_CASE;
        END_FOR;
    END_REGION
    REGION branches
        CASE #n OF
            1:
                #cased := 10;
            2, 3:
                #cased := 20;
            4..6, 8:
                #cased := 30;
            -5..-1:
                #cased := -1;
        ELSE
            #cased := 99;
        END_CASE;
        IF #n < 0 THEN
            #branch := -1;
        ELSIF #n = 0 THEN
            #branch := 0;
        ELSIF #n < 10 THEN
            #branch := 1;
        ELSE
            #branch := 2;
        END_IF;
    END_REGION
    #statCalls := #statCalls + 1;
    #calls := #statCalls;
    #tempCount := #tempCount + 1;  (* a VAR_TEMP starts again in every call *)
    #temp := #tempCount;
    IF #n = 100 THEN
        RETURN;
    END_IF;
    #afterReturn := #n;
END_FUNCTION_BLOCK
"""


flow = compiled(FLOW, "Flow")


# docs/scl.md rules: [S7-FLOW-LOOP] [DEC-FOR]
def test_loops(flow):
    out = once(flow, {"n": 10})
    assert out["sum"] == 55
    assert out["down"] == 5  # 10, 8, 6, 4, 2
    assert out["exited"] == 3
    assert out["odd"] == 1 + 3 + 5 + 7 + 9
    assert out["whiled"] == 12
    assert out["repeated"] == 10
    assert out["edgeLoop"] == 8  # 32760 ... 32767, no wrap into an endless loop
    assert out["caseExit"] == 3
    out = once(flow, {"n": 0})
    assert (out["sum"], out["whiled"], out["repeated"]) == (0, 0, 1)  # REPEAT runs once


@pytest.mark.parametrize(
    "n, cased, branch",
    [
        (1, 10, 1),
        (2, 20, 1),
        (3, 20, 1),
        (5, 30, 1),
        (8, 30, 1),
        (7, 99, 1),
        (-3, -1, -1),
        (0, 99, 0),
        (12, 99, 2),
    ],
)
# docs/scl.md rules: [S7-FLOW-1]
def test_case_and_if(flow, n, cased, branch):
    out = once(flow, {"n": n})
    assert (out["cased"], out["branch"]) == (cased, branch)


# docs/scl.md rules: [S7-FLOW-LOOP] [DEC-TEMP]
def test_statics_keep_temps_restart_and_return(flow):
    rows = calls(flow, [{"n": 1}, {"n": 2}, {"n": 100}, {"n": 3}])
    assert [r["calls"] for r in rows] == [1, 2, 3, 4]
    assert [r["temp"] for r in rows] == [1, 1, 1, 1]
    assert [r["afterReturn"] for r in rows] == [1, 2, 2, 3]  # RETURN ends the call


TIMERS = """
FUNCTION_BLOCK "Timers"
   VAR_INPUT
      in : Bool;
      pt : Time := T#300ms;
   END_VAR
   VAR_OUTPUT
      tonQ : Bool;
      tonET : Time;
      tofQ : Bool;
      tofET : Time;
      tpQ : Bool;
      tpET : Time;
      rising : Bool;
      falling : Bool;
      cycle : UDInt;
      cintStatus : DWord;
      ret : Int;
   END_VAR
   VAR
      statTon {InstructionName := 'TON_TIME'; LibVersion := '1.0'} : TON_TIME;
      statTof : TOF_TIME;
      statTp : TP;
      statRising : R_TRIG;
      statFalling : F_TRIG;
   END_VAR
BEGIN
    #statTon(IN := #in, PT := #pt, Q => #tonQ, ET => #tonET);
    #statTof(IN := #in, PT := #pt);
    #tofQ := #statTof.Q;
    #tofET := #statTof.ET;
    #statTp(IN := #in, PT := #pt);
    #tpQ := #statTp.Q;
    #tpET := #statTp.ET;
    #statRising(CLK := #in);
    #rising := #statRising.Q;
    #statFalling(CLK := #in);
    #falling := #statFalling.Q;
    #ret := QRY_CINT(OB_NR := 30, CYCLE => #cycle, STATUS => #cintStatus);
END_FUNCTION_BLOCK
"""


timers = compiled(TIMERS, "Timers")


# docs/scl.md rules: [S7-TIMER] [S7-TRIG] [S7-INST-CALL]
def test_timers_and_edges_by_hand(timers):
    """docs/behaviour.md §1.12, cycle 100 ms, PT 300 ms; IN TRUE in calls 1 to 5."""
    ins = [False, True, True, True, True, True, False, False, False, False, False]
    rows = calls(timers, [{"in": x} for x in ins])
    col = lambda name: [r[name] for r in rows]  # noqa: E731
    F, T = False, True
    assert col("tonQ") == [F, F, F, F, T, T, F, F, F, F, F]  # 300 ms after call 1
    assert col("tonET") == [0, 0, 0.1, 0.2, 0.3, 0.3, 0, 0, 0, 0, 0]
    assert col("tofQ") == [F, T, T, T, T, T, T, T, T, F, F]  # 300 ms after the fall in call 6
    assert col("tofET") == [0, 0, 0, 0, 0, 0, 0, 0.1, 0.2, 0.3, 0.3]
    assert col("tpQ") == [F, T, T, T, F, F, F, F, F, F, F]  # a pulse of 300 ms from call 1
    assert col("tpET") == [0, 0, 0.1, 0.2, 0.3, 0.3, 0, 0, 0, 0, 0]
    assert col("rising") == [F, T, F, F, F, F, F, F, F, F, F]
    assert col("falling") == [F, F, F, F, F, F, T, F, F, F, F]
    assert col("cycle") == [100_000] * 11  # QRY_CINT answers cycleTime in µs
    # STATUS of a loaded (bit 4), active (bit 2) cyclic-interrupt OB; 0 would be "OB missing"
    assert col("cintStatus") == [0x14] * 11
    assert col("ret") == [0] * 11


# docs/scl.md rules: [S7-TIMER] [S7-QRY-CINT]
def test_ton_takes_pt_at_the_rising_edge(timers):
    """docs/behaviour.md §1.12: "Changing PT has no effect while the timer runs"."""
    per_call = [{"in": False}, {"in": True}, {"pt": 1.0}, {}, {}, {}]
    rows = calls(timers, per_call)
    assert [r["tonQ"] for r in rows] == [False, False, False, False, True, True]


CALLING_OB = """
FUNCTION_BLOCK "CallingOb"
   VAR_INPUT
      callOB : OB_CYCLIC;
      other : OB_CYCLIC := 35;
      x : Int;
   END_VAR
   VAR_OUTPUT
      ob : Int;
      otherOb : Int;
      cycle : UDInt;
      enoAtStart : Bool;
      enoSet : Bool;
      innerOb : Int;
      fcEno : Bool;
   END_VAR
   VAR
      inner : "InnerOb";
   END_VAR
   VAR_TEMP
      ret : Int;
   END_VAR
BEGIN
    #enoAtStart := ENO;
    #ob := #callOB;
    #otherOb := #other;
    #ret := QRY_CINT(OB_NR := #callOB, CYCLE => #cycle);
    ENO := #x > 0;
    #enoSet := ENO;
    #inner(callOB := #callOB, x := #x);
    #innerOb := #inner.ob;
    #fcEno := "FcEno"(x := #x);
END_FUNCTION_BLOCK

FUNCTION_BLOCK "InnerOb"
   VAR_INPUT
      callOB : OB_CYCLIC;
      x : Int;
   END_VAR
   VAR_OUTPUT
      ob : Int;
   END_VAR
BEGIN
    #ob := #callOB + #x;
    ENO := FALSE;
END_FUNCTION_BLOCK

FUNCTION "FcEno" : Bool
   VAR_INPUT
      x : Int;
   END_VAR
BEGIN
    #FcEno := ENO;
    ENO := #x = 0;
END_FUNCTION
"""


# docs/scl.md rules: [DEC-ENO]
def test_the_calling_ob_is_cycle_time_and_eno_a_temporary(tmp_path):
    """docs/scl.md §3.4, §4: an OB_CYCLIC input of the FMU's FB is no FMI variable (cycleTime
    plays the OB) and reads its initial value, 30 without one; one of an FB it uses is an INT
    input its caller sets; ENO starts TRUE in every call of every block (an FB, an FC),
    whatever the call before set."""
    fmu = compile_text(tmp_path, CALLING_OB, "CallingOb")
    names = {v.name for v in unpacked(fmu)[1].modelVariables}
    assert {"x", "ob", "cycle"} <= names
    assert not names & {"callOB", "other", "ENO"}
    rows = calls(fmu, [{"x": 0}, {"x": 1}, {"x": 0}])
    assert [r["ob"] for r in rows] == [30] * 3
    assert [r["otherOb"] for r in rows] == [35] * 3
    assert [r["cycle"] for r in rows] == [100_000] * 3
    assert [r["enoAtStart"] for r in rows] == [True] * 3
    assert [r["enoSet"] for r in rows] == [False, True, False]
    assert [r["innerOb"] for r in rows] == [30, 31, 30]
    assert [r["fcEno"] for r in rows] == [True] * 3
    assert "inner.callOB" in {v.name for v in unpacked(fmu)[1].modelVariables}  # a local


DBS = """
DATA_BLOCK "Settings"
{ S7_Optimized_Access := 'TRUE' }
VERSION : 0.1
NON_RETAIN
   VAR
      limit : Int := 5;
      step : Int := 1;
      total : DInt;
   END_VAR

BEGIN
   limit := 3;
END_DATA_BLOCK

DATA_BLOCK "Counter_DB"
{ S7_Optimized_Access := 'TRUE' }
VERSION : 0.1
NON_RETAIN
"Counter"

BEGIN

END_DATA_BLOCK

DATA_BLOCK "Delay_DB"
{InstructionName := 'IEC_TIMER'; LibVersion := '1.0'}
NON_RETAIN
IEC_TIMER
BEGIN
END_DATA_BLOCK

FUNCTION_BLOCK "Counter"
   VAR_INPUT
      up : Bool;
   END_VAR
   VAR_OUTPUT
      n : Int;
   END_VAR
BEGIN
   IF #up THEN
      #n := #n + 1;
      "Settings".total := "Settings".total + 10;
   END_IF;
END_FUNCTION_BLOCK

FUNCTION "Over" : Bool
   VAR_INPUT
      n : Int;
   END_VAR
BEGIN
   #Over := #n > "Settings".limit;
END_FUNCTION

FUNCTION "Blink" : Void
   VAR_INPUT
      x : Bool;
   END_VAR
BEGIN
   "Pulse_DB".TP(IN := #x, PT := T#200ms);
END_FUNCTION

FUNCTION_BLOCK "UsesDbs"
   VAR_INPUT
      x : Bool;
   END_VAR
   VAR_OUTPUT
      delayed : Bool;
      pulse : Bool;
      count : Int;
      total : DInt;
      over : Bool;
   END_VAR
BEGIN
   // a timer read before it runs: updated at the time of the read (docs/behaviour.md §1.12)
   #pulse := "Pulse_DB".Q;
   "Delay_DB".TON(IN := #x, PT := T#200ms, Q => #delayed);
   "Blink"(x := #x);
   "Counter_DB"(up := #x);
   #count := "Counter_DB".n;
   "Settings".total := "Settings".total + "Settings".step;
   #total := "Settings".total;
   #over := "Over"(n := "Counter_DB".n);
END_FUNCTION_BLOCK
"""


# docs/scl.md rules: [S7-DB-INST] [S7-DB-GLOBAL] [DEC-DB]
def test_dbs_are_statics_of_the_fmus_fb(tmp_path):
    """docs/scl.md §3.9: an instance DB of an FB and of IEC timers (one without a DATA_BLOCK,
    run by an FC), and a global DB whose BEGIN part sets a start value, called, read and written
    by name by the FMU's FB, an FB it calls and an FC; each keeps its data from call to call, as
    the PLC's DBs do, and is among the FMU's locals. Cycle 100 ms, x TRUE in calls 1 to 4."""
    fmu = compile_text(tmp_path, DBS, "UsesDbs")
    names = {v.name for v in unpacked(fmu)[1].modelVariables if v.causality == "local"}
    assert {"Settings.limit", "Counter_DB.n", "Delay_DB.ET", "Pulse_DB.Q"} <= names
    xs = [False, True, True, True, True, False, False]
    rows = calls(fmu, [{"x": x} for x in xs])
    col = lambda name: [r[name] for r in rows]  # noqa: E731
    F, T = False, True
    assert col("delayed") == [F, F, F, T, T, F, F]  # TON 200 ms from call 1
    # TP 200 ms from call 1 (100 ms), read before it runs: TRUE at 200 ms, over at 300 ms (a
    # value left by the last call would still be TRUE in call 3)
    assert col("pulse") == [F, F, T, F, F, F, F]
    assert col("count") == [0, 1, 2, 3, 4, 4, 4]
    assert col("total") == [1, 12, 23, 34, 45, 46, 47]  # + 10 by Counter when up, + 1 here
    assert col("over") == [F, F, F, F, T, T, T]  # n > 3: the BEGIN part's limit, not 5


TYPES = """
FUNCTION_BLOCK "Types"
   VAR_INPUT
      s : SInt := -5;
      us : USInt := 200;
      ui : UInt := 65535;
      by : Byte := 16#0F;
      dw : DWord := 16#00FF00FF;
   END_VAR
   VAR_OUTPUT
      sSum : SInt;
      usSum : USInt;
      uiSum : UInt;
      byNot : Byte;
      dwAnd : DWord;
      mixed : Int;
   END_VAR
   VAR
      statS : SInt;
      statB : Byte;
   END_VAR
BEGIN
    #sSum := #s + SINT#-124;      // -5 - 124 = -129 wraps to 127
    #usSum := #us + 100;          // 300 wraps to 44
    #uiSum := #ui + 1;            // 65536 wraps to 0
    #byNot := NOT #by;
    #dwAnd := #dw AND 16#0000FFFF;
    #mixed := #s + #us;           // SINT + USINT meet in INT (docs/scl.md §3.2)
    #statS := #s;
    #statB := #by;
END_FUNCTION_BLOCK
"""


# docs/scl.md rules: [S7-TYPE-1]
def test_every_integer_type_is_an_fmi_variable_of_its_range(tmp_path):
    """The core's types (src/core/model.h), their ranges in the modelDescription and their wrap."""
    from fmpy import read_model_description

    fmu = compile_text(tmp_path, TYPES, "Types")
    md = {v.name: v for v in read_model_description(str(fmu)).modelVariables}
    ranges = {n: (int(md[n].min), int(md[n].max)) for n in ("s", "us", "ui", "by")}
    assert ranges == {"s": (-128, 127), "us": (0, 255), "ui": (0, 65535), "by": (0, 255)}
    assert (md["s"].start, md["us"].start, md["by"].start) == ("-5", "200", "15")
    out = once(fmu, {})
    assert (out["sSum"], out["usSum"], out["uiSum"]) == (127, 44, 0)
    assert (out["byNot"], out["dwAnd"], out["mixed"]) == (0xF0, 0x00FF, 195)


NAMES = """
FUNCTION_BLOCK "Names"
   VAR_INPUT
      "int" : Int;
      b : Int;
   END_VAR
   VAR_OUTPUT
      call : Int;
      errno : Int;
   END_VAR
   VAR
      scl_wrap : Int;
      NULL : Bool;
   END_VAR
   VAR_TEMP
      data : Int;
      model : Int;
   END_VAR
   VAR CONSTANT
      INT16_MAX : Int := 7;
   END_VAR
BEGIN
    #data := #"int" + #b;
    #model := #INT16_MAX;
    #scl_wrap := #data * #model;
    #NULL := TRUE;
    FOR #scl_wrap := 1 TO 2 DO
        #model += 1;
    END_FOR;
    #call := #data;
    #errno := #model;
END_FUNCTION_BLOCK
"""


def test_scl_names_that_c_has_already(tmp_path):
    """Names that are C keywords, macros of the C headers or names of the generated code keep
    their spelling in the FMU and get their own C name (docs/scl.md §4)."""
    fmu = compile_text(tmp_path, NAMES, "Names")
    out = once(fmu, {"int": 2, "b": 3})
    assert (out["call"], out["errno"]) == (5, 9)


DATA = """
TYPE "Point"
VERSION : 0.1
   STRUCT
      x : Int := 7;   // every Point starts with x = 7
      y : Real;
      flag : Bool := TRUE;
   END_STRUCT;

END_TYPE

TYPE "Segment"
VERSION : 0.1
   STRUCT
      first : "Point" := (x := 1, y := 1.5);   // over Point's own x := 7
      last : "Point";
   END_STRUCT;

END_TYPE

FUNCTION_BLOCK "Data"
VERSION : 0.1
   VAR_INPUT
      i : DInt;   // a run-time index
      j : DInt;
      v : Int;
      w : Word;
      n : Int;
   END_VAR
   VAR_OUTPUT
      p : "Point";   // an interface STRUCT: p.x, p.y, p.flag
      reals : Array[0..3] of Real;   // an interface ARRAY: reals[0] ...
      readI : Real;
      readGrid : Int;
      readOutside : Int;
      segX : Int;
      segFlag : Bool;
      segFirstX : Int;
      segFirstY : Real;
      oneFirstX : Int;
      oneFirstY : Real;
      anonB : DInt;
      lowerGrid : DInt;
      upperGrid2 : DInt;
      total : DInt;
      bit3 : Bool;
      bit15 : Bool;
      setW : Word;
      setN : Int;
      copied : Int;
   END_VAR
   VAR_IN_OUT
      counter : Int;   // an input and the output counter_out
      pair : Array[0..1] of "Point";   // pair[0].x ... and pair_out[0].x ...
      table : Array[*] of Int := [10, 20, 3(1)];   // numberOfTable starts at 5
   END_VAR
   VAR
      r : Array[0..7] of Real := [1.0, 2.0, 3(0.5)];
      grid : Array[1..3, 0..1] of Int := [11, 12, 21, 22, 31, 32];
      segs : Array[-1..1] of "Segment";
      anon : STRUCT
         a : Int := 4;
         b : DInt := 100000;
      END_STRUCT;
      scratch : "Point";
      one : "Segment" := (first := (y := 2.5));   // first.x stays Segment's 1
   END_VAR
   VAR_TEMP
      k : DInt;
      tmpGrid : Array[0..1] of Int;
   END_VAR
BEGIN
    #p.x := #v;
    #p.y := 0.25;
    #p.flag := #v > 0;
    FOR #k := 0 TO 3 DO
        #reals[#k] := #r[#k + 1];
    END_FOR;
    #readI := #r[#i];                  // outside 0..7: 0.0
    #readGrid := #grid[#i, #j];        // outside: 0
    #grid[#i, #j] := -1;               // outside: ignored
    #readOutside := #grid[3, 1];
    #segs[#i].last.x := #v;            // outside -1..1: ignored
    #segX := #segs[0].last.x;
    #segFlag := #segs[-1].first.flag;
    #segFirstX := #segs[1].first.x;
    #segFirstY := #segs[1].first.y;
    #oneFirstX := #one.first.x;
    #oneFirstY := #one.first.y;
    #anonB := #anon.b + #anon.a;
    #lowerGrid := LOWER_BOUND(ARR := #grid, DIM := 1);
    #upperGrid2 := UPPER_BOUND(#grid, 2);
    #total := 0;
    FOR #k := LOWER_BOUND(ARR := #table, DIM := 1) TO UPPER_BOUND(ARR := #table, DIM := 1) DO
        #total += #table[#k];
    END_FOR;
    #table[0] += 1;                    // the block writes its table
    #counter += 1;
    #pair[1].y := #pair[0].y * 2.0;
    #bit3 := #w.%X3;
    #bit15 := #n.%X15;
    #setW := #w;
    #setW.%X0 := TRUE;
    #setW.%X15 := FALSE;
    #setN := #n;
    #setN.%X15 := TRUE;
    #scratch := #p;                    // a whole STRUCT
    #copied := #scratch.x;
    #tmpGrid[1] := #tmpGrid[1] + 1;    // a VAR_TEMP ARRAY starts at 0 in every call
    #copied := #copied + #tmpGrid[1] * 1000;
END_FUNCTION_BLOCK
"""


data = compiled(DATA, "Data")


def test_struct_and_array_interface_names_and_start_values(data):
    """docs/scl.md §4: a STRUCT's members and an ARRAY's elements are FMI variables of their
    own, p.x and reals[0]; a VAR_IN_OUT is the input x and the output x_out; an ARRAY[*] the
    tunable parameters table[i] with its size numberOfTable (start: the initial values given)."""
    from fmpy import read_model_description

    md = {v.name: v for v in read_model_description(str(data)).modelVariables}
    assert {"p.x", "p.y", "p.flag", "reals[0]", "reals[3]"} <= set(md)
    assert md["p.x"].causality == "output" and md["p.y"].type == "Real"
    assert (md["counter"].causality, md["counter_out"].causality) == ("input", "output")
    assert (md["pair[1].y"].causality, md["pair_out[1].y"].causality) == ("input", "output")
    assert md["pair[0].x"].start == "7"  # the UDT's initial value
    size = md["numberOfTable"]
    assert (size.causality, size.variability, size.start) == ("parameter", "fixed", "5")
    assert (int(size.min), int(size.max)) == (1, 64)
    table = [md[f"table[{k}]"] for k in range(64)]
    assert {(t.causality, t.variability) for t in table} == {("parameter", "tunable")}
    assert [t.start for t in table[:6]] == ["10", "20", "1", "1", "1", "0"]
    assert "table[64]" not in md


# docs/scl.md rules: [S7-STRUCT] [S7-ARRAY] [S7-BIT]
def test_arrays_structs_and_their_bounds_by_hand(data):
    inputs = {"i": 2, "j": 1, "v": 9, "w": 0x0008, "n": -1, "counter": 41, "pair[0].y": 0.75}
    out = once(data, inputs)
    assert (out["p.x"], out["p.y"], out["p.flag"]) == (9, 0.25, True)
    # r := [1.0, 2.0, 3(0.5)], the rest 0.0: reals[k] = r[k + 1]
    assert [out[f"reals[{k}]"] for k in range(4)] == [2.0, 0.5, 0.5, 0.5]
    assert out["readI"] == 0.5  # r[2]
    assert out["readGrid"] == 22  # grid[2, 1], the row-major initial values
    assert out["readOutside"] == 32
    assert out["segX"] == 7  # segs[2] is outside -1..1: ignored; x starts at 7 (the UDT)
    assert out["segFlag"] is True  # a nested UDT's default
    # Segment's initial value of its member first overrides Point's, a variable's Segment's
    assert (out["segFirstX"], out["segFirstY"]) == (1, 1.5)
    assert (out["oneFirstX"], out["oneFirstY"]) == (1, 2.5)
    assert out["anonB"] == 100004
    assert (out["lowerGrid"], out["upperGrid2"]) == (1, 1)
    assert out["total"] == 10 + 20 + 1 + 1 + 1
    assert out["counter_out"] == 42
    assert out["pair_out[1].y"] == 1.5  # pair[0].y 0.75 doubled, into the in/out's own data
    assert (out["bit3"], out["bit15"]) == (True, True)  # -1 has every bit set
    assert out["setW"] == 0x0009
    assert out["setN"] == -1
    assert out["copied"] == 9 + 1000


# docs/scl.md rules: [DEC-INDEX]
def test_an_index_outside_reads_0_and_a_write_is_ignored(data):
    """docs/scl.md §3.8, Decision: the CPU stops with an access error; the FMU reads 0 and ignores
    the write, and goes on."""
    rows = calls(data, [{"i": 8, "j": 0}, {"i": 3, "j": 1}, {"i": -5, "j": 0}])
    assert rows[0]["readI"] == 0.0  # r[8]: outside 0..7
    assert rows[0]["readGrid"] == 0  # grid[8, 0]
    assert rows[1]["readGrid"] == 32  # grid[3, 1] is inside: its value ...
    assert rows[1]["readOutside"] == -1  # ... overwritten in the same call
    assert rows[2]["readOutside"] == -1  # i = -5: the write was ignored


# docs/scl.md rules: [S7-ARRAY-STAR]
def test_in_out_keeps_what_the_block_wrote_and_the_table_its_size(data):
    """The in/out counter: the importer's value when it sets one, else what the block left (the
    caller's variable on the PLC); the block sees numberOfTable elements of its table."""
    from tests.scl.driver import run_cs as run

    rows = run(data, CYCLE_US, {"numberOfTable": 2}, {"counter": 5}, [(CYCLE_US, {})] * 2)
    assert [r["counter_out"] for r in rows] == [6, 7, 8]
    # the table [10, 20] and the block's table[0] += 1 in every call
    assert [r["total"] for r in rows] == [30, 31, 32]
    rows = run(data, CYCLE_US, {}, {"counter": 5}, [(CYCLE_US, {"counter": 100})])
    assert [r["counter_out"] for r in rows] == [6, 101]


WIDE = """
FUNCTION_BLOCK "Wide"
   VAR_INPUT
      d : DInt;
      x : LReal;
   END_VAR
   VAR_OUTPUT
      wrapsToMin : Bool;
      ulintWraps : Bool;
      divMin : Bool;
      modMin : DInt;
      lowBits : DInt;
      highBits : DInt;
      fromReal : Bool;
      toReal : LReal;
      ultimeNs : DInt;
      ltimeMs : DInt;
      fromTime : DInt;
      ltimeScaled : DInt;
      lwordBit : Bool;
      lwordShifted : DWord;
      mixed : Bool;
      negMin : Bool;
      absMin : Bool;
      maxUlint : Bool;
      caseUlint : Int;
   END_VAR
   VAR
      big : LInt := LINT#9223372036854775807;
      ubig : ULInt := ULINT#18446744073709551615;
      lw : LWord := LWORD#16#8000_0000_0000_0001;
      lt : LTime := LT#1s5ns;
   END_VAR
   VAR_TEMP
      t : LInt;
      ltShort : LTime;
   END_VAR
BEGIN
    #t := #big + 1;
    #wrapsToMin := #t = LINT#-9223372036854775808;
    #ulintWraps := #ubig + 1 = 0;
    #divMin := #t / -1 = #t;                  // the CPU's wrap, not a trap
    #modMin := LINT_TO_DINT(#t MOD -1);
    #lowBits := LINT_TO_DINT(LINT#16#1_0000_0007);
    #highBits := LINT_TO_DINT(#t / 4294967296);
    #fromReal := LREAL_TO_LINT(#x) = LINT#9223372036854775807;
    #toReal := LINT_TO_LREAL(#big);
    #ultimeNs := LINT_TO_DINT(LTIME_TO_LINT(#lt));
    #ltimeMs := TIME_TO_DINT(LTIME_TO_TIME(LT#1s999ms999us999ns));
    #fromTime := LINT_TO_DINT(LTIME_TO_LINT(TIME_TO_LTIME(T#2ms)));
    #ltShort := #lt * 3 - LT#15ns;
    #ltimeScaled := LINT_TO_DINT(LTIME_TO_LINT(#ltShort));
    #lwordBit := #lw.%X63 AND #lw.%X0 AND NOT #lw.%X1;
    #lwordShifted := LWORD_TO_DWORD(#lw);
    #mixed := #d + #big < 0;                   // DINT + LINT runs in LINT: wraps
    #negMin := -#t = #t;
    #absMin := ABS(#t) = #t;
    #maxUlint := MAX(IN1 := #ubig, IN2 := ULINT#1) = #ubig;   // 2^64 - 1 is the larger
    CASE #ubig OF
        0..9223372036854775807: #caseUlint := 1;
        9223372036854775808..18446744073709551615: #caseUlint := 2;
    END_CASE;
END_FUNCTION_BLOCK
"""


# docs/scl.md rules: [DEC-TYPE-64] [S7-WRAP-64] [S7-TIME-L]
def test_64_bit_types_by_hand(tmp_path):
    """LINT, ULINT, LWORD wrap at 64 bits, LTIME counts ns (docs/scl.md §3.1, §3.3); their FMI
    face is what they convert to, since FMI 2.0 has no 64-bit integer."""
    fmu = compile_text(tmp_path, WIDE, "Wide")
    out = once(fmu, {"d": 1, "x": 1e19})
    assert out["wrapsToMin"] and out["ulintWraps"] and out["divMin"]
    assert out["modMin"] == 0
    assert out["lowBits"] == 7  # the low 32 bits of 2^32 + 7
    assert out["highBits"] == -(2**31)  # -2^63 / 2^32
    assert out["fromReal"]  # 1e19 is beyond the largest LINT: its limit
    assert out["toReal"] == 9223372036854775808.0  # 2^63 - 1 rounds to 2^63
    assert out["ultimeNs"] == 1_000_000_005
    assert out["ltimeMs"] == 1999  # LTIME_TO_TIME truncates to whole ms
    assert out["fromTime"] == 2_000_000
    assert out["ltimeScaled"] == 3_000_000_000 + 15 - 15 - 2**32  # low 32 bits, as a DINT
    assert out["lwordBit"]
    assert out["lwordShifted"] == 1
    assert out["mixed"]  # 1 + (2^63 - 1) wraps to -2^63
    assert out["negMin"] and out["absMin"]
    assert out["maxUlint"]
    assert out["caseUlint"] == 2  # ULINT compares unsigned


def test_arrays_and_structs_are_in_the_fmu_state(data):
    """Every element and member of a static ARRAY or STRUCT is in the FMU state (docs/scl.md
    §4): a serialized state taken after one call and restored later repeats the calls after it."""
    from tests.scl.driver import Instance

    s = Instance(data, {"cycleTime": CYCLE_US / 1e6}, {"i": 1, "j": 0, "v": 3, "counter": 1})
    names = ["readGrid", "readOutside", "segX", "counter_out", "total"]

    def step(changes):
        s.set(changes)
        s.fmu.doStep(currentCommunicationPoint=step.t, communicationStepSize=CYCLE_US / 1e6)
        step.t += CYCLE_US / 1e6
        return s.get(names)

    step.t = 0.0
    step({"i": 3, "j": 1})  # grid[3, 1] := -1 in the call at 0.1 s
    saved = s.fmu.serializeFMUstate(s.fmu.getFMUstate())
    later = [step({"i": 0, "j": 0}), step({"i": 1, "j": 1})]  # segs[0].last.x := 3
    s.fmu.setFMUstate(s.fmu.deSerializeFMUstate(saved))
    step.t = 0.1
    again = [step({"i": 0, "j": 0}), step({"i": 1, "j": 1})]
    s.free()
    assert again == later
    assert later[0]["readOutside"] == -1  # the write before the state was taken
    assert later[0]["segX"] == 3 and later[0]["counter_out"] == 4


INITIALS = """
TYPE "U"
   STRUCT
      a : Int := 1;
      b : LInt;
   END_STRUCT;
END_TYPE
FUNCTION_BLOCK "Initials"
   VAR_INPUT
      k : Int;
   END_VAR
   VAR_OUTPUT
      o : Int;
      q : Bool;
      q7 : Bool;
   END_VAR
   VAR_IN_OUT
      io : Int := 5;
   END_VAR
   VAR CONSTANT
      c : ARRAY[0..1] OF Int := [1, 2];
   END_VAR
   VAR
      x3 : ARRAY[0..1, 0..1, 0..1] OF Bool := [7(TRUE)];
      n : STRUCT y : STRUCT z : Int := 3; END_STRUCT; END_STRUCT;
      u : ARRAY[0..1] OF "U" := [(a := 5), 1()];
      v : ARRAY[0..3] OF Int := [2(1), 2(2)];
   END_VAR
   VAR_TEMP
      tu : ARRAY[1..2] OF "U";
   END_VAR
BEGIN
   #q := #x3[#k, #k, #k];
   #q7 := #x3[1, 1, 1];
   #tu[#k] := #u[#k];                  // a whole UDT element, at run-time indices
   #o := #c[1] + #n.y.z + #u[1].a + #v[3] + #tu[1].a * 10 + #tu[2].a * 100 + #io * 1000;
END_FUNCTION_BLOCK
"""


# docs/scl.md rules: [S7-STRUCT]
def test_initial_values_of_every_shape_and_temporary_arrays(tmp_path):
    """[7(TRUE)] fills the first seven of eight elements (the last index fastest), 1() keeps a
    UDT element's defaults, a nested anonymous STRUCT has its member's, an in/out its input's
    start; a VAR_TEMP ARRAY of a UDT starts at the UDT's initial values in every call."""
    fmu = compile_text(tmp_path, INITIALS, "Initials")
    rows = calls(fmu, [{"k": 0}, {"k": 1}, {"k": 2}])
    # c[1] 2, n.y.z 3, u[1].a 1 (the UDT's), v[3] 2; tu[1] := u[1] at k = 1 (a 1), tu[2] := u[2]
    # (outside u's 0..1: zeros) at k = 2; the untouched temporaries hold the UDT's a = 1
    assert [r["o"] for r in rows] == [
        2 + 3 + 1 + 2 + 10 + 100 + 5000,
        2 + 3 + 1 + 2 + 10 + 100 + 5000,
        2 + 3 + 1 + 2 + 10 + 0 + 5000,
    ]
    # x3[0, 0, 0] is the first element, x3[1, 1, 1] the eighth, x3[2, 2, 2] outside: FALSE
    assert [r["q"] for r in rows] == [True, False, False]
    assert not rows[0]["q7"]  # the eighth element, x3[1, 1, 1], keeps FALSE


def test_data_structures_run_the_same_in_fmi_3(data, tmp_path):
    """The FMI 3.0 FMU of the same SCL: the same names (p.x, reals[0], counter_out, table[i])
    and the same outputs, call by call."""
    fmu3 = compile_text(tmp_path, DATA, "Data", fmi=3)
    per_call = [{"i": 2, "j": 1, "v": 9, "w": 8, "n": -1, "counter": 41}, {"i": 3}, {"i": -5}]
    assert calls(fmu3, per_call) == calls(data, per_call)


def test_a_udt_of_another_source_after_the_block(tmp_path):
    """docs/scl.md §2: a UDT may stand in any of the sources, after the block that uses it; a
    type defined twice is refused at its second definition."""
    from lgf_fmus import scl

    block = tmp_path / "block.scl"
    block.write_text(
        'FUNCTION_BLOCK "Uses"\n   VAR_OUTPUT\n      p : "Pair";\n   END_VAR\nBEGIN\n'
        "    #p.b := #p.a + 1;\nEND_FUNCTION_BLOCK\n",
        encoding="utf-8",
    )
    udt = tmp_path / "types.scl"
    udt.write_text(
        'TYPE "Pair"\n   STRUCT\n      a : Int := 41;\n      b : Int;\n   END_STRUCT;\nEND_TYPE\n',
        encoding="utf-8",
    )
    fmu = scl.compile(
        [block, udt], block="Uses", output=tmp_path / "Uses.fmu", werror=True, win64=False
    )
    assert once(fmu, {})["p.b"] == 42
    with pytest.raises(scl.SclError) as caught:
        scl.generate_c([block, udt, udt], block="Uses")
    (error,) = caught.value.diagnostics
    assert f"{error.loc}: {error.message}" == f"{udt}:1:1: the type Pair is defined twice"
    assert [(str(n.loc), n.message) for n in error.notes] == [(f"{udt}:1:1", "first defined here")]


CALLS = """
FUNCTION_BLOCK "Calls"
   VAR_INPUT
      a : Int;
      b : Int;
      start : Bool;
      speedIn : Int;
   END_VAR
   VAR_OUTPUT
      twice : Int;
      sum : DInt;
      diff : Int;
      voided : Int;
      speed : Int;
      count : Int;
      running : Bool;
      nested : Int;
      nestedRunning : Bool;
   END_VAR
   VAR
      m : "Motor";
      m2 : Motor;
      statDiff : Int;
   END_VAR
BEGIN
    #twice := "Twice"(#a);                             // positional, and the FC's name is
    #sum := "AddSub"(x := #a, y := #b, diff => #statDiff);  // no clash with #twice
    #diff := #statDiff;
    "SetTo"(f := 7, o => #voided);
    #m(start := #start, speedIn := #speedIn, speed => #speed);
    #count := #m.count;
    #running := #m.running;
    IF #b = 1 THEN
        #m2(start := TRUE, speedIn := 1);
    ELSE
        #m2(speedIn := 3);                            // start keeps its last value
    END_IF;
    #nested := #m2.speed;
    #nestedRunning := #m2.running;
END_FUNCTION_BLOCK

FUNCTION "Twice" : Int
   VAR_INPUT
      x : Int;
   END_VAR
BEGIN
    #Twice := #x * 2;
END_FUNCTION

FUNCTION "AddSub" : DInt
   VAR_INPUT
      x : Int;
      y : Int;
   END_VAR
   VAR_OUTPUT
      diff : Int;
   END_VAR
   VAR_TEMP
      t : DInt;
   END_VAR
BEGIN
    #t := #x;
    AddSub := #t + #y;
    #diff := #x - #y;
    IF #x > 100 THEN
        RETURN;
    END_IF;
    #diff := #diff + "Twice"(1);
END_FUNCTION

FUNCTION "SetTo" : Void
   VAR_INPUT
      f : Int;                // f and ctx: names the generated C has (docs/scl.md §4)
   END_VAR
   VAR_OUTPUT
      o : Int;
   END_VAR
   VAR_TEMP
      ctx : Int;
   END_VAR
BEGIN
    #ctx := #f;
    #o := #ctx;
END_FUNCTION
"""

# in a file of its own, after the FB that uses it: blocks may stand in any order, in any file
MOTOR = """
FUNCTION_BLOCK "Motor"
   VAR_INPUT
      start : Bool;
      speedIn : Int;
   END_VAR
   VAR_OUTPUT
      speed : Int;
      count : Int;
      running : Bool;
   END_VAR
   VAR
      edge : R_TRIG;
      calls : Int;
   END_VAR
BEGIN
    #edge(CLK := #start);
    IF #edge.Q THEN
        #count := #count + 1;
    END_IF;
    #calls += 1;
    #speed := "Twice"(x := #speedIn) + #calls;
    #running := #start;
END_FUNCTION_BLOCK
"""


@pytest.fixture(scope="module")
def calls_fmu(tmp_path_factory):
    from lgf_fmus import scl

    tmp = tmp_path_factory.mktemp("calls")
    (tmp / "calls.scl").write_text(CALLS, encoding="utf-8")
    (tmp / "motor.scl").write_text(MOTOR, encoding="utf-8")
    return scl.compile(
        [tmp / "calls.scl", tmp / "motor.scl"],
        block="Calls",
        output=tmp / "Calls.fmu",
        werror=True,
        win64=False,
    )


# docs/scl.md rules: [S7-FC] [S7-FB] [S7-NAMES]
def test_fc_calls_and_multi_instances(calls_fmu):
    """docs/scl.md §3.6: an FC's return value and outputs, RETURN in an FC, an FC of an FC; a
    user FB's instances keep their data from call to call, an input not given keeps its value."""
    per_call = [
        {"a": 3, "b": 5, "start": True, "speedIn": 10},
        {"a": 200, "b": 1},
        {"a": -4, "b": 5, "start": False},
        {"start": True},
    ]
    rows = calls(calls_fmu, per_call)
    col = lambda name: [r[name] for r in rows]  # noqa: E731
    assert col("twice") == [6, 400, -8, -8]
    assert col("sum") == [8, 201, 1, 1]
    # x - y, then + Twice(1) = 2 unless x > 100 returned first
    assert col("diff") == [3 - 5 + 2, 199, -4 - 5 + 2, -7]
    assert col("voided") == [7] * 4
    # m: a count per rising edge of start (R_TRIG), speed = 2 * speedIn + its own calls
    assert col("count") == [1, 1, 1, 2]
    assert col("speed") == [21, 22, 23, 24]
    assert col("running") == [True, True, False, True]
    # m2: speedIn 3 (1 when b = 1) plus its calls; start TRUE from the call with b = 1 on
    assert col("nested") == [2 * 3 + 1, 2 * 1 + 2, 2 * 3 + 3, 2 * 3 + 4]
    assert col("nestedRunning") == [False, True, True, True]


# docs/scl.md rules: [S7-FB]
def test_instances_are_in_the_fmu_state(calls_fmu):
    """Every member of a multi-instance (its R_TRIG's memory too) is restored with the state."""
    from tests.scl.driver import Instance

    s = Instance(calls_fmu, {"cycleTime": 0.1}, {"a": 1, "b": 5, "start": True, "speedIn": 1})
    s.fmu.doStep(currentCommunicationPoint=0.0, communicationStepSize=0.1)
    state = s.fmu.getFMUstate()
    before = s.outputs()
    s.set({"start": False})
    s.fmu.doStep(currentCommunicationPoint=0.1, communicationStepSize=0.1)
    s.set({"start": True})
    s.fmu.doStep(currentCommunicationPoint=0.2, communicationStepSize=0.1)
    assert s.outputs()["count"] == 2  # a second edge
    s.fmu.setFMUstate(state)
    assert s.outputs() == before
    s.fmu.doStep(currentCommunicationPoint=0.1, communicationStepSize=0.1)
    # start is TRUE still: the restored edge memory sees no edge
    assert s.outputs()["count"] == 1
    s.free()


COUNTERS = """
FUNCTION_BLOCK "Counters"
   VAR_INPUT
      cu : Bool;
      cd : Bool;
      r : Bool;
      ld : Bool;
      pv : Int := 3;
   END_VAR
   VAR_OUTPUT
      ctuQ : Bool;
      ctuCV : Int;
      ctdQ : Bool;
      ctdCV : Int;
      qu : Bool;
      qd : Bool;
      ctudCV : Int;
      usCV : USInt;
      usQ : Bool;
      sCV : SInt;
      dCV : DInt;
   END_VAR
   VAR
      up : CTU;
      down : CTD_INT;
      both : CTUD;
      usDown : CTD_USINT;
      sUp : CTU_SINT;
      dUpDown : CTUD_DINT;
   END_VAR
BEGIN
    #up(CU := #cu, R := #r, PV := #pv, Q => #ctuQ, CV => #ctuCV);
    #down(CD := #cd, LD := #ld, PV := #pv, Q => #ctdQ, CV => #ctdCV);
    #both(CU := #cu, CD := #cd, R := #r, LD := #ld, PV := #pv, QU => #qu, QD => #qd, CV => #ctudCV);
    #usDown(CD := #cd, LD := #ld, PV := 2);
    #usCV := #usDown.CV;
    #usQ := #usDown.Q;
    #sUp(CU := #cu, R := #r, PV := 0);
    #sCV := #sUp.CV;
    #dUpDown(CU := #cu, CD := FALSE, R := FALSE, LD := FALSE, PV := 0, CV => #dCV);
END_FUNCTION_BLOCK
"""


counters = compiled(COUNTERS, "Counters")


# docs/scl.md rules: [S7-COUNTER]
def test_counters_by_hand(counters):
    """docs/scl.md §3.6: CU and CD count at their rising edge; R before LD before counting; in
    CTUD an edge of CU and one of CD in the same call cancel; CV stops at the type's limits."""
    F, T = False, True
    # cu, cd, r, ld per call; PV 3
    ins = [
        (T, F, F, F),
        (F, T, F, F),
        (T, T, F, F),
        (F, F, F, T),
        (T, T, F, F),
        (F, F, T, F),
        (T, F, T, T),
        (F, F, F, F),
        (T, F, F, F),
    ]
    rows = calls(counters, [dict(zip(("cu", "cd", "r", "ld"), x)) for x in ins])
    col = lambda name: [r[name] for r in rows]  # noqa: E731
    assert col("ctuCV") == [1, 1, 2, 2, 3, 0, 0, 0, 1]
    assert col("ctuQ") == [F, F, F, F, T, F, F, F, F]
    assert col("ctdCV") == [0, -1, -1, 3, 2, 2, 3, 3, 3]
    assert col("ctdQ") == [T, T, T, F, F, F, F, F, F]
    assert col("ctudCV") == [1, 0, 1, 3, 3, 0, 0, 0, 1]
    assert col("qu") == [F, F, F, T, T, F, F, F, F]
    assert col("qd") == [F, T, F, F, F, T, T, T, F]
    assert col("usCV") == [0, 0, 0, 2, 1, 1, 2, 2, 2]  # a USINT stops at 0
    assert col("usQ") == [T, T, T, F, F, F, F, F, F]


# docs/scl.md rules: [S7-COUNTER]
def test_a_counter_stops_at_its_types_limit(counters):
    """CTU_SINT: 130 rising edges count to 127 and stop there (no wrap to -128)."""
    rows = calls(counters, [{"cu": k % 2 == 0} for k in range(260)], cycle_us=1000)
    assert [r["sCV"] for r in rows] == [min(k // 2 + 1, 127) for k in range(260)]
    assert rows[-1]["dCV"] == 130  # CTUD_DINT: far from its limit


FUNCTIONS = """
FUNCTION_BLOCK "Functions"
   VAR_INPUT
      k : Int;
      w : Word;
      i : Int;
      n : UInt;
      r : Real;
      l : LReal;
   END_VAR
   VAR_OUTPUT
      mux3 : Int;
      muxElse : Int;
      muxBool : Bool;
      shl : Word;
      shr : Word;
      rol : Word;
      ror : Word;
      shrInt : Int;
      shlInt : Int;
      expR : Real;
      lnR : Real;
      logL : LReal;
      powR : Real;
      powL : LReal;
      powInt : LReal;
      expt : Real;
      sinL : LReal;
      cosL : LReal;
      tanR : Real;
      atanL : LReal;
      asinR : Real;
      acosR : Real;
      neg : LReal;
      sqrR : Real;
      sqrL : LReal;
      sqrLit : LReal;
      shortAnd : Bool;
      shortOr : Bool;
      cycleAnd : UDInt;
      cycleOr : UDInt;
      swapW : Word;
      swapD : DWord;
      swapL : DWord;
   END_VAR
BEGIN
    #swapW := SWAP(#w);
    #swapD := SWAP(DW#16#12345678);
    #swapL := LWORD_TO_DWORD(SWAP(LW#16#0102030405060708)); // 16#0807060504030201: its low half
    #mux3 := MUX(K := #k, IN0 := 10, IN1 := 20, IN2 := #i);
    #muxElse := MUX(K := #k, IN0 := 10, IN1 := 20, INELSE := -1);
    #muxBool := MUX(#k, FALSE, TRUE);
    #shl := SHL(IN := #w, N := #n);
    #shr := SHR(IN := #w, N := #n);
    #rol := ROL(IN := #w, N := #n);
    #ror := ROR(IN := #w, N := #n);
    #shrInt := SHR(IN := #i, N := #n);
    #shlInt := SHL(IN := #i, N := #n);
    #expR := EXP(#r);
    #lnR := LN(#r);
    #logL := LOG(#l);
    #powR := #r ** 2;
    #powL := #l ** 0.5;
    #powInt := 2.0 ** 10;
    #expt := EXPT(IN1 := #r, IN2 := REAL#0.5);
    #sinL := SIN(#l);
    #cosL := COS(#l);
    #tanR := TAN(#r);
    #atanL := ATAN(#l);
    #asinR := ASIN(#r);
    #acosR := ACOS(#r);
    #neg := -#l ** 2;                  // ** binds tighter than the sign
    #sqrR := SQR(#r);
    #sqrL := SQR(IN := #l);
    #sqrLit := SQR(3);
    #cycleAnd := 7;
    #shortAnd := #k > 100 AND QRY_CINT(OB_NR := 30, CYCLE => #cycleAnd) = 0;
    #cycleOr := 7;
    #shortOr := #k <= 100 OR QRY_CINT(OB_NR := 30, CYCLE => #cycleOr) = 0;
END_FUNCTION_BLOCK
"""


functions = compiled(FUNCTIONS, "Functions")


@pytest.mark.parametrize(
    "k, mux3, mux_else, mux_bool", [(0, 10, 10, False), (1, 20, 20, True), (2, 7, -1, False)]
)
# docs/scl.md rules: [S7-MUX]
def test_mux(functions, k, mux3, mux_else, mux_bool):
    out = once(functions, {"k": k, "i": 7})
    assert (out["mux3"], out["muxElse"], out["muxBool"]) == (mux3, mux_else, mux_bool)


# docs/scl.md rules: [S7-MUX]
def test_mux_outside_its_inputs_gives_inelse_or_0(functions):
    """docs/scl.md §3.5 (Decision): a K outside IN0 .. INn gives INELSE, or 0 without one."""
    out = once(functions, {"k": -1, "i": 7})
    assert (out["mux3"], out["muxElse"], out["muxBool"]) == (0, -1, False)
    assert once(functions, {"k": 3, "i": 7})["mux3"] == 0


@pytest.mark.parametrize(
    "w, n, shl, shr, rol, ror",
    [
        (0x8001, 1, 0x0002, 0x4000, 0x0003, 0xC000),
        (0x8001, 4, 0x0010, 0x0800, 0x0018, 0x1800),
        (0x8001, 16, 0, 0, 0x8001, 0x8001),  # a shift by the width clears, a rotation is whole
        (0x8001, 17, 0, 0, 0x0003, 0xC000),  # a rotation by 17 is one by 1
    ],
)
# docs/scl.md rules: [S7-SHIFT]
def test_shifts_and_rotations_of_a_word(functions, w, n, shl, shr, rol, ror):
    out = once(functions, {"w": w, "n": n})
    assert (out["shl"], out["shr"], out["rol"], out["ror"]) == (shl, shr, rol, ror)


# docs/scl.md rules: [S7-SWAP]
def test_swap_reverses_the_bytes(functions):
    """The manual's examples: SWAP(16#1234) = 16#3412, SWAP(16#12345678) = 16#78563412."""
    out = once(functions, {"w": 0x1234})
    assert (out["swapW"], out["swapD"], out["swapL"]) == (0x3412, 0x78563412, 0x04030201)


@pytest.mark.parametrize(
    "i, n, shr, shl", [(-8, 1, -4, -16), (-8, 20, -1, 0), (16384, 1, 8192, -32768), (5, 0, 5, 5)]
)
# docs/scl.md rules: [S7-SHIFT]
def test_shifts_of_an_int_keep_its_sign(functions, i, n, shr, shl):
    """SHR of a signed integer fills with its sign bit; SHL wraps in 16 bits."""
    out = once(functions, {"i": i, "n": n})
    assert (out["shrInt"], out["shlInt"]) == (shr, shl)


# docs/scl.md rules: [S7-OP-PRIO] [S7-FN-REAL]
def test_real_and_lreal_functions(functions):
    """docs/scl.md §3.5: a REAL function is the C library's double result rounded to float32,
    an LREAL one the double result; ** is pow; SIN and COS of an LREAL the library's."""
    f32 = lambda x: float(np.float32(x))  # noqa: E731
    out = once(functions, {"r": 2.0, "l": 0.25})
    assert out["expR"] == f32(math.exp(2.0))
    assert out["lnR"] == f32(math.log(2.0))
    assert out["logL"] == math.log10(0.25)
    assert out["powR"] == 4.0
    assert out["powL"] == 0.5
    assert out["powInt"] == 1024.0
    assert out["expt"] == f32(math.sqrt(2.0))
    assert out["sinL"] == math.sin(0.25)
    assert out["cosL"] == math.cos(0.25)
    assert out["tanR"] == f32(math.tan(2.0))
    assert out["atanL"] == math.atan(0.25)
    assert math.isnan(out["asinR"]) and math.isnan(out["acosR"])  # beyond [-1, 1]: NaN
    assert out["neg"] == -0.0625
    out = once(functions, {"r": 0.5, "l": 0.0})
    assert out["asinR"] == f32(math.asin(0.5))
    assert out["acosR"] == f32(math.acos(0.5))
    assert out["lnR"] == f32(math.log(0.5))
    assert out["logL"] == -math.inf  # LOG(0)
    assert once(functions, {"r": 0.0})["lnR"] == -math.inf


# docs/scl.md rules: [S7-OP-SHORT]
def test_and_or_evaluate_their_right_operand_where_it_decides(functions):
    """AND with a FALSE left operand and OR with a TRUE one do not run QRY_CINT on their right,
    which would write CYCLE (docs/scl.md §3.4)."""
    out = once(functions, {"k": 0})
    assert (out["shortAnd"], out["cycleAnd"]) == (False, 7)
    assert (out["shortOr"], out["cycleOr"]) == (True, 7)
    out = once(functions, {"k": 101})
    assert (out["shortAnd"], out["cycleAnd"]) == (True, 100_000)  # cycleTime in µs
    assert (out["shortOr"], out["cycleOr"]) == (True, 100_000)


# docs/scl.md rules: [S7-FN-1]
def test_sqr(functions):
    """docs/scl.md §3.5: SQR(IN) = IN * IN, rounded once to IN's type (Siemens: SQR of a Real or
    LReal); an untyped literal is an LREAL."""
    out = once(functions, {"r": -3.0, "l": 0.1})
    assert (out["sqrR"], out["sqrLit"]) == (9.0, 9.0)
    assert out["sqrL"] == 0.1 * 0.1  # 0.010000000000000002 in double
    r = np.float32(1.1)  # 1.10000002384185791015625
    out = once(functions, {"r": float(r)})
    assert out["sqrR"] == float(r * r)  # 1.21000003814697265625: float32, not 1.21
    assert once(functions, {"r": 2e19})["sqrR"] == math.inf  # 4e38 is beyond the largest REAL


CLOCK = """
FUNCTION_BLOCK "Clock"
   VAR_OUTPUT
      year : UInt;
      month : USInt;
      day : USInt;
      weekday : USInt;
      hour : USInt;
      minute : USInt;
      second : USInt;
      ns : UDInt;
      localHour : USInt;
      localDay : USInt;
      ret : Int;
      elapsed : LReal;
      fcHour : USInt;
   END_VAR
   VAR
      now : DTL;
      statMem : LReal;
   END_VAR
   VAR_TEMP
      loc : DTL;
   END_VAR
BEGIN
    #ret := RD_SYS_T(OUT => #now);
    #year := #now.YEAR;
    #month := #now.MONTH;
    #day := #now.DAY;
    #weekday := #now.WEEKDAY;
    #hour := #now.HOUR;
    #minute := #now.MINUTE;
    #second := #now.SECOND;
    #ns := #now.NANOSECOND;
    RD_LOC_T(OUT => #loc);
    #localHour := #loc.HOUR;
    #localDay := #loc.DAY;
    #elapsed := RUNTIME(#statMem);
    #fcHour := "LocalHour"();
END_FUNCTION_BLOCK

FUNCTION "LocalHour" : USInt   // an FC without inputs reads the clock of its caller's call
   VAR_TEMP
      t : DTL;
   END_VAR
BEGIN
    RD_LOC_T(OUT => #t);
    #LocalHour := #t.HOUR;
END_FUNCTION
"""


clock = compiled(CLOCK, "Clock")


# docs/scl.md rules: [S7-TYPE-DTL] [S7-CLOCK]
def test_rd_sys_t_counts_from_start_date_and_time(clock):
    """docs/scl.md §3.6: 2024-02-28 23:59:59.950 UTC (a Wednesday, WEEKDAY 4) and 100 ms
    later the leap day 2024-02-29 00:00:00.050 (a Thursday); RD_LOC_T one hour ahead."""
    start = 1709164799.95  # 19781 days after 1970-01-01, plus 86399.95 s
    assert start == 19781 * 86400 + 86399.95
    rows = run_cs(
        clock,
        CYCLE_US,
        {"startDateAndTime": start, "localTimeOffset": 3600},
        {},
        [(CYCLE_US, {})],
    )
    first, second = rows
    assert [first[n] for n in ("year", "month", "day", "weekday")] == [2024, 2, 28, 4]
    assert [first[n] for n in ("hour", "minute", "second", "ns")] == [23, 59, 59, 950_000_000]
    assert [second[n] for n in ("year", "month", "day", "weekday")] == [2024, 2, 29, 5]
    assert [second[n] for n in ("hour", "minute", "second", "ns")] == [0, 0, 0, 50_000_000]
    assert (first["localDay"], first["localHour"], first["fcHour"]) == (29, 0, 0)
    assert (second["localDay"], second["localHour"], second["fcHour"]) == (29, 1, 1)
    assert first["ret"] == 0


# docs/scl.md rules: [S7-CLOCK]
def test_start_date_and_time_defaults_to_2024(clock):
    """Without a value: 2024-01-01 00:00 UTC, a Monday (WEEKDAY 2)."""
    out = once(clock, {})
    assert [out[n] for n in ("year", "month", "day", "weekday", "hour")] == [2024, 1, 1, 2, 0]


# docs/scl.md rules: [DEC-RUNTIME]
def test_runtime_measures_the_simulated_time_between_calls(clock):
    """RUNTIME(#mem): the first call with MEM 0 gives the time since the first call (0 s), then
    the time since the previous call, as a difference of the two times in s."""
    rows = calls(clock, [{}] * 5, cycle_us=100_000)
    now = [k * 100_000 / 1e6 for k in range(5)]
    assert [r["elapsed"] for r in rows] == [0.0] + [now[k] - now[k - 1] for k in range(1, 5)]


# docs/scl.md rules: [S7-CLOCK]
def test_the_clock_parameters_exist_only_where_the_block_reads_the_clock(clock, functions):
    from fmpy import read_model_description

    names = lambda fmu: {v.name: v for v in read_model_description(str(fmu)).modelVariables}  # noqa: E731
    ours = names(clock)
    assert ours["startDateAndTime"].causality == "parameter"
    assert ours["startDateAndTime"].start == "1704067200"
    assert ours["localTimeOffset"].type == "Real"  # a TIME, in s
    assert "startDateAndTime" not in names(functions)


def test_statics_are_read_only_local_variables(calls_fmu):
    """docs/scl.md §4: every static, and every member of every instance, is an FMI local
    variable: get gives its value after the call, set is refused with a message naming it."""
    from tests.harness import status_of
    from tests.scl.driver import Instance, unpacked

    directory, md = unpacked(calls_fmu)
    variables = {v.name: v for v in md.modelVariables}
    local = {n for n, v in variables.items() if v.causality == "local"}
    assert {"statDiff", "m.count", "m.calls", "m.edge.Q", "m2.start"} <= local
    assert all(variables[n].start is None and variables[n].initial == "calculated" for n in local)
    names = ["statDiff", "m.calls", "m.edge.Q", "m2.start"]
    rows = calls(
        calls_fmu,
        [{"a": 3, "b": 5, "start": True, "speedIn": 10}, {"a": 200, "b": 1}],
        outputs=names,
    )
    assert rows == [
        {"statDiff": 3 - 5 + 2, "m.calls": 1, "m.edge.Q": True, "m2.start": False},
        {"statDiff": 199, "m.calls": 2, "m.edge.Q": False, "m2.start": True},
    ]

    s = Instance(calls_fmu, {}, {})
    vr = variables["statDiff"].valueReference
    assert status_of(s.fmu.setInteger, [vr], [5]) != 0
    assert any("statDiff is a local variable" in m for m in s.log), s.log
    s.free()


def test_locals_in_fmi3_and_model_exchange(tmp_path):
    """The FMI 3.0 description with locals is valid (FMPy's schema check), and a local reads
    the same in co-simulation and Model Exchange."""
    from fmpy.validation import validate_fmu

    from lgf_fmus import scl
    from tests.scl.driver import run_me

    (tmp_path / "calls.scl").write_text(CALLS + MOTOR, encoding="utf-8")
    # with a win64 DLL where mingw-w64 is installed: the C of FCs, FBs and UDTs compiles
    # without a warning there too
    fmu = scl.compile(
        [tmp_path / "calls.scl"], block="Calls", fmi=3, output=tmp_path / "C3.fmu", werror=True
    )
    assert validate_fmu(str(fmu)) == []
    names = ["statDiff", "m.calls", "m.edge.Q"]
    per_call = [{"a": 3, "b": 5, "start": True, "speedIn": 10}, {"a": 200, "b": 1}]
    want = [
        {"statDiff": 0, "m.calls": 1, "m.edge.Q": True},
        {"statDiff": 199, "m.calls": 2, "m.edge.Q": False},
    ]
    assert calls(fmu, per_call, outputs=names) == want
    assert run_me(fmu, CYCLE_US, {}, per_call, names=names) == want


# Where the two slices meet (docs/scl.md §3.7, §3.8): FCs in indices and with elements as
# arguments and outputs, a UDT temporary of an FC, a used FB with ARRAY, UDT and 64-bit statics
MEET = """
TYPE "Pair"
   STRUCT
      x : Int;
      y : Int := 7;
   END_STRUCT;
END_TYPE
FUNCTION "Bump" : Int
   VAR_INPUT
      x : Int;
   END_VAR
   VAR_OUTPUT
      next : Int;
   END_VAR
BEGIN
    #next := #x + 1;
    #Bump := #x;
END_FUNCTION
FUNCTION "Add" : Int
   VAR_INPUT
      a : Int;
      b : Int;
   END_VAR
   VAR_OUTPUT
      diff : Int;
   END_VAR
   VAR_TEMP
      t : "Pair";
   END_VAR
BEGIN
    #t.x := #a;
    #t.y := #b;
    #diff := #t.x - #t.y;
    #Add := #t.x + #t.y;
END_FUNCTION
FUNCTION_BLOCK "Acc"
   VAR_INPUT
      add : Int;
   END_VAR
   VAR_OUTPUT
      total : Int;
   END_VAR
   VAR
      hist : Array[0..1] of Int;
      last : "Pair";
      big : LInt;
   END_VAR
BEGIN
    #hist[1] := #hist[0];
    #hist[0] := #add;
    #last.x := #add;
    #big := #big + 1;
    #total := #total + #add;
END_FUNCTION_BLOCK
FUNCTION_BLOCK "Meet"
   VAR_INPUT
      v : Int;
      p : "Pair";
      i : Int;
   END_VAR
   VAR_OUTPUT
      arr : Array[1..3] of Int;
      readBack : Int;
      acc3 : Array[1..3] of Int;
      sum : Int;
      diffs : Array[1..2] of Int;
      total : Int;
   END_VAR
   VAR
      k : Int := 1;
      j : Int := 1;
      m : Int := 1;
      n : Int;
      acc : "Acc";
      grid : Array[1..2] of "Pair";
      huge : LInt;
   END_VAR
BEGIN
    #arr["Bump"(x := #k, next => #k)] := #v;          // Bump runs once: k counts by 1
    #readBack := #arr["Bump"(x := #j, next => #j)];
    #acc3["Bump"(x := #m, next => #m)] += 10;         // once for the read and the write
    #arr[#i + 10] := "Bump"(x := #n, next => #n);     // outside: not written, Bump still runs
    #sum := "Add"(a := #p.x, b := #p.y, diff => #diffs[#i]);
    #acc(add := #p.x, total => #total);
    #grid[#i].x := #v;
    #huge := #huge + 1;
END_FUNCTION_BLOCK
"""


# docs/scl.md rules: [S7-FC-DATA]
def test_fcs_and_instances_with_arrays_and_structs_by_hand(tmp_path):
    """An FC in an index runs once per access (docs/scl.md §3.8), with an FC's output it
    counts k, j, m, n by 1 per call; an FC takes members and gives an output to an element
    (dropped at an index outside, §3.7); a used FB's ARRAY and UDT statics are FMI locals
    element by element (a[1].b names, the UDT's default), its 64-bit static and the FB's are
    none (§4)."""
    from tests.scl.driver import unpacked

    fmu = compile_text(tmp_path, MEET, "Meet")
    _, md = unpacked(fmu)
    local = {v.name for v in md.modelVariables if v.causality == "local"}
    leaves = {"acc.hist[0]", "acc.hist[1]", "acc.last.x", "acc.last.y", "grid[1].x", "grid[2].y"}
    assert leaves <= local
    assert not {"huge", "acc.big"} & local
    names = ["arr[1]", "arr[2]", "arr[3]", "readBack", "acc3[1]", "acc3[2]", "acc3[3]"]
    names += ["k", "j", "m", "n", "sum", "diffs[1]", "diffs[2]", "total"]
    names += ["acc.hist[0]", "acc.hist[1]", "acc.last.x", "acc.last.y"]
    names += ["grid[1].x", "grid[1].y", "grid[2].x"]
    per_call = [
        {"v": 5, "p.x": 4, "p.y": 1, "i": 1},
        {"v": 6, "p.x": 10, "p.y": 20, "i": 2},
        {"v": 7, "i": 3},
        {"v": 8, "i": 1},
    ]
    rows = calls(fmu, per_call, outputs=names)
    want = [
        # call 1: arr[1] := 5, readBack arr[1], acc3[1] += 10; 4 + 1 and 4 - 1 into diffs[1]
        [5, 0, 0, 5, 10, 0, 0, 2, 2, 2, 1, 5, 3, 0, 4, 4, 0, 4, 7, 5, 7, 0],
        # call 2: the second elements; 10 + 20, 10 - 20 into diffs[2]
        [5, 6, 0, 6, 10, 10, 0, 3, 3, 3, 2, 30, 3, -10, 14, 10, 4, 10, 7, 5, 7, 6],
        # call 3: i = 3 lies outside diffs and grid: the output and the write are dropped
        [5, 6, 7, 7, 10, 10, 10, 4, 4, 4, 3, 30, 3, -10, 24, 10, 10, 10, 7, 5, 7, 6],
        # call 4: k, j, m = 4 lie outside arr and acc3: nothing written, readBack 0, the
        # indices still counted once
        [5, 6, 7, 0, 10, 10, 10, 5, 5, 5, 4, 30, -10, -10, 34, 10, 10, 10, 7, 8, 7, 6],
    ]
    assert [[row[name] for name in names] for row in rows] == want
