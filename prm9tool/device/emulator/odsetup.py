"""Wiring of the object dictionary to the firmware: live values, commands and write rules."""

from __future__ import annotations

import logging
from typing import TYPE_CHECKING

from prm9tool.catalogue import CATALOGUE, LOAD_SIGNATURE, SAVE_SIGNATURE
from prm9tool.catalogue._comm import revision_number
from prm9tool.catalogue.pdo import mapping_for_control_mode
from prm9tool.catalogue.variant import Config
from prm9tool.device.emulator.constants import FULL
from prm9tool.device.emulator.inputs import CANOPEN_TYPE
from prm9tool.device.emulator.loopstate import SIGNAL_ORDER
from prm9tool.device.emulator.objdict import Value, abort
from prm9tool.device.emulator.statemachine import STATUS_CONTROL_DEVIATION, STATUS_LOCAL
from prm9tool.device.records import DeviceState
from prm9tool.errors import AbortCode

if TYPE_CHECKING:
    from prm9tool.device.emulator.firmware import Firmware

_SIG = {key: i for i, key in enumerate(SIGNAL_ORDER)}
log = logging.getLogger("prm9tool.device.emulator")


def clamp_pv(value: float) -> int:
    """A process value as the S16 object-dictionary integer (±16384 = ±100 %)."""
    return int(max(-FULL, min(FULL, round(value))))


def install(fw: Firmware) -> None:
    """Install getters, hooks and checks on ``fw.od``."""
    _identity(fw)
    _live(fw)
    _errors(fw)
    _commands(fw)
    _rules(fw)


def _getter(fw: Firmware, mnemonic: str, fn: object) -> None:
    if fw.od.has(mnemonic):
        fw.od.getters[fw.od.param(mnemonic).key] = fn  # type: ignore[assignment]


def _identity(fw: Firmware) -> None:
    _getter(fw, "PCODE", lambda: str(fw.type_key))
    _getter(fw, "SNV", lambda: fw.serial)
    _getter(fw, "FWVER", lambda: fw.firmware_version)
    _getter(fw, "REVISION", lambda: revision_number(fw.firmware_version))
    _getter(fw, "SWBAUD", lambda: fw.latched_switches[0])
    _getter(fw, "SWNODE", lambda: fw.latched_switches[1])
    # Table 7-13: entry 2 of RPDO1/TPDO1 follows the control mode 0x6043, on SDO and USB alike.
    for mnemonic in ("RPDO1MAP2", "TPDO1MAP2"):
        if fw.od.has(mnemonic):
            param = fw.od.param(mnemonic)
            _getter(fw, mnemonic, lambda p=param: mapping_for_control_mode(p, fw.value("CTRLMODE")))


def _pv(fw: Firmware, signal: str) -> int:
    return clamp_pv(fw.flush().signals[_SIG[signal]])


def _live(fw: Firmware) -> None:
    _getter(fw, "PWR", lambda: int(min(65535, max(0, round(fw.supply * 1000)))))
    _getter(fw, "TEMP", lambda: int(min(127, max(-128, round(fw.temperature)))))
    _getter(fw, "STATUSWORD", lambda: fw.sm.status_word(status_flags(fw)))
    _getter(fw, "CONTROLWORD", lambda: fw.sm.control_word)
    _getter(fw, "POSACT", lambda: _pv(fw, "position_actual"))
    _getter(fw, "DEMAND", lambda: _pv(fw, "demand"))
    _getter(fw, "CTRLDEV", lambda: clamp_pv(fw.loop.ctrl_dev))
    _getter(fw, "PRCACT", lambda: _pv(fw, "process_actual"))
    for i, mnemonic in enumerate(("SENSVAL", "SENSAFTINV", "SENSAFTOFFS", "SENSAFTGAIN")):
        _getter(fw, mnemonic, lambda i=i: clamp_pv(fw.flush().sensor_chain[i]))
    _getter(fw, "SENSAFTLIN", lambda: clamp_pv(fw.flush().sensor_chain[4]))


def _errors(fw: Firmware) -> None:
    _getter(fw, "ERROR", lambda: fw.faults.code())
    _getter(fw, "ERRREG", lambda: fw.faults.register())
    _getter(fw, "ERRCOUNT", lambda: len(fw.faults.history))
    for k in range(1, 9):
        _getter(fw, f"ERRHIST{k}", lambda k=k: _history(fw, k))
    if fw.od.has("ERRCOUNT"):
        fw.od.hooks[fw.od.param("ERRCOUNT").key] = lambda _v: fw.faults.clear_history()


def status_flags(fw: Firmware) -> int:
    """The CiA 408 upper status-word flags the emulated valve has (docs/canopen.md)."""
    flags = STATUS_LOCAL if fw.analog_only else 0
    active = fw.sm.state is DeviceState.DEVICE_MODE_ACTIVE
    if active and abs(fw.loop.ctrl_dev) > fw.monitoring_threshold:
        flags |= STATUS_CONTROL_DEVIATION
    return flags


def _history(fw: Firmware, k: int) -> int:
    if k > len(fw.faults.history):
        raise abort((0x1003, k), AbortCode.NO_DATA)
    return fw.faults.history[k - 1]


def _commands(fw: Firmware) -> None:
    od = fw.od

    def save(value: Value) -> None:
        if value != SAVE_SIGNATURE:
            raise abort((0x1010, 1), AbortCode.CANNOT_STORE)
        image = fw.nonvolatile_values()
        broken = store_problems(fw, image)
        if broken:  # a set the catalogue rejects is never stored (the RAM keeps it)
            log.info("store refused: %s", "; ".join(broken))
            raise abort((0x1010, 1), AbortCode.CANNOT_STORE)
        _write_image(fw, (0x1010, 1), image)

    def load(value: Value) -> None:
        if value != LOAD_SIGNATURE:
            raise abort((0x1011, 1), AbortCode.CANNOT_STORE)
        _write_image(fw, (0x1011, 1), {})

    def control_word(value: Value) -> None:
        if fw.analog_only:
            raise abort((0x6040, 0), AbortCode.CANNOT_STORE_LOCAL_CONTROL)
        assert isinstance(value, int)
        fw.sm.write_control_word(value, fw.faults.any_present)

    def override_on(value: Value) -> None:
        od.values[od.param("SETPOVRON").key] = value
        fw.override_last = fw.time

    od.hooks[od.param("STOREALL").key] = save
    od.hooks[od.param("RESTOREALL").key] = load
    od.hooks[od.param("CONTROLWORD").key] = control_word
    od.hooks[od.param("SETPOVRON").key] = override_on


def store_problems(fw: Firmware, image: dict[str, int | str]) -> list[str]:
    """The cross-parameter rules (current limits, one-way curves, …) ``image`` breaks: the
    firmware refuses to store such a set with abort 0x08000020, on USB and CANopen alike."""
    values = {**image, "CURNORM": fw.value("CURNORM")}
    rules = CATALOGUE.check_rules(fw.variant, values)
    return [str(problem.text) for problem in rules if problem.severity == "error"]


def _write_image(fw: Firmware, key: tuple[int, int], image: dict[str, int | str]) -> None:
    try:
        fw.nv.replace(image)
    except OSError as exc:  # the image could not be written: memory and file keep the old one
        log.warning("non-volatile memory not written: %s", exc)
        raise abort(key, AbortCode.HARDWARE_ERROR) from exc


def _rules(fw: Firmware) -> None:
    od = fw.od

    def not_in_active_mode(mnemonic: str) -> None:
        def check(_value: Value) -> None:
            if fw.sm.state is DeviceState.DEVICE_MODE_ACTIVE:
                raise abort(od.param(mnemonic).key, AbortCode.CANNOT_STORE_DEVICE_STATE)

        od.checks[od.param(mnemonic).key] = check

    def at_most_curnorm(mnemonic: str) -> None:
        def check(value: Value) -> None:
            if isinstance(value, int) and value > fw.value("CURNORM"):
                raise abort(od.param(mnemonic).key, AbortCode.VALUE_TOO_HIGH)

        od.checks[od.param(mnemonic).key] = check

    def needs_canopen(mnemonic: str) -> None:
        def check(value: Value) -> None:
            if value == CANOPEN_TYPE and not fw.variant.canopen:
                raise abort(od.param(mnemonic).key, AbortCode.INVALID_VALUE)

        od.checks[od.param(mnemonic).key] = check

    def control_mode(value: Value) -> None:
        if value == 4 and fw.variant.config is not Config.E04:
            raise abort(od.param("CTRLMODE").key, AbortCode.INVALID_VALUE)
        state_check(value)

    for mnemonic in ("DEVMODE", "CTRLMODE"):
        not_in_active_mode(mnemonic)
    state_check = od.checks[od.param("CTRLMODE").key]
    od.checks[od.param("CTRLMODE").key] = control_mode
    for mnemonic in ("LIMTA", "LIMTB"):
        if od.has(mnemonic):
            at_most_curnorm(mnemonic)
    for mnemonic in ("AINSETP", "SENSTYPE"):
        if od.has(mnemonic):
            needs_canopen(mnemonic)
