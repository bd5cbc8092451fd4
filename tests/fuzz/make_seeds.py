"""Writes the seed inputs of tests/fuzz/corpus/<block>/ in the input format of fuzz_fmu.c (see the
comment at its top and the op_* functions), for the FMU's FMI 2.0 build and, with bit 6 of the
second byte (fuzz_main.c), its FMI 3.0 build (the seeds named fmi3_*), and the inputs of bugs
found in the FMU and fixed since, in tests/fuzz/regressions/<block>/ (regressions_of below; the
other regressions are committed files, not written here). Both are committed: run this again
after changing the input format, a block's interface or its seeds, or adding a block, from the
repository's root:

    .venv/bin/python -m tests.fuzz.make_seeds

tests/fuzz/test_make_seeds.py fails while a committed seed differs from what this writes (the
corpus folders hold nothing else: this removes the seeds it no longer writes).

Every seed is made from the block's interface, read from its committed modelDescription.xml
(modelDescription/<Block>.xml and fmi3/<Block>.xml): a variable is named, never numbered; its
value reference, its type in either FMI version (which set, get and kind byte it takes), its
start value and its range come from there. Every block (the folders of src/blocks/ with an
interface.toml, as run.sh finds them) gets the same recipes, in both versions:

    walk                every input in turn through values drawn from its start value and range
                        (booleans on and off), calls after each, at the smallest cycleTime,
                        without setupExperiment; outputs read in initialization; doSteps of odd
                        sizes
    states              FMU states before the first call, then while stepping (state_ops,
                        forged call counters, a state cut and padded), from two start times
    misuse              calls in the wrong state or mode, wrong arguments; every settable
                        variable given its bad values (NaN, past min and max, beyond a float32)
                        and its start value, the types mixed up, values and value references as
                        fuzz_fmu.c can also write them
    me_run              Model Exchange: the calls at their time events as importers make them,
                        inputs set in event mode
    me_states           Model Exchange states and round trips of an event iteration
    me_misuse           Model Exchange calls in the wrong mode and with wrong arguments
    me_on_co_simulation the Model Exchange functions on a co-simulation instance

and beside them the block's own: the scenarios that need a particular sequence to reach its deep
states (a time table run through, edges counted in their monitoring time, limits crossed), kept
beside the block in tests/blocks/<Block>/fuzz_seeds.py (imported as tests.blocks.<Block>.
fuzz_seeds; a block without one gets the recipes only):

    SCENARIOS           seed name -> script: a co-simulation run (and its fmi3_ twin); the first
                        scenario's initialization is also that of states and me_states
    EVENTS              optional, me_run's script: its initialization, then the sets of one time
                        event an item (default: the first scenario's initialization, then each
                        input set to its first walk value, booleans toggled and back)

A script is a string of items separated by ";":

    the first item      the initialization: name=value ... set between enterInitializationMode
                        and exitInitializationMode (cycleTime is its start value unless given);
                        startTime=... and stopTime=... go to setupExperiment; may be empty
    name=value ...      set these (a boolean as 0 or 1; numbers as Python's float() and int()
                        read them: inf, -inf, nan, 1e300); one call a type
    N, NxC              N doSteps of one cycle (of C cycles, 1 to 4) from the FMU's time
    get name ...        get these

A scenario ends with a get of every output and input (and, in FMI 3.0, of the time), then
terminate."""

from __future__ import annotations

import importlib
import os
import struct
import xml.etree.ElementTree as ElementTree
from dataclasses import dataclass

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))

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
TIME_VR = 1000000  # the independent variable of FMI 3.0
NO_VARIABLE = 99999  # a value reference no block has
PAYLOAD_TIME = 16  # offset of the time in the serialized payload (fmu_image)
PAYLOAD_CALLS = 24  # offset of the call counter

# The kind byte of OP_GET and of a set in op_me_event (enum kind in fuzz_fmu.c), by the
# variable's type, and the set operation with the byte FMI 3.0 reads after it (set_kind; after
# OP_SET_BOOLEAN too, where it changes nothing).
KINDS_FMI2 = {"Real": 0, "Integer": 1, "Boolean": 2}
KINDS_FMI3 = {
    "Float64": 0,
    "Float32": 1,
    "Int16": 2,
    "UInt16": 3,
    "UInt32": 4,
    "Boolean": 5,
    "Int32": 6,
    "Int8": 7,
    "UInt8": 8,
}
SETS_FMI3 = {
    "Float64": (SET_REAL, 0),
    "Float32": (SET_REAL, 1),
    "Int16": (SET_INTEGER, 0),
    "UInt16": (SET_INTEGER, 1),
    "UInt32": (SET_INTEGER, 2),
    "Int32": (SET_INTEGER, 3),
    "Int8": (SET_INTEGER, 4),
    "UInt8": (SET_INTEGER, 5),
    "Boolean": (SET_BOOLEAN, 0),
}
SETS_FMI2 = {"Real": (SET_REAL,), "Integer": (SET_INTEGER,), "Boolean": (SET_BOOLEAN,)}
MAX_SET = 4  # the values one set or get takes (MAX_SET in fuzz_fmu.c)


def real(x):
    return bytes([0x80]) + struct.pack("<d", x)


def integer(x):
    return bytes([0x80]) + struct.pack("<I", x & 0xFFFFFFFF)


def vr(x):
    return bytes([0xE0]) + struct.pack("<I", x)


def steps(count, cycles=1):
    return bytes([SIMPLE_STEP, cycles - 1]) * count


def chunks(items):
    return [items[i : i + MAX_SET] for i in range(0, len(items), MAX_SET)]


@dataclass(frozen=True)
class Variable:
    name: str
    vr: int
    type: str  # the element's name in this version's modelDescription.xml: Real, Float32, ...
    kind: int  # its kind byte
    causality: str
    variability: str
    start: float | int | bool | None
    min: float | None
    max: float | None
    float32: bool  # a REAL: Float32 in FMI 3.0

    @property
    def boolean(self):
        return self.type == "Boolean"

    @property
    def real(self):
        return self.type in ("Real", "Float64", "Float32")

    def value(self, text):
        """A value of this variable written in a script."""
        if self.boolean:
            return {"0": False, "1": True, "false": False, "true": True}[text.lower()]
        return float(text) if self.real else int(text)


def _number(text, real_):
    if text is None:
        return None
    if text in ("true", "false"):
        return text == "true"
    return float(text) if real_ else int(text)


def _variables(path, fmi3):
    root = ElementTree.parse(path).getroot()
    found = {}
    for element in root.find("ModelVariables"):
        typed = element if fmi3 else element[0]
        type_ = typed.tag
        real_ = type_ in ("Real", "Float64", "Float32")
        found[element.get("name")] = (
            int(element.get("valueReference")),
            type_,
            element.get("causality", "local"),
            element.get("variability", "continuous"),
            _number(typed.get("start"), real_),
            _number(typed.get("min"), True),
            _number(typed.get("max"), True),
        )
    return found


class Interface:
    """One block's interface in one FMI version: what its variables' names become in the bytes
    of an input."""

    def __init__(self, block, fmi3):
        self.block, self.fmi3 = block, fmi3
        self.flag = FMI3 if fmi3 else 0
        folder = os.path.join(ROOT, "modelDescription")
        fmi2_vars = _variables(os.path.join(folder, f"{block}.xml"), False)
        fmi3_vars = _variables(os.path.join(folder, "fmi3", f"{block}.xml"), True)
        self.variables = {}
        for name, (ref, type_, causality, variability, start, low, high) in (
            fmi3_vars if fmi3 else fmi2_vars
        ).items():
            if causality == "independent":
                continue
            kinds = KINDS_FMI3 if fmi3 else KINDS_FMI2
            float32 = fmi3_vars[name][1] == "Float32"
            self.variables[name] = Variable(
                name, ref, type_, kinds[type_], causality, variability, start, low, high, float32
            )
        self.cycle = self.variables["cycleTime"]
        self.real_type, self.integer_type = ("Float64", "Int16") if fmi3 else ("Real", "Integer")

    def __getitem__(self, name):
        try:
            return self.variables[name]
        except KeyError:
            raise KeyError(f"{self.block} has no variable {name!r}") from None

    def inputs(self):
        """The variables a running instance takes: inputs and tunable parameters (of an array,
        its first element only)."""
        return [
            v
            for v in self.variables.values()
            if v.causality == "input"
            or (v.variability == "tunable" and "[" not in v.name.replace("[0]", ""))
        ]

    def settable(self):
        """Every variable a set may name: inputs and parameters."""
        return [v for v in self.variables.values() if v.causality in ("input", "parameter")]

    def outputs(self):
        return [v for v in self.variables.values() if v.causality == "output"]

    def _groups(self, pairs):
        """(variable, value) pairs grouped by type in the order they come, MAX_SET a group."""
        by_type = {}
        for name, value in pairs:
            v = self[name]
            by_type.setdefault(v.type, []).append((v, value))
        return [(type_, group) for type_, items in by_type.items() for group in chunks(items)]

    @staticmethod
    def _pairs(type_, refs_values):
        """The value references and values of a set, each value written as `type_` takes it."""
        if type_ == "Boolean":
            return b"".join(vr(ref) + bytes([0, int(value)]) for ref, value in refs_values)
        if type_ in ("Real", "Float64", "Float32"):
            return b"".join(vr(ref) + real(value) for ref, value in refs_values)
        return b"".join(vr(ref) + integer(int(value)) for ref, value in refs_values)

    def set_as(self, type_, refs_values, count=None):
        """One fmi2Set*/fmi3Set* of `type_` (its set operation and, in FMI 3.0, the byte that
        picks the type), whatever the variables' own types; `count`: another count byte."""
        sets = SETS_FMI3 if self.fmi3 else SETS_FMI2
        count = len(refs_values) if count is None else count
        return bytes(sets[type_] + (count,)) + self._pairs(type_, refs_values)

    def set(self, *pairs):
        """fmi2Set*/fmi3Set* of the named variables: one call a type (and MAX_SET values)."""
        return b"".join(
            self.set_as(type_, [(v.vr, value) for v, value in group])
            for type_, group in self._groups(pairs)
        )

    def event_sets(self, *pairs):
        """The sets of op_me_event (its kind byte, then those of a set), one a type."""
        return [
            bytes([group[0][0].kind, len(group)])
            + self._pairs(type_, [(v.vr, value) for v, value in group])
            for type_, group in self._groups(pairs)
        ]

    def get(self, *names):
        """fmi2Get*/fmi3Get* of the named variables (`time`: FMI 3.0's independent variable)."""
        out, by_kind = b"", {}
        for name in names:
            if name == "time":
                by_kind.setdefault(KINDS_FMI3["Float64"], []).append(TIME_VR)
            else:
                by_kind.setdefault(self[name].kind, []).append(self[name].vr)
        for kind, refs in by_kind.items():
            for group in chunks(refs):
                out += bytes([GET, kind, len(group)]) + b"".join(vr(r) for r in group)
        return out

    def get_all(self):
        """A get of every output and input (and, in FMI 3.0, of the time)."""
        names = [v.name for v in self.outputs() + self.inputs()]
        return self.get(*names, *(["time"] if self.fmi3 else []))

    def first_input(self):
        return next(v for v in self.variables.values() if v.causality == "input")


# ------------------------------------------------------------------------------- scripts ----


def assignments(interface, item):
    """The name=value pairs of one item of a script."""
    pairs = []
    for word in item.split():
        name, equals, value = word.partition("=")
        if not equals:
            raise ValueError(f"{interface.block}: {word!r} is no name=value")
        if name in ("startTime", "stopTime"):
            pairs.append((name, float(value)))
        else:
            pairs.append((name, interface[name].value(value)))
    return pairs


def items_of(script):
    return [item.strip() for item in script.split(";")]


def operation(interface, item):
    """The bytes of one item after the initialization: steps, a get or sets."""
    count, x, cycles = item.partition("x")
    if count.isdigit() and (not x or cycles.isdigit()):
        cycles = int(cycles or 1)
        if not 1 <= cycles <= 4:
            raise ValueError(f"{interface.block}: {item!r}: a doStep takes 1 to 4 cycles")
        return steps(int(count), cycles)
    if item.startswith("get "):
        return interface.get(*item.split()[1:])
    return interface.set(*assignments(interface, item))


def start(
    interface,
    init="",
    start_time=0.0,
    cycle=None,
    model_exchange=False,
    stop_time=None,
    instantiated=b"",
    initializing=b"",
):
    """Instantiate, setupExperiment, initialization with cycleTime and the sets of `init` (an
    item of a script, whose startTime and stopTime win), exit; the operations `instantiated`
    before setupExperiment and `initializing` before exit. FMI 3.0: OP_SETUP keeps the times
    for fmi3EnterInitializationMode (OP_ENTER)."""
    pairs = dict(assignments(interface, init))
    start_time = pairs.pop("startTime", start_time)
    stop_time = pairs.pop("stopTime", stop_time)
    pairs.setdefault("cycleTime", cycle or interface.cycle.start)
    pairs = {"cycleTime": pairs.pop("cycleTime"), **pairs}
    flags = 2 if stop_time is not None else 0
    how = interface.flag | (MODEL_EXCHANGE if model_exchange else 0)
    return (
        bytes([0, 1 | how])
        + instantiated
        + bytes([SETUP, flags])
        + real(0.0)
        + real(start_time)
        + real(stop_time or 0.0)
        + bytes([ENTER])
        + interface.set(*pairs.items())
        + initializing
        + bytes([EXIT])
    )


def scenario(interface, script):
    """A co-simulation run of a script: its initialization, its items, every variable read,
    terminate."""
    init, *rest = items_of(script)
    body = b"".join(operation(interface, item) for item in rest if item)
    return start(interface, init) + body + interface.get_all() + bytes([TERMINATE])


# ---------------------------------------------------------------- values from the interface ----


def walk_values(v):
    """The values `walk` gives a variable, ending on its start value: booleans off and on, a
    number doubled, negated, 0, its min and max, 1e300 and the infinities when unbounded."""
    if v.boolean:
        return [not v.start, v.start]
    s = v.start or 0
    values = [2 * s if s else 1, -s if s else -1, 0, v.min, v.max]
    if v.real and v.min is None and v.max is None:
        values += [1e300, float("inf"), -float("inf")]
    if not v.real:
        values = [None if x is None else int(x) for x in values] + [s + 1]
    seen = []
    for x in values:
        if x is not None and x not in seen and x != s:
            seen.append(x)
    return seen + [s]


def bad_values(v):
    """Values a set must refuse: NaN, past the range, beyond a float32 for a REAL."""
    if v.boolean:
        return []
    values = [float("nan")] if v.real else []
    if v.min is not None:
        values.append(v.min - 1 if not v.real else v.min - 1 - abs(v.min))
    if v.max is not None:
        values.append(v.max + 1 if not v.real else v.max + 1 + abs(v.max))
    if v.float32:
        values.append(1e39)
    if not v.real:
        values = [int(x) for x in values if -(2**31) <= x < 2**32]
    return values


def default_events(interface):
    """Each input set to its first walk value in event mode; booleans toggled and back."""
    pairs = []
    for v in interface.inputs():
        values = walk_values(v)
        pairs += [(v.name, values[0])] + ([(v.name, v.start)] if v.boolean else [])
    return pairs[:8]


# ----------------------------------------------------------------------------- the recipes ----


def all_kinds(interface):
    """A get of every kind, of the first output."""
    kinds = (KINDS_FMI3 if interface.fmi3 else KINDS_FMI2).values()
    return b"".join(bytes([GET, kind, 1]) + vr(interface.outputs()[0].vr) for kind in kinds)


# doSteps of other sizes (pick_t, pick_h): half a cycle twice (no call due, then one), below
# the grid tolerance, three cycles one ulp short, two cycles a little long, from a time a little
# off the FMU's, a tenth of a second, 257/16 cycles.
ODD_STEPS = bytes(
    [DO_STEP, 0, 8, 0x7F, 0, DO_STEP, 0, 8, 0x7F, 0, DO_STEP, 0, 12, 0x40, 0]
    + [DO_STEP, 0, 13, 2, 0xFF, 0, DO_STEP, 0, 15, 1, 0x05, 0, DO_STEP, 4, 0x81, 0, 0]
    + [DO_STEP, 0, 14, 0, 1, DO_STEP, 0, 9, 0x00, 0x01, 0]
)


def walk(interface):
    """Every input through its walk values, without fmi2SetupExperiment (the FMU's defaults), at
    the smallest cycleTime (the inputs set to their start values in initialization, several in
    a call, and the variables read there, an output as every kind too), then steps of other
    sizes (ODD_STEPS), every variable read and terminate."""
    body = b""
    for v in interface.inputs():
        body += b"".join(interface.set((v.name, x)) + steps(2) for x in walk_values(v))
    return (
        bytes([0, 1 | interface.flag, ENTER])
        + interface.set(("cycleTime", interface.cycle.min))
        + interface.set(*[(v.name, v.start) for v in interface.inputs()])
        + interface.get_all()
        + all_kinds(interface)
        + bytes([EXIT])
        + steps(5)
        + body
        + steps(10, 4)
        + ODD_STEPS
        + interface.get_all()
        + bytes([TERMINATE])
    )


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


def forged(offset, value):
    """Deserialize the current state with the 8-byte field of its image at `offset` (an
    integer or a double) replaced, checksum fixed, into slot 2, and set it."""
    how, written = (0x42, real(value)) if isinstance(value, float) else (0x82, integer(value))
    return (
        bytes([DESERIALIZE_MUTATED, 1, 1, how])
        + struct.pack("<H", offset)
        + written
        + bytes([2, 2, SET_STATE, 2])
    )


def forged_calls(value):
    """The current state with its call counter replaced, set; then step."""
    return forged(PAYLOAD_CALLS, value) + steps(2)


# FMU states before the first call: a mutated deserialization before anything was serialized,
# a get, a serialization of a NULL state, without a size, into a short and a NULL buffer,
# then of the state got, deserialized into slot 1, set, freed; the state with a call made and
# with another time than its start (both refused).
EARLY_STATES = (
    bytes([DESERIALIZE_MUTATED, 0, 0, 0, 1, GET_STATE, 0, SERIALIZE, 3, 0, SERIALIZE, 0, 0x80])
    + bytes([SERIALIZE, 0, 0x41, SERIALIZE, 0, 0x20, SERIALIZE, 0, 0])
    + bytes([DESERIALIZE_MUTATED, 0, 0, 0, 1, SET_STATE, 1, FREE_STATE, 0, FREE_STATE, 1])
    + forged(PAYLOAD_CALLS, 1)
    + forged(PAYLOAD_TIME, 0.5)
)


# The serialized state cut to its header (STATE_HEADER_SIZE) and padded by 1 to 7 bytes, size
# and checksum fixed.
CUT_STATE = bytes([DESERIALIZE_MUTATED, 0, 1, 0x83]) + struct.pack("<H", 104) + bytes([3, 1])
CUT_STATE += b"".join(bytes([DESERIALIZE_MUTATED, 0, 1, 0x03, 0, 0, n, 3, 1]) for n in range(1, 8))


def states(interface, init):
    """FMU states while instantiated and initializing (EARLY_STATES), then stepping from
    t0 = 1.5 s: state_ops, forged call counters (behind the FMU's time: refused; far ahead of
    it), a state cut to its header; again after a reset from t0 = -3 s at 10 ms."""
    stepping = steps(7) + state_ops() + forged_calls(3) + forged_calls(1000) + CUT_STATE
    return (
        start(interface, init, 1.5, instantiated=EARLY_STATES, initializing=EARLY_STATES)
        + stepping
        + bytes([RESET])
        + start(interface, init, -3.0, cycle=0.01)[2:]
        + stepping
        + bytes([TERMINATE])
    )


def me_start(interface, init="", start_time=0.0, stop_time=None, cycle=None, **operations):
    """start() for Model Exchange, then the event iteration at t0 and continuous-time mode."""
    return start(interface, init, start_time, cycle, True, stop_time, **operations) + bytes(
        [ME_NEW_DISCRETE_STATES, 0, ME_ENTER_CONTINUOUS]
    )


def me_events(count, how=0):
    """Time events at the next calls (op_me_event): `how` 0 the call time, back to
    continuous-time mode; 0x02 first a time between calls and fmi2CompletedIntegratorStep
    (its byte: 0x80 = half way); 0x08 a second event iteration; 0x10 staying in event mode."""
    extra = bytes([0x80, 0]) if how & 3 == 2 else bytes([0]) if how & 3 else b""
    return (bytes([ME_EVENT, how]) + extra) * count


def me_run(interface, init, events):
    """A normal Model Exchange run: the calls at their time events, varied the way importers
    do, with inputs changed in event mode (`events`: the (name, value) pairs of each event;
    one a type), then every variable read and terminate from continuous-time mode."""
    sets = [s for pairs in events for s in interface.event_sets(*pairs)]
    body = me_events(5) + me_events(3, 0x02) + me_events(2, 0x08) + me_events(2, 0x10)
    body += me_events(1) + b"".join(bytes([ME_EVENT, 0x04]) + s for s in sets) + me_events(10)
    return (
        me_start(interface, init)
        + body
        + interface.get_all()
        + bytes([ME_COMPLETED_INTEGRATOR_STEP, 0, TERMINATE])
    )


def me_states(interface, init):
    """Model Exchange states: get in continuous-time mode, events, set back, serialize,
    deserialize, round trips of an event iteration, free; from t0 = 1.5 s with a stop time,
    and again after a reset from t0 = -3 s at 10 ms without one."""
    body = (
        me_events(7)
        + bytes([GET_STATE, 0])
        + me_events(4)
        + bytes([SET_STATE, 0, SERIALIZE, 0, 0])
        + bytes([DESERIALIZE_MUTATED, 0, 0, 0, 1])
        + bytes([SET_STATE, 1])
        + bytes([ME_ROUND_TRIP, 2, 0, 0])
        + me_events(3)
        + bytes([ME_ENTER_EVENT, ME_ROUND_TRIP, 0, 0, 3])
        + bytes([FREE_STATE, 0, FREE_STATE, 1])
    )
    return (
        me_start(interface, init, 1.5, stop_time=100.0)
        + body
        + bytes([RESET])
        + me_start(interface, init, -3.0, cycle=0.01)[2:]
        + body
    )


# setupExperiment (FMI 3.0: fmi3EnterInitializationMode at once) and initialization again
SETUP_AGAIN = bytes([SETUP, 4]) + real(0.0) * 3 + bytes([ENTER])
# What initialization mode refuses: the above, steps, terminate, the Model Exchange functions.
WRONG_WHILE_INITIALIZING = (
    SETUP_AGAIN
    + bytes([DO_STEP, 0, 0, 0, SIMPLE_STEP, 0, TERMINATE, ME_ENTER_EVENT, ME_SET_TIME, 0])
    + bytes([ME_NEW_DISCRETE_STATES, 0, ME_ENTER_CONTINUOUS, ME_COMPLETED_INTEGRATOR_STEP, 0])
)


def me_misuse(interface):
    """Model Exchange calls in the wrong mode and with wrong arguments, co-simulation calls on
    a Model Exchange instance."""
    how = MODEL_EXCHANGE | interface.flag
    return (
        bytes([0, how, ME_ENTER_EVENT, ME_SET_TIME, 0, ME_NEW_DISCRETE_STATES, 0])
        + bytes([ME_NO_STATES, 4, ME_NO_STATES, 0x08 | 1])
        + me_start(interface, initializing=WRONG_WHILE_INITIALIZING)[2:]
        + bytes([ME_NEW_DISCRETE_STATES, 1])  # eventInfo NULL (in continuous-time mode)
        + SETUP_AGAIN
        + bytes([ME_ENTER_EVENT])
        + SETUP_AGAIN
        + bytes([ME_NEW_DISCRETE_STATES, 1, ME_ENTER_CONTINUOUS])
        + bytes([ME_COMPLETED_INTEGRATOR_STEP, 3])  # both out-pointers NULL
        + bytes([ME_SET_TIME, 4, 0x7F])  # back by twice the tolerance
        + bytes([ME_SET_TIME, 7])
        + real(float("nan"))
        + bytes([ME_SET_TIME, 8, 0xFE])  # two cycles back
        + bytes([ME_NO_STATES, 0x08 | 0, ME_NO_STATES, 0x20 | 2, ME_NO_STATES, 0x80 | 0x08 | 3])
        + interface.set_as(interface.integer_type, [(NO_VARIABLE, 1)])
        + bytes([SIMPLE_STEP, 0, DO_STEP, 0, 0, 0])
        + bytes([MISC, 0, 0, 0, 3, MISC, 0, 1, 0, 5, ME_NULL_COMPONENT, 1, ME_NULL_COMPONENT, 4])
        + me_events(2)
        + bytes([TERMINATE, ME_ENTER_EVENT, ME_SET_TIME, 0, RESET])
    )


def me_on_co_simulation(interface):
    """The Model Exchange functions on a co-simulation instance: all refused."""
    return (
        start(interface)
        + bytes([SIMPLE_STEP, 0, ME_ENTER_EVENT, ME_NEW_DISCRETE_STATES, 0])
        + bytes([ME_ENTER_CONTINUOUS, ME_COMPLETED_INTEGRATOR_STEP, 0, ME_SET_TIME, 0])
        + bytes([ME_NO_STATES, 0, ME_NO_STATES, 1, ME_EVENT, 0, ME_ROUND_TRIP, 0, 0, 0])
        + bytes([SIMPLE_STEP, 1, TERMINATE])
    )


def misuse2(interface):
    """FMI 2.0: a wrong GUID (refused, then the correct instantiation), calls in the wrong
    state, bad values, a wrong t and h, foreign bytes, the functions an importer rarely calls,
    a NULL instance, a failing allocation."""
    cycle = interface.cycle.name
    return (
        bytes([0x0A, 0, 0])
        + bytes([DO_STEP, 0, 0, 0, SIMPLE_STEP, 0, EXIT, TERMINATE])
        + interface.set((cycle, float("nan")))
        + interface.set((cycle, 0.0))
        + interface.set_as("Real", [(NO_VARIABLE, 1.0)])
        + bytes([SETUP, 0])
        + real(0.0)
        + real(float("nan"))  # startTime NaN
        + real(0.0)
        + bytes([ENTER])
        + interface.set_as("Real", [(interface.first_input().vr, float("inf"))])  # any type
        + bytes([EXIT])
        + interface.set((cycle, 0.2))
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
        + bytes([4, MISC, 0, 0, 0, 1, 0, 2, 0, 13, 0, NULL_COMPONENT, 5, FAIL_ALLOCATION, 0])
        + bytes([GET_STATE, 0, RESET, TERMINATE])
    )


def misuse3(interface):
    """FMI 3.0: a wrong token (refused, then the correct instantiation), calls in the wrong
    mode, the experiment's times refused, nValues against nvr, the types without variables,
    the time, the functions the FMU refuses, NULL out-pointers and instances."""
    cycle = interface.cycle.name
    refs = vr(interface.cycle.vr) + vr(interface.first_input().vr)
    misc = [
        [0, 1, 0],  # fmi3GetVersion
        [0, 1, 2, 0x00],  # Int8 get, nvr 1
        [0, 1, 2, 0x86],  # Binary set, nvr 1
        [0, 1, 1, 3],  # fmi3GetDirectionalDerivative
        [0, 1, 1, 0],  # fmi3EnterStepMode
        [0, 1, 3, 5],  # fmi3DoStep, NULL pointers
        [0, 1, 8],  # time and cycleTime
        [0, 1, 9, *real(1.0)],  # set the time
        [0, 1, 12, 0, 0],  # nValues, a get
        [0, 0, 11],  # Scheduled Execution
        [1, 0, 5],  # a count, NULL
    ]
    return (
        bytes([10, FMI3, 3])
        + bytes([DO_STEP, 0, 0, 0, SIMPLE_STEP, 0, EXIT, TERMINATE])
        + interface.set((cycle, float("nan")))
        + bytes([SETUP, 4])
        + real(0.0)
        + real(float("nan"))  # startTime NaN, at once
        + real(0.0)
        + bytes([SETUP, 0])
        + real(0.0) * 3
        + bytes([ENTER])
        + interface.set((cycle, 0.2))
        + bytes([EXIT])
        + bytes([GET, KINDS_FMI3["Float64"], 0x38])  # nValues 2 for nvr 1
        + vr(interface.cycle.vr)
        + b"".join(bytes([MISC]) + refs + bytes(m) for m in misc)
        + interface.get("time", cycle)
        + steps(2)
        + bytes([NULL_COMPONENT, 5, NULL_COMPONENT, 19, ME_NULL_COMPONENT, 1])
        + bytes([ME_ENTER_EVENT, ME_SET_TIME, 0, ME_NEW_DISCRETE_STATES, 1 | (2 << 2)])
        + bytes([GET_STATE, 0, RESET, TERMINATE])
    )


def wrong_kinds(interface):
    """The first variable of each type set, and the first output of each type read, as every
    other type; a set of each type without values and with NULL arrays."""
    types = list(SETS_FMI3 if interface.fmi3 else SETS_FMI2)
    firsts = {}
    for v in interface.settable():
        firsts.setdefault(v.type, v)
    outputs = {}
    for v in interface.outputs():
        outputs.setdefault(v.type, v)
    out = b""
    for type_ in types:
        out += b"".join(
            interface.set_as(type_, [(v.vr, 1)]) for v in firsts.values() if v.type != type_
        )
        kind = (KINDS_FMI3 if interface.fmi3 else KINDS_FMI2)[type_]
        out += b"".join(
            bytes([GET, kind, 1]) + vr(v.vr) for v in outputs.values() if v.type != type_
        )
        out += interface.set_as(type_, [])  # no value: a no-op
        # NULL arrays: bit 7 of the count byte; 0x83 % (MAX_SET + 1) = 1 value
        out += interface.set_as(type_, [(interface.cycle.vr, 0)], count=0x83)
    return out


def encodings(interface):
    """The other ways fuzz_fmu.c reads a value and a value reference (any_real, any_int,
    pick_vr): special values by their index, a sixteenth of an INT; a variable by its index
    among those of its type or among all, the value reference just past a variable, one of the
    largest."""
    out = b""
    for real_, value_tags in (
        (True, [[0x01], [0x07], [0x2B], [0x3F], [0x41, 0x10, 0x00]]),
        (False, [[0x05], [0x13], [0x41, 0xF0, 0xFF]]),
    ):
        ours = [v for v in interface.settable() if v.real == real_ and not v.boolean]
        for v in ours[:1]:
            op = interface.set_as(v.type, [])[:-1]  # the operation and its type byte
            out += b"".join(op + bytes([1]) + vr(v.vr) + bytes(tag) for tag in value_tags)
    op = interface.set_as(interface.cycle.type, [])[:-1]
    for ref in ([0x00, 0], [0x90, 1], [0xC9, 0], [0xCA, 0]):
        out += op + bytes([1, *ref]) + real(0.1)
    return out


def misuse(interface):
    """The misuse of either version, then, while instantiated (after its reset) and again while
    stepping (fixed parameters refused whatever the value): every settable variable given its
    start value and its bad values, the types mixed up."""
    settable = [v for v in interface.settable() if "[" not in v.name or "[0]" in v.name]
    sets = b"".join(interface.set((v.name, x)) for v in settable for x in [*bad_values(v), v.start])
    sets += wrong_kinds(interface) + encodings(interface)
    bad = misuse3(interface) if interface.fmi3 else misuse2(interface)
    return (
        bad
        + sets
        + start(interface, initializing=WRONG_WHILE_INITIALIZING)[2:]
        + SETUP_AGAIN  # refused while stepping
        + bytes([EXIT])
        + sets
        + steps(2)
        + bytes([TERMINATE, SET_REAL])  # the input ends inside an operation: zeros follow
    )


# ------------------------------------------------------------------------------- the blocks ----


def blocks():
    """The blocks: the folders of src/blocks with an interface.toml (as CMakeLists.txt finds
    them)."""
    folder = os.path.join(ROOT, "src", "blocks")
    return sorted(
        name
        for name in os.listdir(folder)
        if os.path.isfile(os.path.join(folder, name, "interface.toml"))
    )


def block_seeds_module(block):
    """tests/blocks/<Block>/fuzz_seeds.py as the module tests.blocks.<Block>.fuzz_seeds, or None."""
    name = f"tests.blocks.{block}.fuzz_seeds"
    try:
        return importlib.import_module(name)
    except ModuleNotFoundError as error:
        if error.name != name:
            raise  # a module that fuzz_seeds.py imports is missing
        return None


RECIPES = ("walk", "states", "misuse", "me_run", "me_states", "me_misuse", "me_on_co_simulation")


def seeds_of(block):
    """Every seed of one block: name -> bytes."""
    module = block_seeds_module(block)
    scenarios = getattr(module, "SCENARIOS", {})
    taken = set(RECIPES) & set(scenarios)
    if taken:
        raise ValueError(f"{block}: the scenarios {sorted(taken)} take the names of recipes")
    init = items_of(next(iter(scenarios.values())))[0] if scenarios else ""
    seeds = {}
    for fmi3 in (False, True):
        interface = Interface(block, fmi3)
        prefix = "fmi3_" if fmi3 else ""
        script = getattr(module, "EVENTS", None)
        if script:
            me_init, *items = items_of(script)
            events = [assignments(interface, item) for item in items]
        else:
            me_init, events = init, [[pair] for pair in default_events(interface)]
        made = {
            "walk": walk(interface),
            **{name: scenario(interface, text) for name, text in scenarios.items()},
            "states": states(interface, init),
            "misuse": misuse(interface),
            "me_run": me_run(interface, me_init, events),
            "me_states": me_states(interface, init),
            "me_misuse": me_misuse(interface),
            "me_on_co_simulation": me_on_co_simulation(interface),
        }
        seeds.update({prefix + name: data for name, data in made.items()})
    return seeds


# Inputs of bugs found in the FMU, written here while they were open (in tests/fuzz/known/,
# tests/fuzz/README.md, "Open findings") and fixed since (README, "Findings"): kept byte for
# byte as they found them.
NVALUES_NO_VARIABLES = (
    bytes([0, FMI3]) + bytes([MISC]) + vr(0) + vr(1) + bytes([0, 0, 2, 0x40])
)  # fmi3GetInt8(inst, vr, 0, values, 1): any value reference, the bug was in nValues
TIME_NULL_VALUES = (
    bytes([0, FMI3])
    + bytes([SETUP, 0])
    + real(0.0) * 3
    + bytes([ENTER, GET, KINDS_FMI3["Float64"], 0x80 | 1, 0xC0])
)  # fmi3GetFloat64({time}, NULL)


def udint_beyond_integer(interface):
    """FMI 2.0, the signal generators: a forged state whose UDINT periode (payload bytes 52..55)
    is 2^31 (op_forge: one field of the block's data, 4 bytes, INT32_MIN's low word), set,
    then fmi2GetInteger(periode)."""
    return (
        start(interface, "cycleTime=0.01")
        + bytes([FORGE, 0, 5, 0x83, 3, 1, 0])
        + interface.get("periode")
    )


def regressions_of(block):
    """The regressions written here: name -> bytes."""
    found = {
        "fmi3-nvalues-no-variables": NVALUES_NO_VARIABLES,
        "fmi3-get-time-null-values": TIME_NULL_VALUES,
    }
    interface = Interface(block, False)
    periode = interface.variables.get("periode")
    if periode and Interface(block, True)["periode"].type == "UInt32":
        found["fmi2-udint-beyond-integer"] = udint_beyond_integer(interface)
    return found


def write(folder, inputs, only=False):
    """Writes the inputs into folder; `only`: and removes every other file there."""
    os.makedirs(folder, exist_ok=True)
    for name in os.listdir(folder) if only else []:
        if name not in inputs:
            os.remove(os.path.join(folder, name))
    for name, data in inputs.items():
        with open(os.path.join(folder, name), "wb") as f:
            f.write(data)


def main():
    for block in blocks():
        write(os.path.join(HERE, "corpus", block), seeds_of(block), only=True)
        write(os.path.join(HERE, "regressions", block), regressions_of(block))


if __name__ == "__main__":
    main()
