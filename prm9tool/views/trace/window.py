"""Communication → CAN trace: open a trace file (ASC, BLF, TRC, candump), read it in words —
a table of its events filtered by node and kind, its incidents, and a timeline of the values
its PDOs carried (pyqtgraph) — and record the bus (Record… / Stop). Decoding runs off the GUI
thread; a file that cannot be read is shown with its line, nothing else changes."""

from __future__ import annotations

import contextlib
import threading
from collections.abc import Callable
from pathlib import Path
from typing import cast

import pyqtgraph as pg
from PySide6.QtCore import QSettings, Qt, Signal
from PySide6.QtGui import QColor
from PySide6.QtWidgets import (
    QComboBox,
    QFileDialog,
    QHBoxLayout,
    QLabel,
    QListWidget,
    QListWidgetItem,
    QPushButton,
    QSplitter,
    QTableView,
    QVBoxLayout,
    QWidget,
)

from prm9tool.online.trace_recording import BusRecording
from prm9tool.trace.events import Kind, Trace
from prm9tool.translate import error_text
from prm9tool.views.localized_axis import LocalizedAxis
from prm9tool.views.screen_fit import fit_to_screen
from prm9tool.views.trace.model import ALL, NO_NODE, EventTableModel, Series, pdo_series
from prm9tool.views.trace.record_controls import TRACE_FILTER, RecordControls

FOLDER_KEY = "trace/folder"
SHOWN = ("POSSETP", "POSACT", "PRCSETP", "PRCACT")  # plotted at first: setpoints, actuals
COLOURS = ("#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf", "#8c564b")


class TraceWindow(QWidget):
    """A decoded CAN trace and the bus recording (see the module docstring)."""

    decoded = Signal(object)  # the Trace shown now
    _deliver = Signal(object)  # from the decoding thread: a Trace or the exception

    def __init__(
        self,
        recording: BusRecording,
        bus: Callable[[], dict[str, object]],
        settings: QSettings,
        parent: QWidget | None = None,
    ) -> None:
        super().__init__(parent, Qt.WindowType.Window)
        self.setWindowTitle(self.tr("CAN trace"))
        self._settings = settings
        self.trace: Trace | None = None
        self._curves: dict[tuple[int, str], pg.PlotDataItem] = {}  # made when first shown
        self._series: Series = {}
        self._colours: dict[tuple[int, str], str] = {}
        self._deliver.connect(self._on_delivered)
        self.open_button = QPushButton(self.tr("Open trace…"))
        self.open_button.clicked.connect(self._on_open_clicked)
        self.node = QComboBox()
        self.kind = QComboBox()
        self.node.currentIndexChanged.connect(self._on_filter_changed)
        self.kind.currentIndexChanged.connect(self._on_filter_changed)
        self.summary = QLabel(self.tr("Open a trace file (ASC, BLF, TRC or candump log)."))
        self.summary.setWordWrap(True)
        self.model = EventTableModel(self)
        self.table = QTableView()
        self.table.setModel(self.model)
        self.table.setSelectionBehavior(QTableView.SelectionBehavior.SelectRows)
        self.table.verticalHeader().setVisible(False)
        self.table.verticalHeader().setDefaultSectionSize(self.fontMetrics().height() + 6)
        self.table.horizontalHeader().setStretchLastSection(False)
        self.table.selectionModel().currentRowChanged.connect(self._on_row_changed)
        self.incidents = QListWidget()
        self.incidents.currentRowChanged.connect(self._on_incident_chosen)
        self.series = QListWidget()
        self.series.itemChanged.connect(self._on_series_toggled)
        # a layout widget holding the plot (pg.PlotWidget forwards unknown attributes to its
        # plot item, which breaks Qt's look-up of Python overrides once the item is deleted)
        self.graphics = pg.GraphicsLayoutWidget()
        axes = {name: LocalizedAxis(name) for name in ("left", "bottom")}
        self.plot = self.graphics.addPlot(row=0, col=0, axisItems=axes)
        self.plot.setLabel("bottom", self.tr("Time (s)"))
        for name in ("left", "bottom"):  # the label names the unit: no "(×0.001)" added to it
            self.plot.getAxis(name).enableAutoSIPrefix(False)
        self.plot.showGrid(x=True, y=True, alpha=0.3)
        self.plot.setClipToView(True)
        self.plot.setDownsampling(auto=True, mode="peak")
        self.time_line = pg.InfiniteLine(angle=90, movable=False)
        self.plot.addItem(self.time_line)
        self.recording = RecordControls(recording, bus, self)  # the bus chosen last
        self._build_layout()
        self._fill_filters()
        fit_to_screen(self, 1200, 800)

    def _build_layout(self) -> None:
        bar = QHBoxLayout()
        bar.addWidget(self.open_button)
        bar.addWidget(QLabel(self.tr("Node")))
        bar.addWidget(self.node)
        bar.addWidget(QLabel(self.tr("Kind")))
        bar.addWidget(self.kind)
        bar.addStretch(1)
        lower = QSplitter(Qt.Orientation.Horizontal)
        lower.addWidget(self.series)
        lower.addWidget(self.graphics)
        lower.setStretchFactor(1, 4)
        upper = QSplitter(Qt.Orientation.Horizontal)
        upper.addWidget(self.table)
        upper.addWidget(self.incidents)
        upper.setStretchFactor(0, 3)
        split = QSplitter(Qt.Orientation.Vertical)
        split.addWidget(upper)
        split.addWidget(lower)
        layout = QVBoxLayout(self)
        layout.addLayout(bar)
        layout.addWidget(self.summary)
        layout.addWidget(split, 1)
        layout.addWidget(self.recording)

    # --- opening ---------------------------------------------------------------------------
    def open_trace(self, path: str) -> None:
        """Decode ``path`` off the GUI thread; :attr:`decoded` when it is shown."""
        import prm9tool.trace as trace

        self.open_button.setEnabled(False)
        self.summary.setText(self.tr("Decoding {0}…").format(path))

        def decode() -> None:
            try:
                decoded = trace.read(path)
                result: object = (decoded, pdo_series(decoded))  # the series off the GUI thread too
            except Exception as exc:  # a Prm9Error, or a bug in the decoder: shown, not raised
                # without its traceback: its frames would keep this window alive in a cycle
                # past its deletion (a crash at the next LanguageChange)
                result = exc.with_traceback(None)
            with contextlib.suppress(RuntimeError):  # the window was closed meanwhile
                self._deliver.emit(result)

        threading.Thread(target=decode, name="can-trace-decode", daemon=True).start()

    def _on_open_clicked(self) -> None:
        folder = str(self._settings.value(FOLDER_KEY, ""))
        path, _filter = QFileDialog.getOpenFileName(
            self, self.tr("Open a CAN trace"), folder,
            self.tr("CAN traces ({0})").format(TRACE_FILTER),
        )  # fmt: skip
        if path:
            self._settings.setValue(FOLDER_KEY, str(Path(path).parent))
            self.open_trace(path)

    def _on_delivered(self, result: object) -> None:
        self.open_button.setEnabled(True)
        if isinstance(result, Exception):
            self.summary.setText(
                self.tr("The trace cannot be read: {0}").format(error_text(result))
            )
            return
        decoded, series = cast(tuple[Trace, Series], result)
        self.show_trace(decoded, series)

    def show_trace(self, trace: Trace, series: Series | None = None) -> None:
        """Show a decoded trace: table, filters, incidents, PDO series (``series``: computed
        already, else here)."""
        self.trace = trace
        self.model.set_trace(trace)
        self._fill_filters()
        self._fill_incidents()
        self._fill_series(pdo_series(trace) if series is None else series)
        if not trace.frames:  # nothing to plot: the first second from the start, no negative time
            self.plot.setRange(xRange=(0.0, 1.0), yRange=(0.0, 1.0), padding=0.0)
        self.summary.setText(self._summary_text(trace))
        self.table.resizeColumnsToContents()
        self.decoded.emit(trace)

    def _summary_text(self, trace: Trace) -> str:
        text = self.tr("{0}: {1} frames, {2} events, {3} not understood, {4} incidents").format(
            trace.path, trace.frames, len(trace.events), len(trace.not_understood),
            len(trace.incidents),
        )  # fmt: skip
        sync = trace.sync
        if sync.mean_period_s is not None and sync.jitter_s is not None:
            text += self.tr("; SYNC period {0:.3f} ms, jitter {1:.1f} µs").format(
                sync.mean_period_s * 1000, sync.jitter_s * 1e6
            )
        return text

    # --- filters, incidents, series ---------------------------------------------------------
    def _fill_filters(self) -> None:
        for combo in (self.node, self.kind):
            combo.blockSignals(True)
            combo.clear()
        self.node.addItem(self.tr("every node"), ALL)
        self.node.addItem(self.tr("the whole bus"), NO_NODE)
        nodes = {e.node for e in self.trace.events if e.node is not None} if self.trace else set()
        for node in sorted(nodes):
            self.node.addItem(self.tr("node {0}").format(node), node)
        self.kind.addItem(self.tr("every kind"), None)
        for kind in Kind:
            self.kind.addItem(kind.value, kind)
        for combo in (self.node, self.kind):
            combo.blockSignals(False)

    def _on_filter_changed(self) -> None:
        self.model.set_filter(int(self.node.currentData()), self.kind.currentData())

    def _fill_incidents(self) -> None:
        self.incidents.clear()
        start = self.trace.start if self.trace else 0.0
        for incident in self.trace.incidents if self.trace else ():
            item = QListWidgetItem(f"{incident.time - start:.6f}  {incident.what}")
            item.setData(Qt.ItemDataRole.UserRole, incident.frames[0] if incident.frames else None)
            self.incidents.addItem(item)

    def _on_incident_chosen(self, row: int) -> None:
        item = self.incidents.item(row)
        frame = item.data(Qt.ItemDataRole.UserRole) if item is not None else None
        if frame is None:
            return
        self.node.setCurrentIndex(0)
        self.kind.setCurrentIndex(0)
        found = self.model.row_of_frame(int(frame))
        if found is not None:
            self.table.selectRow(found)
            self.table.scrollTo(self.model.index(found, 0))

    def _fill_series(self, series: Series) -> None:
        for curve in self._curves.values():
            self.plot.removeItem(curve)
        self._curves.clear()
        self._series = series
        self.series.blockSignals(True)
        self.series.clear()
        shown = [key for key in series if key[1] in SHOWN] or list(series)[:4]
        order = shown + [key for key in series if key not in shown]  # distinct colours first
        self._colours = {key: COLOURS[k % len(COLOURS)] for k, key in enumerate(order)}
        for node, name in series:
            item = QListWidgetItem(self.tr("node {0}: {1}").format(node, name))
            item.setData(Qt.ItemDataRole.UserRole, (node, name))
            item.setForeground(QColor(self._colours[(node, name)]))
            item.setFlags(item.flags() | Qt.ItemFlag.ItemIsUserCheckable)
            visible = (node, name) in shown
            item.setCheckState(Qt.CheckState.Checked if visible else Qt.CheckState.Unchecked)
            self.series.addItem(item)
            if visible:
                self._show_curve((node, name), True)
        self.series.blockSignals(False)

    def _show_curve(self, key: tuple[int, str], visible: bool) -> None:
        """Show or hide one series; its curve is made when first shown (a trace of many
        nodes has dozens of series, most never looked at)."""
        curve = self._curves.get(key)
        if curve is None:
            if not visible:
                return
            times, values = self._series[key]
            pen = pg.mkPen(self._colours[key], width=1.5)
            curve = self._curves[key] = self.plot.plot(times, values, pen=pen)
        curve.setVisible(visible)

    def _on_series_toggled(self, item: QListWidgetItem) -> None:
        key = item.data(Qt.ItemDataRole.UserRole)
        if key in self._series:
            self._show_curve(key, item.checkState() == Qt.CheckState.Checked)

    def _on_row_changed(self, current: object, _previous: object) -> None:
        if self.trace is None or not getattr(current, "isValid", lambda: False)():
            return
        event = self.model.event_at(current.row())  # type: ignore[attr-defined]
        self.time_line.setValue(event.time - self.trace.start)
