r"""Converged partial-slip solution to a requested number of digits, with an error estimate.

Units (docs/conventions.md): r in a; tractions in f p0; slip in f p0 a / mu; omega in f p0 / mu;
T* = 2T/(f F a) (eq. 32).

The Abel-Fredholm method (F1)-(F7) of ``fast`` in arbitrary precision (``nystrom_mp``,
``kernels_mp``, ``special_mp``): the high-precision reference of the converged (exact)
solution, against which every double-precision method is measured.

Error estimate
--------------
``solve_reference_abel_fredholm`` solves twice: at (n, digits + GUARD_DIGITS working
digits) and at (n' = ceil(CHECK_NODE_FACTOR n) + CHECK_EXTRA_NODES, digits + GUARD_DIGITS
+ CHECK_EXTRA_DIGITS), with xi-quadratures that share no panel edge (so they share no
error of the xi-integrals), and with 3 log10(1/(1 - b)) more digits in both as b -> 1
(``rotation_digits_lost``).  It reports the second (finer) solution and, as its error
estimate, the largest relative difference of T* and omega between the two; since both
errors decay geometrically, the difference bounds the error of the coarser solve and
overestimates that of the finer one.  ``profile_error_estimate`` does the same for the
traction and slip at given radii (absolute, f p0 and f p0 a / mu).

The profiles cost a few hundred rows of the Nystrom interpolant per solve (``nystrom_mp``: series
of it on the stick disc and the slip annulus), whatever the number of radii.  Times: each workflow
job records its solves' wall and CPU seconds (``timings/abel_fredholm/``), and
workflow/checks/benchmark_build.py the reference jobs' share of a clean build.
"""

from __future__ import annotations

import math
import time
import warnings
from dataclasses import dataclass, field

import flint
import mpmath

from ..diagnostics import AccuracyWarning
from .arbitrary_precision import arb_radius, arb_to_mp, decimal_string, mp_to_arb, parse_decimal, working_digits
from .nystrom_mp import AbelFredholmState, nodes_for_digits, solve_state

__all__ = [
    "DEFAULT_DIGITS",
    "MAX_DIGITS",
    "GUARD_DIGITS",
    "ERROR_ESTIMATE_METHOD",
    "AbelFredholmReference",
    "rotation_digits_lost",
    "solve_reference_abel_fredholm",
    "reference_set_abel_fredholm",
    "face_shear_arb",
]

#: Significant digits of the reference by default.
DEFAULT_DIGITS = 30
#: Largest number of digits accepted (the time grows roughly like digits^3).
MAX_DIGITS = 100
#: Working digits beyond the requested ones (rounding in the kernels, R(t)/t, the solve).
GUARD_DIGITS = 10
#: Digits beyond the requested ones that the node count aims at.
NODE_MARGIN_DIGITS = 5
#: The check solve of the error estimate: more nodes and more working digits.
CHECK_NODE_FACTOR = 1.25
CHECK_EXTRA_NODES = 4
CHECK_EXTRA_DIGITS = 8
#: xi-quadrature layout of the coarser solve (no panel edge in common with the default).
CHECK_FIRST_PANEL = 0.3
CHECK_WIDTH_DECAYS = 11.0

ERROR_ESTIMATE_METHOD = (
    "largest relative difference of T* and omega between the reported solve and a coarser one "
    "(a factor {factor} fewer Nystrom nodes, {extra} fewer working digits, a xi-quadrature with "
    "other panels); both converge geometrically, so it bounds the coarser solve's error and "
    "overestimates the reported one's"
)


@dataclass(frozen=True)
class AbelFredholmReference:
    """Converged partial-slip solution at one stick radius to ``digits`` significant digits.

    Attributes
    ----------
    stick_radius : mpf
        b/a (the exact decimal input, at the working precision).
    torque, rigid_rotation : mpf
        T*(b) (F4) and omega (F5, f p0 / mu) of the finer solve, rounded to ``digits``.
    digits : int
        Significant digits requested.
    n_nodes : int
        Nystrom nodes of the reported (finer) solve.
    seconds, cpu_seconds : float
        Wall-clock and processor time of both solves (they differ when the cores are shared).
    error_estimate : mpf
        max(|Delta T*|/|T*|, |Delta omega|/|omega|) between the two solves: a relative
        error estimate (see ``error_estimate_method``).
    error_estimate_method : str
    fine, coarse : AbelFredholmState
        The two solves.
    torque_error_estimate, rigid_rotation_error_estimate : mpf
        |Delta T*| and |Delta omega| (absolute).
    """

    stick_radius: object
    torque: object
    rigid_rotation: object
    digits: int
    n_nodes: int
    seconds: float
    error_estimate: object
    error_estimate_method: str
    fine: AbelFredholmState = field(repr=False)
    coarse: AbelFredholmState = field(repr=False)
    torque_error_estimate: object = None
    rigid_rotation_error_estimate: object = None
    cpu_seconds: float = 0.0

    def _radii(self, radii, state):
        with working_digits(state.work_digits):
            return [mp_to_arb(parse_decimal("radii", r, 0, 1)) for r in radii]

    def _profile(self, kind: str, radii, state) -> list:
        exact = self._radii(radii, state)
        values = state.interface_traction(exact) if kind == "traction" else state.interface_slip(exact)
        with working_digits(state.work_digits):
            return [arb_to_mp(v) for v in values]

    def traction(self, radii) -> list:
        """sigma_zt(r, 0)/(f p0) at radii in [0, 1] (decimal strings or mpf), eq. (F6)."""
        return self._profile("traction", radii, self.fine)

    def slip(self, radii) -> list:
        """Slip s(r) in f p0 a / mu at radii in [0, 1] (decimal strings or mpf), eq. (F7)."""
        return self._profile("slip", radii, self.fine)

    def sigma_rt(self, radii, state=None) -> list:
        """sigma_rt(r, 0)/(f p0) at radii in [0, 1] (decimal strings or mpf): ``face_shear_arb``.

        ``state``: the finer solve by default (``coarse`` for the error estimate of a comparison).
        """
        state = self.fine if state is None else state
        exact = self._radii(radii, state)
        values = face_shear_arb(state, exact)
        with working_digits(state.work_digits):
            return [arb_to_mp(v) for v in values]

    def _profiles(self, radii) -> dict:
        """Traction and slip of both solves at ``radii`` (mpf lists, keys fine_/coarse_)."""
        return {f"{name}_{kind}": self._profile(kind, radii, state)
                for name, state in (("fine", self.fine), ("coarse", self.coarse)) for kind in ("traction", "slip")}

    @staticmethod
    def _largest_difference(first, second):
        return max((abs(a - c) for a, c in zip(first, second, strict=True)), default=mpmath.mpf(0))

    def profile_error_estimate(self, radii) -> dict:
        """Largest |fine - coarse| of the traction and of the slip at ``radii`` (absolute)."""
        values = self._profiles(radii)
        with working_digits(self.fine.work_digits):
            return {kind: self._largest_difference(values[f"fine_{kind}"], values[f"coarse_{kind}"])
                    for kind in ("traction", "slip")}

    def as_dict(self, radii=None, extended: bool = False) -> dict:
        """JSON-ready record: decimal strings with ``digits`` significant digits.

        ``radii`` adds ``radii``, ``traction``, ``slip`` and their absolute error estimates;
        ``extended`` adds the finer solve's values with all its working digits (for
        comparisons below 10^-digits; accurate to about the error estimates).
        """
        fine = self.fine
        with working_digits(fine.work_digits):
            record = {
                "stick_radius": mpmath.nstr(self.stick_radius, self.digits + 5),
                "torque": decimal_string(self.torque, self.digits),
                "rigid_rotation": decimal_string(self.rigid_rotation, self.digits),
                "digits": self.digits,
                "method": "fast",
                "n_nodes": self.n_nodes,
                "n_nodes_coarse": self.coarse.n_nodes,
                "working_digits": fine.work_digits,
                "working_digits_coarse": self.coarse.work_digits,
                "seconds": round(self.seconds, 3),
                "cpu_seconds": round(self.cpu_seconds, 3),
                "error_estimate": mpmath.nstr(self.error_estimate, 3),
                "torque_error_estimate": mpmath.nstr(self.torque_error_estimate, 3),
                "rigid_rotation_error_estimate": mpmath.nstr(self.rigid_rotation_error_estimate, 3),
                "error_estimate_method": self.error_estimate_method,
                "rounding_bound": mpmath.nstr(max(arb_radius(fine.torque), arb_radius(fine.rigid_rotation)), 3),
            }
            if extended:
                record["extended"] = {
                    "torque": mpmath.nstr(arb_to_mp(fine.torque), fine.work_digits),
                    "rigid_rotation": mpmath.nstr(arb_to_mp(fine.rigid_rotation), fine.work_digits),
                }
        if radii is not None:
            values = self._profiles(radii)
            with working_digits(fine.work_digits):
                record["radii"] = [str(r) for r in radii]
                for kind in ("traction", "slip"):
                    record[kind] = [decimal_string(v, self.digits) for v in values[f"fine_{kind}"]]
                    error = self._largest_difference(values[f"fine_{kind}"], values[f"coarse_{kind}"])
                    record[f"{kind}_error_estimate"] = mpmath.nstr(error, 3)
                    if extended:
                        record["extended"][kind] = [mpmath.nstr(v, fine.work_digits) for v in values[f"fine_{kind}"]]
        return record


class _ShearProxy:
    """Stands in for an ``AbelFredholmState`` in its slip quadrature (F7), with D(t) replaced by t E(t)."""

    def __init__(self, state):
        self.state = state
        self.stick_radius = state.stick_radius
        self.work_digits = state.work_digits
        self.step = flint.arb(10) ** (-(state.work_digits // 3))

    def _d_function(self, t_points, psi_points) -> list:
        """t E(t) = t D'(t) - D(t) with D' = -D_psi / sin(psi), D_psi by central differences in psi = arccos t.

        D is analytic in psi on [0, arccos b] (the corner's (1 - t)^(3/2) terms are odd powers of
        psi), so the differences lose h^2 |d^3 D / d psi^3| / 6 ~ 10^(-2 W/3) and rounding
        10^(-W) / h ~ 10^(-2 W/3) at W working digits.
        """
        h = self.step
        psi = list(psi_points)  # t = cos(psi); the shifted angles as arccos(cos(psi +- h)) = |psi +- h|
        d = self.state._d_function(t_points, psi)  # noqa: SLF001 - the reference's own D of (F7)
        plus = self.state._d_function([(p + h).cos() for p in psi], [abs(p + h) for p in psi])  # noqa: SLF001
        minus = self.state._d_function([(p - h).cos() for p in psi], [abs(p - h) for p in psi])  # noqa: SLF001
        out = []
        for t, p, dv, dp, dm in zip(t_points, psi, d, plus, minus, strict=True):
            d_psi = (dp - dm) / (2 * h)
            out.append(-t * d_psi / p.sin() - dv)
        return out


def face_shear_arb(state, radii) -> list:
    """sigma_rt(r, 0) = du/dr - u/r at exact radii (arb list), from (F7) in arbitrary precision.

    With t = r sin(phi), u(r, 0) = (2/pi) int_phi_b^(pi/2) sin(phi) D(r sin phi) dphi and D(b) = 0 (F3):

        sigma_rt(r, 0) = (2/(pi r^2)) int_b^r t^2 E(t) / sqrt(r^2 - t^2) dt,   E = dD/dt - D/t,

    i.e. the slip integral of (F7) with D replaced by t E(t), divided by 2 r (the state's own
    quadrature, ``AbelFredholmState.interface_slip``).  0 on the stick disc and at r = 1 (eq. 9).
    """
    proxy = _ShearProxy(state)
    with working_digits(state.work_digits):
        inside = [r if r < 1 else flint.arb(0) for r in radii]
        halves = type(state).interface_slip(proxy, inside)
        return [+(v / (2 * r)) if r < 1 and v != 0 else flint.arb(0) for v, r in zip(halves, radii, strict=True)]


def rotation_digits_lost(stick_radius) -> int:
    """Decimal digits of omega lost to its smallness near slip onset (b -> 1).

    omega ~ 0.7 (1 - b)^3 as b -> 1 (measured), and omega = Omega - BETA T* cancels to
    that size: relative accuracy in omega needs 3 log10(1/(1 - b)) more digits, both
    in the node count and in the working precision.
    """
    b = float(stick_radius)
    return max(0, math.ceil(3.0 * math.log10(1.0 / (1.0 - b))))


def _check_digits(digits) -> int:
    if isinstance(digits, bool) or not isinstance(digits, int) or not 1 <= digits <= MAX_DIGITS:
        raise ValueError(f"digits must be an integer in [1, {MAX_DIGITS}], got {digits!r}")
    return digits


def solve_reference_abel_fredholm(stick_radius, digits: int = DEFAULT_DIGITS, n_nodes: int | None = None):
    """T*(b), omega(b) and the interface profiles of the converged solution to ``digits`` digits.

    Parameters
    ----------
    stick_radius : str, mpf or Decimal
        b/a in the open interval (0, 1), read as an exact decimal (a float is read as
        its shortest repr; prefer strings).
    digits : int
        Significant digits wanted, 1..MAX_DIGITS.
    n_nodes : int, optional
        Nystrom nodes of the reported (finer) solve; default CHECK_NODE_FACTOR n0 +
        CHECK_EXTRA_NODES with n0 = ``nodes_for_digits(b, digits + NODE_MARGIN_DIGITS)``,
        the nodes of the coarser solve of the error estimate.

    Returns
    -------
    AbelFredholmReference

    Raises
    ------
    ValueError
        If ``stick_radius`` is not a decimal in (0, 1) or ``digits`` is out of range.

    Warns
    -----
    AccuracyWarning
        If the error estimate exceeds 10^-digits (relative to max(1, |omega|)).
    """
    digits = _check_digits(digits)
    lost = rotation_digits_lost(parse_decimal("stick_radius", stick_radius, 0, 1, closed=False))
    with working_digits(digits + GUARD_DIGITS + lost + CHECK_EXTRA_DIGITS):
        b = parse_decimal("stick_radius", stick_radius, 0, 1, closed=False)
    if n_nodes is None:
        base = nodes_for_digits(float(b), digits + NODE_MARGIN_DIGITS + lost)
        n_nodes = math.ceil(CHECK_NODE_FACTOR * base) + CHECK_EXTRA_NODES
    n_coarse = max(4, math.floor((n_nodes - CHECK_EXTRA_NODES) / CHECK_NODE_FACTOR))
    start, cpu_start = time.perf_counter(), time.process_time()
    coarse = solve_state(b, n_coarse, digits + GUARD_DIGITS + lost, first_panel=CHECK_FIRST_PANEL,
                         width_decays=CHECK_WIDTH_DECAYS)
    fine = solve_state(b, int(n_nodes), digits + GUARD_DIGITS + lost + CHECK_EXTRA_DIGITS)
    seconds, cpu_seconds = time.perf_counter() - start, time.process_time() - cpu_start
    with working_digits(fine.work_digits):
        torque, rotation = arb_to_mp(fine.torque), arb_to_mp(fine.rigid_rotation)
        torque_error = abs(torque - arb_to_mp(coarse.torque))
        rotation_error = abs(rotation - arb_to_mp(coarse.rigid_rotation))
        estimate = max(torque_error / abs(torque), rotation_error / abs(rotation))
        if estimate > mpmath.mpf(10) ** (-digits):
            warnings.warn(
                f"stick_radius={stick_radius!s}: the relative error estimate {mpmath.nstr(estimate, 3)} exceeds "
                f"10^-{digits}; raise n_nodes",
                AccuracyWarning,
                stacklevel=2,
            )
    with working_digits(digits):
        rounded = (+torque, +rotation)
    method = ERROR_ESTIMATE_METHOD.format(factor=CHECK_NODE_FACTOR, extra=CHECK_EXTRA_DIGITS)
    return AbelFredholmReference(
        stick_radius=b, torque=rounded[0], rigid_rotation=rounded[1], digits=digits, n_nodes=fine.n_nodes,
        seconds=seconds, error_estimate=estimate, error_estimate_method=method, fine=fine, coarse=coarse,
        torque_error_estimate=torque_error, rigid_rotation_error_estimate=rotation_error, cpu_seconds=cpu_seconds,
    )


def reference_set_abel_fredholm(radii, digits: int = DEFAULT_DIGITS, n_nodes: int | None = None) -> list:
    """``solve_reference_abel_fredholm`` for each stick radius in ``radii`` (list of results)."""
    return [solve_reference_abel_fredholm(b, digits, n_nodes) for b in radii]
