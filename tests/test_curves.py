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

from torsional_contact import ResolutionWarning, solve
from torsional_contact.criteria import spinning_deficit
from torsional_contact.curves import loading_work, monotonic_curves
from torsional_contact.curves.table import lobatto_coefficients, panel_edges, read_table
from torsional_contact.histories import dissipation_from_loop_area, dissipation_per_cycle, threshold_asymptotics
from torsional_contact.quadrature import gauss_legendre_panels
from torsional_contact.solvers.abel_fredholm import solve_fast

CURVES = monotonic_curves()


def _direct(b):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ResolutionWarning)
        return solve_fast(b)


def _radii_off_nodes(per_panel: int, seed: int) -> np.ndarray:
    edges = CURVES.by_radius["torque"].edges
    rng = np.random.default_rng(seed)
    return np.concatenate([lo + (hi - lo) * rng.uniform(0.02, 0.98, per_panel)
                           for lo, hi in zip(edges[:-1], edges[1:], strict=True)])


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
    np.testing.assert_allclose(lobatto_coefficients(np.polynomial.chebyshev.chebval(x, c))[:5], c, atol=1e-14)


@pytest.mark.parametrize("seed", [11])
def test_curves_by_radius_against_direct_solves(seed):
    """T* and omega to 1e-12 absolute, 4/3 - T* to 1e-12 relative, W_mono relative 1e-10 (delta > 3e-4).

    Measured: T* <= 2e-14 for 1 - b > 2e-5; below, the solver itself is noisy (up to 3e-12 next
    to b_max, where it warns) and the small-slip asymptote is used; omega <= 2e-14; W_mono <= 7e-11
    for 1 - b > 3e-4, growing to 1e-7 next to b_max (cancellation in the solver's slip there,
    where W_mono < 1e-13).
    """
    for b in _radii_off_nodes(1, seed):
        s = _direct(b)
        assert abs(CURVES.torque(b) - s.torque) < (1e-12 if 1 - b > 2e-5 else 5e-12)
        bound = 1e-12 * max(s.torque_deficit, 1.0 if 1 - b < 2e-5 else 0.0)
        assert abs(CURVES.torque_gap(b) - s.torque_deficit) < bound
        assert abs(CURVES.rotation_at_radius(b) - s.rigid_rotation) < 1e-12
        work = loading_work(s)
        tolerance = 1e-10 if 1 - b > 3e-4 else 1e-13 / work
        assert abs(CURVES.work_at_radius(b) / work - 1) < tolerance


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
    """b(tau) to 1e-12 (or its conditioning), omega_m(tau) to 1e-12, W_mono(tau) relative 1e-10.

    Measured at these non-node torques: b 3e-14, omega 2e-14, W 3e-10 at tau - 1 = 1.1e-4 and
    below 1e-13 elsewhere.
    """
    b = _stick_radius_by_root(tau)
    s = _direct(b)
    assert abs(CURVES.stick_radius(tau) - b) < 1e-12
    assert abs(CURVES.rotation(tau) - s.rigid_rotation) < 1e-12
    assert abs(CURVES.work(tau) / loading_work(s) - 1) < (1e-9 if tau < 1.001 else 1e-10)
    assert CURVES.state(tau) == pytest.approx((CURVES.stick_radius(tau), CURVES.rotation(tau), CURVES.work(tau)),
                                              rel=1e-14, abs=1e-15)


def test_curve_ends_and_regimes():
    assert CURVES.stick_radius(np.array([0.0, 0.5, 1.0])).tolist() == [1.0, 1.0, 1.0]
    assert CURVES.rotation(1.0) == 0.0 and CURVES.work(0.7) == 0.0
    spin = 4.0 / 3.0
    assert CURVES.stick_radius(spin) == 0.0 and CURVES.rotation(spin) == math.inf == CURVES.work(spin)
    # every double below 4/3 (beyond the spinning tolerance) is covered by the table
    tau = np.nextafter(spin * (1 - 4 * np.finfo(float).eps), 0.0)
    assert 0 < CURVES.stick_radius(tau) < 3e-5 and math.isfinite(CURVES.rotation(tau))
    # small slip annuli: the asymptotes continue the table smoothly
    edge = CURVES.trust_torque
    below, above = np.nextafter(edge, 1.0), np.nextafter(edge, 2.0)
    assert abs(CURVES.stick_radius(below) - CURVES.stick_radius(above)) < 1e-12
    assert CURVES.work(below) == pytest.approx(CURVES.work(above), rel=2e-7)
    assert CURVES.torque(1 - 1.9e-5) == pytest.approx(CURVES.by_radius["torque"](1 - 1.9e-5), abs=1e-12)


def test_small_disc_asymptotes():
    """4/3 - T* ~ (16 / (9 pi)) b^3 and omega + ln(b)/2 -> const as b -> 0 (section 'Beyond the table')."""
    b = np.array([1e-5, 1e-4])
    np.testing.assert_allclose(CURVES.torque_gap(b) / b**3, 16 / (9 * np.pi), rtol=1e-6)
    constant = CURVES.rotation_at_radius(b) + 0.5 * np.log(b)
    assert abs(constant[0] - constant[1]) < 5e-9
    # below the table the continuation agrees with a direct solve
    s = _direct(3e-7)
    assert CURVES.rotation_at_radius(3e-7) == pytest.approx(s.rigid_rotation, abs=1e-12)
    assert CURVES.work_at_radius(3e-7) == pytest.approx(loading_work(s), rel=1e-10)


@pytest.mark.parametrize("b", [0.05, 0.6, 0.95])
def test_loading_work_against_slip_quadrature(b):
    """(W2) against (W1): 2 pi int s r dr with the slip of (F7) on 60-node panels split near r = b."""
    s = _direct(b)
    breaks = b + (1 - b) * np.geomspace(1e-6, 1, 16)[:-1]
    nodes, weights = gauss_legendre_panels(b, 1.0, 0.05, breaks)
    quadrature = 2 * math.pi * np.sum(s.interface_slip(nodes) * nodes * weights)
    assert loading_work(s) == pytest.approx(quadrature, rel=5e-9)  # measured 5e-13 .. 1.3e-9 (the slip's accuracy)


@pytest.mark.parametrize("torque_range", [2.001, 2.0032, 2.01, 2.05, 2.1, 2.23, 2.46, 2.6, 2.66])
def test_loop_energy_two_routes(torque_range):
    """W(A): frictional work over the slip annulus = pi x loop area in the (omega, T*) plane.

    Relative 1e-10 wherever W > 1e-3 (A > 2.06; measured 1e-13 .. 1e-12); closer to the
    threshold the loop-area route inherits the absolute accuracy of omega (~1e-15, while
    omega ~ (pi^3/12) eps^3): measured absolute differences below 6e-14.
    """
    friction = dissipation_per_cycle(torque_range)
    area = dissipation_from_loop_area(torque_range)
    assert friction > 0
    assert abs(area - friction) <= 1e-10 * friction + 1e-13


def test_threshold_law():
    """W(2 (1 + eps)) / ((pi^4/3) eps^3) -> 1 linearly in eps (anti-plane edge crack)."""
    eps = np.geomspace(3e-5, 1e-3, 4)  # above the table's small-slip end (1.3e-5)
    ratio = np.array([dissipation_per_cycle(2 * (1 + e)) for e in eps]) / threshold_asymptotics(eps)["dissipation"]
    slope = (ratio - 1) / eps
    assert np.all((slope > 0.02) & (slope < 0.1))  # measured 0.039 .. 0.057: an O(eps) correction, no O(1) error
    assert abs(ratio[0] - 1) < 1e-5


def test_fresh_inverse_agrees_with_the_stick_radius_problem():
    """solve(torque=T*(b)) returns b (first call uses the table, then one Newton step with the solver)."""
    for b in (0.123456, 0.6, 0.987654):
        t = solve(stick_radius=b).torque
        assert solve(torque=t).stick_radius == pytest.approx(b, abs=1e-13)
