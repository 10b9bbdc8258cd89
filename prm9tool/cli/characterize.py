"""``prm9tool --characterize``: the end-of-line test of one valve, headless.

Runs the acceptance profile's tests (steps at three amplitudes, Bode, static characteristic),
writes the PDF report (``--report``), the JSON report (``--json``) and the raw data as CSV
next to them, and exits 0 when every figure is within its limits, 8 when one is not (docs/
tuning.md). An emulated valve is stepped as fast as the CPU allows; a USB valve runs at its
stream rate, a CANopen valve (``--device can:N``) at the SDO sample rate its link gives.

A -CA valve as delivered waits for its CANopen master and does not follow its setpoint;
``--enable`` is that master's part, as the window's "Enable it now?" is: NMT start, then the
control word 08h → 09h → 0Bh → 0Fh (the valve service's ``commission``), before the test.
The valve then follows its setpoint and the spool moves: ``--enable`` needs
``--hydraulics-safe``, the answer to the window's question "make sure the hydraulics are safe
for it".
"""

from __future__ import annotations

import argparse
import json
import sys
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING

from prm9tool.analysis.profile import DEFAULT, Profile, ProfileError, load_profile
from prm9tool.characterize.canrig import rig_for_session
from prm9tool.characterize.frame import LimitExceededError
from prm9tool.characterize.rig import (
    EmulatorRig,
    Rig,
    Stopped,
    ValveFaultError,
    WaitsForMasterError,
)
from prm9tool.characterize.run import Characterization, characterize, report_data, write_csv_files
from prm9tool.cli.batch_devices import BatchError, can_options, select
from prm9tool.device.emulated_valves import emulated_valve
from prm9tool.device.factory import open_session, parse_emulator_spec
from prm9tool.errors import CommunicationError, ExitCode, Prm9Error, SdoAbortError
from prm9tool.files.atomicfile import atomic_write

if TYPE_CHECKING:
    from prm9tool.device.session import ValveSession


def run(args: argparse.Namespace, record: Callable[[Characterization], None] | None = None) -> int:
    """Entry point of ``--characterize``; returns the exit code. ``record``: hears the result
    of a run that finished (the history)."""
    try:
        profile = _profile(args)
        outputs = _outputs(args)
        rig, close = _rig(args)
    except BatchError as exc:
        print(f"prm9tool: {exc}", file=sys.stderr)
        return int(exc.code)
    try:
        result = characterize(
            rig, profile, lambda text: print(f"prm9tool: {text}", file=sys.stderr)
        )
    except (Stopped, LimitExceededError, ValveFaultError) as exc:
        print(f"prm9tool: {stopped_text(exc)}", file=sys.stderr)
        return ExitCode.OUT_OF_LIMITS
    except CommunicationError as exc:
        print(f"prm9tool: {exc}", file=sys.stderr)
        return ExitCode.COMMUNICATION
    except ValueError as exc:  # a record the analysis cannot use (no response at all)
        print(f"prm9tool: the measurement cannot be analysed: {exc}", file=sys.stderr)
        return ExitCode.OUT_OF_LIMITS
    except Prm9Error as exc:  # a test this valve cannot take on this link (it says why)
        print(f"prm9tool: test stopped: {exc}", file=sys.stderr)
        return ExitCode.OUT_OF_LIMITS
    finally:
        close()
    if record is not None:
        record(result)
    try:
        _write(result, outputs)
    except OSError as exc:
        print(f"prm9tool: cannot write the report: {exc}", file=sys.stderr)
        return ExitCode.USAGE
    for figure in result.figures:
        if figure.passed is False:
            seen = f" ({figure.note})" if figure.note is not None else ""  # what it saw instead
            print(f"prm9tool: out of limits: {figure.name} = {figure.text} "
                  f"(limit {figure.limit.text() if figure.limit else ''}){seen}", file=sys.stderr)  # fmt: skip
    verdict = "PASSED" if result.passed else "FAILED"
    print(f"{result.info.type_key} serial {result.info.serial}: {verdict}")
    return ExitCode.OK if result.passed else ExitCode.OUT_OF_LIMITS


ENABLE_HINT = (
    "add --enable --hydraulics-safe to enable it before the test (NMT start, control word "
    "08h → 09h → 0Bh → 0Fh, as its master does)"
)


def stopped_text(exc: Exception) -> str:
    """ "test stopped: …" in words, with how to enable a valve that waits for its master."""
    if isinstance(exc, WaitsForMasterError):
        return f"test stopped: {exc}; {ENABLE_HINT}"
    return f"test stopped: {exc}"


def _profile(args: argparse.Namespace) -> Profile:
    if not args.profile:
        return DEFAULT
    try:
        return load_profile(args.profile)
    except ProfileError as exc:
        raise BatchError(ExitCode.USAGE, str(exc)) from exc


def _outputs(args: argparse.Namespace) -> tuple[Path | None, Path | None]:
    pdf = Path(args.report) if args.report else None
    js = Path(args.json) if args.json else None
    if pdf is None and js is None:
        raise BatchError(
            ExitCode.USAGE, "--characterize needs --report OUT.pdf and/or --json OUT.json"
        )
    for option, path in (("--report", pdf), ("--json", js)):
        if path is not None and not path.parent.is_dir():
            raise BatchError(ExitCode.USAGE, f"{option} {path}: there is no folder {path.parent}")
    return pdf, js


def _rig(
    args: argparse.Namespace, command: str = "--characterize"
) -> tuple[Rig, Callable[[], None]]:
    if len(args.emulator) + len(args.device) != 1:
        raise BatchError(
            ExitCode.USAGE, f"{command} tests one valve: give one --device or --emulator"
        )
    enable = bool(getattr(args, "enable", False))
    if enable and not getattr(args, "hydraulics_safe", False):
        raise BatchError(ExitCode.USAGE, ENABLE_NEEDS_CONFIRMATION)
    if args.emulator:
        try:
            type_key, serial = parse_emulator_spec(args.emulator[0] or "")
            valve = emulated_valve(type_key, serial)
        except Prm9Error as exc:
            raise BatchError(ExitCode.USAGE, f"--emulator: {exc}") from exc
        if enable:  # over the emulated valve's USB link, as the window does
            while valve.status().booting:  # a stepped valve boots only as it is advanced
                valve.advance(0.05)
            with open_session(f"emulator:{valve.type_key}:{serial}", paced=False) as session:
                _commission(session)
        return EmulatorRig(valve), lambda: None
    args.all = False
    entry = select(args)[0]
    try:
        session = open_session(
            entry, paced=False, can_link=can_options(args), label_key=args.type_key
        )
    except Prm9Error as exc:
        raise BatchError(ExitCode.COMMUNICATION, str(exc)) from exc
    try:
        if enable:
            _commission(session)
        return rig_for_session(session), session.close
    except BaseException as exc:
        session.close()
        if isinstance(exc, SdoAbortError):  # the valve refused a read: 1, as --set, --export-dcf
            raise BatchError(
                ExitCode.VERIFY_FAILED, f"{command}: {exc}; nothing was tested"
            ) from exc
        if isinstance(exc, Prm9Error):
            raise BatchError(ExitCode.COMMUNICATION, str(exc)) from exc
        raise


ENABLE_NEEDS_CONFIRMATION = (
    "--enable makes the valve follow its setpoint and the test moves the spool (and on E04 "
    "the actuator): make sure the hydraulics are safe for it and add --hydraulics-safe"
)


def _commission(session: ValveSession) -> None:
    """``--enable`` before the test (``cli/enabling.py``: its words and exit code)."""
    from prm9tool.cli.enabling import commission
    from prm9tool.service.valve import service_for

    commission(service_for(session))


def _write(result: Characterization, outputs: tuple[Path | None, Path | None]) -> None:
    pdf, js = outputs
    stem = (pdf or js or Path("report")).with_suffix("")
    csv_files = write_csv_files(result, stem)
    if pdf is not None:
        from prm9tool import i18n
        from prm9tool.views.tuning.report import ensure_app, write_pdf

        ensure_app()  # the PDF in the program language: the system's, as the GUI starts in
        i18n.set_language(i18n.system_language())
        write_pdf(result, pdf)
    if js is not None:
        text = json.dumps(report_data(result, csv_files), indent=2, ensure_ascii=False)
        atomic_write(js, (text + "\n").encode("utf-8"), backup=False)
