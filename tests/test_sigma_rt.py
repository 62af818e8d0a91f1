"""sigma_rt(r, 0) of the default method for stick discs b >= 1/2: a quadrature of (F7), no differences.

Before, b >= 1/2 used central differences of the slip (~1e-9, ~1e-5 next to r = 1 and r = b).
Checked against the b < 1/2 formula of ``interface.face_shear`` (valid up to b ~ 0.85, where the
Chebyshev series of m(t) still converges: a second representation of the same derivative), the
Dini series of the traction extrapolated to z = 0, finite elements, and (slow tier) the 30-digit
arbitrary-precision reference (``verification.abel_fredholm_mp.face_shear_arb``).
"""

import numpy as np
import pytest
from tolerances import PROFILE_ACCURACY, assert_close, assert_within, spinning_table_bound

from torsional_contact import fields, solve
from torsional_contact.solvers import interface
from torsional_contact.solvers.abel_fredholm import solve_abel_fredholm
from torsional_contact.special.zeros import bessel_j2_zeros
from torsional_contact.verification import finite_element as fe

ANNULUS = np.array([1e-6, 1e-3, 0.1, 0.5, 0.9, 0.999, 0.9999])  # (r - b) / (1 - b)


def _table_share(s):
    """Bound on what the error of the spinning table E_1 (``spinning_table_bound``, largest at the corner t = 1)
    contributes to sigma_rt: E_1 enters D (and the kernel (K5)) with weight up to 4 |Omega| (the size of D's
    terms, ``tolerances.slip_rounding``)."""
    t = np.linspace(float(s.stick_radius), 1.0, 200)
    return 4 * abs(s.rotation_constant) * float(np.max(spinning_table_bound(t)))


@pytest.mark.parametrize("b", [0.5, 0.65, 0.8, 0.85])
def test_two_representations_agree(b):
    """D-series (b >= 1/2) against the spinning kernel (K5) plus the m'-series of the b < 1/2 formula."""
    s = solve_abel_fredholm(b)
    r = b + (1 - b) * ANNULUS
    # both inherit the E_1 table's error (largest next to r = 1); the profiles' own accuracy elsewhere
    assert_close(s.interface_sigma_rt(r), interface.face_shear(r, b, s._correction_chebyshev),
                 "profile accuracy + the E_1 table's share", atol=PROFILE_ACCURACY + _table_share(s))


@pytest.mark.parametrize("b", [0.55, 0.9, 0.999, 1 - 5e-6])
def test_ends_of_the_annulus(b):
    s = solve(stick_radius=b)
    r = np.array([0.0, 0.5 * b, b, 1.0])
    np.testing.assert_array_equal(s.stress(r, 0.0)[1], 0.0)  # stick disc, the stick edge, the free side (eq. 9)
    near = b + (1 - b) * np.array([1e-9, 1e-6])
    values = s.stress(near, 0.0)[1]
    assert np.all(values > 0) and np.all(np.diff(values) > 0)  # rises from 0 like (r - b)^(1/2)
    corner = 1 - (1 - b) * np.array([1e-6, 1e-9])
    values = s.stress(corner, 0.0)[1]
    # falls to 0 like C (1 - r) ln(1 / (1 - r)), C ~ 0.65 from the corner expansion; next to the corner the
    # double-precision D carries the slope error 5.4e-10 of the spinning table E_1 at t = 1, worth (5.4e-10 / pi)
    # ln(1 / (1 - r)).  The law is checked with an allowance of ten on C (an order of the corner, not a
    # tolerance on a computed value)
    gap = 1 - corner
    law = 10 * (0.65 * gap * np.log(1 / gap) + 5.4e-10 / np.pi * np.log(1 / gap))
    assert_within(np.max(np.abs(values) / law), 1.0, "ten times the corner law")


def test_against_the_dini_series_extrapolated_to_the_face():
    """The Dini series of the traction (c_n from the traction, not the slip) at small z, extrapolated to z = 0."""
    b = 0.6
    s, fast = solve(stick_radius=b), solve_abel_fredholm(b)
    r = np.array([0.65, 0.75, 0.85, 0.95])
    lam = bessel_j2_zeros(8192)
    weights = fast.dini_amplitudes(8192) * lam
    z = np.array([1.6e-3, 1.2e-3, 0.8e-3, 0.4e-3])  # converged with 8192 terms; smooth in z
    values = np.array([-fields.series_sum(2, lam, weights, r, zi, 0.0) for zi in z])
    # extrapolated to z = 0 by the cubic through the four points; the quadratic through the last three differs
    # from it by (about) the quadratic's own error, a bound on the cubic's (one order higher in z); plus the tail
    # of the series beyond 8192 terms at the smallest z (|w_N| e^(-lam_N z) / (1 - e^(-pi z)), its terms
    # decaying geometrically) and the face value's accuracy
    cubic = np.array([np.polyfit(z, values[:, j], 3)[-1] for j in range(r.size)])
    quadratic = np.array([np.polyfit(z[1:], values[1:, j], 2)[-1] for j in range(r.size)])
    tail = abs(weights[-1]) * np.exp(-lam[-1] * z[-1]) / (1 - np.exp(-np.pi * z[-1]))
    assert_close(s.stress(r, 0.0)[1], cubic, "the quadratic's extrapolation error + series tail",
                 atol=np.abs(cubic - quadratic) + tail + PROFILE_ACCURACY)


def test_against_finite_elements():
    """sigma_rt = r dw/dr of the P4 finite-element solution on the face converges to it: the error falls at
    least fivefold from level 4 to level 8 (an order of convergence, not a tolerance) and is below 5e-5."""
    b = 0.6
    s = solve(stick_radius=b)
    r = b + (1 - b) * np.array([0.05, 0.3, 0.6, 0.9])
    exact = s.stress(r, 0.0)[1]
    errors = []
    for level in (4, 8):
        fem = fe.solve_finite_element(b, level=level)
        errors.append(np.max(np.abs(fem.stress(r, np.zeros_like(r))[1] - exact)))
    assert errors[1] < 5e-5 and errors[1] < errors[0] / 5


@pytest.mark.slow
@pytest.mark.parametrize("b", ["0.6", "0.95"])
def test_against_the_30_digit_reference(b):
    from torsional_contact.verification.abel_fredholm_mp import solve_reference_abel_fredholm

    reference = solve_reference_abel_fredholm(b, 20)
    stick = float(b)
    r = stick + (1 - stick) * np.array([1e-4, 0.01, 0.3, 0.7, 0.99, 0.9999])
    exact = np.array([float(v) for v in reference.sigma_rt([repr(float(x)) for x in r])])
    fine_vs_coarse = np.array([float(v) for v in reference.sigma_rt([repr(float(x)) for x in r[:2]], reference.coarse)])
    # the reference's own error estimate (fine against coarse resolution): far below double precision
    assert_within(np.max(np.abs(fine_vs_coarse - exact[:2])), 1e-18, "the reference's resolution")
    state = solve(stick_radius=stick)
    got = state.stress(r, 0.0)[1]
    # the profile accuracy, and the E_1 table's share (largest at 1 - r = 1e-4 (1 - b), next to the corner)
    share = _table_share(solve_abel_fredholm(stick))
    assert_close(got, exact, "profile accuracy + the E_1 table's share", atol=PROFILE_ACCURACY + share)
    corner = stick + (1 - stick) * (1 - 1e-6)
    value = float(reference.sigma_rt([repr(corner)])[0])
    # at the corner the slope error of the table (5.4e-10 at t = 1) weighs ln(1 / (1 - r)) / pi
    assert_close(state.stress(corner, 0.0)[1], value, "the E_1 table's slope error at the corner",
                 atol=PROFILE_ACCURACY + share + 5.4e-10 / np.pi * np.log(1 / (1 - corner)))
