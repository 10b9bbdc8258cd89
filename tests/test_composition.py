"""Composition instead of size-driven mixins (issue 28 item 4, docs/ARCHITECTURE.md "Parts, not
mixins"): no class takes a second class of this project as a base, and no class takes a base
that the type checker sees as another class than the interpreter does (``_Base = QObject`` under
``if TYPE_CHECKING:``, ``object`` otherwise) — a class grown too big gets parts it holds."""

from __future__ import annotations

import ast
import enum
import importlib
import inspect
from pathlib import Path

import pytest

PACKAGE = Path(__file__).parents[1] / "prm9tool"
LEFT_OUT = ("views/resources_rc.py", "history/migrations/")


def _modules() -> list[Path]:
    return [
        p
        for p in sorted(PACKAGE.rglob("*.py"))
        if not any(p.relative_to(PACKAGE).as_posix().startswith(s) for s in LEFT_OUT)
    ]


def _module_name(path: Path) -> str:
    parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _checker_only_names(tree: ast.Module) -> set[str]:
    """Names a module assigns in an ``if TYPE_CHECKING:`` statement (either branch)."""
    names: set[str] = set()
    for node in tree.body:
        test = node.test if isinstance(node, ast.If) else None
        if isinstance(test, ast.Name) and test.id == "TYPE_CHECKING":
            for stmt in [*node.body, *node.orelse]:
                if isinstance(stmt, ast.Assign):
                    names |= {t.id for t in stmt.targets if isinstance(t, ast.Name)}
    return names


def test_no_class_takes_a_base_only_the_type_checker_sees():
    found = []
    for path in _modules():
        tree = ast.parse(path.read_text(encoding="utf-8"))
        tricks = _checker_only_names(tree)
        for node in ast.walk(tree):
            if isinstance(node, ast.ClassDef):
                bases = {b.id for b in node.bases if isinstance(b, ast.Name)}
                if bases & tricks:
                    found.append(f"{path.relative_to(PACKAGE)}: {node.name}({', '.join(bases)})")
    assert found == []


def _own_bases(cls: type) -> list[str]:
    """The bases of ``cls`` that are classes of this project (not protocols, errors, enums)."""
    return [
        b.__qualname__
        for b in cls.__bases__
        if b.__module__.startswith("prm9tool")
        and not getattr(b, "_is_protocol", False)
        and not issubclass(b, BaseException | enum.Enum)
    ]


@pytest.mark.usefixtures("qapp")
def test_no_class_is_mixed_from_two_classes_of_this_project():
    found = []
    for path in _modules():
        name = _module_name(path)
        module = importlib.import_module(name)
        for cls in vars(module).values():
            if inspect.isclass(cls) and cls.__module__ == name and len(_own_bases(cls)) > 1:
                found.append(f"{name}.{cls.__qualname__}{tuple(_own_bases(cls))}")
    assert found == []


def test_the_canopen_upload_steps_and_the_live_data_are_parts():
    from PySide6.QtCore import QObject

    from prm9tool.device.canlink.session import CanopenSession
    from prm9tool.device.session import ValveSession
    from prm9tool.online.connection import ValveConnection

    assert CanopenSession.__bases__ == (ValveSession,)
    assert ValveConnection.__bases__ == (QObject,)
