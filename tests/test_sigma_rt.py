"""sigma_rt(r, 0) of the default method for stick discs b >= 1/2: a quadrature of (F7), no differences.

Before, b >= 1/2 used central differences of the slip (~1e-9, ~1e-5 next to r = 1 and r = b).
Checked against the b < 1/2 formula of ``interface.face_shear`` (valid up to b ~ 0.85, where the
Chebyshev series of m(t) still converges: a second representation of the same derivative), the
Dini series of the traction extrapolated to z = 0, finite elements, and (slow tier) the 30-digit
arbitrary-precision reference (``verification.abel_fredholm_mp.face_shear_arb``).
"""

import numpy as np
import pytest

from torsional_contact import fields, solve
from torsional_contact.solvers import interface
from torsional_contact.solvers.abel_fredholm import solve_abel_fredholm
from torsional_contact.special.zeros import bessel_j2_zeros
from torsional_contact.verification import finite_element as fe

ANNULUS = np.array([1e-6, 1e-3, 0.1, 0.5, 0.9, 0.999, 0.9999])  # (r - b) / (1 - b)


@pytest.mark.parametrize("b", [0.5, 0.65, 0.8, 0.85])
def test_two_representations_agree(b):
    """D-series (b >= 1/2) against the spinning kernel (K5) plus the m'-series of the b < 1/2 formula."""
    s = solve_abel_fredholm(b)
    r = b + (1 - b) * ANNULUS
    # measured <= 1.4e-12 (next to r = 1, where both inherit the corner slope error of the E_1 table), 7e-14 elsewhere
    np.testing.assert_allclose(s.interface_sigma_rt(r), interface.face_shear(r, b, s._correction_chebyshev),
                               rtol=0, atol=2e-11)


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
    # falls to 0 like 0.65 (1 - r) ln(1 / (1 - r)); next to the corner the double-precision D carries the
    # slope error 5.4e-10 of the spinning table E_1 at t = 1, worth (5.4e-10 / pi) ln(1 / (1 - r)) < 7e-9
    gap = 1 - corner
    assert np.all(np.abs(values) < gap * (1 + np.log(1 / gap)) + 1e-8)


def test_against_the_dini_series_extrapolated_to_the_face():
    """The Dini series of the traction (c_n from the traction, not the slip) at small z, extrapolated to z = 0."""
    b = 0.6
    s, fast = solve(stick_radius=b), solve_abel_fredholm(b)
    r = np.array([0.65, 0.75, 0.85, 0.95])
    lam = bessel_j2_zeros(8192)
    weights = fast.dini_amplitudes(8192) * lam
    z = np.array([1.2e-3, 0.8e-3, 0.4e-3])  # converged with 8192 terms; quadratic in z
    values = np.array([-fields.series_sum(2, lam, weights, r, zi, 0.0) for zi in z])
    extrapolated = np.array([np.polyfit(z, values[:, j], 2)[-1] for j in range(r.size)])
    np.testing.assert_allclose(s.stress(r, 0.0)[1], extrapolated, rtol=0, atol=2e-8)  # measured 1.7e-9


def test_against_finite_elements():
    """sigma_rt = r dw/dr of the P4 finite-element solution on the face: measured 4e-6 at level 8, 6e-5 at 4."""
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
    assert np.max(np.abs(fine_vs_coarse - exact[:2])) < 1e-18  # the reference's own error estimate
    got = solve(stick_radius=stick).stress(r, 0.0)[1]
    # measured 2e-14 .. 2.5e-12 (the largest at 1 - r = 1e-4 (1 - b), the corner slope error of the E_1 table)
    np.testing.assert_allclose(got, exact, rtol=0, atol=3e-11)
    corner = stick + (1 - stick) * (1 - 1e-6)
    value = float(reference.sigma_rt([repr(corner)])[0])
    assert solve(stick_radius=stick).stress(corner, 0.0)[1] == pytest.approx(value, abs=4e-10)  # measured 3.4e-11
