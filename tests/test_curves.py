"""The monotonic curves of ``torsional_contact.curves`` against direct Abel-Fredholm solves.

Independent checks: every interpolant against the solver at points that are not nodes
(random points inside every panel, both ends included); the work of a monotonic loading
(W2) against the direct quadrature of the slip profile (W1); the loop energy by the
frictional work against the torque-twist loop area (two routes sharing nothing but the
solver); the small-slip and small-disc asymptotes.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
from scipy import optimize
from tolerances import (
    EPS,
    ROTATION_ACCURACY,
    assert_beyond,
    assert_close,
    assert_within,
    onset_remainder,
    rotation_b2_coefficient,
    seeds,
    torque_accuracy,
)

from torsional_contact import ResolutionWarning, solve
from torsional_contact.criteria import spinning_deficit
from torsional_contact.curves import abel_fredholm_loading_work, monotonic_curves
from torsional_contact.curves._precompute.build_table import CURVES as TABULATED
from torsional_contact.curves._precompute.build_table import lobatto_coefficients, panel_edges
from torsional_contact.curves.interpolant import ONSET_DELTA
from torsional_contact.curves.table import read_table
from torsional_contact.histories import dissipation_from_loop_area, dissipation_per_cycle, threshold_asymptotics
from torsional_contact.quadrature import gauss_legendre_panels
from torsional_contact.solvers.abel_fredholm import solve_abel_fredholm

CURVES = monotonic_curves()
#: Lebesgue constant of Chebyshev-Lobatto interpolation with at most 65 points: (2/pi) ln 65 + 1 < 4.  The table
#: reproduces its samples, whose errors (the solver's accuracy) it amplifies at most this much between them.
LEBESGUE = 4.0
#: Relative accuracy of 4/3 - T* (``torque_deficit``): (4/3) b^3 - (16/pi) int s^2 g ds, terms up to 2.4 times the
#: result for small discs, each an n-term sum (n <= 512): 512 EPS x 2.4 = 2.7e-13; a little above.
GAP_ACCURACY = 5e-13


def _direct(b):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ResolutionWarning)
        return solve_abel_fredholm(b)


def _radii_off_nodes(per_panel: int, seed: int) -> np.ndarray:
    edges = CURVES.by_radius["torque"].edges
    rng = np.random.default_rng(seed)
    return np.concatenate([lo + (hi - lo) * rng.uniform(0.02, 0.98, per_panel)
                           for lo, hi in zip(edges[:-1], edges[1:], strict=True)])


def _table_bound(name: str, b: float) -> float:
    """Truncation bound of the tabulated curve ``name`` at b, from the table's construction (its builder).

    On its panel the series keeps the coefficients above the chop tolerance (absolute + relative x the largest
    value on the panel) or the panel's recorded tail where it did not converge; each of the at most ``points``
    coefficients it drops or does not resolve is below max(tail, chop).
    """
    curve = CURVES.by_radius[name]
    panel = CURVES.table["panels"][int(curve.panel(b))]
    size = max(abs(float(curve(panel["lo"]))), abs(float(curve(panel["hi"]))))
    absolute, relative = TABULATED[name]
    return panel["points"] * (panel["tails"][name] + absolute + relative * size)


def _work_rounding(s) -> float:
    """Bound on the rounding error of W_mono by (W2) for one solution ((f p0)^2 a^3 / mu).

    D(t) of (F7) is a difference of terms of size up to 2 Omega (2 Omega t, and R + mixed: sums over the n Nystrom
    nodes of kernels that are sums over the m xi-nodes), so |dD| <= (n + m) EPS 4 Omega; (W2) integrates it
    against 8 t arcsech t, whose integral over [b, 1] is A = 4 (sqrt(1 - b^2) - b^2 arcsech b).  Next to slip
    onset D ~ (1 - b)^(3/2) while its terms are O(1): the relative error of W_mono grows like EPS / (1 - b)^2
    there, in the table's samples as in a direct solve.
    """
    b = s.stick_radius
    area = 4.0 * (math.sqrt((1.0 - b) * (1.0 + b)) - b * b * math.acosh(1.0 / b))
    return area * (s.n_nodes + s._xi.size) * EPS * 4.0 * s.rotation_constant  # noqa: SLF001


def _onset_bound(name: str, b: float) -> float:
    """Below ``ONSET_DELTA`` the curves are the small-slip forms: (S1) to its remainder, (S2) to 1e-16 + delta^5,
    W_mono to its fitted O(e) correction (whose own size 0.04 e bounds its error)."""
    delta = 1.0 - b
    if name in ("torque", "torque_gap"):
        return onset_remainder(delta)
    if name == "rigid_rotation":
        return 1e-16 + delta**5
    return 0.04 * (float(CURVES.torque(b)) - 1.0) * float(CURVES.work_at_radius(b))


def _curve_bound(name: str, b: float, sample_accuracy: float) -> float:
    """|table - direct solve| at b: the samples' and the direct solve's accuracy, and the table's truncation."""
    if 1.0 - b < ONSET_DELTA:
        return sample_accuracy + _onset_bound(name, b)
    return (LEBESGUE + 1.0) * sample_accuracy + _table_bound(name, b)


def test_table_is_the_documented_layout():
    table = read_table()
    b_low, b_high = table["domain"]
    edges = CURVES.by_radius["torque"].edges
    np.testing.assert_array_equal(edges, panel_edges(b_high))
    assert b_low == 1e-6 and 1 - 2e-6 < b_high < 1 - 1e-6
    assert "packages" in table["metadata"] and table["method"].startswith("fast")


def test_lobatto_coefficients_reproduce_a_polynomial():
    x = np.cos(np.pi * np.arange(9) / 8)
    c = np.array([0.3, -1.0, 0.25, 0.0, 2.0])
    # rounding: each coefficient is a 9-term sum of values up to sum|c| carrying ~9 EPS each
    assert_close(lobatto_coefficients(np.polynomial.chebyshev.chebval(x, c))[:5], c,
                 "rounding of 9-term sums, 81 EPS sum|c|", atol=81 * EPS * np.sum(np.abs(c)))


@pytest.mark.parametrize("seed", seeds())
def test_curves_by_radius_against_direct_solves(seed):
    """T*, 4/3 - T*, omega and W_mono of the table against direct solves at random radii off the nodes.

    Tolerances (``_curve_bound``): the solver's accuracy (``tolerances.torque_accuracy``, ``ROTATION_ACCURACY``,
    ``_work_rounding``) in the table's samples and in the direct solve, and the table's truncation bound; below
    ``ONSET_DELTA`` the table's values are the small-slip expansions, within their remainders.
    """
    print(f"seed {seed}")
    for b in _radii_off_nodes(1, seed):
        s = _direct(b)
        assert_within(abs(CURVES.torque(b) - s.torque), _curve_bound("torque", b, torque_accuracy(b)),
                      "solver accuracy (samples, direct solve) + table truncation")
        gap_accuracy = GAP_ACCURACY * s.torque_deficit + torque_accuracy(b) - 1e-13  # + the T* noise near onset
        assert_within(abs(CURVES.torque_gap(b) - s.torque_deficit), _curve_bound("torque_gap", b, gap_accuracy),
                      "4/3 - T* without cancellation (n-term sums) + table truncation")
        assert_within(abs(CURVES.rotation_at_radius(b) - s.rigid_rotation),
                      _curve_bound("rigid_rotation", b, ROTATION_ACCURACY),
                      "solver accuracy of omega + table truncation")
        assert_within(abs(CURVES.work_at_radius(b) - abel_fredholm_loading_work(s)),
                      _curve_bound("loading_work", b, _work_rounding(s)),
                      "rounding of (W2) (cancellation in D near b = 1) + table truncation")


def _stick_radius_by_root(tau):
    """b(tau) by Brent's method on the solver alone (4/3 - T* near spinning)."""
    if tau > 1.3:
        gap = float(spinning_deficit(tau))
        return optimize.brentq(lambda b: _direct(b).torque_deficit - gap, 1e-6, 0.5, xtol=1e-17, rtol=1e-15)
    return optimize.brentq(lambda b: _direct(b).torque - tau, 0.2, CURVES.b_high, xtol=1e-16, rtol=1e-15)


@pytest.mark.parametrize("tau", [1.0001107861168437, 1.0126965094123603, 1.1615840016737249, 1.2255105076048316,
                                 1.3054852164734263, 1.3332752409546944, 1.3333333310479569,
                                 1.333333333333284])
def test_curves_by_torque_against_root_finding(tau):
    """b(tau), omega_m(tau), W_mono(tau) against the solver's own root b(tau) at torques off the nodes.

    The root b is off by db = (the error of the T* it matched, over |dT*/db|) + Brent's tolerance, where that
    error is the solver's and the table's T* bound (4/3 - T* near spinning, where the root is found on it);
    omega and W_mono move by their slopes times db.  The by-torque series are refits of the by-radius ones on 65
    points per panel, chopped at 1e-16 (b, omega) and 1e-15 (W_mono) relative.
    """
    b = _stick_radius_by_root(tau)
    s = _direct(b)
    by_radius = CURVES.by_radius
    slope_b = abs(float(by_radius["torque"].derivative(b)))  # |dT*/db|
    if tau > 1.3:
        matched = _curve_bound("torque_gap", b, GAP_ACCURACY * s.torque_deficit)
    else:
        matched = _curve_bound("torque", b, torque_accuracy(b))
    d_b = matched / slope_b + 1e-16 + 1e-15 * b + 65e-16 * b
    assert_within(abs(CURVES.stick_radius(tau) - b), d_b, "the T* bound over |dT*/db| + Brent + refit")
    rotation_slope = abs(float(by_radius["rigid_rotation"].derivative(b)))
    assert_within(abs(CURVES.rotation(tau) - s.rigid_rotation),
                  _curve_bound("rigid_rotation", b, ROTATION_ACCURACY) + rotation_slope * d_b
                  + 65e-16 * s.rigid_rotation, "omega's bound + its slope times db + refit")
    work = abel_fredholm_loading_work(s)
    work_slope = abs(float(by_radius["loading_work"].derivative(b)))
    assert_within(abs(CURVES.work(tau) - work),
                  _curve_bound("loading_work", b, _work_rounding(s)) + work_slope * d_b + 65e-15 * work,
                  "rounding of (W2) + table truncation + the slope of W_mono times db + refit")
    # state() is the scalar path of the same series (Clenshaw in Python): a few EPS of the coefficient sums
    assert_close(CURVES.state(tau), (CURVES.stick_radius(tau), CURVES.rotation(tau), CURVES.work(tau)),
                 "same series, scalar evaluation: 65 EPS relative", rtol=65 * EPS)


def test_curve_ends_and_regimes():
    assert CURVES.stick_radius(np.array([0.0, 0.5, 1.0])).tolist() == [1.0, 1.0, 1.0]
    assert CURVES.rotation(1.0) == 0.0 and CURVES.work(0.7) == 0.0
    spin = 4.0 / 3.0
    assert CURVES.stick_radius(spin) == 0.0 and CURVES.rotation(spin) == math.inf == CURVES.work(spin)
    # every double below 4/3 (beyond the spinning tolerance) is covered by the table
    tau = np.nextafter(spin * (1 - 4 * np.finfo(float).eps), 0.0)
    # 4/3 - tau ~ 4 ulp of 4/3 = 1.2e-15, so b ~ ((9 pi/16) x 1.2e-15)^(1/3) = 1.3e-5
    assert 0 < CURVES.stick_radius(tau) < 3e-5 and math.isfinite(CURVES.rotation(tau))
    # small slip annuli: the asymptotes continue the table, both within their bounds of the truth
    edge = CURVES.trust_torque
    below, above = np.nextafter(edge, 1.0), np.nextafter(edge, 2.0)
    b = float(CURVES.stick_radius(above))
    s = _direct(b)
    torque_bound = onset_remainder(1.0 - b) + _curve_bound("torque", b, torque_accuracy(b))
    assert_within(abs(CURVES.stick_radius(below) - CURVES.stick_radius(above)), torque_bound / (2 / math.pi),
                  "(S1) remainder + table bound of T*, over |dT*/db| = 2/pi")
    work = float(CURVES.work(above))
    assert_within(abs(CURVES.work(below) - work),
                  0.04 * (edge - 1.0) * work + _curve_bound("loading_work", b, _work_rounding(s)),
                  "small-slip W_mono (its 0.04 e correction bounds its error) + table bound")
    b = 1 - 1.9e-5
    assert_within(abs(CURVES.torque(b) - float(CURVES.by_radius["torque"](b))),
                  onset_remainder(1.0 - b) + _curve_bound("torque", b + 1e-6, torque_accuracy(b)),
                  "(S1) remainder + table bound of T* (last table panel)")


def test_small_disc_asymptotes():
    """4/3 - T* ~ (16 / (9 pi)) b^3 and omega + ln(b)/2 -> const as b -> 0 (section 'Beyond the table')."""
    b = np.array([1e-5, 1e-4])
    # (S7) with its O(b^2) relative correction, whose coefficient is below 1 (the solver's: -0.48): ten times that
    assert_close(CURVES.torque_gap(b) / b**3, 16 / (9 * np.pi), "(S7) truncation: 10 b^2 relative",
                 rtol=10 * b**2 + GAP_ACCURACY)
    # omega + ln(b)/2 = c0 + c2 b^2 + O(b^4 ln b): the difference between the two radii is c2 (b0^2 - b1^2)
    c2 = rotation_b2_coefficient()
    constant = CURVES.rotation_at_radius(b) + 0.5 * np.log(b)
    tables = sum(_curve_bound("rigid_rotation", x, ROTATION_ACCURACY) for x in b)
    assert_within(abs(constant[0] - constant[1] - c2 * (b[0] ** 2 - b[1] ** 2)),
                  tables + 1e-3 * b[1] ** 2 + b[1] ** 4 * math.log(1 / b[0]),
                  "table bounds (omega) + error of c2 (its e4 t^2 term, < 1e-3) + the O(b^4 ln b) remainder")
    # below the table the continuation omega(b_low) + ln(b_low / b)/2 drops c2 (b_low^2 - b^2)
    low, x = CURVES.b_low, 3e-7
    s = _direct(x)
    assert_within(abs(CURVES.rotation_at_radius(x) - s.rigid_rotation),
                  abs(c2) * low**2 + _curve_bound("rigid_rotation", low, ROTATION_ACCURACY),
                  "dropped c2 b_low^2 + table bound at b_low + solver accuracy")
    # W_mono(b) = W(b_low) + slope ln(b_low / b): the slope of the first panel's series at its edge carries the
    # chopped coefficients times k^2 (at most 33 of them, k <= 33, each below the chop tolerance)
    first = CURVES.table["panels"][0]
    chop = TABULATED["loading_work"][1] * abs(float(CURVES.work_at_radius(first["hi"])))
    slope_error = low * 2 / (first["hi"] - first["lo"]) * first["points"] ** 3 * chop
    work = abel_fredholm_loading_work(s)
    assert_within(abs(CURVES.work_at_radius(x) - work),
                  _curve_bound("loading_work", low, _work_rounding(s)) + slope_error * math.log(low / x),
                  "table bound at b_low + the error of its edge slope times ln(b_low / b)")


@pytest.mark.parametrize("b", [0.05, 0.6, 0.95])
def test_loading_work_against_slip_quadrature(b):
    """(W2) against (W1): 2 pi int s r dr with the slip of (F7), on 60-node panels graded toward both ends of the
    slip annulus (the slip starts like (r - b)^(3/2) and has (1 - r) log terms at the corner r = 1)."""
    s = _direct(b)
    breaks = [*(b + (1 - b) * np.geomspace(1e-6, 1, 16)[:-1]), *(1 - (1 - b) * np.geomspace(1e-6, 0.5, 16))]
    nodes, weights = gauss_legendre_panels(b, 1.0, 0.05, sorted(breaks))
    quadrature = 2 * math.pi * np.sum(s.interface_slip(nodes) * nodes * weights)
    # both routes integrate D against smooth weights; (W1) through the 64-point interpolant of D (Lebesgue < 4)
    assert_within(abs(abel_fredholm_loading_work(s) - quadrature), (LEBESGUE + 1) * _work_rounding(s),
                  "rounding of D in (W2) and, through its interpolant, in (W1)")


def _loop_energy_bound(torque_range: float) -> float:
    """|friction route - loop-area route| from the table's bounds: 4 W_mono(A/2) against
    pi [2 A omega_m(A/2) - 8 int_1^(A/2) omega_m dt], whose omega values on [b, 1] each carry omega's bound."""
    tau = torque_range / 2
    b = float(CURVES.stick_radius(tau))
    s = _direct(b)
    edges = [x for x in CURVES.by_radius["rigid_rotation"].edges if b <= x < CURVES.b_high]
    omega = max(_curve_bound("rigid_rotation", x, ROTATION_ACCURACY) for x in [b, *edges])
    return 4 * _curve_bound("loading_work", b, _work_rounding(s)) + math.pi * (2 * torque_range + 8 * (tau - 1)) * omega


@pytest.mark.parametrize("torque_range", [2.001, 2.0032, 2.01, 2.05, 2.1, 2.23, 2.46, 2.6, 2.66])
def test_loop_energy_two_routes(torque_range):
    """W(A): frictional work over the slip annulus = pi x loop area in the (omega, T*) plane.

    The two routes share only the solver (the slip on one side, omega(b) and T*(b) on the other); each carries
    the table's bounds (``_loop_energy_bound``).  Near the threshold the loop-area route is a difference of
    O(1) x omega terms, so its absolute accuracy is omega's while W ~ (pi^4/3) eps^3.
    """
    friction = dissipation_per_cycle(torque_range)
    area = dissipation_from_loop_area(torque_range)
    assert friction > 0
    assert_within(abs(area - friction), _loop_energy_bound(torque_range), "table bounds of W_mono and omega")


def test_threshold_law():
    """W(2 (1 + eps)) / ((pi^4/3) eps^3) = 1 + c1 eps + O(eps^2 ln eps) (anti-plane edge crack).

    c1 = 1/2 - 3 pi^2/64: W = 4 W_mono(1 + eps), W_mono(tau) = pi [tau omega - 2 int_1^tau omega dt] (the loop
    area), omega(delta) of (S2) and delta(eps) from (S1).  The remainder is inherited from (S1)'s
    delta^3 (A ln delta + B) (``tolerances.onset_remainder``, ten times its coefficients): delta moves by
    (pi/2) x remainder, omega ~ delta^3 by three times that relative, delta = (pi/2) eps.
    """
    eps = np.geomspace(3e-5, 1e-3, 4)  # above the table's small-slip end (1.3e-5)
    w = np.array([dissipation_per_cycle(2 * (1 + e)) for e in eps])
    ratio = w / threshold_asymptotics(eps)["dissipation"]
    c1 = 0.5 - 3 * math.pi**2 / 64
    accuracy = np.array([_curve_bound("loading_work", float(CURVES.stick_radius(1 + e)),
                                      _work_rounding(_direct(float(CURVES.stick_radius(1 + e)))))
                         for e in eps]) * 4 / w
    delta = np.pi / 2 * eps
    remainder = 3 * np.pi / 2 * np.array([onset_remainder(d) for d in delta]) / delta
    assert_close(ratio - 1, c1 * eps, "O(eps^2 ln eps) remainder of (S1), (S2) + the table's bound of W_mono",
                 atol=remainder + accuracy)
    assert_beyond(np.min((ratio - 1) / eps), 0.1 * c1, "the O(eps) correction is there (no O(1) error)")


def test_fresh_inverse_agrees_with_the_stick_radius_problem():
    """solve(torque=T*(b)) returns b (first call uses the table, then one Newton step with the solver).

    A round trip through the same solver: b moves by the solver's T* noise (at most its accuracy, both ways) over
    |dT*/db|."""
    for b in (0.123456, 0.6, 0.987654):
        t = solve(stick_radius=b).torque
        slope = abs(float(CURVES.by_radius["torque"].derivative(b)))
        assert_within(abs(solve(torque=t).stick_radius - b), 2 * torque_accuracy(b) / slope,
                      "2 x solver T* accuracy over |dT*/db|")
