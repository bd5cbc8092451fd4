"""TADDR_Param, S7's system data type of a UDP partner's address (docs/scl.md §3.8 [S7-TADDR],
issue 30: LGF_TaddrToString, LGF_StringToTaddr), known without a TYPE in the sources: a STRUCT
as an input, an output, an FC's parameter, assigned whole. The SCL is written here; the values
are computed by hand in the comments."""

from __future__ import annotations

import pytest

from tests.scl.driver import compile_text, run_cs

TADDR = """
FUNCTION "Port" : UInt
   VAR_INPUT
      addr : TADDR_Param;
   END_VAR
BEGIN
   #Port := #addr.REM_PORT_NR + USINT_TO_UINT(#addr.REM_IP_ADDR[4]);
END_FUNCTION

FUNCTION_BLOCK "Taddr"
   VAR_INPUT
      partner : TADDR_Param;
   END_VAR
   VAR_OUTPUT
      port : UInt;
      copy : TADDR_Param;
   END_VAR
BEGIN
   #port := "Port"(addr := #partner);
   #copy := #partner;
   #copy.REM_IP_ADDR[1] := 192;
END_FUNCTION_BLOCK
"""


# docs/scl.md rules: [S7-TADDR]
@pytest.mark.parametrize("fmi", [2, 3])
def test_taddr_param_is_a_struct_of_siemens_layout(tmp_path, fmi):
    fmu = compile_text(tmp_path, TADDR, "Taddr", fmi=fmi)
    partner = {f"partner.REM_IP_ADDR[{i}]": octet for i, octet in enumerate([10, 0, 0, 7], 1)}
    rows = run_cs(fmu, 100_000, {}, {**partner, "partner.REM_PORT_NR": 502}, [])
    # port: 502 + the fourth octet 7; the copy takes every member, then its first octet 192
    assert rows == [
        {
            "port": 509,
            "copy.REM_IP_ADDR[1]": 192,
            "copy.REM_IP_ADDR[2]": 0,
            "copy.REM_IP_ADDR[3]": 0,
            "copy.REM_IP_ADDR[4]": 7,
            "copy.REM_PORT_NR": 502,
            "copy.RESERVED": 0,
        }
    ]


RETURNED = """
TYPE "Pair"
   STRUCT
      a : Int := 5;
      b : Real;
   END_STRUCT;
END_TYPE

FUNCTION "MakeAddr" : TADDR_Param
   VAR_INPUT
      last : USInt;
   END_VAR
BEGIN
   #MakeAddr.REM_IP_ADDR[1] := 10;
   #MakeAddr.REM_IP_ADDR[4] := #last;
   #MakeAddr.REM_PORT_NR := 502;
END_FUNCTION

FUNCTION "Swap" : "Pair"
   VAR_INPUT
      p : "Pair";
   END_VAR
BEGIN
   #Swap.a := REAL_TO_INT(#p.b);
   #Swap.b := INT_TO_REAL(#p.a);
END_FUNCTION

FUNCTION_BLOCK "Returned"
   VAR_INPUT
      last : USInt := 7;
   END_VAR
   VAR_OUTPUT
      addr : TADDR_Param;
      p : "Pair";
   END_VAR
BEGIN
   #addr := "MakeAddr"(last := #last);
   #p := "Swap"(p := #p);
END_FUNCTION_BLOCK
"""


# docs/scl.md rules: [S7-TADDR] [S7-FC-DATA]
def test_an_fc_returns_a_udt_whole(tmp_path):
    fmu = compile_text(tmp_path, RETURNED, "Returned", fmi=3)
    rows = run_cs(fmu, 100_000, {}, {}, [(100_000, {"last": 254})])
    # MakeAddr's value starts at 0 (docs/scl.md §3.7): 10.0.0.<last>, port 502; Swap of the
    # Pair's start (5, 0.0) is (0, 5.0), of that (5, 0.0)
    addr = {"addr.REM_IP_ADDR[1]": 10, "addr.REM_IP_ADDR[2]": 0, "addr.REM_IP_ADDR[3]": 0}
    addr.update({"addr.REM_PORT_NR": 502, "addr.RESERVED": 0})
    assert rows == [
        {**addr, "addr.REM_IP_ADDR[4]": 7, "p.a": 0, "p.b": 5.0},
        {**addr, "addr.REM_IP_ADDR[4]": 254, "p.a": 5, "p.b": 0.0},
    ]
