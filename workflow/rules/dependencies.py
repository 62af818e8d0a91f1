"""Which library files a workflow script depends on: the transitive closure of its imports.

Used by workflow/rules/common.smk (each rule's ``lib`` input) and by the tests.  Reads the
sources with ``ast`` only; imports nothing from the package.  Library files are the package's
modules under src/ and the workflow's own helper modules beside the scripts (``_plotting.py``,
``_timing.py`` in workflow/scripts/: a script imports them by their bare name, its folder being
first on ``sys.path``).
"""

import ast
import functools
import hashlib
import json
import os
import warnings
from pathlib import Path

SRC = Path("src")
PACKAGE = "torsional_contact"

#: Each source's import statements, keyed by a hash of its text: parsing the ~150 sources costs about 0.4 CPU-s at
#: every Snakemake start (each build and dry run), reading and hashing them 0.01 s.  Only the statements are
#: cached (they depend on the text alone); what they resolve to (files, helper modules beside a script) is worked
#: out anew each time.
CACHE = Path(".snakemake") / "import-statements.json"


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


def _statement_records(text):
    """The import statements of a source text as plain data: ``(module or None, names, level)``, module None for
    ``import names`` (level 0), else ``from module import names`` (module "" for ``from . import names``)."""
    records = []
    for node in _import_statements(ast.parse(text).body):
        names = [alias.name for alias in node.names]
        if isinstance(node, ast.Import):
            records.append((None, names, 0))
        else:
            records.append((node.module or "", names, node.level))
    return records


class _StatementCache:
    """The import statements of each source text, read from and written back to ``CACHE`` (see there)."""

    def __init__(self):
        self.used, self.changed = {}, False
        try:
            self.stored = json.loads(CACHE.read_text())
        except FileNotFoundError:
            self.stored = {}
        except (OSError, ValueError) as error:  # unreadable or corrupt: parse everything, rewrite the file
            warnings.warn(f"{CACHE}: {error}; the import statements are parsed anew", stacklevel=2)
            self.stored = {}

    def records(self, path):
        text = path.read_text()
        key = hashlib.sha256(text.encode()).hexdigest()
        if key not in self.stored:
            self.stored[key], self.changed = _statement_records(text), True
        self.used[key] = self.stored[key]
        return self.stored[key]

    def save(self):
        """Write the statements back (atomically) when some were parsed; keep only the entries of the current
        sources once the file holds many more than they need (old versions of edited files)."""
        if not self.changed:
            return
        keep = self.stored if len(self.stored) <= 4 * len(self.used) else self.used
        temporary = CACHE.with_name(f".{CACHE.name}.{os.getpid()}")
        try:
            CACHE.parent.mkdir(parents=True, exist_ok=True)
            temporary.write_text(json.dumps(keep))
            os.replace(temporary, CACHE)
        except OSError as error:  # a cache only: the dependencies are right without it, the next start parses again
            warnings.warn(f"{CACHE} not written ({error}); the next start parses the sources again", stacklevel=2)
            temporary.unlink(missing_ok=True)
            return
        self.changed = False


_STATEMENTS = _StatementCache()


def _imports_uncached(path):
    """Dotted package modules one file imports (absolute or relative), with what they pull in."""
    path = Path(path)
    inside = SRC in path.parents
    here = _dotted(path) if inside else ""
    package = here if path.name == "__init__.py" else here.rpartition(".")[0]
    found = set()
    for module, names, level in _STATEMENTS.records(path):
        if not inside and not level:  # a helper module beside a workflow script
            bare = names if module is None else [module]
            found.update(_local(path, name) for name in bare if (path.parent / f"{name}.py").exists())
        if module is None:
            found.update(name for name in names if name.split(".")[0] == PACKAGE)
            continue
        if level:
            if not inside:
                continue
            base = package.split(".")
            base = base[: len(base) - (level - 1)]
            dotted_module = ".".join(base + ([module] if module else []))
        elif module and module.split(".")[0] == PACKAGE:
            dotted_module = module
        else:
            continue
        found.add(dotted_module)
        exports = _lazy_exports() if dotted_module == PACKAGE else {}
        for name in names:
            if _module_file(f"{dotted_module}.{name}"):  # from package import submodule
                found.add(f"{dotted_module}.{name}")
            elif name in exports:  # a name the lazy __init__ imports on first use
                found.add(f"{PACKAGE}.{exports[name]}")
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
    files = list(_library_files_cached(str(script)))
    _STATEMENTS.save()
    return files


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
