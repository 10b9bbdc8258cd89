"""The configuration dialogs of the diagram's blocks (manual §8.7.2 "Podrobný popis ...")."""

from __future__ import annotations

from collections.abc import Callable

from PySide6.QtWidgets import QWidget

from prm9tool.catalogue.variant import Config
from prm9tool.views.diagram.dialogs.base import BlockContext, BlockDialog, SimulatorFactory
from prm9tool.views.diagram.dialogs.controller import ControllerDialog
from prm9tool.views.diagram.dialogs.current_dither import CurrentDitherDialog
from prm9tool.views.diagram.dialogs.linearization import LinearizationDialog
from prm9tool.views.diagram.dialogs.ramps import RampsDialog
from prm9tool.views.diagram.dialogs.sensor_scaling import SensorScalingDialog
from prm9tool.views.diagram.dialogs.signal_input import SignalInputDialog
from prm9tool.views.diagram.dialogs.threshold_gain import ThresholdGainDialog

__all__ = ["BlockContext", "BlockDialog", "SimulatorFactory", "create_block_dialog"]

Factory = Callable[[BlockContext, str, str, QWidget | None], BlockDialog]


def _threshold(ctx: BlockContext, block: str, title: str, parent: QWidget | None) -> BlockDialog:
    # E02: one window for threshold, gain and offset (figure 8-9); E04: gain/offset act on the
    # process deviation and have a block of their own.
    e02 = ctx.document.variant.config is Config.E02
    return ThresholdGainDialog(ctx, block, title, True, e02, parent)


def _gain(ctx: BlockContext, block: str, title: str, parent: QWidget | None) -> BlockDialog:
    e02 = ctx.document.variant.config is Config.E02
    return ThresholdGainDialog(ctx, block, title, e02, True, parent)


_FACTORIES: dict[str, Factory] = {
    "setpoint_input": lambda c, b, t, p: SignalInputDialog(c, b, t, "AINSETP", "INVERSEP", p),
    "threshold": _threshold,
    "gain_offset": _gain,
    "setpoint_linearization": lambda c, b, t, p: LinearizationDialog(
        c, b, t, "SETPLIN", "SETPLINON", p
    ),
    "ramps": lambda c, b, t, p: RampsDialog(c, b, t, p),
    "process_controller": lambda c, b, t, p: ControllerDialog(c, b, t, "PRC", "process", p),
    "position_controller": lambda c, b, t, p: ControllerDialog(c, b, t, "POS", "position", p),
    "current_limit": lambda c, b, t, p: CurrentDitherDialog(c, b, t, p),
    "dither": lambda c, b, t, p: CurrentDitherDialog(c, b, t, p),
    "ext_sensor": lambda c, b, t, p: SignalInputDialog(c, b, t, "SENSTYPE", "SENSINV", p),
    "ext_sensor_scaling": lambda c, b, t, p: SensorScalingDialog(c, b, t, p),
    "ext_sensor_linearization": lambda c, b, t, p: LinearizationDialog(
        c, b, t, "SENSLIN", "SENSLINON", p
    ),
}


def create_block_dialog(
    block_id: str, ctx: BlockContext, title: str, parent: QWidget | None = None
) -> BlockDialog | None:
    """The dialog of block ``block_id``, or None for blocks without one (valve, CANopen, supply)."""
    factory = _FACTORIES.get(block_id)
    return factory(ctx, block_id, title, parent) if factory is not None else None
