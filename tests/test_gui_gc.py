"""The GUI's cycle collector: run on the GUI thread from a timer, in short pauses.

A full collection every second walked the ~150 000 objects of the window and held the GIL for
0.14 s (idle PC) to 0.8 s (loaded PC): the valve connection's worker sent no report meanwhile
and the valve dropped its setpoint override (0.5 s without a report) in the middle of the
GUI's end-of-line test (static gain 0.24, hysteresis 100 %), while the headless test passed.
"""

from __future__ import annotations

import gc
import weakref

from PySide6.QtCore import QObject, QTimer

from prm9tool import app as gui_app


def test_the_timer_collects_the_young_generations_and_everything_only_rarely(qapp):
    owner = QObject()  # stands for the application: the timer is its child
    gui_app.collect_garbage_on_the_gui_thread(owner)  # type: ignore[arg-type]
    (timer,) = owner.findChildren(QTimer)
    assert timer.interval() == gui_app.GC_INTERVAL_MS and not gc.isenabled()
    generations: list[int] = []

    def seen(phase: str, info: dict[str, int]) -> None:
        if phase == "start":
            generations.append(info["generation"])

    gc.callbacks.append(seen)
    try:
        for _ in range(2 * gui_app.FULL_COLLECTION_EVERY):
            timer.timeout.emit()
    finally:
        gc.callbacks.remove(seen)
        timer.stop()
    assert len(generations) == 2 * gui_app.FULL_COLLECTION_EVERY  # one collection per tick
    assert generations.count(2) == 2  # a full one every FULL_COLLECTION_EVERY ticks
    assert set(generations) == {1, 2}  # the others: the young generations (0 and 1)


class _Node:
    def __init__(self) -> None:
        self.other: _Node | None = None


def test_the_start_up_objects_are_frozen_and_the_garbage_collected_first():
    kept = _Node()  # an object of the start-up (a widget, a module's table)
    garbage, partner = _Node(), _Node()
    garbage.other, partner.other = partner, garbage  # a cycle nobody refers to any more
    gone = weakref.ref(garbage)
    del garbage, partner
    try:
        gui_app.freeze_start_up_objects()
        assert gone() is None  # collected, not frozen for the rest of the session
        assert gc.get_freeze_count() > 0
        assert not any(o is kept for o in gc.get_objects(generation=2))  # no longer walked
    finally:
        gc.unfreeze()
    assert any(o is kept for o in gc.get_objects(generation=2))
