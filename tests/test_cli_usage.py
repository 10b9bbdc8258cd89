"""The command line's option rules that argparse cannot express (cli/usage.py), each with the
words a user sees, and those argparse now says itself (issue 28: the hand checks that an
exclusive group can say are argparse's)."""

from __future__ import annotations

import pytest

from prm9tool.cli.main import main
from prm9tool.cli.parser import SHORT_USAGE
from prm9tool.errors import ExitCode

E02 = "PRM9-06.3Z11/30-24E02S02"
E02_CA = f"{E02}-CA"
EMU = ["--emulator", E02_CA]
CAN = ["--can-interface", "virtual", "--can-channel", "usage"]

KEPT = [
    # an option that modifies a command of another group (argparse has no "requires")
    (["--apply", *EMU], "--apply belongs to --autotune (it applies the proposed gains)"),
    (["--characterize", "--apply", *EMU, "--json", "x.json"],
     "--apply belongs to --autotune (it applies the proposed gains)"),
    (["--hydraulics-safe", *EMU], "--hydraulics-safe answers the hydraulics question of "
     "--enable, --disable, --restart or --restore-factory"),
    (["--characterize", "--hydraulics-safe", *EMU, "--json", "x.json"],
     "--hydraulics-safe confirms --enable: add --enable, or leave it out"),
    (["--fit-twin", "t.toml", "--hydraulics-safe", *EMU],
     "--hydraulics-safe confirms --enable: add --enable, or leave it out"),
    (["--profile", "p.toml", *EMU], "--profile belongs to --characterize or --autotune"),
    (["--od", "manual"], "--od chooses the object dictionary of --emulator or --serve-emulator"),
    (["--store", *EMU], "--store belongs to --set (it stores the values --set writes)"),
    (["--node-id", "5", *EMU], "--node-id belongs to --serve-emulator"),
    (["--from", "run.json"], "--from RUN.json belongs to --fit-twin OUT.toml"),
    (["--download", "x.prm"], "--download belongs to the headless production mode: use it "
     "with --batch"),
    (["--history-unreachable", "queue", "--diff", "a.prm", "b.prm"],
     "--history-unreachable belongs to the headless production mode (--batch)"),
    (["--json", *EMU], "--json [OUT.json] belongs to --diff, --history, --get/--set"),
    (["--enable", "--restart", *EMU, "--hydraulics-safe"],
     "--restart and --enable are separate commands: use one at a time"),
    # two commands of different groups (an exclusive group holds options of one help group)
    (["--serve-emulator", E02_CA, "--list-devices", *CAN],
     "--serve-emulator and --list-devices are separate commands: use one at a time"),
    (["--batch", "x.prm", "--new", E02, "-o", "y.prm"],
     "--batch and --new are separate commands: use one at a time"),
    (["--characterize", "--get", "LIMTA", *EMU],
     "--characterize and --get are separate commands: use one at a time"),
    (["--autotune", "--batch", "x.prm", *EMU],
     "--autotune and --batch are separate commands: use one at a time"),
    (["--restart", "--get", "LIMTA", *EMU, "--hydraulics-safe"],
     "--restart and --get are separate commands: use one at a time"),
    (["--disable", "--diff", "a.prm", *EMU, "--hydraulics-safe"],
     "--disable and --diff are separate commands: use one at a time"),
    (["--get", "LIMTA", "--export-dcf", "x.dcf", *EMU],
     "--export-dcf and --get are separate commands: use one at a time"),
    (["--set", "LIMTA=1", "--list-devices", *EMU],
     "--set and --list-devices are separate commands: use one at a time"),
    (["--diff", "a.prm", "--new", E02], "--diff and --new are separate commands: use one at a "
     "time"),
    (["--lss-scan", "--restart", *CAN], "--lss-scan and --restart are separate commands"),
    (["--decode", "t.asc", "--enable"], "--decode reads a trace file and takes no --enable"),
    (["--replay", "t.asc", "--disable", *CAN], "--replay drives a bus from a trace and takes no "
     "--disable"),
    # a command with a device, a file or a bus it cannot take
    (["--restore-factory", "--hydraulics-safe"], "--restore-factory works on one valve: give "
     "one --device ID or --emulator TYPEKEY[:SERIAL]"),
    (["--restart", "x.prm", *EMU, "--hydraulics-safe"],
     "unexpected file x.prm: --restart works on a valve"),
    (["--enable", *EMU, *CAN, "--hydraulics-safe"],
     "--enable with --emulator uses the emulated valve over USB"),
    (["--restart", *EMU], "--restart: restarting the valve electronics is only allowed with the "
     "hydraulic circuit disconnected"),
    (["--get", "LIMTA"], "--get works on one valve: give one --device ID or --emulator"),
    (["x.prm", "--get", "LIMTA", *EMU], "unexpected file x.prm: --get works on a valve"),
    (["--get", "LIMTA", *EMU, *CAN], "--get with --emulator uses the emulated valve over USB"),
    (["--export-dcf", "x.dcf", *EMU, "--json"],
     "--export-dcf writes the DCF file it names; --json does not belong to it"),
    (["--characterize", "x.prm", *EMU], "unexpected file x.prm: --characterize tests a valve"),
    (["--characterize", *EMU, "--json"],
     "--characterize writes its JSON report to a file: --json OUT.json"),
    (["--signature", "--device", "1", *EMU], "--signature tests one valve: give one --device or "
     "--emulator"),
    (["--fit-twin", "t.toml"], "--fit-twin OUT.toml needs --from RUN.json (a --characterize JSON "
     "report) or one valve to characterize"),
    (["--fit-twin", "t.toml", "--list-devices", *EMU],
     "--fit-twin --device/--emulator takes no --list-devices"),
    (["--fit-twin", "t.toml", "--from", "r.json", *EMU],
     "--fit-twin --from RUN.json takes no --emulator"),
    (["--history", "7", *EMU], "--history works on the history database, not on a valve or file"),
    (["--history-check", "--batch", "x.prm"],
     "--history-check and --batch are separate commands: use one at a time"),
    (["--list-devices", "--device", "7"], "--list-devices lists every valve and takes only "
     "--emulator and the CAN options, not --device"),
    (["--batch", "x.prm", "y.prm"], "unexpected file y.prm: name the file to upload right after "
     "--batch"),
    (["--batch", "x.prm", "-o", "y.prm"], "-o/--output belongs to --new and --export-eds"),
    (["--new", E02, "-o", "y.prm", *CAN], "--can-interface names a CAN bus; --new does not use "
     "CAN"),
    (CAN, "--can-interface names a CAN bus: use it with --device can:NODE, --list-devices"),
    (["--batch", "x.prm", *EMU, *CAN], "--batch with --emulator uses the emulated valve over USB"),
    (["--device", "1", "--device", "2"], "the GUI goes online with one valve: give --device once"),
    (["--serve-emulator", E02_CA], "--serve-emulator needs --can-interface (and --can-channel)"),
    (["--serve-emulator", E02_CA, *CAN, *EMU],
     "--serve-emulator runs emulated valves on a bus and takes no --emulator"),
    (["--serve-emulator", E02_CA, *CAN, "--node-id", "1", "--node-id", "2"],
     "give at most one --node-id per --serve-emulator"),
    (["--serve-emulator", E02_CA, *CAN, "--node-id", "200"],
     "--node-id 200: CANopen node IDs are 1…127"),
    (["--type-key", E02_CA, *EMU], "--type-key belongs to a valve on a CAN bus"),
    (["--type-key", "nonsense", "--device", "can:10", *CAN], "--type-key: "),
    (["--type-key", E02, "--device", "can:10", *CAN],
     f"--type-key {E02}: a valve on a CAN bus is a -CA valve"),
    # a number of values nargs cannot say, a value judged against another option
    (["--diff", "a.prm", "b.prm", "c.prm"], "--diff compares two files (or one file and a valve)"),
    (["--diff", "a.prm", "b.prm", *EMU],
     "--diff with two files compares them: leave out --device/--emulator"),
    (["--diff", "a.prm"], "--diff with one file compares it with a valve: add --device ID or "
     "--emulator"),
    (["--diff", "a.prm", "x.prm", "--all"],
     "--diff compares with one valve: --all and a file to open do not fit"),
]  # fmt: skip


@pytest.mark.parametrize(("argv", "words"), KEPT)
def test_a_rule_argparse_cannot_say_is_refused_in_words(argv, words, capsys):
    assert main(argv) == ExitCode.USAGE
    err = capsys.readouterr().err
    assert err.startswith(f"{SHORT_USAGE}\nprm9tool: error: {words}"), err
    assert len(err.splitlines()) == 2  # one usage line and the sentence, not 27 lines


ARGPARSE = [
    # one exclusive group each: argparse names the pair (the hand checks are gone)
    (["--list-devices", "--batch", "x.prm"], "--batch", "--list-devices"),
    (["--signature", "--characterize", *EMU], "--characterize", "--signature"),
    (["--restart", "--restore-factory", *EMU], "--restore-factory", "--restart"),
    (["--characterize", "--restart", *EMU], "--restart", "--characterize"),
    (["--autotune", "--disable", *EMU], "--disable", "--autotune"),
]


@pytest.mark.parametrize(("argv", "second", "first"), ARGPARSE)
def test_argparse_refuses_two_commands_of_one_group(argv, second, first, capsys):
    assert main(argv) == ExitCode.USAGE
    err = capsys.readouterr().err
    assert (
        err
        == f"{SHORT_USAGE}\nprm9tool: error: argument {second}: not allowed with argument {first}\n"
    )


def test_a_refusal_prints_one_usage_line_and_help_the_whole_usage(capsys):
    assert SHORT_USAGE == "usage: prm9tool [options] [file] — prm9tool --help lists them"
    assert main(["--no-such-option"]) == ExitCode.USAGE
    assert capsys.readouterr().err.splitlines() == [
        SHORT_USAGE,
        "prm9tool: error: unrecognized arguments: --no-such-option",
    ]
    assert main(["--help"]) == ExitCode.OK
    shown = capsys.readouterr().out
    assert shown.startswith("usage: prm9tool [-h] [--version]")  # argparse's, unchanged
    assert "--restore-factory" in shown.split("\n\n", 1)[0]  # the whole usage
