"""The signal-flow diagram (manual §8.7.2, figures 8-6 and 8-7): the main view of the program.

Drawn from the document's variant; every block opens its configuration dialog; blocks the
access level may not change are grey; the red measuring points show live values online and
ask for the oscilloscope when clicked. The view only observes the document, the access model
and the valve connection through their signals. The valve block and the CANopen block ask the
main window (``valve_selection_requested``, ``canopen_requested``): valve selection replaces
the document through the file workflow (which asks about unsaved changes first), and the
CANopen window is the main window's single one.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from PySide6.QtCore import QCoreApplication, QEvent, QRectF, Qt, Signal
from PySide6.QtGui import (
    QContextMenuEvent,
    QKeySequence,
    QPainter,
    QResizeEvent,
    QShortcut,
    QWheelEvent,
)
from PySide6.QtWidgets import QDialog, QGraphicsView, QMenu, QWidget

from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.signals import BY_KEY
from prm9tool.i18n import format_measured, text
from prm9tool.model.access import AccessModel
from prm9tool.model.document import ParameterDocument
from prm9tool.online.connection_protocol import DiagramConnection, StepSimulation
from prm9tool.views.diagram.colours import DiagramColours
from prm9tool.views.diagram.layout import layout_for
from prm9tool.views.diagram.scene import DiagramScene
from prm9tool.views.diagram.summary import block_detail, block_lines

if TYPE_CHECKING:
    from prm9tool.views.diagram.dialogs import SimulatorFactory

_CTX = "DiagramBlock"
# Values a block shows besides the parameters it edits.
_ALSO_SHOWN = {"valve": ("PCODE",), "canopen": ("SWBAUD", "SWNODE")}
ZOOM_STEP = 1.15


# Short tags for measuring points that share a block with others of the same unit.
_TAGS = {
    "current_setpoint_a": "A",
    "current_setpoint_b": "B",
    "current_a": "A",
    "current_b": "B",
    "pwm_a": "PWM A",
    "pwm_b": "PWM B",
}


def format_signal(key: str, raw: float) -> str:
    """A measuring point's raw value in display units, e.g. ``12.5 %`` or ``A 1834 mA``;
    ``A —`` for no data (NaN: a point a valve over CANopen has no object for)."""
    signal = BY_KEY[key]
    tag = f"{_TAGS[key]} " if key in _TAGS else ""
    if math.isnan(raw):
        return f"{tag}—"
    value = signal.to_display(raw)
    return f"{tag}{format_measured(value, signal.unit)} {signal.unit}"


class DiagramView(QGraphicsView):
    """The diagram of ``document``'s variant; works offline and, with a connection, online."""

    measuring_point_clicked = Signal(str)  # measuring-point key
    dialog_opened = Signal(str, object)  # block id, the dialog widget
    valve_selection_requested = Signal()  # the valve block was clicked (offline)
    canopen_requested = Signal()  # the CANopen block was clicked
    tuning_requested = Signal(str)  # a controller dialog's "Tuning…": the loop

    def __init__(
        self,
        document: ParameterDocument,
        access: AccessModel,
        connection: DiagramConnection | None = None,
        parent: QWidget | None = None,
        simulator_factory: SimulatorFactory | None = None,
    ) -> None:
        super().__init__(parent)
        self._doc, self._access, self._connection = document, access, connection
        # the controller dialogs' step responses (tests inject a stand-in)
        self._simulator_factory = simulator_factory or _step_simulator
        self._dialogs: dict[str, QDialog] = {}
        self._fit = True
        self._signals: dict[str, float] = {}  # the last values, shown again in a new language
        self._scene: DiagramScene | None = None
        self.setRenderHints(QPainter.RenderHint.Antialiasing | QPainter.RenderHint.TextAntialiasing)
        self.setMinimumSize(480, 300)
        self._build()
        document.value_changed.connect(self._on_document_value_changed)
        document.values_reset.connect(self._refresh_blocks)
        document.type_key_changed.connect(self._on_type_key_changed)
        access.level_changed.connect(self._on_access_level_changed)
        if connection is not None:
            connection.online_changed.connect(self._on_online_changed)
            connection.signal_values_changed.connect(self._on_signal_values_changed)
        QShortcut(QKeySequence("Ctrl+0"), self, self.zoom_to_fit)
        QShortcut(QKeySequence.StandardKey.ZoomIn, self, self.zoom_in)
        QShortcut(QKeySequence.StandardKey.ZoomOut, self, self.zoom_out)
        self._on_online_changed(self.is_online)

    # --- public ----------------------------------------------------------------------------
    @property
    def diagram(self) -> DiagramScene:
        """The scene currently shown."""
        assert self._scene is not None
        return self._scene

    @property
    def document(self) -> ParameterDocument:
        """The document the diagram shows."""
        return self._doc

    @property
    def is_online(self) -> bool:
        """True while the connection reports a valve online."""
        return self._connection is not None and self._connection.is_online

    def block_ids(self) -> list[str]:
        """Ids of the drawn blocks, in signal order."""
        return self.diagram.layout.block_ids()

    def open_block(self, block_id: str) -> QDialog | None:
        """Open (or raise) the dialog of ``block_id``; returns it.

        None for the supply block (values only) and for the valve and CANopen blocks, whose
        windows belong to the main window: for those the view emits its request signal.
        """
        if block_id == "valve":
            if not self._valve_locked_reason():
                self.valve_selection_requested.emit()
            return None
        if block_id == "canopen":
            self.canopen_requested.emit()
            return None
        dialog = self._dialogs.get(block_id)
        if dialog is None:
            dialog = self._create_dialog(block_id)
            if dialog is None:
                return None
            self._dialogs[block_id] = dialog
            dialog.setObjectName(block_id)
            # bound methods only: a lambda holding ``self`` in a child's connection makes a
            # reference cycle that the garbage collector may break in the middle of a deletion
            dialog.finished.connect(self._on_dialog_finished)
        dialog.show()
        dialog.raise_()
        dialog.activateWindow()
        self.dialog_opened.emit(block_id, dialog)
        return dialog

    def zoom_to_fit(self) -> None:
        """Scale the whole diagram into the window (and keep it fitted on resize)."""
        self._fit = True
        self.fitInView(self.diagram.sceneRect(), Qt.AspectRatioMode.KeepAspectRatio)

    def zoom_in(self) -> None:
        """Enlarge the diagram by one step (Ctrl++, Ctrl+wheel)."""
        self._zoom(ZOOM_STEP)

    def zoom_out(self) -> None:
        """Shrink the diagram by one step (Ctrl+-, Ctrl+wheel)."""
        self._zoom(1 / ZOOM_STEP)

    def _zoom(self, factor: float) -> None:
        self._fit = False
        self.scale(factor, factor)

    def render_picture(self, painter: QPainter, target: QRectF) -> None:
        """Paint the diagram into ``target`` (print / PDF parameter record), aspect kept.

        The picture documents the parameter set: every block in normal ink whatever the
        access level, the red measuring points without live values (see :meth:`picture_scene`).
        """
        scene = self.picture_scene()
        scene.render(painter, target, scene.sceneRect(), Qt.AspectRatioMode.KeepAspectRatio)

    def picture_scene(self) -> DiagramScene:
        """A scene of the document's diagram for printing: dark ink on white whatever the
        screen's palette, no grey blocks, no live values."""
        scene = DiagramScene(layout_for(self._doc.variant))
        for spec in scene.layout.blocks:
            title = QCoreApplication.translate(_CTX, spec.title)
            scene.blocks[spec.id].set_content(title, block_lines(self._doc, spec.id))
        for dot in scene.dots.values():
            dot.set_active(True, "")
        return scene

    # --- building ---------------------------------------------------------------------------
    def _build(self) -> None:
        scene = DiagramScene(layout_for(self._doc.variant), self._screen_colours())
        for item in scene.blocks.values():
            item.activated.connect(self.open_block)
        for dot in scene.dots.values():
            dot.clicked.connect(self.measuring_point_clicked)
        old, self._scene = self._scene, scene
        self.setScene(scene)
        if old is not None:
            old.deleteLater()
        self._refresh_blocks()
        self._refresh_dots()
        if self._fit:
            self.zoom_to_fit()

    def _screen_colours(self) -> DiagramColours:
        """The diagram's colours on the view's (normally the application's) palette."""
        return DiagramColours.for_palette(self.palette())

    def _create_dialog(self, block_id: str) -> QDialog | None:
        # the block dialogs (and their plots) are imported when the first one opens
        from prm9tool.views.diagram.dialogs import BlockContext, create_block_dialog

        spec = self.diagram.layout.block(block_id)
        ctx = BlockContext(
            self._doc,
            self._access,
            self._connection,
            self._simulator_factory,
            self.tuning_requested.emit,
        )
        return create_block_dialog(block_id, ctx, spec.title, self)

    def _on_dialog_finished(self, _result: int) -> None:
        dialog = self._dialogs.pop(self.sender().objectName(), None)
        if dialog is not None:
            dialog.deleteLater()

    def close_dialogs(self) -> None:
        """Close every open block dialog (e.g. when the valve type changes)."""
        for block_id in list(self._dialogs):
            dialog = self._dialogs.pop(block_id)
            dialog.close()
            dialog.deleteLater()

    # --- refreshing -------------------------------------------------------------------------------
    def _refresh_blocks(self) -> None:
        for spec in self.diagram.layout.blocks:
            self._refresh_block(spec.id)

    def _refresh_block(self, block_id: str) -> None:
        spec = self.diagram.layout.block(block_id)
        item = self.diagram.blocks[block_id]
        item.set_content(
            QCoreApplication.translate(_CTX, spec.title), block_lines(self._doc, block_id)
        )
        reason = self._lock_reason(block_id)
        if spec.info:
            tip = self.tr("Values measured by the valve; see the red measuring points.")
        elif reason:
            tip = reason
        else:
            tip = self.tr("Click to edit: %1").replace(
                "%1", QCoreApplication.translate(_CTX, spec.title)
            )
        detail = block_detail(self._doc, block_id)
        item.set_locked(bool(reason), f"{detail}\n{tip}" if detail else tip)

    def _lock_reason(self, block_id: str) -> str:
        if block_id == "valve":
            return self._valve_locked_reason()
        spec = self.diagram.layout.block(block_id)
        params = [CATALOGUE[mn] for mn in spec.mnemonics]
        if not params or any(self._access.may_edit(p) for p in params):
            return ""
        return self._access.why_locked(params[0]) + " " + self.tr("(View → Access level)")

    def _valve_locked_reason(self) -> str:
        if self.is_online:
            return self.tr("Online, the valve type is that of the connected valve.")
        return ""

    def _refresh_dots(self) -> None:
        online = self.is_online
        for key, dot in self.diagram.dots.items():
            if online:
                tip = self._online_tip(key, math.isnan(self._signals.get(key, 0.0)))
            else:
                name = text(BY_KEY[key].text)
                tip = self.tr(
                    "%1 — offline: measuring points show live values only with a valve online."
                ).replace("%1", name)
            dot.set_active(online, tip)

    # --- slots ----------------------------------------------------------------------------------------
    def _on_document_value_changed(self, mnemonic: str) -> None:
        for spec in self.diagram.layout.blocks:
            if mnemonic in spec.mnemonics or mnemonic in _ALSO_SHOWN.get(spec.id, ()):
                self._refresh_block(spec.id)

    def _on_type_key_changed(self, _key: str) -> None:
        if self.diagram.layout.variant != self._doc.variant:
            self.close_dialogs()
            self._build()
            self._watch_signals()
        else:
            self._refresh_blocks()

    def _on_access_level_changed(self, _level: object) -> None:
        self._refresh_blocks()

    def _on_online_changed(self, online: bool) -> None:
        self._signals.clear()
        self._refresh_dots()
        self._refresh_block("valve")
        if online:
            self._watch_signals()

    def _watch_signals(self) -> None:
        if self._connection is not None and self.is_online:
            self._connection.watch_signals(list(self.diagram.dots))

    def _on_signal_values_changed(self, values: dict[str, float]) -> None:
        if not self.is_online:
            return
        self._signals.update(values)
        for key, raw in values.items():
            dot = self.diagram.dots.get(key)
            if dot is not None:
                dot.set_value_text(format_signal(key, raw))
                dot.setToolTip(self._online_tip(key, math.isnan(raw)))

    def _online_tip(self, key: str, no_value: bool) -> str:
        name = text(BY_KEY[key].text)
        if no_value:
            return self.tr(
                "%1 — no live value now: the valve streams three measuring points at a time and"
                " the oscilloscope is recording others (over CANopen: the valve has no object"
                " for this point)."
            ).replace("%1", name)
        return self.tr("%1 — click to show it in the oscilloscope").replace("%1", name)

    # --- Qt events -------------------------------------------------------------------------------------
    def resizeEvent(self, event: QResizeEvent) -> None:
        super().resizeEvent(event)
        if self._fit:
            self.fitInView(self.diagram.sceneRect(), Qt.AspectRatioMode.KeepAspectRatio)

    def wheelEvent(self, event: QWheelEvent) -> None:
        if event.modifiers() & Qt.KeyboardModifier.ControlModifier:
            self._zoom(ZOOM_STEP if event.angleDelta().y() > 0 else 1 / ZOOM_STEP)
            event.accept()
        else:
            super().wheelEvent(event)

    def contextMenuEvent(self, event: QContextMenuEvent) -> None:
        menu = QMenu(self)
        menu.addAction(self.tr("Zoom to fit") + "\tCtrl+0", self.zoom_to_fit)
        menu.addAction(self.tr("Zoom in"), self.zoom_in)
        menu.addAction(self.tr("Zoom out"), self.zoom_out)
        menu.exec(event.globalPos())

    def changeEvent(self, event: QEvent) -> None:
        if event.type() in (QEvent.Type.PaletteChange, QEvent.Type.ApplicationPaletteChange):
            if self._scene is not None:
                self._scene.set_colours(self._screen_colours())
        elif event.type() == QEvent.Type.LanguageChange:
            self.diagram.retranslate()
            self._refresh_blocks()
            self._refresh_dots()
            self._on_signal_values_changed(dict(self._signals))  # 0,0 % for 0.0 %
        super().changeEvent(event)


def _step_simulator(document: ParameterDocument, loop: str) -> StepSimulation:
    """The controller dialogs' step-response simulator (imported when first needed: the
    tuning module brings numpy and the emulator, ~150 ms the program's start need not wait)."""
    from prm9tool.online.tuning import StepSimulator

    return StepSimulator.for_document(document, loop)
