"""The closures of the weak forms (``solve_series(..., closure=)``): how T*(b) is fixed for a given b.

Each closure is checked against a direct evaluation of the condition it imposes (quadrature of the
truncated series), against the exact solution (which satisfies all three), and for the complete weak
form against convergence to the truth; the default is the closure of every earlier result.
"""

import warnings

import numpy as np
import pytest
from scipy import special
from tolerances import EPS, assert_beyond, assert_close, assert_within, profile_accuracy, torque_accuracy

from torsional_contact import solve
from torsional_contact.diagnostics import TorsionalContactWarning
from torsional_contact.solvers.weak_form import CLOSURES, solve_series


def _quiet(b, method, n, closure="traction"):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", TorsionalContactWarning)  # the printed scheme warns about itself
        return solve_series(b, method, n, closure)


def _traction(sol, r):
    return sol.torque * r - special.j1(np.outer(r, sol.eigenvalues)) @ (sol.amplitudes * sol.eigenvalues)


def _displacement(sol, r):
    omega = 0.0 if sol.method == "published" else sol.rigid_rotation
    return omega * r + special.j1(np.outer(r, sol.eigenvalues)) @ sol.amplitudes


def _traction_terms(sol, r):
    """Sum of the absolute values of the terms of ``_traction`` at r (the scale of its rounding)."""
    return np.abs(sol.torque * r) + np.abs(special.j1(np.outer(r, sol.eigenvalues))) @ np.abs(
        sol.amplitudes * sol.eigenvalues)


def _displacement_terms(sol, r):
    omega = 0.0 if sol.method == "published" else sol.rigid_rotation
    return np.abs(omega * r) + np.abs(special.j1(np.outer(r, sol.eigenvalues))) @ np.abs(sol.amplitudes)


def test_default_closure_is_traction_continuity():
    for method in ("published", "complete"):
        default, explicit = _quiet(0.6, method, 80), _quiet(0.6, method, 80, "traction")
        assert default.torque == explicit.torque
        assert np.array_equal(default.amplitudes, explicit.amplitudes)


@pytest.mark.parametrize("method", ["published", "complete"])
@pytest.mark.parametrize("b", [0.3, 0.7])
def test_each_closure_imposes_its_condition(method, b):
    """(v) q(b) = 1, (vi) u(b) = 0, (vii) 4 int_0^b q r^2 + (4/3)(1 - b^3) = T*, evaluated directly."""
    n = 120
    x, w = np.polynomial.legendre.leggauss(600)  # exact for the truncated series to rounding (lam_N b < 300)
    r, w = 0.5 * b * (x + 1), 0.5 * b * w
    for closure in CLOSURES:
        sol = _quiet(b, method, n, closure)
        # the condition is one row of the solver's linear system: its residual after a backward-stable solve is
        # within (n + 1) EPS of the row's terms, and the test's evaluation of the same N-term sum rounds by as
        # much again: 2 (n + 1) EPS of the sum of |terms| (for the moment, of the 600-point Gauss sum of such
        # sums, positive weights: (n + 600) EPS)
        if closure == "traction":
            residual = _traction(sol, np.array([b]))[0] - 1.0
            bound = 2 * (n + 1) * EPS * (_traction_terms(sol, np.array([b]))[0] + 1.0)
        elif closure == "displacement":
            residual = _displacement(sol, np.array([b]))[0]
            bound = 2 * (n + 1) * EPS * _displacement_terms(sol, np.array([b]))[0]
        else:
            residual = 4 * np.sum(w * _traction(sol, r) * r**2) + 4 / 3 * (1 - b**3) - sol.torque
            terms = 4 * np.sum(w * _traction_terms(sol, r) * r**2) + 4 / 3 * (1 - b**3) + abs(sol.torque)
            bound = 2 * (n + 600) * EPS * terms
        assert_within(abs(residual), bound, f"rounding of the solve and of the sums ({closure})")


def test_the_exact_solution_satisfies_every_closure():
    """The converged traction reaches 1 at r = b, the slip vanishes there, and the torque identity holds."""
    b = 0.6
    exact = solve(stick_radius=b)
    accuracy = profile_accuracy(b)  # the traction's and the slip's accuracy (tests/tolerances.py)
    assert_close(exact.traction(np.array([b]))[0], 1.0, "profile accuracy", atol=accuracy)
    assert_close(exact.slip(np.array([b]))[0], 0.0, "profile accuracy", atol=accuracy)
    x, w = np.polynomial.legendre.leggauss(200)
    # the stick traction is smooth in theta, r = b sin(theta) (its sqrt(b - r) edge becomes analytic)
    theta, w = np.pi / 4 * (x + 1), np.pi / 4 * w
    r = b * np.sin(theta)
    moment = np.sum(w * exact.traction(r) * r**2 * b * np.cos(theta))
    # the traction's accuracy integrated (4 int_0^b r^2 dr = 4 b^3 / 3), the torque's, and the rounding of the
    # 200-point Gauss sum (positive terms); its truncation on the analytic integrand is far below
    assert_close(4 * moment + 4 / 3 * (1 - b**3), exact.torque, "traction and torque accuracy + Gauss rounding",
                 atol=4 * b**3 / 3 * accuracy + torque_accuracy(b) + 200 * EPS)


def test_complete_form_converges_under_every_closure():
    """The complete weak form tends to the truth whatever the closure (error at least halved from N = 145 to 1000)."""
    b = 0.6
    truth = solve(stick_radius=b).torque
    for closure in CLOSURES:
        coarse = abs(_quiet(b, "complete", 145, closure).torque - truth)
        fine = abs(_quiet(b, "complete", 1000, closure).torque - truth)
        assert fine < coarse / 2, closure  # about 1/N: a factor ~7 is expected (an order, not a tolerance)
        # T* converges like (a + c ln N) / N (tests/test_convergence.py); the truncation bound (1 + ln N) / N
        # takes |a|, |c| <= 1, more than ten times what N = 145 and 1000 give (about 0.07), as WEAK_FORM_TRUNCATION
        assert_within(fine, (1 + np.log(1000)) / 1000, f"truncation (1 + ln N) / N ({closure})")


def test_printed_scheme_misses_under_every_closure():
    """No closure makes the printed scheme converge: at N = 1000 it stays more than 10 times further from the
    truth than the complete form with the same closure (the errata's consistency factor)."""
    b = 0.6
    truth = solve(stick_radius=b).torque
    for closure in CLOSURES:
        printed = abs(_quiet(b, "published", 1000, closure).torque - truth)
        complete = abs(_quiet(b, "complete", 1000, closure).torque - truth)
        # the errata's consistency factor: a claim about the printed scheme (its floor is the claim, ten times the
        # complete form's error), not an error bound
        assert_beyond(printed, 10 * complete, f"the printed scheme misses by more than ten times ({closure})")


def test_bad_closure_is_rejected():
    with pytest.raises(ValueError, match="closure"):
        solve_series(0.5, "complete", 20, "regularity")
