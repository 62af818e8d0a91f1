"""The closures of the weak forms (``solve_series(..., closure=)``): how T*(b) is fixed for a given b.

Each closure is checked against a direct evaluation of the condition it imposes (quadrature of the
truncated series), against the exact solution (which satisfies all three), and for the complete weak
form against convergence to the truth; the default is the closure of every earlier result.
"""

import warnings

import numpy as np
import pytest
from scipy import special

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
    scale = np.max(np.abs(_quiet(b, method, n).amplitudes * _quiet(b, method, n).eigenvalues))
    for closure in CLOSURES:
        sol = _quiet(b, method, n, closure)
        if closure == "traction":
            residual = _traction(sol, np.array([b]))[0] - 1.0
        elif closure == "displacement":
            residual = _displacement(sol, np.array([b]))[0]
        else:
            residual = 4 * np.sum(w * _traction(sol, r) * r**2) + 4 / 3 * (1 - b**3) - sol.torque
        # tolerance: rounding of a sum of N terms of size `scale` (N eps scale ~ 1e-12), 100x margin
        assert abs(residual) < 100 * n * np.finfo(float).eps * max(scale, 1.0), closure


def test_the_exact_solution_satisfies_every_closure():
    """The converged traction reaches 1 at r = b, the slip vanishes there, and the torque identity holds."""
    b = 0.6
    exact = solve(stick_radius=b)
    assert exact.traction(np.array([b]))[0] == pytest.approx(1.0, abs=1e-10)  # method accuracy ~1e-12
    assert exact.slip(np.array([b]))[0] == pytest.approx(0.0, abs=1e-10)
    x, w = np.polynomial.legendre.leggauss(200)
    # the stick traction is smooth in theta, r = b sin(theta) (its sqrt(b - r) edge becomes analytic)
    theta, w = np.pi / 4 * (x + 1), np.pi / 4 * w
    r = b * np.sin(theta)
    moment = np.sum(w * exact.traction(r) * r**2 * b * np.cos(theta))
    assert 4 * moment + 4 / 3 * (1 - b**3) == pytest.approx(exact.torque, abs=1e-9)  # quadrature ~1e-12


def test_complete_form_converges_under_every_closure():
    """The complete weak form tends to the truth whatever the closure (error at least halved from N = 145 to 1000)."""
    b = 0.6
    truth = solve(stick_radius=b).torque
    for closure in CLOSURES:
        coarse = abs(_quiet(b, "complete", 145, closure).torque - truth)
        fine = abs(_quiet(b, "complete", 1000, closure).torque - truth)
        assert fine < coarse / 2, closure  # about 1/N: a factor ~7 is expected
        assert fine < 1e-3 * truth, closure


def test_printed_scheme_misses_under_every_closure():
    """No closure makes the printed scheme converge: at N = 1000 it stays more than 10 times further from the
    truth than the complete form with the same closure (the errata's consistency factor)."""
    b = 0.6
    truth = solve(stick_radius=b).torque
    for closure in CLOSURES:
        printed = abs(_quiet(b, "published", 1000, closure).torque - truth)
        complete = abs(_quiet(b, "complete", 1000, closure).torque - truth)
        assert printed > 10 * complete, closure


def test_bad_closure_is_rejected():
    with pytest.raises(ValueError, match="closure"):
        solve_series(0.5, "complete", 20, "regularity")
