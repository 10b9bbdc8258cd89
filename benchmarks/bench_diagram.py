"""Signal-flow diagram and tuning simulator: costs against references measured in the same run.

    QT_QPA_PLATFORM=offscreen python benchmarks/bench_diagram.py [--quick]

Diagram: building the E04 -CA diagram, redrawing it (1024 x 640) and pushing one set of live
values, against a plain QGraphicsScene with the same number of rectangles and texts.
Tuning: one simulated closed-loop step response (what a controller dialog runs per slider
move), against advancing the emulated valve by the same simulated time without the step
set-up; and the speed-up over real time.
"""

from __future__ import annotations

import argparse
import os
import statistics
import sys
import time
from collections.abc import Callable

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")

from PySide6.QtCore import QObject, QRectF, Signal
from PySide6.QtGui import QColor, QImage, QPainter
from PySide6.QtWidgets import QApplication, QGraphicsScene

from prm9tool.catalogue import CATALOGUE, Access
from prm9tool.catalogue.signals import signals_for
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.characterize.frame import LOOPS, STEP_PRE_S
from prm9tool.device.emulator import EmulatedValve
from prm9tool.model.access import AccessModel
from prm9tool.model.document import ParameterDocument
from prm9tool.online.tuning import analog_type_key, simulate_step
from prm9tool.views.diagram import DiagramView

E04_CA = "PRM9-06.3Z11/30-24E04S02-CA"
E02 = "PRM9-06.3Z11/30-24E02S02"
QUICK = [False]  # --quick: every measurement once (a smoke run)


def median_ms(work: Callable[[], object], repeat: int) -> float:
    """Median wall time of ``work`` in milliseconds."""
    times = []
    for _ in range(1 if QUICK[0] else repeat):
        start = time.perf_counter()
        work()
        times.append(time.perf_counter() - start)
    return statistics.median(times) * 1000.0


class _Link(QObject):
    online_changed = Signal(bool)
    signal_values_changed = Signal(dict)
    is_online = True

    def watch_signals(self, keys: list[str]) -> None:
        self.keys = keys


def _render(scene: QGraphicsScene) -> None:
    image = QImage(1024, 640, QImage.Format.Format_ARGB32_Premultiplied)
    image.fill(QColor("white"))
    painter = QPainter(image)
    scene.render(painter, QRectF(0, 0, 1024, 640))
    painter.end()


def _reference_scene(items: int) -> QGraphicsScene:
    """A plain scene of the same size: half rounded-looking rectangles, half short texts."""
    scene = QGraphicsScene()
    for n in range(items // 2):
        scene.addRect(QRectF((n % 5) * 228.0, (n // 5) * 150.0, 158, 86))
    for n in range(items - items // 2):
        scene.addSimpleText(f"value {n}").setPos((n % 5) * 228.0, (n // 5) * 150.0 + 30)
    return scene


def bench_diagram() -> None:
    """Build, redraw and live-update the diagram against a plain scene."""
    doc = ParameterDocument(E04_CA)
    access = AccessModel(Access.EXPERT)
    link = _Link()
    views: list[DiagramView] = []

    def build() -> None:
        views.append(DiagramView(doc, access, link, simulator_factory=lambda _d, _l: None))

    build_ms = median_ms(build, 31)
    view = views[-1]
    scene = view.diagram
    blocks, dots, items = len(scene.blocks), len(scene.dots), len(scene.items())
    reference = _reference_scene(items)
    ref_build_ms = median_ms(lambda: _reference_scene(items), 31)
    render_ms = median_ms(lambda: _render(scene), 31)
    ref_render_ms = median_ms(lambda: _render(reference), 31)
    keys = [s.key for s in signals_for(doc.variant)]
    counter = iter(range(10**6))

    def live() -> None:
        n = next(counter)
        link.signal_values_changed.emit({key: float(n % 16384) for key in keys})

    def edit() -> None:
        doc.set_value("PRCKP", 300 + next(counter) % 1000)

    live_ms = median_ms(live, 50)
    edit_ms = median_ms(edit, 30)
    print(f"diagram E04-CA: {blocks} blocks, {dots} measuring points, {items} items")
    print(
        f"  build            {build_ms:7.2f} ms   plain scene {ref_build_ms:6.2f} ms   ratio {build_ms / ref_build_ms:5.1f}x"
    )
    print(
        f"  redraw 1024x640  {render_ms:7.2f} ms   plain scene {ref_render_ms:6.2f} ms   ratio {render_ms / ref_render_ms:5.1f}x"
    )
    print(
        f"  live values (all {dots} dots) {live_ms:6.3f} ms per update (the connection sends ~4 per second)"
    )
    print(f"  one document edit -> block label {edit_ms:6.3f} ms")


def bench_tuning() -> None:
    """One simulated step response per loop against the bare emulator."""
    for key, loop in ((E02, "position"), (E04_CA, "process")):
        variant = TypeKey.parse(key).variant
        values = {p.mnemonic: p.default_for(variant) for p in CATALOGUE.file_parameters(variant)}
        analog = analog_type_key(key)
        probe = EmulatedValve(analog)
        while probe.status().booting:  # as the EmulatorRig of the simulator boots it
            probe.advance(0.05)
        window = LOOPS[loop].simulated_s  # the autotune's step: rest, pre-step, window
        simulated = max(0.1, window) + STEP_PRE_S + window
        total = probe.time + simulated  # power-up and settling, then the step
        step_ms = median_ms(lambda k=key, v=values, lp=loop: simulate_step(k, v, lp), 11)

        def bare(seconds: float = total, analog: TypeKey = analog) -> None:
            EmulatedValve(analog).advance(seconds)

        bare_ms = median_ms(bare, 11)
        print(
            f"step response {loop:8s}: {total * 1000:5.0f} ms simulated in {step_ms:6.1f} ms wall "
            f"= {total * 1000 / step_ms:5.1f}x real time; bare emulator (same simulated time, no "
            f"parameters, no capture) {bare_ms:6.1f} ms, ratio {step_ms / bare_ms:4.2f}x"
        )


def main() -> int:
    """Run both benchmarks."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="a smoke run: seconds, not figures")
    QUICK[0] = parser.parse_args().quick
    app = QApplication.instance() or QApplication(sys.argv)
    assert app is not None
    print(f"Python {sys.version.split()[0]}")
    bench_diagram()
    bench_tuning()
    return 0


if __name__ == "__main__":
    sys.exit(main())
