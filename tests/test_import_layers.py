"""The layout shows the pipeline (issue 24): no import cycle between taskrunner's modules,
and no module over 800 lines.

The import graph is read from the source with :mod:`ast`: an edge for each import run
when a module is imported (its top level, including ``try`` and ``if`` blocks there), not
for imports inside functions (lazy edges, taken when the function runs) nor those under
``if TYPE_CHECKING:``. ``from taskrunner.a import b`` is an edge to ``taskrunner.a.b``
when that is a module, else to ``taskrunner.a``.
"""

from __future__ import annotations

import ast
from functools import cache
from pathlib import Path

import taskrunner

PACKAGE = Path(taskrunner.__file__).resolve().parent
MAX_LINES = 800

# Modules over MAX_LINES, each with its reason and the issue that splits it.
_LONG: dict[str, str] = {}

# Package cycles left, with the way out (issue 24); the test fails on any other, and when
# one of these is gone (take it off the list).
_PACKAGE_CYCLES: dict[frozenset[str], str] = {
    frozenset({"taskrunner.runtime", "taskrunner.tree"}):
        "tree's leaves and context emit runtime.events' RunEvent and use runtime.replay's "
        "object data: those two move below tree (events are the run's vocabulary)",
}


def _module_name(path: Path) -> str:
    parts = list(path.relative_to(PACKAGE.parent).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


def _modules() -> dict[str, Path]:
    return {_module_name(p): p for p in sorted(PACKAGE.rglob("*.py"))
            if "__pycache__" not in p.parts and "data" not in p.relative_to(PACKAGE).parts[:1]}


def _is_type_checking(test: ast.expr) -> bool:
    return (isinstance(test, ast.Name) and test.id == "TYPE_CHECKING") or (
        isinstance(test, ast.Attribute) and test.attr == "TYPE_CHECKING")


def _top_level_imports(tree: ast.Module) -> list[ast.Import | ast.ImportFrom]:
    found: list[ast.Import | ast.ImportFrom] = []

    def visit(body: list[ast.stmt]) -> None:
        for node in body:
            if isinstance(node, (ast.Import, ast.ImportFrom)):
                found.append(node)
            elif isinstance(node, ast.If):
                if not _is_type_checking(node.test):
                    visit(node.body)
                visit(node.orelse)
            elif isinstance(node, ast.Try):
                for block in (node.body, node.orelse, node.finalbody,
                              *(h.body for h in node.handlers)):
                    visit(block)
            elif isinstance(node, (ast.With, ast.For, ast.While)):
                visit(node.body)

    visit(tree.body)
    return found


@cache
def import_graph() -> dict[str, set[str]]:
    """Module -> the taskrunner modules its import runs."""
    modules = _modules()
    graph: dict[str, set[str]] = {name: set() for name in modules}
    for name, path in modules.items():
        is_package = path.name == "__init__.py"
        for node in _top_level_imports(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Import):
                targets = [alias.name for alias in node.names]
            else:
                if node.level:
                    base = name.split(".")
                    base = base[:len(base) - node.level + (1 if is_package else 0)]
                    stem = ".".join(base + ([node.module] if node.module else []))
                else:
                    stem = node.module or ""
                targets = [f"{stem}.{a.name}" if f"{stem}.{a.name}" in modules else stem
                           for a in node.names]
            for target in targets:
                while target and target not in modules and "." in target:
                    target = target.rsplit(".", 1)[0]
                if target in modules and target != name:
                    graph[name].add(target)
    return graph


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components of more than one node (Tarjan), each as one
    cycle through its members, shortest found by a breadth-first search."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    components: list[list[str]] = []

    def strongconnect(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in sorted(graph.get(v, ())):
            if w not in index:
                strongconnect(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                components.append(sorted(component))

    for v in sorted(graph):
        if v not in index:
            strongconnect(v)
    return [_shortest_cycle(graph, set(c)) for c in components]


def _shortest_cycle(graph: dict[str, set[str]], members: set[str]) -> list[str]:
    best: list[str] = []
    for start in sorted(members):
        paths = {start: [start]}
        frontier = [start]
        while frontier and not best or (frontier and len(paths[frontier[0]]) < len(best)):
            nxt = []
            for v in frontier:
                for w in sorted(graph[v] & members):
                    if w == start:
                        cycle = paths[v] + [start]
                        if not best or len(cycle) < len(best):
                            best = cycle
                    elif w not in paths:
                        paths[w] = paths[v] + [w]
                        nxt.append(w)
            frontier = nxt
    return best


def test_no_import_cycle_between_modules():
    found = cycles(import_graph())
    assert not found, "import cycles (move the shared piece down a layer):\n" + "\n".join(
        " -> ".join(c) for c in found)


def test_no_import_cycle_between_packages():
    """taskrunner's subpackages (``tree``, ``runtime`` …; a top-level module is its own
    node) import each other one way only."""
    def package(module: str) -> str:
        return ".".join(module.split(".")[:2])

    graph: dict[str, set[str]] = {}
    for module, targets in import_graph().items():
        if module == "taskrunner":
            continue  # the public API imports from everywhere; nothing imports it back
        graph.setdefault(package(module), set()).update(
            package(t) for t in targets if package(t) != package(module) and t != "taskrunner")
    found = {frozenset(c): c for c in cycles(graph)}
    new = [" -> ".join(c) for members, c in found.items() if members not in _PACKAGE_CYCLES]
    assert not new, "package import cycles:\n" + "\n".join(new)
    gone = set(_PACKAGE_CYCLES) - set(found)
    assert not gone, f"listed package cycles that are gone: {[sorted(g) for g in gone]}"


def test_the_cycle_finder_names_a_cycle():
    graph = {"a": {"b"}, "b": {"c"}, "c": {"a", "d"}, "d": set(), "e": {"e"}}
    assert cycles(graph) == [["a", "b", "c", "a"]]


def test_no_module_is_over_800_lines():
    long = {}
    for path in _modules().values():
        with path.open(encoding="utf-8") as f:
            count = sum(1 for _ in f)
        if count > MAX_LINES:
            long[path.relative_to(PACKAGE).as_posix()] = count
    unexplained = {k: v for k, v in long.items() if k not in _LONG}
    assert not unexplained, f"modules over {MAX_LINES} lines (split along their seams): " \
        f"{unexplained}"
    stale = set(_LONG) - set(long)
    assert not stale, f"listed as long but no longer over {MAX_LINES} lines: {stale}"
