"""The decoder: a trace's frames in, :class:`~prm9tool.trace.events.Event` records out, node by
node (NMT and heartbeats, SDO transfers, PDOs by the mapping in force, CiA 408 state
transitions, EMCY, SYNC, TIME, LSS, error frames), and every frame accounted for. No Qt."""

from __future__ import annotations

from array import array
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.pdo import mapping_for_control_mode
from prm9tool.device.canlink.status import device_state
from prm9tool.trace import words
from prm9tool.trace.dictionary import (
    DEVICE_TYPE,
    VENDOR_ID,
    EdsDictionary,
    NodeDictionary,
    Prm9Dictionary,
    RawDictionary,
)
from prm9tool.trace.events import Event, Kind, Trace
from prm9tool.trace.incidents import IncidentFinder
from prm9tool.trace.pdo import Pdo, PdoMaps
from prm9tool.trace.sdo import DOWNLOAD, SdoTracker, Transfer

if TYPE_CHECKING:
    import can

LSS_MASTER, LSS_SLAVE = 0x7E5, 0x7E4
CONTROL_MODE = CATALOGUE["CTRLMODE"].key  # 0x6043: table 7-13's entry 2 follows it
_PRM9 = Prm9Dictionary()
PDO_CACHE = 4096  # decoded payloads kept per PDO
# a PDO's text, its values and the control/status words in it
_PdoText = tuple[str, tuple[tuple[str, float | int | str], ...], tuple[tuple[int, int], ...]]
_RAW = RawDictionary()


@dataclass
class _Node:
    number: int
    od: NodeDictionary
    sdo: SdoTracker = field(default_factory=SdoTracker)
    control_mode: int = 2
    status_word: int | None = None
    control_word: int | None = None
    heard: bool = False  # it sent a frame (an SDO response, heartbeat, EMCY, TPDO)


class Decoder:
    """Decodes frames one at a time; :meth:`result` gives the :class:`Trace`.

    ``eds``: EDS files by node (None as the key: every node that shows it is no PRM9 — its
    device type 0x1000 or vendor ID 0x1018/1 read in the trace differs). Nodes are PRM9 valves
    until the trace or ``eds`` says otherwise.
    """

    def __init__(self, path: str = "", eds: Mapping[int | None, str | Path] | None = None) -> None:
        self.path = path
        self._eds = dict(eds or {})
        self._nodes: dict[int, _Node] = {}
        self._pdos = PdoMaps()
        self.events: list[Event] = []
        self._sync = array("d")
        self._sync_frames = array("q")
        self._count = 0
        self._start = 0.0
        self.incidents = IncidentFinder()

    # --- frames in ---------------------------------------------------------------------
    def feed_all(self, messages: Iterable[can.Message]) -> Trace:
        """Decode every frame of ``messages``; the decoded trace."""
        feed = self.feed
        for message in messages:
            feed(message)
        return self.result()

    def feed(self, msg: can.Message) -> None:
        """Decode one frame."""
        number = self._count
        self._count += 1
        time = msg.timestamp
        if not number:
            self._start = time
        if msg.is_error_frame:
            self._emit(Event(time, None, Kind.ERROR_FRAME, _error_frame_text(msg), (number,)))
            return
        data = bytes(msg.data)
        if msg.is_extended_id or msg.is_remote_frame or msg.is_fd:
            what = (
                "extended-ID"
                if msg.is_extended_id
                else "remote"
                if msg.is_remote_frame
                else "CAN FD"
            )
            self._not_understood(number, time, msg.arbitration_id, data, f"{what} frame")
            return
        cob = msg.arbitration_id
        handler = _HANDLERS.get(cob >> 7)
        if handler is None:
            self._not_understood(number, time, cob, data, "no CANopen service uses this COB-ID")
            return
        handler(self, number, time, cob, data)

    def result(self) -> Trace:
        """The trace decoded so far, transfers still open listed as incomplete."""
        for node in self._nodes.values():
            for item in node.sdo.finish("the trace ended before its end"):
                self._sdo_item(node, item, 0.0)
        self.events.sort(key=lambda e: e.frames[0] if e.frames else -1)
        nodes = {n: node.od.kind for n, node in self._nodes.items() if node.heard}
        incidents, sync = self.incidents.finish(self.events, self._sync, self._sync_frames)
        return Trace(self.path, self._count, self.events, incidents, sync, nodes, self._start)

    # --- services ------------------------------------------------------------------------
    def _nmt(self, number: int, time: float, cob: int, data: bytes) -> None:
        if cob != 0:
            self._not_understood(number, time, cob, data, "no CANopen service uses this COB-ID")
            return
        if len(data) != 2:
            self._not_understood(number, time, cob, data, "NMT command not 2 bytes long")
            return
        target = data[1]
        text = (
            f"NMT {words.nmt_command_text(data[0])} → {f'node {target}' if target else 'all nodes'}"
        )
        self._emit(Event(time, target or None, Kind.NMT, text, (number,)))
        if data[0] in (0x81, 0x82):
            for node in self._nodes.values() if target == 0 else [self._node(target)]:
                self._reset(node)

    def _sync_or_emcy(self, number: int, time: float, cob: int, data: bytes) -> None:
        if cob == 0x80:
            self._sync.append(time)
            self._sync_frames.append(number)
            counter = f", counter {data[0]}" if data else ""
            self._emit(Event(time, None, Kind.SYNC, f"SYNC{counter}", (number,)))
            return
        node = self._node(cob & 0x7F)
        node.heard = True
        if len(data) < 3:
            self._not_understood(number, time, cob, data, "EMCY shorter than 3 bytes")
            return
        code = int.from_bytes(data[:2], "little")
        text = f"EMCY 0x{code:04X}: {words.emcy_text(code)}, error register 0x{data[2]:02X}"
        if len(data) > 3 and any(data[3:]):
            text += f", manufacturer data {data[3:].hex(' ').upper()}"
        self._emit(Event(time, node.number, Kind.EMCY, text, (number,), (("code", code),)))

    def _time_or_pdo(self, number: int, time: float, cob: int, data: bytes) -> None:
        if cob == 0x100:
            self._emit(
                Event(time, None, Kind.TIME, f"TIME stamp {data.hex(' ').upper()}", (number,))
            )
            return
        self._pdo(number, time, cob, data)

    def _pdo(self, number: int, time: float, cob: int, data: bytes) -> None:
        pdo = self._pdos.by_cob(cob)
        if pdo is None and cob & 0x7F and (cob & 0x7F) not in self._nodes:
            self._node(cob & 0x7F)  # a node seen first by its PDO: its defaults
            pdo = self._pdos.by_cob(cob)
        if pdo is None:
            self._not_understood(number, time, cob, data, "no PDO mapping known for this COB-ID")
            return
        node = self._nodes[pdo.node]
        node.heard = node.heard or not pdo.receive
        if len(data) < pdo.length():
            text = f"{pdo.name} with {len(data)} bytes, shorter than its mapping ({pdo.length()} bytes)"
            self._emit(Event(time, pdo.node, Kind.PDO, text, (number,)))
            return
        self._pdo_values(node, pdo, number, time, data)

    def _pdo_values(self, node: _Node, pdo: Pdo, number: int, time: float, data: bytes) -> None:
        cached: _PdoText | None = pdo.decoded.get(data)  # type: ignore[assignment]
        if cached is None:
            if len(pdo.decoded) >= PDO_CACHE:
                pdo.decoded.clear()
            cached = pdo.decoded[data] = self._pdo_text(node, pdo, data)
        text, values, words_seen = cached
        for index, word in words_seen:
            self._word(node, index, word, number, time)
        self._emit(Event(time, pdo.node, Kind.PDO, text, (number,), values))

    @staticmethod
    def _pdo_text(node: _Node, pdo: Pdo, data: bytes) -> _PdoText:
        """A PDO's text, values and control/status words (cached per PDO and data bytes)."""
        parts, values, words_seen = [], [], []
        for index, sub, reading in pdo.decode(data, node.od):
            if reading is None:
                parts.append(f"0x{index:04X}/{sub}: unknown object")
                continue
            parts.append(reading.text)
            values.append((reading.name, reading.value))
            if (index, sub) in _WORDS:
                words_seen.append((index, reading.value if isinstance(reading.value, int) else 0))
        text = f"{pdo.name}: " + ("; ".join(parts) if parts else "no objects mapped")
        return text, tuple(values), tuple(words_seen)

    def _sdo(self, number: int, time: float, cob: int, data: bytes) -> None:
        node = self._node(cob & 0x7F)
        request = cob >> 7 == 0x0C
        node.heard = node.heard or not request
        for item in node.sdo.feed(number, time, data, request):
            self._sdo_item(node, item, time)

    def _sdo_item(self, node: _Node, item: Transfer | int, time: float) -> None:
        if isinstance(item, int):
            self._emit(
                Event(
                    time, node.number, Kind.NOT_UNDERSTOOD, "SDO frame outside a transfer", (item,)
                )
            )
            return
        address = f"0x{item.index:04X}/{item.subindex}"
        reading = node.od.read(item.index, item.subindex, item.data) if item.data else None
        what = f": {reading.text}" if reading else f" = {item.data.hex(' ').upper() or '(no data)'}"
        verb = (
            "SDO"
            if item.how == "abort"
            else "SDO write"
            if item.direction == DOWNLOAD
            else "SDO read"
        )
        if item.abort is not None:
            name = reading.name if reading else _object_name(node.od, item.index, item.subindex)
            text = (
                f"{verb} {address}{name} aborted: 0x{item.abort:08X} {words.abort_text(item.abort)}"
            )
        elif item.incomplete:
            text = f"{verb} {address} incomplete ({item.how}): {item.incomplete}"
        else:
            text = f"{verb} ({item.how}) {address}{what}"
            self._object_seen(node, item)
        values = ((reading.name, reading.value),) if reading and item.abort is None else ()
        self._emit(Event(item.time, node.number, Kind.SDO, text, item.frames, values))

    def _heartbeat(self, number: int, time: float, cob: int, data: bytes) -> None:
        if cob in (LSS_MASTER, LSS_SLAVE):
            self._emit(
                Event(time, None, Kind.LSS, words.lss_text(data, cob == LSS_MASTER), (number,))
            )
            return
        if cob >> 7 != 0xE or not cob & 0x7F:
            self._not_understood(number, time, cob, data, "no CANopen service uses this COB-ID")
            return
        if len(data) != 1:
            self._not_understood(number, time, cob, data, "heartbeat not 1 byte long")
            return
        node = self._node(cob & 0x7F)
        node.heard = True
        text = words.heartbeat_text(data[0])
        self._emit(Event(time, node.number, Kind.HEARTBEAT, text, (number,)))
        if data[0] & 0x7F == 0:
            self._reset(node)

    # --- state ------------------------------------------------------------------------
    def _node(self, number: int) -> _Node:
        node = self._nodes.get(number)
        if node is None:
            od = self._dictionary(number, identified=False)
            node = self._nodes[number] = _Node(number, od)
            self._pdos.add_defaults(number, od, node.control_mode)
        return node

    def _dictionary(self, number: int, identified: bool) -> NodeDictionary:
        if number in self._eds:
            return EdsDictionary(self._eds[number], number)
        if not identified:
            return _PRM9
        return EdsDictionary(self._eds[None], number) if None in self._eds else _RAW

    def _reset(self, node: _Node) -> None:
        """A reset (node or communication) or a boot-up: PDOs back to their defaults."""
        node.control_mode = 2
        self._pdos.forget(node.number)
        self._pdos.add_defaults(node.number, node.od, node.control_mode)

    def _object_seen(self, node: _Node, item: Transfer) -> None:
        """A value written or read: PDO objects, the control mode, the node's identity."""
        if not item.data or len(item.data) > 4:
            return
        value = int.from_bytes(item.data, "little")
        key = (item.index, item.subindex)
        self._pdos.written(node.number, item.index, item.subindex, value)
        if key == CONTROL_MODE and node.od is _PRM9:
            node.control_mode = value
            for name, sub in (("RPDO1MAP2", 2), ("TPDO1MAP2", 2)):
                param = CATALOGUE[name]
                entry = mapping_for_control_mode(param, value)
                self._pdos.written(node.number, param.index, sub, entry)
        elif key == (0x6040, 0) or (key == (0x6041, 0) and item.direction != DOWNLOAD):
            self._word(node, item.index, value, item.frames[-1], item.time)
        elif key in ((0x1000, 0), (0x1018, 1)) and node.od is _PRM9:
            expected = DEVICE_TYPE if key == (0x1000, 0) else VENDOR_ID
            if (value & 0xFFFF if key == (0x1000, 0) else value) != expected:
                node.od = self._dictionary(node.number, identified=True)
                self._pdos.forget(node.number)
                self._pdos.add_defaults(node.number, node.od, node.control_mode)
        self.incidents.configured(node.number, key, value)

    def _word(self, node: _Node, index: int, word: int, number: int, time: float) -> None:
        """A control word (0x6040) or status word (0x6041): a state event when it changes."""
        if index == 0x6041:
            before, node.status_word = node.status_word, word
            if before is not None and device_state(before) == device_state(word):
                return
            old = f"{device_state(before).value} → " if before is not None else ""
            text = f"device state {old}{words.status_word_text(word)}"
            self._emit(
                Event(time, node.number, Kind.STATE, text, (number,), (("status word", word),))
            )
            return
        before, node.control_word = node.control_word, word
        if before == word:
            return
        old = f"0x{before:04X} → " if before is not None else ""
        text = f"control word {old}{words.control_word_text(word)}"
        self._emit(Event(time, node.number, Kind.STATE, text, (number,), (("control word", word),)))

    def _emit(self, event: Event) -> None:
        self.events.append(event)

    def _not_understood(self, number: int, time: float, cob: int, data: bytes, why: str) -> None:
        text = f"{cob:03X} {data.hex(' ').upper()}: not understood ({why})"
        self._emit(Event(time, None, Kind.NOT_UNDERSTOOD, text, (number,)))


_WORDS = {(0x6040, 0), (0x6041, 0)}


def _object_name(od: NodeDictionary, index: int, subindex: int) -> str:
    reading = od.read(index, subindex, bytes(4))
    return f" {reading.name}" if reading else ""


def _error_frame_text(msg: can.Message) -> str:
    from prm9tool.device.canlink.bus import CAN_ERR_BUSOFF, CAN_ERR_RESTARTED

    if msg.arbitration_id & CAN_ERR_BUSOFF:
        return "error frame: the adapter went bus-off"
    if msg.arbitration_id & CAN_ERR_RESTARTED:
        return "error frame: the adapter restarted after bus-off"
    return f"error frame (class 0x{msg.arbitration_id:X}, data {bytes(msg.data).hex(' ').upper()})"


_Handler = Callable[[Decoder, int, float, int, bytes], None]
# by the function code (COB-ID bits 10…7), CiA 301's predefined connection set
_HANDLERS: dict[int, _Handler] = {
    0x0: Decoder._nmt,
    0x1: Decoder._sync_or_emcy,
    0x2: Decoder._time_or_pdo,
    **dict.fromkeys(range(3, 11), Decoder._pdo),
    0xB: Decoder._sdo,
    0xC: Decoder._sdo,
    0xE: Decoder._heartbeat,
    0xF: Decoder._heartbeat,
}
