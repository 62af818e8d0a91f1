r"""The torque-twist skeleton of a test rig and its inverse: torque as a function of twist.

A rig measures, between two cross-sections and through its own compliance, the twist

    theta = C T + k omega_m(T / T_s),        T_s = f F a / 2,  k = 2 f p0 / mu,

on a monotonic loading from the virgin state (docs/conventions.md: T* = T / T_s, omega in
f p0 / mu, and the twist of the specimen is (f p0 / mu)(T* L / a + 2 omega); its linear part
T L / (mu J) is lumped with the rig's compliance into C).  In normalised form

    x = theta / (C T_s) = X(T*) = T* + kappa omega_m(T*),     kappa = k / (C T_s),

increasing from 0 to infinity as T* goes from 0 to 4/3 (omega_m = 0 in stick, ~ (1/6) ln(1 /
(4/3 - T*)) next to spinning).  ``Skeleton`` inverts it: T*(x) and its slope dT*/dx = 1 / (1 +
kappa omega_m'(T*)), and omega_m(x), for any x >= 0 (odd in x), by cubic Hermite interpolation
in x on nodes where T*, omega_m and omega_m' are exact (the piecewise-Chebyshev curves of
``curves``, by stick radius: T*(b), omega(b) and their derivatives).  The nodes are fixed in b;
only their abscissae x = T* + kappa omega move with kappa, so a new kappa costs one pass over
~250 nodes.

Accuracy: the interpolation error of a cubic Hermite interpolant on a step h is at most
h^4 max|T*''''| / 384; the nodes (12 Chebyshev points per panel of the curves table, whose
panels are geometric in b near spinning) keep it below 1e-10 in T* for 0 <= kappa <= 1e3
(``tests/test_fit.py`` checks it against root finding on the curves themselves).  In stick
(x <= 1) and next to the slip onset (1 - b < 1.7e-6, where kappa omega_m < 3e-18 kappa) T* = x
exactly; beyond the last node (b = 1e-6, 4/3 - T* = 6e-19) T* = 4/3 to rounding.

Every contact model
-------------------
The same inversion serves every model of ``models`` (``Skeleton(kappa, contact)``): its slip
onset and gross-slip torque (``ContactModel.slip_onset_torque``, ``gross_slip_torque``) and its
omega_m(T*) (``ContactModel.monotonic().points``) define X(T*).  A model may give its own nodes
(``skeleton_nodes()``: T*, omega_m, omega_m' from the onset on; the cylinders do, from their curves
as above); otherwise ``model_nodes`` puts them on a grid in T*, uniform below the onset (where a
bonded contact's omega_m is linear), graded geometrically toward the onset and toward spinning
(where omega_m may grow like a logarithm) above it, with omega_m' by central differences of
step ``SLOPE_STEP`` times the node's distance from the nearer end (a relative error about SLOPE_STEP^2 = 1e-6
for a logarithm, plus rounding, below 1e-4 at the last node); the last node lies 1e-8 of the range below
spinning, where T* is the gross-slip torque to that accuracy.
The twist constant of the rig is the model's: k = elastic_bodies f p-bar / G
(``ContactModel.contact_twist``).
"""

from __future__ import annotations

import functools

import numpy as np

__all__ = ["Skeleton", "skeleton_nodes", "skeleton_of", "model_nodes", "cylinder_nodes"]

_NODES_PER_PANEL = 12
#: Extra nodes per unit width in b (the table's panels above b = 0.26 are up to 0.24 wide).
_NODES_PER_UNIT_RADIUS = 600
#: Nodes with 1 - b below this take omega and omega' from the small-slip expansion (S2) of ``asymptotics``
#: (omega = (2/3) delta^3 + (pi/16) delta^4, within 1e-16 there), where the table's omega is rounding noise.
_ONSET_NODES = 1e-3
#: Points from which ``Skeleton`` searches only those at or above the slip onset for their piece (below, the extra
#: gathers cost more than the binary searches they save).
SEARCH_SPLIT = 1024


#: Relative step of the central differences of omega_m (``model_nodes``).
SLOPE_STEP = 1e-3


def cylinder_nodes() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(T*, omega_m, d omega_m / d T*) of the cylinders on their fixed nodes (``Cylinder.skeleton_nodes``)."""
    from ..contact_models.cylinder import CYLINDER

    return CYLINDER.skeleton_nodes()

def skeleton_nodes() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The default model's nodes (``cylinder_nodes``)."""
    return cylinder_nodes()


def _generic_nodes(contact) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(T*, omega_m, omega_m') of a model without nodes of its own, from T* = 0 (module docstring)."""
    onset, gross = float(contact.slip_onset_torque), float(contact.gross_slip_torque)
    monotonic = contact.monotonic()
    below = np.linspace(0.0, onset, 9) if onset > 0 else np.zeros(1)
    span = gross - onset
    fraction = np.unique(np.concatenate([np.linspace(0.0, 1.0, 241), np.geomspace(1e-9, 0.2, 60),
                                         1.0 - np.geomspace(1e-8, 0.2, 80)]))
    t = np.unique(np.concatenate([below, onset + span * fraction[fraction < 1.0]]))
    omega = np.asarray(monotonic.points(t)[1], dtype=float)
    # central differences with a step within the node's distance from the onset and from spinning; one-sided at
    # T* = 0 and at the onset (the bonded side's slope: omega_m is continuous there, its slope may jump)
    scale = np.maximum(np.minimum(np.abs(t - onset), gross - t), 1e-3 * max(onset, 1e-3))
    step = np.minimum(SLOPE_STEP * scale, 0.5 * (gross - t))
    left, right = t - step, t + step
    first = t <= 0.0
    left[first] = t[first]
    if onset > 0:
        at_onset = t == onset
        right[at_onset] = t[at_onset]
    slope = (monotonic.points(right)[1] - monotonic.points(left)[1]) / (right - left)
    return t, omega, np.asarray(slope, dtype=float)


@functools.lru_cache(maxsize=16)
def model_nodes(contact=None) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """(T*, omega_m, omega_m', steps of T*) on the nodes of ``contact`` (a ``ContactModel``; None: the default), the
    node T* = 0 first (module docstring)."""
    from .. import models

    contact = models.get(contact)
    own = getattr(contact, "skeleton_nodes", None)
    if own is not None:
        t, omega, slope = own()
        if t[0] > 0:  # below the onset the contact sticks (omega_m = 0) or is bonded (omega_m linear in T*)
            origin_slope = float(slope[0]) if omega[0] != 0 else 0.0
            t, omega, slope = (np.concatenate([[0.0], t]), np.concatenate([[0.0], omega]),
                               np.concatenate([[origin_slope], slope]))
    else:
        t, omega, slope = _generic_nodes(contact)
    return t, omega, slope, np.diff(t)


def _padded_nodes() -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The default model's ``model_nodes``."""
    return model_nodes(None)


@functools.lru_cache(maxsize=16)
def skeleton_of(kappa: float, contact=None) -> Skeleton:
    """``Skeleton(kappa, contact)``, the same object for the last few kappa asked for (a fit's starting grid and its
    constrained fits revisit them)."""
    return Skeleton(kappa, contact)


class Skeleton:
    """T*(x), dT*/dx and omega_m(x) of the inverted skeleton x = T* + kappa omega_m(T*) (module docstring).

    Parameters
    ----------
    kappa : float
        k / (C T_s) >= 0: twist of the contact per unit omega over the rig's linear twist per unit T*.
    contact : ContactModel or str, optional
        The contact model (``models.get``; default the cylinders).
    """

    def __init__(self, kappa: float, contact=None):
        if not kappa >= 0.0:
            raise ValueError(f"kappa must be >= 0, got {kappa!r}")
        self.kappa = float(kappa)
        # the nodes with the node at x = 0 (T* = 0) in front: for the cylinders the cubic on [0, 1] is T* = x exactly
        # (stick)
        t, omega, slope, t_steps = model_nodes(contact)
        x = t + self.kappa * omega
        x[0] = 0.0
        h = x[1:] - x[:-1]  # np.diff(x)
        if not (h[1:] > 0).all():  # keep strictly increasing abscissae (every node but where x rounds flat)
            keep = np.concatenate([[True, True], np.diff(np.maximum.accumulate(x[1:])) > 0])
            t, omega, slope, x = t[keep], omega[keep], slope[keep], x[keep]
            h, t_steps = np.diff(x), np.diff(t)
        denominator = 1.0 + self.kappa * slope  # 1 at x = 0
        self._x = x
        self._t = t
        self._omega = omega
        self._t_slope = 1.0 / denominator
        self._omega_slope = slope / denominator
        self._h = h
        # each cubic in the power basis of dx = x - x_j: value + dx (c1 + dx (c2 + dx c3)), the last node's own
        # (constant) piece appended for the points beyond it
        self._t_coefficients = self._power_basis(self._t, self._t_slope, t_steps)
        self._omega_table = None  # omega_m's cubics, formed on the first call with ``rotation``
        # one row per quantity, one column per piece: the left node x_j, c0 .. c3 of T* and 2 c2 (exact), so that one
        # gather fetches everything a point needs; a point's piece is the number of inner nodes x_1 .. x_{n-2} at or
        # below |x| (the last piece continues beyond the last node)
        self._table = np.array([self._x[:-1], *self._t_coefficients, 2.0 * self._t_coefficients[2]])
        self._right = self._x[1:]  # the inner nodes x_1 .. x_{n-2} and the last one
        self._pieces = self._table.shape[1]
        self._last = float(self._x[-1])

    def _power_basis(self, value, slope, steps=None):
        """(c0, c1, c2, c3) of the cubic Hermite pieces of ``value`` with ``slope`` at the nodes (``steps``: the
        differences of ``value`` if known)."""
        h = self._h
        secant = (value[1:] - value[:-1] if steps is None else steps) / h  # np.diff(value) if not known
        c2 = (3.0 * secant - 2.0 * slope[:-1] - slope[1:]) / h
        c3 = (slope[:-1] + slope[1:] - 2.0 * secant) / h**2
        return (value[:-1], slope[:-1], c2, c3)

    def _nodes_below(self, a):
        """The number of nodes x_1 .. x_{n-1} at or below each of ``a`` (``searchsorted`` on the right; NaN: all).

        Below the slip onset (x_1 = 1, stick) it is 0 without a search: on a large array (a foot points' grid, most
        of it in stick on a partial-slip loop) only the other points are searched, the same numbers for fewer
        binary searches.
        """
        if a.size < SEARCH_SPLIT:
            return self._right.searchsorted(a, side="right")
        flat = a.ravel()
        searched = np.flatnonzero(~(flat < self._right[0]))  # at or above the onset, or NaN
        j = np.zeros(flat.size, dtype=np.intp)
        j[searched] = self._right.searchsorted(flat.take(searched), side="right")
        return j.reshape(a.shape)

    def magnitudes(self, a, curvature: bool = False):
        """(T*, dT*/dx[, d^2T*/dx^2 with ``curvature``], piece, dx, beyond) at |x| = ``a`` >= 0 (or NaN): T* and the
        curvature of the positive half (``__call__`` gives them their sign), each point's piece and its offset dx from
        the piece's left node, and which points lie beyond the last node (None when none does).
        """
        # the number of nodes x_1 .. x_{n-1} at or below |x|: the piece where it is below the pieces' count (then no
        # point lies at or beyond the last node, nor is NaN), else one more than the last piece for a point at or
        # beyond the last node (and NaN)
        j = self._nodes_below(a)
        is_last = int(j.max(initial=0)) > self._pieces - 1
        if is_last:
            last = self._last
            j = np.minimum(j, self._pieces - 1)  # the piece: min(last node index, pieces - 1)
        nodes, c0, c1, c2, c3, c2_twice = self._table.take(j, axis=1)
        dx = np.minimum(a, last) - nodes if is_last else a - nodes
        t = c0 + dx * (c1 + dx * (c2 + dx * c3))
        beyond = None
        if is_last:
            beyond = a > last
            if not beyond.any():
                beyond = None
        # the plateau beyond the last node (for kappa = 0 the last node's own slope is 1); 6 dx c3 = 2 (3 dx c3)
        # exactly (a factor of two), so that the slope and the curvature share that product
        cubic = 3.0 * dx * c3
        slope = c1 + dx * (c2_twice + cubic)
        if beyond is not None:
            slope = np.where(beyond, 0.0, slope)
        if not curvature:
            return t, slope, j, dx, beyond
        second = c2_twice + (cubic + cubic)
        if beyond is not None:
            second = np.where(beyond, 0.0, second)
        return t, slope, second, j, dx, beyond

    def __call__(self, x, rotation: bool = False, curvature: bool = False):
        """(T*, dT*/dx) at x, and omega_m with ``rotation`` or d^2T*/dx^2 with ``curvature``: T*, omega_m and the
        curvature odd in x, the slope even.

        Beyond the last node (4/3 - T* < 1e-18) T* = 4/3, its slope and curvature 0 and omega_m grows as
        x / kappa.  The curvature is that of the cubic pieces (continuous slopes, curvature jumps at the nodes).
        """
        x = np.asarray(x, dtype=float)
        a = np.abs(x)
        sign = np.sign(x)
        if curvature:
            t, slope, second = self.magnitudes(a, True)[:3]
            return sign * t, slope, sign * second
        t, slope, j, dx, beyond = self.magnitudes(a)
        if not rotation:
            return sign * t, slope
        if self._omega_table is None:
            self._omega_table = np.array(self._power_basis(self._omega, self._omega_slope))
        c0, c1, c2, c3 = self._omega_table.take(j, axis=1)
        omega = c0 + dx * (c1 + dx * (c2 + dx * c3))
        if beyond is not None:
            extra = (a - self._last) / self.kappa if self.kappa > 0 else np.where(beyond, np.inf, 0.0)
            omega = np.where(beyond, omega + extra, omega)
        return sign * t, slope, sign * omega
