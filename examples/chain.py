"""Two FMUs chained: LGF_SawTooth -> LGF_LimRateOfChangeCI, as co-simulation with FMPy.

A co-simulation master in a few lines of FMPy's FMI 2.0 API: at each communication point it
reads the sawtooth's `value` (an INT, an fmi2Integer) and sets it as the rate limiter's `value`
(an LREAL, an fmi2Real), then steps both FMUs by one cycleTime. The second FMU sees the first
one's output one cycle later, like two blocks called in successive OB cycles.

Needs FMPy only (`pip install fmpy`). Run it from anywhere:

    python examples/chain.py            # in the unpacked release, lgf-fmus-<version>/
    python examples/chain.py FOLDER     # the FMI 2.0 FMUs of another folder

It takes the FMI 2.0 FMUs of the release's fmi2/ folder beside this one (or of the
repository's fmus/ after `make build`), and prints what examples/README.md shows.
"""

import sys
from pathlib import Path

from fmpy import extract, read_model_description
from fmpy.fmi2 import FMU2Slave

HERE = Path(__file__).resolve().parent
FOLDERS = [Path(a) for a in sys.argv[1:]] or [HERE.parent / "fmi2", HERE.parent / "fmus"]


def fmu(block):
    """The FMI 2.0 FMU of a block: the first of FOLDERS that holds it."""
    for folder in FOLDERS:
        if (folder / f"{block}.fmu").is_file():
            return str(folder / f"{block}.fmu")
    sys.exit(f"{block}.fmu is in none of {', '.join(map(str, FOLDERS))}")


# ---- the example of the documentation ("Two FMUs chained"), the FMUs' paths aside (the
# project's tests require the same code) ----


class CoSimFMU:
    """One FMU as co-simulation, with its variables by name."""

    def __init__(self, path, instance):
        md = read_model_description(path)
        self.vr = {v.name: v.valueReference for v in md.modelVariables}
        self.fmu = FMU2Slave(
            guid=md.guid,
            unzipDirectory=extract(path),
            modelIdentifier=md.coSimulation.modelIdentifier,
            instanceName=instance,
        )
        self.fmu.instantiate()
        self.fmu.setupExperiment(startTime=0.0)
        self.fmu.enterInitializationMode()


saw = CoSimFMU(fmu("LGF_SawTooth"), "saw")  # start values: 0, 10, ..., 50 every 0.5 s
lim = CoSimFMU(fmu("LGF_LimRateOfChangeCI"), "lim")
saw.fmu.exitInitializationMode()  # the sawtooth's first PLC call, at t = 0
# value is an INT, an fmi2Integer, in the sawtooth; an LREAL, an fmi2Real, in the rate limiter
[value] = saw.fmu.getInteger([saw.vr["value"]])
lim.fmu.setReal([lim.vr["value"], lim.vr["setChangeRate"]], [float(value), 15.0])
lim.fmu.exitInitializationMode()

h = 0.1  # = cycleTime of both: one PLC call per step
print("   t  sawtooth  limited")
for n in range(60):
    [value] = saw.fmu.getInteger([saw.vr["value"]])  # connect at communication point n·h
    lim.fmu.setReal([lim.vr["value"]], [float(value)])
    saw.fmu.doStep(currentCommunicationPoint=n * h, communicationStepSize=h)
    lim.fmu.doStep(currentCommunicationPoint=n * h, communicationStepSize=h)
    if (n + 1) % 5 == 0:
        [limited] = lim.fmu.getReal([lim.vr["delayedValue"]])
        [value] = saw.fmu.getInteger([saw.vr["value"]])
        print(f"{(n + 1) * h:4.1f}  {value:8d}  {limited:7.1f}")
for block in (saw, lim):
    block.fmu.terminate()
    block.fmu.freeInstance()
