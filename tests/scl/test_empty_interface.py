"""An FB with no inputs, no outputs and no parameters of its own (only cycleTime) still makes an
FMU that FMI importers load, in FMI 2.0 and 3.0. The FMI 2.0 schema requires at least one
Unknown in <Outputs> and <InitialUnknowns>, so such a description must leave both elements out
(FMPy refuses an empty one); its statics stay visible as locals."""

from __future__ import annotations

import xml.etree.ElementTree as ET
import zipfile

import pytest
from fmpy import simulate_fmu
from fmpy.validation import validate_fmu

from lgf_fmus import scl
from tests.scl.driver import Instance

SOURCE = """
FUNCTION_BLOCK "Counter"
   VAR
      count : Int;
   END_VAR
BEGIN
    #count := #count + 1;
END_FUNCTION_BLOCK
"""


@pytest.fixture(scope="module", params=[2, 3])
def fmu(request, tmp_path_factory):
    folder = tmp_path_factory.mktemp(f"empty{request.param}")
    source = folder / "Counter.scl"
    source.write_text(SOURCE)
    return scl.compile([source], block="Counter", fmi=request.param, output=folder / "Counter.fmu")


def test_the_description_has_no_empty_structure_elements(fmu):
    root = ET.fromstring(zipfile.ZipFile(fmu).read("modelDescription.xml"))
    structure = root.find("ModelStructure")
    assert structure is not None
    for element in structure:
        assert len(element) > 0 or element.attrib, f"empty <{element.tag}>"
    assert [v.get("name") for v in root.iter() if v.get("causality") == "output"] == []


def test_fmpy_validates_and_simulates_it(fmu):
    assert validate_fmu(str(fmu)) == []
    result = simulate_fmu(str(fmu), stop_time=1.0, output_interval=0.1)
    assert len(result) == 11


def test_its_static_counts_the_calls(fmu):
    # call 0 in exitInitializationMode, then one call per 100 ms step
    s = Instance(fmu, {"cycleTime": 0.1}, {})
    counts = [s.get(["count"])["count"]]
    for k in range(5):
        s.fmu.doStep(currentCommunicationPoint=k * 0.1, communicationStepSize=0.1)
        counts.append(s.get(["count"])["count"])
    s.free()
    assert counts == [1, 2, 3, 4, 5, 6]
