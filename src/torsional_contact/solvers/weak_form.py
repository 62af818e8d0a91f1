r"""The weak form of the dual series equations: eq. (38) as published, and completed.

Units: lengths in a, tractions in f p0, displacements in f p0 a / mu (docs/conventions.md).

Field representation
--------------------
The upper cylinder (z >= 0) carries the bilateral field T* r z (eq. 4) plus a
corrective field.  Write the corrective interface displacement as

    u(r, 0) = omega r + sum_n c_n J1(lam_n r),        J2(lam_n) = 0,          (i)

so the interface traction, from eq. (17) and (26), is

    sigma_zt(r, 0) = T* r - sum_n c_n lam_n J1(lam_n r).                      (ii)

``c_n`` is the paper's coefficient in our units: c_n = lam_n A~_n with A~_n of
eq. (31).  ``omega`` is a rigid rotation: it is the lambda = 0 member of the Dini
family (x J1'(x) - J1(x) = 0, i.e. J2 = 0, has the extra eigenfunction r because
H + nu = -1 + 1 = 0; Watson, Bessel Functions, 18.3).  It produces no stress.  Every
J1(lam_n r) is orthogonal to r on (0, 1) with weight r (int_0^1 r^2 J1(lam_n r) dr =
J2(lam_n)/lam_n = 0), so without omega every admissible interface displacement has
int_0^1 u r^2 dr = 0: a slip that is zero on the stick disc and positive on the slip
annulus is impossible.  The published series (21) forces omega = 0.

Boundary conditions (7), (8) with (i), (ii):

    omega r + sum c_n J1(lam_n r) = 0                  0 <= r < b   (stick, 29)
    sum c_n lam_n J1(lam_n r)     = T* r - 1           b <  r <= 1  (slip, 30)

Weak form
---------
Let R(r) be the residual of the stick equation on (0, b) and of the slip equation on
(b, 1).  Eq. (33) asks int_0^1 R(r) J1(lam_m r) r dr = 0 for m = 1..N.  With the
orthogonality (34) and the split (36) this becomes, for the unknowns c_n:

    c_m h_m + sum_n (lam_n - 1) I_mn c_n + omega S_m = T* L_m - K_m           (iii)

where h_m = h(lam_m) (35), I_mn = int_b^1 J1(lam_m r) J1(lam_n r) r dr (52, 53),
S_m = int_0^b r^2 J1(lam_m r) dr = b^2 J2(lam_m b)/lam_m, L_m = int_b^1 r^2 J1 dr
= -S_m and K_m = int_b^1 r J1 dr (51).  With c_n = lam_n A~_n, (iii) with
omega = 0 is exactly eq. (38): A~_m lam_m h_m + sum_n A~_n C_mn = B_m, with
T* L_m - K_m = B_m.

* ``published``: (iii) with omega = 0, m, n = 1..N: the paper's eq. (38).
* ``complete``: omega is an unknown and r is added to the test functions.  The extra
  row is int_0^1 R(r) r r dr = 0:

    sum_n (1 - lam_n) S_n c_n + omega b^4/4 = T* (1 - b^4)/4 - (1 - b^3)/3.   (iv)

  (uses int_b^1 r^2 J1(lam_n r) dr = -S_n).  Since {r} U {J1(lam_n r)} is complete
  on (0, 1), R -> 0 as N grows; in the published system R keeps an uncontrolled
  component along r, i.e. the published solution satisfies u = alpha r on the
  stick disc (a rigid slip) and traction 1 - alpha r on the slip annulus (alpha < 0:
  the stick disc slips backwards and the slip-zone traction exceeds the friction limit).

Regularity: fixing T* for a given b
-----------------------------------
For a given b, (iii)-(iv) have a solution for every T*; it is linear in T*.  The
exact solution of the mixed problem has a stick-side traction singularity
K (b - r)^(-1/2) at r = b unless T* takes one value, T*(b), at which the traction
rises continuously to the friction limit (docs/conventions.md).  We impose this as
continuity of the truncated traction series at r = b:

    sigma_zt(b, 0) = T* b - sum_n c_n lam_n J1(lam_n b) = 1,                  (v)

which, with c = c_K + T* c_L (two right-hand sides, one factorisation), gives T*
in closed form.  When K != 0 the truncated traction at b grows like sqrt(N), so
(v) selects K -> 0 as N grows; the error of T*(b) decreases about like 1/N
(measured in ``tests/test_convergence.py``).  The paper says only that it
'evaluates the torque actually present'; that torque is T* identically, because every
eigenfunction carries zero torque, so it cannot by itself fix b.

Other closures (``closure=``), for asking which findings about the printed scheme depend
on (v).  Each is a reading of the paper's 'impose the stick and slip conditions
immediately either side this point ... and finally evaluate the imposed torque actually
present', each is linear in T*, and each holds for the exact solution:

* ``"traction"`` (default): (v), the slip condition q = 1 imposed at r = b+;
* ``"displacement"``: the stick condition imposed at r = b-,

      u(b) = omega b + sum_n c_n J1(lam_n b) = 0;                               (vi)

* ``"torque"``: the torque of the traction actually present, the truncated series on
  the stick disc and the friction limit 1 on the slip annulus, equals T*,

      T* = 4 int_0^b q(r) r^2 dr + (4/3)(1 - b^3),
      int_0^b q r^2 dr = T* b^4/4 - sum_n c_n lam_n S_n.                         (vii)

  Since every eigenfunction carries zero torque, (vii) says the slip-zone residual
  1 - q carries no torque.  For the printed system, whose residual tends to alpha r
  (see above), (vi) and (vii) both force alpha -> 0 as N grows instead of regularity.

Limits: b = 1 gives c = 0, omega = 0 and T* = 1 exactly (slip onset, eq. 5).  b = 0
(spinning) decouples (iii) into c_m lam_m h_m = B_m with T* = 4/3 (torque balance
for traction 1) and omega -> +infinity (omega grows like ln(1/b)/2 as b -> 0).
"""

from __future__ import annotations

import math
import sys
import warnings
from dataclasses import dataclass

import numpy as np
from scipy import special

from ..criteria import GROSS_SLIP_TORQUE
from ..diagnostics import IllConditioningWarning, ResolutionWarning, UnphysicalResultWarning
from ..special import integrals
from ..special.zeros import bessel_j2_zeros
from .equilibration import equilibrated_solve

__all__ = [
    "WEAK_FORMS",
    "MAX_SERIES_TERMS",
    "SeriesSolution",
    "solve_series",
    "assemble",
    "complete_border",
    "resolution_limit",
    "terms_to_resolve",
    "minimum_inverse_terms",
    "CLOSURES",
    "closure_torque",
]

#: The weak forms (``solve_series``): eq. (38) as printed, and with the missing rigid-rotation mode.
WEAK_FORMS = ("published", "complete")

#: How T* is fixed for a given b (see the module docstring): (v), (vi) or (vii).
CLOSURES = ("traction", "displacement", "torque")

#: Largest N accepted: the dense (N+1)^2 system and its equilibrated copy take ~16 N^2
#: bytes (1.6 GB at N = 10000) and the solve ~N^3/3 flops (about a minute on 2 cores).
MAX_SERIES_TERMS = 10_000

#: Smallest number of highest-term wavelengths (lam_N * width) that must fit across
#: the stick disc and across the slip annulus before we stop warning.
RESOLUTION_WAVELENGTHS = 10.0

#: Reciprocal condition number below which the solve warns.
RCOND_WARN = 1e-13



@dataclass(frozen=True)
class SeriesSolution:
    """Coefficients of one solution of the dual series equations for T* > 0.

    Attributes
    ----------
    method : str
        "published" or "complete".
    stick_radius : float
        b/a.
    torque : float
        T*(b) from the regularity condition (v); 1 at b = 1, 4/3 at b = 0.
    rigid_rotation : float
        omega (units f p0 / mu); nan for ``published`` (no such unknown), +inf at b = 0.
    eigenvalues : ndarray
        lam_n, zeros of J2.
    amplitudes : ndarray
        c_n = lam_n A~_n: interface displacement amplitudes (units f p0 a / mu).
    rcond : float
        Reciprocal 1-norm condition number estimate of the equilibrated matrix.
    """

    method: str
    stick_radius: float
    torque: float
    rigid_rotation: float
    eigenvalues: np.ndarray
    amplitudes: np.ndarray
    rcond: float

    @property
    def n_terms(self) -> int:
        return int(self.eigenvalues.size)


def resolution_limit(n_terms: int) -> tuple[float, float]:
    """Range of stick radii (b_min, b_max) resolved by ``n_terms`` eigenfunctions.

    Outside it the stick disc or the slip annulus is narrower than
    ``RESOLUTION_WAVELENGTHS / lam_N`` and the solution warns.
    """
    width = RESOLUTION_WAVELENGTHS / bessel_j2_zeros(n_terms)[-1]
    return width, 1.0 - width


def terms_to_resolve(width: float) -> int:
    """Smallest N whose highest term fits ``RESOLUTION_WAVELENGTHS`` wavelengths into ``width`` (0 < width <= 1).

    lam_N >= RESOLUTION_WAVELENGTHS / width with the zeros of J2, lam_N ~ pi (N + 3/4).  A width below the smallest
    normal double counts as that (the estimate would overflow; the N is astronomically beyond any solve either way).
    """
    width = max(float(width), sys.float_info.min)
    n = max(1, math.ceil(RESOLUTION_WAVELENGTHS / (math.pi * width) - 0.75))
    if n > 10 * MAX_SERIES_TERMS:  # far beyond what can be solved: the estimate says enough
        return n
    while bessel_j2_zeros(n)[-1] < RESOLUTION_WAVELENGTHS / width:
        n += 1
    return n


def minimum_inverse_terms() -> int:
    """Smallest N for which some stick radius is resolved (stick disc and annulus both >= 10 / lam_N)."""
    return terms_to_resolve(0.5)


def complete_border(lam: np.ndarray, b: float):
    """The border of the complete system around the published one: (column, row, corner, rhs_torque, rhs_constant)
    with the matrix [[A, column], [row, corner]] and the right-hand sides' last entries (equation (iv), unknown
    omega)."""
    lam = np.asarray(lam, dtype=float)
    stick = integrals.stick_moment(lam, b)
    return stick, (1.0 - lam) * stick, b**4 / 4.0, (1.0 - b**4) / 4.0, -(1.0 - b**3) / 3.0


def assemble(method: str, lam: np.ndarray, b: float, order: str = "C"):
    """Matrix and the two right-hand sides (torque part, constant part) of (iii)-(iv).

    Returns ``(matrix, rhs_torque, rhs_constant)`` so that the system reads
    ``matrix @ x = T* rhs_torque + rhs_constant`` with x = (c_1..c_N[, omega]).  ``order``: the matrix's
    memory layout ("F": the one LAPACK factors without a copy); the entries do not depend on it.
    """
    lam = np.asarray(lam, dtype=float)
    n = lam.size
    # the complete system borders the published one: its leading block is written in place
    full = np.empty((n, n) if method == "published" else (n + 1, n + 1), order=order)
    matrix = integrals.lommel_matrix(lam, b, out=full if method == "published" else full[:n, :n])
    matrix *= (lam - 1.0)[None, :]
    matrix[np.diag_indices_from(matrix)] += integrals.dini_norm(lam)
    rhs_torque = integrals.load_integral_linear(lam, b)
    rhs_constant = -integrals.load_integral_constant(lam, b)
    if method == "published":
        return matrix, rhs_torque, rhs_constant
    full[:n, n], full[n, :n], full[n, n], torque_last, constant_last = complete_border(lam, b)
    return full, np.append(rhs_torque, torque_last), np.append(rhs_constant, constant_last)


def _gross_slip(method: str, lam: np.ndarray) -> SeriesSolution:
    """b = 0: traction 1 everywhere; (iii) is diagonal, c_m lam_m h_m = B_m."""
    load = integrals.load_vector(lam, 0.0, GROSS_SLIP_TORQUE)
    amplitudes = load / (lam * integrals.dini_norm(lam))
    omega = math.nan if method == "published" else math.inf
    return SeriesSolution(method, 0.0, GROSS_SLIP_TORQUE, omega, lam, amplitudes, 1.0)


def closure_torque(closure: str, method: str, lam: np.ndarray, b: float, x_torque: np.ndarray,
                   x_constant: np.ndarray) -> float:
    """T* from the closure (v), (vi) or (vii), given the solution c = x_constant + T* x_torque of (iii)-(iv).

    ``x_torque``, ``x_constant``: solutions for the two right-hand sides of ``assemble`` (the
    last entry is omega for ``complete``).  Each closure is linear in T*.
    """
    n = lam.size
    if closure == "traction":
        weight = lam * special.j1(lam * b)
        # (v): T* b - w.(c_K + T* c_L) = 1
        return (1.0 + weight @ x_constant[:n]) / (b - weight @ x_torque[:n])
    if closure == "displacement":
        # (vi): omega b + J1(lam b).c = 0, omega = 0 for the printed system
        weight = special.j1(lam * b)
        at_b = [weight @ x_torque[:n], weight @ x_constant[:n]]
        if method == "complete":
            at_b = [at_b[0] + b * x_torque[n], at_b[1] + b * x_constant[n]]
        return -at_b[1] / at_b[0]
    if closure == "torque":
        # (vii): T* (1 - b^4 + 4 w.c_L) = (4/3)(1 - b^3) - 4 w.c_K, w_n = lam_n S_n
        weight = lam * integrals.stick_moment(lam, b)
        return (((4.0 / 3.0) * (1.0 - b**3) - 4.0 * weight @ x_constant[:n])
                / (1.0 - b**4 + 4.0 * weight @ x_torque[:n]))
    raise ValueError(f"closure must be one of {CLOSURES}, got {closure!r}")


def solve_series(stick_radius: float, method: str = "complete", n_terms: int = 145,
                 closure: str = "traction") -> SeriesSolution:
    """Solve eq. (38) (``published``) or (iii)-(iv) (``complete``) for a stick radius.

    Parameters
    ----------
    stick_radius : float
        b/a in [0, 1].  b = 1 is the slip onset (T* = 1), b = 0 spinning (T* = 4/3).
    method : {"published", "complete"}
    n_terms : int
        Number N of eigenfunctions J1(lam_n r) (the paper used 145).
    closure : {"traction", "displacement", "torque"}
        How T* is fixed: traction continuity (v) at r = b (default), the stick condition
        (vi) at r = b, or the torque of the traction actually present (vii).  The
        exact solution satisfies all three; the truncated systems do not.

    Returns
    -------
    SeriesSolution
        For positive torque; the caller mirrors it for negative torque.

    Warns
    -----
    ResolutionWarning
        If the stick disc or slip annulus is narrower than 10 / lam_N.
    IllConditioningWarning
        If the reciprocal condition number of the equilibrated system is below 1e-13.
    UnphysicalResultWarning
        If the published formulation returns T* > 4/3 (physically impossible).

    Raises
    ------
    ValueError
        Naming stick_radius, if its system or T* leaves the double range (b near the bottom of the
        double range, e.g. 1e-300 for the complete form, 5e-324 for the published one).
    """
    if closure not in CLOSURES:
        raise ValueError(f"closure must be one of {CLOSURES}, got {closure!r}")
    b = float(stick_radius)
    lam = bessel_j2_zeros(n_terms)
    if b == 0.0:
        return _gross_slip(method, lam)
    if b == 1.0:  # slip onset: no slip annulus, the bilateral field is exact
        omega = math.nan if method == "published" else 0.0
        return SeriesSolution(method, 1.0, 1.0, omega, lam, np.zeros(lam.size), 1.0)
    b_min, b_max = resolution_limit(n_terms)
    if b < b_min or b > b_max:
        needed = terms_to_resolve(min(b, 1.0 - b))
        warnings.warn(
            f"stick_radius={b:.6g} is not resolved by n_terms={n_terms}: the "
            f"{'stick disc' if b < 0.5 else 'slip annulus'} is narrower than "
            f"{RESOLUTION_WAVELENGTHS:g} wavelengths of the highest term; T* and the "
            f"fields near r = b may be off in their leading digits (use n_terms >= {float(needed):.6g}).",
            ResolutionWarning,
            stacklevel=3,
        )
    matrix, rhs_torque, rhs_constant = assemble(method, lam, b)
    too_small = (f"stick_radius={b:.6g} is too small for the {method} weak form at n_terms={n_terms}: its system "
                 f"leaves the double range")
    try:  # a scaling that overflows is refused by the finiteness check of equilibrated_solve
        with np.errstate(divide="ignore", over="ignore", invalid="ignore"):
            x, rcond = equilibrated_solve(matrix, np.column_stack([rhs_torque, rhs_constant]))
    except ValueError as error:  # entries at the bottom of the double range: the scaling overflows
        raise ValueError(f"{too_small} ({error}); the default method solves any stick_radius in [0, 1]") from error
    if rcond < RCOND_WARN:
        warnings.warn(
            f"the {method} system for stick_radius={b:.6g}, n_terms={n_terms} is "
            f"ill-conditioned (reciprocal condition number {rcond:.2e}); expect to lose "
            f"about {-math.log10(rcond):.0f} digits",
            IllConditioningWarning,
            stacklevel=3,
        )
    x_torque, x_constant = x[:, 0], x[:, 1]
    n = lam.size
    with np.errstate(divide="ignore", over="ignore", invalid="ignore"):  # checked on the next line
        torque = closure_torque(closure, method, lam, b, x_torque, x_constant)
    if not math.isfinite(torque):
        raise ValueError(f"{too_small} (T* = {torque}); the default method solves any stick_radius in [0, 1]")
    coeffs = x_constant + torque * x_torque
    omega = float(coeffs[n]) if method == "complete" else math.nan
    if not 1.0 <= torque <= GROSS_SLIP_TORQUE:
        cause = ("a consequence of the missing rigid-rotation mode (see the errata)" if method == "published"
                 else f"n_terms={n_terms} does not resolve stick_radius={b:.6g}")
        warnings.warn(
            f"the {method} formulation gives T* = {torque:.6g} at stick_radius={b:.6g}, outside [1, 4/3] "
            f"(partial slip): physically impossible; {cause}",
            UnphysicalResultWarning,
            stacklevel=3,
        )
    return SeriesSolution(method, b, float(torque), omega, lam, coeffs[:n].copy(), rcond)
