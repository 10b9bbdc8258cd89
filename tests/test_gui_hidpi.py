"""HiDPI: at a device pixel ratio of 2 the whole window (diagram, icons, texts) is drawn with
twice the pixels, not scaled up from a low-resolution picture. Runs the program in a subprocess
because the scale factor must be set before the QApplication exists."""

from __future__ import annotations

import os
import textwrap

from PySide6.QtGui import QImage
from support.python_process import run_python

SCRIPT = textwrap.dedent(
    """
    import sys, tempfile
    from PySide6.QtCore import QSettings, QSize, QTimer
    from prm9tool import app
    from prm9tool.app import start_plan
    from prm9tool.cli.main import build_parser
    from prm9tool.views.icons import icon

    QSettings.setPath(QSettings.Format.NativeFormat, QSettings.Scope.UserScope, tempfile.mkdtemp())
    args = build_parser().parse_args(["--emulator", "PRM9-10.3Z11/60-24E04S02-CA"])
    qapp = app.create_application()
    window = app.create_window(args)
    window.resize(1024, 700)
    window.show()
    start_plan.start(window, start_plan.plan_from(args))

    def shot():
        picture = window.grab()
        picture.save(sys.argv[1])
        scope_icon = icon("scope").pixmap(QSize(24, 24), qapp.devicePixelRatio())
        print(picture.devicePixelRatio(), picture.width(), window.width(),
              scope_icon.width(), window.connection.is_online)
        qapp.quit()

    QTimer.singleShot(1500, shot)
    qapp.exec()
    window.connection.shutdown()
    """
)


def test_the_window_is_drawn_at_twice_the_pixels_on_a_scale_factor_of_2(tmp_path):
    env = dict(os.environ, QT_SCALE_FACTOR="2", PRM9TOOL_DATA_DIR=str(tmp_path / "data"))
    image = tmp_path / "hidpi.png"
    result = run_python("-c", SCRIPT, str(image), env=env)
    assert result.returncode == 0, result.stderr
    ratio, device_width, logical_width, icon_width, online = result.stdout.split()
    assert float(ratio) == 2.0 and int(device_width) == 2 * int(logical_width) == 2048
    assert int(icon_width) == 48  # the SVG icons are rendered at the device's resolution
    assert online == "True"
    assert QImage(str(image)).width() == 2048
