"""The work of a monotonic loading at small slip annuli, eq. (S8) of ``asymptotics``.

W_mono = (pi^4/12) e^3 [1 + (1/2 - 3 pi^2/64) e + O(e^2 ln e)], e = T* - 1, derived from the
edge-crack expansions (S1), (S2) and the loop-area identity, replaces a coefficient fitted to
the curve table (0.04).  Checked against the Abel-Fredholm work (W2) of ``curves.work`` by a
fit of the asymptotic form on moderate slip annuli, and (slow tier) against the 30-digit
arbitrary-precision reference.
"""

import math
import warnings

import flint
import numpy as np
import pytest
from tolerances import EPS, assert_beyond, assert_close, assert_within, torque_accuracy

from torsional_contact import ResolutionWarning, asymptotics
from torsional_contact.curves import abel_fredholm_loading_work, monotonic_curves
from torsional_contact.curves.interpolant import ONSET_WORK
from torsional_contact.solvers.abel_fredholm import solve_abel_fredholm

DERIVED = 0.5 - 3 * math.pi**2 / 64
FITTED_BEFORE = 0.04


def _scaled_excess(delta):
    """(e, g) with g = (W_mono / ((pi^4/12) e^3) - 1) / e from the Abel-Fredholm solution at b = 1 - delta."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ResolutionWarning)
        s = solve_abel_fredholm(1 - delta)
    e = s.torque - 1
    return e, (abel_fredholm_loading_work(s) / (math.pi**4 / 12 * e**3) - 1) / e


def _fit(deltas, bounds=False):
    """Least-squares g = c + e (alpha ln e + beta) + e^2 (gamma ln e + kappa): coefficients and largest residual;
    with ``bounds`` also the error bounds of the intercept and of the residual that the solver's T* accuracy
    implies: g moves by 3 dT* / e^2 (W ~ e^3), dT* <= ``torque_accuracy``, carried by the pseudo-inverse's first
    row (intercept) and by the residual projector I - H (residual), in absolute sums."""
    rows = np.array([_scaled_excess(d) for d in deltas])
    e, g = rows[:, 0], rows[:, 1]
    design = np.column_stack([np.ones_like(e), e * np.log(e), e, e * e * np.log(e), e * e])
    coefficients = np.linalg.lstsq(design, g, rcond=None)[0]
    residual = g - design @ coefficients
    if not bounds:
        return coefficients, float(np.max(np.abs(residual)))
    noise = np.array([3 * torque_accuracy(1 - d) / x**2 for d, x in zip(deltas, e, strict=True)])
    pinv = np.linalg.pinv(design)
    projector = np.eye(e.size) - design @ pinv
    return coefficients, float(np.max(np.abs(residual))), float(np.abs(pinv[0]) @ noise), float(
        np.max(np.abs(projector) @ noise)), float(np.abs(pinv[0]) @ np.abs(residual))


def test_the_coefficient_is_the_derived_one_and_the_curves_use_it():
    assert asymptotics.ONSET_WORK_COEFFICIENT == DERIVED == ONSET_WORK
    curves = monotonic_curves()
    tau = 1 + np.array([1e-9, 1e-7, 1e-6])  # below the curves' switch to the table (e < 1.27e-5)
    assert np.all(tau < curves.trust_torque)
    # the same expression in e = tau - 1 (from the same tau): a handful of roundings
    assert_close(curves.work(tau), math.pi**4 / 12 * (tau - 1) ** 3 * (1 + DERIVED * (tau - 1)),
                 "the same expression: 8 roundings", rtol=8 * EPS)


def test_coefficient_against_the_abel_fredholm_work():
    """The intercept of the asymptotic form fitted to (W2) on 3e-4 <= delta <= 3e-2 is the derived value.

    Below delta ~ 3e-4 the solver's T* error enters g as 3 dT* / e^2 and spoils the fit; above 3e-2 more
    terms of the expansion would be needed.
    """
    (c, alpha, *_), residual, intercept_noise, residual_noise, truncation = _fit(np.geomspace(3e-4, 3e-2, 12),
                                                                                bounds=True)
    # the model fits: the residual within what the T* accuracy leaves through the residual projector (the
    # truncation of the five-term form lies below it on these annuli)
    assert_within(residual, residual_noise, "T* accuracy through the residual projector")
    # the intercept: the T* accuracy through the pseudo-inverse, plus the truncation the residual shows
    bound = intercept_noise + truncation
    assert_close(c, DERIVED, "T* accuracy through the pseudo-inverse + the residual's share", atol=bound)
    # the fitted 0.04 is excluded: beyond the intercept's error bound
    assert_beyond(abs(c - FITTED_BEFORE), bound, "0.04 beyond the intercept's error bound")
    assert -3 < alpha < -2  # the e ln e term of the next order (O(delta^3 ln delta) in (S1)): a sign and a size


@pytest.mark.slow
def test_coefficient_against_the_30_digit_reference():
    """At b = 0.999 (e = 6.5e-4): W_mono by (W2) from the arbitrary-precision Abel-Fredholm solution,
    the double-precision value used by the fit, and the fitted asymptotic form all agree."""
    from torsional_contact.verification.abel_fredholm_mp import solve_reference_abel_fredholm
    from torsional_contact.verification.arbitrary_precision import gauss_legendre, working_digits

    reference = solve_reference_abel_fredholm("0.999", 20)
    state = reference.fine
    with working_digits(state.work_digits):
        psi_b = state.stick_radius.acos()  # W = 8 int_0^psi_b cos(psi) D sin(psi) artanh(sin psi) dpsi
        nodes, weights = gauss_legendre(60)  # analytic integrand on [0, psi_b]: far beyond 20 digits
        psi = [psi_b * (x + 1) / 2 for x in nodes]
        t = [p.cos() for p in psi]
        d = state._d_function(t, psi)  # noqa: SLF001 - D(t) of (F7) in arbitrary precision, t = cos(psi)
        total = sum((w * tj * dj * p.sin().atanh() * p.sin() for w, p, tj, dj in zip(weights, psi, t, d, strict=True)),
                    flint.arb(0))
        work = 8 * total * psi_b / 2
        e = state.torque - 1
        g_reference = float(((work / (flint.arb.pi() ** 4 / 12 * e**3) - 1) / e).mid())
        e = float(e.mid())
    e_double, g_double = _scaled_excess(1e-3)
    accuracy = torque_accuracy(0.999)
    assert_close(e_double, e, "the solver's T* accuracy", atol=accuracy)
    assert_close(g_double, g_reference, "T* accuracy -> 3 dT* / e^2 in g", atol=3 * accuracy / e**2)
    (c, alpha, beta, gamma, kappa), residual, intercept_noise, residual_noise, truncation = _fit(
        np.geomspace(3e-4, 3e-2, 12), bounds=True)
    model = DERIVED + e * (alpha * math.log(e) + beta) + e * e * (gamma * math.log(e) + kappa)
    # the fitted form at e: within the fit's residual bound and the intercept's error bound
    assert_close(g_reference, model, "the fit's residual and intercept bounds",
                 atol=residual_noise + intercept_noise + truncation)
