r"""Numbers for print: LaTeX scientific notation for the manuscript, plain text for notes and JSON.

LaTeX numbers are returned without the surrounding ``$``: ``sci(2.1e-3)`` is
``2.1\times10^{-3}``, so a note writes ``f"${sci(x)}$"``.
"""

from __future__ import annotations

import math

__all__ = ["sci", "fixed", "plain_sci", "tex_list"]


def _mantissa_exponent(x: float, digits: int) -> tuple[str, int]:
    text = f"{abs(x):.{digits}e}"
    mantissa, exponent = text.split("e")
    return mantissa, int(exponent)


def sci(x: float, digits: int = 1, always: bool = False) -> str:
    r"""LaTeX scientific notation: ``2.1\times10^{-3}``; plain decimals for 0.01 <= |x| < 1000.

    ``digits`` decimals in the mantissa; ``always``: scientific notation for every nonzero x
    (a table column).  0 is ``0``; inf and nan raise ValueError (a note must say what a
    non-finite number means instead of printing it).
    """
    x = float(x)
    if not math.isfinite(x):
        raise ValueError(f"x must be finite for typesetting, got {x!r}")
    if x == 0:
        return "0"
    sign = "-" if x < 0 else ""
    mantissa, exponent = _mantissa_exponent(x, digits)
    if -2 <= exponent <= 2 and not always:
        return sign + f"{abs(x):.{max(digits - exponent, 0)}f}"
    if mantissa.rstrip("0").rstrip(".") == "1":
        return f"{sign}10^{{{exponent}}}"
    return f"{sign}{mantissa}\\times10^{{{exponent}}}"


def fixed(x: float, decimals: int) -> str:
    """LaTeX fixed-point number with ``decimals`` decimals (the minus sign is math mode's)."""
    x = float(x)
    if not math.isfinite(x):
        raise ValueError(f"x must be finite for typesetting, got {x!r}")
    return f"{x:.{decimals}f}"


def plain_sci(x: float, digits: int = 1) -> str:
    """Plain-text scientific notation for the JSON/Markdown note: ``2.1e-03``; 0 is ``0``."""
    x = float(x)
    return "0" if x == 0 else f"{x:.{digits}e}"


def tex_list(items) -> str:
    """'a, b and c' for LaTeX text (items already typeset)."""
    items = list(items)
    if len(items) <= 1:
        return "".join(items)
    return ", ".join(items[:-1]) + " and " + items[-1]
