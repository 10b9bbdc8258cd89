"""Benchmarks must keep running (issue 25 item 18): each has a smoke mode that CI runs
(`benchmarks/smoke.py`, `.ci/run`), and each uses the program's public interfaces only, so a
restructuring that keeps those cannot break it (bench_scope.py read ValveConnection._session)."""

from __future__ import annotations

import ast
import subprocess
import sys
from pathlib import Path

import pytest

BENCHMARKS = sorted((Path(__file__).parents[1] / "benchmarks").glob("bench_*.py"))
ALLOWED = {("os", "_exit")}  # the standard library's own public name


@pytest.mark.parametrize("path", BENCHMARKS, ids=lambda p: p.stem)
def test_every_benchmark_has_a_smoke_mode(path):
    if '"--quick"' in path.read_text(encoding="utf-8"):
        return
    # the option comes from a shared helper (bench_startup.compare_with_pyside): ask the script
    run = subprocess.run(
        [sys.executable, str(path), "--help"], capture_output=True, text=True, timeout=60
    )
    assert "--quick" in run.stdout, run.stdout + run.stderr


@pytest.mark.parametrize("path", BENCHMARKS, ids=lambda p: p.stem)
def test_every_benchmark_uses_public_interfaces_only(path):
    tree = ast.parse(path.read_text(encoding="utf-8"))
    private = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Attribute) and _private(node.attr):
            owner = node.value.id if isinstance(node.value, ast.Name) else ""
            if owner not in ("self", "cls") and (owner, node.attr) not in ALLOWED:
                private.append(f"line {node.lineno}: {ast.unparse(node)}")
        elif isinstance(node, ast.ImportFrom) and (node.module or "").startswith("prm9tool"):
            private += [f"line {node.lineno}: {a.name}" for a in node.names if _private(a.name)]
    assert private == []


def _private(name: str) -> bool:
    return name.startswith("_") and not name.startswith("__")
