"""Result records: every key a result writes, declared once with the physical quantity it measures.

A record is a frozen dataclass made by ``record``; each of its fields says what it holds in its
metadata, through one of

* ``measured(quantity)``: a number (or a list of numbers) in the normalised unit of a physical
  ``quantity`` of ``QUANTITIES`` ("torque", "length", "stress", ...);
* ``plain()``: something without a unit (a count, a name, a flag, a fraction);
* ``nested()``: another record, or a list of records;
* ``extra()``: a dict of plain values written at the record's own level (a backend's metadata).

``record`` refuses a class with a field that says none of these, so a key cannot reach a JSON file
without saying whether, and how, it converts to SI units.  ``Record.as_dict`` gives the JSON-ready
normalised record (non-finite numbers -> None, nested records as dicts); ``Record.si_dict`` the same
in SI units, converted field by field with the factors of ``specimen.Specimen.scales`` and the units
written into a ``units`` map; records with both ``torque`` and ``rigid_rotation`` gain the ``twist`` a
rig measures (``Record.twist_keys``), and a record may name SI-only aliases (``Record.si_aliases``:
a cycle's ``energy``).  ``specimen.physical_record`` is the one place that calls it.
"""

from __future__ import annotations

import dataclasses
import math
import numbers
from collections.abc import Callable, Mapping

__all__ = ["QUANTITIES", "ABSENT", "measured", "plain", "nested", "extra", "record", "Record", "json_value",
           "SolutionRecord", "StateRecord", "SignalStateRecord", "CycleRecord", "BinRecord", "ProfileRecord",
           "SignalSummary"]

#: physical quantity -> its SI unit as printed (the factor from the normalised unit: ``Specimen.scales``).
QUANTITIES = {
    "torque": "N m",
    "length": "m",
    "stress": "Pa",
    "displacement": "m",
    "rotation": "rad",
    "energy": "J",
}

_PLAIN, _NESTED, _EXTRA = "plain", "nested", "extra"


class _Absent:
    """The value of an optional field that is left out of the record (``ABSENT``)."""

    def __repr__(self) -> str:
        return "ABSENT"


#: Default of an optional field: the key is left out of the record while it holds this.
ABSENT = _Absent()


def measured(quantity: str, **kwargs):
    """A field holding a number or a list of numbers in the normalised unit of ``quantity`` (``QUANTITIES``)."""
    if quantity not in QUANTITIES:
        raise ValueError(f"quantity must be one of {sorted(QUANTITIES)}, got {quantity!r}")
    return dataclasses.field(metadata={"quantity": quantity}, **kwargs)


def plain(**kwargs):
    """A field without a unit (a count, a name, a flag)."""
    return dataclasses.field(metadata={"quantity": _PLAIN}, **kwargs)


def nested(**kwargs):
    """A field holding a record or a list of records."""
    return dataclasses.field(metadata={"quantity": _NESTED}, **kwargs)


def extra():
    """A dict of plain values written at the record's own level."""
    return dataclasses.field(default_factory=dict, metadata={"quantity": _EXTRA})


def json_value(value):
    """A JSON-ready number or list: numpy scalars as Python numbers, non-finite floats as None."""
    if value is None or isinstance(value, (bool, str)):
        return value
    if isinstance(value, numbers.Integral):
        return int(value)
    if isinstance(value, numbers.Real):
        value = float(value)
        return value if math.isfinite(value) else None
    if isinstance(value, (list, tuple)):
        return [json_value(v) for v in value]
    if isinstance(value, Record):
        return value.as_dict()
    return value


def _scaled(value, factor: float):
    if value is None or isinstance(value, bool):
        return value
    if isinstance(value, (list, tuple)):
        return [_scaled(v, factor) for v in value]
    value = float(value) * factor
    return value if math.isfinite(value) else None


class Record:
    """Base of the records (module docstring)."""

    #: Keys (torque, rigid_rotation) from which the SI form adds the measured ``twist``; None: no twist.
    twist_keys: tuple[str, str] | None = None
    #: SI-only aliases: new key -> the key whose SI value it repeats.
    si_aliases: Mapping[str, str] = {}

    def as_dict(self) -> dict:
        """The normalised record, JSON-ready."""
        out = {}
        for f in dataclasses.fields(self):
            value = getattr(self, f.name)
            if value is ABSENT:
                continue
            if f.metadata["quantity"] == _EXTRA:
                out.update({k: json_value(v) for k, v in value.items()})
            else:
                out[f.name] = json_value(value)
        return out

    def si_dict(self, scales: Mapping[str, float], units: dict, twist: Callable | None = None) -> dict:
        """The record in SI units: each ``measured`` field times ``scales[quantity]``; ``units`` gains the unit of
        every key converted; ``twist(torque, rigid_rotation)`` (SI rad, normalised arguments) adds ``twist``."""
        out = {}
        for f in dataclasses.fields(self):
            value, quantity = getattr(self, f.name), f.metadata["quantity"]
            if value is ABSENT:
                continue
            if quantity == _EXTRA:
                out.update({k: json_value(v) for k, v in value.items()})
            elif quantity == _NESTED:
                if isinstance(value, (list, tuple)):
                    out[f.name] = [v.si_dict(scales, units, twist) for v in value]
                else:
                    out[f.name] = None if value is None else value.si_dict(scales, units, twist)
            elif quantity == _PLAIN:
                out[f.name] = json_value(value)
            else:
                out[f.name] = _scaled(value, scales[quantity])
                units[f.name] = QUANTITIES[quantity]
        for alias, key in self.si_aliases.items():
            out[alias] = out[key]
            units[alias] = units[key]
        if twist is not None and self.twist_keys is not None:
            torque, rotation = (getattr(self, k) for k in self.twist_keys)
            if torque is not None:
                value = twist(torque, rotation) if rotation is not None and math.isfinite(rotation) else None
                out["twist"] = None if value is None or not math.isfinite(value) else float(value)
                units["twist"] = "rad"
        return out


def record(cls):
    """Make ``cls`` (a ``Record`` subclass) a frozen dataclass whose every field declares its quantity."""
    if not issubclass(cls, Record):
        raise TypeError(f"{cls.__name__} must derive from Record")
    cls = dataclasses.dataclass(frozen=True)(cls)
    kinds = set(QUANTITIES) | {_PLAIN, _NESTED, _EXTRA}
    for f in dataclasses.fields(cls):
        if f.metadata.get("quantity") not in kinds:
            raise TypeError(f"{cls.__name__}.{f.name} does not declare its quantity: use measured(...), plain(), "
                            "nested() or extra() (records.py)")
    return cls


# --------------------------------------------------------------------------- the package's records
@record
class SolutionRecord(Record):
    """``Solution.as_dict``: one solution of ``solve``."""

    stick_radius: float = measured("length")
    torque: float = measured("torque")
    rigid_rotation: float = measured("rotation")
    regime: str = plain()
    method: str | None = plain()
    n_terms: int | None = plain()
    model: str = plain()
    details: dict = extra()

    twist_keys = ("torque", "rigid_rotation")


@record
class _StateFields(Record):
    """The fields of an interface state after a torque history (``StateRecord``, ``SignalStateRecord``)."""

    torque: float = measured("torque")
    stick_radius: float = measured("length")
    slip_fronts: list = measured("length")
    turning_points: list = measured("torque")
    rigid_rotation: float = measured("rotation")
    regime: str = plain()
    dissipated_energy: float = measured("energy")
    direction: int = plain()

    twist_keys = ("torque", "rigid_rotation")


@record
class StateRecord(_StateFields):
    """``InterfaceState.as_dict``: a state of ``history``."""

    method: str | None = plain()
    n_terms: int | None = plain()
    model: str = plain()


@record
class SignalStateRecord(_StateFields):
    """``SignalHistory.states``: the state at a turning point of a sampled signal (``index``: its sample)."""

    index: int = plain()


@record
class CycleRecord(Record):
    """``SignalHistory.cycles``: the closed loops of one (range, mean); ``count`` counts halves 1/2."""

    range: float = measured("torque")
    mean: float = measured("torque")
    count: float = plain()
    dissipated_energy: float = measured("energy")

    si_aliases = {"energy": "dissipated_energy"}


@record
class BinRecord(CycleRecord):
    """``SignalHistory.rainflow_bins``: the loops of one bin of the rainflow matrix (``range`` and ``mean`` its
    centre, ``range_bin`` and ``mean_bin`` its edges)."""

    range_bin: list = measured("torque")
    mean_bin: list = measured("torque")


@record
class ProfileRecord(Record):
    """Interface profiles at the radii ``radii`` (the command line's ``--radii``)."""

    radii: list = measured("length")
    traction: list = measured("stress")
    slip: list = measured("displacement")
    residual_traction: list = measured("stress", default=ABSENT)


@record
class SignalSummary(Record):
    """``history --signal``: the analysis of a sampled torque signal (``io.history_command.analyse_values``).

    ``cycles`` (loops, or rainflow bins of width ``bin_width``) and ``states`` (short signals) only in the
    full summary."""

    samples: int = plain()
    turning_points: int = plain()
    dropped_turning_points: int = plain()
    gate: float = measured("torque")
    dissipated_energy: float = measured("energy")
    closed_loops: float = plain()
    half_loops: int = plain()
    loop_energy: float = measured("energy")
    method: str | None = plain()
    n_terms: int | None = plain()
    model: str = plain()
    states_file: str | None = plain()
    output_file: str | None = plain()
    bin_width: float | None = measured("torque", default=ABSENT)
    cycles: list = nested(default=ABSENT)
    states: list = nested(default=ABSENT)
