"""Every value a workflow script uses comes from its rule, and every rule runs its script with all of them.

Read from the sources (``ast`` for the scripts, the text of the rules): an option of a script that is
not required (one with a default, or a flag) must be given by every rule that runs the script, so
that no script default decides a value of the build behind the configuration; the helper modules
beside the scripts (``_plotting.py``: the options every figure script shares) declare required
options only.  Each rule takes its values from config/config.yaml (validated by the strict
config/schema.json), which tests/test_workflow.py checks end to end.
"""

import ast
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SCRIPTS = ROOT / "workflow" / "scripts"
RULE_START = re.compile(r"^(?:rule|checkpoint) (\w+):", re.MULTILINE)


def rules() -> dict:
    """rule name -> its text, from every workflow/rules/*.smk."""
    found = {}
    for path in sorted((ROOT / "workflow" / "rules").glob("*.smk")):
        text = path.read_text()
        starts = list(RULE_START.finditer(text))
        for match, following in zip(starts, [*starts[1:], None], strict=False):  # each start with the next
            found[match.group(1)] = text[match.start(): following.start() if following else len(text)]
    return found


def options(path: Path) -> list:
    """(option strings, required, default as source text) of every ``add_argument`` call of a file."""
    out = []
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Call) and getattr(node.func, "attr", None) == "add_argument":
            flags = [a.value for a in node.args if isinstance(a, ast.Constant) and isinstance(a.value, str)]
            keywords = {k.arg: k.value for k in node.keywords}
            required = isinstance(keywords.get("required"), ast.Constant) and keywords["required"].value is True
            positional = bool(flags) and not flags[0].startswith("-")
            default = ast.unparse(keywords["default"]) if "default" in keywords else None
            out.append((flags, required or positional, default))
    return out


def unset_options(rule_texts: dict) -> list:
    """"script: option (default ...) not set by rule R" for every optional option a rule omits."""
    problems = []
    for script in sorted(SCRIPTS.glob("*.py")):
        if script.name.startswith("_"):
            continue
        runners = {name: text for name, text in rule_texts.items() if f"workflow/scripts/{script.name}" in text}
        for flags, required, default in options(script):
            if required:
                continue
            for name, text in runners.items():
                if not any(re.search(re.escape(flag) + r"(?![\w-])", text) for flag in flags):
                    problems.append(f"{script.name}: {flags[0]} (default {default}) not set by rule {name}")
    return problems


def test_the_scan_finds_an_option_a_rule_omits(tmp_path, monkeypatch):
    """The check itself: a script option with a default that its rule does not pass is reported."""
    monkeypatch.setitem(globals(), "SCRIPTS", tmp_path)
    (tmp_path / "probe.py").write_text(
        "import argparse\np = argparse.ArgumentParser()\np.add_argument('--seed', type=int, default=3)\n"
        "p.add_argument('--n', type=int, required=True)\np.add_argument('--json')\n")
    rule_texts = {"probe": 'shell:\n    "python workflow/scripts/probe.py --n 4 --json out.json"\n'}
    assert unset_options(rule_texts) == ["probe.py: --seed (default 3) not set by rule probe"]


def test_every_script_is_run_by_a_rule():
    rule_texts = "\n".join(rules().values())
    unused = [p.name for p in sorted(SCRIPTS.glob("*.py"))
              if not p.name.startswith("_") and f"workflow/scripts/{p.name}" not in rule_texts]
    assert unused == []


def test_no_script_default_bypasses_the_configuration():
    assert unset_options(rules()) == []


def test_helper_modules_declare_only_required_options():
    optional = [f"{path.name}: {flags[0]}" for path in sorted(SCRIPTS.glob("_*.py"))
                for flags, required, _ in options(path) if not required]
    assert optional == []
