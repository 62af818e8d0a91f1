"""The layout of the package: an acyclic import graph, build-time code apart, a core that imports no extra.

The graph is read from the sources with ``ast`` (nothing is imported): every import statement at any
depth (functions too: a lazy import is still a dependency), relative or absolute, with the
``__init__`` of every package a target lies in (Python runs it first), except the packages the
importing module itself lies in (they are initialised before it).
"""

import ast
import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SRC = ROOT / "src"
PACKAGE = "torsional_contact"

#: Packages of the extras (``extras.EXTRAS``): a core path must not import them.
EXTRA_MODULES = ("mpmath", "flint", "skfem", "tqdm", "matplotlib")
#: Parts of the core dependencies that the core paths need not load: scipy.stats alone costs about 0.5 CPU-s at
#: every start of a process that fits a loop (its quantiles are scipy.special's functions).
HEAVY_CORE_MODULES = ("scipy.stats",)


def _module_name(path: Path) -> str:
    parts = list(path.relative_to(SRC).with_suffix("").parts)
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


MODULES = {_module_name(p): p for p in (SRC / PACKAGE).rglob("*.py")}


def _import_nodes(body):
    for node in body:
        if isinstance(node, ast.Import | ast.ImportFrom):
            yield node
            continue
        for _, block in ast.iter_fields(node):
            if isinstance(block, list) and block and isinstance(block[0], ast.stmt | ast.excepthandler):
                yield from _import_nodes(block)


def _targets(name: str, path: Path) -> set:
    """Package modules ``name`` imports (with the packages they lie in, minus its own)."""
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    found = set()
    for node in _import_nodes(ast.parse(path.read_text()).body):
        if isinstance(node, ast.Import):
            found |= {alias.name for alias in node.names}
            continue
        if node.level:
            base = package.split(".")
            module = ".".join(base[: len(base) - (node.level - 1)] + ([node.module] if node.module else []))
        else:
            module = node.module or ""
        submodules = {f"{module}.{alias.name}" for alias in node.names} & MODULES.keys()
        found |= submodules | ({module} if len(submodules) < len(node.names) else set())
    closed = set()
    for target in found:
        parts = target.split(".")
        closed |= {".".join(parts[:k]) for k in range(1, len(parts) + 1)}
    return {t for t in closed & MODULES.keys() if t != name and not name.startswith(t + ".")}


def import_graph() -> dict:
    return {name: _targets(name, path) for name, path in MODULES.items()}


def cycles(graph: dict) -> list:
    """Strongly connected components of more than one module (Tarjan, iterative)."""
    index, low, stack, on_stack, found, counter = {}, {}, [], set(), [], 0
    for root in graph:
        if root in index:
            continue
        work = [(root, iter(sorted(graph[root])))]
        index[root] = low[root] = counter
        counter += 1
        stack.append(root)
        on_stack.add(root)
        while work:
            node, children = work[-1]
            child = next(children, None)
            if child is not None:
                if child not in index:
                    index[child] = low[child] = counter
                    counter += 1
                    stack.append(child)
                    on_stack.add(child)
                    work.append((child, iter(sorted(graph[child]))))
                elif child in on_stack:
                    low[node] = min(low[node], index[child])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[node])
            if low[node] == index[node]:
                component = []
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    component.append(member)
                    if member == node:
                        break
                if len(component) > 1:
                    found.append(sorted(component))
    return found


def test_cycle_finder_finds_a_known_cycle():
    graph = {"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}, "e": set()}
    assert cycles(graph) == [["a", "b", "c"]]
    assert cycles({"a": {"b"}, "b": set()}) == []


def test_graph_sees_relative_lazy_and_package_imports():
    graph = import_graph()
    # lazy (inside a function), relative, and the package __init__ of a target
    assert "torsional_contact.verification.errata" in graph["torsional_contact.io.cli"]
    assert "torsional_contact.verification" in graph["torsional_contact.io.cli"]
    assert "torsional_contact.solution" in graph["torsional_contact.dispatch"]


def test_package_import_graph_has_no_cycle():
    assert cycles(import_graph()) == []


def _package(module: str) -> str:
    """The package a module belongs to: ``torsional_contact.histories`` for ``torsional_contact.histories.memory``;
    a module directly in ``torsional_contact`` is its own node."""
    return ".".join(module.split(".")[:2])


def test_no_import_cycle_between_packages():
    """Between subpackages (and the top-level modules) the imports go one way: e.g. ``io`` (the command line) uses
    ``output`` and ``provenance``, which never use ``io``."""
    graph: dict = {}
    for name, targets in import_graph().items():
        graph.setdefault(_package(name), set()).update(_package(t) for t in targets if _package(t) != _package(name))
    for targets in list(graph.values()):
        for t in targets:
            graph.setdefault(t, set())
    assert cycles(graph) == []
    assert cycles({"p.a": {"p.b"}, "p.b": {"p.a"}}) == [["p.a", "p.b"]]  # the finder sees a package cycle


def test_only_the_reference_and_errata_subcommands_import_verification():
    """The library never imports ``verification`` (solve, history, Specimen, fit); the command line's
    ``reference`` and ``errata`` subcommands do, lazily, and need the ``[reference]`` extra."""
    importers = sorted(name for name, targets in import_graph().items()
                       if not name.startswith("torsional_contact.verification")
                       and any(t.startswith("torsional_contact.verification") for t in targets))
    assert importers == ["torsional_contact.io.cli"]
    source = (SRC / PACKAGE / "io" / "cli.py").read_text()
    top_level = [line for line in source.splitlines() if line.startswith(("from ..verification", "import "))
                 and "verification" in line]
    assert top_level == []  # lazily, inside the subcommands


def test_build_time_generators_are_not_imported_at_run_time():
    """Only the table's rebuild entry point (``python -m torsional_contact.curves``) imports the builder."""
    importers = sorted(name for name, targets in import_graph().items()
                       if any(".curves._precompute" in t for t in targets) and "._precompute" not in name)
    assert importers == ["torsional_contact.curves.__main__"]


def test_core_paths_import_no_extra():
    """solve, history, the specimen, the loop fit and the CLI's solve/history/fit import none of the extras' packages
    (they are installed here: the check is that nothing loads them), nor scipy.stats (start-up time)."""
    code = (
        "import sys, io, contextlib\n"
        "import torsional_contact as tc\n"
        "from torsional_contact.io.cli import main\n"
        "tc.solve(torque=1.23).stress([0.5], [0.1]); tc.solve(stick_radius=0.6, method='complete')\n"
        "tc.history([0, 1.23, -1.0]); tc.solve(torque=1.1, model='half-space')\n"
        "tc.Specimen(radius='5 mm', normal_force='1 kN', friction=0.5, shear_modulus='80 GPa')"
        ".solve(torque='1.5 N m')\n"
        "with contextlib.redirect_stdout(io.StringIO()):\n"
        "    assert main(['solve', '--torque', '1.2', '--json']) == 0\n"
        "    assert main(['history', '--turning-points', '0', '1.2', '-1', '--json']) == 0\n"
        "    assert main(['fit', '--loop', 'notebooks/data/lab_loop.csv', '--radius', '5 mm', '--normal-force', '1 kN',"
        " '--json']) == 0\n"
        f"print(sorted(m for m in {EXTRA_MODULES + HEAVY_CORE_MODULES!r} if m in sys.modules))\n"
    )
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, env=env,
                            check=True)
    assert result.stdout.strip() == "[]", result.stdout
