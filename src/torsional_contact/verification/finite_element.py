r"""Axisymmetric finite-element solution of the partial-slip torsion problem.

An independent check of the series and Abel-Fredholm solvers: it shares no code with them
(no Dini series, no kernels, no Abel transform), only the boundary-value problem
(eqs. 7-9 and the far field), discretised with Lagrange triangles of scikit-fem.

Units: r, z in a; tractions and stresses in f p0; u_theta in f p0 a / mu; the local
rotation w = u_theta / r and omega in f p0 / mu; T* = 2T/(f F a) (eq. 32).

Boundary-value problem
----------------------
Torsion u_theta(r, z) of the upper cylinder 0 <= r <= 1, z >= 0.  With the local rotation
w = u_theta / r, sigma_zt = r dw/dz and sigma_rt = du/dr - u/r = r dw/dr, and equilibrium
d(r^2 sigma_rt)/dr + r^2 d(sigma_zt)/dz = 0 becomes the weighted Laplace equation

    div(r^3 grad w) = 0,   0 < r < 1,  0 < z < L,   grad = (d/dr, d/dz),           (E1)

regular on the axis (the weight vanishes there: no condition is set).  Boundary
conditions: sigma_rt(1, z) = 0 (eq. 9, natural); w(r, 0) = 0 on the stick disc r < b
(eq. 7); sigma_zt(r, 0) = 1 on the slip annulus b < r < 1 (eq. 8); at the truncation z = L
the traction T* r of the far field u_theta -> T* r z + omega r.  The corrective field
decays like exp(-lambda z), lambda = 5.1356 (eq. 20); the traction condition at z = L
reflects it, which changes the interface by O(exp(-2 lambda L)) (4e-14 for L = 3).

Weak form: find w with w(r, 0) = g(r) on r < b such that, for every v vanishing there,

    int_0^L int_0^1 r^3 grad w . grad v dr dz
        = int_0^1 r^2 t_L(r) v(r, L) dr - int_b^1 r^2 t_0(r) v(r, 0) dr,           (E2)

with the slip traction t_0 = 1, the end traction t_L = T* r and the stick rotation g = 0
for the contact problem (other data serve the tests).  (E2) is linear in T*:
w = w_0 + T* w_1, w_0 loaded by t_0 = 1 alone and w_1 by t_L = r alone.  The uniform
twist z (exact in the element space) is split off, w_1 = z + v_1 with v_1 loaded by
t_0 = -r alone: the unknowns w_0, v_1 stay O(0.1).  Solved for directly, w_1 grows to L
at the top, and the rounding of the assembled stiffness entries (relative 1e-16, amplified
by the condition number of this mostly-Neumann problem) moved T* and omega by ~1e-10;
with the split they are reproducible to ~1e-13.  One sparse LU factorisation serves both
loads.

Rigid rotation.  No corrective mode J_1(lambda_n r) exp(-lambda_n z) carries torque,
int_0^1 J_1(lambda r) r^2 dr = J_2(lambda) / lambda = 0 (eq. 19), so at every height
4 int_0^1 r^3 w dr = T* z + omega, exactly also for the truncated problem:

    omega = 4 int_0^1 r^3 w(r, L) dr - T* L = 4 int_0^1 r^3 (w_0 + T* v_1)(r, L) dr.   (E3)

Regularity fixes T*.  With r - b = rho cos(theta), z = rho sin(theta) (theta = 0 on the
slip annulus, pi on the stick disc), the solution near the stick/slip front is

    w = C rho^{1/2} cos(theta / 2) + O(rho),                                        (E4)

so the slip is s = 2 b C (r - b)^{1/2} + ..., the stick-side traction is
b C / (2 (b - r)^{1/2}) + ... and K_III = lim (2 pi (b - r))^{1/2} sigma_zt = b C (pi/2)^{1/2}.
C = C_0 + T* C_1 and the regular solution (traction rising continuously to 1, slip
~ (r - b)^{3/2}) has C = 0, so T* = -C_0 / C_1.  C is extracted by an interaction
integral (reciprocal theorem) with the dual singular solution

    v = r^{-3/2} rho^{-1/2} cos(theta / 2),
    div(r^3 grad v) = -(3/4) r^{-1/2} rho^{-1/2} cos(theta / 2),

which vanishes on the stick disc and has dv/dz = 0 on the slip annulus.  For a cut-off
q(max(|r - b|, z)) equal to 1 near the front and 0 beyond a distance <= d, Green's
identity on the domain minus a half-disc rho < eps (eps -> 0) gives

    J(w) = int r^3 (v grad w - w grad v) . grad q dr dz - int q w div(r^3 grad v) dr dz
         = - int_b^1 q r^2 v t_0 dr - (pi/2) b^{3/2} C.                              (E5)

Every integrand is bounded (grad q vanishes near the front; w ~ rho^{1/2} meets
rho^{-1/2}), no derivative of the finite-element solution is taken near the front, and
J is a domain functional, which converges faster than point values of the slip or the
traction (fitting (r - b)^{1/2} to the slip would rely on exactly the values the mesh
resolves worst).  q is a cubic smooth step between two of the square rings
max(|r - b|, z) = const that are lines of the mesh, so it is polynomial inside every
element and Gauss quadrature loses nothing.  The exact J does not depend on q: two
cut-offs give two T*, whose difference measures the discretisation error of the
regularity condition.

Mesh.  A tensor grid with 2n elements across the front box |r - b| <= d, z <= d
(d = min(b, 1 - b) / 2) and n across the corner box 1 - d <= r, z <= d, whose nodes are
moved radially, p -> p (|p|_inf / d)^(gamma - 1) about the front (gamma =
``front_exponent``) and the corner (``corner_exponent``): algebraic grading with element
aspect ratios bounded by gamma.  Outside the boxes the sizes grow like GROWTH x distance /
n.  Each grid cell is split along the diagonal that points away from the front (the
corner), so the square rings about them are mesh lines.  ``level`` n refines everything.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.polynomial import legendre
from scipy import special
from scipy.sparse.linalg import splu

try:
    from skfem import (
        Basis,
        BilinearForm,
        ElementTriP1,
        ElementTriP2,
        ElementTriP3,
        ElementTriP4,
        FacetBasis,
        Functional,
        LinearForm,
        MeshTri,
    )
    from skfem.helpers import dot, grad
except ModuleNotFoundError as _missing:  # without the fem extra: say which package installs it, not a bare import error
    if (_missing.name or "").split(".")[0] != "skfem":
        raise
    from ..extras import MissingExtraError, missing_message

    raise MissingExtraError(missing_message("the finite-element check (verification.finite_element)", ["skfem"],
                                            "fem")) from None

from ..diagnostics import AccuracyWarning, TruncationWarning

__all__ = ["ELEMENTS", "GradedMesh", "Load", "RotationField", "FiniteElementSolution", "graded_mesh",
           "solve_rotation_fields", "front_coefficient", "cutoff_rings", "solve_finite_element"]

#: Lagrange triangles by polynomial degree.
ELEMENTS = {1: ElementTriP1, 2: ElementTriP2, 3: ElementTriP3, 4: ElementTriP4}
#: lambda_{2,1}, the slowest decay rate of the corrective field (eqs. 19-20).
FIRST_EIGENVALUE = float(special.jn_zeros(2, 1)[0])
#: exp(-2 lambda L) above this raises a TruncationWarning (L < 2.69).
TRUNCATION_TOLERANCE = 1e-12
#: Relative difference of T* between the two cut-offs of (E5) above this: AccuracyWarning.
REGULARITY_TOLERANCE = 1e-5
#: Outside the graded boxes: element size = GROWTH x (distance from the box) / level.
GROWTH = 2.0
_SLIP_NODES = 40  # Gauss-Legendre nodes per piece of the slip-annulus term of (E5)


def _check_stick_radius(stick_radius) -> float:
    b = float(stick_radius)
    if not 0.0 < b < 1.0:  # also rejects nan
        raise ValueError(f"stick_radius must lie in (0, 1) (a stick/slip front), got {stick_radius!r}")
    return b


def _geometric(start: float, stop: float, level: int) -> np.ndarray:
    """Nodes on [start, stop] (0 < start < stop), sizes ~ GROWTH x / level (geometric)."""
    count = max(1, math.ceil(math.log(stop / start) / math.log1p(GROWTH / level)))
    nodes = start * (stop / start) ** np.linspace(0.0, 1.0, count + 1)
    nodes[0], nodes[-1] = start, stop
    return nodes


def _chebyshev(start: float, stop: float, count: int) -> np.ndarray:
    """``count`` elements on [start, stop], finer at both ends (Chebyshev-Lobatto points)."""
    nodes = start + (stop - start) * 0.5 * (1.0 - np.cos(np.pi * np.linspace(0.0, 1.0, count + 1)))
    nodes[0], nodes[-1] = start, stop
    return nodes


def _radial_map(x, z, exponent):
    """Grade a uniform grid of the unit half-square toward its centre: p -> p |p|_inf^(exponent - 1)."""
    scale = np.maximum(np.abs(x), z) ** (exponent - 1.0)
    return x * scale, z * scale


@dataclass(frozen=True)
class GradedMesh:
    """Triangle mesh of (0, 1) x (0, L) graded toward the front (b, 0) and the corner (1, 0).

    ``front_rings`` d (k/n)^gamma, k = 0..n, are the half-widths of the square rings
    max(|r - b|, z) = const that are lines of the mesh; ``front_size`` is d.
    """

    mesh: MeshTri
    stick_radius: float
    truncation: float
    front_size: float
    front_rings: np.ndarray
    level: int


def graded_mesh(stick_radius: float, level: int, truncation: float = 3.0,
                front_exponent: float = 3.0, corner_exponent: float = 2.0) -> GradedMesh:
    """Mesh for stick radius b at refinement ``level`` n (module docstring, "Mesh").

    r-grid: [0, b - d] geometric toward b - d, [b - d, b + d] 2n uniform, [b + d, 1 - d]
    n Chebyshev (empty for b >= 1/2), [1 - d, 1] n uniform; z-grid: [0, d] n uniform,
    [d, L] geometric; then the radial maps of the two boxes.
    """
    b = _check_stick_radius(stick_radius)
    n = int(level)
    if n < 3 or n != level:
        raise ValueError(f"level must be an integer >= 3, got {level!r}")
    length = float(truncation)
    d = 0.5 * min(b, 1.0 - b)
    if not length > 2.0 * d:
        raise ValueError(f"truncation must be a number > {2 * d:g} (twice the front box), got {truncation!r}")
    if not (front_exponent >= 1.0 and corner_exponent >= 1.0):
        raise ValueError(f"grading exponents must be >= 1, got {front_exponent!r}, {corner_exponent!r}")
    r_parts = [b - _geometric(d, b, n)[::-1], b + np.linspace(-d, d, 2 * n + 1)]
    if b + d < 1.0 - d:
        r_parts.append(_chebyshev(b + d, 1.0 - d, n))
    r_parts.append(np.linspace(1.0 - d, 1.0, n + 1))
    r_nodes = np.concatenate([r_parts[0]] + [part[1:] for part in r_parts[1:]])
    r_nodes[0] = 0.0
    z_nodes = np.concatenate([np.linspace(0.0, d, n + 1), _geometric(d, length, n)[1:]])
    r, z = (grid.ravel() for grid in np.meshgrid(r_nodes, z_nodes, indexing="ij"))
    front = (np.abs(r - b) <= d) & (z <= d)
    x, y = _radial_map((r[front] - b) / d, z[front] / d, front_exponent)
    r[front], z[front] = b + d * x, d * y
    corner = (r >= 1.0 - d) & (z <= d)
    x, y = _radial_map((r[corner] - 1.0) / d, z[corner] / d, corner_exponent)
    r[corner], z[corner] = 1.0 + d * x, d * y
    nr, nz = r_nodes.size, z_nodes.size
    i, j = (a.ravel() for a in np.meshgrid(np.arange(nr - 1), np.arange(nz - 1), indexing="ij"))
    n00, n10, n01, n11 = i * nz + j, (i + 1) * nz + j, i * nz + j + 1, (i + 1) * nz + j + 1
    centre = 0.5 * (r_nodes[i] + r_nodes[i + 1])
    rising = (centre > b) & (centre < 1.0 - d)  # split along (1, 1), else along (-1, 1)
    triangles = np.concatenate([
        np.where(rising, [n00, n10, n11], [n00, n10, n01]),
        np.where(rising, [n00, n11, n01], [n10, n11, n01]),
    ], axis=1)
    rings = d * np.linspace(0.0, 1.0, n + 1) ** front_exponent
    rings[-1] = d
    return GradedMesh(MeshTri(np.vstack([r, z]), triangles), b, length, d, rings, n)


@dataclass(frozen=True)
class Load:
    """Data of (E2) as numpy-vectorised functions of r; ``None`` means zero.

    stick_rotation: g(r) = w(r, 0) on r < b (f p0 / mu); slip_traction: t_0(r) =
    sigma_zt(r, 0) on r > b; end_traction: t_L(r) = sigma_zt(r, L) (f p0).
    """

    stick_rotation: Callable | None = None
    slip_traction: Callable | None = None
    end_traction: Callable | None = None


@dataclass(frozen=True)
class RotationField:
    """A finite-element rotation field w = u_theta / r (coefficients on ``basis``)."""

    graded: GradedMesh
    basis: Basis
    coefficients: np.ndarray

    def evaluate(self, r, z):
        """(w, dw/dr, dw/dz) at points (r, z) of the meshed domain (broadcast)."""
        r, z = np.broadcast_arrays(np.asarray(r, dtype=float), np.asarray(z, dtype=float))
        points = np.vstack([r.ravel(), z.ravel()])
        inside = (points[0] >= 0.0) & (points[0] <= 1.0) & (points[1] >= 0.0) & (points[1] <= self.graded.truncation)
        if not np.all(inside):  # also rejects nan
            raise ValueError(f"points (r, z) must lie in 0 <= r <= 1, 0 <= z <= {self.graded.truncation:g}")
        basis = self.basis
        cells = basis.mesh.element_finder(mapping=basis.mapping)(*points)
        reference = basis.mapping.invF(points[:, :, None], tind=cells)
        value = np.zeros(points.shape[1])
        gradient = np.zeros((2, points.shape[1]))
        for k in range(basis.Nbfun):
            phi = basis.elem.gbasis(basis.mapping, reference, k, tind=cells)[0]
            c = self.coefficients[basis.element_dofs[k, cells]]
            value += c * np.asarray(phi)[:, 0]
            gradient += c * phi.grad[:, :, 0]
        return value.reshape(r.shape), gradient[0].reshape(r.shape), gradient[1].reshape(r.shape)

    def _facet_integral(self, facets, integrand) -> float:
        facet_basis = FacetBasis(self.basis.mesh, self.basis.elem, facets=facets,
                                 intorder=2 * self.basis.elem.maxdeg + 4)
        form = Functional(lambda w: integrand(w.x[0], w["w"]))
        return float(form.assemble(facet_basis, w=facet_basis.interpolate(self.coefficients)))

    def end_moment(self) -> float:
        """4 int_0^1 r^3 w(r, L) dr (= T* L + omega for the contact problem, (E3))."""
        top = self.basis.mesh.facets_satisfying(lambda x: x[1] == self.graded.truncation, boundaries_only=True)
        return 4.0 * self._facet_integral(top, lambda r, w: r**3 * w)

    def stick_torque(self) -> float:
        """4 int_0^b r^2 sigma_zt(r, 0) dr from the gradient of w (the stick disc's share of T*)."""
        b = self.graded.stick_radius
        stick = self.basis.mesh.facets_satisfying(lambda x: (x[1] == 0.0) & (x[0] < b), boundaries_only=True)
        return 4.0 * self._facet_integral(stick, lambda r, w: r**3 * w.grad[1])


def _flux(basis, facets, traction) -> np.ndarray:
    """Load vector int r^2 t(r) v dr over horizontal boundary ``facets``."""
    facet_basis = FacetBasis(basis.mesh, basis.elem, facets=facets, intorder=2 * basis.elem.maxdeg + 4)
    return LinearForm(lambda v, w: w.x[0] ** 2 * traction(w.x[0]) * v).assemble(facet_basis)


def solve_rotation_fields(graded: GradedMesh, degree: int, loads) -> list[RotationField]:
    """Solve (E2) on ``graded`` with Lagrange triangles of ``degree`` for each ``Load``.

    The stiffness int r^3 grad u . grad v is integrated exactly (Gauss order 2 degree + 3)
    and factorised once (sparse LU of the free degrees of freedom); the Dirichlet data
    g are interpolated at the nodes of the stick disc.  Returns one field per load.
    """
    if degree not in ELEMENTS:
        raise ValueError(f"degree must be one of {sorted(ELEMENTS)}, got {degree!r}")
    mesh, b = graded.mesh, graded.stick_radius
    basis = Basis(mesh, ELEMENTS[degree](), intorder=2 * degree + 3)
    weight = basis.global_coordinates().value[0] ** 3  # r^3 at the quadrature points, once for all basis pairs
    stiffness = BilinearForm(lambda u, v, w: w.weight * dot(grad(u), grad(v))).assemble(basis, weight=weight).tocsr()
    stick = mesh.facets_satisfying(lambda x: (x[1] == 0.0) & (x[0] < b), boundaries_only=True)
    slip = mesh.facets_satisfying(lambda x: (x[1] == 0.0) & (x[0] > b), boundaries_only=True)
    top = mesh.facets_satisfying(lambda x: x[1] == graded.truncation, boundaries_only=True)
    fixed = basis.get_dofs(stick).all()
    free = np.setdiff1d(np.arange(basis.N), fixed)
    # symmetric positive definite (Dirichlet data on the stick disc): a fill-reducing ordering of A + A^T and no
    # pivoting, as for a Cholesky factor; a third of the time of SuperLU's default (COLAMD with partial pivoting)
    factor = splu(stiffness[free][:, free].tocsc(), permc_spec="MMD_AT_PLUS_A", diag_pivot_thresh=0.0,
                  options={"SymmetricMode": True})
    coupling = stiffness[free][:, fixed]
    fields = []
    for load in loads:
        rhs = np.zeros(basis.N)
        if load.end_traction is not None:
            rhs += _flux(basis, top, load.end_traction)
        if load.slip_traction is not None:
            rhs -= _flux(basis, slip, load.slip_traction)
        w = np.zeros(basis.N)
        if load.stick_rotation is not None:
            w[fixed] = load.stick_rotation(basis.doflocs[0, fixed])
        w[free] = factor.solve(rhs[free] - coupling @ w[fixed])
        fields.append(RotationField(graded, basis, w))
    return fields


def _smooth_step(s, inner, outer):
    """Cut-off profile: 1 for s <= inner, cubic C^1 step to 0 at outer; and its derivative."""
    t = np.clip((s - inner) / (outer - inner), 0.0, 1.0)
    return 1.0 - t * t * (3.0 - 2.0 * t), -6.0 * t * (1.0 - t) / (outer - inner)


def _dual_solution(r, z, b):
    """v, dv/dr, dv/dz and div(r^3 grad v) of the dual singular solution of (E5)."""
    zeta = (r - b) + 1j * z  # arg in [0, pi]: the principal branch
    phi = np.real(zeta**-0.5)  # rho^{-1/2} cos(theta/2), harmonic: f = zeta^{-1/2}
    derivative = -0.5 * zeta**-1.5  # f' = phi_r - i phi_z
    weight = r**-1.5
    v = weight * phi
    v_r = -1.5 * r**-2.5 * phi + weight * np.real(derivative)
    v_z = -weight * np.imag(derivative)
    return v, v_r, v_z, -0.75 * r**-0.5 * phi


def front_coefficient(field: RotationField, slip_traction: Callable | None, inner: float, outer: float) -> float:
    """C of (E4) from the interaction integral (E5).

    Parameters
    ----------
    field : RotationField
        A solution of (E2) with zero stick rotation.
    slip_traction : callable or None
        The slip traction t_0(r) the field was loaded with (None: zero).
    inner, outer : float
        Break points of the cut-off q, entries of ``field.graded.front_rings`` (mesh lines),
        0 < inner < outer.

    Returns
    -------
    float
        C in f p0 / mu per a^{1/2}: the slip starts as 2 b C (r - b)^{1/2}.
    """
    graded = field.graded
    b = graded.stick_radius
    if not (inner in graded.front_rings and outer in graded.front_rings and 0.0 < inner < outer):
        raise ValueError(f"inner < outer must be positive entries of front_rings, got {inner!r}, {outer!r}")
    mesh = graded.mesh
    mid = mesh.p[:, mesh.t].mean(axis=1)
    box = np.nonzero(np.maximum(np.abs(mid[0] - b), mid[1]) < outer)[0]
    basis = Basis(mesh, field.basis.elem, elements=box, intorder=2 * field.basis.elem.maxdeg + 6)
    w = basis.interpolate(field.coefficients)
    r, z = np.asarray(basis.global_coordinates())
    radial = np.abs(r - b) > z  # q depends on |r - b| there, on z elsewhere
    q, dq = _smooth_step(np.where(radial, np.abs(r - b), z), inner, outer)
    v, v_r, v_z, div_v = _dual_solution(r, z, b)
    w_value, (w_r, w_z) = np.asarray(w), w.grad
    flux = r**3 * np.where(radial, (v * w_r - w_value * v_r) * np.sign(r - b), v * w_z - w_value * v_z) * dq
    interaction = float(np.sum((flux - q * w_value * div_v) * basis.dx))
    slip_term = 0.0
    if slip_traction is not None:  # int q r^2 v t_0 dr with r = b + tau^2 (removes (r - b)^{-1/2})
        x, weights = legendre.leggauss(_SLIP_NODES)
        for lo, hi in ((0.0, math.sqrt(inner)), (math.sqrt(inner), math.sqrt(outer))):
            tau = 0.5 * (hi - lo) * (x + 1.0) + lo
            radius = b + tau**2
            q_slip = _smooth_step(tau**2, inner, outer)[0]
            slip_term += 0.5 * (hi - lo) * np.sum(weights * 2.0 * q_slip * np.sqrt(radius) * slip_traction(radius))
    return -2.0 / (math.pi * b**1.5) * (interaction + slip_term)


def cutoff_rings(graded: GradedMesh):
    """Two cut-offs (inner, outer) for (E5): rings nearest (d/2, d) and (d/8, d/2)."""
    rings, d = graded.front_rings, graded.front_size
    n = rings.size - 1
    half = int(np.clip(np.argmin(np.abs(rings - d / 2)), 2, n - 1))
    eighth = int(np.clip(np.argmin(np.abs(rings - d / 8)), 1, half - 1))
    return (rings[half], rings[n]), (rings[eighth], rings[half])


@dataclass(frozen=True)
class FiniteElementSolution:
    """The regular finite-element solution for one stick radius (see module docstring).

    Attributes
    ----------
    stick_radius, torque, rigid_rotation : float
        b, T* (from C = 0 in (E4)) and omega (E3).
    torque_alternative : float
        T* from the second cut-off of (E5); |torque - torque_alternative| estimates the
        discretisation error of the regularity condition.
    front_coefficients : tuple of float
        (C_0, C_1) of w_0 and w_1: C = C_0 + T* C_1 for any torque.
    degree, level, n_dofs : int
        Element degree, mesh level, number of unknowns.
    slip_field, twist_field : RotationField
        w_0 and w_1 of (E2); w = w_0 + T* w_1.
    """

    stick_radius: float
    torque: float
    rigid_rotation: float
    torque_alternative: float
    front_coefficients: tuple
    degree: int
    level: int
    n_dofs: int
    slip_field: RotationField
    twist_field: RotationField

    def field(self, torque: float | None = None) -> RotationField:
        """w = w_0 + T* w_1 for ``torque`` (default: the regular T*)."""
        t = self.torque if torque is None else float(torque)
        return RotationField(self.slip_field.graded, self.slip_field.basis,
                             self.slip_field.coefficients + t * self.twist_field.coefficients)

    @property
    def torque_from_traction(self) -> float:
        """Torque balance: 4 int_0^1 r^2 sigma_zt(r, 0) dr (stick part from the gradient of w)."""
        return self.field().stick_torque() + 4.0 * (1.0 - self.stick_radius**3) / 3.0

    def stress(self, r, z):
        """(sigma_zt, sigma_rt) = (r dw/dz, r dw/dr), in f p0."""
        _, w_r, w_z = self.field().evaluate(r, z)
        r = np.asarray(r, dtype=float)
        return r * w_z, r * w_r

    def displacement(self, r, z):
        """u_theta = r w of the upper cylinder, in f p0 a / mu."""
        return np.asarray(r, dtype=float) * self.field().evaluate(r, z)[0]

    def traction(self, r):
        """sigma_zt(r, 0): 1 on the slip annulus (the data), r dw/dz on the stick disc."""
        r = np.asarray(r, dtype=float)
        return np.where(r > self.stick_radius, 1.0, self.stress(r, np.zeros_like(r))[0])

    def slip(self, r):
        """s(r) = 2 u_theta(r, 0+), in f p0 a / mu."""
        return 2.0 * self.displacement(r, np.zeros_like(np.asarray(r, dtype=float)))


def solve_finite_element(stick_radius: float, level: int = 8, degree: int = 4, truncation: float = 3.0,
                         front_exponent: float = 3.0, corner_exponent: float = 2.0) -> FiniteElementSolution:
    """T*, omega and the fields for stick radius b by the finite-element method.

    Parameters
    ----------
    stick_radius : float
        b in (0, 1).
    level : int
        Refinement level n >= 3 of ``graded_mesh``.
    degree : int
        Lagrange degree 1-4.
    truncation : float
        Height L of the meshed cylinder (a TruncationWarning when exp(-2 lambda L) is
        above ``TRUNCATION_TOLERANCE``).
    front_exponent, corner_exponent : float
        Grading exponents toward the front and the corner.  gamma = 3 resolves the
        (r - b)^{3/2} term of the regular solution at the full rate of P4.

    Returns
    -------
    FiniteElementSolution
        An AccuracyWarning when the two cut-offs of (E5) disagree by more than
        ``REGULARITY_TOLERANCE`` (relative): the mesh does not resolve the front.
    """
    graded = graded_mesh(stick_radius, level, truncation, front_exponent, corner_exponent)
    leak = math.exp(-2.0 * FIRST_EIGENVALUE * graded.truncation)
    if leak > TRUNCATION_TOLERANCE:
        warnings.warn(f"truncation L = {graded.truncation:g} leaves exp(-2 lambda L) = {leak:.1e} of the far field",
                      TruncationWarning, stacklevel=2)
    unit_slip = np.ones_like
    slip_field, twist_correction = solve_rotation_fields(
        graded, degree, [Load(slip_traction=unit_slip), Load(slip_traction=lambda r: -r)])
    basis = slip_field.basis
    twist_field = RotationField(graded, basis, twist_correction.coefficients + basis.doflocs[1])  # z + v_1
    torques, coefficients = [], []
    for inner, outer in cutoff_rings(graded):
        c0 = front_coefficient(slip_field, unit_slip, inner, outer)
        c1 = front_coefficient(twist_field, None, inner, outer)
        torques.append(-c0 / c1)
        coefficients.append((c0, c1))
    torque = torques[0]
    if abs(torques[0] - torques[1]) > REGULARITY_TOLERANCE * abs(torque):
        warnings.warn(f"the regularity condition is resolved to {abs(torques[0] - torques[1]):.1e} in T* only "
                      f"(level {level}, degree {degree}): refine the mesh", AccuracyWarning, stacklevel=2)
    omega = slip_field.end_moment() + torque * twist_correction.end_moment()
    return FiniteElementSolution(graded.stick_radius, float(torque), float(omega), float(torques[1]),
                                 coefficients[0], int(degree), int(level), int(basis.N), slip_field, twist_field)
