"""Which library files a workflow script depends on: the transitive closure of its imports.

Used by workflow/rules/common.smk (each rule's ``lib`` input) and by the tests.  Reads the
sources with ``ast`` only; imports nothing from the package.  Library files are the package's
modules under src/ and the workflow's own helper modules beside the scripts (``_plotting.py``,
``_timing.py`` in workflow/scripts/: a script imports them by their bare name, its folder being
first on ``sys.path``).
"""

import ast
import functools
from pathlib import Path

SRC = Path("src")
PACKAGE = "torsional_contact"


def _module_file(dotted):
    """The file of a dotted module name under src/ (module.py or package/__init__.py), or None."""
    base = SRC.joinpath(*dotted.split("."))
    for candidate in (base.with_suffix(".py"), base / "__init__.py"):
        if candidate.exists():
            return candidate
    return None


def _dotted(path):
    """Dotted module name of a file under src/ (a package's __init__.py names the package)."""
    parts = list(Path(path).relative_to(SRC).with_suffix("").parts)
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


@functools.cache
def _lazy_exports():
    """name -> submodule of the package's lazy ``__init__`` (its _EXPORTS table)."""
    tree = ast.parse((SRC / PACKAGE / "__init__.py").read_text())
    for node in tree.body:
        if isinstance(node, ast.AnnAssign | ast.Assign):
            targets = [node.target] if isinstance(node, ast.AnnAssign) else node.targets
            if any(getattr(t, "id", None) == "_EXPORTS" for t in targets):
                return ast.literal_eval(node.value)
    return {}


@functools.cache
def _imports_cached(path):
    return frozenset(_imports_uncached(path))


def _imports(path):
    """Dotted package modules one file imports (cached per file: each is parsed once per process)."""
    return set(_imports_cached(Path(path)))


_BLOCKS = ast.stmt | ast.excepthandler | ast.match_case


def _import_statements(body):
    """Import statements at any depth of a statement list (functions, classes, if/try/with blocks).

    Imports are statements: only statement lists are visited, not the far more numerous
    expression nodes (``ast.walk`` would visit those too).
    """
    for node in body:
        if isinstance(node, ast.Import | ast.ImportFrom):
            yield node
            continue
        for _, block in ast.iter_fields(node):  # body, orelse, finalbody, handlers, cases
            if isinstance(block, list) and block and isinstance(block[0], _BLOCKS):
                yield from _import_statements(block)


def _imports_uncached(path):
    """Dotted package modules one file imports (absolute or relative), with what they pull in."""
    path = Path(path)
    tree = ast.parse(path.read_text())
    inside = SRC in path.parents
    here = _dotted(path) if inside else ""
    package = here if path.name == "__init__.py" else here.rpartition(".")[0]
    found = set()
    for node in _import_statements(tree.body):
        if not inside and not getattr(node, "level", 0):  # a helper module beside a workflow script
            names = [a.name for a in node.names] if isinstance(node, ast.Import) else [node.module or ""]
            found.update(_local(path, name) for name in names if (path.parent / f"{name}.py").exists())
        if isinstance(node, ast.Import):
            found.update(a.name for a in node.names if a.name.split(".")[0] == PACKAGE)
            continue
        if not isinstance(node, ast.ImportFrom):
            continue
        if node.level:
            if not inside:
                continue
            base = package.split(".")
            base = base[: len(base) - (node.level - 1)]
            dotted_module = ".".join(base + ([node.module] if node.module else []))
        elif node.module and node.module.split(".")[0] == PACKAGE:
            dotted_module = node.module
        else:
            continue
        found.add(dotted_module)
        exports = _lazy_exports() if dotted_module == PACKAGE else {}
        for alias in node.names:
            if _module_file(f"{dotted_module}.{alias.name}"):  # from package import submodule
                found.add(f"{dotted_module}.{alias.name}")
            elif alias.name in exports:  # a name the lazy __init__ imports on first use
                found.add(f"{PACKAGE}.{exports[alias.name]}")
    return found


#: Prefix of the names ``_imports`` gives to helper modules beside a workflow script (file paths).
_LOCAL = "file:"


def _local(script, name):
    """The name of the helper module ``name`` beside ``script`` (its path, marked)."""
    return _LOCAL + str(Path(script).parent / f"{name}.py")


def _file(name):
    """The file of a package module or of a marked helper module, or None."""
    return Path(name[len(_LOCAL):]) if name.startswith(_LOCAL) else _module_file(name)


@functools.cache
def _library_files_cached(script):
    return tuple(_library_files(script))


def library_files(script):
    """Library files a workflow script depends on: the transitive closure of its imports (a new list)."""
    return list(_library_files_cached(str(script)))


def _library_files(script):
    """Library files a workflow script depends on: the transitive closure of its imports.

    Importing a.b.c runs the __init__ of a and a.b first, so those are included too.
    """
    todo, seen = list(_imports(script)), set()
    while todo:
        name = todo.pop()
        if name in seen or _file(name) is None:
            continue
        seen.add(name)
        if not name.startswith(_LOCAL):
            parts = name.split(".")
            todo.extend(".".join(parts[:k]) for k in range(1, len(parts)))
        todo.extend(_imports(_file(name)) - seen)
    files = {_file(name) for name in seen}
    # data shipped inside a package the script uses (e.g. the tabulated monotonic curves)
    files |= {data for f in list(files) if f.name == "__init__.py" for data in f.parent.glob("*.json")}
    return sorted(str(f) for f in files)
