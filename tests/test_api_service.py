"""What a test-bench engineer met scripting against docs/api.md (issue 28, "Why"), each now
refused or reported in words by the valve service: wrong types, a read-only parameter, a
characterization under the script's own generator, a capture's own error inside a generator,
the status after the script's own NMT stop, the CAN libraries' raw log lines, DCF export."""

from __future__ import annotations

import logging

import pytest

import prm9tool
from prm9tool.cli.main import main
from prm9tool.errors import (
    AccessDeniedError,
    CommunicationError,
    DeviceTimeoutError,
    ValueRangeError,
)

KEY = "PRM9-06.3Z11/30-24E02S02-CA"


@pytest.fixture
def valve():
    with prm9tool.connect(f"emulator:{KEY}:4811", record_history=False) as opened:
        yield opened


def _spy_writes(valve, monkeypatch):
    sent: list[object] = []
    session = valve.session
    for name in ("write", "write_many"):
        real = getattr(session, name)
        monkeypatch.setattr(session, name, lambda *a, _real=real: (sent.append(a), _real(*a))[1])
    return sent


@pytest.mark.parametrize(
    ("value", "words"),
    [
        (True, "LIMTA: expected a number in mA, got True"),
        (None, "LIMTA: expected a number in mA, got None"),
        ("abc", "LIMTA: 'abc' is not a number"),
        ([1800], "LIMTA: expected a number in mA, got [1800]"),
    ],
)
def test_a_value_of_the_wrong_type_is_refused_in_words_before_anything_is_sent(
    valve, monkeypatch, value, words
):
    before = valve["LIMTA"]
    sent = _spy_writes(valve, monkeypatch)
    with pytest.raises(ValueRangeError) as refused:
        valve["LIMTA"] = value
    assert str(refused.value) == words
    assert sent == [] and valve["LIMTA"] == before


def test_a_value_typed_as_text_is_parsed_as_the_command_line_parses_it(valve):
    valve["LIMTA"] = "1700"
    assert valve["LIMTA"] == 1700
    valve["LIMTA"] = 1650.4  # rounded to the parameter's resolution (1 mA)
    assert valve["LIMTA"] == 1650


def test_a_read_only_parameter_is_refused_with_its_mnemonic_before_anything_is_sent(
    valve, monkeypatch
):
    sent = _spy_writes(valve, monkeypatch)
    with pytest.raises(AccessDeniedError, match=r"^CURNORM: the parameter is read-only$"):
        valve["CURNORM"] = valve["CURNORM"]
    assert sent == []


def test_a_capture_that_loses_the_link_inside_the_generator_raises_its_own_error(
    valve, monkeypatch
):
    generator = valve.generator("square", amplitude=10, period=0.5)

    def lost(*_args):
        raise DeviceTimeoutError("the valve sent no samples for 1.0 s (0 of 5000)")

    def cleanup_fails(*_args, **_kwargs):
        raise CommunicationError("no SDO answer for 0x1400/5")

    def script() -> None:  # what the script wrote
        with generator:
            monkeypatch.setattr(valve.session, "stream_start", lost)
            monkeypatch.setattr(generator._driver, "stop", cleanup_fails)
            valve.capture(["demand"], 1.0)

    with pytest.raises(DeviceTimeoutError, match="sent no samples") as caught:
        script()
    assert any("0x1400/5" in note for note in caught.value.__notes__)
    assert valve.service.motion.running is None  # the motion is free again


def test_characterize_refuses_while_the_scripts_own_generator_runs(valve):
    from prm9tool.service.motion import MotionBusyError

    with valve.generator("sine", amplitude=5, period=1.0):
        with pytest.raises(MotionBusyError, match="while the setpoint generator runs"):
            valve.characterize()
        with pytest.raises(MotionBusyError):  # a second generator neither
            valve.generator("square").start()


def test_export_dcf_writes_the_windows_dcf_in_the_api_and_on_the_command_line(
    valve, tmp_path, capsys
):
    valve["DYNFREQ"] = 125
    valve.store()
    assert valve.export_dcf(tmp_path / "api.dcf") == valve["NODEID"]
    valve.close()
    assert main(["--emulator", f"{KEY}:4811", "--export-dcf", str(tmp_path / "cli.dcf")]) == 0
    assert "DCF saved as" in capsys.readouterr().out

    def body(name):
        text = (tmp_path / name).read_text(encoding="ascii")
        return [line for line in text.splitlines() if not line.startswith(("Creation", "Modif"))]

    api, cli = body("api.dcf"), body("cli.dcf")
    assert api == cli and "[DeviceComissioning]" in api
    assert any(line.startswith("ParameterValue=") for line in api)


def test_export_dcf_of_a_valve_without_canopen_says_why(tmp_path, capsys):
    no_can = "PRM9-06.3Z11/30-24E02S02"
    assert main(["--emulator", f"{no_can}:4812", "--export-dcf", str(tmp_path / "x.dcf")]) == 2
    assert "--export-dcf:" in capsys.readouterr().err
    assert not (tmp_path / "x.dcf").exists()


def test_after_the_scripts_own_nmt_stop_status_says_so(tmp_path, request):
    from support.can_link_rig import E04, make_link_rig

    from prm9tool.device.canlink.status import StoppedNodeError

    rig = make_link_rig(request.node.name, tmp_path, E04)
    try:
        bus = {"can_interface": "virtual", "can_channel": rig.options.channel}
        with prm9tool.connect("can:10", record_history=False, **bus) as valve:
            valve.session._sdo.timeout_s = 0.3  # a stopped valve answers no SDO: not long
            valve.nmt("stop")
            # the session knows its own stop (issue 30 item 3): never "is the valve powered"
            with pytest.raises(StoppedNodeError) as caught:
                valve.status()
            text = str(caught.value)
            assert "NMT stopped (this tool stopped it)" in text
            assert "is the valve powered" not in text
            valve.nmt("start")
            valve.status()  # it answers again
    finally:
        rig.close()


def test_the_can_libraries_log_lines_reach_a_script_in_prm9tools_words(tmp_path, request, caplog):
    from support.can_link_rig import E04, make_link_rig

    rig = make_link_rig(request.node.name, tmp_path, E04)
    caplog.set_level(logging.WARNING)
    try:
        bus = {"can_interface": "virtual", "can_channel": rig.options.channel}
        with prm9tool.connect("can:10", record_history=False, **bus):
            logging.getLogger("canopen.sdo.client").warning(
                "Transfer aborted by client with code 0x%08X", 0x05040000
            )
    finally:
        rig.close()
    raw = [r for r in caplog.records if r.name.startswith("canopen")]
    ours = [r.getMessage() for r in caplog.records if r.name == "prm9tool.api"]
    assert raw == []
    assert any("prm9tool abandoned an SDO transfer" in text for text in ours)
    assert logging.getLogger("canopen").propagate  # given back once the valve is closed


def test_a_capture_names_its_units_and_tells_how_to_get_a_dataframe(valve):
    data = valve.capture(["demand", "current_a"], 0.01)
    assert isinstance(data, dict) and set(data) == {"demand", "current_a", "t"}
    assert data.units == {"demand": "%", "current_a": "mA", "t": "s"}
    try:
        import pandas  # noqa: F401
    except ImportError:
        with pytest.raises(ImportError, match=r"needs pandas \(pip install pandas\)"):
            data.to_dataframe()
    else:
        frame = data.to_dataframe()
        assert list(frame.columns) == ["demand [%]", "current_a [mA]"]
        assert len(frame) == len(data["t"])


def test_a_closed_valve_is_not_kept_alive_by_its_service():
    import gc
    import weakref

    valve = prm9tool.connect(f"emulator:{KEY}:4813", record_history=False)
    session = weakref.ref(valve.session)
    valve["LIMTA"] = 1800  # the service is made and used
    valve.close()
    del valve
    gc.collect()
    assert session() is None


def test_verify_by_restart_in_the_api_needs_the_hydraulics_off(valve, monkeypatch):
    sent = _spy_writes(valve, monkeypatch)
    with pytest.raises(AccessDeniedError, match="confirm_hydraulics_off=True"):
        valve.upload(valve.download(), backup=False, verify_by_restart=True)
    assert sent == []
