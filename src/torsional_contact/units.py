"""Physical quantities at the boundary: SI floats from numbers, pint quantities or strings such as "5 mm".

The solvers work in the normalised units of docs/conventions.md; only ``specimen``, the
fitting of measured loops, the lab files and the command line's specimen options see physical
units, and they turn every value into a float in SI units here, once, checking its dimension.

A value is accepted as

* a real number: already in the SI unit of its kind (m, N, Pa, N m, rad, s, J);
* a pint ``Quantity`` (of any registry): converted with its own registry;
* a string of one decimal number and one unit (docs/units.md): "5 mm", "1 kN", "80 GPa",
  "1.8 N m", "1.8 N*m", "1.8 N·m", "1.8 Nm", "1.8 N-m", "300 N mm", "1.5 mrad", "0.1 deg", "2 °".

The grammar of a unit string (the same on the command line, in the API and in file headers)::

    quantity := number unit            (at most MAX_TEXT characters, blanks around allowed)
    number   := [+-] (digits [. digits] | . digits) [(e|E) [+-] digits]      (a point decimal mark)
    unit     := factor (separator factor)*       separator: blank, "*", "/", "·"
    factor   := name [("^" | "**") [-] digit]    name: letters (µ and ° included)

The unit is looked up in pint's registry as a unit (``UnitRegistry.parse_units`` on a string
this grammar accepted), never evaluated as an expression: there is no arithmetic, no
parenthesis and no number inside it, so "2 3 mm", "5 mm; 3", "9**9**9 N m", "(5 mm" and "1/0"
are refused, and nothing can take long.  A decimal comma ("5,0 mm") is refused with a hint
("write 5.0 mm"); only a file whose separator is not a comma reads decimal commas
(``io.text_tables``).  Spellings of lab exports are read case-insensitively where that is
unambiguous: deg, Deg, DEG, degree(s), ° (degrees); rad, RAD, radian(s); mrad; µrad, urad; and the
newton metre as Nm, N-m, N.m, N·m, N*m, N m (also kNm, mNm, Nmm; "nm" stays the nanometre).
An angle must be a unit of plane angle (rad, deg, ...): "%" or a plain number ratio is refused.

Bounds: a value converted to SI must be 0 or of magnitude in [MIN_MAGNITUDE, MAX_MAGNITUDE]
(1e-100 to 1e100), so that "1e300 N m" is a ValueError here and not an overflow later.  Every
failure is a ValueError naming the argument.  pint's registry is built on first use (about half
a second), so that importing the package stays cheap.
"""

from __future__ import annotations

import functools
import math
import numbers
import re

import numpy as np

__all__ = ["KINDS", "MAX_TEXT", "MIN_MAGNITUDE", "MAX_MAGNITUDE", "NUMBER", "registry", "parse_unit",
           "parse_quantity", "si_value", "si_array", "si_unit", "positive_si", "shown", "shown_text"]

#: kind -> (pint dimensionality, SI unit as printed, examples for messages)
KINDS = {
    "length": ("[length]", "m", '"5 mm", "0.005 m" or a number in m'),
    "force": ("[force]", "N", '"1 kN", "1000 N" or a number in N'),
    "pressure": ("[pressure]", "Pa", '"80 GPa", "8e10 Pa" or a number in Pa'),
    "torque": ("[energy]", "N m", '"1.8 N m", "1.8 Nm", "1800 N mm" or a number in N m'),
    "energy": ("[energy]", "J", '"1 mJ" or a number in J'),
    "angle": ("", "rad", '"1.5 mrad", "0.1 deg" or a number in rad'),
    "time": ("[time]", "s", '"2 ms" or a number in s'),
    "dimensionless": ("", "1", "a plain number"),
}

#: Longest unit string read (characters): longer text is refused before it is parsed.
MAX_TEXT = 64
#: Smallest and largest magnitude of a non-zero value in SI units.
MIN_MAGNITUDE, MAX_MAGNITUDE = 1e-100, 1e100

#: A decimal number with a point decimal mark (the whole grammar's number).
NUMBER = r"[+-]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?"
_NAME = r"[^\W\d_]+"  # letters of any script: µ, Ω; "°" is mapped to "degree" before the check
_FACTOR = rf"{_NAME}(?:(?:\^|\*\*)-?\d)?"
_UNIT = re.compile(rf"{_FACTOR}(?:(?:\s*[*/]\s*|\s+){_FACTOR})*")
_QUANTITY = re.compile(rf"\s*({NUMBER})\s*(.*?)\s*")
_NUMBER_ONLY = re.compile(rf"\s*{NUMBER}\s*")
_DECIMAL_COMMA = re.compile(r"\s*([+-]?\d*),(\d+)\s*(.*?)\s*")

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

#: The newton metre as labs write it: Nm, N-m, N.m, N·m (pint reads "Nm" as a "number metre"), with a prefix.
_NEWTON_METRE = re.compile(r"(?<![^\W\d_])([mkM]?)N\s*[-.·⋅•×*]?\s*m(m?)(?![^\W\d_])")
_PRODUCT_SIGNS = str.maketrans({"·": "*", "⋅": "*", "•": "*", "×": "*", "μ": "µ"})
#: Whole factors read case-insensitively (lower case -> pint's name): unambiguous spellings of angles.
_ANY_CASE = {"deg": "degree", "degs": "degree", "degree": "degree", "degrees": "degree", "°": "degree",
             "rad": "radian", "rads": "radian", "radian": "radian", "radians": "radian", "mrad": "milliradian",
             "µrad": "microradian", "urad": "microradian"}
_TOKEN = re.compile(r"[^\W\d_]+|°")
#: kind -> its SI unit in pint's spelling
_PINT_SI = {"length": "meter", "force": "newton", "pressure": "pascal", "torque": "newton*meter", "energy": "joule",
            "angle": "radian", "time": "second", "dimensionless": "dimensionless"}


@functools.lru_cache(maxsize=1)
def registry():
    """The package's pint UnitRegistry (built once, on first use)."""
    import pint

    return pint.UnitRegistry()


def shown_text(text, limit: int = 60) -> str:
    """``text`` as a message may show it: quoted, escaped (no control character reaches a terminal), cut at
    ``limit`` characters."""
    text = str(text)
    return repr(text[:limit] + ("..." if len(text) > limit else ""))


def shown(value: float, kind: str) -> str:
    """A value in SI units as messages print it, e.g. "0.0015 N m"."""
    unit = KINDS[kind][1]
    return f"{value:.6g}" if unit == "1" else f"{value:.6g} {unit}"


def _check_kind(name: str, kind: str) -> tuple[str, str, str]:
    if kind not in KINDS:
        raise ValueError(f"unknown kind of quantity {kind!r} for {name} (one of {', '.join(KINDS)})")
    return KINDS[kind]


def _kind_phrase(kind: str) -> str:
    return {"length": "a length", "force": "a force", "pressure": "a pressure (a stress or modulus)",
            "torque": "a torque", "energy": "an energy", "angle": "an angle", "time": "a time",
            "dimensionless": "a plain number"}[kind]


def _normalised_unit(text: str) -> str | None:
    """``text`` in pint's spelling, or None if it is not a unit of the grammar."""
    text = _NEWTON_METRE.sub(lambda m: f"{m.group(1)}N*{'mm' if m.group(2) else 'm'}", text.strip())
    text = text.translate(_PRODUCT_SIGNS)
    text = _TOKEN.sub(lambda m: _ANY_CASE.get(m.group(0).lower(), m.group(0)), text)
    text = text.replace("µ", "u")
    return text if _UNIT.fullmatch(text) else None


@functools.lru_cache(maxsize=256)
def _unit_factor(unit: str, kind: str):
    """(factor to SI, None) for a unit of ``kind`` in pint's spelling, or (None, why not)."""
    import pint

    dimensionality, si_unit, _ = KINDS[kind]
    ureg = registry()
    try:
        parsed = ureg.parse_units(unit)
    except (pint.errors.PintError, ValueError, TypeError, AttributeError, SyntaxError, KeyError, AssertionError):
        return None, "not a unit pint knows"
    try:
        root = ureg.get_root_units(parsed)[1]
    except pint.errors.PintError:  # pragma: no cover - every parsed unit has root units
        return None, "not a unit pint knows"
    angle_power = dict(root._units).get("radian", 0)
    if kind == "angle":
        if parsed.dimensionality or angle_power != 1 or len(root._units) != 1:
            return None, ("a ratio, not an angle" if not parsed.dimensionality and angle_power == 0
                          else "not a plane angle" if not parsed.dimensionality else _dimension_name(parsed))
    elif dimensionality:
        if not parsed.dimensionality == ureg.get_dimensionality(dimensionality) or angle_power:
            return None, _dimension_name(parsed) + (" per angle" if angle_power else "")
    elif parsed.dimensionality or angle_power:
        return None, "an angle" if angle_power else _dimension_name(parsed)
    return float(ureg.Quantity(1.0, parsed).m_as(_PINT_SI[kind])), None


def _dimension_name(unit) -> str:
    dims = str(unit.dimensionality)
    return _DIMENSION_NAMES.get(dims, dims)


def _unit_to_si(name: str, unit_text: str, kind: str, original: str, expected: str = "one number and one unit"
                ) -> float:
    _, si_unit, examples = KINDS[kind]
    if kind == "angle" and unit_text.strip() == "%":
        raise ValueError(f"{name}: {shown_text(original)} is a percentage, not an angle (write it in rad, mrad or "
                         "deg)")
    unit = _normalised_unit(unit_text)
    if unit is None:
        raise ValueError(f"{name}: cannot read {shown_text(original)} as {kind}: expected {expected}, "
                         f"no arithmetic (examples: {examples})")
    factor, why = _unit_factor(unit, kind)
    if factor is None:
        if why == "not a unit pint knows":
            raise ValueError(f"{name}: cannot read {shown_text(original)} as {kind}: {unit_text.strip()!r} is "
                             f"{why} (examples: {examples})")
        raise ValueError(f"{name} must be {_kind_phrase(kind)} (unit {si_unit}), got {shown_text(original)}, which is "
                         f"{why}")
    return factor


def _check_length(name: str, text: str) -> None:
    if len(text) > MAX_TEXT:
        raise ValueError(f"{name}: {shown_text(text)} is longer than {MAX_TEXT} characters: expected one number "
                         "and one unit, e.g. '5 mm'")


def parse_unit(name: str, text: str, kind: str) -> float:
    """The factor that converts a value in unit ``text`` (e.g. "N mm") to the SI unit of ``kind``.

    ``text`` is a unit of the module's grammar (no number).  Raises ValueError naming ``name`` for
    text that is not such a unit, a unit pint does not know or one of another dimension.
    """
    _, si_unit, _ = _check_kind(name, kind)
    if not isinstance(text, str) or not text.strip():
        raise ValueError(f"{name}: expected a unit of {kind} ({si_unit}), got {shown_text(text)}")
    _check_length(name, text)
    return _unit_to_si(name, text, kind, text, "one unit")


def _bounded(name: str, value: float, kind: str, original) -> float:
    if not math.isfinite(value) or (value != 0 and not MIN_MAGNITUDE <= abs(value) <= MAX_MAGNITUDE):
        raise ValueError(f"{name} must be 0 or of magnitude {MIN_MAGNITUDE:g} to {MAX_MAGNITUDE:g} "
                         f"{KINDS[kind][1]}, got {shown_text(original)}")
    return value


def parse_quantity(name: str, text: str, kind: str) -> float:
    """A string of the module's grammar (one number and one unit, or a plain number in SI) as a float in SI.

    Raises ValueError naming ``name``: longer than ``MAX_TEXT``; a decimal comma (with the hint
    "write 5.0 mm"); no number; text that is not one unit; a unit of another dimension; a value
    outside the bounds.
    """
    _check_kind(name, kind)
    _check_length(name, text)
    if _NUMBER_ONLY.fullmatch(text):
        return _bounded(name, float(text), kind, text)
    comma = _DECIMAL_COMMA.fullmatch(text)
    if comma:
        suggestion = f"{comma.group(1) or '0'}.{comma.group(2)}" + (f" {comma.group(3)}" if comma.group(3) else "")
        raise ValueError(f"{name}: {shown_text(text)} has a decimal comma: write {suggestion} (a point decimal mark)")
    match = _QUANTITY.fullmatch(text)
    if match is None or not match.group(2):
        raise ValueError(f"{name}: cannot read {shown_text(text)} as {kind}: expected one number and one unit "
                         f"(examples: {KINDS[kind][2]})")
    factor = _unit_to_si(name, match.group(2), kind, text)
    return _bounded(name, float(match.group(1)) * factor, kind, text)


def _quantity_to_si(name: str, quantity, kind: str, shown_as) -> float:
    dimensionality, si_unit, _ = KINDS[kind]
    fits = quantity.dimensionless if not dimensionality else quantity.check(dimensionality)
    if not fits:
        raise ValueError(f"{name} must be {_kind_phrase(kind)} (unit {si_unit}), got {shown_text(shown_as)}, which "
                         f"is {_dimension_name(quantity)}")
    magnitude = quantity.m_as(_PINT_SI[kind])
    if isinstance(magnitude, np.ndarray):
        return magnitude.astype(float)
    return float(magnitude)


def si_value(name: str, value, kind: str) -> float:
    """``value`` (number in SI units, pint quantity or string of the module's grammar) as a float in SI units.

    Raises ValueError naming ``name`` for a value of another dimension, a string outside the
    grammar, a boolean or anything else that is not a number.  Finiteness of numbers is not checked
    here (a string's value is: it must lie within the module's bounds).
    """
    _check_kind(name, kind)
    if isinstance(value, bool) or isinstance(value, np.bool_):
        raise ValueError(f"{name} must be {_kind_phrase(kind)}, got {value!r}")
    if isinstance(value, (numbers.Real, np.floating, np.integer)):
        return float(value)
    if isinstance(value, str):
        return parse_quantity(name, value, kind)
    if hasattr(value, "dimensionality") and hasattr(value, "m_as"):  # a pint Quantity of any registry
        out = _quantity_to_si(name, value, kind, str(value))
        if np.ndim(out) != 0:
            raise ValueError(f"{name} must be a single value, got an array of shape {np.shape(out)}")
        return float(out)
    raise ValueError(f"{name} must be {_kind_phrase(kind)}: a number in {KINDS[kind][1]}, a pint quantity or a "
                     f"string such as {KINDS[kind][2].split(' or ')[0]}, got {shown_text(value)}")


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
    """``si_value`` that must also be finite and > 0 (>= 0 with ``allow_zero``), at most ``maximum`` if given and
    within [MIN_MAGNITUDE, MAX_MAGNITUDE] unless 0."""
    x = si_value(name, value, kind)
    unit = KINDS[kind][1]
    low = "> 0" if not allow_zero else ">= 0"
    top = MAX_MAGNITUDE if maximum is None else min(maximum, MAX_MAGNITUDE)
    valid = f"finite and {low}" + (f" and <= {maximum:g} {unit}" if maximum is not None else "")
    if not math.isfinite(x) or x < 0 or (x == 0 and not allow_zero) or x > top or 0 < x < MIN_MAGNITUDE:
        where = "" if kind == "dimensionless" else f" (in {unit})"
        if math.isfinite(x) and (x > MAX_MAGNITUDE or 0 < x < MIN_MAGNITUDE):
            valid += f", of magnitude {MIN_MAGNITUDE:g} to {MAX_MAGNITUDE:g}"
        got = shown_text(value) if isinstance(value, str) else repr(value)
        raise ValueError(f"{name} must be {valid}{where}, got {got}")
    return x
