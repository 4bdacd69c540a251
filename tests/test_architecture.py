"""Imports go one way: a static walk of every module of src/coindie.

Every ``import`` and ``from ... import`` statement counts, at module level or inside a function (a lazy import
is still a dependency). The one exemption: imports under ``if TYPE_CHECKING:``, which never run and only name
types for annotations. Each module belongs to a layer (below, lowest first); a module may import its own layer
and the layers below it, never a layer above, and the peers of one rank (serve, report) never each other.
Independently of the order, no two packages and no two modules may import each other through a cycle.

The checker runs on the real tree and, so that the test can fail, on small fake trees with a planted
upward import, a peer import and a cycle.
"""

from __future__ import annotations

import ast
from dataclasses import dataclass, field
from pathlib import Path

import pytest

SOURCE_ROOT = Path(__file__).resolve().parents[1] / "src"

# Lowest first. A tuple is one rank of peers that may not import each other.
LAYERS: tuple[str | tuple[str, ...], ...] = (
    "<base>",
    "io",
    "preprocess",
    "render",
    "registration",
    "candidates",
    "similarity",
    "clustering",
    "project",
    "numismatics",
    ("serve", "report"),
    "synth",
    "bench",
    "cli",
)
# Modules directly under coindie/ that everything may use: they import nothing of coindie but each other.
BASE_MODULES = frozenset({"__init__", "errors", "ids", "scan", "arrays", "transforms", "params", "caches"})


@dataclass(frozen=True)
class Import:
    importer: str  # dotted module name
    imported: str  # dotted module name (a module of the tree, or the package whose name was imported from)
    path: Path
    line: int


@dataclass
class ImportGraph:
    package: str
    modules: dict[str, Path] = field(default_factory=dict)
    imports: list[Import] = field(default_factory=list)


def _module_name(root: Path, path: Path) -> tuple[str, bool]:
    parts = list(path.relative_to(root).with_suffix("").parts)
    is_package = parts[-1] == "__init__"
    if is_package:
        parts = parts[:-1]
    return ".".join(parts), is_package


def _type_checking_nodes(tree: ast.Module) -> set[int]:
    """ids of the import nodes under ``if TYPE_CHECKING:`` (or ``typing.TYPE_CHECKING``)."""
    exempt: set[int] = set()
    for node in ast.walk(tree):
        if not isinstance(node, ast.If):
            continue
        test = node.test
        name = test.id if isinstance(test, ast.Name) else test.attr if isinstance(test, ast.Attribute) else ""
        if name == "TYPE_CHECKING":
            for statement in node.body:
                exempt.update(id(child) for child in ast.walk(statement))
    return exempt


def _resolve(module: str, is_package: bool, node: ast.ImportFrom) -> str:
    if node.level == 0:
        return node.module or ""
    base = module.split(".")
    if not is_package:
        base = base[:-1]
    if node.level > 1:
        base = base[: len(base) - (node.level - 1)]
    return ".".join(base + ([node.module] if node.module else []))


def build_graph(root: Path, package: str) -> ImportGraph:
    """Every static import of ``package`` (a folder under ``root``) by a module of it."""
    graph = ImportGraph(package)
    parsed: list[tuple[str, bool, Path, ast.Module]] = []
    for path in sorted((root / package).rglob("*.py")):
        name, is_package = _module_name(root, path)
        graph.modules[name] = path
        parsed.append((name, is_package, path, ast.parse(path.read_text(encoding="utf-8"), str(path))))

    def inside(name: str) -> bool:
        return name == package or name.startswith(package + ".")

    for name, is_package, path, tree in parsed:
        exempt = _type_checking_nodes(tree)
        for node in ast.walk(tree):
            if id(node) in exempt:
                continue
            targets: list[str] = []
            if isinstance(node, ast.Import):
                targets = [alias.name for alias in node.names]
            elif isinstance(node, ast.ImportFrom):
                source = _resolve(name, is_package, node)
                # ``from pkg import sub`` depends on the submodule when there is one, else on pkg itself.
                targets = [
                    f"{source}.{alias.name}" if f"{source}.{alias.name}" in graph.modules else source
                    for alias in node.names
                ]
            for target in targets:
                if not inside(target):
                    continue
                while target not in graph.modules and "." in target:
                    target = target.rsplit(".", 1)[0]  # ``import a.b.c`` of a name, not a module
                if target != name:
                    graph.imports.append(Import(name, target, path, node.lineno))
    return graph


def unit_of(module: str, package: str) -> str:
    """The package (or base module) a module belongs to: coindie.registration.icp -> registration."""
    parts = module.split(".")[1:]
    if not parts:
        return "<base>:__init__"
    if parts[0] in BASE_MODULES:
        return f"<base>:{parts[0]}"
    return parts[0]


def rank_of(unit: str, layers: tuple[str | tuple[str, ...], ...]) -> int:
    layer = "<base>" if unit.startswith("<base>") else unit
    for rank, entry in enumerate(layers):
        if layer == entry or (isinstance(entry, tuple) and layer in entry):
            return rank
    raise KeyError(f"{unit} is in no layer: add it to LAYERS in tests/test_architecture.py")


def layer_violations(graph: ImportGraph, layers=LAYERS) -> list[str]:
    """Upward imports and imports between peers, one line each."""
    problems = []
    for edge in graph.imports:
        source, target = unit_of(edge.importer, graph.package), unit_of(edge.imported, graph.package)
        if source == target:
            continue
        source_rank, target_rank = rank_of(source, layers), rank_of(target, layers)
        where = f"{edge.path.name}:{edge.line}: {edge.importer} imports {edge.imported}"
        if target_rank > source_rank:
            problems.append(f"upward import ({source} -> {target}): {where}")
        elif target_rank == source_rank and not source.startswith("<base>"):
            problems.append(f"import between peers ({source} -> {target}): {where}")
    return problems


def _cycles(edges: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components with more than one node (Tarjan)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    components: list[list[str]] = []

    def visit(node: str) -> None:
        index[node] = low[node] = len(index)
        stack.append(node)
        on_stack.add(node)
        for successor in sorted(edges.get(node, ())):
            if successor not in index:
                visit(successor)
                low[node] = min(low[node], low[successor])
            elif successor in on_stack:
                low[node] = min(low[node], index[successor])
        if low[node] == index[node]:
            component = []
            while True:
                member = stack.pop()
                on_stack.discard(member)
                component.append(member)
                if member == node:
                    break
            if len(component) > 1:
                components.append(sorted(component))

    for node in sorted(edges):
        if node not in index:
            visit(node)
    return components


def _is_package(graph: ImportGraph, module: str) -> bool:
    return graph.modules[module].name == "__init__.py"


def package_cycles(graph: ImportGraph) -> list[list[str]]:
    edges: dict[str, set[str]] = {}
    for edge in graph.imports:
        source, target = unit_of(edge.importer, graph.package), unit_of(edge.imported, graph.package)
        if source != target:
            edges.setdefault(source, set()).add(target)
    return _cycles(edges)


def module_cycles(graph: ImportGraph) -> list[list[str]]:
    """Cycles between modules (a package's __init__ re-exporting its own submodules is no cycle with them)."""
    edges: dict[str, set[str]] = {}
    for edge in graph.imports:
        if _is_package(graph, edge.importer) and edge.imported.startswith(edge.importer + "."):
            continue
        edges.setdefault(edge.importer, set()).add(edge.imported)
    return _cycles(edges)


@pytest.fixture(scope="module")
def coindie_graph() -> ImportGraph:
    return build_graph(SOURCE_ROOT, "coindie")


def test_every_package_has_a_layer(coindie_graph: ImportGraph) -> None:
    units = {unit_of(module, "coindie") for module in coindie_graph.modules}
    assert all(rank_of(unit, LAYERS) >= 0 for unit in units)
    assert len(coindie_graph.imports) > 500  # the walk sees the imports at all


def test_imports_go_one_way(coindie_graph: ImportGraph) -> None:
    problems = layer_violations(coindie_graph)
    assert not problems, "\n".join(problems)


def test_no_cycle_between_packages(coindie_graph: ImportGraph) -> None:
    cycles = package_cycles(coindie_graph)
    assert not cycles, cycles


def test_no_cycle_between_modules(coindie_graph: ImportGraph) -> None:
    cycles = module_cycles(coindie_graph)
    assert not cycles, cycles


def _fake_tree(root: Path, files: dict[str, str]) -> None:
    for relative, text in {"fake/__init__.py": "", **files}.items():
        path = root / relative
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="utf-8")


def test_checker_flags_upward_and_peer_imports(tmp_path: Path) -> None:
    _fake_tree(
        tmp_path,
        {
            "fake/io/__init__.py": "",
            "fake/io/reader.py": "def read():\n    from fake.registration import icp\n",
            "fake/registration/__init__.py": "",
            "fake/registration/icp.py": "from ..io.reader import read\nimport fake.errors\n",
            "fake/errors.py": "",
            "fake/serve/__init__.py": "from fake.report import html\n",
            "fake/report/__init__.py": "",
            "fake/report/html.py": (
                "from typing import TYPE_CHECKING\nif TYPE_CHECKING:\n    from fake.cli import app\n"
            ),
            "fake/cli/__init__.py": "",
            "fake/cli/app.py": "from fake.serve import *\n",
        },
    )
    graph = build_graph(tmp_path, "fake")
    problems = layer_violations(graph)
    assert len(problems) == 2, problems
    assert problems[0].startswith("upward import (io -> registration): reader.py:2")
    assert problems[1].startswith("import between peers (serve -> report)")
    assert package_cycles(graph) == [["io", "registration"]]


def test_checker_flags_module_cycles(tmp_path: Path) -> None:
    _fake_tree(
        tmp_path,
        {
            "fake/cli/__init__.py": "from fake.cli.app import main\n",
            "fake/cli/app.py": "from fake.cli import train\n",
            "fake/cli/train.py": "def run():\n    from fake.cli.app import main\n",
            "fake/cli/scans.py": "from fake.cli import app\n",
        },
    )
    graph = build_graph(tmp_path, "fake")
    assert layer_violations(graph) == []
    assert package_cycles(graph) == []
    assert module_cycles(graph) == [["fake.cli.app", "fake.cli.train"]]
