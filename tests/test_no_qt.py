"""The packages that claim "no Qt" import without PySide6 and pyqtgraph (scripts, batch, emulator).

import-linter checks the import graph (pyproject.toml); this imports every module for real in a
fresh process where a meta-path finder refuses PySide6 and pyqtgraph, so a lazy import at module
level or a package ``__init__`` that re-exports too much fails here too.
"""

from __future__ import annotations

import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
# The one module of these packages that is Qt by design (as in pyproject.toml's contract): it
# turns a file into the QtCore document the views edit.
EXCEPTIONS = ("prm9tool.files.prmdocument:",)
QT_FREE = (
    "api",
    "service",
    "analysis",
    "characterize",
    "trace",
    "twin",
    "scope",
    "compare",
    "history",
    "device",
    "files",
    "catalogue",
)

PROBE = textwrap.dedent(
    """
    import importlib, pkgutil, sys

    class NoQt:
        def find_spec(self, name, path=None, target=None):
            if name.partition(".")[0] in ("PySide6", "pyqtgraph"):
                raise ImportError(f"{name} is blocked")
            return None

    sys.meta_path.insert(0, NoQt())
    failed = []
    for statement in sys.argv[2:]:
        try:
            exec(statement)
        except ImportError as exc:
            failed.append(f"{statement}: {exc}")
    package = importlib.import_module(sys.argv[1])
    names = [sys.argv[1]] + [
        m.name for m in pkgutil.walk_packages(package.__path__, sys.argv[1] + ".")
        if ".migrations" not in m.name  # Alembic's scripts run inside Alembic only
    ]
    for name in names:
        try:
            importlib.import_module(name)
        except ImportError as exc:
            if "_ckernel" in str(exc):  # the compiled control loop, not built on this checkout
                continue
            failed.append(f"{name}: {exc}")
    print(len(names))
    print("\\n".join(failed))
    """
)


def _import_without_qt(package: str, *statements: str) -> tuple[int, list[str]]:
    done = subprocess.run(
        [sys.executable, "-c", PROBE, package, *statements],
        cwd=ROOT,
        capture_output=True,
        text=True,
        check=True,
    )
    count, *failed = done.stdout.splitlines()
    return int(count), [line for line in failed if line]


@pytest.mark.parametrize("package", QT_FREE)
def test_every_module_of_a_qt_free_package_imports_without_pyside6(package):
    count, failed = _import_without_qt(f"prm9tool.{package}")
    assert [line for line in failed if not line.startswith(EXCEPTIONS)] == []
    assert count >= 1


def test_the_tuning_procedures_import_without_pyside6():
    _, failed = _import_without_qt(
        "prm9tool.characterize", "import prm9tool.characterize.procedures"
    )
    assert failed == []


def test_the_probe_sees_a_module_that_needs_qt():
    """The finder really blocks: the model's document is a QObject and fails to import."""
    _, failed = _import_without_qt("prm9tool.model")
    assert any(line.startswith("prm9tool.model.document:") for line in failed)
