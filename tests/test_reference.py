"""The high-precision reference (verification/reference.py) against independent computations.

Independent means: mpmath.besseljzero for the zeros, mpmath.quad for the integrals,
a second precision / a second linear-solve backend for the solve, and a direct
evaluation of the traction series for the regularity condition.
"""

import json
import math
import re
import subprocess
import sys
import warnings

import flint
import mpmath
import numpy as np
import pytest
from arb_points import at_mpf
from tolerances import EPS, assert_close, assert_within

from torsional_contact.diagnostics import AccuracyWarning, ResolutionWarning
from torsional_contact.io import cli
from torsional_contact.solvers import weak_form as formulations
from torsional_contact.special import integrals
from torsional_contact.special.zeros import bessel_j2_zeros
from torsional_contact.verification import arbitrary_precision, crosscheck, reference, weak_form_mp


def _quad(f, lower, upper, lam_max):
    """mpmath.quad with breakpoints every half period of the fastest oscillation."""
    pieces = max(2, int(math.ceil(float(upper - lower) * float(lam_max) / math.pi)))
    points = [lower + (upper - lower) * mpmath.mpf(k) / pieces for k in range(pieces + 1)]
    return mpmath.quad(f, points)


def test_zeros_match_besseljzero_and_restore_precision():
    before = mpmath.mp.dps
    lam = weak_form_mp.bessel_j2_zeros(145, 50)
    assert mpmath.mp.dps == before
    with mpmath.workdps(50):
        for n in (1, 2, 5, 60, 145):
            assert_within(abs(lam[n - 1] - mpmath.besseljzero(2, n)), mpmath.mpf(10) ** -48 * lam[n - 1],
                          "50-digit zeros: 100 units of the last digit")
    picked = weak_form_mp.bessel_j2_zeros_at([3, 145], 50)
    assert picked == (lam[2], lam[144])


@pytest.mark.skipif(not arbitrary_precision.FLINT, reason="needs python-flint")
@pytest.mark.parametrize(("indices", "digits"), [(range(1, 61), 40), ([1, 145, 320, 3000, 3001], 40),
                                                 ([2, 145, 290], 70)])
def test_zeros_by_newton_in_arb_and_in_mpmath_are_the_same_numbers(indices, digits):
    """The Arb iteration (the default) and mpmath's round to the same mpf: both stop at a step below
    10^-(digits + 5) relative, far inside the last digit kept; and J2 vanishes there to the digits asked."""
    start = [float(bessel_j2_zeros(max(indices))[i - 1]) for i in indices]
    arb = weak_form_mp._newton_j2(start, digits, arithmetic="arb")
    mp = weak_form_mp._newton_j2(start, digits, arithmetic="mpmath")
    assert arb == mp
    with mpmath.workdps(digits + 10):
        for lam in arb:  # |J2(lam)| <= |J2'| |lam - lam*|, |lam - lam*| <= half a unit of the last digit
            assert_within(abs(mpmath.besselj(2, lam)), mpmath.mpf(10) ** (1 - digits) * lam, "a zero of J2")
    with pytest.raises(ValueError, match="arithmetic must be"):
        weak_form_mp._newton_j2(start, digits, arithmetic="flint")


@pytest.mark.parametrize("lam_index", [1, 7, 40])
def test_closed_forms_match_quadrature(lam_index):
    with mpmath.workdps(30):
        lam = weak_form_mp.bessel_j2_zeros(max(40, lam_index + 1), 30)
        x, y = lam[lam_index - 1], lam[lam_index]
        b = mpmath.mpf("0.35")
        # 30-digit closed forms against 30-digit quadrature of oscillatory Bessel products: cancellation in the
        # closed forms (Lommel's differences of J products, up to lam ~ 130) costs up to ~4 digits; 10^-25
        tol = mpmath.mpf(10) ** -25
        h = _quad(lambda r: mpmath.besselj(1, x * r) ** 2 * r, 0, 1, 2 * x)
        assert_within(abs(weak_form_mp.dini_norm(x) - h), tol * h, "30 digits less cancellation")
        off = _quad(lambda r: mpmath.besselj(1, x * r) * mpmath.besselj(1, y * r) * r, b, 1, x + y)
        assert_within(abs(weak_form_mp.lommel_offdiagonal(x, y, b) - off), tol * abs(off),
                      "30 digits less cancellation")
        diag = _quad(lambda r: mpmath.besselj(1, x * r) ** 2 * r, b, 1, 2 * x)
        assert_within(abs(weak_form_mp.lommel_diagonal(x, b) - diag), tol * diag, "30 digits less cancellation")
        torque = mpmath.mpf("1.25")
        load = _quad(lambda r: (torque * r - 1) * mpmath.besselj(1, x * r) * r, b, 1, x)
        for form in ("hyp1f2", "struve"):
            assert_within(abs(weak_form_mp.load_vector(x, b, torque, form) - load), tol * abs(load),
                          "30 digits less cancellation")


def test_hyp1f2_and_struve_forms_agree_at_large_argument():
    with mpmath.workdps(40):
        for x in ("0.5", "37.2", "460.1", "9000.3"):
            g1 = weak_form_mp.integral_t_j1_hyp1f2(mpmath.mpf(x))
            g2 = weak_form_mp.integral_t_j1_struve(mpmath.mpf(x))
            # two 40-digit forms; the 1F2 series cancels like exp(-x)-size terms up to ~e^x / x^1.5: 5 digits at 9000
            assert_within(abs(g1 - g2), mpmath.mpf(10) ** -35 * abs(g2), "40 digits less the 1F2 cancellation")


def test_assembly_matches_double_precision_assembly():
    lam = weak_form_mp.bessel_j2_zeros(30, 30)
    lam_double = bessel_j2_zeros(30)
    for method in ("published", "complete"):
        with mpmath.workdps(30):
            m_mp, rt_mp, rc_mp = weak_form_mp.assemble(method, lam, mpmath.mpf("0.45"))
        m_dp, rt_dp, rc_dp = formulations.assemble(method, lam_double, 0.45)
        m_mp = np.array(m_mp.tolist(), dtype=float)
        # the double closed forms: ~lam EPS conditioning of J at lam <= 96 of the largest entries: 100 lam_N EPS
        scale = 100 * lam_double[-1] * EPS
        assert_within(np.max(np.abs(m_mp - m_dp)), scale * np.max(np.abs(m_dp)), "conditioning of J(lam), lam <= 96")
        assert_close(np.array(rt_mp, dtype=float), rt_dp, "conditioning of J(lam)", atol=scale * np.max(np.abs(rt_dp)))
        assert_close(np.array(rc_mp, dtype=float), rc_dp, "conditioning of J(lam)", atol=scale * np.max(np.abs(rc_dp)))
    with mpmath.workdps(30):
        c_mp = np.array(weak_form_mp.coupling_matrix(lam[:8], mpmath.mpf("0.45")).tolist(), dtype=float)
    c_dp = integrals.coupling_matrix(lam_double[:8], 0.45)
    assert_within(np.max(np.abs(c_mp - c_dp)), 100 * lam_double[7] * EPS * np.max(np.abs(c_dp)),
                  "conditioning of J(lam), lam <= 27")


@pytest.mark.parametrize("method", ["published", "complete"])
def test_solution_independent_of_precision_backend_and_form(method):
    flint_prec = None if arbitrary_precision.flint is None else arbitrary_precision.flint.ctx.prec
    a = reference.solve_reference(0.6, method, 25, 30)
    b = reference.solve_reference(0.6, method, 25, 45, backend="mpmath", form="struve")
    with mpmath.workdps(45):
        # the 30-digit solve against the 45-digit one: 30 digits less the system's conditioning (~10)
        tol = mpmath.mpf(10) ** -29
        assert_within(abs(a.torque - b.torque), tol * b.torque, "30 digits less conditioning")
        worst = max(abs(x - y) for x, y in zip(a.amplitudes, b.amplitudes, strict=True))
        assert_within(worst, tol * max(abs(y) for y in b.amplitudes), "30 digits less conditioning")
        if method == "complete":
            assert_within(abs(a.rigid_rotation - b.rigid_rotation), tol * abs(b.rigid_rotation),
                          "30 digits less conditioning")
        else:
            assert a.rigid_rotation is None and b.rigid_rotation is None
    assert a.solve_bound is not None and a.solve_bound < 1e-40  # rigorous (Arb) bound on the solve
    assert mpmath.mp.dps == 15
    assert arbitrary_precision.flint is None or arbitrary_precision.flint.ctx.prec == flint_prec


@pytest.mark.slow  # long: the CI tier (workflow/test.sh) runs it
def test_regularity_condition_and_stick_condition_hold():
    """(v): the traction series equals 1 at r = b; the stick equation holds in the weak sense."""
    sol = reference.solve_reference("0.5", "complete", 30, 40)
    with mpmath.workdps(40):
        b = sol.stick_radius
        traction = sol.torque * b - mpmath.fsum(
            c * x * mpmath.besselj(1, x * b) for c, x in zip(sol.amplitudes, sol.eigenvalues, strict=True)
        )
        assert_within(abs(traction - 1), mpmath.mpf(10) ** -35, "40 digits less the 30-term sum's cancellation")

        # the extra row (iv): int_0^1 R(r) r^2 dr = 0 with R the stick / slip residual, by quadrature; the residual
        # in Arb (tests/arb_points.py: mpmath's J1 at 40 digits made this test take half a minute)
        decimals = mpmath.mp.dps + 15
        terms = [(mpmath.nstr(c, decimals), mpmath.nstr(x, decimals))
                 for c, x in zip(sol.amplitudes, sol.eigenvalues, strict=True)]
        rotation, torque = mpmath.nstr(sol.rigid_rotation, decimals), mpmath.nstr(sol.torque, decimals)

        def residual_arb(t, stick):
            series = [flint.arb(c) * (flint.arb(x) * t).bessel_j(1) for c, x in terms]
            if stick:
                return flint.arb(rotation) * t + sum(series)
            return sum(s * flint.arb(x) for s, (_, x) in zip(series, terms, strict=True)) - flint.arb(torque) * t + 1

        def residual(r):
            return at_mpf(lambda t: residual_arb(t, r < b), r, absolute=True)

        lam_max = sol.eigenvalues[-1]
        moment = _quad(lambda r: residual(r) * r * r, 0, b, lam_max) + _quad(
            lambda r: residual(r) * r * r, b, 1, lam_max
        )
        assert_within(abs(moment), mpmath.mpf(10) ** -30, "40-digit quadrature of a 30-term residual")


@pytest.mark.parametrize("method", ["published", "complete"])
@pytest.mark.parametrize("b", [0.3, 0.6, 0.9])
def test_scipy_agrees_with_reference_to_condition_number(method, b):
    ref = reference.solve_reference(b, method, 40, 30)
    with warnings.catch_warnings():
        warnings.simplefilter("error", AccuracyWarning)
        err = crosscheck.rounding_error(ref)
    # rounding of a dense solve: conditioning (1 / rcond) times EPS, times the growth allowed by
    # crosscheck.GROWTH_DIGITS
    allowed = 10**crosscheck.GROWTH_DIGITS * EPS / err["rcond"]
    assert_within(err["torque"], allowed, "100 EPS / rcond")
    assert_within(err["amplitudes"], allowed, "100 EPS / rcond")
    if method == "complete":
        assert_within(err["rigid_rotation"], allowed, "100 EPS / rcond")
    # the backward-stable solve's bound (crosscheck.GROWTH_DIGITS beyond log10 of the condition number)
    assert_within(10 ** err["digits_lost"], 10 ** (err["predicted_digits_lost"] + crosscheck.GROWTH_DIGITS),
                  "error factor: kappa x 10^GROWTH_DIGITS")


def test_condition_numbers_small_n():
    rows = crosscheck.condition_numbers([20, 60], 0.6)
    assert {(r["n_terms"], r["method"]) for r in rows} == {
        (20, "published"),
        (20, "complete"),
        (60, "published"),
        (60, "complete"),
    }
    for r in rows:
        assert 1 <= r["equilibrated"] < np.inf and 1 <= r["raw"] < np.inf
    # independent check of the estimate: exact 1-norm condition number of the raw matrix
    lam = bessel_j2_zeros(20)
    matrix, _, _ = formulations.assemble("complete", lam, 0.6)
    exact = np.linalg.cond(matrix, 1)
    est = next(r["raw"] for r in rows if r["n_terms"] == 20 and r["method"] == "complete")
    assert exact / 3 <= est <= exact * 1.0000001


def test_condition_numbers_shared_factorisation_against_own_factorisations():
    """One LU per N (bordered for the complete form, scaled for the equilibrated ones) against dgecon on each
    matrix's own LU and against the exact 1-norm condition number."""
    from torsional_contact.solvers.equilibration import equilibrate, reciprocal_condition

    n = 300
    rows = crosscheck.condition_numbers([n], 0.6)
    lam = bessel_j2_zeros(n)
    for method in ("published", "complete"):
        matrix, _, _ = formulations.assemble(method, lam, 0.6)
        row = next(r for r in rows if r["method"] == method)
        for key, m in (("raw", matrix), ("equilibrated", equilibrate(matrix))):
            own = 1.0 / reciprocal_condition(m)
            exact = np.linalg.cond(m, 1)
            # the same estimator (Hager-Higham, dgecon) on the same inverse through different factors: the solves
            # differ by kappa EPS relative each, and the estimate is the norm of one solve: 1e3 kappa EPS
            assert_close(row[key], own, "the same estimator through other factors: 1e3 kappa EPS",
                         rtol=1e3 * exact * EPS)
            # an estimate is the norm of a computed column of A^-1 (a lower bound, to rounding) and at worst a
            # small factor below (3 covers LAPACK's estimator on these matrices, as for the own factorisation)
            assert exact / 3 <= row[key] <= exact * (1 + 1e3 * exact * EPS)


def _random_system(seed):
    """A random square matrix of one of four kinds (dense, triangular-heavy, badly row-scaled, unit lower plus
    noise) and a random border; dgecon's estimate falls short of the exact ||A^-1||_1 on some of them."""
    rng = np.random.default_rng(seed)
    n = int(rng.integers(2, 60))
    kind = seed % 4
    if kind == 0:
        a = rng.standard_normal((n, n))
    elif kind == 1:
        a = np.triu(rng.standard_normal((n, n))) + 0.1 * np.eye(n)
    elif kind == 2:
        a = rng.standard_normal((n, n)) * np.exp(rng.uniform(-5, 5, n))[:, None]
    else:
        a = np.eye(n) + 2.0 * np.tril(rng.uniform(-1, 1, (n, n)), -1)
    return a, rng.standard_normal(n), rng.standard_normal(n), float(rng.standard_normal())


def _one_norm(matrix):
    return np.max(np.sum(np.abs(matrix), axis=0))


def test_rcond_estimate_is_dgecon_step_for_step():
    """dlacn2's iteration driven by triangular solves against LAPACK's dgecon on explicitly formed factors: of A,
    of R A C (factors R_p L R_p^-1, R_p U C), of A bordered by a row and a column, and of both; on random matrices,
    some of them where the estimate stops short of the exact ||A^-1||_1 (so the iterations' paths are compared,
    not only their limit).  The two differ by the rounding of their solves (1e3 kappa EPS, as the estimates
    through other factors in test_condition_numbers_shared_factorisation_against_own_factorisations, times the
    factors' growth) and are lower bounds of the exact norm (dense inverse) to the same rounding."""
    from scipy import linalg

    short = 0
    for seed in range(200):
        a, column, border_row, corner = _random_system(seed)
        n = a.shape[0]
        lu, pivots = linalg.lu_factor(a)
        order = crosscheck._row_order(pivots)
        lower, upper = np.tril(lu, -1) + np.eye(n), np.triu(lu)
        # bordered factors, by dense solves: L u = P c, l U = r, pivot d - l.u
        u = np.linalg.solve(lower, column[order])
        l_row = np.linalg.solve(upper.T, border_row)
        pivot = corner - l_row @ u
        bordered_lu = np.block([[lu, u[:, None]], [l_row[None, :], np.array([[pivot]])]])
        bordered = np.block([[a, column[:, None]], [border_row[None, :], np.array([[corner]])]])
        rng = np.random.default_rng(seed + 1000)
        row, col = np.exp(rng.uniform(-3, 3, n + 1)), np.exp(rng.uniform(-3, 3, n + 1))
        for matrix, factors, border, order_m in ((a, lu, None, order), (bordered, bordered_lu, (u, l_row, pivot),
                                                                          np.append(order, n))):
            m = matrix.shape[0]
            r_p, c = row[:m][order_m], col[:m]
            scaled_factors = np.tril(factors, -1) * (r_p[:, None] / r_p[None, :]) + np.triu(factors) * (
                r_p[:, None] * c[None, :])
            scaled = matrix * row[:m, None] * c[None, :]
            for target, target_factors, scale in ((matrix, factors, None), (scaled, scaled_factors, (r_p, c))):
                anorm = _one_norm(target)
                expected = linalg.lapack.dgecon(target_factors, anorm, norm="1")[0]
                estimate = crosscheck._rcond_estimate(lu, anorm, border, scale)
                exact = 1.0 / (anorm * _one_norm(np.linalg.inv(target)))
                # the solves are backward stable with |dA| <= gamma_n |L||U|: their relative forward error is
                # kappa EPS times the growth || |L||U| ||_1 / ||A||_1 (large where a border's pivot is small)
                growth = _one_norm(np.abs(np.tril(target_factors, -1) + np.eye(m)) @ np.abs(np.triu(target_factors)))
                kappa_eps = EPS / exact * growth / anorm
                assert_close(estimate, expected, "dgecon's iteration through other solves: 1e3 kappa growth EPS",
                             rtol=1e3 * kappa_eps)
                assert estimate >= exact * (1 - 1e3 * kappa_eps)
                short += expected > exact * (1 + 1e3 * kappa_eps)
    assert short >= 10  # the set exercises iterations that stop before the largest column


@pytest.mark.parametrize("n", [1, 7, 300])
@pytest.mark.parametrize("kind", ["assembled", "random"])
def test_bordered_norms_against_the_plain_expressions(n, kind):
    """The scalings of A and of the bordered matrix bit for bit as ``scalings`` gives them on the formed matrices;
    their raw and equilibrated 1-norms within N EPS of the exact column sums (math.fsum of the formed matrices'
    entries), the bound of any order of summation of N + 1 non-negative terms."""
    from torsional_contact.solvers.equilibration import equilibrate, scalings

    if kind == "assembled":
        lam = bessel_j2_zeros(n)
        published, _, _ = formulations.assemble("published", lam, 0.6, order="F")
        column, row, corner, _, _ = formulations.complete_border(lam, 0.6)
    else:
        rng = np.random.default_rng(n)
        published = np.asfortranarray(rng.standard_normal((n, n)) * np.exp(rng.uniform(-20, 20, n))[:, None])
        column, row = rng.standard_normal(n) * np.exp(rng.uniform(-20, 20, n)), rng.standard_normal(n)
        corner = float(rng.standard_normal())
    complete = np.block([[published, column[:, None]], [row[None, :], np.array([[corner]])]])
    norms = crosscheck._bordered_norms(published, column, row, corner)
    for method, matrix in (("published", np.ascontiguousarray(published)), ("complete", complete)):
        anorm, row_scale, col_scale, anorm_equilibrated = norms[method]
        plain_row, plain_col = scalings(matrix)
        assert np.array_equal(row_scale, plain_row) and np.array_equal(col_scale, plain_col)
        for value, formed in ((anorm, matrix), (anorm_equilibrated, equilibrate(matrix))):
            exact = max(math.fsum(np.abs(formed[:, j])) for j in range(formed.shape[1]))
            assert_within(abs(value - exact), formed.shape[0] * EPS * exact, "any summation order: N EPS")


def test_rcond_estimate_degenerate_cases():
    """n = 1 (the estimate is |1/a|, exact), a zero pivot and a zero matrix (0, as dgecon)."""
    from scipy import linalg

    lu = np.array([[-4.0]])
    assert crosscheck._rcond_estimate(lu, 4.0) == linalg.lapack.dgecon(lu, 4.0, norm="1")[0] == 1.0
    singular = np.array([[1.0, 2.0], [0.0, 0.0]])
    assert crosscheck._rcond_estimate(singular, 3.0) == 0.0
    assert crosscheck._rcond_estimate(np.zeros((3, 3)), 0.0) == 0.0


@pytest.mark.parametrize("b", [0.1, 0.6, 0.9])
def test_weak_forms_at_published_is_solve_series_bit_for_bit(b, monkeypatch):
    """The published system assembled in Fortran order and equilibrated in place, by blocks (at every size):
    solve_series' T* bit for bit, and its rounding bound EPS / rcond that of solve_series' dgecon, to the
    rounding of the estimate's solves (1e3 kappa EPS) and of the 1-norm's summation ((N + log2 N) EPS)."""
    from torsional_contact.solvers import equilibration

    monkeypatch.setattr(equilibration, "_LARGE", 0)
    monkeypatch.setattr(equilibration, "_BLOCK_ENTRIES", 5000)
    n = 300
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", formulations.UnphysicalResultWarning)
        out = crosscheck.weak_forms_at(b, n)
        own = formulations.solve_series(b, "published", n)
    assert out["published"][0] == own.torque
    kappa_eps = EPS / own.rcond
    assert_close(out["rounding_bound"], kappa_eps, "the same estimate: 1e3 kappa EPS + (N + 9) EPS",
                 rtol=1e3 * kappa_eps + (n + 9) * EPS)


@pytest.mark.parametrize("b", [0.3, 0.9])
def test_truncation_errors_one_factorisation(b):
    """Both weak forms at the converged N from one LU: the published solve is solve_series' own; the complete one
    (block elimination) agrees with solve_series' own dense solve to the rounding bound of a stable solve."""
    n = 600
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", formulations.UnphysicalResultWarning)
        rows = {r["method"]: r for r in crosscheck.truncation_errors(b, 145, n)}
        own = {m: formulations.solve_series(b, m, n) for m in ("published", "complete")}
    assert rows["published"]["torque_converged"] == own["published"].torque  # the same operations
    kappa_eps = rows["complete"]["converged_rounding_bound"]  # EPS / rcond of the equilibrated published matrix
    # two backward-stable solves of one system differ by the forward error bound kappa x growth x EPS, growth
    # as ``crosscheck.GROWTH_DIGITS``; the complete system's condition is the published one's to a few %
    bound = 10**crosscheck.GROWTH_DIGITS * kappa_eps
    assert_within(abs(rows["complete"]["torque_converged"] - own["complete"].torque) / own["complete"].torque,
                  bound, "two stable solves: 10^GROWTH_DIGITS EPS / rcond")
    assert_within(abs(rows["complete"]["rigid_rotation_converged"] - own["complete"].rigid_rotation)
                  / abs(own["complete"].rigid_rotation), bound / abs(own["complete"].rigid_rotation),
                  "two stable solves, omega against |x| ~ 1: 10^GROWTH_DIGITS EPS / rcond")


@pytest.mark.parametrize("b, n, message", [
    (0.0, 10, "stick_radius must lie in (0, 1]"), (1.5, 10, "stick_radius must lie in [0, 1]"),
    (-0.1, 10, "stick_radius must lie in [0, 1]"), (math.nan, 10, "stick_radius must be finite"),
    (0.5, 0, "n_terms must be an integer >= 1"), (0.5, 2.5, "n_terms must be an integer >= 1"),
    (5e-324, 60, "is too small for the weak forms"), (1e-300, 60, "is too small for the weak forms"),
    (1e-200, 60, "is too small for the weak forms"),
])
def test_weak_forms_at_rejects_bad_input_naming_the_argument(b, n, message):
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)  # no numpy warning on the way
        warnings.simplefilter("ignore", AccuracyWarning)  # the Schur complement at 1e-200: ours, before the error
        with pytest.raises(ValueError, match=re.escape(message)):
            crosscheck.weak_forms_at(b, n)


def test_weak_forms_at_an_unresolved_stick_radius_warns():
    with pytest.warns(ResolutionWarning, match="stick_radius=1e-12 is not resolved by n_terms=60"):
        crosscheck.weak_forms_at(1e-12, 60)


def test_write_json_atomic(tmp_path):
    sols = [reference.solve_reference(0.6, "complete", 10, 25)]
    path = tmp_path / "ref.json"
    reference.write_reference_json(path, sols)
    data = json.loads(path.read_text())
    assert [p.name for p in tmp_path.iterdir()] == ["ref.json"]
    entry = data["solutions"][0]
    assert entry["n_terms"] == 10 and entry["digits"] == 25 and entry["method"] == "complete"
    assert len(entry["torque"].replace(".", "").lstrip("0")) >= 25
    assert data["metadata"]["packages"]["mpmath"] == mpmath.__version__
    with mpmath.workdps(25):
        assert_within(abs(mpmath.mpf(entry["torque"]) - sols[0].torque), mpmath.mpf(10) ** -24 / 2,
                      "25 printed digits: half a unit of the 25th of T* ~ 1.2", exact=True)


@pytest.mark.skipif(arbitrary_precision.flint is None, reason="the Arb assembly needs python-flint")
@pytest.mark.parametrize("method", ["published", "complete"])
@pytest.mark.parametrize("b", ["0.1", "0.9"])  # a small stick disc and a thin slip annulus
def test_arb_assembly_agrees_with_mpmath_assembly(method, b):
    digits = 40
    with warnings.catch_warnings():  # N = 60 does not resolve b = 0.9 and the printed form leaves [1, 4/3]:
        warnings.simplefilter("ignore")  # both paths solve the same truncated system, which is the point
        arb = reference.solve_reference(b, method, 60, digits, assembly="arb")
        mp = reference.solve_reference(b, method, 60, digits, assembly="mpmath")
    with mpmath.workdps(digits + 10):
        # both are the same system at digits + 20 working digits, less its conditioning (~4 digits),
        # then rounded to ``digits``: they differ by at most the two roundings, 10^-digits relative
        tol = mpmath.mpf(10) ** -digits
        assert_within(abs(arb.torque - mp.torque), tol * abs(mp.torque), "two roundings to the digits")
        for x, y in zip(arb.amplitudes, mp.amplitudes, strict=True):
            assert_within(abs(x - y), tol * abs(y), "two roundings to the digits")
        if method == "complete":
            assert_within(abs(arb.rigid_rotation - mp.rigid_rotation), tol * abs(mp.rigid_rotation),
                          "two roundings to the digits")
    # the Arb ball covers the assembly's rounding as well as the solve's: still far below 10^-digits
    assert arb.solve_bound is not None and arb.solve_bound < mpmath.mpf(10) ** -(digits + 5)


@pytest.mark.skipif(arbitrary_precision.flint is None, reason="the Arb assembly needs python-flint")
def test_arb_assembly_keeps_the_functions_of_the_zeros_exact_across_radii_and_precisions():
    """The Arb assembly evaluates J_k(lam_n) and int_0^lam_n t J1 once per set of zeros and working precision: its
    matrices are ball for ball those of an assembly without the kept values, at a second radius (values kept) and at
    another precision (not the 30-digit values reused at 40)."""
    from torsional_contact.verification import weak_form_arb

    with mpmath.workdps(60), arbitrary_precision.working_digits(50):  # the same zeros (balls) at both precisions
        lam = [arbitrary_precision.mp_to_arb(x) for x in weak_form_mp.bessel_j2_zeros(20, 55)]

    def assembled(b, digits, fresh):
        with arbitrary_precision.working_digits(digits):
            if fresh:
                weak_form_arb._ZERO_VALUES.clear()
            matrix, rhs = weak_form_arb.assemble("complete", lam, arbitrary_precision.flint.arb(b) / 10)
            return [(x.mid().man_exp(), x.rad().man_exp()) for x in matrix.entries() + rhs.entries()]

    with mpmath.workdps(60):
        first = assembled(3, 30, fresh=True)
        kept = assembled(7, 30, fresh=False)
        assert kept == assembled(7, 30, fresh=True)
        assembled(3, 30, fresh=False)
        finer = assembled(7, 40, fresh=False)
        assert finer == assembled(7, 40, fresh=True) and finer != kept and first != kept


def test_bad_assembly():
    with pytest.raises(ValueError, match="assembly"):
        reference.solve_reference(0.5, "complete", 10, 20, assembly="numpy")
    if arbitrary_precision.flint is not None:
        with pytest.raises(ValueError, match="assembly"):
            reference.solve_reference(0.5, "complete", 10, 20, assembly="arb", form="struve")


def test_bad_input():
    with pytest.raises(ValueError, match="stick_radius"):
        reference.solve_reference(1.0, "complete", 10, 20)
    with pytest.raises(ValueError, match="stick_radius"):
        reference.solve_reference(float("nan"), "complete", 10, 20)
    with pytest.raises(ValueError, match="method"):
        reference.solve_reference(0.5, "exact", 10, 20)
    with pytest.raises(ValueError, match="n_terms"):
        reference.solve_reference(0.5, "complete", 0, 20)


def test_cli_reference_json_subprocess():
    out = subprocess.run(
        [
            sys.executable,
            "-m",
            "torsional_contact",
            "reference",
            "--stick-radius",
            "0.6",
            "--n-terms",
            "20",
            "--digits",
            "30",
            "--method",
            "published",
            "--json",
        ],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert out.returncode == 0, out.stderr
    data = json.loads(out.stdout)
    assert data["rigid_rotation"] is None and data["method"] == "published"
    assert data["digits"] == 30 and data["n_terms"] == 20 and data["seconds"] >= 0
    ref = reference.solve_reference("0.6", "published", 20, 30)
    with mpmath.workdps(30):
        assert_within(abs(mpmath.mpf(data["torque"]) - ref.torque), mpmath.mpf(10) ** -28,
                      "30 printed digits of the same computation")
    assert len(data["torque"].replace(".", "").lstrip("0")) == 30


@pytest.mark.parametrize(
    "args",
    [
        ["--stick-radius", "1.5"],
        ["--stick-radius", "0"],
        ["--stick-radius", "nan"],
        ["--stick-radius", "x"],
        ["--stick-radius", "0.5", "--digits", "0"],
        ["--stick-radius", "0.5", "--n-terms", "-3"],
        ["--stick-radius", "0.5", "--method", "exact"],
        [],
    ],
)
def test_cli_reference_bad_input(args, capsys):
    assert cli.main(["reference", *args, "--json"]) == 2
    out = capsys.readouterr()
    assert out.out == ""
    assert len(out.err.strip().splitlines()) == 1


def test_the_reference_runs_without_python_flint():
    """python-flint is optional everywhere: without it the dense solve falls back to mpmath, same digits."""
    import subprocess
    import sys

    code = (
        "import sys; sys.modules['flint'] = None\n"  # import flint now raises ImportError
        "from torsional_contact.verification import arbitrary_precision, reference\n"
        "assert not arbitrary_precision.FLINT and arbitrary_precision.backend() == 'mpmath'\n"
        "s = reference.solve_reference('0.6', 'complete', 12, 25)\n"
        "import mpmath; print(s.backend, mpmath.nstr(s.torque, 25))\n"
    )
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    backend, torque = run.stdout.split()
    with_flint = reference.solve_reference("0.6", "complete", 12, 25)
    assert backend == "mpmath"
    with mpmath.workdps(30):
        assert_within(abs(mpmath.mpf(torque) - with_flint.torque), mpmath.mpf(10) ** -22,
                      "25 digits by two backends, less the system's conditioning (~1e2)")
