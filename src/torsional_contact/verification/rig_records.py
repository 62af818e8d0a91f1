r"""Torque-twist records as a real torsion rig writes them, made independently of the loop fit.

Units: time s, torque N m, twist rad, lengths m, force N, modulus Pa, frequency Hz.

The physics (one contact model of ``models.MODELS``, asked only for its monotonic numbers)
-----------------------------------------------------------------------------------------
A rig twists two shafts (or two bodies) pressed together by the normal force F and records the
torque T and the twist theta between two cross-sections a gauge length L apart.  On the virgin
loading to T* = 2T/(f F a) (eq. 32) the twist is the skeleton

    h(T*) = (f p-bar / G) contact_twist(T*, omega_m(T*), L/a) + C_rig T_s T*,   T_s = f F a / 2,

with omega_m the model's monotonic rigid rotation (``ContactModel.rotation``), ``contact_twist``
its measured twist (for shafts ``elastic_bodies`` omega + T* L / a, i.e. the shaft's L/(G J) T
plus the contact) and C_rig the rig's own compliance.  Any other history follows by Masing's
rules, written here on their own (``MasingWalk``; the package's ``histories`` and ``fitting``
are not used): from the last reversal (x_r, y_r) a branch in the direction d is
y = y_r + d 2 S(d (x - x_r) / 2), where S is the skeleton of the driven variable x (S = h for a
torque-controlled rig, x = T, y = theta; S = h^-1 for a twist-controlled one); a branch that
reaches the reversal before the last closes that loop and continues the older branch
(memory), and the virgin curve is left at the first reversal and rejoined beyond its mirror.
A twist-controlled rig's torque saturates at the gross-slip torque (the contact spins): its
plateau is the model's ``gross_slip_torque`` times T_s.

What a rig adds (``RigDefects``)
--------------------------------
Each record has a time column (``sample_rate``), white Gaussian noise on both channels (torque:
a fraction of the torque range; twist: rad) and an arbitrary twist zero, and any of the defects
of real rigs:

=====================  ======================================================================
``lag``                the twist channel lags the torque channel by ``lag`` s (the twist at
                       t - lag is recorded at t; at rest before the start)
``drift``              the twist channel drifts by ``drift`` rad/s
``torque_offset``      the torque channel reads ``torque_offset`` N m at zero torque
``spikes``             ``spikes`` twist samples carry a spike of +-``spike_height`` rad
``exact_torque``       the torque channel is the commanded torque (no noise)
``skip_half_cycle``    the record starts after the first half cycle (not from the virgin state)
``invert_twist``       the twist channel's sign is inverted
``torque_step``,       the channels are quantised to these steps (N m, rad; 0: not quantised)
``twist_step``
``friction_end``,      running-in: the friction changes linearly with the cycle number from f
``running_in_cycles``  to ``friction_end`` over ``running_in_cycles`` cycles (constant on each
                       branch, changed at the reversals; the torque clipped at the gross-slip
                       torque of the branch's friction)
=====================  ======================================================================

``rig_record`` returns a ``RigRecord``: the recorded channels, the noise-free and defect-free
channels (the physics, for checks) and the truth (f, G, the compliance a loop fit sees and the
rig's own).
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass, field

import numpy as np
from scipy.interpolate import PchipInterpolator

from .. import models, validation

__all__ = ["RigSpecimen", "RigDefects", "RigRecord", "MasingWalk", "rig_record", "DEFECT_NAMES"]


@dataclass(frozen=True)
class RigSpecimen:
    """A specimen in its rig (SI): contact radius a, gauge length L, shear modulus G, friction f, normal
    force F, the rig's own compliance C_rig (rad/(N m)), the contact ``model`` (a name of ``models.MODELS``
    or a ``ContactModel``) and the twist channel's zero (rad)."""

    radius: float = 5e-3
    gauge_length: float = 20e-3
    shear_modulus: float = 80e9
    friction: float = 0.6
    normal_force: float = 1000.0
    rig_compliance: float = 1.5e-4
    model: object = None
    twist_zero: float = 1e-4

    def __post_init__(self):
        for name, low in (("radius", 0.0), ("gauge_length", 0.0), ("shear_modulus", 0.0), ("friction", 0.0),
                          ("normal_force", 0.0), ("rig_compliance", 0.0)):
            value = validation.real_number(name, getattr(self, name))
            if not value > low and not (name == "rig_compliance" and value == 0.0):
                raise ValueError(f"{name} must be > 0, got {value!r}")
        validation.real_number("twist_zero", self.twist_zero)
        models.get(self.model)

    @property
    def contact(self):
        """The contact model object."""
        return models.get(self.model)

    def slip_torque(self, friction: float | None = None) -> float:
        """T_s = f F a / 2 (N m): the unit of T* (eq. 32)."""
        return 0.5 * (self.friction if friction is None else friction) * self.normal_force * self.radius

    def gross_slip_torque(self, friction: float | None = None) -> float:
        """The torque (N m) at which the contact spins: the model's gross-slip T* times T_s."""
        return self.contact.gross_slip_torque * self.slip_torque(friction)

    def twist_unit(self, friction: float | None = None) -> float:
        """f p-bar / G (rad): the unit of the rigid rotation."""
        f = self.friction if friction is None else friction
        return f * self.normal_force / (math.pi * self.radius**2) / self.shear_modulus

    @property
    def shaft_compliance(self) -> float:
        """L / (G J), J = pi a^4 / 2 (rad/(N m)): the shafts over the gauge length (0 for bodies that are not
        shafts)."""
        if not self.contact.shaft:
            return 0.0
        return self.gauge_length / (self.shear_modulus * 0.5 * math.pi * self.radius**4)

    @property
    def compliance(self) -> float:
        """The linear part of the twist per torque (rad/(N m)): shafts and rig, what a loop fit calls C."""
        return self.shaft_compliance + self.rig_compliance

    def skeleton(self, torque_star, friction: float | None = None):
        """h(T*): twist (rad) of the virgin loading to 0 <= T* <= gross slip (module docstring; vectorised)."""
        contact = self.contact
        tau = np.asarray(torque_star, dtype=float)
        omega = contact.rotation(tau)
        gauge = self.gauge_length / self.radius if contact.shaft else None
        twist = self.twist_unit(friction) * contact.contact_twist(tau, omega, gauge)
        return twist + self.rig_compliance * self.slip_torque(friction) * tau

    def skeleton_inverse(self, twist, friction: float | None = None):
        """T* >= 0 on the virgin curve at twist >= 0 (``skeleton`` inverted; the gross-slip torque beyond the
        twist where the model's rotation becomes unbounded).  A table of ``INVERSE_CELLS`` cells graded toward the
        gross-slip torque brackets each root, its monotone cubic interpolant gives a start and ``NEWTON_STEPS``
        Newton steps on ``skeleton`` itself (with the table's slope) refine it: the twist residual is below 1e-11
        rad of a 1e-3 rad twist except within 1e-9 of the gross-slip torque, where the rotation grows like a
        logarithm (the tests measure it).  Vectorised."""
        nodes, values, inverse = _inverse_table(self, self.friction if friction is None else friction)
        top = self.contact.gross_slip_torque
        y = np.asarray(twist, dtype=float)
        out = np.full(y.shape, top)
        inside = y < values[-1]
        if not inside.any():
            return out
        yi = np.maximum(y[inside], 0.0)
        j = np.clip(np.searchsorted(values, yi, side="right") - 1, 0, nodes.size - 2)
        lo, hi = nodes[j], nodes[j + 1]
        slope = inverse.derivative()(yi)  # dT*/dtwist, from the table
        mid = np.clip(inverse(yi), lo, hi)
        for _ in range(NEWTON_STEPS):  # Newton with the table's slope, kept inside the bracket
            mid = np.clip(mid - (self.skeleton(mid, friction) - yi) * slope, lo, hi)
        out[inside] = mid
        return out


#: Cells of the table that brackets the inverse skeleton's roots.
INVERSE_CELLS = 4096
#: Newton steps from the table's interpolant.
NEWTON_STEPS = 3
_INVERSE_TABLES: dict = {}


def _inverse_table(specimen: RigSpecimen, friction: float):
    """(T* nodes, skeleton twists) on a grid graded toward the gross-slip torque, cached per specimen and friction."""
    key = (specimen, float(friction))
    table = _INVERSE_TABLES.get(key)
    if table is None:
        top = specimen.contact.gross_slip_torque
        u = np.linspace(0.0, 1.0, INVERSE_CELLS + 1)
        # graded toward the gross-slip end, where the rotation may grow like a logarithm
        nodes = top * (1.0 - (1.0 - u) ** 3)
        nodes[-1] = top * (1.0 - 1e-12)
        table = (nodes, specimen.skeleton(nodes, friction))
        table = table + (PchipInterpolator(table[1], table[0]),)
        if len(_INVERSE_TABLES) > 64:
            _INVERSE_TABLES.clear()
        _INVERSE_TABLES[key] = table
    return table


class MasingWalk:
    """Masing's rules with memory for one skeleton S (x >= 0 -> y, increasing, odd continuation), walked over a
    drive sequence that contains its turning points (module docstring).  ``skeleton(x, branch)`` may depend on
    the branch number (0: virgin loading), and ``clip(y, branch)`` bounds the response (or None)."""

    def __init__(self, skeleton, clip=None):
        self.skeleton = skeleton
        self.clip = clip

    def walk(self, drive) -> np.ndarray:
        """The response y at every value of ``drive`` (starting from the virgin state x = 0, y = 0)."""
        x = np.concatenate([[0.0], np.asarray(drive, dtype=float)])
        y = np.empty_like(x)
        y[0] = 0.0
        step = np.sign(np.diff(x))
        # segments: maximal runs of one direction (zero steps join the run they sit in)
        direction = 0.0
        stack: list[tuple[float, float]] = []  # reversal points (x_r, y_r), oldest first
        branch = 0
        i = 1
        n = x.size
        while i < n:
            d = step[i - 1]
            if d == 0.0:
                y[i] = y[i - 1]
                i += 1
                continue
            if direction != 0.0 and d != direction:
                stack.append((x[i - 1], y[i - 1]))  # a reversal at the last sample
                branch += 1
            direction = d
            j = i
            while j < n and step[j - 1] != -d:
                j += 1
            self._segment(x, y, i, j, d, stack, branch)
            i = j
        return y[1:]

    def _branch(self, xs, d, stack, branch):
        if not stack:
            y = np.sign(xs) * self.skeleton(np.abs(xs), branch)
        else:
            xr, yr = stack[-1]
            y = yr + d * 2.0 * self.skeleton(np.maximum(d * (xs - xr), 0.0) / 2.0, branch)
        if self.clip is not None:
            y = self.clip(y, branch)
        return y

    def _segment(self, x, y, i, j, d, stack, branch):
        """Fill y[i:j] (a run of direction d), closing loops of the stack as the run passes their levels."""
        while i < j:
            if not stack:
                y[i:j] = self._branch(x[i:j], d, stack, branch)
                return
            level = stack[-2][0] if len(stack) >= 2 else -stack[-1][0]
            beyond = d * (x[i:j] - level) > 0.0
            if not beyond.any():
                y[i:j] = self._branch(x[i:j], d, stack, branch)
                return
            k = i + int(np.argmax(beyond))
            y[i:k] = self._branch(x[i:k], d, stack, branch)
            # the loop closes at the level: forget its two reversals (or, from the first, rejoin the virgin curve)
            del stack[-2 if len(stack) >= 2 else -1:]
            i = k


@dataclass(frozen=True)
class RigDefects:
    """What a rig adds to the physics (module docstring's table).  Defaults: a perfect rig."""

    lag: float = 0.0
    drift: float = 0.0
    torque_offset: float = 0.0
    spikes: int = 0
    spike_height: float = 5e-4
    exact_torque: bool = False
    skip_half_cycle: bool = False
    invert_twist: bool = False
    torque_step: float = 0.0
    twist_step: float = 0.0
    friction_end: float | None = None
    running_in_cycles: float = 20.0

    def __post_init__(self):
        for name in ("lag", "drift", "torque_offset", "spike_height", "torque_step", "twist_step",
                     "running_in_cycles"):
            validation.real_number(name, getattr(self, name))
        for name in ("lag", "spike_height", "torque_step", "twist_step"):
            if getattr(self, name) < 0:
                raise ValueError(f"{name} must be >= 0, got {getattr(self, name)!r}")
        if isinstance(self.spikes, bool) or not isinstance(self.spikes, (int, np.integer)) or self.spikes < 0:
            raise ValueError(f"spikes must be an integer >= 0, got {self.spikes!r}")
        if not self.running_in_cycles > 0:
            raise ValueError(f"running_in_cycles must be > 0, got {self.running_in_cycles!r}")
        if self.friction_end is not None and not validation.real_number("friction_end", self.friction_end) > 0:
            raise ValueError(f"friction_end must be > 0, got {self.friction_end!r}")

    def active(self) -> tuple[str, ...]:
        """The names of the defects present."""
        perfect = RigDefects()
        names = [k for k in DEFECT_NAMES if getattr(self, k) != getattr(perfect, k)]
        return tuple(names)


#: The defect fields of ``RigDefects`` that change a record (``spike_height`` and ``running_in_cycles`` only size
#: ``spikes`` and ``friction_end``).
DEFECT_NAMES = ("lag", "drift", "torque_offset", "spikes", "exact_torque", "skip_half_cycle", "invert_twist",
                "torque_step", "twist_step", "friction_end")


@dataclass(frozen=True)
class RigRecord:
    """One record: the channels as written (``time`` s, ``torque`` N m, ``twist`` rad), the physics at the same
    times (``clean_torque``, ``clean_twist``: no noise, no defect, twist zero excluded), the noise levels used
    (standard deviations: ``torque_noise`` N m, ``twist_noise`` rad), the truth and the settings."""

    time: np.ndarray = field(repr=False)
    torque: np.ndarray = field(repr=False)
    twist: np.ndarray = field(repr=False)
    clean_torque: np.ndarray = field(repr=False)
    clean_twist: np.ndarray = field(repr=False)
    torque_noise: float
    twist_noise: float
    truth: dict
    control: str
    amplitude: float
    frequency: float
    sample_rate: float
    specimen: RigSpecimen
    defects: RigDefects
    spike_indices: np.ndarray = field(repr=False, default_factory=lambda: np.empty(0, dtype=int))

    def metadata(self) -> dict:
        """JSON-ready settings and truth."""
        specimen = asdict(self.specimen)
        specimen["model"] = self.specimen.contact.name
        return {"control": self.control, "amplitude": self.amplitude, "frequency": self.frequency,
                "sample_rate": self.sample_rate, "samples": int(self.time.size), "torque_noise": self.torque_noise,
                "twist_noise": self.twist_noise, "truth": self.truth, "specimen": specimen,
                "defects": asdict(self.defects)}


def _turning_times(frequency: float, t_end: float) -> np.ndarray:
    """Times of the extremes of sin(2 pi nu t) in [0, t_end]: (1/4 + m/2) / nu."""
    count = int(math.floor(2.0 * frequency * t_end - 0.5)) + 1
    return (0.25 + 0.5 * np.arange(max(count, 0))) / frequency


def _branch_friction(specimen: RigSpecimen, defects: RigDefects, branch) -> np.ndarray:
    """The friction of a branch (0: the virgin loading; branch k starts at the k-th reversal, cycle k / 2)."""
    cycle = 0.5 * np.asarray(branch, dtype=float)
    if defects.friction_end is None:
        return np.full(cycle.shape, specimen.friction)
    share = np.minimum(cycle / defects.running_in_cycles, 1.0)
    return specimen.friction + (defects.friction_end - specimen.friction) * share


def rig_record(specimen: RigSpecimen | None = None, *, control: str = "torque", amplitude: float = 1.3,
               mean: float = 0.0, cycles: float = 2.0, frequency: float = 1.0, sample_rate: float = 200.0,
               torque_noise: float = 0.005, twist_noise: float = 1e-5, defects: RigDefects | None = None,
               rng=None) -> RigRecord:
    """A record of a rig driven sinusoidally from the virgin state (module docstring).

    Parameters
    ----------
    specimen : RigSpecimen (default: a = 5 mm, L = 20 mm, G = 80 GPa, f = 0.6, F = 1 kN, cylinders)
    control : "torque" (T = T_s (mean + amplitude sin 2 pi nu t), ``amplitude`` and ``mean`` in T*) or
        "twist" (theta = amplitude sin 2 pi nu t + twist zero, ``amplitude`` in rad, ``mean`` must be 0)
    cycles, frequency, sample_rate : record length in cycles, drive frequency nu (Hz), samples per second
    torque_noise : standard deviation of the torque noise as a fraction of the torque range (0: none)
    twist_noise : standard deviation of the twist noise (rad)
    defects : RigDefects (default none)
    rng : numpy Generator or seed of the noise and the spikes

    Raises
    ------
    ValueError naming the argument (a torque amplitude at or beyond gross slip, a bad control, ...).
    """
    specimen = RigSpecimen() if specimen is None else specimen
    defects = RigDefects() if defects is None else defects
    rng = np.random.default_rng(rng)
    if control not in ("torque", "twist"):
        raise ValueError(f"control must be 'torque' or 'twist', got {control!r}")
    amplitude = validation.real_number("amplitude", amplitude)
    mean = validation.real_number("mean", mean)
    cycles = validation.real_number("cycles", cycles)
    frequency = validation.real_number("frequency", frequency)
    sample_rate = validation.real_number("sample_rate", sample_rate)
    torque_noise = validation.real_number("torque_noise", torque_noise)
    twist_noise = validation.real_number("twist_noise", twist_noise)
    for name, value in (("amplitude", amplitude), ("cycles", cycles), ("frequency", frequency),
                        ("sample_rate", sample_rate)):
        if not value > 0:
            raise ValueError(f"{name} must be > 0, got {value!r}")
    for name, value in (("torque_noise", torque_noise), ("twist_noise", twist_noise)):
        if value < 0:
            raise ValueError(f"{name} must be >= 0, got {value!r}")
    contact = specimen.contact
    end_friction = specimen.friction if defects.friction_end is None else min(specimen.friction, defects.friction_end)
    limit = contact.gross_slip_torque * end_friction / specimen.friction
    if control == "torque" and not abs(mean) + amplitude < limit:
        raise ValueError(f"|mean| + amplitude must lie below the gross-slip torque {limit:g} (T*; the {contact.bodies} "
                         f"spin) under torque control, got {abs(mean) + amplitude!r}")
    if control == "twist" and mean != 0.0:
        raise ValueError(f"mean must be 0 under twist control (the twist zero is arbitrary), got {mean!r}")
    start = 0.5 / frequency if defects.skip_half_cycle else 0.0
    n = int(round(cycles * sample_rate / frequency)) + 1
    time = start + np.arange(n) / sample_rate
    # the physics on the union of the sample times, the lagged times and the drive's turning points
    lagged = time - defects.lag
    grid = np.unique(np.concatenate([time, lagged[lagged > 0.0], _turning_times(frequency, time[-1])]))
    phase = np.sin(2.0 * np.pi * frequency * grid)

    def friction_of(branch):
        return _branch_friction(specimen, defects, branch)

    if control == "torque":
        drive = mean + amplitude * phase  # T*, of the initial friction

        def skeleton(x, branch):
            f = float(friction_of(branch))
            return specimen.skeleton(x * specimen.friction / f, f)

        twist = MasingWalk(skeleton).walk(drive)
        torque = drive * specimen.slip_torque()
    else:
        drive = amplitude * phase

        def skeleton(x, branch):
            f = float(friction_of(branch))
            return specimen.skeleton_inverse(x, f) * specimen.slip_torque(f)

        def clip(y, branch):
            top = specimen.gross_slip_torque(float(friction_of(branch)))
            return np.clip(y, -top, top)

        torque = MasingWalk(skeleton, clip).walk(drive)
        twist = drive
    position = np.searchsorted(grid, time)
    clean_torque, clean_twist = torque[position], twist[position]
    lag_position = np.searchsorted(grid, lagged)
    seen_twist = np.where(lagged > 0.0, twist[np.minimum(lag_position, grid.size - 1)], 0.0)
    torque_sd = 0.0 if defects.exact_torque else torque_noise * float(np.ptp(clean_torque))
    out_torque = clean_torque + defects.torque_offset + torque_sd * rng.standard_normal(n)
    out_twist = seen_twist + specimen.twist_zero + defects.drift * time + twist_noise * rng.standard_normal(n)
    spikes = np.empty(0, dtype=int)
    if defects.spikes:
        if defects.spikes > n - 2:
            raise ValueError(f"spikes must be at most {n - 2} for this record, got {defects.spikes!r}")
        spikes = np.sort(rng.choice(np.arange(1, n - 1), size=defects.spikes, replace=False))
        out_twist[spikes] += defects.spike_height * rng.choice([-1.0, 1.0], size=spikes.size)
    if defects.torque_step > 0:
        out_torque = defects.torque_step * np.round(out_torque / defects.torque_step)
    if defects.twist_step > 0:
        out_twist = defects.twist_step * np.round(out_twist / defects.twist_step)
    if defects.invert_twist:
        out_twist = -out_twist
    truth = {"friction": specimen.friction, "shear_modulus": specimen.shear_modulus,
             "compliance": specimen.compliance, "rig_compliance": specimen.rig_compliance,
             "shaft_compliance": specimen.shaft_compliance, "model": contact.name,
             "max_torque_ratio": float(np.max(np.abs(clean_torque)) / specimen.slip_torque())}
    if defects.friction_end is not None:
        count = int(math.ceil(cycles))
        odd = 2 * np.arange(1, count + 1) - 1  # cycle m: the branches from its two reversals, 2m - 1 and 2m
        truth["friction_per_cycle"] = [float(f) for f in 0.5 * (friction_of(odd) + friction_of(odd + 1))]
    return RigRecord(time=time, torque=out_torque, twist=out_twist, clean_torque=clean_torque,
                     clean_twist=clean_twist, torque_noise=torque_sd, twist_noise=twist_noise, truth=truth,
                     control=control, amplitude=amplitude, frequency=frequency, sample_rate=sample_rate,
                     specimen=specimen, defects=defects, spike_indices=spikes)
