"""The errata table: structure, the verdict rules, the verdicts, coverage, the LaTeX notes and table.

The verdicts are computed by ``errata.errata_table``; ``EXPECTED`` below is the
reviewed outcome.  If a change of code or threshold flips a verdict, this test fails.
Every new formula check is also fed a corrupted formula and must then fail.
"""

import importlib.util
import json
import math
import re
import shutil
import subprocess
from pathlib import Path

import mpmath
import pytest
from tolerances import EPS, assert_within

from torsional_contact import solve
from torsional_contact.io import cli
from torsional_contact.verification import errata, quadrature_mp, weak_form_mp
from torsional_contact.verification.errata import (
    bilateral,
    conditions,
    dual_series,
    series_terms,
    settings,
    solution_e,
)
from torsional_contact.verification.quadrature_mp import gauss_legendre

ROOT = Path(__file__).resolve().parents[1]

EXPECTED = {
    "1": "correct",
    "2": "correct",
    "3": "correct",
    "4": "correct",
    "5": "correct",
    "6": "correct",
    "7": "correct",
    "8": "correct",
    "9": "correct",
    "10": "correct",
    "11": "correct",
    "12": "correct",
    "13": "correct",
    "14": "correct",
    "15": "correct",
    "16": "correct",
    "17": "correct",
    "18": "correct",
    "19": "correct",
    "20": "correct",
    "21": "correct",
    "22": "correct",
    "23": "correct",
    "24": "correct",
    "25": "correct",
    "26": "correct",
    "27": "correct",
    "28": "correct",
    "29": "correct",
    "30": "correct",
    "31": "correct",  # a definition, consistent with (25), (26), (29), (30)
    "32": "correct",  # a definition, consistent with (2), (5), (30) and the spinning limit
    "33-38": "correct",
    "34": "correct",
    "35": "correct",
    "A.39": "correct",
    "A.40": "correct",
    "A.41": "correct",
    "A.42": "correct",
    "A.43": "correct",
    "A.44": "correct",
    "A.45": "correct",
    "A.46": "correct",
    "A.47": "correct",
    "A.48": "correct",
    "A.49": "correct",
    "A.50": "correct",
    "51": "numerically-hazardous",  # exact, but its 1F2 series fails in double precision
    "51-series": "numerically-hazardous",
    "52": "correct",
    "53": "correct",
    "Sec.4-decay": "correct",
    "Sec.4-limits": "correct",
    "Sec.4-N145": "numerically-hazardous",
    "Sec.3-torque": "incorrect",
    "Sec.3-closure": "incorrect",  # no closure makes the printed scheme converge to the solution
    "Sec.3-weighting": "incorrect",  # the scheme (21) + (38), not the algebra of (38)
    "completeness": "incorrect",
    "Fig.5": "correct",
    "Fig.5-reverse": "correct",
    "Sec.4-shakedown": "correct",
}

#: Rows whose verdict or numbers use this project's closure (T* from traction continuity at r = b).
CLOSURE_ROWS = {"33-38", "Sec.3-weighting", "Sec.4-limits", "Sec.4-N145", "completeness", "Fig.5"}

#: Names of the thresholds a check may cite (settings), or the half-unit rule of quoted numbers.
THRESHOLDS = ("TOL_FORMULA", "TOL_DOUBLE", "HAZARD_DIGITS_KEPT", "NEGLIGIBLE_CHANGE", "QUOTED_TORQUE_HALF_UNIT",
              "CONSISTENCY_FACTOR", "half a unit")


@pytest.fixture(scope="module")
def table():
    return errata.errata_table()


def test_verdicts_unchanged(table):
    assert errata.summary(table) == EXPECTED


def test_rows_well_formed(table):
    seen = set()
    for row in table:
        assert {"equation", "check", "max_rel_discrepancy", "verdict", "note", "note_latex", "details"} <= set(row)
        assert row["verdict"] in errata.VERDICTS
        assert row["details"]["kind"] in settings.KINDS
        d = row["max_rel_discrepancy"]
        assert d is None or (isinstance(d, float) and math.isfinite(d) and d >= 0)
        assert row["equation"] not in seen
        seen.add(row["equation"])
    json.dumps(table, allow_nan=False)


def test_rows_in_paper_order(table):
    numbers = [errata.paper_equations(row["equation"])[0] for row in table if errata.paper_equations(row["equation"])]
    assert numbers == sorted(numbers)
    first_statement = next(i for i, row in enumerate(table) if not errata.paper_equations(row["equation"]))
    assert all(not errata.paper_equations(row["equation"]) for row in table[first_statement:])


def test_formula_verdicts_follow_from_discrepancies(table):
    """Every row whose check cites TOL_FORMULA and is marked correct really is within it."""
    cited = [row for row in table if "TOL_FORMULA =" in row["check"] and row["verdict"] == "correct"]
    assert len(cited) >= 45
    for row in cited:
        assert row["max_rel_discrepancy"] <= errata.TOL_FORMULA, row["equation"]


def test_every_check_states_its_threshold(table):
    for row in table:
        assert any(name in row["check"] for name in THRESHOLDS), row["equation"]
    assert f"TOL_FORMULA = {errata.TOL_FORMULA:.0e}".replace("e-0", "e-") in table[0]["check"]


def test_definitions_are_marked(table):
    kinds = {row["equation"]: row["details"]["kind"] for row in table}
    assert {eq for eq, kind in kinds.items() if kind == "definition"} == {"31", "32"}
    for row in table:
        if row["details"]["kind"] == "definition":
            assert row["note"].startswith("Definition (consistent with")
            assert row["note_latex"].startswith("Definition, consistent with")


def test_every_paper_equation_has_a_row_or_a_reason(table):
    """Equations 1-53: each has a row or is in the explicit, justified exclusion list."""
    assert settings.PAPER_EQUATIONS == tuple(range(1, 54))
    cov = errata.coverage(table)
    assert cov["missing"] == []
    for number in range(1, 54):
        has_row = any(number in errata.paper_equations(row["equation"]) for row in table)
        reason = settings.UNCHECKED.get(number, "")
        assert has_row or len(reason.split()) >= 5, number
    assert sorted(cov["checked"]) == [n for n in range(1, 54) if n not in settings.UNCHECKED]


def test_paper_equations_of_labels():
    assert errata.paper_equations("33-38") == (33, 34, 35, 36, 37, 38)
    assert errata.paper_equations("A.40") == (40,)
    assert errata.paper_equations("51-series") == (51,)
    assert errata.paper_equations("Sec.3-weighting") == ()
    assert errata.paper_equations("Sec.4-N145") == ()
    assert errata.paper_equations("Fig.5") == ()


def test_verdicts_do_not_contradict_each_other(table):
    """A statement about the scheme or the text is not filed under an equation number (so '(33)-(38) correct'
    and 'the scheme (21) + (38) depends on the weighting' are two different claims), and no 'incorrect' row
    shows a discrepancy at the rounding level in its discrepancy column (a numerically hazardous formula is
    exact, so its discrepancy is small by definition)."""
    for row in table:
        if row["details"]["kind"] == "statement":
            assert errata.paper_equations(row["equation"]) == (), row["equation"]
        if row["verdict"] == "incorrect" and row["max_rel_discrepancy"] is not None:
            assert row["max_rel_discrepancy"] > errata.TOL_DOUBLE, row["equation"]


def test_closure_survey_findings(table):
    """Reviewed outcome of the closures row: which pathologies of the printed scheme depend on the closure."""
    rows = {r["equation"]: r for r in table}
    flags = rows["Sec.3-closure"]["details"]["pathologies"]
    assert flags["traction"] == dict.fromkeys(flags["traction"], True)
    assert flags["torque"] == {"above_spinning": False, "negative_alpha": False, "backward_slip_near_b": True,
                               "above_friction_limit": False, "weighting_dependent": False, "not_converging": True}
    assert flags["displacement"]["above_spinning"] is False and flags["displacement"]["not_converging"] is True
    survey = rows["Sec.3-closure"]["details"]["survey"]
    for closure, s in survey.items():  # the complete form converges whatever the closure
        assert s["error_complete"]["1000"] < s["error_complete"]["145"], closure
    assert not rows["Sec.3-closure"]["details"]["depends_on_closure"]


def _outside_math(text):
    """Text segments outside $...$ (escaped \\$ ignored)."""
    return re.split(r"(?<!\\)\$", text)[0::2]


def _assert_latex_ready(text, where):
    assert len(re.findall(r"(?<!\\)\$", text)) % 2 == 0, f"{where}: unbalanced $"
    assert text.count("{") == text.count("}"), f"{where}: unbalanced braces"
    for bad in ("e-0", "e+", "e-1", "e-2", "e-3", "e-4"):
        assert not re.search(rf"\d{re.escape(bad)}", text), f"{where}: {bad} in a number"
    for segment in _outside_math(text):
        assert not re.search(r"[\^_<>|]", segment), f"{where}: ASCII maths outside $: {segment!r}"
        assert not re.search(r"(?<!\\)[%&#]", segment), f"{where}: unescaped special outside $: {segment!r}"
        assert not re.search(r"\b[a-z]+\.[a-z_]+\(", segment), f"{where}: library identifier: {segment!r}"
        assert not re.search(r"\blam(_|\b)", segment), f"{where}: ASCII lam: {segment!r}"
        assert not re.search(r"\bint \d", segment), f"{where}: ASCII integral: {segment!r}"


def test_note_latex_ready_for_the_manuscript(table):
    for row in table:
        text = row["note_latex"]
        _assert_latex_ready(text, row["equation"])
        assert text[0].isupper() or text[0] in "$(", row["equation"]
        assert text.rstrip().endswith("."), row["equation"]
        assert "..." not in text
    _assert_latex_ready(errata.verdict_rules(latex=True), "rules")
    _assert_latex_ready(errata.closure_caveat(latex=True), "caveat")


def test_the_latex_checker_catches_ascii_maths():
    for bad in ("k^2 grows", "error 2.1e-03 here", "about $x$ and lam n", "unbalanced $x",
                "see integrals.integral_t_j1(x)"):
        with pytest.raises(AssertionError):
            _assert_latex_ready(bad, "probe")


def test_closure_caveat_is_stated(table):
    assert "closure" in settings.__doc__ and "b/a = 0.6" in settings.__doc__
    assert "4/3" in errata.closure_caveat() and "1.23" in errata.closure_caveat(latex=True)
    marked = {row["equation"] for row in table if row["details"]["depends_on_closure"]}
    assert marked == CLOSURE_ROWS
    for row in table:
        if row["equation"] in CLOSURE_ROWS:
            assert "closure" in row["note"] and "closure" in row["note_latex"], row["equation"]


def test_n145_is_measured_against_the_truth(table):
    """The T* error of N = 145 in the table equals the one computed through the public API."""
    details = {r["equation"]: r for r in table}["Sec.4-N145"]["details"]
    for b in settings.RADII:
        truth = solve(stick_radius=b)
        assert truth.method == "fast"
        truncated = solve(stick_radius=b, method="complete", n_terms=settings.N_PAPER).torque
        # the same computation in the table and here: a difference of T* ~ 1.2 values ~1e-3 apart, each to a few
        # ulp (the N = 145 solve's rounding, 145 EPS / rcond < 1e-12): relative 1e-9 of the difference
        error = abs(truncated - truth.torque)
        assert_within(abs(details["torque_error_absolute"][str(b)] - error), 1e-9 * error, "rounding of the solves")
    worst = max(details["torque_error"].values())
    assert 1e-3 < worst < settings.QUOTED_TORQUE_HALF_UNIT
    assert "Abel-Fredholm" in {r["equation"]: r for r in table}["Sec.4-N145"]["check"]


def test_verdict_rules():
    assert errata.verdict_formula(1e-30) == "correct"
    assert errata.verdict_formula(1e-3, corrected_discrepancy=1e-31) == "typo"
    assert errata.verdict_formula(1e-3) == "incorrect"
    assert errata.verdict_quoted(5.13562, 5.1356, 4)[0] == "correct"
    assert errata.verdict_quoted(5.13572, 5.1356, 4)[0] == "incorrect"
    assert errata.verdict_quoted(-0.7700, -0.77, 2)[0] == "correct"


# -- each new check fails for a corrupted formula ----------------------------------------------------------

def _fails(discrepancy):
    return errata.verdict_formula(discrepancy) == "incorrect"


def test_pressure_and_bilateral_shear_detect_wrong_formulas():
    assert _fails(bilateral.measure_pressure(lambda force, a: force / a**2))  # pi missing in (1)
    assert _fails(bilateral.measure_no_rt_shear(  # u ~ r^2 z is not a uniform twist
        lambda r, z, torque, mu, a: 2 * torque * r * r * z / (mpmath.pi * mu * a**5)))


def test_conditions_detect_wrong_formulas():
    assert _fails(conditions.measure_stick(  # u^B nonzero on z = 0
        lambda r, z, torque, mu, a: 2 * torque * r * (z + a) / (mpmath.pi * mu * a**4)))
    assert _fails(conditions.measure_slip(lambda f, force, a: f * force / (mpmath.pi * a)))  # a^2 -> a in (8)
    assert _fails(conditions.measure_side_traction(  # sigma_zt in place of sigma_rt on r = a
        lambda amp, lam, a, z: -amp * lam**2 * mpmath.exp(-lam * z) * mpmath.besselj(1, lam * a)))


def test_separation_detects_wrong_formulas():
    d11, d12 = solution_e.measure_separation(ode=lambda g, dg, d2g, lam, r: d2g(r) + dg(r) / r - lam**2 * g(r))
    assert not _fails(d11) and _fails(d12)
    d11, _ = solution_e.measure_separation(form=lambda lam, g: (lambda r, z: mpmath.exp(-lam * z * r) * g(r)))
    assert _fails(d11)
    d13, bounded = solution_e.measure_bounded(lambda lam, r: mpmath.besselj(1, lam * r))
    assert _fails(d13)
    _, bounded = solution_e.measure_bounded(lambda lam, r: mpmath.bessely(0, lam * r))
    assert not bounded
    assert _fails(solution_e.measure_harmonic(
        lambda amp, lam: (lambda r, z: amp * mpmath.exp(-lam * z) * mpmath.besselj(1, lam * r))))


def test_terms_and_side_detect_wrong_formulas():
    plus = {"16": lambda amp, lam, r, z: amp * lam**2 * mpmath.exp(-lam * z) * mpmath.besselj(2, lam * r)}
    out = solution_e.measure_terms(plus)
    assert _fails(out["16"]) and not _fails(out["15"])
    assert _fails(solution_e.measure_side(
        lambda amp, lam, a, z: -amp * lam**2 * mpmath.exp(-lam * z) * mpmath.besselj(1, lam * a)))
    assert _fails(solution_e.measure_eigen_condition(lambda n: mpmath.besseljzero(1, n)))  # J1 = 0 in (19)


@pytest.mark.parametrize("key, wrong", [
    ("22", lambda amps, lams, mu, r, z: series_terms._sum(amps, lams, 1, 1, r, z)),  # 1/mu missing
    ("23", lambda amps, lams, mu, r, z: -series_terms._sum(amps, lams, 2, 1, r, z)),  # J1 for J2
    ("24", lambda amps, lams, mu, r, z: -series_terms._sum(amps, lams, 1, 1, r, z)),  # lam for lam^2
    ("25", lambda amps, lams, mu, r, z: series_terms._sum(amps, lams, 2, 1, r, 0) / mu),
    ("26", lambda amps, lams, mu, r, z: -series_terms._sum(amps, [x * 1.5 for x in lams], 2, 1, r, 0)),
])
def test_series_terms_detect_wrong_formulas(key, wrong):
    out = series_terms.measure_series({key: wrong})
    assert _fails(out[key])
    assert all(not _fails(v) for k, v in out.items() if k != key)


def test_series_detects_wrong_eigenvalues():
    out = series_terms.measure_series(zeros=lambda n, a: mpmath.besseljzero(1, n) / a)  # J1 zeros: (9) fails
    assert _fails(out["21"])


@pytest.mark.parametrize("key, wrong, row", [
    ("27", lambda amps, zeros, r, c: dual_series._bessel_sum(amps, zeros, c["a"], r, 2) / c["a"], "27"),
    ("28-lhs", lambda amps, zeros, r, c: dual_series._bessel_sum(amps, zeros, c["a"], r, 2) / c["a"] ** 2, "28"),
    ("29", lambda tilde, zeros, r, c: dual_series._bessel_sum(tilde, zeros, c["a"], r, 2), "29"),
    ("30-rhs", lambda r, tstar, c: r * tstar - 1, "30"),
    ("31", lambda amps, c: [A * mpmath.pi / c["F"] for A in amps], "31"),
    ("32", lambda c: c["T"] / (c["f"] * c["F"] * c["a"]), "32"),
])
def test_dual_series_detects_wrong_formulas(key, wrong, row):
    assert _fails(dual_series.measure_dual({key: wrong})[row])


def test_quadrature_detects_a_wrong_formula():
    """The machinery would flag a sign error in (35): h with + 2 J0 J1 / lam."""
    with mpmath.workdps(40):
        lam = weak_form_mp.bessel_j2_zeros(3, 40)[2]
        nodes, weights = gauss_legendre(0, 1, 2 * lam)
        quad = mpmath.fsum(w * mpmath.besselj(1, lam * r) ** 2 * r for r, w in zip(nodes, weights, strict=True))
        j0, j1 = mpmath.besselj(0, lam), mpmath.besselj(1, lam)
        wrong = (j0 * j0 + 2 * j0 * j1 / lam + j1 * j1) / 2
        right = weak_form_mp.dini_norm(lam)
        assert errata.verdict_formula(float(abs(wrong - quad) / quad)) == "incorrect"
        assert errata.verdict_formula(float(abs(right - quad) / quad)) == "correct"


@pytest.mark.parametrize("flint", [True, False])
def test_products_of_j1_by_the_rule_against_closed_forms(flint, monkeypatch):
    """``Nodes.integral_of_j1`` (Arb balls, or mpf without python-flint) against closed forms the
    errata check independently: h (eq. 35) = int_0^1 J1(lam r)^2 r dr for lam not a zero of J2, and
    int_0^1 r^2 J1(lam r) dr = J2(lam) / lam.  The 20-point rule per period is exact to ~1e-38 for
    these (``gauss_legendre``); 40-digit rounding of ~1e3 terms: 1e-34 relative leaves 10x margin."""
    monkeypatch.setattr(quadrature_mp.ap, "FLINT", flint and quadrature_mp.ap.FLINT)
    with mpmath.workdps(40):
        lam = mpmath.mpf("731.3")
        nodes = quadrature_mp.Nodes(0, 1, 2 * lam)
        h = nodes.integral_of_j1([lam, lam], (0, 1))
        assert abs(h / weak_form_mp.dini_norm(lam) - 1) < mpmath.mpf(10) ** -34
        moment = nodes.integral_of_j1([lam], (0, 0, 1))
        assert abs(moment / (mpmath.besselj(2, lam) / lam) - 1) < mpmath.mpf(10) ** -34
        # a constant and a linear term at once: int_0^1 (3 - 2 r) J1 r dr = 3 int J1 r - 2 J2 / lam
        mixed = nodes.integral_of_j1([lam], (0, 3, -2))
        assert abs(mixed - (3 * nodes.integral_of_j1([lam], (0, 1)) - 2 * moment)) < mpmath.mpf(10) ** -36


def test_gauss_legendre_oscillatory():
    with mpmath.workdps(40):
        omega = mpmath.mpf(3000)
        nodes, weights = gauss_legendre(0, 1, omega)
        got = mpmath.fsum(w * mpmath.cos(omega * x) for x, w in zip(nodes, weights, strict=True))
        assert abs(got - mpmath.sin(omega) / omega) < mpmath.mpf(10) ** -34


def test_key_numbers(table):
    rows = {r["equation"]: r for r in table}
    comp = rows["completeness"]["details"]
    assert comp["alpha"] < 0  # backward rigid slip on the stick disc
    assert comp["min_slip_near_b"] < 0
    # int_0^1 u r^2 dr = 0 for every Dini term: the rounding of the N = 145 series and its quadrature
    assert_within(abs(comp["stick_moment"]), 1e-12, "rounding of the 145-term series, ~145^2 EPS")
    assert comp["published_small_b"]["0.3"] > 4 / 3
    # min_r (sigma_max(r) + 1) / r on 4000 points, attained at r = 1 exactly: (1 + 1) / 1, to rounding
    assert_within(abs(rows["Fig.5-reverse"]["details"]["torque_increment"] - 2.0), 1e-9, "rounding at r = 1")
    # each eigenfunction carries zero torque: the 1200-point rule of a 145-term series, rounding ~145 x 1200 EPS
    present = rows["Sec.3-torque"]["details"]["torque_present"]
    assert_within(max(abs(present[k] - float(k)) for k in ("1.0", "1.3")), 1e-12, "rounding of the series' torque")
    # the truth of the table is the default solver: the same number
    assert_within(abs(rows["Fig.5"]["details"]["torque_truth"] - solve(stick_radius=0.6).torque), 4 * EPS,
                  "the same computation")


# -- reports ---------------------------------------------------------------------------------------------

def test_write_markdown_report(table, tmp_path):
    path = tmp_path / "errata.md"
    errata.write_markdown_report(path, table)
    text = path.read_text()
    assert text.count("\n| ") >= len(table)
    assert "## Verdict rules" in text and "## Coverage" in text and "closure" in text
    assert [p.name for p in tmp_path.iterdir()] == ["errata.md"]


def test_markdown_report_lists_every_entry(table):
    text = errata.markdown_report(table, {"condition": [{"n_terms": 10, "raw": 1.5}]})
    for row in table:
        assert f"| {row['equation']} | {row['verdict']} |" in text
    assert "### condition" in text


def _tables_script():
    spec = importlib.util.spec_from_file_location("errata_tables", ROOT / "workflow" / "scripts" / "errata_tables.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _payload(table):
    return {
        "thresholds": {"WORK_DPS": errata.WORK_DPS, "TOL_FORMULA": errata.TOL_FORMULA,
                       "TOL_DOUBLE": errata.TOL_DOUBLE, "HAZARD_DIGITS_KEPT": errata.HAZARD_DIGITS_KEPT,
                       "NEGLIGIBLE_CHANGE": errata.NEGLIGIBLE_CHANGE,
                       "QUOTED_TORQUE_HALF_UNIT": errata.QUOTED_TORQUE_HALF_UNIT},
        "rules": {"latex": errata.verdict_rules(latex=True)},
        "closure_caveat": {"latex": errata.closure_caveat(latex=True)},
        "coverage": errata.coverage(table),
        "errata": table,
    }


def test_latex_table_and_macros(table):
    script = _tables_script()
    tex = script.errata_longtable(_payload(table))
    assert tex.count(r"\tabularnewline") == len(table)
    assert "e-0" not in tex and "e+" not in tex and "..." not in tex
    assert r"$^\dagger$" in tex and "no correct digit" in tex  # the diverging 1F2 series
    for row in table:
        assert row["note_latex"] in tex
    macros = script.errata_macros(_payload(table))
    assert macros["errata-checks"] == len(table)
    assert sum(macros[f"errata-{v}"] for v in errata.VERDICTS) == len(table)
    assert macros["errata-equations"] == 53 and macros["errata-unchecked-list"] == "none"
    assert macros["errata-coverage"].startswith("All 53 numbered equations")
    assert script.discrepancy_cell(2.1e-3) == r"$2.1\times10^{-3}$"
    assert script.discrepancy_cell(3.7e181) == "no correct digit"
    assert script.equation_label("33-38") == "(33)--(38)" and script.equation_label("A.40") == "(40)"


@pytest.mark.skipif(shutil.which("pdflatex") is None, reason="pdflatex not installed")
def test_latex_table_compiles_without_overfull_lines(table, tmp_path):
    """The table in the manuscript's page geometry (11 pt, A4, 25 mm margins, \\small) typesets cleanly."""
    script = _tables_script()
    (tmp_path / "errata_table.tex").write_text(script.errata_longtable(_payload(table)))
    (tmp_path / "doc.tex").write_text(
        "\\documentclass[11pt,a4paper]{article}\n\\usepackage[margin=25mm]{geometry}\n"
        "\\usepackage{amsmath,amssymb,booktabs,longtable}\n\\usepackage{caption}\n\\captionsetup{font=small}\n"
        "\\begin{document}\n{\\small\n\\input{errata_table.tex}\n}\n\\end{document}\n")
    for _ in range(2):  # longtable needs two passes for its column widths
        run = subprocess.run(["pdflatex", "-interaction=nonstopmode", "-halt-on-error", "doc.tex"], cwd=tmp_path,
                             capture_output=True, text=True, timeout=120)
        assert run.returncode == 0, run.stdout[-2000:]
    log = (tmp_path / "doc.log").read_text(errors="replace")
    assert "Overfull" not in log


def test_cli_errata_json(table, capsys):
    assert cli.main(["errata", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert {r["equation"]: r["verdict"] for r in data} == EXPECTED
    assert all(isinstance(r["note_latex"], str) and r["note_latex"] for r in data)


def test_cli_errata_bad_input(capsys):
    assert cli.main(["errata", "--n-terms", "5"]) == 2
    out = capsys.readouterr()
    assert out.out == "" and len(out.err.strip().splitlines()) == 1


def test_typeset_numbers():
    from torsional_contact.typeset import sci

    assert sci(2.1e-3) == r"2.1\times10^{-3}"
    assert sci(0.51) == "0.51" and sci(0.51, always=True) == r"5.1\times10^{-1}"
    assert sci(1e-28, 0) == "10^{-28}"
    with pytest.raises(ValueError, match="finite"):
        sci(math.inf)
    assert sci(123.4) == "123"
