r"""``HalfSpace(pressure=p)``: a half-space contact under any axisymmetric pressure, and its named cases.

Units (docs/conventions.md): radii in the contact radius a; the pressure p(r) in p-bar = F/(pi a^2)
with mean 1 (2 int_0^1 p r dr = 1); T* = 2T/(f F a); tractions in f p-bar; slip in f p-bar a / mu;
``rigid_rotation`` Omega the rotation of one elastic body's stick zone relative to its remote
points (f p-bar / mu); energies in (f p-bar)^2 a^3 / mu.

The bodies (``bodies``):

* ``"similar"``: two elastically similar half-spaces (or bodies large against a, e.g. a sphere on
  a flat of the same material), each turning by Omega: relative rotation 2 Omega, slip s = 2 u;
* ``"rigid-punch"``: a rigid body on one elastic half-space: relative rotation Omega, slip s = u.

Torsion does not change the pressure (elastic similarity for ``"similar"``; a rigid punch on a
half-space: the normal and torsional problems of the half-space are uncoupled), so the friction
limit stays f p(r) and the memory rules of ``histories.memory`` hold.

Numbers and fields from Jaeger's superposition (``half_space.jaeger``, equations (J1)-(J6)): stick
radius b <-> T*, Omega(b) = R(b), the traction (f p on the slip annulus, (J4) in the stick disc)
and the slip (J5) by quadrature; slip onset (8/3) c0 (c0 = lim sqrt(1 - r^2) p(r)), gross slip
4 int_0^1 p r^2 dr.  The monotonic numbers b(tau), Omega_m(tau), W_mono(tau) as the histories use
them come from the cached interpolants of ``half_space.monotonic_table`` (built on first use).

The table's entries "hertz" (``HERTZ``: p = (3/2) sqrt(1 - r^2), two similar bodies, gross slip
3 pi/8) and "flat-punch" (``FLAT_PUNCH``: p = 1/(2 sqrt(1 - r^2)), rigid punch, bonded to T* = 4/3,
gross slip pi/2) are instances; their closed forms are in ``half_space.elliptic``.
"""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass

import numpy as np

from .. import validation
from ..contact_models.base import ContactModel
from ..solution import Solution
from . import jaeger
from .monotonic_table import MonotonicTable

__all__ = ["HalfSpace", "PressureState", "PressureSolution", "BODIES", "MEAN_TOLERANCE", "HERTZ", "FLAT_PUNCH"]

#: The bodies a ``HalfSpace`` can be: name -> (elastic bodies n, description).
BODIES = {
    "similar": (2, "two elastically similar half-spaces"),
    "rigid-punch": (1, "a rigid punch on an elastic half-space"),
}
#: |2 int_0^1 p r dr - 1| accepted for the pressure's mean (the quadrature of ``jaeger.mean_pressure`` is exact
#: to ~1e-15 for the pressures it resolves; a coarser value is a pressure not normalised by p-bar).
MEAN_TOLERANCE = 1e-9
#: Radii at which the pressure is checked to be finite and >= 0 (besides the quadrature nodes).
_CHECK_RADII = np.linspace(0.0, 1.0, 2001)[:-1]
_FIELDS = ("traction", "slip")


@dataclass(frozen=True)
class PressureState:
    """The positive-torque state of a ``HalfSpace`` at stick radius b (the interface of ``backends``)."""

    contact: object
    stick_radius: float
    torque: float
    rigid_rotation: float
    dini_is_truncation = False

    def traction(self, r):
        """sigma_zt(r, 0) / (f p-bar): f p on the slip annulus, (J4) on the stick disc, the bonded disc below onset."""
        return self.contact.traction_at(np.asarray(r, dtype=float), self.stick_radius, self.torque)

    def displacement(self, r):
        """u(r) of one body's face relative to its stick disc (f p-bar a / mu), (J5); the slip is n u."""
        return self.contact.displacement_at(np.asarray(r, dtype=float), self.stick_radius, self.rigid_rotation)

    def dini(self, z_min, tolerance):
        return None

    def metadata(self) -> dict:
        return {}


@dataclass(frozen=True)
class PressureSolution(Solution):
    """``solve`` for a ``HalfSpace``: the attributes of ``Solution``; the fields ``traction`` and ``slip``.

    ``rigid_rotation`` is Omega (f p-bar / mu), one body's stick zone relative to its remote points;
    ``method`` and ``n_terms`` are None (quadrature); ``slip`` is n u (``HalfSpace.elastic_bodies``).
    """

    model: str = "half-space"

    def slip(self, r):
        """Slip s(r) = n u(r) (f p-bar a / mu): 0 on the stick disc, (J5) on the annulus, +inf at gross slip."""
        r = validation.coordinates(r)
        contact = self.backend.contact
        return self.sign * contact.elastic_bodies * self.backend.displacement(r)

    def stress(self, r, z):
        raise ValueError(f"model {self.model!r} offers the fields {', '.join(_FIELDS)} only (no stress field)")

    def displacement(self, r, z):
        raise ValueError(f"model {self.model!r} offers the fields {', '.join(_FIELDS)} only (no displacement "
                         "field in the bodies: use slip for the interface)")


def _as_weighted(pressure, weighted):
    """(p(r), e(r, root) = p sqrt(1 - r^2)) from the arguments (ValueError naming ``pressure``)."""
    if isinstance(pressure, bool):
        raise ValueError(f"pressure must be 1 (uniform) or a callable p(r) on [0, 1], got {pressure!r}")
    if isinstance(pressure, numbers.Real):
        if float(pressure) != 1.0:
            raise ValueError(f"pressure must have mean 1 (it is normalised by p-bar = F/(pi a^2)): a uniform "
                             f"pressure is 1, got {pressure!r}")
        return (lambda r: np.ones_like(np.asarray(r, dtype=float))), (lambda r, root: root)
    if not callable(pressure):
        raise ValueError(f"pressure must be 1 (uniform) or a callable p(r) on [0, 1], got {pressure!r}")
    if weighted is None:
        def weighted(r, root):
            return np.asarray(pressure(r), dtype=float) * root
    elif not callable(weighted):
        raise ValueError(f"weighted must be a callable e(r, sqrt(1 - r^2)) = p(r) sqrt(1 - r^2), got {weighted!r}")
    return pressure, weighted


class HalfSpace(ContactModel):
    """A half-space contact under the axisymmetric pressure ``pressure`` (module docstring).

    Parameters
    ----------
    pressure : 1 or callable
        p(r) / p-bar on 0 <= r < 1, vectorised over an array r, with mean 1: 2 int_0^1 p r dr = 1 to
        ``MEAN_TOLERANCE``; finite and >= 0 (it may grow like c0 / sqrt(1 - r^2) at the edge).  1: uniform.
    bodies : "similar" or "rigid-punch"
        Two elastically similar bodies (slip 2u) or a rigid punch on one elastic half-space (slip u).
    weighted : callable, optional
        e(r, root) = p(r) sqrt(1 - r^2) given root = sqrt(1 - r^2) exactly: the same pressure, written
        so that a pressure singular at the edge keeps its accuracy next to r = 1 (the quadrature evaluates
        e; by default e = pressure(r) * root, which loses ~eps / (1 - r^2) relative there).
    edge : float, optional
        c0 = lim sqrt(1 - r^2) p(r) (0 for a pressure bounded at the edge): fixes the slip onset
        (8/3) c0.  Default: weighted(1, 0) when ``weighted`` is given, else extrapolated from e on
        0.01 <= sqrt(1 - r^2) <= 0.2 (a value below 1e-9 taken as 0).
    name, description, gross_slip_text : str, optional
        The name in ``models.MODELS`` (for ``models.register``), one line on the contact, and how
        messages write the gross-slip torque (default: its value to 6 digits).

    Raises
    ------
    ValueError
        Naming ``pressure`` (not a callable, not normalised, negative or not finite), ``bodies``,
        ``weighted`` or ``edge``.
    """

    fields = _FIELDS
    shaft = False

    def __init__(self, pressure=1.0, *, bodies: str = "similar", weighted=None, edge=None, name: str = "",
                 description: str = "", gross_slip_text: str = ""):
        bodies = validation.choice("bodies", bodies, BODIES)
        self.pressure, self.weighted = _as_weighted(pressure, weighted)
        self.elastic_bodies, what = BODIES[bodies]
        self.body_kind = bodies
        self.bodies = "the half-spaces" if bodies == "similar" else "the punch and the half-space"
        self._check_pressure()
        mean = jaeger.mean_pressure(self.weighted)
        if not abs(mean - 1.0) <= MEAN_TOLERANCE:
            raise ValueError(f"pressure must have mean 1, 2 int_0^1 p r dr = 1 within {MEAN_TOLERANCE:g} (it is "
                             f"normalised by p-bar = F/(pi a^2)), got {mean!r}")
        self.edge_coefficient = self._edge(edge, weighted is not None)
        self.slip_onset_torque = 8.0 * self.edge_coefficient / 3.0
        self.gross_slip_torque = jaeger.gross_slip_torque(self.weighted)
        if not self.gross_slip_torque > self.slip_onset_torque:
            raise ValueError(f"pressure: the gross-slip torque {self.gross_slip_torque:.6g} must exceed the slip "
                             f"onset (8/3) c0 = {self.slip_onset_torque:.6g}")
        self.gross_slip_text = gross_slip_text or f"{self.gross_slip_torque:.6g}"
        self.name = name
        self.description = description or f"{what}, a given axisymmetric pressure"
        self._table = None

    # ----------------------------------------------------------------------------- checks
    def _check_pressure(self) -> None:
        theta, _ = jaeger.graded_rule(np.zeros(1), np.full(1, 0.5 * math.pi), np.full(1, 0.5 * math.pi))
        r = np.concatenate([_CHECK_RADII, np.sin(theta.ravel())])
        try:
            values = np.asarray(self.weighted(r, jaeger.edge_root(r)), dtype=float)
            direct = np.asarray(self.pressure(_CHECK_RADII), dtype=float)
        except Exception as error:  # a user callable: report what it raised, naming the argument
            raise ValueError(f"pressure must be a vectorised callable p(r) of an array of radii in [0, 1): calling "
                             f"it raised {type(error).__name__}: {error}") from error
        for label, v, radii in (("p(r) sqrt(1 - r^2)", values, r), ("p(r)", direct, _CHECK_RADII)):
            if v.shape != radii.shape:
                raise ValueError(f"pressure must return one value per radius (shape {radii.shape}), got shape "
                                 f"{v.shape} for {label}")
            bad = ~(np.isfinite(v) & (v >= 0))
            if bad.any():
                i = int(np.argmax(bad))
                raise ValueError(f"pressure must be finite and >= 0 on [0, 1), got {label} = {v[i]!r} at r = "
                                 f"{radii[i]!r}")

    def _edge(self, edge, exact: bool) -> float:
        if edge is not None:
            return validation.real_number("edge", edge, 0.0, None)
        if exact:
            return float(np.asarray(self.weighted(np.ones(1), np.zeros(1)), dtype=float).ravel()[0])
        root = 0.105 + 0.095 * np.cos(math.pi * (np.arange(24) + 0.5) / 24)  # 0.01 .. 0.2
        r = np.sqrt((1.0 - root) * (1.0 + root))
        fit = np.polynomial.Chebyshev.fit(root, self.weighted(r, root), 10)
        value = float(fit(0.0))
        return value if value > 1e-9 else 0.0

    # ----------------------------------------------------------------------------- exact numbers
    def rotation_at_radius(self, b):
        """Omega(b) = R(b), eq. (J1), for an array 0 < b <= 1 (f p-bar / mu): exact quadrature."""
        b = np.asarray(b, dtype=float)
        out = jaeger.rotation(self.weighted, b.ravel())
        return out.reshape(b.shape) if b.ndim else float(out[0])

    def torque_at_radius(self, b):
        """T*(b), eq. (J2), for an array 0 <= b <= 1 (exact quadrature; the slip onset at b = 1)."""
        b = np.asarray(b, dtype=float)
        out = jaeger.torque(self.weighted, b.ravel())
        out = np.where(b.ravel() >= 1.0, self.slip_onset_torque, np.where(b.ravel() <= 0.0, self.gross_slip_torque,
                                                                          out))
        return out.reshape(b.shape) if b.ndim else float(out[0])

    def loading_work_at_radius(self, b):
        """W_mono(b), eq. (J6), for an array 0 < b < 1 (nested quadrature: a check of the interpolants)."""
        b = np.asarray(b, dtype=float)
        out = jaeger.loading_work(lambda c: jaeger.rotation(self.weighted, c), b.ravel(), self.elastic_bodies)
        return out.reshape(b.shape) if b.ndim else float(out[0])

    def traction_at(self, r, b: float, torque: float):
        """Positive-torque traction (f p-bar) at radii r for stick radius b and torque T* (vectorised over r)."""
        out = np.zeros(r.shape)
        flat, o = r.ravel(), out.ravel()
        if b >= 1.0:  # bonded disc of radius a: (3 T*/8) r / sqrt(1 - r^2) (Reissner-Sagoci)
            root = jaeger.edge_root(flat)
            with np.errstate(divide="ignore"):
                o[:] = np.where(root > 0, 0.375 * torque * flat / np.where(root > 0, root, 1.0), np.inf)
            return out
        slipping = flat >= b
        if slipping.any():
            rs = flat[slipping]
            root = jaeger.edge_root(rs)
            with np.errstate(divide="ignore", invalid="ignore"):
                values = np.asarray(self.weighted(rs, root), dtype=float) / root
            o[slipping] = np.where(root > 0, values, np.asarray(self.pressure(rs), dtype=float))
        stick = ~slipping
        if stick.any() and b > 0.0:
            o[stick] = jaeger.stick_traction(self.weighted, flat[stick], b)
        return out

    def displacement_at(self, r, b: float, omega: float):
        """u(r), eq. (J5), at radii r for stick radius b (0 on the stick disc; +inf off the axis at b = 0)."""
        out = np.zeros(r.shape)
        flat, o = r.ravel(), out.ravel()
        if b >= 1.0:
            return out
        if b <= 0.0:
            o[flat > 0] = np.inf
            return out
        slipping = flat > b
        if slipping.any():
            o[slipping] = jaeger.displacement(lambda c: jaeger.rotation(self.weighted, c), flat[slipping], b, omega)
        return out

    # ----------------------------------------------------------------------------- the ContactModel interface
    @property
    def table(self) -> MonotonicTable:
        """The cached interpolants of b(tau), Omega(tau), W(tau) (built on first use; ``monotonic_table``)."""
        if self._table is None:
            self._table = MonotonicTable(lambda b, k: jaeger.rotation_and_torque(self.weighted, b, k),
                                         lambda b, k: jaeger.torque_deficit(self.weighted, b, k),
                                         self.slip_onset_torque, self.gross_slip_torque, self.elastic_bodies)
        return self._table

    def _state(self, b: float, torque: float, omega: float, sign: float, regime: str, tolerance: float):
        backend = PressureState(contact=self, stick_radius=b, torque=torque, rigid_rotation=omega)
        solution = PressureSolution(stick_radius=b, torque=sign * torque + 0.0, rigid_rotation=sign * omega + 0.0,
                                    regime=regime, method=None, n_terms=None, tolerance=tolerance, backend=backend)
        object.__setattr__(solution, "model", self.name or "half-space (given pressure)")
        return solution

    def solution_at_radius(self, b: float, tolerance: float):
        if b <= 0.0:
            return self._state(0.0, self.gross_slip_torque, math.inf, 1.0, "gross-slip", tolerance)
        if b >= 1.0:
            torque = self.slip_onset_torque
            return self._state(1.0, torque, 3.0 * math.pi * torque / 32.0, 1.0, "stick", tolerance)
        omega, torque = jaeger.rotation_and_torque(self.weighted, np.array([b]))
        return self._state(b, float(torque[0]), float(omega[0]), 1.0, "partial-slip", tolerance)

    def solution_at_torque(self, magnitude: float, sign: float, tolerance: float):
        if magnitude >= self.gross_slip_torque * (1.0 - validation.TORQUE_TOLERANCE):
            return self._state(0.0, self.gross_slip_torque, math.inf, sign, "gross-slip", tolerance)
        if magnitude <= self.slip_onset_torque:
            return self._state(1.0, magnitude, 3.0 * math.pi * magnitude / 32.0, sign,
                               "stick", tolerance)
        b, omega, _ = self.table.point(magnitude)
        return self._state(b, magnitude, omega, sign, "partial-slip", tolerance)

    def monotonic_points(self, tau):
        """b, Omega_m, W_mono for an array 0 <= tau <= gross-slip torque (the interpolants; bonded below onset)."""
        tau = np.asarray(tau, dtype=float)
        b, omega, work = np.ones(tau.shape), 3.0 * math.pi * tau / 32.0, np.zeros(tau.shape)
        spinning = tau >= self.gross_slip_torque * (1.0 - validation.TORQUE_TOLERANCE)
        slipping = (tau > self.slip_onset_torque) & ~spinning
        if slipping.any():
            b[slipping], omega[slipping], work[slipping] = self.table.evaluate(tau[slipping])
        b[spinning], omega[spinning], work[spinning] = 0.0, math.inf, math.inf
        return b, omega, work

    def monotonic_slope(self, tau):
        """dOmega_m/dT* = 3 pi / (32 b^3), eq. (J3) (3 pi / 32 while bonded; +inf at gross slip)."""
        b = self.monotonic_points(np.asarray(tau, dtype=float))[0]
        with np.errstate(divide="ignore"):
            return 3.0 * math.pi / (32.0 * b**3)

    def as_dict(self) -> dict:
        out = super().as_dict()
        out["bodies"] = self.body_kind
        out["edge_coefficient"] = self.edge_coefficient
        return out


def _hertz_pressure(r):
    return 1.5 * jaeger.edge_root(r)


def _hertz_weighted(r, root):
    return 1.5 * root * root


def _punch_pressure(r):
    with np.errstate(divide="ignore"):
        return 0.5 / jaeger.edge_root(r)


def _punch_weighted(r, root):
    return np.full(np.shape(root), 0.5)


#: "hertz": two elastically similar bodies under the Hertzian pressure (3/2) sqrt(1 - r^2) (a sphere on a flat,
#: Lubkin, Deresiewicz); slip at any torque, gross slip at T* = 3 pi/8.
HERTZ = HalfSpace(pressure=_hertz_pressure, weighted=_hertz_weighted, name="hertz",
                  description="two elastically similar bodies, Hertzian pressure (sphere on a flat)",
                  gross_slip_text="3 pi/8")
#: "flat-punch": a rigid flat punch on an elastic half-space, pressure 1 / (2 sqrt(1 - r^2)); bonded up to
#: T* = 4/3 (Omega = 3 pi T*/32), gross slip at T* = pi/2.
FLAT_PUNCH = HalfSpace(pressure=_punch_pressure, weighted=_punch_weighted, bodies="rigid-punch", name="flat-punch",
                       description="a rigid flat punch on an elastic half-space (pin on disc)",
                       gross_slip_text="pi/2")
