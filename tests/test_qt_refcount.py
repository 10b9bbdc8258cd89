"""Guard against the PySide6 6.12.0 bug that drops a reference to None on every void Qt call."""

from __future__ import annotations

import subprocess
import sys


def test_void_qt_calls_keep_the_refcount_of_none():
    # Run in a child process: with a broken binding the interpreter aborts (none_dealloc).
    code = (
        "import sys\n"
        "from PySide6.QtCore import QObject, QTimer\n"
        "obj = QObject(); timer = QTimer()\n"
        "before = sys.getrefcount(None)\n"
        "for i in range(5000):\n"
        "    obj.setObjectName('x')\n"
        "    timer.setInterval(i % 100 + 1)\n"
        "after = sys.getrefcount(None)\n"
        "print(after - before)\n"
    )
    result = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, timeout=120, check=False
    )
    assert result.returncode == 0, result.stderr
    # A handful of references may come and go with the interpreter; 10 000 lost ones may not.
    assert abs(int(result.stdout.strip())) < 50
