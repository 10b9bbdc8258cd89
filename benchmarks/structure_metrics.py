"""Structure metrics of the prm9tool package (issue 28): modules, lines, modules over 400
lines, median function length, import cycles (module-level imports; with and without the
``if TYPE_CHECKING:`` blocks). Run from the repository root::

    python benchmarks/structure_metrics.py
"""

from __future__ import annotations

import ast
import statistics
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent / "prm9tool"
GENERATED = {"resources_rc.py"}


def module_name(path: Path) -> str:
    parts = list(path.relative_to(ROOT.parent).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


def _is_type_checking(node: ast.If) -> bool:
    test = node.test
    return (isinstance(test, ast.Name) and test.id == "TYPE_CHECKING") or (
        isinstance(test, ast.Attribute) and test.attr == "TYPE_CHECKING"
    )


def imports(
    tree: ast.Module, name: str, is_pkg: bool, known: set[str]
) -> tuple[set[str], set[str]]:
    """(imports at run time at module level, imports under TYPE_CHECKING). ``from pkg import
    sub`` of a module ``pkg.sub`` imports that module, as import-linter counts it, not the
    package's ``__init__`` (which every submodule import would otherwise close a cycle with)."""
    run, typing_only = set(), set()

    def visit(body: list[ast.stmt], into: set[str]) -> None:
        for node in body:
            if isinstance(node, ast.Import):
                into.update(a.name for a in node.names)
            elif isinstance(node, ast.ImportFrom):
                base = node.module or ""
                if node.level:
                    pkg = name.split(".") if is_pkg else name.split(".")[:-1]
                    pkg = pkg[: len(pkg) - node.level + 1]
                    base = ".".join(pkg + ([node.module] if node.module else []))
                for alias in node.names:
                    full = f"{base}.{alias.name}"
                    into.add(full if full in known else base)
            elif isinstance(node, ast.If):
                visit(node.body, typing_only if _is_type_checking(node) else into)
                visit(node.orelse, into)
            elif isinstance(node, ast.Try):
                visit(node.body, into)

    visit(tree.body, run)
    return run, typing_only


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """Strongly connected components of more than one module (Tarjan), each sorted."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on: set[str] = set()
    found: list[list[str]] = []
    sys.setrecursionlimit(10000)

    def strong(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        on.add(v)
        for w in graph[v]:
            if w not in index:
                strong(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for v in graph:
        if v not in index:
            strong(v)
    return sorted(found)


def main() -> None:
    files = sorted(p for p in ROOT.rglob("*.py") if p.name not in GENERATED)
    modules = {module_name(p) for p in files}
    lines: dict[str, int] = {}
    functions: list[int] = []
    run_edges: dict[str, set[str]] = {}
    all_edges: dict[str, set[str]] = {}
    for path in files:
        text = path.read_text(encoding="utf-8")
        name = module_name(path)
        lines[name] = text.count("\n")
        tree = ast.parse(text)
        functions += [
            n.end_lineno - n.lineno + 1
            for n in ast.walk(tree)
            if isinstance(n, ast.FunctionDef | ast.AsyncFunctionDef) and n.end_lineno
        ]
        run, typing_only = imports(tree, name, path.name == "__init__.py", modules)
        run_edges[name], all_edges[name] = run, run | typing_only
    known = set(lines)
    for graph in (run_edges, all_edges):
        for name in graph:
            graph[name] = {m for m in graph[name] if m in known and m != name}
    print(f"modules: {len(lines)}")
    print(f"lines: {sum(lines.values())}")
    print(f"modules > 400 lines: {sum(n > 400 for n in lines.values())}")
    print(f"modules 350-400 lines: {sum(350 <= n <= 400 for n in lines.values())}")
    print(f"modules 300-349 lines: {sum(300 <= n < 350 for n in lines.values())}")
    print(f"median function length: {statistics.median(functions)} lines")
    at_run_time, with_typing = cycles(run_edges), cycles(all_edges)
    print(f"import cycles (module level, run time): {len(at_run_time)}")
    print(f"import cycles (with TYPE_CHECKING imports): {len(with_typing)}")
    for kind, components in (("run time", at_run_time), ("with TYPE_CHECKING", with_typing)):
        for component in components:
            print(f"  cycle ({kind}): {' <-> '.join(component)}")


if __name__ == "__main__":
    main()
