"""Physical quantities at the boundary: SI floats from numbers, pint quantities or strings such as "5 mm".

The solvers work in the normalised units of docs/conventions.md; only ``specimen``, the
fitting of measured loops and the command line's specimen options see physical units, and
they turn every value into a float in SI units here, once, checking its dimension.

A value is accepted as

* a real number: already in the SI unit of its kind (m, N, Pa, N m, rad, s, J);
* a pint ``Quantity`` (of any registry): converted with its own registry;
* a string with a number and a unit, parsed by pint: "5 mm", "1 kN", "80 GPa", "1.8 N*m",
  "1.8 N m", "1.8 N·m", "2 kN m", "300 N mm", "1.5 mrad", "0.1 deg".  Lab exports often
  write the newton metre "Nm" (pint reads it as another unit): "Nm", "kNm", "mNm", "Nmm"
  are read as N m, kN m, mN m, N mm.

A value of the wrong dimension ("1 kN" for a radius) raises ValueError naming the argument,
the dimension it needs and the dimension it has.  pint's registry is built on first use
(about half a second), so that importing the package stays cheap.
"""

from __future__ import annotations

import functools
import math
import numbers
import re

import numpy as np

__all__ = ["KINDS", "registry", "parse_unit", "si_value", "si_array", "si_unit", "positive_si"]

#: kind -> (pint dimensionality, SI unit as printed, examples for messages)
KINDS = {
    "length": ("[length]", "m", '"5 mm", "0.005 m" or a number in m'),
    "force": ("[force]", "N", '"1 kN", "1000 N" or a number in N'),
    "pressure": ("[pressure]", "Pa", '"80 GPa", "8e10 Pa" or a number in Pa'),
    "torque": ("[energy]", "N m", '"1.8 N m", "1.8 N*m", "1800 N mm" or a number in N m'),
    "energy": ("[energy]", "J", '"1 mJ" or a number in J'),
    "angle": ("", "rad", '"1.5 mrad", "0.1 deg" or a number in rad'),
    "time": ("[time]", "s", '"2 ms" or a number in s'),
    "dimensionless": ("", "1", "a plain number"),
}

#: Names of common dimensionalities, for error messages.
_DIMENSION_NAMES = {
    "[length]": "a length",
    "[mass] * [length] / [time] ** 2": "a force",
    "[mass] / [length] / [time] ** 2": "a pressure (stress, modulus)",
    "[mass] * [length] ** 2 / [time] ** 2": "a torque or energy",
    "[time]": "a time",
    "dimensionless": "dimensionless (a number or an angle)",
    "[mass]": "a mass",
    "[length] ** 2": "an area",
}

#: Newton-metre spellings of lab exports that pint reads otherwise ("Nm" is a "number metre" to pint).
_NEWTON_METRE = re.compile(r"(?<![A-Za-z])([mkM]?)Nm(m?)(?![A-Za-z])")
_PRODUCT_SIGNS = str.maketrans({"·": "*", "⋅": "*", "•": "*", "×": "*"})


@functools.lru_cache(maxsize=1)
def registry():
    """The package's pint UnitRegistry (built once, on first use)."""
    import pint

    return pint.UnitRegistry()


def _normalise_text(text: str) -> str:
    text = text.strip().translate(_PRODUCT_SIGNS)
    return _NEWTON_METRE.sub(lambda m: f"{m.group(1)}N*{'mm' if m.group(2) else 'm'}", text)


def _dimension_name(quantity) -> str:
    dims = str(quantity.dimensionality)
    return _DIMENSION_NAMES.get(dims, dims)


def _check_kind(name: str, kind: str) -> tuple[str, str, str]:
    if kind not in KINDS:
        raise ValueError(f"unknown kind of quantity {kind!r} for {name} (one of {', '.join(KINDS)})")
    return KINDS[kind]


def parse_unit(name: str, text: str, kind: str) -> float:
    """The factor that converts a value in unit ``text`` (e.g. "N mm") to the SI unit of ``kind``.

    Raises ValueError naming ``name`` for a unit pint does not know or one of another dimension.
    """
    dimensionality, si_unit, examples = _check_kind(name, kind)
    if not isinstance(text, str) or not text.strip():
        raise ValueError(f"{name}: expected a unit of {kind} ({si_unit}), got {text!r}")
    return _to_si(name, "1 " + _normalise_text(text), kind, text)


def _to_si(name: str, text: str, kind: str, shown) -> float:
    import pint

    dimensionality, si_unit, examples = KINDS[kind]
    try:
        quantity = registry().Quantity(text)
    except (pint.errors.PintError, ValueError, TypeError, AttributeError, SyntaxError, KeyError):
        raise ValueError(f"{name}: cannot read {shown!r} as {kind} (examples: {examples})") from None
    return _quantity_to_si(name, quantity, kind, shown)


def _quantity_to_si(name: str, quantity, kind: str, shown) -> float:
    dimensionality, si_unit, examples = KINDS[kind]
    fits = quantity.dimensionless if not dimensionality else quantity.check(dimensionality)
    if not fits:
        raise ValueError(f"{name} must be {_kind_phrase(kind)} (unit {si_unit}), got {shown!r}, which is "
                         f"{_dimension_name(quantity)}")
    unit = {"angle": "radian", "dimensionless": "dimensionless"}.get(kind, si_unit.replace(" ", "*"))
    unit = {"N": "newton", "Pa": "pascal", "N*m": "newton*meter", "J": "joule", "m": "meter", "s": "second"}.get(
        unit, unit)
    magnitude = quantity.m_as(unit)
    if isinstance(magnitude, np.ndarray):
        return magnitude.astype(float)
    return float(magnitude)


def _kind_phrase(kind: str) -> str:
    return {"length": "a length", "force": "a force", "pressure": "a pressure (a stress or modulus)",
            "torque": "a torque", "energy": "an energy", "angle": "an angle", "time": "a time",
            "dimensionless": "a plain number"}[kind]


def si_value(name: str, value, kind: str) -> float:
    """``value`` (number in SI units, pint quantity or string with a unit) as a float in the SI unit of ``kind``.

    Raises ValueError naming ``name`` for a value of another dimension, a string pint cannot
    read, a boolean or anything else that is not a number.  Finiteness is not checked here.
    """
    _check_kind(name, kind)
    if isinstance(value, bool) or isinstance(value, np.bool_):
        raise ValueError(f"{name} must be {_kind_phrase(kind)}, got {value!r}")
    if isinstance(value, (numbers.Real, np.floating, np.integer)):
        return float(value)
    if isinstance(value, str):
        text = _normalise_text(value)
        try:  # a plain number in a string: SI
            return float(text)
        except ValueError:
            pass
        return _to_si(name, text, kind, value)
    if hasattr(value, "dimensionality") and hasattr(value, "m_as"):  # a pint Quantity of any registry
        out = _quantity_to_si(name, value, kind, str(value))
        if np.ndim(out) != 0:
            raise ValueError(f"{name} must be a single value, got an array of shape {np.shape(out)}")
        return float(out)
    raise ValueError(f"{name} must be {_kind_phrase(kind)}: a number in {KINDS[kind][1]}, a pint quantity or a "
                     f"string such as {KINDS[kind][2].split(' or ')[0]}, got {value!r}")


def si_array(name: str, values, kind: str) -> np.ndarray:
    """A 1-d float array in SI units from numbers, a pint quantity array, or a sequence of values/strings."""
    _check_kind(name, kind)
    if hasattr(values, "dimensionality") and hasattr(values, "m_as"):
        return np.atleast_1d(np.asarray(_quantity_to_si(name, values, kind, f"<array in {values.units}>"), float))
    if isinstance(values, (str, bytes)) or np.ndim(values) == 0:
        return np.array([si_value(name, values, kind)])
    array = np.asarray(values, dtype=object).ravel() if not isinstance(values, np.ndarray) else values.ravel()
    if isinstance(array, np.ndarray) and array.dtype.kind in "fiu":
        return array.astype(float)
    return np.array([si_value(f"{name}[{i}]", v, kind) for i, v in enumerate(array)], dtype=float)


def si_unit(kind: str) -> str:
    """The SI unit of ``kind`` as printed in results (e.g. "N m")."""
    return KINDS[kind][1]


def positive_si(name: str, value, kind: str, *, allow_zero: bool = False, maximum: float | None = None) -> float:
    """``si_value`` that must also be finite and > 0 (>= 0 with ``allow_zero``, <= ``maximum`` if given)."""
    x = si_value(name, value, kind)
    unit = KINDS[kind][1]
    low = "> 0" if not allow_zero else ">= 0"
    valid = f"finite and {low}" + (f" and <= {maximum:g} {unit}" if maximum is not None else "")
    if not math.isfinite(x) or x < 0 or (x == 0 and not allow_zero) or (maximum is not None and x > maximum):
        where = "" if kind == "dimensionless" else f" (in {unit})"
        raise ValueError(f"{name} must be {valid}{where}, got {value!r}")
    return x
