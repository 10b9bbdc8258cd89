"""The valve service's operations (``--set``/``--get``, ``--export-dcf``, ``--enable``,
``--restart``, ``--restore-factory`` and the API's) against foreign and broken CANopen nodes
(tests/support/bad_node.py) on the in-process virtual bus: the user sees a sentence and a
documented exit code (or a typed ``Prm9Error``), never a traceback, and nothing half-done
without being told. ``sound=IDENTITY``: a node that identifies as a PRM9, then breaks."""

from __future__ import annotations

import time
from collections.abc import Iterator
from contextlib import ExitStack, contextmanager

import pytest
from support.bad_node import IDENTITY, BadNode, Fault, prm9_objects, serving_node
from support.canopen_rig import unique_channel

import prm9tool
from prm9tool.cli.main import main
from prm9tool.device.canlink import session as can_session
from prm9tool.errors import CommunicationError, ExitCode, Prm9Error

CIA402_DRIVE = (0x00020192).to_bytes(4, "little")  # device type of a CiA 402 drive


@contextmanager
def nodes(*specs: dict[str, object]) -> Iterator[tuple[str, list[BadNode]]]:
    """BadNodes at node 11 on a fresh virtual channel (each spec: BadNode's keywords; none:
    nothing answers at node 11); yields the channel and the nodes."""
    channel = unique_channel("service")
    with ExitStack() as stack:
        started = [
            stack.enter_context(
                serving_node(channel, 11, **{"objects": prm9_objects(parameters=True), **spec})
            )
            for spec in specs
        ]
        yield channel, started


def cli(channel: str, *args: str) -> int:
    return main([*args, "--device", "can:11", "--can-interface", "virtual",
                 "--can-channel", channel])  # fmt: skip


def said(capsys: pytest.CaptureFixture[str]) -> str:
    err = capsys.readouterr().err
    assert "Traceback" not in err, err
    return err


@pytest.fixture
def quick_boot(monkeypatch):
    """The wait for a boot-up after NMT reset node: 1 s, not 10 (BadNode never boots)."""
    monkeypatch.setattr(can_session, "BOOT_TIMEOUT_S", 1.0)


# --- --set / --get ---------------------------------------------------------------------------
@pytest.mark.parametrize(
    ("fault", "words"),
    [
        (Fault.ANSWERS_1000_ONLY, "node 11: no SDO answer for 0x2004/1 within 0.5 s"),
        (Fault.SHORT_FRAMES, "0x2004/1: an answer of 3 bytes, not 8"),
        (Fault.OTHER_OBJECT, "0x2004/1: the node answered for 0x2004/2"),
    ],
    ids=["silent-after-identity", "short-frames", "other-object"],
)
def test_set_on_a_node_that_breaks_after_identifying_is_exit_6_in_words(
    data_dir, capsys, fault, words
):
    started = time.monotonic()
    with nodes({"fault": fault, "sound": IDENTITY}) as (channel, (node,)):
        code = cli(channel, "--set", "LIMTA=1500", "--store")
    err = said(capsys)
    assert code == ExitCode.COMMUNICATION, err
    assert f"prm9tool: --set: {words}" in err and "nothing was written" in err, err
    assert node.writes == [] and node.stored is None
    assert time.monotonic() - started < 5


def test_set_on_a_node_that_resets_at_the_write_says_nothing_was_stored(data_dir, capsys):
    with nodes({"fault": Fault.RESETS}) as (channel, (node,)):
        code = cli(channel, "--set", "LIMTA=1500", "--store")
    err = said(capsys)
    assert code == ExitCode.COMMUNICATION
    assert "prm9tool: --set LIMTA: node 11: no SDO answer for 0x2004/2" in err, err
    assert "nothing was stored; until the valve restarts" in err, err
    assert node.stored is None


def test_get_from_a_node_silent_after_identifying_is_exit_6_in_words(data_dir, capsys):
    with nodes({"fault": Fault.ANSWERS_1000_ONLY, "sound": IDENTITY}) as (channel, _):
        code = cli(channel, "--get", "LIMTA")
    err = said(capsys)
    assert code == ExitCode.COMMUNICATION
    assert "no SDO answer for 0x2004/2 within 0.5 s; is the valve powered" in err, err


@pytest.mark.parametrize(
    ("fault", "says"),
    [
        (Fault.REFUSES_STORE, "--store: 0x1010/1: abort 0x08000020"),
        (Fault.CLAMPS, "--set LIMTA: LIMTA: wrote 1500, the valve reads back 750"),
    ],
    ids=["refused-store", "clamped"],
)
def test_a_refused_store_or_a_clamped_value_is_exit_1_and_nothing_stored(
    data_dir, capsys, fault, says
):
    with nodes({"fault": fault}) as (channel, (node,)):
        code = cli(channel, "--set", "LIMTA=1500", "--store")
    err = said(capsys)
    assert code == ExitCode.VERIFY_FAILED
    assert says in err, err
    assert (
        "; nothing was stored; until the valve restarts, it works with what it now holds for "
        "LIMTA" in err
    ), err
    assert node.stored is None


# --- --export-dcf ----------------------------------------------------------------------------
def test_export_dcf_from_a_node_that_refuses_a_read_is_exit_1_and_no_file(
    data_dir, tmp_path, capsys
):
    out = tmp_path / "valve.dcf"
    with nodes({"fault": Fault.ABORTS, "sound": IDENTITY}) as (channel, _):
        code = cli(channel, "--export-dcf", str(out))
    err = said(capsys)
    assert code == ExitCode.VERIFY_FAILED, err
    assert "prm9tool: --export-dcf: 0x2010/2: abort 0x05040001" in err, err
    assert "no DCF was written" in err and not out.exists()


def test_export_dcf_from_a_node_silent_after_identifying_is_exit_6_and_no_file(
    data_dir, tmp_path, capsys
):
    out = tmp_path / "valve.dcf"
    with nodes({"fault": Fault.ANSWERS_1000_ONLY, "sound": IDENTITY}) as (channel, _):
        code = cli(channel, "--export-dcf", str(out))
    err = said(capsys)
    assert code == ExitCode.COMMUNICATION, err
    assert "prm9tool: --export-dcf: node 11: no SDO answer for 0x2010/1" in err, err
    assert "no DCF was written" in err and not out.exists()


# --- --signature, --characterize ----------------------------------------------------------------
@pytest.mark.parametrize(
    "command",
    [["--signature"], ["--characterize", "--json", "eol.json"]],
    ids=["signature", "characterize"],
)
def test_a_test_whose_set_up_the_node_refuses_is_exit_1_naming_the_command(
    data_dir, tmp_path, monkeypatch, capsys, command
):
    # an SDO abort while the rig is made (before anything moves): the valve refused, as
    # --set and --export-dcf say it, not a communication error (exit 1, not 6)
    monkeypatch.chdir(tmp_path)
    with nodes({"fault": Fault.ABORTS, "sound": IDENTITY}) as (channel, _):
        code = cli(channel, *command, "--history-db", f"sqlite:///{tmp_path / 'h.db'}")
    err = said(capsys)
    assert code == ExitCode.VERIFY_FAILED, err
    assert f"prm9tool: {command[0]}: 0x6301/1: abort 0x05040001" in err, err
    assert err.rstrip().endswith("; nothing was tested"), err
    assert not (tmp_path / "eol.json").exists()


# --- --restore-factory, --restart --------------------------------------------------------------
def test_restore_factory_whose_restart_fails_says_the_factory_values_are_stored(
    data_dir, capsys, quick_boot
):
    with nodes({"fault": Fault.NONE}) as (channel, (node,)):
        code = cli(channel, "--restore-factory", "--hydraulics-safe")
    err = said(capsys)
    assert code == ExitCode.COMMUNICATION, err
    assert "no boot-up within 1 s after the reset" in err, err
    assert "the factory values were already loaded in the valve" in err, err
    assert "the valve's previous parameters are in " in err, err
    assert (0x1011, 1) in node.writes


def test_api_restore_factory_whose_restart_fails_raises_the_link_error_saying_so(
    data_dir, quick_boot
):
    with nodes({"fault": Fault.NONE}) as (channel, _):
        valve = prm9tool.connect("can:11", can_interface="virtual", can_channel=channel)
        with valve, pytest.raises(CommunicationError) as caught:
            valve.restore_factory(confirm_hydraulics_off=True)
    assert "the factory values were already loaded in the valve" in str(caught.value)


def test_a_restart_without_a_boot_up_is_exit_6_naming_the_node(data_dir, capsys, quick_boot):
    with nodes({"fault": Fault.NONE}) as (channel, _):
        code = cli(channel, "--restart", "--hydraulics-safe")
    err = said(capsys)
    assert code == ExitCode.COMMUNICATION
    assert "--restart: node 11: no boot-up within 1 s after the reset" in err, err


# --- --disable, --enable ------------------------------------------------------------------------
ACTIVE = {**prm9_objects(parameters=True), (0x6041, 0): b"\x0f\x00"}  # DEVICE_MODE_ACTIVE


def test_disable_of_a_valve_that_stays_active_is_exit_1_saying_it_follows_its_setpoint(
    data_dir, capsys
):
    started = time.monotonic()
    with nodes({"objects": ACTIVE}) as (channel, (node,)):
        code = cli(channel, "--disable", "--hydraulics-safe")
    err = said(capsys)
    assert code == ExitCode.VERIFY_FAILED, err
    assert (
        "prm9tool: --disable: the valve stays in DEVICE_MODE_ACTIVE after the control word "
        "0Fh → 0Bh → 09h → 08h and still follows its setpoint" in err
    ), err
    assert node.writes.count((0x6040, 0)) == 4
    assert time.monotonic() - started < 5


def test_api_disable_of_a_valve_that_stays_active_raises_not_disabled(data_dir):
    from prm9tool.device.enabling import NotDisabledError

    with (
        nodes({"objects": ACTIVE}) as (channel, _),
        prm9tool.connect("can:11", can_interface="virtual", can_channel=channel) as valve,
        pytest.raises(NotDisabledError, match="still follows its setpoint"),
    ):
        valve.disable()
    assert issubclass(NotDisabledError, prm9tool.AccessDeniedError)


def test_enable_of_a_node_that_ignores_the_control_word_is_exit_1_in_words(data_dir, capsys):
    with nodes({"fault": Fault.NONE}) as (channel, _):
        code = cli(channel, "--enable", "--hydraulics-safe")
    err = said(capsys)
    assert code == ExitCode.VERIFY_FAILED
    assert "--enable: the valve is in NOT_READY after the control word 08h → 09h → 0Bh → 0Fh" in err
    assert (  # what to do, as every other refusal of the enable says it
        ": it has not finished starting up (about 2 s after power-up) — wait until it has, then "
        "enable again; if it stays in NOT_READY, check its supply voltage (19.2 … 28 V)" in err
    ), err


def test_api_enable_of_a_valve_still_not_ready_says_to_wait_and_check_the_supply(data_dir):
    from prm9tool.device.enabling import NotEnabledError

    with (
        nodes({"fault": Fault.NONE}) as (channel, _),
        prm9tool.connect("can:11", can_interface="virtual", can_channel=channel) as valve,
        pytest.raises(NotEnabledError) as caught,
    ):
        valve.enable()
    words = str(caught.value)
    assert words.startswith("the valve is in NOT_READY after the control word"), words
    assert "wait until it has, then enable again" in words and "check its supply" in words


# --- nodes that are no valve, none, or two -------------------------------------------------------
@pytest.mark.parametrize(
    "command",
    [
        ["--enable", "--hydraulics-safe"],
        ["--restart", "--hydraulics-safe"],
        ["--set", "LIMTA=1500"],
        ["--export-dcf", "x.dcf"],
    ],
    ids=["enable", "restart", "set", "export-dcf"],
)
@pytest.mark.parametrize(
    ("specs", "says"),
    [
        ((), "no valve 'can:11' answers on the CAN bus virtual channel"),
        (
            ({"objects": {**prm9_objects(parameters=True), (0x1000, 0): CIA402_DRIVE}},),
            "node 11: not a PRM9 (device type 0x20192, vendor 0xE6); prm9tool does not write",
        ),
        (
            ({}, {"objects": prm9_objects(777002, parameters=True), "delay_s": 0.004}),
            "node 11: two nodes answer at this ID",
        ),
    ],
    ids=["nothing", "cia402-drive", "two-nodes"],
)
def test_no_node_a_foreign_node_or_two_nodes_are_exit_4_and_nothing_written(
    data_dir, tmp_path, monkeypatch, capsys, specs, says, command
):
    monkeypatch.chdir(tmp_path)
    with nodes(*specs) as (channel, started):
        code = cli(channel, *command)
    err = said(capsys)
    assert code == ExitCode.NO_DEVICE, err
    assert says in err and err.count("write") <= 1, err  # said once
    assert all(node.writes == [] for node in started)
    assert not (tmp_path / "x.dcf").exists()


def test_api_on_a_foreign_node_is_a_typed_error_in_words(data_dir):
    spec = {"objects": {**prm9_objects(parameters=True), (0x1000, 0): CIA402_DRIVE}}
    with nodes(spec) as (channel, (node,)), pytest.raises(Prm9Error, match="is not a PRM9"):
        prm9tool.connect("can:11", can_interface="virtual", can_channel=channel)
    assert node.writes == []


def test_api_set_on_a_node_silent_after_identifying_is_a_communication_error(data_dir):
    with (
        nodes({"fault": Fault.ANSWERS_1000_ONLY, "sound": IDENTITY}) as (channel, (node,)),
        prm9tool.connect("can:11", can_interface="virtual", can_channel=channel) as valve,
        pytest.raises(CommunicationError, match="no SDO answer for 0x2004/1"),
    ):
        valve["LIMTA"] = 1500
    assert node.writes == []
