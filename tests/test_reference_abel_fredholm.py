"""The arbitrary-precision Abel-Fredholm reference (``verification.abel_fredholm_mp``).

Checks against things computed another way: mpmath's Bessel functions, hypergeometric
function and quadrature (for the xi-integrals), the double-precision solver ``solve``,
physical identities evaluated by quadrature of the computed profiles (torque balance,
omega = 2 int s r^2 dr), the asymptotes b -> 0 and b -> 1, the solve at other resolutions
and precisions, and the direct collocation method (slow tier).  The default tier works
at 20-25 digits.
"""

import math
from pathlib import Path

import mpmath
import numpy as np
import pytest

flint = pytest.importorskip("flint")  # the Arb-based reference needs python-flint (optional)

from tolerances import (  # noqa: E402 (after the skip)
    PROFILE_ACCURACY,
    ROTATION_ACCURACY,
    assert_close,
    assert_within,
    onset_remainder,
    profile_accuracy,
    spinning_table_bound,
    torque_accuracy,
)

from torsional_contact import solve  # noqa: E402 (after the skip)
from torsional_contact.io.cli import main as cli_main  # noqa: E402 (after the skip)
from torsional_contact.verification import kernels_mp, nystrom_mp, sinh_excess_mp, special_mp  # noqa: E402 (after the skip)
from torsional_contact.verification.abel_fredholm_mp import MAX_DIGITS, solve_reference_abel_fredholm  # noqa: E402 (after the skip)
from torsional_contact.verification.arbitrary_precision import (  # noqa: E402 (after the skip)
    arb_radius,
    arb_to_mp,
    mp_to_arb,
    to_full_accuracy,
    working_digits,
)
from torsional_contact.verification.nystrom_mp import nodes_for_digits, solve_state  # noqa: E402 (after the skip)

REFERENCE_RADII = ("0.1", "0.3", "0.5", "0.6", "0.7", "0.9")
ROOT = Path(__file__).resolve().parents[1]


@pytest.fixture(scope="module")
def references():
    """20-digit references at the reference radii (computed once for the module)."""
    return {b: solve_reference_abel_fredholm(b, 20) for b in REFERENCE_RADII}


def _mp(value):
    return arb_to_mp(value)


# -- kernels (M1)-(M4) against mpmath -------------------------------------------------


@pytest.mark.parametrize("x", ["1e-9", "0.3", "7", "33.5", "80", "250"])
def test_bessel_ratio_against_mpmath(x):
    with working_digits(30):
        value = _mp(special_mp.bessel_ratio([flint.arb(x).mid()])[0])
        xm = _mp(flint.arb(x).mid())
        exact = mpmath.besselk(2, xm) / mpmath.besseli(2, xm)
        assert_within(abs(value / exact - 1), mpmath.mpf(10) ** -29, "two 30-digit evaluations: 10 units of the last")


@pytest.mark.parametrize("x", ["0.3", "7", "60", "150", "400"])
def test_integral_x_i1_against_hypergeometric_form(x):
    """F(x) = x^3/6 1F2(3/2; 2, 5/2; x^2/4) (eq. A3), mpmath's hyp1f2; above the
    asymptotic threshold (~83 at 30 digits) the Hankel-type expansion is used."""
    with working_digits(30):
        xm = mpmath.mpf(x)
        exact = xm**3 / 6 * mpmath.hyp1f2(mpmath.mpf(3) / 2, 2, mpmath.mpf(5) / 2, xm**2 / 4)
        value = _mp(special_mp.integral_x_i1(flint.arb(x)))
        excess = _mp(special_mp.integral_x_i1_excess(flint.arb(x)))
        assert_within(abs(value / exact - 1), mpmath.mpf(10) ** -29, "two 30-digit evaluations: 10 units of the last")
        # F - x^3/6 cancels up to x^2/20 of F at x = 0.3: 2 more digits
        assert_within(abs(excess / (exact - xm**3 / 6) - 1), mpmath.mpf(10) ** -27, "30 digits less the cancellation")


def test_torque_rotation_against_mpmath_quadrature():
    """BETA = 1/2 + (1/pi) int K2 [1 - xi^2/(8 I2)] d xi with mpmath's Bessel functions and
    tanh-sinh quadrature; the bracket cancels like xi^2/12 at small xi, so the integrand is
    evaluated with 10 + 2 log10(1/xi) extra digits."""
    with working_digits(20):
        beta = _mp(kernels_mp.torque_rotation(20))

        def integrand(x):
            with mpmath.workdps(28 + max(0, int(-2 * mpmath.log10(x)))):
                return mpmath.besselk(2, x) * (1 - x**2 / (8 * mpmath.besseli(2, x)))

        exact = mpmath.mpf(1) / 2 + mpmath.quad(integrand, [0, 1, 4, 16, 64]) / mpmath.pi
        assert_within(abs(beta - exact), mpmath.mpf(10) ** -19, "20-digit values: 10 units of the last")
    from torsional_contact.solvers.kernels import TORQUE_ROTATION

    # the double constant is BETA correctly rounded: half an ulp (one allowed)
    assert_within(abs(float(beta) - TORQUE_ROTATION), np.spacing(TORQUE_ROTATION), "one ulp", exact=True)


def test_abel_kernel_against_mpmath_quadrature():
    """P(t, s) of (A2) at one point by mpmath quadrature (integrand with 20 guard digits)."""
    t, s = mpmath.mpf("0.3"), mpmath.mpf("0.55")
    with working_digits(22):
        quadrature = kernels_mp.xi_quadrature(2 - 0.3 - 0.55, 22)
        value = _mp(kernels_mp.abel_kernel([mp_to_arb(t)], [mp_to_arb(s)], quadrature)[0, 0])

        def integrand(x):  # the bracket is O(xi^4) from terms O(xi^2): 2 log10(1/xi) digits lost
            with mpmath.workdps(30 + max(0, int(-2 * mpmath.log10(x)))):
                return (mpmath.sinh(x * t) * mpmath.sinh(x * s) - x * x * t * s) * (
                    mpmath.besselk(2, x) / mpmath.besseli(2, x))

        exact = 2 / mpmath.pi * mpmath.quad(integrand, [0, 1, 4, 16, 64])
        assert_within(abs(value - exact), mpmath.mpf(10) ** -21, "22-digit values: 10 units of the last")


@pytest.mark.parametrize(("rate", "digits"), [(0.4, 30), (0.02, 45), (1.0, 90)])
def test_xi_quadrature_split_point(rate, digits):
    """The first n_below nodes are exactly those below X (a panel edge), whatever the
    first panel's node count; the weights add up to the length of the covered interval."""
    with working_digits(digits):
        q = kernels_mp.xi_quadrature(rate, digits)
        assert float(q.nodes[q.n_below - 1]) < q.asymptotic_start
        assert q.n_below == len(q.nodes) or q.asymptotic_start < float(q.nodes[q.n_below])
        assert all(float(a) < float(b) for a, b in zip(q.nodes, q.nodes[1:], strict=False))
        below = sum(q.weights[: q.n_below], flint.arb(0))
        # n weights, each to the working precision: the sum is within n units of the last digit of X
        assert_within(abs(_mp(below) - mpmath.mpf(q.asymptotic_start)),
                      q.n_below * mpmath.mpf(10) ** -digits * max(1, q.asymptotic_start),
                      "rounding of n weights at the working precision")


def test_spinning_transform_tail_is_independent_of_its_split_point():
    """E_1(t) up to t = 1: numerical integral to X plus the closed-form tail (M4), for two
    different X (quadratures built for 30 and 45 digits), agree to the working precision;
    and the double-precision table of ``kernels`` agrees to its stated accuracy."""
    from torsional_contact.solvers.kernels import spinning_transform

    t_values = ["0.2", "0.9", "0.999", "0.9999999", "1"]
    with working_digits(30):
        points = [flint.arb(t).mid() for t in t_values]
        one = flint.arb(1)
        first = kernels_mp.load_transform(points, one, kernels_mp.xi_quadrature(0.3, 30))
        second = kernels_mp.load_transform(points, one, kernels_mp.xi_quadrature(0.2, 45))
        assert kernels_mp.xi_quadrature(0.3, 30).asymptotic_start != kernels_mp.xi_quadrature(0.2, 45).asymptotic_start
        for a, b in zip(first, second, strict=True):
            assert_within(abs(_mp(a) - _mp(b)), mpmath.mpf(10) ** -28, "30-digit values: 100 units of the last")
    t = np.array([float(x) for x in t_values])
    double = spinning_transform(t)
    values = np.array([float(v) for v in first])
    assert_close(double, values, "rounding of the samples + 10 x (table of 48 points - table of 96)",
                 atol=spinning_table_bound(t))


# -- the solution: resolution, precision, double precision ----------------------------


@pytest.mark.parametrize("b", ["0.3", "0.9"])
def test_two_resolutions_and_precisions_agree(b):
    """The default node count for 25 digits and 1.4 times as many nodes at 8 more working
    digits give T* and omega to 10^-25 (relative)."""
    n = nodes_for_digits(float(b), 25)
    coarse = solve_state(b, n, 27)
    fine = solve_state(b, math.ceil(1.4 * n), 35)
    with working_digits(35):
        for name in ("torque", "rigid_rotation"):
            a, c = _mp(getattr(coarse, name)), _mp(getattr(fine, name))
            assert_within(abs(a / c - 1), mpmath.mpf(10) ** -25, "the coarse solve's design accuracy, 25 digits")


def test_sixty_digits_do_not_depend_on_the_discretisation():
    """At 60 digits (first xi-panel mapped by u^5) two Nystrom resolutions, two working
    precisions and two xi-quadrature layouts give the same T* and omega."""
    first = solve_state("0.6", 60, 62)
    second = solve_state("0.6", 76, 68, first_panel=0.3, width_decays=11.0)
    with working_digits(68):
        for name in ("torque", "rigid_rotation"):
            a, c = _mp(getattr(first, name)), _mp(getattr(second, name))
            assert_within(abs(a / c - 1), mpmath.mpf(10) ** -58, "60 nodes' design accuracy: 58 digits")


def test_reference_result_and_its_error_estimate(references):
    for b, ref in references.items():
        assert ref.digits == 20
        assert 0 < ref.error_estimate < mpmath.mpf(10) ** -20
        assert ref.fine.n_nodes > ref.coarse.n_nodes and ref.fine.work_digits > ref.coarse.work_digits
        assert 1 < ref.torque < mpmath.mpf(4) / 3 and ref.rigid_rotation > 0, b
        record = ref.as_dict(["0.25", "0.95"])
        assert len(record["torque"].replace(".", "").lstrip("0")) == 20
        assert set(record) >= {"torque", "rigid_rotation", "n_nodes", "seconds", "error_estimate",
                               "error_estimate_method", "radii", "traction", "slip"}
    # T* decreases with b (the torque curve)
    torques = [references[b].torque for b in REFERENCE_RADII]
    assert all(t1 < t0 for t0, t1 in zip(torques, torques[1:], strict=False))


def test_double_precision_solve_within_1e13(references):
    radii = ["0.05", "0.2", "0.45", "0.62", "0.8", "0.97"]
    """The accuracy bounds of tests/tolerances.py (torque_accuracy, ROTATION_ACCURACY, PROFILE_ACCURACY), which the
    other tests use for the double-precision solver, against the 20-digit references."""
    for b, ref in references.items():
        double = solve(stick_radius=float(b))
        assert_within(abs(double.torque - float(ref.torque)), torque_accuracy(float(b)), "T* accuracy bound")
        assert_within(abs(double.rigid_rotation - float(ref.rigid_rotation)), ROTATION_ACCURACY, "omega bound")
        r = np.array([float(x) for x in radii])
        assert_close(double.traction(r), [float(v) for v in ref.traction(radii)], "profile bound",
                     atol=PROFILE_ACCURACY)
        assert_close(double.slip(r), [float(v) for v in ref.slip(radii)], "profile bound", atol=PROFILE_ACCURACY)


def test_traction_near_slip_onset_at_two_precisions():
    """b = 0.97 needs 125-150 Chebyshev terms for (F6): the series is summed without loss
    (two working precisions agree; a Clenshaw recurrence in ball arithmetic lost 9 digits
    here) and matches the double-precision solver."""
    radii = ["0.1", "0.5", "0.9", "0.969"]
    values = []
    for work in (25, 32):
        state = solve_state("0.97", 70, work)
        with working_digits(work):
            values.append([_mp(v) for v in state.interface_traction([mp_to_arb(mpmath.mpf(r)) for r in radii])])
    with working_digits(32):
        assert_within(max(abs(a - c) for a, c in zip(*values, strict=True)), mpmath.mpf(10) ** -22,
                      "70 nodes' accuracy at b = 0.97 (the coarser of the two precisions is 25 digits)")
    double = solve(stick_radius=0.97).traction(np.array([float(r) for r in radii]))
    assert_close(double, [float(v) for v in values[1]], "profile bound", atol=profile_accuracy(0.97))


def test_precision_is_restored():
    mpmath.mp.dps = 17
    flint.ctx.prec = 77
    try:
        solve_state("0.5", 12, 20)
        assert mpmath.mp.dps == 17 and flint.ctx.prec == 77
    finally:
        flint.ctx.prec = 53


# -- the profiles: series of the Nystrom interpolant -------------------------------------


def test_chebyshev_sums_and_coefficients_against_mpmath():
    """``_chebyshev_values`` sums 300 terms (monomial coefficients up to (1 + sqrt 2)^300, hence its
    extra precision) as mpmath's sum of c_k cos(k arccos x) does, near both ends too; and
    ``_chebyshev_coefficients`` (a table of 4n cosines, or cosines entry by entry at given angles)
    inverts the sum at the nodes.
    Tolerance at 30 digits: 2^-110 = 8e-34 per operation, a few operations (4) per term, over the n terms
    of a sum, each of size <= sum |c_k| (the values; <= 1 for the coefficients' own terms): 4 n 2^-110
    max(1, sum |c_k|)."""
    rng = np.random.default_rng(7)
    with working_digits(30):
        coefficients = [mp_to_arb(mpmath.mpf(float(v)) / (k + 1)) for k, v in enumerate(rng.standard_normal(300))]
        points = [flint.arb(x).mid() for x in ("-0.9999", "-0.3", "0.25", "0.999999")]
        values = nystrom_mp._chebyshev_values(coefficients, points)
        with mpmath.workdps(45):
            for x, value in zip(points, values, strict=True):
                angle = mpmath.acos(_mp(x))
                exact = mpmath.fsum(_mp(c) * mpmath.cos(k * angle) for k, c in enumerate(coefficients))
                # 300 terms of size <= 1
                assert_within(float(abs(_mp(value) - exact)), 4 * 300 * 2.0**-110, "30-digit rounding of 300 terms")
        head = coefficients[:48]
        # the values at the nodes are up to sum |c_k|: the back transform's 48 terms are that large
        scale = max(1.0, float(sum(abs(_mp(c)) for c in head)))
        back = nystrom_mp._chebyshev_coefficients(nystrom_mp._chebyshev_values(head, nystrom_mp.chebyshev_nodes(48)))
        assert_within(float(max(abs(_mp(a) - _mp(c)) for a, c in zip(head, back, strict=True))),
                      4 * 2 * 48 * 2.0**-110 * scale, "30-digit rounding of two 48-term transforms")
        angles = [flint.arb.pi() * (2 * j + 1) / 96 for j in range(48)]  # the entry-by-entry transform
        nodes = [a.cos() for a in angles]
        back = nystrom_mp._chebyshev_coefficients(nystrom_mp._chebyshev_values(head, nodes), angles)
        assert_within(float(max(abs(_mp(a) - _mp(c)) for a, c in zip(head, back, strict=True))),
                      4 * 2 * 48 * 2.0**-110 * scale, "30-digit rounding of two 48-term transforms")


@pytest.mark.parametrize("b", ["0.05", "0.6", "0.97"])
def test_interpolant_series_against_direct_rows(b):
    """H(u) = bracket(1 - u^2)/(1 - u^2) from its series on the slip annulus (and, as a harder case
    of the same code, on the stick disc u in [sqrt(1 - b), 1], where the series would cross t = 0)
    against rows of A(xi t) evaluated directly, at points off the Chebyshev nodes (the ends
    included): the difference is at the direct evaluation's rounding (2^-94 = 5e-29 at 25 digits), which
    the xi-sum's cancellation near u = 0 amplifies; tolerance 10^-23, an allowance of 2 x 10^5 for that
    cancellation (the cancellation itself is not computed here)."""
    state = solve_state(b, nodes_for_digits(float(b), 20), 25)
    rng = np.random.default_rng(3)
    with working_digits(25):
        edge, slip = state._slip_zone
        stick = state._h_series(edge, flint.arb(1))
        for lo, hi, coefficients in ((flint.arb(0), edge, slip), (edge, flint.arb(1), stick)):
            fractions = [0.0005, *rng.uniform(0.0, 1.0, 5), 0.9995]
            u = [lo + (hi - lo) * flint.arb(f) for f in fractions]
            t = [(1 - v) * (1 + v) for v in u]
            direct = [br / tv for br, tv in zip(state._bracket(t), t, strict=True)]
            series = nystrom_mp._chebyshev_values(coefficients, [(2 * v - lo - hi) / (hi - lo) for v in u])
            assert_within(float(max(abs(_mp(a) - _mp(c)) for a, c in zip(direct, series, strict=True))), 1e-23,
                          "25-digit rounding x the xi-sum's cancellation (allowance 2e5)")


def test_cancelled_bits_groups_are_those_of_the_scalar_formula():
    """The vectorised grouping of the products by the bits sinh(x) - x cancels puts every product in the group
    the scalar formula 32 ceil((2 log2(2.5/x) + 8)/32) gives (0 at x >= 1/2, -1 at x = 0), also at the floats
    next to the group boundaries x = 2.5 2^-(16 k - 4), where numpy's log2 and libm's may round apart."""
    boundaries = [2.5 * 2.0 ** -(16 * k - 4) for k in range(1, 5)]
    near = [np.nextafter(x, direction) for x in boundaries for direction in (0.0, 1.0)]
    logs = np.random.default_rng(3).uniform(-1070.0, 1.5, 4000)
    sizes = np.concatenate([[0.0, 0.5, np.nextafter(0.5, 0.0), 5e-324, 1e-310], boundaries, near, 2.0**logs])

    def scalar(size):
        if size >= 0.5:
            return 0
        if size == 0.0:
            return -1
        if size < 2.5 / np.finfo(float).max:  # 2.5/x overflows (subnormal x)
            return 32 * math.ceil((2.0 * (math.log2(2.5) - math.log2(size)) + 8) / 32)
        return 32 * math.ceil((2.0 * math.log2(2.5 / size) + 8) / 32)

    groups = sinh_excess_mp._cancelled_bits_groups(sizes)
    assigned = {index: extra for extra, members in groups for index in members}
    assert sorted(assigned) == list(range(sizes.size))  # every product in exactly one group
    assert [assigned[i] for i in range(sizes.size)] == [scalar(float(x)) for x in sizes]
    assert len({extra for extra, _ in groups}) == len(groups)


def test_fast_sinh_excess_and_short_tail_within_rounding():
    """The profiles' shortcuts: A(x) = sinh(x) - x with the cancelled bits added back equals the
    Taylor series to the rounding of both (2^-110 = 8e-34 per operation at 30 digits, a few dozen
    operations each: tolerance 10^-28 relative, more than ten times that), at tiny, small and large
    products; the E_1 tail without its J_k(1 + t) half differs by less than exp(-X), the bound in
    ``spinning_tail``'s docstring, and the solve's tail (that half replaced by a rigorous bound in
    the ball's radius) contains the tail with it computed, its radius below exp(-X) plus rounding."""
    with working_digits(30):
        xi = [flint.arb(x).mid() for x in ("1e-12", "3e-4", "0.01", "0.2", "0.7", "3", "40")]
        points = [flint.arb(t).mid() for t in ("0.001", "0.37", "1")]
        series = special_mp.sinh_excess_matrix(points, xi)
        cancel = special_mp.sinh_excess_matrix(points, xi, method="cancel")
        for i in range(len(points)):
            for k in range(len(xi)):
                exact, fast = _mp(series[i, k]), _mp(cancel[i, k])
                assert_close(fast, exact, "30-digit rounding of two evaluations", rtol=mpmath.mpf(10) ** -28)
        start = kernels_mp.xi_quadrature(0.5, 30).asymptotic_start
        for t in [flint.arb(0), *points]:
            full = kernels_mp.spinning_tail(t, start, far="exact")
            short = kernels_mp.spinning_tail(t, start, far=False)
            bounded = kernels_mp.spinning_tail(t, start)
            assert_within(float(abs(_mp(full) - _mp(short))), float(mpmath.exp(-start)),
                          "the J_k(1 + t) half's bound exp(-X) (spinning_tail)")
            assert bounded.contains(full.mid())
            # the bound added is below exp(-X) (2e-42 at X = 96; ~1.7e-43 at t = 0), the rest is the short
            # tail's own rounding: an oversized bound (x 100) fails here
            assert_within(float(bounded.rad()), float(4 * short.rad() + mpmath.exp(-start)),
                          "the J_k(1 + t) half's bound exp(-X) plus the short tail's rounding (spinning_tail)")
        # the inequality behind that bound, J_k(eps) <= exp(-eps X) X^(-k-1/2) / (k + 1/2), against mpmath's
        # incomplete gamma function (J_k(eps) = eps^(k+1/2) Gamma(-k-1/2, eps X)), independent of tail_integrals
        with mpmath.workdps(40):
            x = mpmath.mpf(start)
            for k in (0, 1, 4):
                for eps in (1, mpmath.mpf("1.37"), 2):
                    exact = eps ** (k + mpmath.mpf(1) / 2) * mpmath.gammainc(-k - mpmath.mpf(1) / 2, eps * x)
                    # xi = X + u / eps: exp(-eps X) / eps int_0^inf exp(-u) (X + u / eps)^(-k-3/2) du
                    quad = mpmath.exp(-eps * x) / eps * mpmath.quad(
                        lambda u, e=eps, k=k: mpmath.exp(-u) * (x + u / e) ** (-k - mpmath.mpf(3) / 2), [0, mpmath.inf])
                    assert_close(exact, quad, "40-digit quadrature of a smooth decaying integrand",
                                 rtol=mpmath.mpf(10) ** -30)
                    assert exact <= mpmath.exp(-eps * x) * x ** (-k - mpmath.mpf(1) / 2) / (k + mpmath.mpf(1) / 2)
        with pytest.raises(ValueError, match="far"):
            kernels_mp.spinning_tail(points[0], start, far="bound")
    with pytest.raises(ValueError, match="method"):
        special_mp.sinh_excess_matrix(points, xi, method="taylor")


@pytest.mark.parametrize("digits", [30, 49])
def test_sharp_sinh_excess_contains_the_exact_value_and_overlaps_the_series(digits):
    """``sinh_excess_matrix(method="sharp")`` (the Nystrom solve's: Arb's sinh at raised precision on
    exact products) against A(x) = sinh(x) - x of the exact product in mpmath at three times the
    digits (an independent evaluation: its error is 10^-(3 digits) relative, far below the balls):
    every ball contains it; it overlaps the Taylor series' ball; for exact input its radius is at
    most 2^(10 - prec) relative (about three roundings at the working precision times
    sinh(x)/A(x) <= 25 at x >= 1/2, ~2^6.2; observed at most 54 = 2^5.8; 2^10 leaves more than ten
    times that) and at most 4 times the series' (as tight; measured below 1).  A point with a radius
    keeps a rigorous (wider) ball that still contains the exact values of its midpoint's products
    plus the point's own spread."""
    with working_digits(digits):
        prec = flint.ctx.prec
        xi = [flint.arb(x).mid() for x in ("1e-12", "3e-4", "0.01", "0.2", "0.7", "3", "40", "130")]
        exact_points = [flint.arb(t).mid() for t in ("0", "1e-3", "0.0123456789", "0.37", "0.98", "1")]
        sharp = special_mp.sinh_excess_matrix(exact_points, xi, method="sharp")
        series = special_mp.sinh_excess_matrix(exact_points, xi)
        for i, t in enumerate(exact_points):
            for k, x in enumerate(xi):
                value, reference = sharp[i, k], series[i, k]
                with mpmath.workdps(3 * digits):
                    product = _mp(x) * _mp(t)  # exact: both are binary numbers of < prec bits
                    exact = mpmath.sinh(product) - product
                    assert value.contains(mp_to_arb(exact))  # (mp_to_arb at 3 digits: the mpf kept whole)
                assert value.overlaps(reference)
                if exact != 0:
                    assert value.rad() <= abs(value.mid()) * flint.arb(2) ** (10 - prec)
                    assert value.rad() <= 4 * reference.rad() + abs(value.mid()) * flint.arb(2) ** (-prec)
        wide = [flint.arb(t) + flint.arb(0, flint.arb(2) ** (-prec)) for t in ("0.001", "0.5")]
        balls = special_mp.sinh_excess_matrix(wide, xi, method="sharp")
        for i, t in enumerate(wide):
            for k, x in enumerate(xi):
                with mpmath.workdps(3 * digits):  # the ends mid -+ rad of the point, exactly
                    for end in (_mp(t) - arb_radius(t), _mp(t) + arb_radius(t)):
                        product = _mp(x) * end
                        exact = mpmath.sinh(product) - product
                        assert balls[i, k].contains(mp_to_arb(exact))


@pytest.mark.parametrize(("rate", "digits", "layout"), [(0.1, 30, (0.25, 16.0)), (0.5, 49, (0.3, 11.0)),
                                                        (0.02, 54, (0.25, 16.0))])
def test_factored_exponentials_against_direct_sinh(rate, digits, layout):
    """The rows of A(xi t) over runs of equal panels, exp(xi t) = exp(c_p t) exp(d_j t) as outer
    products (``blocks``), against the direct Arb sinh of every entry (no blocks) and, for a few
    entries, mpmath's sinh(x) - x of the exact product at three times the digits: the quadrature's
    nodes are exactly c_p + d_j (no tolerance); the balls overlap the direct ones and contain the
    exact values; the radii are at most 2^(10 - prec) relative (as for ``sharp``: about three
    roundings times sinh(x)/A(x) <= 25 at x >= 1/2; observed at most 54 = 2^5.8) and at most 4 times
    the direct ones (measured below 2).
    Both methods, exact and wide points, and rows cut short by ``lengths``."""
    with working_digits(digits):
        prec = flint.ctx.prec
        quadrature = kernels_mp.xi_quadrature(rate, digits, *layout)
        xi, blocks = quadrature.nodes, quadrature.blocks
        assert blocks and sum(len(mids) * len(offsets) for _, mids, offsets in blocks) > len(xi) / 4
        with mpmath.workdps(3 * digits):
            for start, mids, offsets in blocks:
                for p, c in enumerate(mids):
                    for j, d in enumerate(offsets):
                        assert _mp(xi[start + p * len(offsets) + j]) == _mp(c) + _mp(d)
        points = [flint.arb(t).mid() for t in ("0.004", "0.05", "0.5", "0.98", "1")]
        points.append(flint.arb("0.7") + flint.arb(0, flint.arb(2) ** (-prec)))
        lengths = [len(xi)] * (len(points) - 1) + [blocks[0][0] + len(blocks[0][2]) + 3]
        in_blocks = [k for start, mids, offsets in blocks for k in range(start, start + len(mids) * len(offsets))]
        for method in ("sharp", "cancel"):
            factored = special_mp.sinh_excess_matrix(points, xi, method=method, lengths=lengths, blocks=blocks)
            direct = special_mp.sinh_excess_matrix(points, xi, method=method, lengths=lengths)
            for i, t in enumerate(points):
                for k in range(len(xi)):
                    value, reference = factored[i, k], direct[i, k]
                    assert value.overlaps(reference)
                    if k >= lengths[i]:
                        assert value == 0
                    elif t.rad() == 0 or method == "cancel":
                        assert value.rad() <= abs(value.mid()) * flint.arb(2) ** (10 - prec)
                        assert value.rad() <= 4 * reference.rad() + abs(value.mid()) * flint.arb(2) ** (-prec)
            for i, t in enumerate(points[:-1]):
                for k in in_blocks[:: max(1, len(in_blocks) // 7)]:
                    with mpmath.workdps(3 * digits):
                        product = _mp(xi[k]) * _mp(t)
                        exact = mpmath.sinh(product) - product
                        assert factored[i, k].contains(mp_to_arb(exact))


def _key(value):
    """Midpoint and radius of an arb, exactly (for bit-for-bit comparisons)."""
    return value.mid().man_exp(), value.rad().man_exp()


def _sinh_excess_rows(points, xi, method, lengths, blocks):
    """A(xi_k t_i) row by row, entry by entry, as ``sinh_excess_matrix`` formed them before it took the whole
    matrix at once (a block's panels all formed, then cut to the row's length): the reference of the bit-for-bit
    test below."""
    prec = flint.ctx.prec
    rows = []
    try:
        for t, length in zip(points, lengths, strict=True):
            t_float = float(t)
            if method == "cancel":
                t = t.mid()
            values = [None] * length
            for start, mids, offsets in blocks:
                if start >= length or float(xi[start]) * t_float < 0.5:
                    continue
                xi_block = flint.arb_mat(len(mids), len(offsets), list(xi[start:start + len(mids) * len(offsets)]))
                flint.ctx.prec = 2 * prec + 80
                mid_products, offset_products = [c * t for c in mids], [d * t for d in offsets]
                flint.ctx.prec = prec + 8
                up_mid, up_offset = [v.exp() for v in mid_products], [v.exp() for v in offset_products]
                growth = flint.arb_mat(len(mids), 1, up_mid) * flint.arb_mat(1, len(offsets), up_offset)
                decay = (flint.arb_mat(len(mids), 1, [1 / v for v in up_mid])
                         * flint.arb_mat(1, len(offsets), [1 / v for v in up_offset]))
                half_difference, linear = (growth - decay) / 2, xi_block * t
                flint.ctx.prec = prec
                block = (half_difference - linear).entries()
                stop = min(length - start, len(block))
                values[start:start + stop] = block[:stop]
            for k in range(length):
                if values[k] is not None:
                    continue
                size = float(xi[k]) * t_float
                extra = 0 if size >= 0.5 else (-1 if size == 0.0 else sinh_excess_mp._cancelled_bits(size))
                if extra < 0:
                    values[k] = flint.arb(0)
                    continue
                flint.ctx.prec = 2 * prec + 80
                product = xi[k] * t
                flint.ctx.prec = prec + extra
                value = product.sinh() - product
                flint.ctx.prec = prec
                values[k] = +value if extra > 0 else value
            rows.append(values + [flint.arb(0)] * (len(xi) - length))
    finally:
        flint.ctx.prec = prec
    return rows


@pytest.mark.parametrize("b", ["0.02", "0.6", "0.97"])
def test_sinh_excess_matrix_is_the_entrywise_evaluation(b):
    """``sinh_excess_matrix`` groups the products of the whole matrix by their cancelled bits and forms only
    the panels of a block that a row reaches: bit for bit (midpoints and radii) the entry-by-entry evaluation
    (``_sinh_excess_rows``), for both methods, at a solve's nodes and xi-layer, with rows cut short anywhere
    (inside a block, at its edges, before it) and points exact and with radii."""
    state = solve_state(b, nodes_for_digits(float(b), 20), 25)
    xi, blocks = state._xi, state._xi_blocks
    assert blocks
    with working_digits(25):
        prec = flint.ctx.prec
        points = [*state.nodes[::3], state.stick_radius, flint.arb(1),
                  flint.arb("0.5") + flint.arb(0, flint.arb(2) ** (-prec)), flint.arb(0)]
        start, mids, offsets = blocks[0]
        cuts = [len(xi), 0, start, start + 1, start + len(offsets), start + len(offsets) + 5,
                start + len(mids) * len(offsets) - 1, 3]
        lengths = [cuts[i % len(cuts)] for i in range(len(points))]
        for method in ("sharp", "cancel"):
            for layout, row_lengths in (((), None), (blocks, None), (blocks, lengths)):
                matrix = special_mp.sinh_excess_matrix(points, xi, method=method, lengths=row_lengths, blocks=layout)
                values = special_mp.sinh_excess_values(points, xi, method=method, lengths=row_lengths, blocks=layout)
                reference = _sinh_excess_rows(points, xi, method, row_lengths or [len(xi)] * len(points), layout)
                for i, row in enumerate(reference):
                    for k, expected in enumerate(row):
                        assert _key(matrix[i, k]) == _key(expected), (method, i, k)
                        assert _key(values[i * len(xi) + k]) == _key(expected)


@pytest.mark.parametrize("digits", [20, 49, 100])
def test_bessel_k2_i2_with_shared_digamma_weights(digits):
    """``bessel_k2_i2`` takes the weights psi(k+1) + psi(k+3) of its K2 series from a table per precision
    (``_digamma_weights``, extended on demand): bit for bit the series with the harmonic numbers summed inline,
    whether the table is empty, short or long, and its ball holds Arb's own K2 and I2 (``arb.bessel_k``,
    ``arb.bessel_i``, an independent evaluation) at three times the digits (mpmath's K2 takes 5 s at 300 digits)."""
    with working_digits(digits):
        prec = flint.ctx.prec
        for text in ("1e-6", "0.3", "2.5", "17", "40.25", "66"):
            x = flint.arb(text).mid()
            special_mp._DIGAMMA_WEIGHTS.clear()
            first = special_mp.bessel_k2_i2(x)
            second = special_mp.bessel_k2_i2(x)  # a filled table
            flint.ctx.prec = prec + math.ceil(2.9 * float(x)) + 24
            try:  # the series as it was written before the table: the harmonic numbers summed in the loop
                quarter = x * x / 4
                tau = quarter / 2
                gamma = flint.arb.const_euler()
                harmonic_k, harmonic_k2 = flint.arb(0), flint.arb(3) / 2
                i2 = tau
                psi_sum = (harmonic_k + harmonic_k2 - 2 * gamma) * tau
                limit = flint.arb(2) ** (-flint.ctx.prec)
                k = 0
                while True:
                    k += 1
                    tau = tau * quarter / (k * (k + 2))
                    harmonic_k += flint.arb(1) / k
                    harmonic_k2 += flint.arb(1) / (k + 2)
                    i2 += tau
                    psi_sum += (harmonic_k + harmonic_k2 - 2 * gamma) * tau
                    if k > float(x) and tau * (1 + math.log(k + 3)) < limit * i2:
                        break
                k2 = 2 / (x * x) - flint.arb(1) / 2 - (x / 2).log() * i2 + psi_sum / 2
            finally:
                flint.ctx.prec = prec
            inline = (+k2, +i2)
            for values in (first, second):
                assert [_key(v) for v in values] == [_key(v) for v in inline]
            with working_digits(3 * digits):
                k2_fine = to_full_accuracy(lambda y: y.bessel_k(2), x)
                i2_fine = to_full_accuracy(lambda y: y.bessel_i(2), x)
            assert first[0].contains(k2_fine.mid()) and first[1].contains(i2_fine.mid())


def test_bessel_ratio_asymptotic_by_horner_in_c():
    """Above the switch, ``bessel_ratio`` sums the Hankel expansions of all the nodes with the same number of
    terms at once (``arb_poly.evaluate``): bit for bit the Horner loop term by term in Python (also its own
    fallback above 1024 bits), and within 2^(8 - prec) relative of Arb's own K2/I2 (``arb.bessel_k``,
    ``arb.bessel_i``) at three times the digits."""
    for digits in (30, 49, 320):
        with working_digits(digits):
            prec = flint.ctx.prec
            switch = (prec * math.log(2.0) + 24.0) / 2.0
            points = [flint.arb(switch * f).mid() for f in (1.0, 1.001, 1.3, 2.0, 7.5)]
            ratios = special_mp.bessel_ratio(points)
            for x, ratio in zip(points, ratios, strict=True):
                count = special_mp.expansion_terms(float(x), 2.0)
                kappa = special_mp._hankel_arb(2, count, prec)
                inverse = 1 / x
                numerator, denominator = flint.arb(0), flint.arb(0)
                for k in range(count - 1, -1, -1):
                    numerator = numerator * inverse + kappa[k]
                    denominator = denominator * inverse + (kappa[k] if k % 2 == 0 else -kappa[k])
                loop = flint.arb.pi() * (-2 * x).exp() * numerator / denominator
                assert _key(ratio) == _key(loop)
                if digits < 100:
                    with working_digits(3 * digits):
                        exact = (to_full_accuracy(lambda y: y.bessel_k(2), x)
                                 / to_full_accuracy(lambda y: y.bessel_i(2), x))
                        assert abs(ratio.mid() / exact - 1) < flint.arb(2) ** (8 - prec)


@pytest.mark.parametrize("digits", [30, 49])
def test_tail_integrals_against_the_incomplete_gamma_function(digits):
    """J_k(eps) = eps^(k+1/2) Gamma(-k-1/2, eps X) of ``tail_integrals`` (constants X^(-1/2), 1/X, k + 1/2
    cached per (X, count, precision)) against mpmath's incomplete gamma function at three times the digits (an
    independent evaluation): relative error below 2^(16 - prec) for every k, eps = 0 (X^(-k-1/2)/(k + 1/2))
    included, on either side of the pivot k = eps X of the recurrences; a second call gives the same bits."""
    with working_digits(digits):
        prec = flint.ctx.prec
        start = kernels_mp.xi_quadrature(0.5, digits).asymptotic_start
        count = special_mp.expansion_terms(start)
        for eps_text in ("0", "1e-5", "0.03", "0.3", "1", "1.7"):
            eps = flint.arb(eps_text)
            values = special_mp.tail_integrals(eps, start, count)
            again = special_mp.tail_integrals(eps, start, count)
            assert [_key(v) for v in values] == [_key(v) for v in again]
            with mpmath.workdps(3 * digits):
                e, x = _mp(eps.mid()), mpmath.mpf(start)
                for k in sorted({0, 1, count // 3, count // 2, count - 1}):
                    s = k + mpmath.mpf(1) / 2
                    exact = x ** (-s) / s if e == 0 else e**s * mpmath.gammainc(-s, e * x)
                    assert abs(_mp(values[k]) / exact - 1) < mpmath.mpf(2) ** (16 - prec), (eps_text, k)


@pytest.mark.parametrize("x", ["0", "1e-9", "0.3", "7", "60", "82", "150", "400"])
@pytest.mark.parametrize("digits", [30, 49])
def test_integral_x_i1_pair_against_the_series(x, digits):
    """``integral_x_i1_pair`` (the xi-layer's F and F - x^3/6: Arb's 2F3 in C below the asymptotic
    threshold, ~83 at 30 and ~130 at 49 digits) against the power series in Python of
    ``integral_x_i1``/``integral_x_i1_excess`` (an independent evaluation): the balls overlap, and
    both carry at least prec - 12 bits relative (a few dozen roundings of positive terms, 6 bits, and
    the series' own 2^-(prec + 4) truncation; the series carries 164 of 173 bits at 49 digits);
    above the threshold both use the same Hankel expansion and agree exactly."""
    with working_digits(digits):
        prec = flint.ctx.prec
        point = flint.arb(x).mid()
        full, excess = special_mp.integral_x_i1_pair(point)
        for pair_value, single in ((full, special_mp.integral_x_i1(point)),
                                   (excess, special_mp.integral_x_i1_excess(point))):
            assert pair_value.overlaps(single)
            if x == "0":
                assert pair_value == 0 and single == 0
                continue
            assert pair_value.rel_accuracy_bits() >= prec - 12
            if float(point) >= special_mp.asymptotic_threshold():
                assert pair_value.mid() == single.mid()


@pytest.mark.parametrize("digits", [30, 49])
def test_asymptotic_integral_x_i1_with_coefficients_rounded_once(digits):
    """Above the threshold F(x) sums its Hankel expansion with the exact phi_k rounded to the working precision once
    per precision (``_f_coefficients_arb``): bit for bit Horner's rule with each phi_k rounded at every node, and
    within 2^(12 - prec) relative of mpmath's x^3/6 1F2(3/2; 2, 5/2; x^2/4) at twice the digits; the cache is per
    precision and leaves flint's precision as it was."""
    with working_digits(digits):
        prec = flint.ctx.prec
        start = special_mp.asymptotic_threshold()
        for x in [flint.arb(start * f).mid() for f in (1.0, 1.37, 3.0)]:
            value = special_mp._integral_x_i1_asymptotic(x)
            assert flint.ctx.prec == prec
            inverse, total = 1 / x, flint.arb(0)
            for c in reversed(special_mp._f_coefficients(special_mp.expansion_terms(float(x)))):
                total = total * inverse + flint.arb(c)
            assert _key(value) == _key(x.exp() * x * total / (2 * flint.arb.pi() * x).sqrt())
            with mpmath.workdps(2 * digits):
                y = _mp(x)
                exact = y**3 / 6 * mpmath.hyp1f2(mpmath.mpf(3) / 2, 2, mpmath.mpf(5) / 2, y * y / 4)
                assert abs(_mp(value) / exact - 1) < mpmath.mpf(2) ** (12 - prec)
    for prec in (64, 256):  # each precision its own roundings
        saved = flint.ctx.prec
        flint.ctx.prec = prec
        try:
            direct = [flint.arb(c) for c in special_mp._f_coefficients(16)]
        finally:
            flint.ctx.prec = saved
        assert [_key(c) for c in special_mp._f_coefficients_arb(16, prec)] == [_key(c) for c in direct]
    assert any(low.mid() != high.mid() for low, high in zip(special_mp._f_coefficients_arb(16, 64),
                                                           special_mp._f_coefficients_arb(16, 256), strict=True))


@pytest.mark.parametrize("b", ["0.3", "0.9"])
def test_xi_profiles_from_the_solve_matrix_by_a_row_vector(b):
    """The interpolant's xi-profiles take sum_j w_j g_j A(xi_k t_j) as a row vector times the solve's matrix of
    A(xi_k t_j) (with its edge row t = b weighted by 0): bit for bit (midpoints and radii) the transposed matrix
    times the column of w_j g_j, formed here entry by entry from the matrix."""
    n = 30 if b == "0.3" else 64
    state = solve_state(b, n, 30)
    a_points, scale, xi, side_full, _, column = state._interpolant
    with working_digits(30):
        weights_g = [c * g for c, g in zip(column, state.density, strict=True)]
        transposed = flint.arb_mat(len(xi), n, [a_points[j, k] for k in range(len(xi)) for j in range(n)])
        sums = transposed * flint.arb_mat(n, 1, weights_g)
        two_over_pi = 2 / flint.arb.pi()
        t_sum = sum((c * tj for c, tj in zip(weights_g, state.nodes, strict=True)), flint.arb(0))
        expected = [s * (two_over_pi * (sums[k, 0] + x * t_sum) + f)
                    for k, (s, x, f) in enumerate(zip(scale, xi, side_full, strict=True))]
    assert [_key(v) for v in state._profile_a] == [_key(v) for v in expected]


@pytest.mark.parametrize("b", ["0.5", "0.98"])
def test_truncated_profile_rows_bound_what_they_drop(b):
    """The profiles' rows of A(xi t) stop early (``kernels_mp.xi_sum_truncation``): the terms they drop,
    summed directly in ball arithmetic, are within the bound added to the ball, which is below the target
    t 2^-(prec + TRUNCATION_GUARD_BITS) (no tolerance: both are rigorous); the truncated sums overlap the full ones;
    a row well inside the stick disc stops early (at b = 0.98 below a tenth of the xi-range)."""
    state = solve_state(b, nodes_for_digits(float(b), 20), 25)
    xi, coefficients = state._xi, state._profile_a
    with working_digits(25):
        radius = state.stick_radius
        t_points = [radius * flint.arb(f) for f in ("0.001", "0.3", "0.7", "1")] + [
            radius + (1 - radius) * flint.arb(f) for f in ("0.5", "1")]
        lengths, rests = kernels_mp.xi_sum_truncation(t_points, xi, coefficients)
        full = special_mp.sinh_excess_matrix(t_points, xi, method="cancel")
        short = special_mp.sinh_excess_matrix(t_points, xi, method="cancel", lengths=lengths)
        target = 2.0 ** (-flint.ctx.prec - kernels_mp.TRUNCATION_GUARD_BITS)
        for i, (t, k, rest) in enumerate(zip(t_points, lengths, rests, strict=True)):
            dropped = sum((full[i, j] * coefficients[j] for j in range(k, len(xi))), flint.arb(0))
            if rest is None:
                assert k == len(xi)
                continue
            assert abs(dropped).upper() <= rest.upper()
            assert float(rest.upper()) <= float(t) * target
            kept = sum((short[i, j] * coefficients[j] for j in range(len(xi))), flint.arb(0))
            whole = sum((full[i, j] * coefficients[j] for j in range(len(xi))), flint.arb(0))
            assert (kept + flint.arb(0, rest)).overlaps(whole)
        assert lengths[1] < len(xi)
        if b == "0.98":  # the xi-range is set by the rate 1 - b of E_1 at t = 1; a row at t = 0.3 b decays at 1.7 - b
            assert float(xi[lengths[1]]) < float(xi[-1]) / 10
        with pytest.raises(ValueError, match="ascending"):
            kernels_mp.xi_sum_truncation(t_points, list(reversed(xi)), coefficients)
        with pytest.raises(ValueError, match="lengths"):
            special_mp.sinh_excess_matrix(t_points, xi, lengths=[len(xi) + 1] * len(t_points))


def test_several_radii_in_one_job_give_the_files_of_single_jobs(tmp_path):
    """The workflow script with two stick radii (the higher working precision first, and a node
    sweep) writes the same files as one process per radius: the caches shared between radii
    (xi-functions per node, torque constant, Gauss rules) change no digit."""
    import json
    import subprocess
    import sys

    script = ROOT / "workflow" / "scripts" / "reference_abel_fredholm.py"

    def run(radii, folder):
        """JSON records (without metadata) written by one process for ``radii``."""
        folder.mkdir()
        sweep = ["--convergence", "0.9:8,12", "--convergence-digits", "12", "16"] if "0.9" in radii else []
        subprocess.run([sys.executable, str(script), "--stick-radii", *radii, "--digits", "12", *sweep,
                        "--json", *[str(folder / f"b{r}.json") for r in radii]], check=True, capture_output=True,
                       cwd=ROOT)
        records = {r: json.loads((folder / f"b{r}.json").read_text()) for r in radii}
        for record in records.values():
            record.pop("metadata")
        return records

    together = run(["0.9", "0.3"], tmp_path / "together")
    alone = {**run(["0.9"], tmp_path / "alone_0.9"), **run(["0.3"], tmp_path / "alone_0.3")}
    assert together == alone
    assert len(together["0.9"]["convergence"]) == 4


# -- physical identities at high precision ---------------------------------------------


def test_torque_balance_by_quadrature_of_the_traction(references):
    """T* = 4 int_0^1 q r^2 dr with q from (F6), by mpmath's tanh-sinh quadrature over the
    stick disc (in theta, r = b cos theta: analytic), independent of (F4)."""
    ref = references["0.6"]
    state = ref.fine
    with working_digits(state.work_digits):
        b = arb_to_mp(state.stick_radius)

        def integrand(theta):
            r = b * mpmath.cos(theta)
            q = arb_to_mp(state.interface_traction([mp_to_arb(r)])[0])
            return q * r * r * b * mpmath.sin(theta)

        mpmath.mp.dps = 24
        stick = mpmath.quad(integrand, [0, mpmath.pi / 2])
        balance = 4 * stick + 4 * (1 - b**3) / 3
        assert_within(abs(balance - ref.torque), mpmath.mpf(10) ** -20, "the 20-digit reference's accuracy")


def _rotation_from_slip(ref, b_text, digits):
    """2 int_b^1 s r^2 dr by mpmath's tanh-sinh quadrature (the slip has (r - b)^(3/2) at
    r = b and logarithmic terms at the corner r = 1, which tanh-sinh absorbs)."""
    with working_digits(digits + 3):
        b = mpmath.mpf(b_text)

        def integrand(r):
            return ref.slip([r])[0] * r * r

        mpmath.mp.dps = digits
        return 2 * mpmath.quad(integrand, [b, 1])


def test_rigid_rotation_from_the_slip():
    """omega = 4 int u r^2 dr = 2 int_b^1 s r^2 dr (every Dini term is orthogonal to r), with
    s from (F7) and omega from (F5): an identity the method does not impose (here to 10^-13,
    beyond double precision; to 10^-19 in the slow tier)."""
    ref = solve_reference_abel_fredholm("0.7", 13)
    assert_within(abs(_rotation_from_slip(ref, "0.7", 13) - ref.rigid_rotation), mpmath.mpf(10) ** -13,
                  "13-digit reference and quadrature at 13 digits: omega(0.7) = 0.03, 1e-13 is 300 units of the last")


@pytest.mark.slow
@pytest.mark.parametrize("b", ["0.3", "0.7"])
def test_rigid_rotation_from_the_slip_to_20_digits(references, b):
    ref = references[b]
    assert_within(abs(_rotation_from_slip(ref, b, 21) - ref.rigid_rotation), mpmath.mpf(10) ** -19,
                  "20-digit reference, quadrature at 21 digits: 10 units of the 20th digit of omega ~ 0.1")


def test_interface_conditions(references):
    ref = references["0.5"]
    b = mpmath.mpf("0.5")
    with working_digits(25):
        stick = [b * k / 40 for k in range(40)]
        traction = ref.traction(stick)
        assert all(abs(q) <= 1 for q in traction)
        # the stick-side traction rises continuously to 1 (no inverse square root at r = b)
        gaps = [1 - q for q in ref.traction([b * (1 - mpmath.mpf(10) ** -k) for k in (8, 12)])]
        assert all(g > 0 for g in gaps)
        # 1 - q = C sqrt(b - r) (1 + O((b - r)/b)): the ratio is 1e-2 to a relative 10 x 1e-8
        assert_within(abs(gaps[1] / gaps[0] - mpmath.mpf(10) ** -2), mpmath.mpf(10) ** -2 * 10 * mpmath.mpf(10) ** -8,
                      "next term of the square-root edge, O((b - r)/b)")
        annulus = [b + (1 - b) * mpmath.mpf(k) / 12 for k in range(1, 13)]
        slip = ref.slip(annulus)
        assert all(s > 0 for s in slip) and all(s1 > s0 for s0, s1 in zip(slip, slip[1:], strict=False))
        assert all(q == 1 for q in ref.traction(annulus))
        assert all(s == 0 for s in ref.slip(stick))
        # the slip starts like (r - b)^(3/2)
        eps = [mpmath.mpf(10) ** -6, mpmath.mpf(10) ** -5]
        ratio = [s / e**1.5 for s, e in zip(ref.slip([b + e for e in eps]), eps, strict=True)]
        # the next term of the slip's (r - b)^(3/2) start is O((r - b)/(1 - b)) relative: 10 x 1e-5 / 0.5
        assert_within(abs(ratio[0] / ratio[1] - 1), 10 * eps[1] / (1 - b), "next term, O((r - b)/(1 - b))")


# -- limits b -> 0 and b -> 1 --------------------------------------------------------------


def test_small_stick_disc_limit():
    """4/3 - T* = (16/(9 pi)) b^3 + O(b^5): Richardson in b^2 from b = 0.01, 0.02."""
    deficits = {}
    for b in ("0.01", "0.02"):
        state = solve_state(b, 20, 22)
        with working_digits(22):
            deficits[b] = (mpmath.mpf(4) / 3 - _mp(state.torque)) / mpmath.mpf(b) ** 3
    extrapolated = (4 * deficits["0.01"] - deficits["0.02"]) / 3
    # Richardson in b^2 leaves the O(b^4) term, (4 b1^4 - b2^4)/3 times its coefficient (< 10)
    assert_within(abs(extrapolated - 16 / (9 * mpmath.pi)), 10 * (4 * 0.01**4 + 0.02**4) / 3,
                  "O(b^4) remainder of the Richardson step")


@pytest.mark.slow
def test_slip_onset_limit():
    """T* - 1 = (2/pi)(1 - b) + O((1 - b)^2): linear extrapolation of (T* - 1)/(1 - b)."""
    slopes = {}
    for b in ("0.99", "0.995"):
        state = solve_state(b, 90, 20)
        with working_digits(20):
            slopes[b] = (_mp(state.torque) - 1) / (1 - mpmath.mpf(b))
    extrapolated = 2 * slopes["0.995"] - slopes["0.99"]
    # (T* - 1)/(1 - b) = 2/pi + delta/8 + delta^2 (A ln delta + B) (S1): the linear step 2 s(delta/2) - s(delta)
    # leaves delta^2 (A ln(1/delta) - B)/2 + delta^2 A ln(2)/2; A, B bounded as in tolerances.onset_remainder
    delta = 0.01
    remainder = onset_remainder(delta) / delta / 2 + delta**2 * 3 * math.log(2) / 2
    assert_within(abs(extrapolated - 2 / mpmath.pi), remainder, "delta^2 ln delta remainder of the linear step")
    assert slopes["0.995"] < slopes["0.99"]


# -- independent methods (slow) ------------------------------------------------------------


@pytest.mark.slow
def test_agrees_with_direct_collocation(references):
    """A second method: first-kind collocation of the stick condition (double precision)."""
    from torsional_contact.verification.collocation import solve_direct

    direct = solve_direct(0.3, 8)
    ref = references["0.3"]
    # the collocation's stated accuracy (tests/test_fast.py, COLLOCATION: limited by its brute-force kernels)
    assert_within(abs(direct.torque - float(ref.torque)), 1e-10, "stated accuracy of the collocation")
    assert_within(abs(direct.rigid_rotation - float(ref.rigid_rotation)), 1e-10, "stated accuracy of the collocation")


@pytest.mark.slow
def test_thirty_digits_at_the_reference_radius():
    ref = solve_reference_abel_fredholm("0.6", 30)
    assert ref.error_estimate < mpmath.mpf(10) ** -30
    check = solve_state("0.6", 70, 50)
    with working_digits(50):
        assert_within(abs(_mp(check.torque) - ref.torque), mpmath.mpf(10) ** -30, "the 30-digit reference")
        assert_within(abs(_mp(check.rigid_rotation) - ref.rigid_rotation), mpmath.mpf(10) ** -31,
                      "the 30-digit reference (omega ~ 0.1: 10^-31 absolute)")


# -- bad input: API and command line ----------------------------------------------------------


@pytest.mark.parametrize("value", ["0", "1", "1.5", "-0.2", "nan", "inf", "abc", "1/2", ""])
def test_bad_stick_radius(value):
    with pytest.raises(ValueError, match="stick_radius"):
        solve_reference_abel_fredholm(value, 10)


@pytest.mark.parametrize("digits", [0, -3, MAX_DIGITS + 1, 2.5, True])
def test_bad_digits(digits):
    with pytest.raises(ValueError, match="digits"):
        solve_reference_abel_fredholm("0.5", digits)


@pytest.mark.parametrize(
    "argv",
    [
        ["--stick-radius", "0.6", "--method", "fast", "--n-terms", "145"],
        ["--stick-radius", "0.6", "--method", "fast", "--digits", "0"],
        ["--stick-radius", "0.6", "--method", "fast", "--digits", str(MAX_DIGITS + 1)],
        ["--stick-radius", "0.6", "--method", "fastest"],
        ["--stick-radius", "1", "--method", "fast"],
        ["--stick-radius", "0", "--method", "fast"],
        ["--stick-radius", "0x0.8", "--method", "fast"],
        ["--stick-radius", "nan", "--method", "fast"],
        ["--stick-radius", "0.6", "--method", "fast", "--radii", "0.5", "1.01"],
        ["--stick-radius", "0.6", "--method", "fast", "--radii", "-0.1"],
        ["--stick-radius", "0.6", "--method", "fast", "--radii", "half"],
        ["--stick-radius", "0.6", "--method", "complete", "--radii", "0.5"],
    ],
)
def test_cli_bad_input_exits_2(argv, capsys):
    assert cli_main(["reference", *argv, "--json"]) == 2
    captured = capsys.readouterr()
    assert captured.out == ""
    assert captured.err.count("\n") == 1 and "error" in captured.err


def test_cli_reference_fast(capsys):
    import json

    assert cli_main(["reference", "--stick-radius", "0.7", "--method", "fast", "--digits", "12", "--json",
                     "--radii", "0.35", "0.85"]) == 0
    record = json.loads(capsys.readouterr().out)
    assert record["method"] == "fast" and record["digits"] == 12 and record["stick_radius"] == "0.7"
    assert len(record["torque"].replace(".", "").lstrip("0")) == 12
    double = solve(stick_radius=0.7)
    # 12 printed significant digits: half a unit of the 12th, plus the double solve's accuracy
    for name, accuracy in (("torque", torque_accuracy(0.7)), ("rigid_rotation", ROTATION_ACCURACY)):
        value = float(record[name])
        assert_within(abs(value - getattr(double, name)), 0.5 * 10 ** (math.floor(math.log10(value)) - 11) + accuracy,
                      "half a unit of the 12th printed digit + solver accuracy", exact=True)
    assert float(record["error_estimate"]) < 1e-12 and record["error_estimate_method"]
    assert record["radii"] == ["0.35", "0.85"] and len(record["traction"]) == len(record["slip"]) == 2
    assert float(record["slip"][0]) == 0 and float(record["traction"][1]) == 1
    assert_within(abs(float(record["slip"][1]) - float(double.slip(0.85))), 1e-11, "12 printed digits + accuracy")
