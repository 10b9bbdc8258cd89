"""The upload contract, one suite over every link (as python-can runs one over every interface).

Each test runs against an emulated valve reached over the emulated USB link, over the hidapi
backend talking to a fake ``hid`` module (tests/support/fake_hid, tests/support/usb_fakes.py), and over
CANopen on a virtual bus (the ``canopen`` master against the emulated valve's slave), through
the public API's :class:`~prm9tool.api.valve.Valve`. The contract
(:mod:`prm9tool.device.session`): write all → read every value back and compare → store, and
``stored`` only when the valve stored the verified set; a refused or out-of-range value or a
valve of another type leaves it as it was; the result reports every step. The link-specific
ways of making sure of the store (USB's second read-back, CANopen's boot-up watch) and link
faults stay in the links' own tests (test_usb_session.py, test_usb_hidapi.py,
test_can_link.py, test_can_upload_steps.py).
"""

from __future__ import annotations

import sys
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from pathlib import Path

import pytest
from support.can_link_rig import make_link_rig
from support.usb_fakes import FakeHid

import prm9tool
from prm9tool.api.valve import Valve
from prm9tool.catalogue import CATALOGUE
from prm9tool.device import emulated_valves
from prm9tool.device.emulator import EmulatedValve
from prm9tool.device.session import ValveSession
from prm9tool.errors import AbortCode, SdoAbortError, TypeKeyError, ValueRangeError

E04 = "PRM9-06.3Z11/30-24E04S02-CA"
OTHER_VARIANT = "PRM9-06.3Z11/30-24E02S02-CA"
SAME_VARIANT = "PRM9-10.3Z11/60-24E04S02-CA"
HID_PATH = b"/dev/hidraw7"
# a few values, each valid with the others (the valve refuses to store a set that breaks a
# cross-parameter rule); every link's valve holds its factory values before
CHANGES = {"LIMTA": 1500, "LIMTB": 1600, "DYNFREQ": 120, "DTAMP": 10.0}  # display units
RAW = {m: CATALOGUE[m].to_raw(v) for m, v in CHANGES.items()}
# "canopen-manual": a valve with only the objects the manual lists (the emulator's --od manual)
LINKS = ("usb-emulated", "usb-hidapi", "canopen", "canopen-manual")


@dataclass
class Link:
    """One valve behind one link: the emulated valve itself and a way to open the link."""

    name: str
    valve: EmulatedValve
    opener: Callable[[], ValveSession]
    # how the link's peer refuses a write: CANopen's SDO server (can_link_rig), else the
    # emulated valve's object dictionary behind the USB firmware
    refuser: Callable[[int, int, int], None] | None = None

    def open(self) -> Valve:
        """The link's session as the API's Valve."""
        return Valve(self.opener())

    def stored(self) -> dict[str, int | str]:
        """What the valve starts with after a power cycle, of the parameters the tests change
        (non-volatile memory; an entry never stored is at its factory value). A valve without
        a store command keeps what is written (manual §7.2.2), so after a failed upload the
        master writes the old values back and they are in its memory again: the values count,
        not which entries the memory holds."""
        with self.valve.lock:
            memory = dict(self.valve.firmware.nv.values)
        variant = self.valve.variant
        return {m: memory.get(m, CATALOGUE[m].default_for(variant)) for m in CHANGES}

    def working(self) -> dict[str, int | str]:
        """The values the valve works with now (RAM), of its file parameter set."""
        params = CATALOGUE.file_parameters(self.valve.variant)
        return {p.mnemonic: self.valve.read(*p.key) for p in params}

    def refuse(self, monkeypatch: pytest.MonkeyPatch, mnemonic: str) -> None:
        """The valve refuses every write of ``mnemonic`` (abort 0x08000022, whatever the link)."""
        key, original = CATALOGUE[mnemonic].key, self.valve.write_bytes
        if self.refuser is not None:
            self.refuser(*key, AbortCode.CANNOT_STORE_DEVICE_STATE)
            return

        def write_bytes(index: int, subindex: int, data: bytes) -> None:
            if (index, subindex) == key:
                raise SdoAbortError(index, subindex, AbortCode.CANNOT_STORE_DEVICE_STATE)
            original(index, subindex, data)

        monkeypatch.setattr(self.valve, "write_bytes", write_bytes)


@pytest.fixture(params=LINKS)
def link(request, tmp_path: Path, monkeypatch: pytest.MonkeyPatch, data_dir) -> Iterator[Link]:
    """The same valve type (a -CA E04) behind each link."""
    kind = request.param
    if kind.startswith("canopen"):
        from prm9tool.device.canlink.session import CanopenSession

        manual = kind == "canopen-manual"  # it does not tell its type key: the label's is given
        od = "manual" if manual else "full"  # the emulator's --od manual
        rig = make_link_rig(request.node.name, tmp_path, E04, real_valve=manual, od=od)
        key = E04 if manual else None
        yield Link(
            kind, rig.valve, lambda: CanopenSession(rig.options, 10, type_key=key), rig.refuse
        )
        rig.close()
        return
    valve = EmulatedValve(E04, 4711, "2.3.4", nv_path=tmp_path / "nv.json")
    valve.advance(3.0)  # past the power-up timeline
    if kind == "usb-emulated":
        from prm9tool.device.usb.session import UsbSession
        from prm9tool.device.usb.transport.emulator import EmulatorTransport

        yield Link(kind, valve, lambda: UsbSession(EmulatorTransport(valve), "emulator:contract"))
        return
    from prm9tool.device.usb.session import UsbSession
    from prm9tool.device.usb.transport.hidapi import HidTransport

    fake = FakeHid()
    monkeypatch.setitem(sys.modules, "hid", fake.as_module())
    monkeypatch.setitem(sys.modules, "hidraw", fake.as_module())
    monkeypatch.setattr(HidTransport, "settle_s", 0.0)
    fake.add(valve, HID_PATH)
    yield Link(
        kind,
        valve,
        lambda: UsbSession(HidTransport(HID_PATH, timeout_s=0.2), f"usb:{HID_PATH.decode()}"),
    )
    emulated_valves.forget_emulated_valves()


def test_upload_writes_verifies_stores_and_reports_each_step(link):
    steps: list[tuple[int, int, str]] = []
    with link.open() as valve:
        params = valve.download()
        params.update(CHANGES)
        result = valve.upload(params, progress=lambda d, t, s: steps.append((d, t, s)))
        assert valve.download() == params
    total = 2 * len(params) + 1
    assert (result.stored, result.verified, result.failed_step, result.mismatches) == (
        True,
        True,
        None,
        {},
    )
    assert result.written == len(params) and result.skipped == ()
    assert steps[-1] == (total, total, "store")
    order = [s for _, _, s in steps if s in ("write", "verify", "store")]
    assert order == sorted(order, key=["write", "verify", "store"].index)
    stored = link.stored()
    assert all(stored[m] == v for m, v in RAW.items())


def test_the_report_goes_into_the_history(link):
    with link.open() as valve:
        params = valve.download()
        params.update(CHANGES)
        result = valve.upload(params)
        serial = valve.info.serial
    records = prm9tool.history.records(serial)
    assert [r["operation"] for r in records] == ["download", "backup", "upload"]
    upload = records[-1]
    assert (upload["outcome"], upload["failed_step"]) == ("ok", None)
    assert upload["details"]["written"] == result.written
    assert result.to_dict()["stored"] is True  # the record as JSON shows it


def test_a_valve_of_another_type_is_refused_and_nothing_is_written(link):
    before, working = link.stored(), link.working()
    with link.open() as valve:
        other = prm9tool.ParameterSet.factory(OTHER_VARIANT)
        with pytest.raises(TypeKeyError, match="the parameter sets differ"):
            valve.upload(other, force_type=True)
        same_variant = prm9tool.ParameterSet(SAME_VARIANT, valve.download().raw)
        same_variant.update(CHANGES)
        with pytest.raises(TypeKeyError, match=r"use force_type=True to upload anyway"):
            valve.upload(same_variant)
    assert (link.stored(), link.working()) == (before, working)


def test_a_value_out_of_range_leaves_the_valve_unchanged(link):
    before, working = link.stored(), link.working()
    with link.open() as valve:
        values = {**valve.download(), **CHANGES, "LIMTA": 99999}
        with pytest.raises(ValueRangeError, match="LIMTA: 99999 mA is outside the allowed range"):
            valve.upload(values)
        above_cap = {**valve.download(), **CHANGES, "LIMTB": 3000.0}  # > CURNORM (7-14)
        with pytest.raises(ValueRangeError, match="LIMTB = 3000 mA is above the nominal"):
            valve.upload(above_cap)
        raw = {**valve.download().raw, **RAW, "DYNFREQ": 70000}
        with pytest.raises(ValueRangeError, match="DYNFREQ"):
            valve.session.upload(raw)  # the device layer checks before it sends, too
    assert (link.stored(), link.working()) == (before, working)


def test_a_refused_value_stores_nothing_and_the_valve_runs_on_its_stored_set(link, monkeypatch):
    before, working = link.stored(), link.working()
    link.refuse(monkeypatch, "DTAMP")
    with link.open() as valve:
        params = valve.download()
        params.update(CHANGES)
        result = valve.upload(params)
    assert (result.stored, result.verified, result.failed_step) == (False, False, "write")
    assert result.reloaded and result.reload_error is None
    assert "abort 0x08000022" in str(result.mismatches["DTAMP"][1])
    assert link.stored() == before
    assert link.working() == working  # LIMTA, LIMTB were written before DTAMP: put back
