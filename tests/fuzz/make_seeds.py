#!/usr/bin/env python3
"""Writes the hand-made seed inputs of tests/fuzz/corpus/<block>/ in the input format of
fuzz_fmu.c (see the comment at its top and the op_* functions), for the FMU's FMI 2.0 build
and, with bit 6 of the second byte (fuzz_main.c), its FMI 3.0 build (the seeds named fmi3_*),
and the inputs of bugs found in the FMU and fixed since, in tests/fuzz/regressions/<block>/
(REGRESSIONS below; the other regressions are committed files, not written here). Both are
committed; run this again after changing the format or adding a block:
python3 tests/fuzz/make_seeds.py (the files of the blocks already there come out unchanged)."""

import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))

# Operation numbers: the enum in fuzz_fmu.c.
(
    SETUP,
    ENTER,
    EXIT,
    SET_REAL,
    SET_INTEGER,
    SET_BOOLEAN,
    GET,
    DO_STEP,
    SIMPLE_STEP,
    GET_STATE,
    SET_STATE,
    FREE_STATE,
    SERIALIZE,
    DESERIALIZE_MUTATED,
    DESERIALIZE_RAW,
    ROUND_TRIP,
    TERMINATE,
    RESET,
    DEBUG_LOGGING,
    MISC,
    NULL_COMPONENT,
    FAIL_ALLOCATION,
    FORGE,
    ME_ENTER_EVENT,
    ME_NEW_DISCRETE_STATES,
    ME_ENTER_CONTINUOUS,
    ME_COMPLETED_INTEGRATOR_STEP,
    ME_SET_TIME,
    ME_NO_STATES,
    ME_EVENT,
    ME_ROUND_TRIP,
    ME_NULL_COMPONENT,
) = range(32)

MODEL_EXCHANGE = 0x80  # bit 7 of byte 1: instantiate for Model Exchange
FMI3 = 0x40  # bit 6 of byte 1: the FMU's FMI 3.0 build (fuzz_main.c)

# FMI 3.0: the kinds of OP_GET and of the sets inside op_me_event (kind in fuzz_fmu.c), and the
# byte after OP_SET_REAL (0 Float64, 1 Float32) and OP_SET_INTEGER (SET_INTEGER_BYTE of the kind)
F64, F32, I16, U16, U32, BOOL3, I32, I8, U8 = range(9)
SET_INTEGER_BYTE = {I16: 0, U16: 1, U32: 2, I32: 3, I8: 4, U8: 5}
TIME_VR = 1000000  # the independent variable of FMI 3.0

PAYLOAD_CALLS = 24  # offset of the call counter in the serialized payload (fmu_image)


def real(x):
    return bytes([0x80]) + struct.pack("<d", x)


def integer(x):
    return bytes([0x80]) + struct.pack("<i", x)


def vr(x):
    return bytes([0xE0]) + struct.pack("<I", x)


def set_real(*pairs):
    return bytes([SET_REAL, len(pairs)]) + b"".join(vr(v) + real(x) for v, x in pairs)


def set_integer(*pairs):
    return bytes([SET_INTEGER, len(pairs)]) + b"".join(vr(v) + integer(x) for v, x in pairs)


def set_boolean(*pairs):
    return bytes([SET_BOOLEAN, len(pairs)]) + b"".join(vr(v) + bytes([0, int(x)]) for v, x in pairs)


# FMI 3.0's sets: the type byte after the op
def set_float64(*pairs):
    return bytes([SET_REAL, 0, len(pairs)]) + b"".join(vr(v) + real(x) for v, x in pairs)


def set_float32(*pairs):
    return bytes([SET_REAL, 1, len(pairs)]) + b"".join(vr(v) + real(x) for v, x in pairs)


def set_int16(*pairs):
    return bytes([SET_INTEGER, 0, len(pairs)]) + b"".join(vr(v) + integer(x) for v, x in pairs)


def set_uint32(*pairs):
    return bytes([SET_INTEGER, 2, len(pairs)]) + b"".join(vr(v) + integer(x) for v, x in pairs)


def steps(count, cycles=1):
    return bytes([SIMPLE_STEP, cycles - 1]) * count


def start(cycle=0.1, start_time=0.0, *inputs, interface=0, stop_time=None):
    """Instantiate, setupExperiment, initialization with cycleTime and inputs, exit. With
    interface | FMI3: OP_SETUP keeps the times for fmi3EnterInitializationMode (OP_ENTER)."""
    flags = 2 if stop_time is not None else 0
    cycle_time = set_float64((0, cycle)) if interface & FMI3 else set_real((0, cycle))
    return (
        bytes([0, 1 | interface, SETUP, flags])
        + real(0.0)
        + real(start_time)
        + real(stop_time or 0.0)
        + bytes([ENTER])
        + cycle_time
        + b"".join(inputs)
        + bytes([EXIT])
    )


def me_start(cycle=0.1, start_time=0.0, *inputs, stop_time=None, interface=0):
    """The same for Model Exchange, then the event iteration at t0 and continuous-time mode."""
    return start(
        cycle, start_time, *inputs, interface=MODEL_EXCHANGE | interface, stop_time=stop_time
    ) + bytes([ME_NEW_DISCRETE_STATES, 0, ME_ENTER_CONTINUOUS])


def me_events(count, how=0):
    """Time events at the next calls (op_me_event): `how` 0 the call time, back to
    continuous-time mode; 0x02 first a time between calls and fmi2CompletedIntegratorStep
    (its byte: 0x80 = half way); 0x08 a second event iteration; 0x10 staying in event mode."""
    extra = bytes([0x80, 0]) if how & 3 == 2 else bytes([0]) if how & 3 else b""
    return (bytes([ME_EVENT, how]) + extra) * count


def me_event_with_input(set_op):
    """A time event whose inputs are set in event mode (set_op: a set_real/integer/boolean
    without its leading op byte, i.e. the kind byte then the pairs)."""
    return bytes([ME_EVENT, 0x04]) + set_op


def me_run(*inputs):
    """A normal Model Exchange run: the calls at their time events, varied the way importers
    do, with inputs changed in event mode, then terminate from continuous-time mode."""
    body = me_events(5) + me_events(3, 0x02) + me_events(2, 0x08) + me_events(2, 0x10)
    body += me_events(1) + b"".join(me_event_with_input(i) for i in inputs) + me_events(10)
    return body + bytes([ME_COMPLETED_INTEGRATOR_STEP, 0, TERMINATE])


def me_states():
    """Model Exchange states: get in continuous-time mode, events, set back, serialize,
    deserialize, round trips of an event iteration, free."""
    return (
        bytes([GET_STATE, 0])
        + me_events(4)
        + bytes([SET_STATE, 0, SERIALIZE, 0, 0])
        + bytes([DESERIALIZE_MUTATED, 0, 0, 0, 1])
        + bytes([SET_STATE, 1])
        + bytes([ME_ROUND_TRIP, 2, 0, 0])
        + me_events(3)
        + bytes([ME_ENTER_EVENT, ME_ROUND_TRIP, 0, 0, 3])
        + bytes([FREE_STATE, 0, FREE_STATE, 1])
    )


def me_misuse():
    """Model Exchange calls in the wrong mode and with wrong arguments, co-simulation calls on
    a Model Exchange instance."""
    return (
        bytes([0, MODEL_EXCHANGE, ME_ENTER_EVENT, ME_SET_TIME, 0, ME_NEW_DISCRETE_STATES, 0])
        + bytes([ME_NO_STATES, 4, ME_NO_STATES, 0x08 | 1])
        + me_start()[2:]
        + bytes([ME_NEW_DISCRETE_STATES, 1])  # eventInfo NULL (in continuous-time mode)
        + bytes([ME_ENTER_EVENT, ME_NEW_DISCRETE_STATES, 1, ME_ENTER_CONTINUOUS])
        + bytes([ME_COMPLETED_INTEGRATOR_STEP, 3])  # both out-pointers NULL
        + bytes([ME_SET_TIME, 4, 0x7F])  # back by twice the tolerance
        + bytes([ME_SET_TIME, 7])
        + real(float("nan"))
        + bytes([ME_SET_TIME, 8, 0xFE])  # two cycles back
        + bytes([ME_NO_STATES, 0x08 | 0, ME_NO_STATES, 0x20 | 2, ME_NO_STATES, 0x80 | 0x08 | 3])
        + set_integer((99999, 1))
        + bytes([SIMPLE_STEP, 0, DO_STEP, 0, 0, 0])
        + bytes([MISC, 0, 0, 0, 3, MISC, 0, 1, 0, 5, ME_NULL_COMPONENT, 1, ME_NULL_COMPONENT, 4])
        + me_events(2)
        + bytes([TERMINATE, ME_ENTER_EVENT, ME_SET_TIME, 0, RESET])
    )


def me_on_co_simulation():
    """The Model Exchange functions on a co-simulation instance: all refused."""
    return (
        start()
        + bytes([SIMPLE_STEP, 0, ME_ENTER_EVENT, ME_NEW_DISCRETE_STATES, 0])
        + bytes([ME_ENTER_CONTINUOUS, ME_COMPLETED_INTEGRATOR_STEP, 0, ME_SET_TIME, 0])
        + bytes([ME_NO_STATES, 0, ME_NO_STATES, 1, ME_EVENT, 0, ME_ROUND_TRIP, 0, 0, 0])
        + bytes([SIMPLE_STEP, 1, TERMINATE])
    )


def get(kind, *vrs):
    return bytes([GET, kind, len(vrs)]) + b"".join(vr(v) for v in vrs)


def misuse3(token_byte=3):
    """FMI 3.0: a wrong token (refused, then the correct instantiation), calls in the wrong
    mode, the experiment's times refused, nValues against nvr, the types without variables,
    the time, the functions the FMU refuses, NULL out-pointers and instances."""
    return (
        bytes([10, FMI3, token_byte])
        + bytes([DO_STEP, 0, 0, 0, EXIT, TERMINATE])
        + set_float64((0, float("nan")))
        + bytes([SETUP, 4])
        + real(0.0)
        + real(float("nan"))
        + real(0.0)  # startTime NaN, at once
        + bytes([SETUP, 0])
        + real(0.0)
        + real(0.0)
        + real(0.0)
        + bytes([ENTER])
        + set_float64((0, 0.2))
        + bytes([EXIT])
        + bytes([GET, F64, 0x38])
        + vr(0)  # nValues 2 for nvr 1
        + bytes([MISC])
        + vr(0)
        + vr(1)
        + bytes([0, 1, 2, 0x00])  # Int8 get, nvr 1
        + bytes([MISC])
        + vr(0)
        + vr(1)
        + bytes([0, 1, 2, 0x86])  # Binary set, nvr 1
        + bytes([MISC])
        + vr(0)
        + vr(1)
        + bytes([0, 1, 1, 3])  # fmi3GetDirectionalDerivative
        + bytes([MISC])
        + vr(0)
        + vr(1)
        + bytes([0, 1, 1, 0])  # fmi3EnterStepMode
        + bytes([MISC])
        + vr(0)
        + vr(1)
        + bytes([0, 1, 3, 5])  # fmi3DoStep, NULL pointers
        + bytes([MISC])
        + vr(0)
        + vr(1)
        + bytes([0, 1, 8])  # time and cycleTime
        + bytes([MISC])
        + vr(0)
        + vr(1)
        + bytes([0, 1, 9])
        + real(1.0)  # set the time
        + bytes([MISC])
        + vr(0)
        + vr(1)
        + bytes([0, 1, 12, 0, 0])  # nValues, a get
        + bytes([MISC])
        + vr(0)
        + vr(1)
        + bytes([0, 0, 11])  # Scheduled Execution
        + bytes([MISC])
        + vr(0)
        + vr(1)
        + bytes([1, 0, 5])  # a count, NULL
        + get(F64, TIME_VR, 0)
        + steps(2)
        + bytes([NULL_COMPONENT, 5, NULL_COMPONENT, 19, ME_NULL_COMPONENT, 1])
        + bytes([ME_ENTER_EVENT, ME_SET_TIME, 0, ME_NEW_DISCRETE_STATES, 1 | (2 << 2)])
        + bytes([GET_STATE, 0, RESET, TERMINATE])
    )


def me_run3(*inputs):
    """me_run for FMI 3.0 (the same bytes: the event's set carries its kind)."""
    return me_run(*inputs)


def generator_seeds(fmi3):
    """The signal generators (LGF_SawToothCI, LGF_TriangleCI, LGF_RectangleCI, LGF_SinusCI,
    LGF_CosinusCI share an interface): vr 1 amplitude, 2 offset, 4 phaseShift (REAL), 3
    periode (UDINT, ms), 5 reset; outputs 6 value, 7 error, 8 status."""
    v = FMI3 if fmi3 else 0
    real_ = set_float32 if fmi3 else set_real
    udint = set_uint32 if fmi3 else set_integer
    inputs = (real_((1, 2.5), (2, -1.0), (4, 25.0)), udint((3, 400)))
    run = (
        start(0.01, 0.0, *inputs, interface=v)
        + steps(60)
        + real_((1, 4.0))
        + steps(20, 2)
        + set_boolean((5, 1))
        + steps(2)
        + set_boolean((5, 0))
        + steps(30)
        + get(F32 if fmi3 else 0, 6)
        + get(U16 if fmi3 else 1, 8)
        + bytes([TERMINATE])
    )
    me_event_input = (
        bytes([F32 if fmi3 else 0, 1]) + vr(1) + real(-3.0),
        bytes([BOOL3 if fmi3 else 2, 1]) + vr(5) + bytes([0, 1]),
        bytes([BOOL3 if fmi3 else 2, 1]) + vr(5) + bytes([0, 0]),
    )
    me = me_start(0.01, 0.0, *inputs, interface=v) + me_run(*me_event_input)
    states = start(0.01, 0.5, *inputs, interface=v) + steps(9) + state_ops() + forged_calls(20)
    prefix = "fmi3_" if fmi3 else ""
    return {prefix + "run": run, prefix + "me_run": me, prefix + "states": states}


def state_ops():
    """FMU states: get, step, set back, serialize, deserialize, round trip, free."""
    return (
        bytes([GET_STATE, 0])
        + steps(5)
        + bytes([SET_STATE, 0, SERIALIZE, 0, 0])
        # deserialize the serialized bytes unchanged into slot 1 and set it
        + bytes([DESERIALIZE_MUTATED, 0, 0, 0, 1])
        + bytes([SET_STATE, 1])
        # round trip with one Boolean set, then doStep(now, 3 cycles)
        + bytes([ROUND_TRIP, 2, 0, 0, 2])
        + steps(3)
        + bytes([FREE_STATE, 0, FREE_STATE, 1])
    )


def forged_calls(value):
    """Deserialize the current state with its call counter replaced, checksum fixed, and set
    it into slot 2; then step."""
    return (
        bytes([DESERIALIZE_MUTATED, 1, 1, 0x82])
        + struct.pack("<H", PAYLOAD_CALLS)
        + integer(value)
        + bytes([2, 2, SET_STATE, 2])
        + steps(2)
    )


def misuse():
    """Calls in the wrong state and bad values."""
    return (
        bytes([0x0A, 0, 0])  # wrong GUID, then the correct instantiation
        + bytes([DO_STEP, 0, 0, 0, EXIT, TERMINATE])
        + set_real((0, float("nan")))
        + set_real((0, 0.0))
        + set_real((99999, 1.0))
        + bytes([ENTER])
        + set_real((1, float("inf")))
        + bytes([EXIT])
        + set_real((0, 0.2))
        + bytes([DO_STEP, 7])
        + real(-5.0)
        + bytes([0, 0])  # wrong t
        + bytes([DO_STEP, 0, 11])
        + real(-1.0)
        + bytes([0])  # h < 0
        + bytes([DO_STEP, 0, 11])
        + real(1e300)
        + bytes([0])  # h huge
        + bytes([DESERIALIZE_RAW, 0, 8, 0])
        + b"LGF-FMU\0"
        + bytes([4])
        + bytes(
            [
                MISC,
                0,
                0,
                0,
                1,
                0,
                2,
                0,
                13,
                0,
                NULL_COMPONENT,
                5,
                FAIL_ALLOCATION,
                0,
                GET_STATE,
                0,
                RESET,
                TERMINATE,
            ]
        )
    )


SEEDS = {
    "LGF_SawTooth": {
        "documented": start(0.1, 0.0, set_integer((2, 5), (4, 3), (5, 4)), set_real((3, 0.3)))
        + steps(30)
        + get(1, 8)
        + set_boolean((7, 1))
        + steps(2)
        + set_boolean((7, 0))
        + steps(10, 3)
        + bytes([TERMINATE]),
        "plc_timing_endless": bytes([0, 0, ENTER])
        + set_boolean((1, 1), (6, 1))
        + set_integer((4, 30000))
        + set_real((0, 0.001), (3, 0.0))
        + bytes([EXIT])
        + steps(40),
        "states": start(0.1, 1.5) + steps(7) + state_ops() + forged_calls(3),
        "misuse": misuse(),
        "me_documented": me_start(0.1, 0.0, set_integer((2, 5), (4, 3), (5, 4)), set_real((3, 0.3)))
        + me_run(bytes([1, 1]) + vr(7) + bytes([0, 1]), bytes([1, 1]) + vr(7) + bytes([0, 0])),
        "me_states": me_start(0.1, 1.5, stop_time=100.0) + me_events(7) + me_states(),
        "me_misuse": me_misuse(),
        "me_on_co_simulation": me_on_co_simulation(),
        "fmi3_documented": start(
            0.1, 0.0, set_int16((2, 5), (4, 3), (5, 4)), set_float64((3, 0.3)), interface=FMI3
        )
        + steps(30)
        + get(I16, 8)
        + get(F64, TIME_VR)
        + set_boolean((7, 1))
        + steps(2)
        + set_boolean((7, 0))
        + steps(10, 3)
        + bytes([TERMINATE]),
        "fmi3_me_documented": me_start(
            0.1, 0.0, set_int16((2, 5), (4, 3), (5, 4)), set_float64((3, 0.3)), interface=FMI3
        )
        + me_run3(
            bytes([BOOL3, 1]) + vr(7) + bytes([0, 1]), bytes([BOOL3, 1]) + vr(7) + bytes([0, 0])
        ),
        "fmi3_states": start(0.1, 1.5, interface=FMI3) + steps(7) + state_ops() + forged_calls(3),
        "fmi3_me_states": me_start(0.1, 1.5, stop_time=100.0, interface=FMI3)
        + me_events(7)
        + me_states(),
        "fmi3_misuse": misuse3(),
    },
    "LGF_LimRateOfChangeCI": {
        "ramp": start(0.1, 0.0, set_real((1, 10.0), (2, 5.0)))
        + steps(30)
        + get(0, 5)
        + set_real((2, -1.0))
        + steps(2)
        + set_boolean((4, 1))
        + set_real((3, 3.0))
        + steps(2)
        + set_boolean((4, 0))
        + steps(5, 2)
        + bytes([TERMINATE]),
        "infinities": start(1e-6, 0.0, set_real((1, float("inf")), (2, float("inf"))))
        + steps(3)
        + set_real((1, -float("inf")))
        + steps(3),
        "states": start(0.01, -3.0, set_real((1, 1.0), (2, 2.0)))
        + steps(7)
        + state_ops()
        + forged_calls(1000),
        "misuse": misuse(),
        "me_ramp": me_start(0.1, 0.0, set_real((1, 10.0), (2, 5.0)))
        + me_run(
            bytes([1, 1]) + vr(2) + real(-1.0),
            bytes([1, 1]) + vr(4) + bytes([0, 1]),
            bytes([1, 1]) + vr(4) + bytes([0, 0]),
        ),
        "me_states": me_start(0.01, -3.0, set_real((1, 1.0), (2, 2.0)))
        + me_events(7)
        + me_states(),
        "me_misuse": me_misuse(),
        "me_on_co_simulation": me_on_co_simulation(),
        "fmi3_ramp": start(0.1, 0.0, set_float64((1, 10.0), (2, 5.0)), interface=FMI3)
        + steps(30)
        + get(F64, 5, TIME_VR)
        + set_float64((2, -1.0))
        + steps(2)
        + get(U16, 7)
        + set_boolean((4, 1))
        + set_float64((3, 3.0))
        + steps(2)
        + set_boolean((4, 0))
        + steps(5, 2)
        + bytes([TERMINATE]),
        "fmi3_me_ramp": me_start(0.1, 0.0, set_float64((1, 10.0), (2, 5.0)), interface=FMI3)
        + me_run3(
            bytes([F64, 1]) + vr(2) + real(-1.0),
            bytes([BOOL3, 1]) + vr(4) + bytes([0, 1]),
            bytes([BOOL3, 1]) + vr(4) + bytes([0, 0]),
        ),
        "fmi3_states": start(0.01, -3.0, set_float64((1, 1.0), (2, 2.0)), interface=FMI3)
        + steps(7)
        + state_ops()
        + forged_calls(1000),
        "fmi3_misuse": misuse3(),
    },
    "LGF_RampCI": {
        "worked_example": start(
            0.1,
            0.0,
            set_integer((1, 4)),
            set_real((100, 0.0), (200, 0.3), (101, 30.0), (201, 0.2)),
            set_real((102, 30.0), (202, 0.25), (103, 0.0), (203, 0.0)),
        )
        + steps(1)
        + set_boolean((14, 1))
        + steps(12)
        + get(0, 20, 23, 24, 25)
        + bytes([TERMINATE]),
        "hold_continue_cyclic": start(0.1, 0.0)
        + set_boolean((14, 1), (17, 1))
        + steps(20)
        + set_boolean((15, 1), (16, 1))
        + set_integer((11, 2))
        + set_real((12, 1.0))
        + steps(3)
        + set_boolean((15, 0), (18, 1), (19, 1))
        + steps(3)
        + set_boolean((13, 1))
        + set_real((10, 7.0))
        + steps(5, 4),
        "states": start(0.001, 0.0)
        + set_boolean((14, 1))
        + steps(9)
        + state_ops()
        + forged_calls(50),
        "misuse": misuse() + set_integer((1, 65)) + set_integer((11, 70)) + set_real((200, -1.0)),
        "me_worked_example": me_start(
            0.1,
            0.0,
            set_integer((1, 4)),
            set_real((100, 0.0), (200, 0.3), (101, 30.0), (201, 0.2)),
            set_real((102, 30.0), (202, 0.25), (103, 0.0), (203, 0.0)),
        )
        + me_run(bytes([2, 1]) + vr(14) + bytes([0, 1])),
        "me_states": me_start(0.001, 0.0, set_boolean((14, 1))) + me_events(9) + me_states(),
        "me_misuse": me_misuse(),
        "me_on_co_simulation": me_on_co_simulation(),
        "fmi3_worked_example": start(
            0.1,
            0.0,
            set_int16((1, 4)),
            set_float64((100, 0.0), (200, 0.3), (101, 30.0), (201, 0.2)),
            set_float64((102, 30.0), (202, 0.25), (103, 0.0), (203, 0.0)),
            interface=FMI3,
        )
        + steps(1)
        + set_boolean((14, 1))
        + steps(12)
        + get(F64, 20, 23, 24, 25)
        + get(I16, 22)
        + bytes([TERMINATE]),
        "fmi3_me_worked_example": me_start(
            0.1,
            0.0,
            set_int16((1, 4)),
            set_float64((100, 0.0), (200, 0.3), (101, 30.0), (201, 0.2)),
            set_float64((102, 30.0), (202, 0.25), (103, 0.0), (203, 0.0)),
            interface=FMI3,
        )
        + me_run3(bytes([BOOL3, 1]) + vr(14) + bytes([0, 1])),
        "fmi3_states": start(0.001, 0.0, interface=FMI3)
        + set_boolean((14, 1))
        + steps(9)
        + state_ops()
        + forged_calls(50),
        "fmi3_misuse": misuse3()
        + set_int16((1, 65))
        + set_int16((11, 70))
        + set_float64((200, -1.0)),
    },
}

for generator in (
    "LGF_SawToothCI",
    "LGF_TriangleCI",
    "LGF_RectangleCI",
    "LGF_SinusCI",
    "LGF_CosinusCI",
):
    SEEDS[generator] = {**generator_seeds(False), **generator_seeds(True)}

# Inputs of bugs found in the FMU, written here while they were open (in tests/fuzz/known/,
# tests/fuzz/README.md, "Open findings") and fixed since (README, "Findings").
NVALUES_NO_VARIABLES = (
    bytes([0, FMI3]) + bytes([MISC]) + vr(0) + vr(1) + bytes([0, 0, 2, 0x40])
)  # fmi3GetInt8(inst, vr, 0, values, 1)
TIME_NULL_VALUES = (
    bytes([0, FMI3])
    + bytes([SETUP, 0])
    + real(0.0)
    + real(0.0)
    + real(0.0)
    + bytes([ENTER, GET, F64, 0x80 | 1, 0xC0])
)  # fmi3GetFloat64({time}, NULL)
# FMI 2.0, the signal generators: a forged state whose UDINT periode (payload bytes 52..55) is
# 2^31 (op_forge: one field of the block's data, 4 bytes, INT32_MIN's low word), set, then
# fmi2GetInteger(periode)
UDINT_BEYOND_INTEGER = (
    start(0.01, 0.0) + bytes([FORGE, 0, 5, 0x83, 3, 1, 0]) + bytes([GET, 1, 1]) + vr(3)
)
# Fixed since: these inputs are regressions now (write("regressions", ...)).
REGRESSIONS = {
    block: {
        "fmi3-nvalues-no-variables": NVALUES_NO_VARIABLES,
        "fmi3-get-time-null-values": TIME_NULL_VALUES,
    }
    for block in SEEDS
}
for generator in (
    "LGF_SawToothCI",
    "LGF_TriangleCI",
    "LGF_RectangleCI",
    "LGF_SinusCI",
    "LGF_CosinusCI",
):
    REGRESSIONS[generator]["fmi2-udint-beyond-integer"] = UDINT_BEYOND_INTEGER


def write(kind, inputs):
    for block, seeds in inputs.items():
        folder = os.path.join(HERE, kind, block)
        os.makedirs(folder, exist_ok=True)
        for name, data in seeds.items():
            with open(os.path.join(folder, name), "wb") as f:
                f.write(data)


def main():
    write("corpus", SEEDS)
    write("regressions", REGRESSIONS)


if __name__ == "__main__":
    main()
