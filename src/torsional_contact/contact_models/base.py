r"""The contact-model protocol: everything the package asks of a contact model, in one object.

Units (docs/conventions.md, one normalisation for every model): radii in the contact radius a;
T* = 2T/(f F a); tractions and stresses in f p-bar, p-bar = F/(pi a^2) the mean pressure (p0 of
the cylinders); displacements and slip in f p-bar a / mu; ``rigid_rotation`` the rotation of one
elastic body's stick zone relative to its remote points, in f p-bar / mu (for the cylinders: the
far-field rotation beyond the uniform twist, omega); energies in (f p-bar)^2 a^3 / mu.

A contact model (``ContactModel``) is one object that knows

* its **monotonic solution**: ``solve`` (a ``Solution`` for a stick radius or a torque) and
  ``monotonic`` (the numbers b(tau), omega_m(tau), W_mono(tau) and the solutions mono(tau) that
  the memory rules of ``histories`` combine, behind the ``Monotonic`` interface);
* its **thresholds**: ``slip_onset_torque`` (slip starts: 1 for the cylinders, 0 for a
  half-space under a pressure that vanishes or stays finite at the edge, 4/3 for the flat punch)
  and ``gross_slip_torque`` (the contact spins: T* = 4 int_0^1 p(r) r^2 dr / p-bar);
* what **fields** its solutions offer (``fields``), which solution **methods** it takes
  (``methods``, ``default_method``; empty for a closed-form or quadrature model) and its **units**
  (``units``: how ``rigid_rotation`` and the twist are measured; ``elastic_bodies`` whose
  compliance the relative rotation adds; ``shaft``: whether the bodies are shafts, whose twist
  over a gauge length adds the uniform twist T* L / a).

What follows from these facts is written once, here, and never overridden: the energy per
closed loop (Masing, rule 5 of ``histories.memory``) W(A) = 4 W_mono(A/2); the regime of a
torque; the reversal range above which a reversal slips again, 2 ``slip_onset_torque``; the check
of a torque against the gross-slip torque; the twist a rig measures.

The models and their names are in one table, ``models.MODELS`` (the only place that compares a
model's name); ``models.register`` adds one.  A model without solution methods derives from
``ContactModel`` and implements ``monotonic_points`` (vectorised numbers), ``solution_at_radius``
and ``solution_at_torque``; ``solve`` and ``monotonic`` come from here (``SimpleMonotonic``).
The cylinders, with their methods, override ``solve`` and ``monotonic``
(``contact_models.cylinder``).
"""

from __future__ import annotations

import math
import numbers
from collections.abc import Mapping
from typing import Protocol

import numpy as np

from .. import validation

__all__ = ["ContactModel", "Monotonic", "SimpleMonotonic", "FIELDS", "TORQUE_TOLERANCE", "stick_radius_grid"]

#: Every field a ``Solution`` can offer: interface traction and slip, stresses and displacement anywhere,
#: and the interface's sigma_rt.
FIELDS = ("traction", "slip", "stress", "displacement", "sigma_rt")

#: Relative rounding of a torque accepted beyond the gross-slip torque (and clipped to it).
TORQUE_TOLERANCE = validation.TORQUE_TOLERANCE


class Monotonic(Protocol):
    """The monotonic solution mono(tau), 0 <= tau <= gross-slip torque, as the memory rules use it.

    ``point(tau)`` -> (b, omega_m, W_mono) at one torque; ``points(tau)`` the same for an array
    (vectorised: the arrays b, omega_m, W_mono); ``solution(tau)`` the full ``Solution`` (cached).
    W_mono(tau) is the work against friction of a monotonic loading from the virgin state to tau
    ((f p-bar)^2 a^3 / mu), +inf at the gross-slip torque when the rotation is unbounded there.
    """

    contact: ContactModel
    method: str | None
    n_terms: int | None

    def point(self, tau: float) -> tuple[float, float, float]: ...

    def points(self, tau) -> tuple[np.ndarray, np.ndarray, np.ndarray]: ...

    def solution(self, tau: float): ...

    def path_torques(self, b_start: float, b_end: float, n_points: int) -> list[float]: ...

    def rotation_slope(self, tau: float, step: float = 1e-4) -> float: ...

    def rotation_integral(self, tau: float) -> float: ...


def stick_radius_grid(b_start: float, b_end: float, n_points: int, b_max: float = 1.0) -> np.ndarray:
    """``n_points`` stick radii equally spaced from b_start down to b_end (both excluded), those <= ``b_max``."""
    upper = min(b_start, b_max)
    if upper <= b_end:
        return np.empty(0)
    return np.linspace(upper, b_end, n_points + 1)[:-1][1 if upper == b_start else 0:]


class ContactModel:
    """One contact model (module docstring).  Subclasses set the class attributes and implement the
    abstract methods; the methods below them are the same for every model."""

    #: The model's name in ``models.MODELS`` (the JSON ``model`` key, the command line's ``--model``).
    name: str = ""
    #: One line: what is in contact, under which pressure.
    description: str = ""
    #: The bodies, as messages name them ("the cylinders", "the half-spaces", ...).
    bodies: str = "the bodies"
    #: T* at which slip starts (a reversal of range above twice this slips again).
    slip_onset_torque: float = math.nan
    #: T* at which the whole contact slips (the bodies spin).
    gross_slip_torque: float = math.nan
    #: How the gross-slip torque is written in messages ("4/3", "3 pi/8").
    gross_slip_text: str = ""
    #: Elastic bodies whose compliance the relative rotation of remote points adds (2: two elastically
    #: similar bodies; 1: a rigid body on an elastic one).
    elastic_bodies: int = 2
    #: True when the bodies are shafts whose twist over a gauge length L adds the uniform twist T* L / a.
    shaft: bool = False
    #: The fields its solutions offer (a subset of ``FIELDS``).
    fields: tuple[str, ...] = FIELDS
    #: Solution methods ``solve`` takes (name -> one-line description); empty: none (give no method).
    methods: Mapping[str, str] = {}
    #: The method used when none is given (None: the model has no methods).
    default_method: str | None = None
    #: How the model's quantities are measured, for documents and JSON (``as_dict``).
    units: Mapping[str, str] = {
        "radius": "contact radius a",
        "torque": "T* = 2T/(f F a)",
        "traction": "f p-bar, p-bar = F/(pi a^2)",
        "slip": "f p-bar a / mu",
        "rigid_rotation": "f p-bar / mu: one elastic body's stick zone relative to its remote points",
        "energy": "(f p-bar)^2 a^3 / mu",
    }

    # ----------------------------------------------------------------------------- options
    def options(self, method=None, n_terms=None) -> tuple[str | None, int | None]:
        """The resolved (method, n_terms); ValueError naming the argument.

        A model without methods refuses both (it is closed-form or computed by quadrature).
        """
        if not self.methods:
            for argument, value in (("method", method), ("n_terms", n_terms)):
                if value is not None:
                    raise ValueError(f"{argument}={value!r} applies to models with solution methods only (e.g. "
                                     f"'cylinder'); model={self.name!r} has none: omit {argument}")
            return None, None
        raise NotImplementedError(f"model {self.name!r} has methods and must resolve its options")

    # ----------------------------------------------------------------------------- solutions
    def solve(self, stick_radius=None, torque=None, *, method=None, n_terms=None, tolerance=None):
        """The ``Solution`` for a stick radius b/a in [0, 1] or a torque |T*| <= ``gross_slip_torque``.

        Raises ValueError naming the argument (as ``torsional_contact.solve``).
        """
        from ..fields import DEFAULT_TOLERANCE

        self.options(method, n_terms)
        tolerance = validation.real_number("tolerance", DEFAULT_TOLERANCE if tolerance is None else tolerance,
                                           0.0, 1.0)
        if (stick_radius is None) == (torque is None):
            raise ValueError("give exactly one of stick_radius (in [0, 1]) and torque "
                             f"(in [-{self.gross_slip_text}, {self.gross_slip_text}])")
        if stick_radius is not None:
            b = validation.real_number("stick_radius", stick_radius, 0.0, 1.0)
            return self.solution_at_radius(b, tolerance)
        t = self.checked_torque("torque", torque)
        return self.solution_at_torque(abs(t), -1.0 if t < 0 else 1.0, tolerance)

    def solution_at_radius(self, b: float, tolerance: float):
        """The positive-torque ``Solution`` with stick radius b (validated, in [0, 1])."""
        raise NotImplementedError

    def solution_at_torque(self, magnitude: float, sign: float, tolerance: float):
        """The ``Solution`` at torque sign * magnitude (validated, 0 <= magnitude <= gross-slip torque)."""
        raise NotImplementedError

    # ----------------------------------------------------------------------------- memory rules
    def monotonic(self, method=None, n_terms=None) -> Monotonic:
        """The monotonic solution for the memory rules (one object per resolved options, shared)."""
        self.options(method, n_terms)
        cached = self.__dict__.get("_monotonic")
        if cached is None:
            cached = SimpleMonotonic(self)
            self.__dict__["_monotonic"] = cached
        return cached

    def monotonic_points(self, tau) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """b(tau), omega_m(tau), W_mono(tau) for an array 0 <= tau <= gross-slip torque (vectorised).

        Models without methods implement this; the cylinders go through ``monotonic``.
        """
        raise NotImplementedError

    def torque_at_radius(self, b):
        """T*(b) of the monotonic solution for an array of stick radii 0 <= b < 1 (vectorised; models without
        methods implement it)."""
        raise NotImplementedError

    def monotonic_slope(self, tau):
        """d omega_m / d T* at the monotonic torques tau (vectorised; models without methods implement it)."""
        raise NotImplementedError

    def quadrature_rotation_integral(self, tau: float, monotonic: Monotonic | None = None) -> float:
        """int_0^tau omega_m(t) dt by Gauss-Legendre panels of ``monotonic.points`` (default options).

        omega_m is smooth in t between the slip onset and the gross-slip torque, where it may grow
        like a logarithm (integrable): the panels are graded geometrically toward both ends.  Used by
        the loop-area route of the energy (``histories.energy.dissipation_from_loop_area``), an
        independent check of W(A) = 4 W_mono(A/2).
        """
        from ..quadrature import gauss_legendre

        monotonic = self.monotonic() if monotonic is None else monotonic
        nodes, weights = gauss_legendre(16)
        onset = min(self.slip_onset_torque, tau)
        # below the onset omega_m is zero (cylinders) or linear in t (bonded): one panel is exact
        t = 0.5 * onset * (nodes + 1.0)
        total = float(np.sum(0.5 * onset * weights * monotonic.points(t)[1])) if onset > 0.0 else 0.0
        if tau <= onset:
            return total
        grading = np.geomspace(1e-14, 0.5, 24)
        u = np.unique(np.concatenate([[0.0, 1.0], grading, 1.0 - grading]))
        edges = onset + (tau - onset) * u
        lo, hi = edges[:-1, None], edges[1:, None]
        t = 0.5 * (hi + lo) + 0.5 * (hi - lo) * nodes
        values = monotonic.points(t.ravel())[1].reshape(t.shape)
        return total + float(np.sum(0.5 * (hi - lo) * weights * values))

    # ----------------------------------------------------------------------------- numbers
    def stick_radius(self, tau, *, method=None, n_terms=None):
        """b/a of the monotonic loading to 0 <= tau <= gross-slip torque (vectorised)."""
        return self._numbers(tau, 0, method, n_terms)

    def rotation(self, tau, *, method=None, n_terms=None):
        """omega_m(tau) (f p-bar / mu) of the monotonic loading (vectorised)."""
        return self._numbers(tau, 1, method, n_terms)

    def loading_work(self, tau, *, method=None, n_terms=None):
        """W_mono(tau): work against friction of the monotonic loading to tau ((f p-bar)^2 a^3 / mu; vectorised)."""
        return self._numbers(tau, 2, method, n_terms)

    def _numbers(self, tau, which: int, method, n_terms):
        values = self._monotonic_argument("tau", tau)
        out = self.monotonic(method, n_terms).points(values)[which]
        return out if np.ndim(tau) else float(out)

    def _monotonic_argument(self, name: str, tau) -> np.ndarray:
        values = np.asarray(tau, dtype=float)
        limit = self.gross_slip_torque * (1.0 + TORQUE_TOLERANCE)
        bad = ~((values >= 0.0) & (values <= limit))
        if bad.any():
            first = values.ravel()[int(np.argmax(bad.ravel()))]
            raise ValueError(f"{name} must lie in [0, {self.gross_slip_text}] (model {self.name!r}), got {first!r}")
        return np.minimum(values, self.gross_slip_torque)

    def energy_per_cycle(self, torque_range, *, method=None, n_terms=None):
        """W(A) = 4 W_mono(A/2): the energy dissipated per closed loop of torque range A (any mean torque).

        Masing's rule (rule 5 of ``histories.memory``): on each half cycle the traction is the
        friction limit reversed on the annulus that slips, and the slip increment there is twice the
        monotonic slip at A/2.  Units (f p-bar)^2 a^3 / mu; 0 for A <= 2 ``slip_onset_torque``;
        +inf at A = 2 ``gross_slip_torque`` when the rotation is unbounded there.  Vectorised.

        Raises ValueError if A is not finite or outside [0, 2 gross-slip torque].
        """
        values = np.asarray(torque_range, dtype=float)
        limit = 2.0 * self.gross_slip_torque * (1.0 + TORQUE_TOLERANCE)
        bad = ~((values >= 0.0) & (values <= limit))
        if bad.any():
            first = values.ravel()[int(np.argmax(bad.ravel()))]
            raise ValueError(f"torque_range must lie in [0, 2 x {self.gross_slip_text}] (model {self.name!r}), "
                             f"got {first!r}")
        work = self.monotonic(method, n_terms).points(np.minimum(0.5 * values, self.gross_slip_torque))[2]
        out = 4.0 * np.asarray(work)
        return out if np.ndim(torque_range) else float(out)

    @property
    def reversal_slip_range(self) -> float:
        """Torque range above which a reversal slips again: twice the slip onset (memory rule 2)."""
        return 2.0 * self.slip_onset_torque

    def regime(self, torque) -> str:
        """"stick" (|T*| <= slip onset), "gross-slip" (|T*| >= gross-slip torque) or "partial-slip"."""
        t = abs(float(torque))
        if t <= self.slip_onset_torque:
            return "stick"
        return "gross-slip" if t >= self.gross_slip_torque else "partial-slip"

    def checked_torque(self, name: str, value) -> float:
        """``value`` as a finite T* in [-gross, gross] (a rounding beyond it clipped), or ValueError naming ``name``."""
        return validation.torque(name, value, limit=self.gross_slip_torque, limit_text=self.gross_slip_text,
                                 spinning=f"{self.bodies} spin")

    def contact_twist(self, torque, rigid_rotation, gauge_length=None):
        """The relative rotation (f p-bar / mu) of two cross-sections (shafts) or remote points (half-spaces).

        ``elastic_bodies`` x ``rigid_rotation``, plus the uniform twist T* L / a of shafts over
        the gauge length L / a (``gauge_length``, required for shafts, not accepted otherwise).
        Vectorised over the torque and the rotation.
        """
        twist = self.elastic_bodies * np.asarray(rigid_rotation, dtype=float)
        if self.shaft:
            if gauge_length is None:
                raise ValueError(f"the twist of {self.bodies} needs a gauge length (distance between the two "
                                 "cross-sections)")
            twist = twist + np.asarray(torque, dtype=float) * gauge_length
        elif gauge_length is not None:
            raise ValueError(f"a gauge length does not apply to model {self.name!r} ({self.bodies} have no "
                             "cross-sections: the twist is the relative rotation of remote points)")
        return twist

    def offers(self, field: str) -> bool:
        """Whether the model's solutions offer ``field`` (one of ``FIELDS``)."""
        return field in self.fields

    def as_dict(self) -> dict:
        """The model's facts, JSON-ready (documents, provenance)."""
        return {
            "name": self.name,
            "description": self.description,
            "slip_onset_torque": self.slip_onset_torque,
            "gross_slip_torque": self.gross_slip_torque,
            "elastic_bodies": self.elastic_bodies,
            "shaft": self.shaft,
            "fields": list(self.fields),
            "methods": list(self.methods),
            "default_method": self.default_method,
            "units": dict(self.units),
        }

    def __repr__(self) -> str:
        return f"<contact model {self.name!r}: {self.description}>"


class SimpleMonotonic:
    """The ``Monotonic`` of a model without methods: its ``monotonic_points`` and ``solve`` (cached solutions)."""

    method = None
    n_terms = None
    _CACHE_SIZE = 4096

    def __init__(self, contact: ContactModel):
        self.contact = contact
        self._solutions: dict = {}

    def __repr__(self) -> str:
        return f"SimpleMonotonic({self.contact.name!r})"

    def point(self, tau: float) -> tuple[float, float, float]:
        b, omega, work = self.points(np.array([tau], dtype=float))
        return float(b[0]), float(omega[0]), float(work[0])

    def points(self, tau):
        tau = np.clip(np.asarray(tau, dtype=float), 0.0, self.contact.gross_slip_torque)
        b, omega, work = self.contact.monotonic_points(tau.ravel())
        return (np.asarray(b, dtype=float).reshape(tau.shape), np.asarray(omega, dtype=float).reshape(tau.shape),
                np.asarray(work, dtype=float).reshape(tau.shape))

    def path_torques(self, b_start: float, b_end: float, n_points: int) -> list[float]:
        """Monotonic torques at ``n_points`` stick radii equally spaced from b_start down to b_end (excluded)."""
        radii = stick_radius_grid(b_start, b_end, n_points)
        return [float(t) for t in np.atleast_1d(self.contact.torque_at_radius(radii))] if radii.size else []

    def rotation_slope(self, tau: float, step: float = 1e-4) -> float:
        """d omega_m / d T* at the monotonic torque tau (exact: ``step``, the weak forms' difference width, unused)."""
        return float(self.contact.monotonic_slope(np.array([tau], dtype=float))[0])

    def rotation_integral(self, tau: float) -> float:
        """int_0^tau omega_m(t) dt (``ContactModel.quadrature_rotation_integral``)."""
        return self.contact.quadrature_rotation_integral(tau, self)

    def solution(self, tau):
        """mono(tau) for 0 <= tau <= gross-slip torque (cached)."""
        if isinstance(tau, bool) or not isinstance(tau, numbers.Real):
            raise ValueError(f"tau must be a real number in [0, {self.contact.gross_slip_text}], got {tau!r}")
        tau = self.contact.checked_torque("tau", tau)
        if tau < 0:
            raise ValueError(f"tau must lie in [0, {self.contact.gross_slip_text}], got {tau!r}")
        if tau not in self._solutions:
            if len(self._solutions) >= self._CACHE_SIZE:
                self._solutions.clear()
            self._solutions[tau] = self.contact.solve(torque=tau)
        return self._solutions[tau]
