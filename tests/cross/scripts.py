"""The machinery of the runner scripts of tests/cross/scenario_runner.c: one fixed scenario per
block, each block's in its tests/blocks/<Block>/cross.py (`script(md) -> str`, built with Script).

The same script is run against the linux64 and the win64 binary of an FMU; the two printouts
must be identical. Each scenario makes a few hundred doStep calls of varying size, changes the
inputs so that every rule of the block is exercised (docs/behaviour.md §2-4), tries a few values the FMU
must refuse, and saves, restores and reserializes the FMU state. Names are resolved through the
FMU's modelDescription.xml, so the scripts follow the interface."""
from __future__ import annotations

import struct


def bits(value: float) -> str:
    return struct.pack(">d", float(value)).hex()


class Script:
    def __init__(self, model_description):
        self.md = model_description
        self.variables = {v.name: v for v in model_description.modelVariables}
        self.lines = [f"guid {model_description.guid}"]
        self.time = 0.0
        self.saved_time = None

    def set(self, values: dict):
        for name, value in values.items():
            v = self.variables[name]
            if v.type == "Real":
                self.lines.append(f"real {v.valueReference} {bits(value)}")
            elif v.type == "Integer":
                self.lines.append(f"int {v.valueReference} {int(value)}")
            else:
                self.lines.append(f"bool {v.valueReference} {1 if value else 0}")

    def start(self, name: str, start_time: float, values: dict):
        self.lines.append(f"instantiate {name}")
        for v in self.md.modelVariables:
            if v.causality == "output":
                self.lines.append(f"output {v.type[0].lower()} {v.valueReference} {v.name}")
        self.lines.append(f"setup {bits(start_time)}")
        self.lines.append("enter")
        self.set(values)
        self.lines.append("exit")
        self.time = start_time

    def run(self, steps: int, sizes: list[float], events: dict[int, dict | str] | None = None):
        """`steps` doSteps with the step sizes of `sizes` in turn; before step k the inputs of
        events[k] are set (or the FMU-state command events[k] is given)."""
        events = events or {}
        for k in range(steps):
            event = events.get(k)
            for command in (event if isinstance(event, list) else [event]):
                if isinstance(command, dict):
                    self.set(command)
                elif command == "save":
                    self.lines.append("save")
                    self.saved_time = self.time
                elif command in ("restore", "reserialize"):
                    if command == "reserialize":
                        self.lines.append("reserialize")
                    self.lines.append("restore")
                    self.time = self.saved_time
            h = sizes[k % len(sizes)]
            self.lines.append(f"step {bits(self.time)} {bits(h)}")
            self.time = self.time + h  # as the FMU computes its next communication point

    def finish(self):
        self.lines += ["terminate", "free"]

    def text(self) -> str:
        return "\n".join(self.lines) + "\n"

