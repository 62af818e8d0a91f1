import mpmath
import numpy as np
import pytest
from tolerances import assert_close, assert_within

from torsional_contact.special.zeros import PAPER_J2_ZEROS, bessel_j2_zeros


@pytest.mark.parametrize("n", [1, 2, 3, 5, 8, 13, 50, 100, 777, 1000, 4321, 10000])
def test_zeros_match_mpmath_to_a_few_ulp(n):
    zeros = bessel_j2_zeros(10000)
    exact = mpmath.besseljzero(2, n)
    # each zero correctly rounded to within a few ulp (Newton-polished): an exact rounding statement
    assert_within(abs(zeros[n - 1] - float(exact)), 4 * np.spacing(float(exact)), "4 ulp", exact=True)


def test_paper_zeros_after_eq_20_are_the_correctly_rounded_first_five():
    np.testing.assert_array_equal(np.round(bessel_j2_zeros(5), 4), PAPER_J2_ZEROS)


def test_zeros_are_increasing_and_spaced_by_about_pi():
    spacing = np.diff(bessel_j2_zeros(10000))
    assert np.all(spacing > 0)
    # McMahon: j_{2,s} = beta - 15/(8 beta) - ..., beta = (s + 3/4) pi, so the spacing is pi + (15/8) pi / beta^2 +
    # ... < pi + 6e-5 for s >= 100; 1e-3
    assert_close(spacing[100:], np.pi, "McMahon's second term (< 6e-5), sixteen times", atol=1e-3)


@pytest.mark.parametrize("bad", [0, -3, 2.5, "7", True, None])
def test_bad_count_is_rejected(bad):
    with pytest.raises(ValueError, match="n_zeros"):
        bessel_j2_zeros(bad)
