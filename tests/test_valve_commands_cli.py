"""``--restart``, ``--restore-factory``, ``--enable`` and ``--disable`` on the command line
(cli/valve_commands.py): what they print, ``--json OUT.json``, the backup named once."""

from __future__ import annotations

import json

from prm9tool.cli.main import main
from prm9tool.errors import ExitCode

E02 = "PRM9-06.3Z11/30-24E02S02"
E02_CA = f"{E02}-CA"


def test_restore_factory_names_the_backup_it_took_and_then_the_one_it_kept(capsys):
    args = ["--emulator", f"{E02}:7401", "--restore-factory", "--hydraulics-safe"]
    assert main(args) == ExitCode.OK
    out = capsys.readouterr().out.splitlines()
    assert out[0].startswith("factory values restored; the valve's previous parameters are in ")
    assert out[0].endswith(".prm")
    assert main(args) == ExitCode.OK
    again = capsys.readouterr().out.splitlines()
    assert again[0] == "factory values restored; the valve's backup from before is kept"
    assert again[1].startswith("device state ")  # a valve without CANopen waits for no master
    assert "waits for its CANopen master" not in again[1]


def test_the_json_of_a_valve_command_goes_to_the_file_it_names(capsys, tmp_path):
    target = tmp_path / "enabled.json"
    args = ["--emulator", f"{E02_CA}:7402", "--enable", "--hydraulics-safe", "--json", str(target)]
    assert main(args) == ExitCode.OK
    assert capsys.readouterr().out == ""
    report = json.loads(target.read_text(encoding="utf-8"))
    assert report["operation"] == "enable" and report["device"]["serial"] == 7402
    assert report["status"]["device_state"] == "DEVICE_MODE_ACTIVE"


def test_a_restart_of_a_ca_valve_says_it_waits_for_its_master(capsys):
    args = ["--emulator", f"{E02_CA}:7403", "--restart", "--hydraulics-safe"]
    assert main(args) == ExitCode.OK
    captured = capsys.readouterr()
    assert captured.err == (  # what is done, not the refusal's "only allowed with …"
        "prm9tool: --restart: restarting the valve (hydraulics confirmed safe): the spool "
        "returns to its spring-centred position and the setpoint is ignored for a few seconds …\n"
    )
    lines = captured.out.splitlines()
    assert lines[0].startswith("the valve restarted; it runs with its stored parameters (")
    assert lines[1] == (
        "device state INIT, NMT pre-operational: it waits for its CANopen master and does not "
        "follow its setpoint (--enable --hydraulics-safe enables it)"
    )


def test_disable_of_a_valve_without_canopen_is_refused_in_words(capsys):
    args = ["--emulator", f"{E02}:7404", "--disable", "--hydraulics-safe"]
    assert main(args) == ExitCode.USAGE
    err = capsys.readouterr().err
    assert err.startswith("prm9tool: --disable: this valve's CANopen is off")


def test_one_rule_for_the_exit_code_of_an_enable_that_fails():
    # issue 28: a refusal by the valve is not a communication error, alone or before a test
    from prm9tool.cli.enabling import NoControlWordError, exit_code_of
    from prm9tool.device.enabling import NotEnabledError
    from prm9tool.errors import AbortCode, DeviceTimeoutError, SdoAbortError

    assert exit_code_of(NotEnabledError("the valve stays in FAULT_HOLD")) == ExitCode.VERIFY_FAILED
    assert exit_code_of(SdoAbortError(0x6040, 0, AbortCode.GENERAL_ERROR)) == 1
    assert exit_code_of(NoControlWordError("CANopen off")) == ExitCode.USAGE
    assert exit_code_of(DeviceTimeoutError("no SDO answer for 0x6040/0")) == 6


def test_fit_twin_of_a_ca_valve_waiting_for_its_master_says_how_to_enable_it(capsys, tmp_path):
    """A -CA valve as delivered waits for its master: the refusal names --enable."""
    args = ["--fit-twin", str(tmp_path / "t.toml"), "--emulator", f"{E02_CA}:7405"]
    assert main(args) == ExitCode.OUT_OF_LIMITS
    err = capsys.readouterr().err
    assert "waits for its master to enable it); nothing was tested; add --enable " in err
    assert "--hydraulics-safe to enable it before the test" in err


def test_disable_over_can_before_a_heartbeat_does_not_say_nmt_unknown(capsys, tmp_path, data_dir):
    """A fresh session over CAN has heard no heartbeat yet (0x1017, 1 s): the NMT state is not
    known, and the line says so in words rather than "NMT unknown"."""
    from support.can_link_rig import make_link_rig

    rig = make_link_rig("disable-nmt", tmp_path)
    rig.valve.start()
    bus = ["--can-interface", "virtual", "--can-channel", rig.options.channel]
    try:
        assert main(["--device", "can:10", *bus, "--disable", "--hydraulics-safe"]) == 0
    finally:
        rig.valve.stop()
        rig.close()
    out = capsys.readouterr().out
    assert "NMT unknown" not in out
    assert out.startswith("device state INIT, NMT state not heard yet (it answers SDO: ")


def test_confirmed_enable_and_disable_say_what_they_do_not_the_warning(capsys):
    for flag, said in (
        ("--enable", "enabling the valve (hydraulics confirmed safe): it follows its setpoint"),
        ("--disable", "disabling the valve (hydraulics confirmed safe): the spool returns to "
         "its rest position"),
    ):  # fmt: skip
        assert main(["--emulator", f"{E02_CA}:7405", flag, "--hydraulics-safe"]) == ExitCode.OK
        assert capsys.readouterr().err == f"prm9tool: {flag}: {said} …\n"


def test_a_confirmed_factory_reset_says_what_it_does(capsys):
    args = ["--emulator", f"{E02}:7406", "--restore-factory", "--hydraulics-safe"]
    assert main(args) == ExitCode.OK
    err = capsys.readouterr().err
    assert err == (
        "prm9tool: --restore-factory: restoring the factory values (hydraulics confirmed safe), "
        "then restarting the valve: the spool returns to its spring-centred position and the "
        "setpoint is ignored for a few seconds …\n"
    )
    assert "only allowed with" not in err
