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
    # vr 1 trigger, 2 set, 3 reset (inputs), 4 out (docs/behaviour.md §11)
    "LGF_PulseRelay": {
        "toggle_set_reset": start(0.1, 0.0, set_boolean((1, 1)))
        + (set_boolean((1, 0)) + steps(1) + set_boolean((1, 1)) + steps(1)) * 6
        + get(2, 4)
        + set_boolean((2, 1), (1, 0))
        + steps(2)
        + set_boolean((3, 1), (2, 0))
        + steps(2)
        + set_boolean((1, 1), (2, 1), (3, 0))
        + steps(1)
        + set_boolean((1, 0), (2, 0), (3, 1))
        + steps(3, 2)
        + bytes([TERMINATE]),
        "states": start(0.01, 2.5, set_boolean((1, 1)))
        + steps(3)
        + set_boolean((1, 0))
        + steps(2)
        + state_ops()
        + forged_calls(7),
        "misuse": misuse(),
        "me_toggle": me_start(0.1, 0.0)
        + me_run(
            bytes([2, 1]) + vr(1) + bytes([0, 1]),
            bytes([2, 1]) + vr(2) + bytes([0, 1]),
            bytes([2, 1]) + vr(3) + bytes([0, 1]),
        ),
        "me_states": me_start(0.01, 2.5, set_boolean((1, 1)), stop_time=100.0)
        + me_events(7)
        + me_states(),
        "me_misuse": me_misuse(),
        "me_on_co_simulation": me_on_co_simulation(),
        "fmi3_toggle_set_reset": start(0.1, 0.0, set_boolean((1, 1)), interface=FMI3)
        + (set_boolean((1, 0)) + steps(1) + set_boolean((1, 1)) + steps(1)) * 6
        + get(BOOL3, 4)
        + get(F64, TIME_VR)
        + set_boolean((2, 1), (1, 0))
        + steps(2)
        + set_boolean((1, 1), (2, 1), (3, 1))
        + steps(3, 2)
        + bytes([TERMINATE]),
        "fmi3_me_toggle": me_start(0.1, 0.0, interface=FMI3)
        + me_run3(
            bytes([BOOL3, 1]) + vr(1) + bytes([0, 1]), bytes([BOOL3, 1]) + vr(3) + bytes([0, 1])
        ),
        "fmi3_states": start(0.01, 2.5, set_boolean((1, 1)), interface=FMI3)
        + steps(5)
        + state_ops()
        + forged_calls(7),
        "fmi3_me_states": me_start(0.01, 2.5, stop_time=100.0, interface=FMI3)
        + me_events(7)
        + me_states(),
        "fmi3_misuse": misuse3(),
    },
    # vr 1 trigger, 2 monitorTime (TIME), 3 single, 4 double, 5 long, 6 severalEdges (BOOL),
    # 7 noOfEdges (USINT) (docs/behaviour.md §12)
    "LGF_CountBooleanEdges": {
        "single_double_long": start(0.1, 0.0, set_boolean((1, 1)), set_real((2, 0.5)))
        + set_boolean((1, 0))
        + steps(6)
        + get(1, 7)
        + (set_boolean((1, 1)) + steps(1) + set_boolean((1, 0)) + steps(1)) * 2
        + steps(4)
        + set_boolean((1, 1))
        + steps(8)
        + get(2, 3, 4, 5, 6)
        + set_real((2, 0.0))
        + set_boolean((1, 0))
        + steps(2, 3)
        + bytes([TERMINATE]),
        "many_edges": start(0.001, 0.0, set_real((2, 1.0)))
        + (set_boolean((1, 1)) + steps(1) + set_boolean((1, 0)) + steps(1)) * 300
        + steps(500, 4),
        "states": start(0.01, 2.5, set_boolean((1, 1)), set_real((2, 0.05)))
        + steps(2)
        + set_boolean((1, 0))
        + steps(1)
        + state_ops()
        + forged_calls(9),
        "misuse": misuse() + set_real((2, float("nan")), (2, 3e6)),
        "me_edges": me_start(0.1, 0.0, set_real((2, 0.3)))
        + me_run(
            bytes([2, 1]) + vr(1) + bytes([0, 1]),
            bytes([2, 1]) + vr(1) + bytes([0, 0]),
            bytes([2, 1]) + vr(1) + bytes([0, 1]),
        ),
        "me_states": me_start(0.01, 2.5, set_real((2, 0.05)), stop_time=100.0)
        + me_events(7)
        + me_states(),
        "me_misuse": me_misuse(),
        "me_on_co_simulation": me_on_co_simulation(),
        "fmi3_single_double_long": start(
            0.1, 0.0, set_boolean((1, 1)), set_float64((2, 0.5)), interface=FMI3
        )
        + set_boolean((1, 0))
        + steps(6)
        + get(U8, 7)
        + get(F64, TIME_VR)
        + (set_boolean((1, 1)) + steps(1) + set_boolean((1, 0)) + steps(1)) * 2
        + steps(4)
        + set_boolean((1, 1))
        + steps(8)
        + get(BOOL3, 3, 4, 5, 6)
        + bytes([TERMINATE]),
        "fmi3_me_edges": me_start(0.1, 0.0, set_float64((2, 0.3)), interface=FMI3)
        + me_run3(
            bytes([BOOL3, 1]) + vr(1) + bytes([0, 1]), bytes([BOOL3, 1]) + vr(1) + bytes([0, 0])
        ),
        "fmi3_states": start(0.01, 2.5, set_boolean((1, 1)), interface=FMI3)
        + steps(5)
        + state_ops()
        + forged_calls(9),
        "fmi3_me_states": me_start(0.01, 2.5, stop_time=100.0, interface=FMI3)
        + me_events(7)
        + me_states(),
        "fmi3_misuse": misuse3() + set_float64((2, -3e6)),
    },
    "LGF_IecTimerOnOff": {
        # vr 1 in, 2 timeOnDelay, 3 timeOffDelay, 4 out (docs/behaviour.md §8)
        "delays": start(0.1, 0.0, set_boolean((1, 1)), set_real((2, 0.3), (3, 0.2)))
        + steps(5)
        + get(2, 4)
        + set_boolean((1, 0))
        + steps(3)
        + set_boolean((1, 1))
        + steps(1)
        + set_boolean((1, 0))
        + set_real((3, 0.05))
        + steps(5, 2)
        + bytes([TERMINATE]),
        "zero_negative_largest": start(0.0015, 0.0, set_real((2, -1.0), (3, 0.0)))
        + steps(3)
        + set_boolean((1, 1))
        + steps(3)
        + set_real((2, 2147483.647), (3, 0.0025))
        + set_boolean((1, 0))
        + steps(2)
        + set_boolean((1, 1))
        + steps(4, 200),
        "states": start(0.1, 1.5, set_boolean((1, 1))) + steps(7) + state_ops() + forged_calls(3),
        "misuse": misuse() + set_real((2, float("nan"))) + set_real((3, 3e6)),
        "me_delays": me_start(0.1, 0.0, set_real((2, 0.3), (3, 0.2)))
        + me_run(bytes([2, 1]) + vr(1) + bytes([0, 1]), bytes([2, 1]) + vr(1) + bytes([0, 0])),
        "me_states": me_start(0.1, 1.5, set_boolean((1, 1)), stop_time=100.0)
        + me_events(7)
        + me_states(),
        "me_misuse": me_misuse(),
        "me_on_co_simulation": me_on_co_simulation(),
        "fmi3_delays": start(
            0.1, 0.0, set_boolean((1, 1)), set_float64((2, 0.3), (3, 0.2)), interface=FMI3
        )
        + steps(5)
        + get(BOOL3, 4)
        + get(F64, TIME_VR)
        + set_boolean((1, 0))
        + steps(3)
        + set_boolean((1, 1))
        + steps(1)
        + set_boolean((1, 0))
        + steps(5, 2)
        + bytes([TERMINATE]),
        "fmi3_me_delays": me_start(0.1, 0.0, set_float64((2, 0.3), (3, 0.2)), interface=FMI3)
        + me_run3(
            bytes([BOOL3, 1]) + vr(1) + bytes([0, 1]), bytes([BOOL3, 1]) + vr(1) + bytes([0, 0])
        ),
        "fmi3_states": start(0.1, 1.5, set_boolean((1, 1)), interface=FMI3)
        + steps(7)
        + state_ops()
        + forged_calls(3),
        "fmi3_me_states": me_start(0.1, 1.5, stop_time=100.0, interface=FMI3)
        + me_events(7)
        + me_states(),
        "fmi3_misuse": misuse3(),
    },
    "LGF_Impulse": {
        # vr 1 frequency (REAL), 2 impulse, 3 countdown (docs/behaviour.md §9)
        "pulses": start(0.1, 0.0, set_real((1, 3.0)))
        + steps(14)
        + get(2, 2)
        + get(0, 3)
        + set_real((1, 20.0))
        + steps(6)
        + set_real((1, 0.0))
        + steps(3)
        + set_real((1, 0.8))
        + steps(5, 3)
        + bytes([TERMINATE]),
        "limits": start(0.0015, 0.0, set_real((1, float("inf"))))
        + steps(4)
        + set_real((1, 4.656613157294487e-07))
        + steps(2)
        + set_real((1, 4.6e-7))  # refused
        + set_real((1, -float("inf")))
        + steps(2)
        + set_real((1, 1001.0))
        + steps(4, 200),
        "states": start(0.1, 1.5, set_real((1, 2.0))) + steps(7) + state_ops() + forged_calls(3),
        "misuse": misuse() + set_real((1, float("nan"))) + set_real((1, 1e-40)),
        "me_pulses": me_start(0.1, 0.0, set_real((1, 3.0)))
        + me_run(bytes([0, 1]) + vr(1) + real(10.0), bytes([0, 1]) + vr(1) + real(0.0)),
        "me_states": me_start(0.1, 1.5, set_real((1, 2.0)), stop_time=100.0)
        + me_events(7)
        + me_states(),
        "me_misuse": me_misuse(),
        "me_on_co_simulation": me_on_co_simulation(),
        "fmi3_pulses": start(0.1, 0.0, set_float32((1, 3.0)), interface=FMI3)
        + steps(14)
        + get(BOOL3, 2)
        + get(F64, 3, TIME_VR)
        + get(F32, 1)
        + set_float32((1, 20.0))
        + steps(6)
        + set_float32((1, 0.0))
        + steps(3)
        + set_float32((1, 0.8))
        + steps(5, 3)
        + bytes([TERMINATE]),
        "fmi3_me_pulses": me_start(0.1, 0.0, set_float32((1, 3.0)), interface=FMI3)
        + me_run3(bytes([F32, 1]) + vr(1) + real(10.0), bytes([F32, 1]) + vr(1) + real(0.0)),
        "fmi3_states": start(0.1, 1.5, set_float32((1, 2.0)), interface=FMI3)
        + steps(7)
        + state_ops()
        + forged_calls(3),
        "fmi3_me_states": me_start(0.1, 1.5, stop_time=100.0, interface=FMI3)
        + me_events(7)
        + me_states(),
        "fmi3_misuse": misuse3() + set_float32((1, float("nan"))) + set_float32((1, 1e-40)),
    },
    # vr 1 value, 2 setpoint, 3 lowerMinimum, 4 upperMaximum (REAL), 5 reset, 6 ... 8 the
    # configuration's BOOLs, 9 ... 11 its TIMEs, 12 ... 16 the BOOL outputs, 17 status (WORD)
    # (docs/behaviour.md §13)
    "LGF_IsValueInToleranceByTime": {
        "timing": start(0.1, 0.0, set_real((1, 50.0)), set_real((9, 0.3), (10, 0.2), (11, 0.5)))
        + steps(3)
        + set_real((1, 58.0))
        + steps(6)
        + set_real((1, 40.0))
        + steps(5)
        + set_real((2, 80.0), (1, 50.0))
        + steps(8)
        + get(2, 12, 13, 14, 15)
        + set_boolean((5, 1))
        + steps(1)
        + set_boolean((5, 0), (6, 1))
        + steps(2)
        + set_boolean((6, 0))
        + steps(10, 2)
        + bytes([TERMINATE]),
        "status_codes": start(0.01, 0.0)
        + set_boolean((7, 1))
        + steps(2)
        + get(1, 17)
        + set_real((3, 60.0), (4, 40.0))
        + steps(2)
        + set_real((3, 70.0), (4, 90.0))
        + steps(2)
        + set_boolean((7, 0), (8, 1))
        + set_real((2, float("inf")), (4, -float("inf")))
        + steps(2)
        + set_boolean((8, 0))
        + set_real((2, -100.0))
        + steps(3),
        "states": start(0.01, 2.5, set_real((11, 0.05), (9, 0.02)))
        + steps(3)
        + state_ops()
        + forged_calls(11),
        "misuse": misuse() + set_real((1, float("nan")), (2, 1e39), (9, 3e6)),
        "me_timing": me_start(0.1, 0.0, set_real((11, 0.3), (9, 0.2)))
        + me_run(
            bytes([0, 1]) + vr(1) + real(50.0),
            bytes([0, 1]) + vr(1) + real(58.0),
            bytes([2, 1]) + vr(5) + bytes([0, 1]),
        ),
        "me_states": me_start(0.01, 2.5, stop_time=100.0) + me_events(7) + me_states(),
        "me_misuse": me_misuse(),
        "me_on_co_simulation": me_on_co_simulation(),
        "fmi3_timing": start(
            0.1,
            0.0,
            set_float32((1, 50.0)),
            set_float64((9, 0.3), (10, 0.2), (11, 0.5)),
            interface=FMI3,
        )
        + steps(3)
        + set_float32((1, 58.0))
        + steps(6)
        + get(U16, 17)
        + get(F32, 1, 2)
        + set_float32((1, 40.0))
        + steps(5)
        + set_boolean((7, 1))
        + steps(2)
        + get(BOOL3, 12, 13, 14, 15, 16)
        + bytes([TERMINATE]),
        "fmi3_me_timing": me_start(0.1, 0.0, set_float64((11, 0.3)), interface=FMI3)
        + me_run3(bytes([F32, 1]) + vr(1) + real(58.0), bytes([BOOL3, 1]) + vr(5) + bytes([0, 1])),
        "fmi3_states": start(0.01, 2.5, set_float64((11, 0.05)), interface=FMI3)
        + steps(5)
        + state_ops()
        + forged_calls(11),
        "fmi3_me_states": me_start(0.01, 2.5, stop_time=100.0, interface=FMI3)
        + me_events(7)
        + me_states(),
        "fmi3_misuse": misuse3() + set_float32((3, float("nan"))),
    },
    "LGF_Frequency": {
        # vr 1 frequency, 2 pulsePauseRatio (REAL), 3 clock, 4 countdown (docs/behaviour.md §10)
        "clock": start(0.1, 0.0, set_real((1, 2.0), (2, 3.0)))
        + steps(14)
        + get(2, 3)
        + get(0, 4)
        + set_real((2, 0.5))
        + steps(6)
        + set_real((1, 0.0))
        + steps(3)
        + set_real((1, 2.0))
        + steps(5, 3)
        + bytes([TERMINATE]),
        "limits": start(0.0015, 0.0, set_real((1, float("inf")), (2, 1e9)))
        + steps(4)
        + set_real((1, 1.0), (2, 1e-9))
        + steps(2)
        + set_real((1, 1e-9))  # refused
        + set_real((2, float("inf")))  # refused
        + set_real((2, -float("inf")))
        + steps(2)
        + set_real((1, 4e-7), (2, 1.0))
        + steps(4, 200),
        "states": start(0.1, 1.5, set_real((1, 3.0))) + steps(7) + state_ops() + forged_calls(3),
        "misuse": misuse() + set_real((1, float("nan"))) + set_real((2, 1e-40), (1, 1e-40)),
        "me_clock": me_start(0.1, 0.0, set_real((1, 2.0), (2, 3.0)))
        + me_run(bytes([0, 1]) + vr(2) + real(0.25), bytes([0, 1]) + vr(1) + real(0.0)),
        "me_states": me_start(0.1, 1.5, set_real((1, 3.0)), stop_time=100.0)
        + me_events(7)
        + me_states(),
        "me_misuse": me_misuse(),
        "me_on_co_simulation": me_on_co_simulation(),
        "fmi3_clock": start(0.1, 0.0, set_float32((1, 2.0), (2, 3.0)), interface=FMI3)
        + steps(14)
        + get(BOOL3, 3)
        + get(F64, 4, TIME_VR)
        + get(F32, 1, 2)
        + set_float32((2, 0.5))
        + steps(6)
        + set_float32((1, 0.0))
        + steps(3)
        + set_float32((1, 2.0))
        + steps(5, 3)
        + bytes([TERMINATE]),
        "fmi3_me_clock": me_start(0.1, 0.0, set_float32((1, 2.0), (2, 3.0)), interface=FMI3)
        + me_run3(bytes([F32, 1]) + vr(2) + real(0.25), bytes([F32, 1]) + vr(1) + real(0.0)),
        "fmi3_states": start(0.1, 1.5, set_float32((1, 3.0)), interface=FMI3)
        + steps(7)
        + state_ops()
        + forged_calls(3),
        "fmi3_me_states": me_start(0.1, 1.5, stop_time=100.0, interface=FMI3)
        + me_events(7)
        + me_states(),
        "fmi3_misuse": misuse3() + set_float32((1, float("nan"))) + set_float32((2, float("inf"))),
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

# LGF_NonLinearInterpolation (docs/behaviour.md §20): vr 1 numberOfSetpoints, 10 value, 11
# defaultOutValue, 12 enDefaultOutValue, 13 track, 14 reset, 20 outputValue, 100 + i
# setpoints[i].inputValue, 200 + i setpoints[i].outputValue.
NON_LIN_TABLE = (
    set_integer((1, 4)),
    set_real((100, -10.0), (200, 5.0), (101, 0.0), (201, 0.0), (102, 10.0), (202, 30.0)),
    set_real((103, 40.0), (203, -20.0)),
)
NON_LIN_TABLE3 = (
    set_int16((1, 4)),
    set_float64((100, -10.0), (200, 5.0), (101, 0.0), (201, 0.0), (102, 10.0), (202, 30.0)),
    set_float64((103, 40.0), (203, -20.0)),
)


def non_lin_sweep(real_):
    """value across the table and beyond, on its points, then the modes and a table change."""
    body = b"".join(real_((10, x)) + steps(1) for x in (-30.0, -10.0, 5.0, 10.0, 25.0, 60.0, 10.0))
    return (
        body
        + set_boolean((13, 1))
        + steps(2)
        + set_boolean((13, 0), (12, 1))
        + real_((11, 7.5))
        + steps(2)
        + set_boolean((14, 1))
        + steps(2)
        + set_boolean((12, 0), (14, 0))
        + real_((202, 1e300), (10, float("inf")))
        + steps(3)
    )


SEEDS["LGF_NonLinearInterpolation"] = {
    "curve": start(0.1, 0.0, *NON_LIN_TABLE)
    + non_lin_sweep(set_real)
    + get(0, 20)
    + bytes([TERMINATE]),
    "start_values": start(0.01, 0.0) + steps(20, 3),
    "states": start(0.1, 2.0, *NON_LIN_TABLE)
    + set_real((10, 35.0))
    + steps(3)
    + state_ops()
    + forged_calls(7),
    "misuse": misuse() + set_integer((1, 1)) + set_integer((1, 65)) + set_real((100, float("nan"))),
    "me_curve": me_start(0.1, 0.0, *NON_LIN_TABLE)
    + me_run(bytes([1, 1]) + vr(10) + real(25.0), bytes([2, 1]) + vr(14) + bytes([0, 1])),
    "me_states": me_start(0.1, 2.0, *NON_LIN_TABLE) + me_events(7) + me_states(),
    "me_misuse": me_misuse(),
    "me_on_co_simulation": me_on_co_simulation(),
    "fmi3_curve": start(0.1, 0.0, *NON_LIN_TABLE3, interface=FMI3)
    + non_lin_sweep(set_float64)
    + get(F64, 20, TIME_VR)
    + bytes([TERMINATE]),
    "fmi3_me_curve": me_start(0.1, 0.0, *NON_LIN_TABLE3, interface=FMI3)
    + me_run3(bytes([F64, 1]) + vr(10) + real(25.0), bytes([BOOL3, 1]) + vr(14) + bytes([0, 1])),
    "fmi3_states": start(0.1, 2.0, *NON_LIN_TABLE3, interface=FMI3)
    + steps(7)
    + state_ops()
    + forged_calls(7),
    "fmi3_misuse": misuse3() + set_int16((1, 1)) + set_float64((100, float("nan"))),
}


def floating_average_seeds(fmi3):
    """LGF_FloatingAverage (docs/behaviour.md §15): vr 1 cyclicExecution, 2 trigger, 3 value
    (REAL), 4 windowSize (INT), 5 reset; outputs 6 average (REAL), 7 windowSizeReached, 8 error,
    9 status. A window that fills and slides, trigger edges, Inf and the NaN it leaves, a wrong
    window size (16#8200), a reset; FMU states; Model Exchange; misuse."""
    v = FMI3 if fmi3 else 0
    real_ = set_float32 if fmi3 else set_real
    int_ = set_int16 if fmi3 else set_integer
    real_kind, int_kind, bool_kind = (F32, I16, BOOL3) if fmi3 else (0, 1, 2)
    inputs = (set_boolean((1, 1)), real_((3, 0.1)), int_((4, 5)))
    run = (
        start(0.01, 0.0, *inputs, interface=v)
        + steps(8)
        + real_((3, 1e8))
        + steps(2)
        + int_((4, 2))
        + real_((3, 1.0))
        + steps(4)
        + real_((3, float("inf")))
        + steps(1)
        + real_((3, -2.5))
        + steps(3)
        + int_((4, 0))
        + steps(2)
        + int_((4, 100))
        + set_boolean((1, 0), (2, 1))
        + steps(1)
        + set_boolean((2, 0))
        + steps(1)
        + set_boolean((2, 1), (5, 1))
        + steps(2)
        + set_boolean((5, 0), (1, 1))
        + steps(120)
        + get(real_kind, 6)
        + get(U16 if fmi3 else 1, 9)
        + bytes([TERMINATE])
    )
    me_event_input = (
        bytes([real_kind, 1]) + vr(3) + real(7.25),
        bytes([int_kind, 1]) + vr(4) + integer(3),
        bytes([bool_kind, 1]) + vr(5) + bytes([0, 1]),
        bytes([bool_kind, 1]) + vr(5) + bytes([0, 0]),
        bytes([int_kind, 1]) + vr(4) + integer(101),
    )
    me = me_start(0.01, 0.0, *inputs, interface=v) + me_run(*me_event_input)
    states = start(0.01, 0.5, *inputs, interface=v) + steps(9) + state_ops() + forged_calls(20)
    bad = misuse3() if fmi3 else misuse()
    bad += int_((4, 40000)) + real_((3, float("nan"))) + real_((3, 1e39))
    prefix = "fmi3_" if fmi3 else ""
    seeds = {prefix + "run": run, prefix + "me_run": me, prefix + "states": states}
    seeds[prefix + "misuse"] = bad
    if not fmi3:
        seeds["me_misuse"] = me_misuse()
        seeds["me_on_co_simulation"] = me_on_co_simulation()
    return seeds


SEEDS["LGF_FloatingAverage"] = {**floating_average_seeds(False), **floating_average_seeds(True)}


# LGF_ScaleLinear (docs/behaviour.md §19): x 1, x1 2, y1 3, x2 4, y2 5, yMin 6, yMax 7; y 8,
# error 9, status 10. The line, both limits, yMin > yMax, x1 = x2 and infinities.
SEEDS["LGF_ScaleLinear"] = {
    "scale": start(0.1, 0.0, set_real((1, -100.0), (4, 27648.0), (5, 100.0), (7, 100.0)))
    + steps(5)
    + set_real((1, 13824.0))
    + steps(2)
    + get(0, 8)
    + set_real((1, 30000.0))
    + steps(2)
    + set_real((6, 120.0))
    + steps(2)
    + set_real((6, 0.0), (4, 0.0), (3, 25.0))
    + steps(5, 2)
    + bytes([TERMINATE]),
    "infinities": start(1e-6, 0.0, set_real((2, float("inf")), (4, float("inf"))))
    + steps(3)
    + set_real((1, -float("inf")), (2, 0.0), (6, -float("inf")), (7, float("inf")))
    + steps(3),
    "states": start(0.01, -3.0, set_real((1, 2.5), (4, 10.0), (5, 100.0), (7, 100.0)))
    + steps(7)
    + state_ops()
    + forged_calls(1000),
    "misuse": misuse(),
    "me_scale": me_start(0.1, 0.0, set_real((1, 2.5), (4, 10.0), (5, 100.0), (7, 100.0)))
    + me_run(
        bytes([1, 1]) + vr(1) + real(11.0),
        bytes([1, 1]) + vr(6) + real(200.0),
        bytes([1, 1]) + vr(6) + real(0.0),
    ),
    "me_states": me_start(0.01, -3.0, set_real((1, 1.0))) + me_events(7) + me_states(),
    "me_misuse": me_misuse(),
    "me_on_co_simulation": me_on_co_simulation(),
    "fmi3_scale": start(
        0.1, 0.0, set_float64((1, -100.0), (4, 27648.0), (5, 100.0), (7, 100.0)), interface=FMI3
    )
    + steps(5)
    + get(F64, 8, TIME_VR)
    + set_float64((6, 120.0))
    + steps(2)
    + get(U16, 10)
    + set_float64((6, 0.0), (4, 0.0))
    + steps(5, 2)
    + bytes([TERMINATE]),
    "fmi3_me_scale": me_start(0.1, 0.0, set_float64((1, 2.5)), interface=FMI3)
    + me_run3(bytes([F64, 1]) + vr(1) + real(-1.0), bytes([F64, 1]) + vr(6) + real(200.0)),
    "fmi3_states": start(0.01, -3.0, set_float64((1, 1.0)), interface=FMI3)
    + steps(7)
    + state_ops()
    + forged_calls(1000),
    "fmi3_misuse": misuse3(),
}


# LGF_LimRateOfChangeAdvancedCI (docs/behaviour.md §21): vr 1 autoValue, 2 manualValue, 3 ... 6
# setPosUpRateLim, setPosDownRateLim, setNegUpRateLim, setNegDownRateLim, 7 setHighLim, 8
# setLowLim, 9 defaultOutValue, 10 enDefaultOutValue, 11 track, 12 manOp, 13 reset, 14
# outputValue, 15 ... 20 the flags, 21 error, 22 status, 23 subFunctionStatus.
def lim_adv_inputs(real_):
    return real_(
        (1, 30.0), (2, 70.0), (3, 20.0), (4, 40.0), (5, 20.0), (6, 30.0), (7, 50.0)
    ) + real_((8, -50.0), (9, -10.0))


def lim_adv_run(real_, status_kind):
    """Both zero crossings, the limits, manual mode, tracking, pre-assignment, reset, both
    errors."""
    return (
        steps(20)
        + real_((1, -60.0))
        + steps(40)
        + real_((1, 20.0))
        + steps(30)
        + set_boolean((12, 1))
        + steps(2)
        + set_boolean((12, 0))
        + steps(10)
        + set_boolean((11, 1))
        + real_((1, 55.0))
        + steps(2)
        + set_boolean((11, 0), (10, 1))
        + steps(2)
        + set_boolean((10, 0), (13, 1))
        + steps(2)
        + set_boolean((13, 0))
        + real_((8, 60.0))
        + steps(2)
        + get(status_kind, 22)
        + real_((8, -50.0), (5, -1.0))
        + steps(2)
        + real_((5, float("inf")), (7, float("inf")), (1, 1e300))
        + steps(3)
    )


SEEDS["LGF_LimRateOfChangeAdvancedCI"] = {
    "modes": start(0.1, 0.0, lim_adv_inputs(set_real))
    + lim_adv_run(set_real, 1)
    + bytes([TERMINATE]),
    "start_values": start(0.1, 0.0) + steps(50) + get(0, 14),
    "states": start(0.01, -3.0, lim_adv_inputs(set_real))
    + steps(7)
    + set_boolean((12, 1))
    + steps(1)
    + state_ops()
    + forged_calls(1000),
    "misuse": misuse() + set_real((3, float("nan"))) + set_real((7, -1.0), (8, 1.0)) + steps(2),
    "me_modes": me_start(0.1, 0.0, lim_adv_inputs(set_real))
    + me_run(
        bytes([1, 1]) + vr(1) + real(-60.0),
        bytes([2, 1]) + vr(12) + bytes([0, 1]),
        bytes([2, 1]) + vr(12) + bytes([0, 0]),
    ),
    "me_states": me_start(0.01, -3.0, lim_adv_inputs(set_real)) + me_events(7) + me_states(),
    "me_misuse": me_misuse(),
    "me_on_co_simulation": me_on_co_simulation(),
    "fmi3_modes": start(0.1, 0.0, lim_adv_inputs(set_float64), interface=FMI3)
    + lim_adv_run(set_float64, U16)
    + get(F64, 14, TIME_VR)
    + bytes([TERMINATE]),
    "fmi3_me_modes": me_start(0.1, 0.0, lim_adv_inputs(set_float64), interface=FMI3)
    + me_run3(
        bytes([F64, 1]) + vr(1) + real(-60.0),
        bytes([BOOL3, 1]) + vr(12) + bytes([0, 1]),
        bytes([BOOL3, 1]) + vr(12) + bytes([0, 0]),
    ),
    "fmi3_states": start(0.01, -3.0, lim_adv_inputs(set_float64), interface=FMI3)
    + steps(7)
    + state_ops()
    + forged_calls(1000),
    "fmi3_misuse": misuse3() + set_float64((3, float("nan"))),
}


def sampled_seeds(fmi3, delta_t=None):
    """The blocks that read a value in at each rising edge of insert while enabled,
    LGF_SimpleSmoothingFB (docs/behaviour.md §16) and, with `delta_t` (the vr of deltaT, 4),
    LGF_DifferenceQuotientFB (§17): vr 1 enable, 2 insert, 3 value (LREAL); the outputs follow
    the inputs (the LREAL result, error, status). Values read in at edges, enough and not enough
    of them, ±Inf, enable off and on (with insert rising with it), deltaT 0 (16#8200); states,
    Model Exchange, misuse."""
    v = FMI3 if fmi3 else 0
    real_ = set_float64 if fmi3 else set_real
    real_kind, bool_kind = (F64, BOOL3) if fmi3 else (0, 2)
    result = 5 if delta_t else 4
    inputs = (set_boolean((1, 1)), real_((3, 0.5)))
    if delta_t:
        inputs += (real_((delta_t, 0.1)),)

    def sample(x):
        return real_((3, x)) + set_boolean((2, 1)) + steps(1) + set_boolean((2, 0)) + steps(1)

    run = start(0.01, 0.0, *inputs, interface=v) + b"".join(
        sample(x) for x in (1.0, 2.0, 4.0, 8.0, 16.0, 32.0, float("inf"), -3.0, 0.1, 0.2, 0.3)
    )
    if delta_t:
        run += real_((delta_t, 0.0)) + sample(5.0) + real_((delta_t, -0.5)) + sample(6.0)
    run += set_boolean((1, 0)) + steps(2) + set_boolean((1, 1), (2, 1)) + steps(1)
    run += set_boolean((2, 0)) + steps(3) + sample(7.0) + sample(9.0) + sample(-1.0)
    run += get(real_kind, result) + get(U16 if fmi3 else 1, result + 2) + bytes([TERMINATE])
    me_event_input = (
        bytes([real_kind, 1]) + vr(3) + real(7.25),
        bytes([bool_kind, 1]) + vr(2) + bytes([0, 1]),
        bytes([bool_kind, 1]) + vr(2) + bytes([0, 0]),
        bytes([bool_kind, 1]) + vr(2) + bytes([0, 1]),
        bytes([bool_kind, 1]) + vr(1) + bytes([0, 0]),
    )
    me = me_start(0.01, 0.0, *inputs, interface=v) + me_run(*me_event_input)
    states = (
        start(0.01, 0.5, *inputs, interface=v)
        + b"".join(sample(x) for x in (1.0, 2.0, 3.0))
        + state_ops()
        + forged_calls(20)
    )
    bad = misuse3() if fmi3 else misuse()
    bad += real_((3, float("nan")))
    if delta_t:
        bad += real_((delta_t, float("nan")))
    prefix = "fmi3_" if fmi3 else ""
    seeds = {prefix + "run": run, prefix + "me_run": me, prefix + "states": states}
    seeds[prefix + "misuse"] = bad
    if not fmi3:
        seeds["me_misuse"] = me_misuse()
        seeds["me_on_co_simulation"] = me_on_co_simulation()
    return seeds


SEEDS["LGF_SimpleSmoothingFB"] = {**sampled_seeds(False), **sampled_seeds(True)}
SEEDS["LGF_DifferenceQuotientFB"] = {**sampled_seeds(False, 4), **sampled_seeds(True, 4)}


# LGF_StoreMinMax (docs/behaviour.md §14): value 1, reset 2; minValue 3, maxValue 4.
SEEDS["LGF_StoreMinMax"] = {
    "extremes": start(0.1, 0.0, set_real((1, 3.0)))
    + steps(3)
    + set_real((1, -2.0))
    + steps(2)
    + get(0, 3, 4)
    + set_boolean((2, 1))
    + set_real((1, 7.0))
    + steps(2)
    + set_boolean((2, 0))
    + steps(5, 2)
    + bytes([TERMINATE]),
    "infinities": start(1e-6, 0.0, set_real((1, float("inf"))))
    + steps(3)
    + set_real((1, -float("inf")))
    + steps(3)
    + set_boolean((2, 1))
    + steps(2),
    "states": start(0.01, -3.0, set_real((1, 1.0))) + steps(7) + state_ops() + forged_calls(1000),
    "misuse": misuse(),
    "me_extremes": me_start(0.1, 0.0, set_real((1, 2.0)))
    + me_run(
        bytes([1, 1]) + vr(1) + real(-4.0),
        bytes([1, 1]) + vr(2) + bytes([0, 1]),
        bytes([1, 1]) + vr(2) + bytes([0, 0]),
    ),
    "me_states": me_start(0.01, -3.0, set_real((1, 1.0))) + me_events(7) + me_states(),
    "me_misuse": me_misuse(),
    "me_on_co_simulation": me_on_co_simulation(),
    "fmi3_extremes": start(0.1, 0.0, set_float64((1, 3.0)), interface=FMI3)
    + steps(3)
    + get(F64, 3, 4, TIME_VR)
    + set_boolean((2, 1))
    + steps(2)
    + set_boolean((2, 0))
    + steps(5, 2)
    + bytes([TERMINATE]),
    "fmi3_me_extremes": me_start(0.1, 0.0, set_float64((1, 2.0)), interface=FMI3)
    + me_run3(
        bytes([F64, 1]) + vr(1) + real(-4.0),
        bytes([BOOL3, 1]) + vr(2) + bytes([0, 1]),
        bytes([BOOL3, 1]) + vr(2) + bytes([0, 0]),
    ),
    "fmi3_states": start(0.01, -3.0, set_float64((1, 1.0)), interface=FMI3)
    + steps(7)
    + state_ops()
    + forged_calls(1000),
    "fmi3_misuse": misuse3(),
}

# LGF_Integration (docs/behaviour.md §18): enable 1, value 2, reset 3; integral 4, error 5,
# status 6, subFunctionStatus 7. Trapezoids, hold, reset, sub-ms cycles, infinities.
SEEDS["LGF_Integration"] = {
    "integrate": start(0.1, 0.0, set_real((2, 2.0)))
    + steps(10)
    + set_real((2, -3.0))
    + steps(3)
    + get(0, 4)
    + set_boolean((1, 0))
    + steps(2)
    + set_boolean((1, 1))
    + steps(2)
    + set_boolean((3, 1))
    + steps(2)
    + set_boolean((3, 0))
    + steps(5, 2)
    + bytes([TERMINATE]),
    "sub_ms_infinities": start(0.0015, 0.0, set_real((2, float("inf"))))
    + steps(3)
    + set_real((2, -float("inf")))
    + steps(3)
    + set_boolean((3, 1))
    + steps(2),
    "states": start(0.01, -3.0, set_real((2, 1.0))) + steps(7) + state_ops() + forged_calls(1000),
    "misuse": misuse(),
    "me_integrate": me_start(0.1, 0.0, set_real((2, 2.0)))
    + me_run(
        bytes([1, 1]) + vr(2) + real(-4.0),
        bytes([1, 1]) + vr(1) + bytes([0, 0]),
        bytes([1, 1]) + vr(1) + bytes([0, 1]),
        bytes([1, 1]) + vr(3) + bytes([0, 1]),
    ),
    "me_states": me_start(0.01, -3.0, set_real((2, 1.0))) + me_events(7) + me_states(),
    "me_misuse": me_misuse(),
    "me_on_co_simulation": me_on_co_simulation(),
    "fmi3_integrate": start(0.1, 0.0, set_float64((2, 2.0)), interface=FMI3)
    + steps(10)
    + get(F64, 4, TIME_VR)
    + set_boolean((1, 0))
    + steps(2)
    + get(U16, 6, 7)
    + set_boolean((1, 1), (3, 1))
    + steps(2)
    + set_boolean((3, 0))
    + steps(5, 2)
    + bytes([TERMINATE]),
    "fmi3_me_integrate": me_start(0.1, 0.0, set_float64((2, 2.0)), interface=FMI3)
    + me_run3(
        bytes([F64, 1]) + vr(2) + real(-4.0),
        bytes([BOOL3, 1]) + vr(1) + bytes([0, 0]),
        bytes([BOOL3, 1]) + vr(3) + bytes([0, 1]),
    ),
    "fmi3_states": start(0.01, -3.0, set_float64((2, 1.0)), interface=FMI3)
    + steps(7)
    + state_ops()
    + forged_calls(1000),
    "fmi3_misuse": misuse3(),
}

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
