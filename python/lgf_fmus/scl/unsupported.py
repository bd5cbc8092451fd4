"""The constructs of S7 SCL outside the subset, by name (docs/scl.md §6): a source that uses one
is refused with an error that names it (E002), not with a bare syntax error or an "unknown
type". The parser looks a word up where a syntax error stands at it or after it, the checks
where a type or a function is not found. Adding a construct to the subset removes it here."""

from __future__ import annotations

_NOT_YET = "is not supported yet (docs/scl.md §6)"

# What only a CPU with its hardware, files, network and clock has: the FMU models the program,
# not the CPU's operating system, so these stay outside the subset for good (docs/scl.md §6).
_HARDWARE = "a hardware identifier of the CPU's configuration; an FMU has no hardware"
_SYSTEM = (
    "a system instruction of the CPU (its clock, files, data logs, network or I/O devices), "
    "which an FMU has no model of"
)
HARDWARE_TYPES = ("HW_ANY", "HW_IO", "HW_DEVICE", "HW_DPSLAVE", "HW_SUBMODULE", "HW_MODULE")
HARDWARE_TYPES += ("HW_INTERFACE", "HW_IEPORT", "HW_HSC", "HW_PWM", "HW_PTO", "CONN_ANY")
HARDWARE_TYPES += ("CONN_OUC", "CONN_PRG", "PORT", "EVENT_ANY", "EVENT_ATT", "OB_ANY")
SYSTEM_FBS = ("FileReadC", "FileWriteC", "SET_TIMEZONE", "TCON", "TDISCON", "TSEND", "TRCV")
SYSTEM_FBS += ("TSEND_C", "TRCV_C", "TUSEND", "TURCV", "TMAIL_C", "RDREC", "WRREC", "RALRM")
SYSTEM_FBS += ("GET_DIAG", "RCVPTP", "SEND_PTP", "RCV_PTP", "MB_CLIENT", "MB_SERVER")
SYSTEM_INSTRUCTIONS = ("D_ACT_DP", "DeviceStates", "ModuleStates", "GEO2LOG", "LOG2GEO")
SYSTEM_INSTRUCTIONS += ("WR_SYS_T", "WR_LOC_T", "RD_ADDR", "LED", "DataLogCreate")
SYSTEM_INSTRUCTIONS += ("DataLogOpen", "DataLogWrite", "DataLogClose", "DataLogDelete")
SYSTEM_INSTRUCTIONS += ("DataLogClear", "DataLogNewFile", "SET_CINT", "DIS_AIRT", "EN_AIRT")

# data types
TYPES = {
    **{
        t: f"{t} is not supported yet (docs/scl.md §3.1: of the date types, DTL, DATE and TOD are)"
        for t in ("DATE_AND_TIME", "DT", "LDT", "LTOD", "LTIME_OF_DAY")
    },
    **{
        t: f"{t} {_NOT_YET}: the subset has no pointers or references"
        for t in ("VARIANT", "ANY", "POINTER", "REF_TO", "DB_ANY")
    },
    **{
        t: f"{t} {_NOT_YET}: the generic counter types (write CTU_INT, ...)"
        for t in ("IEC_COUNTER", "IEC_UCOUNTER", "IEC_SCOUNTER", "IEC_USCOUNTER")
        + ("IEC_DCOUNTER", "IEC_UDCOUNTER", "IEC_LCOUNTER", "IEC_ULCOUNTER")
    },
    **{
        f"{kind}_{t}": f"{kind}_{t} {_NOT_YET}: the 64-bit counters"
        for kind in ("CTU", "CTD", "CTUD")
        for t in ("LINT", "ULINT")
    },
    **{
        t: f"{t} {_NOT_YET}: the LTIME timers and TONR"
        for t in ("IEC_LTIMER", "TON_LTIME", "TOF_LTIME", "TP_LTIME", "TONR", "TONR_TIME")
    },
    **{t: f"{t} is not supported (docs/scl.md §6): {_HARDWARE}" for t in HARDWARE_TYPES},
    **{t.upper(): f"{t} is not supported (docs/scl.md §6): {_SYSTEM}" for t in SYSTEM_FBS},
}

# functions (the instructions of TIA Portal's "Basic instructions")
FUNCTIONS = {
    **{
        f: f"{f} {_NOT_YET}: the conversions between character strings and numbers"
        for f in ("S_CONV", "CHARS_TO_STRG", "STRG_TO_CHARS")
    },
    **{f: f"{f} {_NOT_YET}" for f in ("S_MOVE", "ATH", "HTA", "JOIN", "SPLIT")},
    **{
        f: f"{f} {_NOT_YET}"
        for f in ("MOVE_BLK", "PRESET_TIMER", "UFILL_BLK")
        + ("FILL_BLK", "UMOVE_BLK", "SERIALIZE", "DESERIALIZE", "PEEK", "POKE", "T_COMBINE")
        + ("GET_ERROR", "GET_ERR_ID", "TYPEOF", "REF")
    },
    **{f.upper(): f"{f} is not supported (docs/scl.md §6): {_SYSTEM}" for f in SYSTEM_INSTRUCTIONS},
}

# words of statements and declarations
WORDS = {
    "AT": f"a declaration AT another (an overlay) {_NOT_YET}",
    "REF_TO": TYPES["REF_TO"],
    "VAR_STAT": f"VAR_STAT {_NOT_YET}",
    **TYPES,
}

# characters that start a construct outside the subset
CHARACTERS = {
    "^": "a dereference ^: pointers and references are not supported (docs/scl.md §6)",
    "?": f"?= (an assignment attempt) {_NOT_YET}",
}


def type_message(name: str) -> str | None:
    return TYPES.get(name.upper())


def function_message(name: str) -> str | None:
    return FUNCTIONS.get(name.upper())


def word_message(word: str) -> str | None:
    return WORDS.get(word.upper())
