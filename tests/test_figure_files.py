"""Figure scripts that draw several figures in one job (--quantity with one --pdf and --png each).

The panels of Fig. 2 and Fig. 4 are drawn by one job each, from one solution per stick radius.  The
check is independent of that sharing: the same panels drawn one per process must give the same
bytes (SOURCE_DATE_EPOCH fixes the PDF's dates).  Bad lists are refused by the parser, naming the
option, before anything is written.
"""

import argparse
import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
SCRIPTS = ROOT / "workflow" / "scripts"
STYLE = ROOT / "workflow" / "styles" / "paper.mplstyle"


def _run_fig4(out: Path, quantities):
    env = dict(os.environ, SOURCE_DATE_EPOCH="0", MPLBACKEND="agg")
    command = [sys.executable, str(SCRIPTS / "fig4_interface.py"), "--quantity", *quantities,
               "--stick-radii", "0.3", "0.7", "--method", "fast", "--n-terms", "60", "--n-points", "41",
               "--style", str(STYLE), "--pdf", *[str(out / f"{q}.pdf") for q in quantities],
               "--png", *[str(out / f"{q}.png") for q in quantities]]
    return subprocess.run(command, cwd=SCRIPTS, env=env, capture_output=True, text=True)


def test_panels_drawn_in_one_job_are_those_drawn_one_per_process(tmp_path):
    together, alone = tmp_path / "together", tmp_path / "alone"
    together.mkdir()
    alone.mkdir()
    run = _run_fig4(together, ["traction", "slip"])
    assert run.returncode == 0, run.stderr
    # the second panel: the one drawn after another figure of the same process (each run costs a second or two)
    run = _run_fig4(alone, ["slip"])
    assert run.returncode == 0, run.stderr
    for suffix in (".pdf", ".png"):
        assert (together / f"slip{suffix}").read_bytes() == (alone / f"slip{suffix}").read_bytes()
    assert (together / "traction.pdf").read_bytes() != (together / "slip.pdf").read_bytes()


@pytest.fixture(scope="module")
def plotting():
    sys.path.insert(0, str(SCRIPTS))
    try:
        import _plotting
    finally:
        sys.path.remove(str(SCRIPTS))
    return _plotting


@pytest.mark.parametrize("quantity, pdf, png, message", [
    (["a", "b"], ["a.pdf"], ["a.png", "b.png"], "--pdf: one file per --quantity (2), got 1"),
    (["a"], ["a.pdf"], ["a.png", "b.png"], "--png: one file per --quantity (1), got 2"),
    (["a", "a"], ["a.pdf", "b.pdf"], ["a.png", "b.png"], "--quantity: each quantity once"),
    (["a", "b"], ["a.pdf", "a.pdf"], ["a.png", "b.png"], "--pdf, --png: every file a different path"),
    (["a"], ["a.pdf"], ["a.pdf"], "--pdf, --png: every file a different path"),
])
def test_bad_file_lists_are_refused_naming_the_option(plotting, capsys, quantity, pdf, png, message):
    parser = plotting.figure_parser("A figure.", quantities={"a": "A", "b": "B"})
    args = argparse.Namespace(quantity=quantity, pdf=pdf, png=png)
    with pytest.raises(SystemExit) as stop:
        plotting.figure_files(parser, args)
    assert stop.value.code == 2 and message in capsys.readouterr().err


def test_matching_lists_pair_each_quantity_with_its_files(plotting):
    parser = plotting.figure_parser("A figure.", quantities={"a": "A", "b": "B"})
    args = parser.parse_args(["--quantity", "b", "a", "--method", "fast", "--n-terms", "10", "--style", "s",
                              "--pdf", "b.pdf", "a.pdf", "--png", "b.png", "a.png"])
    assert plotting.figure_files(parser, args) == [("b", "b.pdf", "b.png"), ("a", "a.pdf", "a.png")]
