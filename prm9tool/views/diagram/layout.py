"""Where the blocks, junctions, arrows and measuring points of the signal-flow diagram go.

Pure data (no Qt widgets): the diagram of manual §8.7.2 (figures 8-6, 8-7) for a variant as a
list of blocks on a grid, the arrows between them and the position of every measuring point of
:mod:`prm9tool.catalogue.signals`. Block ids are the ``Signal.block`` names, so a red dot follows its block.

Grid (columns left to right, rows top to bottom)::

    row 0  [CANopen]   (E04: sensor input → sensor offset/gain → sensor lin.) ┐   [Supply]
    row 1  setpoint input → threshold → (E02: gain/offset) → lin. → ramps →(Σ E04 gain/offset)┐
    row 2  (E04: process PIDT1) → Σ position PIDT1 → current limiter → dither → valve
                                  └──────────── spool position (LVDT) ──────────┘
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass, field

from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.signals import signals_for
from prm9tool.catalogue.variant import Config, Variant

BLOCK_W = 168.0
BLOCK_H = 100.0  # a two-line title and three value lines
COL_PITCH = 238.0
ROW_PITCH = 160.0
LAST_COL_EXTRA = 36.0  # room for the dither's four live values in front of the valve
HEADER_H = 66.0  # height of the small header blocks (CANopen, supply): one-line title
MARGIN = 46.0
SUM_R = 9.0  # radius of a summing junction
DOT_STEP = 15.0  # vertical distance of measuring points stacked on a block's edge


def QT_TRANSLATE_NOOP(context: str, source: str) -> str:
    """Mark ``source`` for pyside6-lupdate (context ``context``); returns it untranslated.

    Qt's own QT_TRANSLATE_NOOP does the same but is typed as returning ``object``.
    """
    del context
    return source


@dataclass(frozen=True)
class BlockSpec:
    """One block of the diagram: what it is called and which parameters it edits."""

    id: str
    title: str  # English source text, translated at display time (context "DiagramBlock")
    mnemonics: tuple[str, ...]  # parameters the block's dialog edits (filtered by variant)
    col: int
    row: int
    info: bool = False  # True: shows values only, has no dialog
    compact: bool = False  # True: header-row height


@dataclass(frozen=True)
class Link:
    """An arrow from one block (or junction) to another; ``route`` picks the drawn path."""

    source: str
    target: str
    route: str = "right"  # right | wrap | feedback | sensor | down | into_sum


@dataclass(frozen=True)
class Layout:
    """The complete diagram of one variant."""

    variant: Variant
    blocks: tuple[BlockSpec, ...]
    sums: dict[str, str]  # junction id -> block it sits in front of
    links: tuple[Link, ...]
    dots: dict[str, tuple[str, str, int]]  # signal key -> (block id, side, stack index)
    compact_header: bool = True  # row 0 holds only the small header blocks
    same_as: dict[str, str] = field(default_factory=dict)  # undrawn signal -> dot with its value

    def block(self, block_id: str) -> BlockSpec:
        """The block with ``block_id``; KeyError if the variant has none."""
        for spec in self.blocks:
            if spec.id == block_id:
                return spec
        raise KeyError(block_id)

    def block_ids(self) -> list[str]:
        """Ids of every block, in signal order."""
        return [spec.id for spec in self.blocks]


def _present(variant: Variant, mnemonics: tuple[str, ...]) -> tuple[str, ...]:
    return tuple(mn for mn in mnemonics if CATALOGUE[mn].applies(variant))


def _curve(prefix: str) -> tuple[str, ...]:
    return tuple(f"{prefix}{axis}{p}" for axis in "XY" for p in "ABCDEFGHI")


SETPOINT_INPUT = ("AINSETP", "INVERSEP")
THRESHOLD = ("THRESETP",)
GAIN_OFFSET = ("GAINSETPOS", "GAINSETNEG", "OFFSETPOS", "OFFSETNEG")
SETPOINT_LIN = ("SETPLINON", *_curve("SETPLIN"))
RAMPS = ("RAMPSETPOSUP", "RAMPSETPOSDOWN", "RAMPSETNEGUP", "RAMPSETNEGDOWN")
POSITION_PIDT1 = ("POSKP", "POSKI", "POSKD", "POST1")
PROCESS_PIDT1 = ("PRCKP", "PRCKI", "PRCKD", "PRCT1")
CURRENT_LIMIT = ("LIMTA", "LIMTB")
DITHER = ("DTAMP", "DYNFREQ")
SENSOR_INPUT = ("SENSTYPE", "SENSINV")
SENSOR_SCALING = ("SENSOFFS", "SENSGAIN")
SENSOR_LIN = ("SENSLINON", *_curve("SENSLIN"))
CANOPEN = ("NODEID", "BITRATE", "CANTERM")


def _chain(variant: Variant) -> list[BlockSpec]:
    e04 = variant.config is Config.E04
    blocks = [
        BlockSpec(
            "setpoint_input",
            QT_TRANSLATE_NOOP("DiagramBlock", "Setpoint input"),
            SETPOINT_INPUT,
            0,
            1,
        ),
        BlockSpec("threshold", QT_TRANSLATE_NOOP("DiagramBlock", "Threshold"), THRESHOLD, 1, 1),
    ]
    if not e04:
        blocks.append(
            BlockSpec(
                "gain_offset", QT_TRANSLATE_NOOP("DiagramBlock", "Gain & offset"), GAIN_OFFSET, 2, 1
            )
        )
    lin_col = 2 if e04 else 3
    blocks += [
        BlockSpec(
            "setpoint_linearization",
            QT_TRANSLATE_NOOP("DiagramBlock", "Linearization"),
            SETPOINT_LIN,
            lin_col,
            1,
        ),
        BlockSpec("ramps", QT_TRANSLATE_NOOP("DiagramBlock", "Ramps"), RAMPS, lin_col + 1, 1),
    ]
    if e04:
        blocks += [
            BlockSpec(
                "gain_offset",
                QT_TRANSLATE_NOOP("DiagramBlock", "Deviation gain & offset"),
                GAIN_OFFSET,
                4,
                1,
            ),
            BlockSpec(
                "process_controller",
                QT_TRANSLATE_NOOP("DiagramBlock", "Process PIDT1"),
                PROCESS_PIDT1,
                0,
                2,
            ),
            BlockSpec(
                "ext_sensor",
                QT_TRANSLATE_NOOP("DiagramBlock", "External sensor"),
                SENSOR_INPUT,
                1,
                0,
            ),
            BlockSpec(
                "ext_sensor_scaling",
                QT_TRANSLATE_NOOP("DiagramBlock", "Sensor offset & gain"),
                SENSOR_SCALING,
                2,
                0,
            ),
            BlockSpec(
                "ext_sensor_linearization",
                QT_TRANSLATE_NOOP("DiagramBlock", "Sensor linearization"),
                SENSOR_LIN,
                3,
                0,
            ),
        ]
    blocks += [
        BlockSpec(
            "position_controller",
            QT_TRANSLATE_NOOP("DiagramBlock", "Position PIDT1"),
            POSITION_PIDT1,
            1,
            2,
        ),
        BlockSpec(
            "current_limit",
            QT_TRANSLATE_NOOP("DiagramBlock", "Current limiter"),
            CURRENT_LIMIT,
            2,
            2,
        ),
        BlockSpec("dither", QT_TRANSLATE_NOOP("DiagramBlock", "Dither"), DITHER, 3, 2),
        BlockSpec("valve", QT_TRANSLATE_NOOP("DiagramBlock", "Valve"), (), 4, 2),
    ]
    return blocks


def _header(variant: Variant) -> list[BlockSpec]:
    blocks = []
    if variant.canopen:
        blocks.append(
            BlockSpec(
                "canopen", QT_TRANSLATE_NOOP("DiagramBlock", "CANopen"), CANOPEN, 0, 0, compact=True
            )
        )
    blocks.append(
        BlockSpec(
            "supply", QT_TRANSLATE_NOOP("DiagramBlock", "Supply"), (), 4, 0, info=True, compact=True
        )
    )
    return blocks


def _links(variant: Variant) -> tuple[Link, ...]:
    e04 = variant.config is Config.E04
    setpoint = ["setpoint_input", "threshold"]
    setpoint += ["setpoint_linearization", "ramps"] if e04 else ["gain_offset"]
    if not e04:
        setpoint += ["setpoint_linearization", "ramps"]
    links = [Link(a, b) for a, b in itertools.pairwise(setpoint)]
    if e04:
        links += [
            Link("ramps", "sum_process"),
            Link("sum_process", "gain_offset"),
            Link("gain_offset", "process_controller", "wrap"),
            Link("process_controller", "sum_position"),
            Link("ext_sensor", "ext_sensor_scaling"),
            Link("ext_sensor_scaling", "ext_sensor_linearization"),
            Link("ext_sensor_linearization", "sum_process", "sensor"),
        ]
    else:
        links.append(Link("ramps", "sum_position", "wrap"))
    loop = ["sum_position", "position_controller", "current_limit", "dither", "valve"]
    links += [Link(a, b) for a, b in itertools.pairwise(loop)]
    links.append(Link("valve", "sum_position", "feedback"))
    if variant.canopen:
        links.append(Link("canopen", "setpoint_input", "down"))
    return tuple(links)


# Measuring points drawn nowhere because another dot on the same line shows the same value
# (the firmware computes them as copies, see prm9tool/device/emulator/kernel.py); the
# oscilloscope still offers them. E02: the ramp output goes straight into the position loop.
# E04 (process control, figure 8-7): the process setpoint is the ramp output, and the
# setpoint passes the gain block unchanged (gain and offset act on the process deviation).
SAME_AS: dict[Config, dict[str, str]] = {
    Config.E02: {"position_setpoint": "demand"},
    Config.E04: {"process_setpoint": "demand", "setpoint_gain": "setpoint_threshold"},
}
# Dots that sit on the input side of their block (after the junction) or on the feedback line.
_SIDE = {"position_deviation": "in", "position_actual": "feedback"}


def _dots(variant: Variant, block_ids: set[str]) -> dict[str, tuple[str, str, int]]:
    dots: dict[str, tuple[str, str, int]] = {}
    stacks: dict[tuple[str, str], int] = {}
    hidden = SAME_AS[variant.config]
    for sig in signals_for(variant):
        if sig.key in hidden:
            continue
        side = _SIDE.get(sig.key, "out")
        if sig.block not in block_ids and side != "feedback":
            raise ValueError(f"measuring point {sig.key}: block {sig.block} is not drawn")
        index = stacks.get((sig.block, side), 0)
        stacks[(sig.block, side)] = index + 1
        dots[sig.key] = (sig.block, side, index)
    return dots


def layout_for(variant: Variant) -> Layout:
    """The diagram of ``variant``: blocks in signal order, junctions, arrows, measuring points."""
    blocks = []
    for spec in [*_chain(variant), *_header(variant)]:
        mnemonics = _present(variant, spec.mnemonics)
        blocks.append(
            BlockSpec(spec.id, spec.title, mnemonics, spec.col, spec.row, spec.info, spec.compact)
        )
    sums = {"sum_position": "position_controller"}
    if variant.config is Config.E04:
        sums["sum_process"] = "gain_offset"
    ids = {b.id for b in blocks}
    compact = all(b.compact for b in blocks if b.row == 0)
    dots = _dots(variant, ids)
    same_as = dict(SAME_AS[variant.config])
    return Layout(variant, tuple(blocks), sums, _links(variant), dots, compact, same_as)


def row_top(row: int, compact_header: bool = False) -> float:
    """Scene y of the top edge of grid row ``row``."""
    if row == 0:
        return MARGIN
    shrink = BLOCK_H - HEADER_H if compact_header else 0.0
    return MARGIN + row * ROW_PITCH - shrink


def block_rect(spec: BlockSpec, compact_header: bool = False) -> tuple[float, float, float, float]:
    """Scene rectangle ``(x, y, w, h)`` of a block."""
    x = MARGIN + spec.col * COL_PITCH + (LAST_COL_EXTRA if spec.col == 4 else 0.0)
    height = HEADER_H if spec.compact else BLOCK_H
    return (x, row_top(spec.row, compact_header), BLOCK_W, height)
