"""A closed loop to start from: the tank's PLC program (Control.scl, program.toml, PLCTags.csv)
compiled into one FMU, the tank (Plant.scl) into another, both connected in TankLoop.ssp.

    python examples/tank/tank.py build   # TankControl.fmu, TankPlant.fmu, TankLoop.ssp in build/
    python examples/tank/tank.py run     # 60 s of the loop with FMPy, tank.png and the SSP's run

`build` needs the package lgf-fmus (in the repository: make package) and a C compiler;
`run` needs FMPy and matplotlib only. The connection is the same in the script and in the SSP:
at each communication point of 10 ms the controller's Valve goes to the plant's valve and the
plant's level to the controller's Level, then both FMUs step."""

from __future__ import annotations

import sys
import zipfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
BUILD = HERE / "build"
STEP = 0.01  # s: the communication step, the plant's cycleTime and the program's tick
STOP = 60.0

# the SSP's system structure (SSP 1.0): the two FMUs, their connections, the buttons as the
# system's inputs and the plant's cycleTime as a parameter of the system
SSD = """<?xml version="1.0" encoding="UTF-8"?>
<ssd:SystemStructureDescription version="1.0" name="TankLoop"
    xmlns:ssc="http://ssp-standard.org/SSP1/SystemStructureCommon"
    xmlns:ssd="http://ssp-standard.org/SSP1/SystemStructureDescription"
    xmlns:ssv="http://ssp-standard.org/SSP1/SystemStructureParameterValues">
  <ssd:System name="TankLoop">
    <ssd:Connectors>
      <ssd:Connector name="Start" kind="input"><ssc:Boolean/></ssd:Connector>
      <ssd:Connector name="Stop" kind="input"><ssc:Boolean/></ssd:Connector>
    </ssd:Connectors>
    <ssd:ParameterBindings>
      <ssd:ParameterBinding>
        <ssd:ParameterValues>
          <ssv:ParameterSet version="1.0" name="Tank">
            <ssv:Parameters>
              <ssv:Parameter name="plant.cycleTime"><ssv:Real value="0.01"/></ssv:Parameter>
            </ssv:Parameters>
          </ssv:ParameterSet>
        </ssd:ParameterValues>
      </ssd:ParameterBinding>
    </ssd:ParameterBindings>
    <ssd:Elements>
      <ssd:Component name="controller" source="resources/TankControl.fmu">
        <ssd:Connectors>
          <ssd:Connector name="Start" kind="input"><ssc:Boolean/></ssd:Connector>
          <ssd:Connector name="Stop" kind="input"><ssc:Boolean/></ssd:Connector>
          <ssd:Connector name="Level" kind="input"><ssc:Integer/></ssd:Connector>
          <ssd:Connector name="Valve" kind="output"><ssc:Boolean/></ssd:Connector>
          <ssd:Connector name="Alarm" kind="output"><ssc:Boolean/></ssd:Connector>
        </ssd:Connectors>
      </ssd:Component>
      <ssd:Component name="plant" source="resources/TankPlant.fmu">
        <ssd:Connectors>
          <ssd:Connector name="valve" kind="input"><ssc:Boolean/></ssd:Connector>
          <ssd:Connector name="level" kind="output"><ssc:Integer/></ssd:Connector>
        </ssd:Connectors>
      </ssd:Component>
    </ssd:Elements>
    <ssd:Connections>
      <ssd:Connection startConnector="Start" endElement="controller" endConnector="Start"/>
      <ssd:Connection startConnector="Stop" endElement="controller" endConnector="Stop"/>
      <ssd:Connection startElement="controller" startConnector="Valve"
                      endElement="plant" endConnector="valve"/>
      <ssd:Connection startElement="plant" startConnector="level"
                      endElement="controller" endConnector="Level"/>
    </ssd:Connections>
  </ssd:System>
  <ssd:DefaultExperiment startTime="0" stopTime="60"/>
</ssd:SystemStructureDescription>
"""


def build(folder: Path = BUILD) -> dict:
    """The two FMUs (FMI 2.0, which FMPy's SSP runner takes) and the SSP of the loop."""
    try:
        from lgf_fmus import scl
    except ImportError:
        sys.exit("tank.py build needs the package lgf-fmus: in the repository, make package")
    folder.mkdir(parents=True, exist_ok=True)
    control = scl.compile(
        [HERE / "Control.scl"],
        output=folder / "TankControl.fmu",
        program=HERE / "program.toml",
        tags=HERE / "PLCTags.csv",
    )
    plant = scl.compile([HERE / "Plant.scl"], block="TankPlant", output=folder / "TankPlant.fmu")
    ssp = folder / "TankLoop.ssp"
    with zipfile.ZipFile(ssp, "w", zipfile.ZIP_DEFLATED) as z:
        z.writestr("SystemStructure.ssd", SSD)
        z.write(control, "resources/TankControl.fmu")
        z.write(plant, "resources/TankPlant.fmu")
    return {"control": control, "plant": plant, "ssp": ssp}


class Fmu:
    """One FMU of the loop through FMPy's FMI 2.0 API, its variables by name."""

    def __init__(self, path: Path, start: dict):
        from fmpy import extract, read_model_description
        from fmpy.fmi2 import FMU2Slave

        self.md = read_model_description(path)
        self.vars = {v.name: v for v in self.md.modelVariables}
        self.fmu = FMU2Slave(
            guid=self.md.guid,
            unzipDirectory=extract(path),
            modelIdentifier=self.md.coSimulation.modelIdentifier,
            instanceName=path.stem,
        )
        self.fmu.instantiate()
        self.fmu.setupExperiment(startTime=0.0)
        self.fmu.enterInitializationMode()
        self.set(start)
        self.fmu.exitInitializationMode()

    def set(self, values: dict):
        for name, value in values.items():
            v = self.vars[name]
            if v.type == "Boolean":
                self.fmu.setBoolean([v.valueReference], [bool(value)])
            elif v.type == "Integer":
                self.fmu.setInteger([v.valueReference], [int(value)])
            else:
                self.fmu.setReal([v.valueReference], [float(value)])

    def get(self, name: str):
        v = self.vars[name]
        getter = {"Boolean": self.fmu.getBoolean, "Integer": self.fmu.getInteger}
        return getter.get(v.type, self.fmu.getReal)([v.valueReference])[0]


def run(fmus: dict, stop: float = STOP, settings: dict | None = None, buttons=None) -> dict:
    """The loop for `stop` s in steps of STEP: the time, level, valve, alarm and mode after each
    step. settings: start values of the controller (Settings.setpoint, ...); buttons(t): the
    Start and Stop buttons at t (default: Start pressed for the first second)."""
    buttons = buttons or (lambda t: {"Start": t < 1.0, "Stop": False})
    control = Fmu(fmus["control"], {**(settings or {}), **buttons(0.0)})
    plant = Fmu(fmus["plant"], {"cycleTime": STEP})
    out = {"time": [], "level": [], "valve": [], "alarm": [], "mode": []}
    for k in range(round(stop / STEP)):
        t = k * STEP
        # the connections, as the SSP's: outputs at t to inputs for the step from t
        control.set({"Level": plant.get("level"), **buttons(t)})
        plant.set({"valve": control.get("Valve")})
        control.fmu.doStep(currentCommunicationPoint=t, communicationStepSize=STEP)
        plant.fmu.doStep(currentCommunicationPoint=t, communicationStepSize=STEP)
        out["time"].append(round(t + STEP, 6))
        out["level"].append(plant.get("level"))
        out["valve"].append(bool(control.get("Valve")))
        out["alarm"].append(bool(control.get("Alarm")))
        out["mode"].append(control.get("Mode"))
    for f in (control, plant):
        f.fmu.terminate()
        f.fmu.freeInstance()
    return out


def run_ssp(ssp: Path, stop: float = STOP):
    """The same loop from TankLoop.ssp, with FMPy's SSP runner (its parameter set applied)."""
    from fmpy.ssp.simulation import simulate_ssp
    from fmpy.ssp.ssd import read_ssd

    parameters = read_ssd(str(ssp)).system.parameterBindings[0].parameterValues[0]
    return simulate_ssp(
        str(ssp),
        stop_time=stop,
        step_size=STEP,
        parameter_set=parameters,
        input={"Start": lambda t: t < 1.0, "Stop": lambda t: False},
    )


def plot(out: dict, path: Path):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (ax1, ax2) = plt.subplots(2, 1, sharex=True, figsize=(8, 5))
    ax1.plot(out["time"], out["level"], label="level")
    ax1.set_ylabel("level / mm")
    ax1.grid(True)
    ax2.step(out["time"], out["valve"], where="post", label="valve")
    ax2.step(out["time"], out["alarm"], where="post", label="alarm")
    ax2.set_ylabel("on")
    ax2.set_xlabel("time / s")
    ax2.legend()
    fig.tight_layout()
    fig.savefig(path)


def main(argv: list[str]) -> int:
    if argv[:1] == ["build"]:
        for name, path in build().items():
            print(f"{name}: {path}")
        return 0
    if argv[:1] == ["run"]:
        fmus = {"control": BUILD / "TankControl.fmu", "plant": BUILD / "TankPlant.fmu"}
        out = run(fmus)
        plot(out, BUILD / "tank.png")
        valve = out["valve"]
        closing = next(out["time"][i] for i in range(1, len(valve)) if valve[i - 1] > valve[i])
        print(f"the valve first closes at {closing:.2f} s, level {max(out['level'][:1400])} mm")
        print(f"the level after 30 s: {min(out['level'][3000:])} ... {max(out['level'][3000:])} mm")
        print(f"plot: {BUILD / 'tank.png'}")
        ssp = run_ssp(BUILD / "TankLoop.ssp")
        print(f"the SSP's run, level at 60 s: {ssp['plant.level'][-1]} mm")
        return 0
    print(__doc__)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
