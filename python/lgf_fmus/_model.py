"""The FMUs bundled with the package and what their modelDescription.xml says: the block list,
fmu_path, the variables and the checks of names and values that every entry point makes before
anything runs."""

from __future__ import annotations

import difflib
import functools
import math
import re
import xml.etree.ElementTree as ET
import zipfile
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

FMU_DIR = Path(__file__).resolve().parent / "fmus"


class LgfValueError(ValueError):
    """A name or a value that the FMU would not take: raised before anything runs, naming the
    variable and what it allows."""


class SimulationError(RuntimeError):
    """A run that the FMU refused (the message is the FMU's)."""


@functools.cache
def _bundled() -> dict[tuple[str, int], Path]:
    """(block, major FMI version) -> FMU, from every .fmu under the package's fmus/ folder; the
    FMI version and the block's name (the co-simulation modelIdentifier) are read from each
    FMU's modelDescription.xml, so the file names and folders do not matter."""
    found: dict[tuple[str, int], Path] = {}
    for path in sorted(FMU_DIR.rglob("*.fmu")):
        with zipfile.ZipFile(path) as archive:
            root = ET.fromstring(archive.read("modelDescription.xml"))
        version = int(root.get("fmiVersion", "0").split(".")[0])
        cs = root.find("CoSimulation")
        name = cs.get("modelIdentifier") if cs is not None else root.get("modelName")
        found[(name, version)] = path
    return found


def blocks(fmi_version: int | None = None) -> list[str]:
    """The blocks whose FMUs are bundled (with `fmi_version`, only those built for it)."""
    return sorted(
        {name for name, version in _bundled() if fmi_version is None or version == fmi_version}
    )


def fmi_versions(block: str) -> list[int]:
    """The FMI versions the block's FMU is bundled for."""
    return sorted(version for name, version in _bundled() if name == block)


def fmu_path(block: str, fmi_version: int = 2) -> Path:
    """The bundled FMU of a block, e.g. fmu_path("LGF_RampCI") or fmu_path("LGF_RampCI", 3)."""
    path = _bundled().get((block, int(fmi_version)))
    if path is not None:
        return path
    names = blocks()
    if block not in names:
        raise LgfValueError(
            f"no block {block!r}{_did_you_mean(block, names)}; the bundled "
            f"blocks are {', '.join(names) or 'none'}"
        )
    raise LgfValueError(
        f"{block} has no FMI {fmi_version}.0 FMU in this package; it is bundled "
        f"for FMI {', '.join(f'{v}.0' for v in fmi_versions(block))}"
    )


def _did_you_mean(name: str, candidates) -> str:
    close = difflib.get_close_matches(name, list(candidates), n=3)
    return f" (did you mean {' or '.join(close)}?)" if close else ""


# ---- variables -----------------------------------------------------------------------------

TYPES = ("Real", "Integer", "Boolean")
INT32 = (-(2**31), 2**31 - 1)
# FMI 3.0's types as the kind of FMI 2.0 that holds their values (list --variables of an FMI
# 3.0 FMU; simulate and sweep run FMI 2.0 FMUs only)
FMI3_KINDS = {
    "Float64": "Real",
    "Float32": "Real",
    **{t: "Integer" for t in ("Int8", "UInt8", "Int16", "UInt16", "Int32", "UInt32")},
}
# their own range, where the variable states no min or max
FMI3_RANGES = {
    "Int8": (-128, 127),
    "UInt8": (0, 255),
    "Int16": (-32768, 32767),
    "UInt16": (0, 65535),
    "Int32": INT32,
    "UInt32": (0, 2**32 - 1),
}


@dataclass(frozen=True)
class Variable:
    name: str
    vr: int
    type: str  # Real, Integer, Boolean
    causality: str
    variability: str
    initial: str | None
    start: object
    min: float | None
    max: float | None
    unit: str | None
    description: str

    @property
    def type_code(self) -> int:
        return TYPES.index(self.type)

    def allowed(self) -> str:
        """What the variable takes, in words."""
        if self.type == "Boolean":
            return "a Boolean (true/false or 1/0)"
        low = self.min if self.min is not None else (INT32[0] if self.type == "Integer" else None)
        high = self.max if self.max is not None else (INT32[1] if self.type == "Integer" else None)
        kind = "an integer" if self.type == "Integer" else "a number (not NaN)"
        unit = f" {self.unit}" if self.unit else ""
        if low is None and high is None:
            return kind
        return f"{kind} in [{_g(low, '-inf')}, {_g(high, 'inf')}]{unit}"


def _g(value, unbounded: str) -> str:
    if value is None:
        return unbounded
    return f"{value:.10g}" if isinstance(value, float) else str(value)


# FMPy's rules (fmpy.simulation.settable_in_instantiated / settable_in_initialization_mode):
# which start values it sets before fmi2EnterInitializationMode and which in it.
def settable_after_instantiation(v: Variable) -> bool:
    return v.causality == "input" or (
        v.variability != "constant" and v.initial in ("approx", "exact")
    )


def settable_in_initialization(v: Variable) -> bool:
    return (
        v.causality == "input"
        or (v.causality != "parameter" and v.variability == "tunable")
        or (v.variability != "constant" and v.initial == "exact")
    )


@dataclass
class Model:
    """One FMU: its modelDescription, its variables and its setpoint-like tables."""

    path: Path
    fmi_version: int
    identifier: str
    guid: str
    variables: dict[str, Variable]
    start_time: float | None
    stop_time: float | None
    step_size: float | None
    tolerance: float | None
    can_handle_variable_step_size: bool
    tables: dict[str, "Table"] = field(default_factory=dict)

    @property
    def block(self) -> str:
        return self.identifier

    def names(self, causality: str) -> list[str]:
        return [v.name for v in self.variables.values() if v.causality == causality]

    @property
    def inputs(self) -> list[str]:
        return self.names("input")

    @property
    def outputs(self) -> list[str]:
        return self.names("output")

    @property
    def parameters(self) -> list[str]:
        return self.names("parameter")

    def variable(self, name: str, what: str = "variable") -> Variable:
        try:
            return self.variables[name]
        except KeyError:
            plain = [n for n in self.variables if "[" not in n]
            arrays = sorted({re.sub(r"\[\d+\]", "[i]", n) for n in self.variables if "[" in n})
            raise LgfValueError(
                f"{self.identifier} has no {what} {name!r}{_did_you_mean(name, self.variables)}; "
                f"its variables are {', '.join(plain + arrays)}"
            ) from None

    def _of_kind(self, name: str, what: str, accepts, listing: str) -> Variable:
        v = self.variable(name, what)
        if not accepts(v):
            raise LgfValueError(
                f"{self.identifier}.{name} is {_article(v.causality)} "
                f"({v.variability}), not {_article(what)}; {listing}"
            )
        return v

    def settable(self, name: str) -> Variable:
        """A variable that may take a start value (a parameter or an input)."""
        return self._of_kind(
            name,
            "parameter or input",
            lambda v: (
                v.causality in ("parameter", "input")
                and (settable_after_instantiation(v) or settable_in_initialization(v))
            ),
            f"the parameters are {', '.join(self.parameters_shown())} and the inputs "
            f"{', '.join(self.inputs)}",
        )

    def input(self, name: str) -> Variable:
        """A variable that may be driven by a table over time: an input or a tunable parameter."""
        return self._of_kind(
            name,
            "input",
            lambda v: (
                v.causality == "input"
                or (v.variability == "tunable" and v.causality == "parameter")
            ),
            f"the inputs are {', '.join(self.inputs)}",
        )

    def output(self, name: str) -> Variable:
        return self._of_kind(
            name,
            "output",
            lambda v: v.causality == "output",
            f"the outputs are {', '.join(self.outputs)}",
        )

    def parameters_shown(self) -> list[str]:
        shown = []
        for n in self.parameters:
            generic = re.sub(r"\[\d+\]", "[i]", n)
            if generic not in shown:
                shown.append(generic)
        return shown

    def cycle_time(self, parameters: dict) -> float | None:
        if "cycleTime" in parameters:
            return float(parameters["cycleTime"])
        v = self.variables.get("cycleTime")
        return float(v.start) if v is not None and v.start is not None else None


def _article(word: str) -> str:
    return ("an " if word[:1] in "aeiou" else "a ") + word


@dataclass(frozen=True)
class Table:
    """An array of records in the FMU (LGF_RampCI: setpoints[i].outputValue, setpoints[i].time)
    with the parameter that counts its rows (numberOfSetpoints)."""

    name: str
    fields: tuple[str, ...]
    size: int
    count: str | None


def _tables(variables: dict[str, Variable]) -> dict[str, Table]:
    records: dict[str, dict] = {}
    for name in variables:
        m = re.fullmatch(r"(\w+)\[(\d+)\]\.(\w+)", name)
        if m:
            base, index, field_name = m.group(1), int(m.group(2)), m.group(3)
            entry = records.setdefault(base, {"fields": [], "size": 0})
            if field_name not in entry["fields"]:
                entry["fields"].append(field_name)
            entry["size"] = max(entry["size"], index + 1)
    tables = {}
    for base, entry in records.items():
        count = "numberOf" + base[:1].upper() + base[1:]
        tables[base] = Table(
            base, tuple(entry["fields"]), entry["size"], count if count in variables else None
        )
    return tables


def _float(text):
    return None if text is None else float(text)


def file_key(path: Path) -> tuple[str, int, int]:
    """What the caches of an FMU are keyed by: its path, modification time and size, so that
    an FMU rebuilt at the same path (an SCL block compiled again) is read and loaded again."""
    stat = path.stat()
    return str(path), stat.st_mtime_ns, stat.st_size


# bounded: an FMU compiled again and again at one path adds an entry each time
def _or(value, default):
    return default if value is None else value


@functools.lru_cache(maxsize=256)
def _read(path: Path, key: tuple[str, int, int]) -> Model:
    from fmpy import read_model_description

    md = read_model_description(str(path))
    variables = {}
    for sv in md.modelVariables:
        kind = FMI3_KINDS.get(sv.type, sv.type)
        if kind not in TYPES:
            continue
        start = sv.start
        if start is not None:
            if kind == "Real":
                start = float(start)
            elif kind == "Integer":
                start = int(start)
            else:
                start = start in ("true", "1", True)
        variables[sv.name] = Variable(
            name=sv.name,
            vr=sv.valueReference,
            type=kind,
            causality=sv.causality,
            variability=sv.variability,
            initial=sv.initial,
            start=start,
            min=_float(_or(getattr(sv, "min", None), FMI3_RANGES.get(sv.type, (None,))[0])),
            max=_float(_or(getattr(sv, "max", None), FMI3_RANGES.get(sv.type, (None, None))[1])),
            unit=getattr(sv, "unit", None),
            description=sv.description or "",
        )
    experiment = md.defaultExperiment
    cs = md.coSimulation
    if cs is None:
        raise LgfValueError(f"{path} has no co-simulation interface")
    return Model(
        path=path,
        fmi_version=int(md.fmiVersion.split(".")[0]),
        identifier=cs.modelIdentifier,
        guid=md.guid,
        variables=variables,
        start_time=_float(experiment.startTime) if experiment else None,
        stop_time=_float(experiment.stopTime) if experiment else None,
        step_size=_float(experiment.stepSize) if experiment else None,
        tolerance=_float(experiment.tolerance) if experiment else None,
        can_handle_variable_step_size=bool(cs.canHandleVariableCommunicationStepSize),
        tables=_tables(variables),
    )


def model(block, fmi_version: int = 2) -> Model:
    """The Model of a bundled block, or of an FMU file given by its path."""
    path = Path(block) if str(block).endswith(".fmu") else fmu_path(block, fmi_version)
    if not path.is_file():
        raise LgfValueError(f"no FMU at {path}")
    path = path.resolve()
    return _read(path, file_key(path))


# ---- values --------------------------------------------------------------------------------


def _bool_of(value, v: Variable, where: str):
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    if isinstance(value, str) and value.strip().lower() in ("true", "false", "1", "0"):
        return value.strip().lower() in ("true", "1")
    if (
        isinstance(value, (int, float, np.integer, np.floating))
        and not isinstance(value, bool)
        and value in (0, 1)
    ):
        return bool(value)
    raise LgfValueError(f"{where}{v.name} = {value!r} is not allowed: {v.name} takes {v.allowed()}")


def check_value(v: Variable, value, where: str = ""):
    """The value converted to the variable's Python type, or LgfValueError naming the variable
    and what it allows (never a silent conversion: 2.5 for an Integer is refused)."""
    if v.type == "Boolean":
        return _bool_of(value, v, where)
    if isinstance(value, str):
        try:
            value = float(value)
        except ValueError:
            raise LgfValueError(
                f"{where}{v.name} = {value!r} is not allowed: {v.name} takes {v.allowed()}"
            ) from None
    if isinstance(value, (bool, np.bool_)) or not isinstance(
        value, (int, float, np.integer, np.floating)
    ):
        raise LgfValueError(
            f"{where}{v.name} = {value!r} is not allowed: {v.name} takes {v.allowed()}"
        )
    if v.type == "Integer":
        if isinstance(value, (float, np.floating)) and not (
            math.isfinite(value) and value == int(value)
        ):
            raise LgfValueError(
                f"{where}{v.name} = {value!r} is not allowed: {v.name} takes "
                f"{v.allowed()} (a fractional value is refused, not truncated)"
            )
        value = int(value)
        low = v.min if v.min is not None else INT32[0]
        high = v.max if v.max is not None else INT32[1]
    else:
        value = float(value)
        if math.isnan(value):
            raise LgfValueError(
                f"{where}{v.name} = nan is not allowed: {v.name} takes {v.allowed()}"
            )
        low, high = v.min, v.max
    if (low is not None and value < low) or (high is not None and value > high):
        raise LgfValueError(
            f"{where}{v.name} = {value!r} is out of range: {v.name} takes {v.allowed()}"
        )
    return value


def check_array(v: Variable, values, where=lambda i: "") -> np.ndarray:
    """check_value for many values at once (a sweep's column): the values as float64, or
    LgfValueError for the first bad one, naming where it is."""
    array = np.asarray(values)
    if array.dtype.kind in "biuf" and array.ndim == 1:
        numbers = array.astype(np.float64)
        if v.type == "Boolean":
            bad = ~np.isin(numbers, (0.0, 1.0))
        elif v.type == "Integer":
            low = v.min if v.min is not None else INT32[0]
            high = v.max if v.max is not None else INT32[1]
            with np.errstate(invalid="ignore"):
                bad = (
                    ~np.isfinite(numbers)
                    | (numbers != np.round(numbers))
                    | (numbers < low)
                    | (numbers > high)
                )
        else:
            bad = np.isnan(numbers)
            if v.min is not None:
                bad |= numbers < v.min
            if v.max is not None:
                bad |= numbers > v.max
        if bad.any():
            i = int(np.flatnonzero(bad)[0])
            check_value(v, array[i].item(), where(i))  # raises with the message
        return numbers
    return np.array(
        [float(check_value(v, x, where(i))) for i, x in enumerate(array.tolist())], dtype=np.float64
    )
