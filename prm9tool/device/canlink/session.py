"""The valve session over CANopen (manual chapter 7): one link of
:class:`prm9tool.device.session.ValveSession`, with the ``canopen`` package as SDO/NMT master.

Parameters travel by the catalogue's object address through SDO. An object the valve does not
have (abort 0x06020000/0x06090011; on a real valve the objects this project decided on) makes
the parameter "not available over CANopen on this valve": it is skipped and listed in
:attr:`unavailable`. Store is 0x1010/1 "save", restore factory values 0x1011/1 "load",
restart NMT reset node.

The upload's decisions (the snapshot that reverts a failed upload, fewer frames with the same
guarantees) are in :mod:`prm9tool.device.canlink.upload_steps`, which carries them out; the
entry reads and writes are :mod:`prm9tool.device.canlink.entries`, the measuring-point stream
:mod:`prm9tool.device.canlink.stream`: parts the session holds.
"""

from __future__ import annotations

import threading
from collections.abc import Callable, Mapping, Sequence

import numpy as np

from prm9tool.catalogue import CATALOGUE, LOAD_SIGNATURE, SAVE_SIGNATURE, Parameter
from prm9tool.catalogue.commissioning import NmtCommand
from prm9tool.device.canlink import bus as canbus
from prm9tool.device.canlink import discovery, relocate
from prm9tool.device.canlink.entries import SdoEntries
from prm9tool.device.canlink.nmt_confirm import send_and_confirm
from prm9tool.device.canlink.pdo_scope import min_period_s
from prm9tool.device.canlink.sdo import MISSING, SdoChannel
from prm9tool.device.canlink.status import read_status, stopped_status
from prm9tool.device.canlink.storing import STORED_WITH_1010, factory_upload
from prm9tool.device.canlink.stream import CanStream
from prm9tool.device.canlink.typekeys import GivenKey
from prm9tool.device.canlink.upload_steps import CanopenUploadSteps
from prm9tool.device.records import (
    DeviceInfo,
    NmtState,
    Progress,
    Steps,
    UploadResult,
    Value,
    ValveStatus,
)
from prm9tool.device.session import ValveSession
from prm9tool.device.setpoint import SetpointLink
from prm9tool.errors import (
    AccessDeniedError,
    CanBusOffError,
    DeviceDisconnectedError,
    DeviceTimeoutError,
    Prm9Error,
    ProtocolError,
    SdoAbortError,
    TypeKeyError,
)

SDO_TIMEOUT_S = 0.5
STORE_TIMEOUT_S = 3.0  # writing the non-volatile memory takes longer than an SDO answer
BOOT_TIMEOUT_S = 10.0  # NMT reset node -> boot-up (the valve takes about 2 s, manual §7.6)
LINK_PARAMETERS = ("NODEID", "BITRATE")  # take effect at power-up: the tool's link moves
__all__ = ["CanopenSession", "NotAPrm9Error"]


class NotAPrm9Error(AccessDeniedError):
    """The node is some other CANopen device: prm9tool does not write to it."""


class CanopenSession(ValveSession):
    """One PRM9 -CA valve as a node on a CAN bus, the tool its CANopen master; the upload's
    CANopen steps are the part it holds (:class:`CanopenUploadSteps`)."""

    def __init__(
        self,
        options: canbus.CanOptions,
        node_id: int,
        *,
        type_key: str | None = None,
        on_close: Callable[[], None] | None = None,
        timeout_s: float = SDO_TIMEOUT_S,
        label_key: str | None = None,
    ) -> None:
        """``type_key``: the key to use when the valve has no 0x2041 (the batch file's); it is
        checked against what the object dictionary tells. ``label_key``: the key the user read
        from the valve's label (``--type-key``): it goes first, is checked the same way and is
        remembered for the valve's serial number."""
        if not 1 <= node_id <= 127:
            raise Prm9Error(f"CANopen node IDs are 1…127, not {node_id}")
        super().__init__(f"can:{node_id}", on_close)
        self.node_id = node_id
        self._key = GivenKey(type_key, label_key)  # the key given where the valve tells none
        self._shared = canbus.acquire(options)
        self._closed = False
        self._upload = CanopenUploadSteps(
            self,
            lambda: self._sdo,
            lambda: self._shared.node_seen(self.node_id).boot_ups,
            self._key_refusal,
        )
        self.upload_steps = self._upload
        self._entries = SdoEntries(lambda: self._sdo, self.unavailable, self._upload)
        self.stream = CanStream(lambda: self._shared, lambda: self._sdo)
        self._stopped_by_me = False  # this session's NMT stop is in force (no SDO then)
        self._last_status: ValveStatus | None = None
        self._lost_before = 0
        try:
            self._sdo = self._open_node(timeout_s)
            self._start()
        except BaseException:
            self._release()
            raise

    @property
    def options(self) -> canbus.CanOptions:
        """The bus this session is on."""
        return self._shared.options

    @property
    def sdo(self) -> SdoChannel:
        """The node's SDO channel (the OD browser, statistics)."""
        return self._sdo

    @property
    def closed(self) -> bool:
        """True once the session released the bus."""
        return self._closed

    @property
    def key_given(self) -> bool:
        """True: the type key was given, the valve has no 0x2041."""
        return self._key.given

    # --- identity ---------------------------------------------------------------------------
    def identify(self) -> DeviceInfo:
        """Who the node is; NotAPrm9Error for another CANopen device (0x1000, 0x1018/1)."""
        found = discovery.identify_node(self._shared, self.node_id, SDO_TIMEOUT_S)
        if found.duplicate:
            raise ProtocolError(f"node {self.node_id}: {found.problem}")
        if found.device_type is None:
            raise DeviceTimeoutError(f"node {self.node_id}: {found.problem}")
        if not found.is_prm9:
            raise NotAPrm9Error(
                f"node {self.node_id} is {found.problem}; prm9tool does not write to it"
            )
        if found.problem:
            raise ProtocolError(f"node {self.node_id}: {found.problem}")
        key = self._key.key_of(found.serial, found.type_key, found.derived)
        bus = self.options
        return DeviceInfo(
            type_key=key,
            serial=found.serial,
            firmware=found.firmware,
            protocol_version=0,
            device_id=self._device_id,
            link_parameters=LINK_PARAMETERS,
            can_bus=(bus.interface, bus.channel, bus.bitrate),
            # the SYNC + TPDO1 pace (docs/can-link.md)
            stream_rate_limit_hz=1.0 / min_period_s(bus.bitrate),
            stream_gaps=True,  # both samplers place samples by time (NaN rows for lost ones)
        )

    def upload(
        self,
        values: Mapping[str, Value],
        progress: Progress | None = None,
        cancel: threading.Event | None = None,
    ) -> UploadResult:
        """:meth:`ValveSession.upload`; a valve without 0x2041 that stored a set for the type
        key given (the batch file's) keeps that key remembered for its serial number."""
        result = super().upload(values, progress, cancel)
        if result.stored:
            self._key.stored(self.info.serial, self.info.type_key)
        return result

    def download(
        self, progress: Progress | None = None, cancel: threading.Event | None = None
    ) -> dict[str, Value]:
        """:meth:`ValveSession.download`; a valve whose key was given (no 0x2041) and that
        lacks objects the manual lists for that key is refused (TypeKeyError), and the key is
        no longer remembered for it."""
        values = super().download(progress, cancel)
        self._key.check_download(self.info.serial, self.info.type_key, values)
        return values

    def _key_refusal(self) -> TypeKeyError | None:
        """Asked after the upload's snapshot, before anything is written: for a key that was
        given (no 0x2041), the refusal of a key whose objects the snapshot found missing (an
        E04 file's key on an E02 without the external-sensor objects)."""
        if not self.key_given:
            return None
        present = {
            p.mnemonic: 0
            for p in CATALOGUE.file_parameters(self.variant)
            if p.mnemonic not in self.unavailable
        }
        return self._key.refusal(self.info.serial, self.info.type_key, present)

    # --- entries ----------------------------------------------------------------------------
    def _read_entries(
        self, params: Sequence[Parameter], steps: Steps | None, cancel: threading.Event | None
    ) -> dict[str, Value | SdoAbortError]:
        return self._entries.read(params, steps, cancel)

    def _write_entries(
        self,
        params: Sequence[Parameter],
        values: Mapping[str, Value],
        steps: Steps | None,
        cancel: threading.Event | None,
    ) -> int:
        return self._entries.write(params, values, steps, cancel)

    # --- commands ---------------------------------------------------------------------------
    def store(self) -> None:
        """0x1010/1 = "save": the working parameters become the stored ones; a valve without
        a store command kept every write already (prm9tool.device.canlink.storing)."""
        kind = self._upload.store_kind()
        if kind == STORED_WITH_1010:
            self._sdo.download(0x1010, 1, SAVE_SIGNATURE.to_bytes(4, "little"), STORE_TIMEOUT_S)
        self.store_done = kind
        self._upload.stored()

    def reload(self) -> None:
        """Working values ← those read before the upload, for the parameters it wrote (the
        module's decision; :meth:`CanopenUploadSteps.reload`)."""
        self._upload.reload()

    def restore_factory(self) -> None:
        """0x1011/1 = "load": factory values at the next reset or power-up. A valve without
        0x1011 (manual table 7-13) gets the catalogue's factory set uploaded, as any upload."""
        try:
            self._sdo.download(0x1011, 1, LOAD_SIGNATURE.to_bytes(4, "little"), STORE_TIMEOUT_S)
        except SdoAbortError as exc:
            if exc.code not in MISSING:
                raise
            factory_upload(self)

    def restart(self) -> None:
        """NMT reset node, then find the valve again — at its old node, or where a changed node
        ID or bit rate puts it (prm9tool.device.canlink.relocate) — and identify it (hydraulics
        off). ValveMovedError says where it is when the session cannot follow."""
        self.stream.stop()
        after = relocate.predict(self)
        self._upload.known.clear()  # the valve comes back with its stored set
        nodes = [self.node_id, *([after.node_id] if after and after.node_id else [])]
        boot_ups = {n: self._shared.node_seen(n).boot_ups for n in nodes}  # the old one first
        old = self.node_id
        self._sdo.node.nmt.send_command(NmtCommand.RESET_NODE)
        if relocate.bitrate_moves(self.options, after):
            assert after is not None and after.node_id is not None
            reason = relocate.why_not_follow(self.options, self._shared.users)
            if reason:
                raise relocate.moved_error(self.options, after, reason)
            bus = canbus.CanOptions(self.options.interface, self.options.channel, after.bitrate)
            self._rebind(after.node_id, bus)
            relocate.await_answer(self._sdo, old, after, BOOT_TIMEOUT_S)
        else:
            booted = relocate.await_boot_up(self._shared, boot_ups, after, BOOT_TIMEOUT_S)
            self._rebind(booted, self.options)
        info = self.identify()
        if info.serial != self.info.serial:
            raise ProtocolError(
                f"node {self.node_id} came back as serial {info.serial}, not {self.info.serial}"
            )
        if self.node_id != old or info != self.info:
            self.info = info

    def _rebind(self, node_id: int, options: canbus.CanOptions) -> None:
        """This session now talks to ``node_id`` on the bus ``options``."""
        if node_id == self.node_id and options == self.options:
            return
        timeout_s = self._sdo.timeout_s
        network = self._shared.network
        with self._shared.lock:
            if network.nodes.get(self.node_id) is self._sdo.node:
                del network[self.node_id]
        if options != self.options:
            shared = canbus.acquire(options)
            canbus.release(self._shared)
            self._shared = shared
        self.node_id, self._device_id = node_id, f"can:{node_id}"
        self._sdo = self._open_node(timeout_s)

    def status(self) -> ValveStatus:
        """State 0x6041, error register 0x1001, errors, LEDs derived from them, NMT state.

        A node this session stopped answers no SDO (CiA 301): its status is then the last one
        read, NMT stopped, with the device state table 7-21 couples to the stop, instead of a
        timeout that would call the valve unpowered."""
        seen = self._shared.node_seen(self.node_id)
        if self._stopped_by_me and seen.nmt_state is NmtState.STOPPED:
            return stopped_status(self._last_status, self.node_id)
        status = read_status(self._sdo, seen)
        self._last_status = status
        return status

    @property
    def nmt_state(self) -> NmtState | None:
        """The node's NMT state: as this session's own NMT command left it (confirmed,
        :mod:`.nmt_confirm`) or as its last heartbeat told (None before either)."""
        return self._shared.node_seen(self.node_id).nmt_state

    def setpoint_link(self) -> SetpointLink:
        """RPDO1 (control word + 0x6300/0x6380, table 7-13): what a real valve has."""
        from prm9tool.device.canlink.rpdo_setpoint import RpdoSetpoint

        return RpdoSetpoint(self)

    def send_frame(self, cob_id: int, data: bytes) -> None:
        """Put one frame on the bus (a PDO); DeviceDisconnectedError when the bus refuses."""
        import can

        try:
            self._shared.network.send_message(cob_id, data)
        except (can.CanError, OSError, RuntimeError) as exc:  # RuntimeError: bus closed
            if self._shared.is_bus_off(exc):
                raise CanBusOffError(
                    f"node {self.node_id}: the CAN adapter is bus-off ({exc})"
                ) from None
            raise DeviceDisconnectedError(
                f"node {self.node_id}: the CAN bus refused to send 0x{cob_id:03X} ({exc})"
            ) from None

    def listen(self, cob_id: int, callback: Callable[[int, bytearray, float], None]) -> None:
        """Call ``callback(can_id, data, timestamp)`` for each frame with ``cob_id`` (a PDO),
        from the bus's receive thread, until :meth:`unlisten`."""
        self._shared.network.subscribe(cob_id, callback)

    def unlisten(self, cob_id: int, callback: Callable[[int, bytearray, float], None]) -> None:
        """Stop calling ``callback`` for ``cob_id``."""
        self._shared.network.unsubscribe(cob_id, callback)

    def nmt(self, command: int) -> None:
        """Send an NMT command (:class:`~prm9tool.catalogue.commissioning.NmtCommand`) to this
        node and confirm the state it asked for within a bound (:mod:`.nmt_confirm`: the next
        heartbeat, the first TPDO or an SDO read), so :attr:`nmt_state` tells it at once."""
        self._stopped_by_me = command == NmtCommand.STOP
        send_and_confirm(self._shared, self._sdo, self.node_id, command)

    # --- measuring points (the part it holds: canlink/stream.py) --------------------------
    def stream_start(self, keys: Sequence[str], rate_hz: int = 5000) -> None:
        """Sample ``keys`` at ``rate_hz``: TPDO1 at a SYNC the tool produces when they are its
        mapped value and the node is OPERATIONAL, else by SDO (what the bus does not deliver
        counts as lost; :attr:`stream_source` says which)."""
        self.stream.start(keys, rate_hz)

    @property
    def stream_source(self) -> str:
        """``pdo`` or ``sdo`` while a stream runs, else empty."""
        return self.stream.source

    def stream_read(self) -> np.ndarray:
        """Samples taken since the last call: shape (n, len(keys)), raw values."""
        return self.stream.read()

    @property
    def samples_lost(self) -> int:
        """Sample periods the bus could not serve since :meth:`stream_start`."""
        return self.stream.lost

    @property
    def sample_rate_hz(self) -> float:
        """The rate the running stream really achieves (0 when none runs)."""
        return self.stream.achieved_hz

    def stream_stop(self) -> None:
        """Stop sampling."""
        self.stream.stop()

    # --- internals --------------------------------------------------------------------------
    def _open_node(self, timeout_s: float) -> SdoChannel:
        import canopen

        network = self._shared.network
        with self._shared.lock:
            if self.node_id in network.nodes:
                raise Prm9Error(f"node {self.node_id} is already open in this program")
            node = canopen.RemoteNode(self.node_id, canopen.ObjectDictionary())
            network.add_node(node)
        return SdoChannel(node, timeout_s, self._shared)

    def _close_link(self) -> None:
        self.stream.stop()
        self._release()

    def _release(self) -> None:
        if self._closed:
            return
        self._closed = True
        network = self._shared.network
        with self._shared.lock:
            node = network.nodes.get(self.node_id)
            if (
                node is not None
                and getattr(self, "_sdo", None) is not None
                and node is self._sdo.node
            ):
                del network[self.node_id]
        canbus.release(self._shared)
