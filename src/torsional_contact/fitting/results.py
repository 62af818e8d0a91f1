"""What a loop fit reports: ``Estimate`` (one fitted quantity with its interval or bounds) and ``LoopFit``.

Units as in ``fitting.loop_fit``: friction 1, shear modulus Pa, compliance rad / (N m), torque N m, twist rad.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np


@dataclass(frozen=True)
class Estimate:
    """A fitted quantity: ``value``, ``stderr``, ``interval`` (lower, upper; None: unbounded or undefined).

    ``identified`` is false when the data do not bound the quantity on both sides: ``value`` and
    ``stderr`` are then None, ``interval`` holds what the data do say (None: unbounded) and
    ``lower_bound`` its lower end.  ``assumed_end`` ("lower" or "upper") names an end of the interval
    set by the model's bound kappa <= ``loop_fit.KAPPA_MAX`` rather than by the data.  ``bootstrap_interval``:
    the bias-corrected percentile interval of a parametric bootstrap, when asked for, and ``bootstrap_bias`` its
    bias correction z_0 = Phi^-1(fraction of the refits below the estimate): the estimator's median bias in
    standard errors, with the opposite sign (``fitting.bootstrap``).  ``withheld`` names the check that withheld
    the quantity ("lag": a lag explains the loop as well as slip; "model": another contact model fits the loop
    better); ``value`` and ``interval`` are then None, and a known G does not bring it back.
    """

    value: float | None
    stderr: float | None
    interval: tuple[float | None, float | None]
    identified: bool = True
    lower_bound: float | None = None
    bootstrap_interval: tuple[float | None, float | None] | None = None
    assumed_end: str | None = None
    bootstrap_bias: float | None = None
    withheld: str | None = None

    @classmethod
    def withheld_by(cls, check: str) -> Estimate:
        """No value and no interval: the check ``check`` withheld the quantity."""
        return cls(None, None, (None, None), identified=False, withheld=check)

    def as_dict(self) -> dict:
        out = {"value": _json(self.value), "stderr": _json(self.stderr),
               "interval": [_json(self.interval[0]), _json(self.interval[1])], "identified": self.identified}
        if self.lower_bound is not None:
            out["lower_bound"] = _json(self.lower_bound)
        if self.assumed_end is not None:
            out["assumed_end"] = self.assumed_end
        if self.bootstrap_interval is not None:
            out["bootstrap_interval"] = [_json(self.bootstrap_interval[0]), _json(self.bootstrap_interval[1])]
        if self.bootstrap_bias is not None:
            out["bootstrap_bias"] = _json(self.bootstrap_bias)
        if self.withheld is not None:
            out["withheld"] = self.withheld
        return out


def _json(x):
    return None if x is None or not math.isfinite(x) else float(x)


@dataclass(frozen=True)
class LoopFit:
    """Result of ``fit_loop`` (module docstring).  ``friction`` is None-valued when the loop never slipped.

    Attributes
    ----------
    friction, shear_modulus (Pa), compliance (rad / (N m)), twist_offset (rad) : Estimate
    correlation : float or None
        Correlation of the friction and modulus estimates (None unless both are identified).
    residual_rms : float
        RMS twist residual (rad) off the gross-slip plateaus, (T_i - T_model) / (dT/dtheta).
    torque_residual_rms : float
        RMS torque residual (N m) over every sample.
    noise : dict
        The noise levels of the channels (``torque`` N m, ``twist`` rad) and whether they were ``estimated``; for a
        long record whose torque was fitted as a smooth function of time (``fitting.smoothing``) also the smoothed
        channel's level ``torque_smoothed`` (N m) and the spline's ``spline_coefficients``.
    noise_scale : float
        sqrt(reduced chi-square): 1 when the distances match the noise levels.
    regime : str
        "stick", "partial-slip" or "gross-slip": the largest |T*| the fitted loop reaches.
    slip_detected : bool
    stick_test : float
        Likelihood-ratio statistic of stick against the full model (residual variances).
    stick_critical : float
        Its critical value at the test's level (1 - confidence), by Davies' bound.
    noise_limited : bool
        The noise hides a parameter: f or G has only a bound (module docstring, "Limits"); a
        ``NoiseLimitedFitWarning`` was raised.
    interval_method : str
        "profile likelihood" (slip) or "wald" (stick: C and theta_0 of a straight line, exact).
    message : str
    samples, reversals, dof : int
    fitted_torque : ndarray
        The model's torque at every measured twist (N m).
    bootstrap : int
        Number of parametric-bootstrap refits behind ``bootstrap_interval`` (0: none).
    warnings : tuple of str
        One line per defect of the record found (spikes removed, lag, drift, offset, non-virgin start, residuals
        that are not noise, a failed optimisation, ...): each names the defect; empty when none.
    spikes : int
        Samples removed as spikes before the fit (``fitting.record_checks``).
    rig_compliance : Estimate or None
        With the shear modulus and the gauge length given: the rig's own compliance C - L / (G J) (rad / (N m),
        ``fitting.known_modulus``).
    cycles : tuple of dict or None
        With ``per_cycle``: one fit per whole cycle (``fitting.per_cycle``): ``cycle``, ``friction``, ``compliance``
        ({value, stderr, interval}), ``regime``, ``warnings``, ``start``, ``end`` (sample indices) [, ``time``].
    parameters : ndarray or None
        The fitted parameter vector [T_s (N m), kappa, C (rad/(N m)), theta_0 (rad), U_1..U_M (rad)]
        (``fitting.loop_model``); None in stick.
    """

    friction: Estimate
    shear_modulus: Estimate
    compliance: Estimate
    twist_offset: Estimate
    correlation: float | None
    residual_rms: float
    torque_residual_rms: float
    noise: dict
    noise_scale: float
    regime: str
    slip_detected: bool
    stick_test: float
    stick_critical: float
    noise_limited: bool
    interval_method: str
    message: str
    samples: int
    reversals: int
    dof: int
    radius: float
    normal_force: float
    confidence: float
    fitted_torque: np.ndarray = field(repr=False)
    bootstrap: int = 0
    parameters: np.ndarray | None = field(default=None, repr=False)
    warnings: tuple = ()
    spikes: int = 0
    cycles: tuple | None = None
    rig_compliance: Estimate | None = None

    def as_dict(self) -> dict:
        """JSON-ready (non-finite numbers -> None); ``fitted_torque`` is left out."""
        return {
            "friction": self.friction.as_dict(),
            "shear_modulus": self.shear_modulus.as_dict(),
            "compliance": self.compliance.as_dict(),
            "twist_offset": self.twist_offset.as_dict(),
            "correlation": _json(self.correlation),
            "residual_rms": _json(self.residual_rms),
            "torque_residual_rms": _json(self.torque_residual_rms),
            "noise": {k: (_json(v) if isinstance(v, float) else v) for k, v in self.noise.items()},
            "noise_scale": _json(self.noise_scale),
            "regime": self.regime,
            "slip_detected": self.slip_detected,
            "stick_test": _json(self.stick_test),
            "stick_critical": _json(self.stick_critical),
            "noise_limited": self.noise_limited,
            "interval_method": self.interval_method,
            "confidence": self.confidence,
            "bootstrap": self.bootstrap,
            "message": self.message,
            "samples": self.samples,
            "reversals": self.reversals,
            "dof": self.dof,
            "radius": self.radius,
            "normal_force": self.normal_force,
            "warnings": list(self.warnings),
            "spikes": self.spikes,
            **({} if self.cycles is None else {"cycles": [dict(c) for c in self.cycles]}),
            **({} if self.rig_compliance is None else {"rig_compliance": self.rig_compliance.as_dict()}),
            "units": {"shear_modulus": "Pa", "compliance": "rad/(N m)", "twist_offset": "rad", "residual_rms": "rad",
                      "torque_residual_rms": "N m", "radius": "m", "normal_force": "N", "rig_compliance": "rad/(N m)",
                      "noise": {"torque": "N m", "twist": "rad", "torque_smoothed": "N m"}},
        }
