"""Comparisons whose tolerances say where they come from, and the headroom each one keeps.

Every numerical comparison of the tests states its error bound: the method's own error
estimate, conditioning times the machine epsilon ``EPS``, a truncation bound, or the accuracy
of the independent reference.  The bound must sit at least ten times above the largest error
seen on any floating-point variant (BLAS threads, numpy's SIMD dispatch, random seeds;
workflow/checks/fp_variants.py): a tolerance is never the error seen once.

* ``assert_within(observed, tolerance, reason)``: a scalar error against its bound (``exact=True``: a statement
  of exact rounding, e.g. half an ulp, where no margin is possible).
* ``assert_close(actual, expected, reason, rtol=, atol=)``: elementwise
  |actual - expected| <= atol + rtol |expected| (numpy arrays, floats or mpmath numbers).
* ``assert_beyond(observed, floor, reason)``: a quantity that must exceed a floor (the check
  has power: the effect it looks for is there, well above the noise).
* ``assert_sampled(observed, expected, standard_error, k, reason)``: a sampled statistic (a Monte
  Carlo rate, a coverage, an estimate of a noisy record) within k of its standard errors.  Its margin
  is a false-alarm probability, not a tenfold ratio: the headroom report lists these apart, with
  the z-score |observed - expected| / standard_error against k.

With ``TORSIONAL_HEADROOM=<directory>`` every comparison is recorded (test id, the line of the
test, observed, tolerance, reason; the worst element of an array) and written to
``<directory>/<pid>.jsonl`` when the session ends (tests/conftest.py); workflow/checks/headroom.py
runs the numerical tests so and prints the smallest ratios tolerance / observed.
"""

from __future__ import annotations

import json
import math
import os
import sys

import numpy as np

__all__ = ["EPS", "assert_within", "assert_close", "assert_beyond", "assert_sampled", "write_records", "seeds",
           "torque_accuracy",
           "ROTATION_ACCURACY", "PROFILE_ACCURACY", "onset_remainder", "slip_rounding", "profile_accuracy",
           "spinning_table_bound", "rotation_b2_coefficient", "WEAK_FORM_TRUNCATION"]

#: Machine epsilon of IEEE double (2.2e-16), the unit of every rounding bound.
EPS = float(np.finfo(float).eps)
#: Environment variable naming the directory of the headroom records.
HEADROOM = "TORSIONAL_HEADROOM"
#: Environment variable with comma-separated seeds for the tests that draw random points.
SEEDS = "TORSIONAL_TEST_SEEDS"

_records: dict = {}


# -- the accuracy of the default (Abel-Fredholm) solver in double precision -----------------------------------------
# Bounds that other tests use as the accuracy of a solve; each is verified against an independent reference with a
# tenfold margin: tests/test_reference_abel_fredholm.py (20-digit references at b = 0.1 .. 0.9) and
# tests/test_extremes.py (the small-slip expansion (S1), exact to rounding for 1 - b < 2e-5).

#: |omega_double - omega| (f p0 / mu): Omega and BETA T* are O(1) numbers from the Nystrom solve (sums of at most
#: 512 terms), omega = Omega - BETA T* loses no relative digits beyond them; 1e-13 = 450 EPS.
ROTATION_ACCURACY = 1e-13
#: |traction| and |slip| errors (f p0, f p0 a / mu) of the interface profiles: Chebyshev interpolants of the
#: Nystrom solution (F6), (F7), evaluated by quadratures of O(1) terms; 1e-12 = 4500 EPS.
PROFILE_ACCURACY = 1e-12


def slip_rounding(s, r=1.0):
    """Bound on the rounding error of the slip (F7) of an Abel-Fredholm solution ``s`` at radius r (f p0 a / mu).

    Every term of D(t) is odd in t (2 Omega t, t arcsech t, the mixed and E terms), of size up to t 4 Omega, and
    passes through sums over the n Nystrom nodes, the m xi-nodes, the 64-point interpolant of D and the Gauss
    sum of (F7): |dD(t)| <= t eps_D, eps_D = (n + m + 128) EPS 4 Omega.  (F7) turns it into
    |ds(r)| <= eps_D r min(1, (4/pi) sqrt(1 - b^2/r^2)); times 5 for the interpolant's Lebesgue constant (< 4)
    and a second, directly evaluated D (a reference) compared with it.
    """
    b = float(s.stick_radius)
    eps_d = (s.n_nodes + s._xi.size + 128) * EPS * 4.0 * abs(s.rotation_constant)  # noqa: SLF001
    r = np.asarray(r, dtype=float)
    width = np.minimum(1.0, 4.0 / math.pi * np.sqrt(np.clip(1.0 - (b / np.maximum(r, b)) ** 2, 0.0, None)))
    return 5.0 * eps_d * r * width


def spinning_table_bound(t):
    """Bound on the error of ``kernels.spinning_transform`` (the table of E_1) at t.

    Its samples are m-term xi-sums (m = 576 at the table's smallest 1 - t), interpolated in psi = arccos t with a
    Lebesgue constant below 4: 4 m EPS |E_1|.  Its interpolation error grows toward the corner t = 1 (psi = 0),
    where E_1 is not analytic ((1 - t) log terms): bounded by ten times the change of the table from 48 to 96
    points (an a-posteriori estimate; the coarser table's error dominates that change).
    """
    from numpy.polynomial import chebyshev

    from torsional_contact.solvers import kernels

    t = np.asarray(t, dtype=float)
    saved = kernels._SPIN_POINTS  # noqa: SLF001
    try:
        kernels._SPIN_POINTS = 48  # noqa: SLF001
        coarse = kernels._spinning_chebyshev.__wrapped__()  # noqa: SLF001
    finally:
        kernels._SPIN_POINTS = saved  # noqa: SLF001
    x = np.arccos(np.clip(t, 0.0, 1.0)) / (np.pi / 4.0) - 1.0
    table = kernels.spinning_transform(t)
    return 4 * 576 * EPS * np.abs(table) + 10 * np.abs(table - t * chebyshev.chebval(x, coarse))


def rotation_b2_coefficient() -> float:
    """c2 of omega + ln(b)/2 = c0 + c2 b^2 + O(b^4 ln b) (S6): -1/8 from arcsech(b)/2 = ln(2/b)/2 - b^2/8 - ..., and
    e2/2 from e(b) = E_1(b)/b = e0 + e2 b^2 + ... (E_1 is odd), e2 from the table of E_1 at b = 1e-2, 5e-3."""
    t = np.array([1e-2, 5e-3])
    from torsional_contact.solvers import kernels

    e = kernels.spinning_transform(t) / t
    e2 = (e[0] - e[1]) / (t[0] ** 2 - t[1] ** 2)
    return e2 / 2 - 1 / 8


def torque_accuracy(b) -> float:
    """Bound on |T*_double - T*| of ``solve_abel_fredholm(b)`` (and of the T* samples of the shipped curve table).

    1e-13 (450 EPS: the rounding of the Nystrom solve and of (F4)); next to slip onset the image singularity of the
    kernel P at t + s = 2 comes within 1 - b of the Nystrom grid, and the rounding of the solve grows like
    1 / (1 - b): + 1e-16 / (1 - b).
    """
    return 1e-13 + 1e-16 / (1.0 - float(b)) if b < 1.0 else 1e-13


#: Truncation bounds K / N^p of the complete weak form (``method="complete"``) at N terms, with the orders of
#: tests/test_convergence.py (the traction at the corner r = 1 converges like 1/N; the slip on the stick disc and
#: the torque balance of the traction at least like 1/N^2) and K a round number more than ten times the largest
#: coefficient that N = 145 and N = 1160 give (0.2, 0.22 and 0.012; tests/test_formulations.py).
WEAK_FORM_TRUNCATION = {"slip_traction": (3.0, 1), "stick_slip": (3.0, 2), "torque_balance": (0.2, 2)}


def profile_accuracy(b) -> float:
    """Bound on the error of the interface traction and slip of ``solve_abel_fredholm(b)``: ``PROFILE_ACCURACY``,
    plus the same growth as the T* bound next to slip onset (``torque_accuracy``), 1e-16 / (1 - b)."""
    return PROFILE_ACCURACY + (1e-16 / (1.0 - float(b)) if b < 1.0 else 0.0)


def onset_remainder(delta) -> float:
    """Bound on |T* - (S1)| at slip annulus delta = 1 - b: the remainder delta^3 (A ln delta + B) of ``asymptotics``
    (A = 0.197, B = -0.425 from the Abel-Fredholm solver), with the coefficients rounded up to 0.3 and 0.6 and
    then ten times larger."""
    return delta**3 * (3.0 * math.log(1.0 / delta) + 6.0)


def seeds(default=(11, 2024, 31337)) -> list:
    """Seeds of the tests that draw random points: ``default``, or the ones in TORSIONAL_TEST_SEEDS."""
    text = os.environ.get(SEEDS, "").strip()
    return [int(s) for s in text.split(",")] if text else list(default)


def _float(x) -> float:
    try:
        return float(x)
    except OverflowError:
        return math.inf


def _record(kind: str, observed: float, bound: float, reason: str) -> None:
    if HEADROOM not in os.environ:
        return
    frame = sys._getframe(2)  # the test that called assert_*
    where = f"{os.path.basename(frame.f_code.co_filename)}:{frame.f_lineno}"
    test = os.environ.get("PYTEST_CURRENT_TEST", "?").rsplit(" (", 1)[0]
    if kind == "floor":
        ratio = observed / bound if bound > 0 else math.inf
    else:
        ratio = bound / observed if observed > 0 else math.inf
    key = (test, where)
    old = _records.get(key)
    if old is None or ratio < old["ratio"]:
        _records[key] = {"test": test, "line": where, "kind": kind, "observed": observed, "tolerance": bound,
                         "ratio": ratio, "reason": reason}


def write_records() -> None:
    """Append the records of this process to <TORSIONAL_HEADROOM>/<pid>.jsonl (session end)."""
    directory = os.environ.get(HEADROOM)
    if not directory or not _records:
        return
    os.makedirs(directory, exist_ok=True)
    with open(os.path.join(directory, f"{os.getpid()}.jsonl"), "a", encoding="utf-8") as handle:
        for entry in _records.values():
            handle.write(json.dumps(entry, allow_nan=True) + "\n")
    _records.clear()


def assert_within(observed, tolerance, reason: str, *, exact: bool = False) -> None:
    """observed (an error, >= 0) <= tolerance, the bound ``reason`` derives.

    ``exact``: the bound is an exact rounding statement (a correctly rounded double is off by at most half an
    ulp), where no tenfold margin can exist; the headroom report lists these apart.
    """
    value, bound = _float(observed), _float(tolerance)
    _record("exact" if exact else "error", value, bound, reason)
    assert value <= bound, f"{value:.3e} > {bound:.3e} ({reason})"


def assert_beyond(observed, floor, reason: str) -> None:
    """observed > floor: the effect the test looks for is there, above the noise."""
    value, bound = _float(observed), _float(floor)
    _record("floor", value, bound, reason)
    assert value > bound, f"{value:.3e} <= {bound:.3e} ({reason})"


def assert_sampled(observed, expected, standard_error, k, reason: str, *, side: str = "both") -> None:
    """A sampled statistic within k standard errors of its expectation: |z| <= k, z = (observed - expected) /
    standard_error (``side="upper"``: z <= k only, ``"lower"``: z >= -k only).

    The tolerance of a statistical test is its false-alarm probability (k = 3: 0.27 % two-sided for a normal
    statistic; state the probability in ``reason`` when the statistic is not normal), so its headroom is not a
    ratio of ten: the report lists these as kind ``sampled``, apart from the error bounds.
    """
    if side not in ("both", "upper", "lower"):
        raise ValueError(f"side must be 'both', 'upper' or 'lower', got {side!r}")
    z = (_float(observed) - _float(expected)) / _float(standard_error)
    excess = abs(z) if side == "both" else (z if side == "upper" else -z)
    _record("sampled", max(excess, 0.0), float(k), reason)
    assert excess <= k, f"z = {z:.3g} beyond {k} standard errors ({reason})"


def assert_close(actual, expected, reason: str, *, rtol=0.0, atol=0.0) -> None:
    """|actual - expected| <= atol + rtol |expected| elementwise (atol, rtol may be arrays)."""
    if _is_mp(actual) or _is_mp(expected):
        value, limit = _float(abs(actual - expected)), _float(atol + rtol * abs(expected))
        _record("error", value, limit, reason)
        assert value <= limit, f"{value:.3e} > {limit:.3e} ({reason})"
        return
    a = np.asarray(actual, dtype=float)
    e = np.asarray(expected, dtype=float)
    with np.errstate(invalid="ignore"):  # inf - inf: handled below
        error = np.abs(a - e)
    bound = np.asarray(atol, dtype=float) + np.asarray(rtol, dtype=float) * np.abs(e)
    error, bound = np.broadcast_arrays(error, bound)
    if error.size == 0:
        return
    finite = np.isfinite(a) == np.isfinite(e)
    same = (a == e) | (np.isnan(a) & np.isnan(e))  # infinities of the same sign, or equal values
    error = np.where(same, 0.0, np.where(finite, error, np.inf))
    with np.errstate(divide="ignore", invalid="ignore"):
        ratios = np.where(error > 0, bound / error, np.inf)
    worst = np.unravel_index(int(np.argmin(ratios)), ratios.shape)
    value, limit = float(error[worst]), float(bound[worst])
    _record("error", value, limit, reason)
    assert np.all(error <= bound), (f"{int(np.sum(error > bound))} of {error.size} beyond tolerance; worst "
                                    f"{value:.3e} > {limit:.3e} at index {tuple(int(i) for i in worst)} ({reason})")


def _is_mp(x) -> bool:
    return type(x).__module__.startswith("mpmath")
