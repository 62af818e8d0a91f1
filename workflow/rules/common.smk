# Shared definitions: output folder, the matplotlib style (an input of every figure rule),
# and each script's library dependencies (the package modules it imports, transitively),
# so that changing one module reruns only the rules whose scripts use it.
import ast
from pathlib import Path

OUT = config["outdir"]
STYLE = config["style"]
PAPER_PDF = f"{OUT}/paper/ms.pdf"
PACKAGE = Path("src/torsional_contact")


def _imported_modules(path):
    """Modules of the package imported by one file (absolute or relative imports)."""
    tree = ast.parse(Path(path).read_text())
    inside = Path(path).parent == PACKAGE
    found = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            for alias in node.names:
                parts = alias.name.split(".")
                if parts[0] == "torsional_contact":
                    found.add(parts[1] if len(parts) > 1 else "__init__")
        elif isinstance(node, ast.ImportFrom):
            relative = node.level > 0 and inside
            if node.module and (node.module.split(".")[0] == "torsional_contact" or relative):
                parts = node.module.split(".")
                sub = parts[1:] if parts[0] == "torsional_contact" else parts
                found.add(sub[0] if sub else "__init__")
                if not sub:
                    found.update(alias.name for alias in node.names)
            elif node.module is None and relative:  # from . import x
                found.update(alias.name for alias in node.names)
                found.add("__init__")
            elif node.module == "torsional_contact":
                found.add("__init__")
                found.update(alias.name for alias in node.names)
    return {name for name in found if (PACKAGE / f"{name}.py").exists()}


def lib(script):
    """Library files a workflow script depends on (transitive closure of its imports)."""
    todo, seen = list(_imported_modules(script)), set()
    if todo:  # importing any submodule runs the package's __init__ first
        todo.append("__init__")
    while todo:
        name = todo.pop()
        if name in seen:
            continue
        seen.add(name)
        todo.extend(_imported_modules(PACKAGE / f"{name}.py") - seen)
    return sorted(str(PACKAGE / f"{name}.py") for name in seen)


def fig(name):
    """PDF and PNG of one figure."""
    return {"pdf": f"{OUT}/figures/{name}.pdf", "png": f"{OUT}/figures/{name}.png"}


wildcard_constraints:
    quantity="[a-z_]+",
