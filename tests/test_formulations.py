"""Interface conditions, limits and the published formulation's defect."""

import warnings

import numpy as np
import pytest
from oscillatory_quadrature import integrate
from tolerances import EPS, WEAK_FORM_TRUNCATION, assert_close, assert_within, rotation_b2_coefficient

from torsional_contact import ResolutionWarning, solve
from torsional_contact.diagnostics import UnphysicalResultWarning
from torsional_contact.solvers.abel_fredholm import solve_abel_fredholm
from torsional_contact.solvers.weak_form import assemble, solve_series
from torsional_contact.special.integrals import coupling_matrix, dini_norm, load_vector
from torsional_contact.special.zeros import bessel_j2_zeros

MARGIN = 0.05  # distance from r = b where pointwise checks start


def stick_torque(s, b, n_terms):
    """int_0^b traction r^2 dr by quadrature resolving the highest term."""
    return integrate(lambda r: s.traction(r.ravel()).reshape(r.shape) * r**2, 0, b, 3.2 * n_terms)


def interface_errors(b, n_terms):
    s = solve(stick_radius=b, n_terms=n_terms, method="complete")
    stick = np.linspace(0.0, b - MARGIN, 300)
    slip_zone = np.linspace(b + MARGIN, 1.0, 300)
    return {
        "stick_slip": np.max(np.abs(s.slip(stick))),
        "slip_traction": np.max(np.abs(s.traction(slip_zone) - 1.0)),
        "stick_traction_excess": np.max(s.traction(np.linspace(0, b, 2000))) - 1.0,
        "negative_slip": -min(0.0, np.min(s.slip(np.linspace(b, 1, 2000)))),
        "torque_balance": abs(4 * (stick_torque(s, b, n_terms) + (1 - b**3) / 3) - s.torque),
    }


TRUNCATION = WEAK_FORM_TRUNCATION  # tests/tolerances.py


@pytest.mark.parametrize("b", [0.3, 0.6, 0.9])
def test_complete_formulation_interface_conditions_tighten_with_n_terms(b):
    coarse, fine = interface_errors(b, 145), interface_errors(b, 1160)
    for n, errors in ((145, coarse), (1160, fine)):
        for key, (k, p) in TRUNCATION.items():
            assert_within(errors[key], k / n**p, f"truncation bound K / N^{p}")
        # the stick bound |q| <= 1 to the rounding of the N-term series (N EPS)
        assert_within(max(0.0, errors["stick_traction_excess"]), n * EPS, "rounding of the N-term traction series")
        assert errors["negative_slip"] == 0.0
    # ... and they tighten with N (8x more terms: at least 4x smaller errors; a convergence order above 2/3)
    for key in ("stick_slip", "slip_traction", "torque_balance"):
        assert fine[key] < coarse[key] / 4, key


def test_eigenfunction_traction_carries_no_torque():
    # T* = 4 int_0^1 traction r^2 dr holds identically for the series
    s = solve(stick_radius=0.45, n_terms=300, method="complete")
    total = 4 * integrate(lambda r: s.traction(r.ravel()).reshape(r.shape) * r**2, 0, 1, 3.2 * 300)
    # the quadrature resolves every term (tests/oscillatory_quadrature.py: ~1e-14); the 300-term sums round to 300 EPS
    assert_within(abs(total - s.torque), 1e-14 + 300 * EPS, "quadrature + rounding of the 300-term series")


def test_published_system_is_eq_38_built_from_appendix_b():
    lam = bessel_j2_zeros(40)
    b, torque = 0.55, 1.25
    matrix, rhs_t, rhs_c = assemble("published", lam, b)
    # eq. (38): A~_m lam_m h_m + sum_n A~_n C_mn = B_m, with c_n = lam_n A~_n
    paper = np.diag(lam * dini_norm(lam)) + coupling_matrix(lam, b)
    # the same closed forms (52), (53), (35), (51) assembled two ways: a few ulp of the largest terms (lam^2 ~ 1.6e4
    # times Lommel integrals ~ 1/lam): 64 EPS relative, and absolute 64 EPS x the largest entry of the row
    scale = np.max(np.abs(paper), axis=1, keepdims=True)
    assert_close(matrix * lam[None, :], paper, "rounding of the closed forms", rtol=64 * EPS, atol=64 * EPS * scale)
    load = load_vector(lam, b, torque)
    assert_close(torque * rhs_t + rhs_c, load, "rounding of (51)", rtol=64 * EPS, atol=64 * EPS * np.max(np.abs(load)))


def test_stick_onset_and_spinning_limits():
    for method in ("complete", "published"):
        onset = solve_series(1.0, method, 145)
        assert onset.torque == 1.0 and np.all(onset.amplitudes == 0)
        spinning = solve_series(0.0, method, 145)
        assert_within(abs(spinning.torque - 4 / 3), 4 * EPS, "4/3 to a few ulp")
    # approaching the limits continuously (complete formulation, well resolved)
    near_one = [solve_series(b, "complete", 2000).torque for b in (0.99, 0.995)]
    assert 1.0 < near_one[1] < near_one[0] < 1.01
    near_zero = [solve_series(b, "complete", 1000).torque for b in (0.05, 0.03)]
    assert near_zero[0] < near_zero[1] < 4 / 3
    # the deficit is O(b^3): (16 / (9 pi)) b^3 (S7) = 1.5e-5 at b = 0.03; ten times that
    assert_within(4 / 3 - near_zero[1], 10 * 16 / (9 * np.pi) * 0.03**3, "(S7): ten times the O(b^3) deficit")


@pytest.mark.slow  # long: the CI tier (workflow/test.sh) runs it
def test_torque_decreases_with_stick_radius():
    radii = np.linspace(0.02, 0.98, 49)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ResolutionWarning)
        torques = np.array([solve_series(b, "complete", 600).torque for b in radii])
    assert np.all(np.diff(torques) < 0)
    assert np.all((torques > 1) & (torques < 4 / 3))


def test_rigid_rotation_grows_like_half_log_one_over_b():
    """omega = ln(1/b)/2 + c0 + c2 b^2 (c2 = e2/2 - 1/8 = 0.2, tests/test_curves.py): the exact (Abel-Fredholm)
    slopes per ln 2 are 1/2 - c2 (b1^2 - b2^2) / ln 2 to O(b^4); the weak form at N = 2000 reproduces omega to its
    truncation error, which converges like 1/N: below the change from N = 125 (fifteen times the N = 2000 error)."""
    radii = np.array([0.02, 0.04, 0.08])
    exact = np.array([solve_abel_fredholm(b).rigid_rotation for b in radii])
    slopes = -np.diff(exact) / np.log(2)
    curvature = rotation_b2_coefficient() * (radii[:-1] ** 2 - radii[1:] ** 2) / np.log(2)
    # beyond c2 b^2, (S6) drops the O(b^3 ln b) mixed and E_b terms (tests/test_extremes.py bounds them by
    # b^3 ln(1/b)): twice that at the larger radius, per ln 2, plus omega's bound
    remainder = 2 * radii[1:] ** 3 * np.log(1 / radii[:-1]) / np.log(2) + 2 * 1e-13 / np.log(2)
    assert_close(slopes, 0.5 + curvature, "(S6) O(b^3 ln b) remainder + omega's bound", atol=remainder)
    weak = np.array([solve_series(b, "complete", 2000).rigid_rotation for b in radii])
    coarse = np.array([solve_series(b, "complete", 125).rigid_rotation for b in radii])
    assert_close(weak, exact, "weak-form truncation at N = 2000, below its change from N = 125",
                 atol=np.abs(coarse - weak))


class TestPublishedDefect:
    """Without the rigid-rotation mode the published solution is a different problem."""

    b = 0.6

    def setup_method(self):
        self.pub = solve(stick_radius=self.b, method="published", n_terms=145)
        self.com = solve(stick_radius=self.b, method="complete", n_terms=145)

    def test_int_u_r2_vanishes_so_slip_cannot_be_one_signed(self):
        # int_0^1 u r^2 dr = 0 for every J1(lam_n r) with J2(lam_n) = 0: by Gauss panels resolving the series
        # (tests/oscillatory_quadrature.py, ~1e-14), to the rounding of the 145-term series
        # (145 EPS x sum of the terms < 1)
        moment = integrate(lambda r: self.pub.slip(r.ravel()).reshape(r.shape) / 2 * r**2, 0, 1, 3.2 * 145)
        assert_within(abs(moment), 1e-14 + 145 * EPS, "quadrature + rounding of the 145-term series")
        assert np.min(self.pub.slip(np.linspace(self.b, 1, 4000))) < -0.04  # backward slip
        assert np.min(self.com.slip(np.linspace(self.b, 1, 4000))) >= 0.0

    def test_stick_zone_rotates_rigidly_backwards(self):
        r = np.linspace(0.2, self.b - 0.05, 50)
        alpha = self.pub.slip(r) / (2 * r)
        # constant to the series error (~1e-5 in u at N = 145), 37x smaller than alpha
        assert np.ptp(alpha) < 0.03 * abs(np.mean(alpha)) and np.mean(alpha) < -0.03

    def test_slip_zone_traction_is_one_minus_alpha_r(self):
        r_stick = np.linspace(0.2, self.b - 0.05, 50)
        alpha = np.mean(self.pub.slip(r_stick) / (2 * r_stick))
        r = np.linspace(self.b + 0.05, 0.95, 50)
        # to the traction's truncation error at N = 145 (TRUNCATION: 2 / N, as for the complete form)
        k, p = TRUNCATION["slip_traction"]
        assert_close(self.pub.traction(r), 1 - alpha * r, "traction truncation bound K / N", atol=k / 145**p)
        assert np.all(self.pub.traction(r) > 1.0)  # exceeds the friction limit

    def test_torque_exceeds_spinning_for_small_stick_disc(self):
        with pytest.warns(UnphysicalResultWarning, match="physically impossible"):
            s = solve(stick_radius=0.3, method="published", n_terms=145)
        assert s.torque > 4 / 3
        assert self.pub.torque - self.com.torque > 0.02


@pytest.mark.parametrize("b", [0.2, 0.6, 0.9])
def test_slip_never_raises_the_shear_above_the_bilateral_maximum(b):
    # Section 4: 'the presence of slip simply reduces the severity of the state of stress', so
    # the von Mises limit (6) of the monolithic shaft (shear T* f p0 at r = a) also holds here.
    s = solve(stick_radius=b, n_terms=600)
    r = np.linspace(0, 1, 401)[:, None]
    z = np.concatenate([[0.0, 1e-4, 1e-3], np.linspace(0.005, 1.5, 120)])[None, :]
    sigma_zt, sigma_rt = s.stress(r, z)
    resultant = np.hypot(sigma_zt, sigma_rt)
    # the limit T*, to the fields' truncation tolerance (``fields.DEFAULT_TOLERANCE``, 1e-12) and rounding
    assert_within(max(0.0, resultant.max() - s.torque), 1e-12 + 64 * EPS, "fields' tolerance + rounding")
    # attained far from the interface, at r = a: within ten times the slowest Dini mode at z = 1.5,
    # |c_1 lam_1 J1(lam_1 r)| exp(-1.5 lam_1) <= |c_1| lam_1 0.582 exp(-1.5 lam_1)
    c1 = abs(solve_abel_fredholm(b).dini_amplitudes(1)[0])
    lam1 = bessel_j2_zeros(1)[0]
    assert_within(s.torque - resultant.max(), 10 * c1 * lam1 * 0.582 * np.exp(-1.5 * lam1), "slowest Dini mode")


@pytest.mark.parametrize("method, b", [("complete", 5e-324), ("complete", 1e-300), ("published", 5e-324)])
def test_a_stick_radius_at_the_bottom_of_the_double_range_is_refused_naming_it(method, b):
    """Where a weak form's system or T* leaves the double range: a ValueError naming stick_radius, without a
    numpy warning on the way (the resolution warning of our own category comes first)."""
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)
        warnings.simplefilter("ignore", ResolutionWarning)
        with pytest.raises(ValueError, match=f"stick_radius=.* is too small for the {method} weak form"):
            solve(stick_radius=b, method=method, n_terms=60)


def test_the_published_form_at_1e_300_is_finite_and_flagged():
    """Still inside the double range the printed scheme returns its (impossible) finite T*, flagged as such."""
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)
        warnings.simplefilter("ignore", ResolutionWarning)
        with pytest.warns(UnphysicalResultWarning):
            s = solve(stick_radius=1e-300, method="published", n_terms=60)
    assert np.isfinite(s.torque) and s.torque > 4 / 3


def test_terms_to_resolve_a_subnormal_width_is_an_integer():
    from torsional_contact.solvers.weak_form import MAX_SERIES_TERMS, terms_to_resolve

    needed = terms_to_resolve(5e-324)
    assert isinstance(needed, int) and needed > 10 * MAX_SERIES_TERMS
