"""What the hand-traced tests of the two blocks with a setpoint table share, LGF_RampCI
(docs/behaviour.md §4.6) and LGF_NonLinearInterpolation (§20.5): numberOfSetpoints, 2 ... 64,
refused outside with a message that names it. Each block's test file imports these tests, and
pytest runs them there, on the block of that file's `initializing` fixture (an instance in
initialization mode), with that file's test ids."""

import pytest
from fmpy.fmi2 import fmi2OK

from tests.harness import refused


@pytest.mark.parametrize("value", [1, 0, -1, 65])
def test_number_of_setpoints_outside_2_to_64_is_refused(initializing, value):
    s = initializing
    assert refused(s, s.fmu.setInteger, "numberOfSetpoints", value)
    assert "numberOfSetpoints" in s.log[-1][2]


@pytest.mark.parametrize("value", [2, 64])
def test_number_of_setpoints_at_the_limits_is_accepted(initializing, value):
    s = initializing
    assert s.status_of(s.fmu.setInteger, [s.vr("numberOfSetpoints")], [value]) == fmi2OK
