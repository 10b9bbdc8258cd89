"""Dead-band offsets (OFFSETPOS/OFFSETNEG) and the E04 flow characteristic on the emulator."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from prm9tool.analysis.deadband import dead_band, gain_offset, gain_offset_inverse, offsets_for
from prm9tool.catalogue import CATALOGUE
from prm9tool.characterize.flow import flow_test
from prm9tool.characterize.procedures import static_test
from prm9tool.characterize.rig import EmulatorRig
from prm9tool.device.emulator import EmulatedValve
from prm9tool.device.emulator.constants import PLANT
from prm9tool.errors import Prm9Error

E02 = "PRM9-06.3Z11/30-24E02S02"
E04 = "PRM9-06.3Z11/30-24E04S02"
# a linearization flat within ±25 %: a dead band behind the gain/offset stage
DEAD_ZONE = {
    "SETPLINON": -1,
    "THRESETP": 0,
    **dict(zip([f"SETPLINX{c}" for c in "ABCDEFGHI"],
               [-16384, -12288, -8192, -4096, 0, 4096, 8192, 12288, 16384], strict=True)),
    **dict(zip([f"SETPLINY{c}" for c in "ABCDEFGHI"],
               [-16384, -10923, -5461, 0, 0, 0, 5461, 10923, 16384], strict=True)),
}  # fmt: skip


def rig_of(type_key: str, values: dict[str, int] | None = None, overlap: float = 0.0):
    valve = EmulatedValve(type_key, plant=dataclasses.replace(PLANT, spool_overlap=overlap))
    for mnemonic, raw in (values or {}).items():
        param = CATALOGUE[mnemonic]
        valve.write(param.index, param.subindex, raw)
    return EmulatorRig(valve)


def test_gain_offset_stage_is_the_firmwares_and_inverts():
    values = {"GAINSETPOS": 16384, "OFFSETPOS": 4096, "GAINSETNEG": 8192, "OFFSETNEG": 0}
    x = np.array([-16384.0, -100.0, 0.0, 100.0, 16384.0])
    out = gain_offset(x, values)
    assert out.tolist() == pytest.approx([-8192, -50, 0, 4096 + 75, 16384])
    assert gain_offset_inverse(out, values) == pytest.approx(x)


def test_offsets_from_the_static_characteristic_remove_the_dead_band():
    rig = rig_of(E02, DEAD_ZONE)
    before = static_test(rig, period_s=4.0)
    ch = before.record.channels
    band = dead_band(ch["setpoint_gain"] * 163.84, ch["position_actual"])
    offsets = offsets_for(band, rig.read(["OFFSETPOS", "OFFSETNEG"]))
    assert offsets["OFFSETPOS"] == pytest.approx(4096, rel=0.03)
    assert offsets["OFFSETNEG"] == pytest.approx(4096, rel=0.03)
    rig.write(offsets)
    after = static_test(rig, period_s=4.0)
    assert before.characteristic.dead_band_pct > 20.0
    assert after.characteristic.dead_band_pct <= 2.0
    assert after.characteristic.linearity_pct * 5.0 <= before.characteristic.linearity_pct


def test_e04_flow_characteristic_finds_the_overlap_and_the_gain():
    rig = rig_of(E04, overlap=0.1)  # 10 % of the stroke overlapped
    saved = rig.read(["PRCKI", "PRCKD", "OFFSETPOS", "OFFSETNEG", "THRESETP", "SETPOVRON"])
    result = flow_test(rig)
    flow = result.characteristic
    # the plant: full stroke (200 % of the sensor's range) in 0.5 s at 100 % opening
    assert flow.gain == pytest.approx(4.0, rel=0.05)
    assert flow.band.positive / 163.84 == pytest.approx(10.0, rel=0.05)
    assert flow.band.negative / 163.84 == pytest.approx(-10.0, rel=0.05)
    assert rig.read(list(saved)) == saved  # the valve is as it was
    # the deviation offsets: Kp (2.0) times the jump opens the spool to the overlap's edge
    assert result.offsets["OFFSETPOS"] == pytest.approx(819, rel=0.05)
    assert result.offsets["OFFSETNEG"] == pytest.approx(819, rel=0.05)


def remaining_error(rig: EmulatorRig) -> float:
    """Process setpoint step −30 → 30 % with the P-only loop: the deviation left at the end."""
    rig.write({"PRCKI": 0, "THRESETP": 0})
    rig.play(np.full(5000, -30.0), ["process_actual"])
    out = rig.play(np.full(5000, 30.0), ["process_actual"])
    rig.release()
    return 30.0 - float(out[-1, 0]) * 100.0 / 16384.0


def test_e04_offsets_take_the_overlap_out_of_the_process_loop():
    rig = rig_of(E04, overlap=0.1)
    before = remaining_error(rig)
    rig.write(flow_test(rig).offsets)
    after = remaining_error(rig)
    assert before == pytest.approx(5.0, abs=0.5)  # overlap 10 % / Kp 2
    assert abs(after) < 0.5


def test_without_overlap_nothing_is_proposed_and_e02_is_refused(qapp):
    result = flow_test(rig_of(E04))
    assert result.characteristic.dead_band_pct < 1.0
    assert all(v < 30 for v in result.offsets.values())
    with pytest.raises(Prm9Error, match="measured on E04 valves") as refused:
        flow_test(rig_of(E02))
    _check_german(refused.value)


def _check_german(error: Exception) -> None:
    """The refusal is a translatable message: a view shows it in the program language."""
    from prm9tool import i18n
    from prm9tool.translate import error_text

    try:
        i18n.set_language("de")
        assert error_text(error).startswith("die Durchflusskennlinie wird an E04-Ventilen")
    finally:
        i18n.set_language("en")


def test_end_of_line_on_e04_reports_the_flow_characteristic(tmp_path):
    from prm9tool.analysis.profile import parse_profile
    from prm9tool.characterize.run import characterize, report_data, write_csv_files

    profile = parse_profile(
        {"process": {"test": {"step_amplitudes_pct": [20], "step_duration_s": 1,
                              "bode_duration_s": 4, "bode_f_min_hz": 0.5, "bode_f_max_hz": 5,
                              "static_period_s": 20}},
         "limits": {"flow_dead_band_pct": {"max": 5}}}  # flow figures: the process loop's
    )  # fmt: skip
    result = characterize(rig_of(E04, overlap=0.1), profile)
    figures = {f.name: f for f in result.figures}
    assert figures["flow_gain"].value == pytest.approx(4.0, rel=0.05)
    assert figures["flow_dead_band_pct"].value == pytest.approx(20.0, rel=0.05)
    assert figures["flow_dead_band_pct"].passed is False  # the 10 % overlap is beyond 5 %
    assert result.steps[0].loop == "process"  # in control mode 4 the setpoint is the process's
    assert result.static is not None and result.static.response_key == "process_actual"
    files = write_csv_files(result, tmp_path / "e04")
    assert (tmp_path / "e04-flow.csv") in files
    assert report_data(result, files)["passed"] is False


def test_a_sweep_too_short_for_the_rate_says_what_it_needs():
    from prm9tool.characterize.procedures import bode_test

    with pytest.raises(ValueError, match=r"at least 256 samples; .* at least 0\.1 s"):
        bode_test(rig_of(E02), 10.0, 0.0, 1.0, 200.0, 0.04)


class _ManualOnlyRig(EmulatorRig):
    """As a -CA valve reached over CAN that has only the manual's objects: no process gains."""

    def read(self, mnemonics):
        return {k: v for k, v in super().read(mnemonics).items() if not k.startswith("PRCK")}


def test_a_valve_without_the_process_gains_skips_the_flow_test_and_says_why(qapp):
    from prm9tool.analysis.profile import Profile
    from prm9tool.characterize.flow import flow_objects_missing
    from prm9tool.characterize.run import characterize

    rig = rig_of(E04, {"CTRLMODE": 4})
    manual = _ManualOnlyRig(rig.valve)
    why = flow_objects_missing(manual)
    assert "PRCKP, PRCKI, PRCKD" in str(why)  # (a Message: the report translates it)
    assert flow_objects_missing(rig) == ""
    with pytest.raises(Prm9Error, match="no object for PRCKP"):  # not a KeyError
        flow_test(manual)
    short = dataclasses.replace(
        Profile(), step_amplitudes_pct=(), bode_f_max_hz=20.0, bode_duration_s=1.0,
        static_period_s=1.0,
    )  # fmt: skip
    profile = Profile(process=short)  # the process loop's part: an E04 in control mode 4
    result = characterize(manual, profile)
    assert result.flow is None
    assert why in result.notes
