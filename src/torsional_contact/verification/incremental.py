r"""Direct weak-form solver of a general mixed interface problem (independent check of ``histories``).

Units (docs/conventions.md): r in a; tractions in f p0; displacements in f p0 a / mu; torque
T* = 2T/(f F a); omega in f p0 / mu.

Problem
-------
Find the interface state of the upper cylinder, written as in ``solvers.weak_form`` as

    u(r, 0) = omega r + sum_n c_n J1(lam_n r),        J2(lam_n) = 0,          (i)
    q(r)    = T* r - sum_n c_n lam_n J1(lam_n r),                             (ii)

(eqs. 17, 22, 26 with c_n = lam_n A~_n) such that

    u(r, 0) = g(r)      0 <= r < c    (displacement prescribed: "no further slip"),
    q(r)    = p(r)      c <  r <= 1   (traction prescribed: the friction limit).

The paper's monotonic problem (7)-(8) is g = 0, p = 1, c = b.  An unloading step of a
torque history is g = the interface displacement remembered from the previous turning
point (the points of 0 <= r < c do not slip during the step) and p = -1 (the friction
limit reversed); this is the problem ``histories`` avoids by superposition, and the
reason this module exists: it solves the incremental problem directly, without the
memory rules.

Weak form
---------
Testing the residual (u - g on (0, c), q - p on (c, 1)) against J1(lam_m r) r and
against r r, exactly as eq. (33) and the ``complete`` form of ``solvers.weak_form``
(iii)-(iv), gives for x = (c_1..c_N, omega)

    c_m h_m + sum_n (lam_n - 1) I_mn c_n + omega S_m = T* L_m + G_m - P_m,
    sum_n (1 - lam_n) S_n c_n + omega c^4/4        = T* (1 - c^4)/4 + G_0 - P_0,

with h_m of eq. (35), I_mn = int_c^1 J1(lam_m r) J1(lam_n r) r dr (eqs. 52-53,
``integrals.lommel_matrix``), S_m = int_0^c r^2 J1(lam_m r) dr, L_m = -S_m, and the
*data integrals*

    G_m = int_0^c g(r) J1(lam_m r) r dr,   G_0 = int_0^c g(r) r^2 dr,
    P_m = int_c^1 p(r) J1(lam_m r) r dr,   P_0 = int_c^1 p(r) r^2 dr,

computed here by composite Gauss-Legendre quadrature (panels narrower than about 20 /
lam_N, split at user breakpoints such as earlier slip fronts, where g has a kink), so
that nothing of the closed forms of eq. (51) is reused.

Regularity
----------
For given c the solution is linear in T*; as in condition (v) of ``solvers.weak_form`` the
torque is fixed by requiring that the stick-side traction reaches the prescribed
traction continuously at r = c:  q(c) = T* c - sum c_n lam_n J1(lam_n c) = p(c).
``solve_mixed_for_torque`` inverts T*(c) for a prescribed torque by Brent's method.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np
from scipy import optimize, special

from ..quadrature import gauss_legendre_panels
from ..solvers.equilibration import equilibrated_solve
from ..special import integrals
from ..special.zeros import bessel_j2_zeros

__all__ = ["MixedSolution", "solve_mixed", "solve_mixed_for_torque"]

#: Largest panel width times lam_N of the composite Gauss-Legendre rule.
_PANEL_WAVES = 20.0


@dataclass(frozen=True)
class MixedSolution:
    """Solution of the mixed problem: u = g on (0, c), q = p on (c, 1).

    Attributes
    ----------
    stick_radius : float
        c, the radius of the displacement-prescribed disc (units a).
    torque : float
        T* fixed by the regularity condition q(c) = p(c).
    rigid_rotation : float
        omega (f p0 / mu).
    eigenvalues, amplitudes : ndarray
        lam_n and c_n of (i)-(ii) (amplitudes in f p0 a / mu).
    rcond : float
        Reciprocal condition number estimate of the equilibrated system.
    """

    stick_radius: float
    torque: float
    rigid_rotation: float
    eigenvalues: np.ndarray
    amplitudes: np.ndarray
    rcond: float

    def displacement(self, r):
        """Interface displacement u_theta(r, 0+) of the upper cylinder, f p0 a / mu, eq. (i)."""
        r = np.asarray(r, dtype=float)
        return self.rigid_rotation * r + special.j1(np.multiply.outer(r, self.eigenvalues)) @ self.amplitudes

    def slip(self, r):
        """Slip s(r) = 2 u_theta(r, 0+), f p0 a / mu."""
        return 2.0 * self.displacement(r)

    def traction(self, r):
        """Interface traction sigma_zt(r, 0) / (f p0), eq. (ii)."""
        r = np.asarray(r, dtype=float)
        lam = self.eigenvalues
        return self.torque * r - special.j1(np.multiply.outer(r, lam)) @ (self.amplitudes * lam)


def _data_integrals(func, lam, lower, upper, breakpoints):
    """(int func J1(lam_m r) r dr for every m, int func r^2 dr) over [lower, upper] by quadrature."""
    nodes, weights = gauss_legendre_panels(lower, upper, _PANEL_WAVES / lam[-1], breakpoints)
    if nodes.size == 0:
        return np.zeros(lam.size), 0.0
    values = np.asarray(func(nodes), dtype=float) * weights
    return special.j1(np.outer(lam, nodes)) @ (values * nodes), float(values @ nodes**2)


def solve_mixed(
    stick_radius: float,
    displacement: Callable[[np.ndarray], np.ndarray],
    traction: Callable[[np.ndarray], np.ndarray],
    *,
    n_terms: int = 145,
    breakpoints: Sequence[float] = (),
) -> MixedSolution:
    """Solve u = g on (0, c), q = p on (c, 1) in the weak form of the module docstring.

    Parameters
    ----------
    stick_radius : float
        c in (0, 1): radius of the disc on which the displacement is prescribed.
    displacement : callable
        g(r), the prescribed interface displacement u_theta(r, 0+) (f p0 a / mu) on (0, c).
    traction : callable
        p(r), the prescribed traction (f p0) on (c, 1); -1 for a reversed friction limit.
    n_terms : int
        Number N of eigenfunctions.
    breakpoints : sequence of float
        Radii where g or p is not smooth (earlier slip fronts); the quadrature splits there.

    Returns
    -------
    MixedSolution
        With T* from the regularity condition q(c) = p(c).
    """
    c = float(stick_radius)
    if not 0.0 < c < 1.0:
        raise ValueError(f"stick_radius must lie in (0, 1), got {stick_radius!r}")
    lam = np.asarray(bessel_j2_zeros(n_terms), dtype=float)
    n = lam.size
    stick = integrals.stick_moment(lam, c)  # S_m
    matrix = np.empty((n + 1, n + 1))
    matrix[:n, :n] = integrals.lommel_matrix(lam, c) * (lam - 1.0)[None, :]
    matrix[np.diag_indices(n)] += integrals.dini_norm(lam)
    matrix[:n, n] = stick
    matrix[n, :n] = (1.0 - lam) * stick
    matrix[n, n] = c**4 / 4.0
    g_m, g_0 = _data_integrals(displacement, lam, 0.0, c, breakpoints)
    p_m, p_0 = _data_integrals(traction, lam, c, 1.0, breakpoints)
    rhs_torque = np.append(-stick, (1.0 - c**4) / 4.0)
    rhs_data = np.append(g_m - p_m, g_0 - p_0)
    x, rcond = equilibrated_solve(matrix, np.column_stack([rhs_torque, rhs_data]))
    weight = lam * special.j1(lam * c)
    p_c = float(np.asarray(traction(np.array([c])), dtype=float)[0])
    torque = (p_c + weight @ x[:n, 1]) / (c - weight @ x[:n, 0])
    coeffs = x[:, 1] + torque * x[:, 0]
    return MixedSolution(c, float(torque), float(coeffs[n]), lam, coeffs[:n].copy(), rcond)


def solve_mixed_for_torque(
    torque: float,
    displacement: Callable[[np.ndarray], np.ndarray],
    traction: Callable[[np.ndarray], np.ndarray],
    *,
    bracket: tuple[float, float],
    n_terms: int = 145,
    breakpoints: Sequence[float] = (),
    xtol: float = 1e-12,
) -> MixedSolution:
    """The c in ``bracket`` with T*(c) = ``torque`` (Brent's method), and its solution.

    Raises
    ------
    ValueError
        If T*(c) - torque does not change sign over the bracket.
    """

    def residual(c):
        return solve_mixed(c, displacement, traction, n_terms=n_terms, breakpoints=breakpoints).torque - torque

    lo, hi = bracket
    f_lo, f_hi = residual(lo), residual(hi)
    if f_lo * f_hi > 0:
        raise ValueError(
            f"torque={torque!r} is not reached for stick radii in [{lo:g}, {hi:g}] "
            f"(T* - torque = {f_lo:.3g} and {f_hi:.3g} at the ends)"
        )
    c = optimize.brentq(residual, lo, hi, xtol=xtol)
    return solve_mixed(c, displacement, traction, n_terms=n_terms, breakpoints=breakpoints)
