"""The errata table: structure, the verdict rules, and the verdicts themselves.

The verdicts are computed by ``errata.errata_table``; ``EXPECTED`` below is the
reviewed outcome.  If a change of code or threshold flips a verdict, this test fails.
"""

import json
import math

import mpmath
import pytest

from torsional_contact.io import cli
from torsional_contact.verification import errata, weak_form_mp
from torsional_contact.verification.quadrature import gauss_legendre

EXPECTED = {
    "2": "correct",
    "4": "correct",
    "5": "correct",
    "6": "correct",
    "10": "correct",
    "15": "correct",
    "16": "correct",
    "17": "correct",
    "20": "correct",
    "33-38": "correct",
    "38-weighting": "incorrect",
    "34": "correct",
    "35": "correct",
    "51": "numerically-hazardous",  # exact, but its 1F2 series fails in double precision
    "52": "correct",
    "53": "correct",
    "51-series": "numerically-hazardous",
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
    "Sec.4-decay": "correct",
    "Sec.4-limits": "correct",
    "Sec.4-N145": "numerically-hazardous",
    "Sec.3-torque": "incorrect",
    "completeness": "incorrect",
    "Fig.5": "correct",
    "Fig.5-reverse": "correct",
    "Sec.4-shakedown": "correct",
}


@pytest.fixture(scope="module")
def table():
    return errata.errata_table()


def test_verdicts_unchanged(table):
    assert errata.summary(table) == EXPECTED


def test_rows_well_formed(table):
    seen = set()
    for row in table:
        assert {"equation", "check", "max_rel_discrepancy", "verdict", "note"} <= set(row)
        assert row["verdict"] in errata.VERDICTS
        d = row["max_rel_discrepancy"]
        assert d is None or (isinstance(d, float) and math.isfinite(d) and d >= 0)
        assert row["equation"] not in seen
        seen.add(row["equation"])
    json.dumps(table, allow_nan=False)


def test_formula_verdicts_follow_from_discrepancies(table):
    """Every formula entry marked correct really is within the stated tolerance."""
    for row in table:
        if row["equation"] in {"35", "51", "52", "53", "34", "33-38"} or row["equation"].startswith("A."):
            assert row["max_rel_discrepancy"] <= errata.TOL_FORMULA


def test_verdict_rules():
    assert errata.verdict_formula(1e-30) == "correct"
    assert errata.verdict_formula(1e-3, corrected_discrepancy=1e-31) == "typo"
    assert errata.verdict_formula(1e-3) == "incorrect"
    assert errata.verdict_quoted(5.13562, 5.1356, 4)[0] == "correct"
    assert errata.verdict_quoted(5.13572, 5.1356, 4)[0] == "incorrect"
    assert errata.verdict_quoted(-0.7700, -0.77, 2)[0] == "correct"


def test_quadrature_detects_a_wrong_formula():
    """The machinery would flag a sign error in (35): h with + 2 J0 J1 / lam."""
    with mpmath.workdps(40):
        lam = weak_form_mp.j2_zeros(3, 40)[2]
        nodes, weights = gauss_legendre(0, 1, 2 * lam)
        quad = mpmath.fsum(w * mpmath.besselj(1, lam * r) ** 2 * r for r, w in zip(nodes, weights, strict=True))
        j0, j1 = mpmath.besselj(0, lam), mpmath.besselj(1, lam)
        wrong = (j0 * j0 + 2 * j0 * j1 / lam + j1 * j1) / 2
        right = weak_form_mp.dini_norm(lam)
        assert errata.verdict_formula(float(abs(wrong - quad) / quad)) == "incorrect"
        assert errata.verdict_formula(float(abs(right - quad) / quad)) == "correct"


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
    assert abs(comp["stick_moment"]) < 1e-12
    assert comp["published_small_b"]["0.3"] > 4 / 3
    assert rows["Fig.5-reverse"]["details"]["torque_increment"] == pytest.approx(2.0, abs=1e-9)
    assert max(rows["Sec.3-torque"]["details"]["torque_present"][k] - float(k) for k in ("1.0", "1.3")) < 1e-12


def test_write_markdown_report(table, tmp_path):
    path = tmp_path / "errata.md"
    errata.write_markdown_report(path, table)
    assert path.read_text().count("\n| ") >= len(table)
    assert [p.name for p in tmp_path.iterdir()] == ["errata.md"]


def test_markdown_report_lists_every_entry(table):
    text = errata.markdown_report(table, {"condition": [{"n_terms": 10, "raw": 1.5}]})
    for row in table:
        assert f"| {row['equation']} | {row['verdict']} |" in text
    assert "### condition" in text


def test_cli_errata_json(table, capsys):
    assert cli.main(["errata", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert {r["equation"]: r["verdict"] for r in data} == EXPECTED


def test_cli_errata_bad_input(capsys):
    assert cli.main(["errata", "--n-terms", "5"]) == 2
    out = capsys.readouterr()
    assert out.out == "" and len(out.err.strip().splitlines()) == 1
