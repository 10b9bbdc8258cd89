"""A single-coil E04 characterized on its one side and twinned (issue 31 item 2: "for E04 the
actuator"): its spring return (``actuator_return_s``) fitted from the process-loop run."""

from __future__ import annotations

from dataclasses import replace

import pytest

from prm9tool.analysis.profile import DEFAULT
from prm9tool.catalogue import CATALOGUE
from prm9tool.characterize.rig import EmulatorRig
from prm9tool.characterize.run import characterize
from prm9tool.device.emulator import EmulatedValve
from prm9tool.device.emulator.constants import PLANT
from prm9tool.twin.fitvalve import twin_of_run
from prm9tool.twin.twinfile import read_twin

E04_A = "PRM9-06.2Z51/30-24E04S02"  # one coil (A): the spool opens one way, a spring returns
SLOWER_RETURN = replace(PLANT, actuator_return_s=1.5)  # the factory's 1 s


@pytest.mark.timeout(600)  # a whole default characterization and its process-loop fit
def test_a_single_coil_e04_is_characterized_and_its_spring_return_fitted(tmp_path):
    """Set up as a single-coil E04 is commissioned: 0…10 V setpoint and sensor (manual table
    8-4 for one coil), and a control monitor that lets the spring return the actuator (5 s,
    50 %: with the factory's 1 s the 90 % step's return to 0 trips it). Before, the
    characterization stopped at its first step reading the negative side's ramps (SDO abort
    0x6333/1)."""
    valve = EmulatedValve(E04_A, serial=5306, plant=SLOWER_RETURN)
    settings = {"AINSETP": 6, "SENSTYPE": 6, "MONDELAY": 5000, "MONTHRES": 8192}
    for mnemonic, raw in settings.items():
        valve.write(*CATALOGUE[mnemonic].key, raw)
    while valve.status().booting:
        valve.advance(0.05)
    run = characterize(EmulatorRig(valve), DEFAULT)
    assert run.loop == "process" and run.flow is not None and run.static is not None
    assert run.static.demand.min() == pytest.approx(0.0)  # the one side
    assert run.bode is not None and run.bode.centre_pct > 0.0
    twin = twin_of_run(run, tmp_path / "e04a.toml")
    spring = twin.fit.constant("actuator_return_s")
    assert spring.determined and spring.value == pytest.approx(1.5, rel=0.03), spring
    # the process steps are explained to 1.2 % rms only (docs/twin.md): the spring return
    # is found, what else differs is the valve's structure against the plant's, not kept
    assert twin.fit.rms_pct < twin.fit.start_rms_pct / 1.5
    assert read_twin(twin.path).plant.actuator_return_s == pytest.approx(1.5, rel=0.03)
