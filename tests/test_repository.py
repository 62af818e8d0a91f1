"""The repository stands alone and shows its architecture.

No tracked file names a path outside the repository; no issue numbers in code; the product never
imports the verification wing (the command line reaches it only inside its ``reference`` and
``errata`` subcommands); modules stay small; the README's layout section names every module.
"""

import ast
import re
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PACKAGE = ROOT / "src" / "torsional_contact"


def tracked_files():
    try:
        listing = subprocess.run(["git", "ls-files"], cwd=ROOT, capture_output=True, text=True, check=True).stdout
    except (OSError, subprocess.CalledProcessError):
        pytest.skip("not a git checkout")
    return [ROOT / line for line in listing.splitlines() if (ROOT / line).is_file()]


OUTSIDE = re.compile(r"\.\./(shared|\.library)\b|/work/(main|shared)|CONTRACT\.md")


def test_no_tracked_file_names_a_path_outside_the_repository():
    offenders = []
    for path in tracked_files():
        if path.name == Path(__file__).name:
            continue  # this file spells the patterns out
        try:
            text = path.read_text(encoding="utf-8")
        except UnicodeDecodeError:
            continue
        for number, line in enumerate(text.splitlines(), 1):
            if OUTSIDE.search(line):
                offenders.append(f"{path.relative_to(ROOT)}:{number}: {line.strip()[:100]}")
    assert not offenders, "\n".join(offenders)


def test_no_issue_numbers_in_code_tests_or_workflow():
    pattern = re.compile(r"\bissues? ?#?\d", re.I)
    offenders = [f"{p.relative_to(ROOT)}:{n}" for p in tracked_files()
                 if p.suffix in (".py", ".smk", ".yaml", ".json", ".sh", ".tex") or p.name == "Snakefile"
                 for n, line in enumerate(p.read_text(encoding="utf-8").splitlines(), 1) if pattern.search(line)]
    assert not offenders, offenders


def _imports(path):
    """(module-level imports, imports inside functions) of a package file, as dotted names."""
    tree = ast.parse(path.read_text())
    package = ".".join(path.relative_to(ROOT / "src").with_suffix("").parts[:-1])
    top, inner = set(), set()

    def resolve(node):
        if isinstance(node, ast.Import):
            return {a.name for a in node.names}
        base = package.split(".")[: len(package.split(".")) - (node.level - 1)] if node.level else []
        module = ".".join(base + ([node.module] if node.module else []))
        return {module} | {f"{module}.{a.name}" for a in node.names}

    for node in ast.walk(tree):
        if isinstance(node, ast.Import | ast.ImportFrom):
            (top if node.col_offset == 0 else inner).update(resolve(node))
    return top, inner


def test_the_product_never_imports_the_verification_wing():
    wing = "torsional_contact.verification"
    for path in PACKAGE.rglob("*.py"):
        rel = path.relative_to(PACKAGE).as_posix()
        if rel.startswith("verification/"):
            continue
        top, inner = _imports(path)
        assert not any(m.startswith(wing) for m in top), f"{rel} imports the verification wing at module level"
        if rel != "io/cli.py":  # the reference and errata subcommands import it when they run
            assert not any(m.startswith(wing) for m in inner), f"{rel} imports the verification wing"


def test_modules_stay_small():
    sizes = {p.relative_to(PACKAGE).as_posix(): len(p.read_text().splitlines()) for p in PACKAGE.rglob("*.py")}
    assert max(sizes.values()) <= 550, {k: v for k, v in sizes.items() if v > 550}


def test_the_readme_layout_names_every_module():
    readme = (ROOT / "README.md").read_text()
    layout = readme[readme.index("## Layout"):]
    missing = [p.relative_to(PACKAGE).as_posix() for p in sorted(PACKAGE.rglob("*.py"))
               if not p.name.startswith("__") and p.relative_to(PACKAGE).with_suffix("").as_posix() not in layout]
    assert not missing, missing
