"""Command line: ``python -m torsional_contact <subcommand> ...`` (docs/conventions.md).

Bad input exits with status 2 and one line on standard error; nothing is printed
on standard output.  Accuracy warnings are printed as one line each on stderr.

Numbers: every subcommand's parser (``_Parser``) takes negative numbers in any form,
-1, -.5, -1e-1, -1E+3 (argparse alone reads "-1e-1" as an option), and the number
options use ``real_argument`` as their type, so that "nan", "inf" and non-numbers are
refused with exit status 2 naming the option.
"""

from __future__ import annotations

import argparse
import decimal
import json
import math
import re
import sys
import warnings

import numpy as np

from .. import __version__
from ..models import DEFAULT_MODEL, MODELS
from ..solution import DEFAULT_N_TERMS, METHODS, solve
from ..solvers.weak_form import METHODS as SERIES_METHODS

__all__ = ["main", "build_parser", "real_argument", "NEGATIVE_NUMBER", "MAX_REFERENCE_TERMS", "MAX_REFERENCE_DIGITS",
           "REFERENCE_METHODS"]

PROG = "torsional_contact"

#: What argparse must treat as a negative number rather than an option: decimal and
#: exponent forms (argparse's own pattern, ^-\d+$|^-\d*\.\d+$, misses "-1e-1").
NEGATIVE_NUMBER = re.compile(r"^-(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$|^-(inf|infinity|nan)$", re.IGNORECASE)


class UsageError(Exception):
    """Bad command-line input (exit status 2)."""


class _Parser(argparse.ArgumentParser):
    """argparse with one-line errors and negative numbers in exponent form (every subcommand)."""

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        self._negative_number_matcher = NEGATIVE_NUMBER

    def error(self, message):  # one line, no usage dump
        raise UsageError(message)


def real_argument(text: str) -> float:
    """argparse ``type`` for a finite real number in decimal or exponent form ("-1e-1", "1.23")."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a real number, got {text!r}") from None
    if not math.isfinite(value):
        raise argparse.ArgumentTypeError(f"expected a finite real number, got {text!r}")
    return value


def _json_number(value):
    return value if isinstance(value, float) and math.isfinite(value) else None


def _finite_record(record):
    """``record`` with every non-finite float (nan, inf) replaced by None: the JSON stays valid."""
    if isinstance(record, dict):
        return {key: _finite_record(value) for key, value in record.items()}
    if isinstance(record, list):
        return [_finite_record(value) for value in record]
    if isinstance(record, float) and not math.isfinite(record):
        return None
    return record


def _profiles(record: dict, state, radii, fields=("traction", "slip")) -> dict:
    """Add the interface profiles ``fields`` of ``state`` at ``radii`` (JSON: non-finite -> null)."""
    if radii is not None:
        radii = np.asarray(radii, dtype=float)
        record["radii"] = radii.tolist()
        for name in fields:
            record[name] = [_json_number(float(v)) for v in getattr(state, name)(radii)]
    return record


def _cmd_solve(args) -> dict:
    solution = solve(stick_radius=args.stick_radius, torque=args.torque, method=args.method, n_terms=args.n_terms,
                     model=args.model)
    return _profiles({**solution.as_dict(), "model": args.model}, solution, args.radii)


def _cmd_history(args):
    """``history``: states at the given turning points, or the analysis of a sampled signal (``--signal``)."""
    from .. import validation
    from ..histories import history

    if args.signal is None:
        if args.output is not None:
            raise UsageError("--output needs --signal (the per-sample table of a sampled signal)")
        torques = validation.torque_sequence("--turning-points", args.turning_points)
        states = history(torques, method=args.method, n_terms=args.n_terms, model=args.model)
        fields = ("traction", "slip", "residual_traction")
        return [_profiles(state.as_dict(), state, args.radii, fields) for state in states]
    if args.radii is not None:
        raise UsageError("--radii applies to --turning-points only (profiles of a few states)")
    from .history_signal import analyse_file

    return analyse_file(args.signal, method=args.method, n_terms=args.n_terms, model=args.model, output=args.output,
                        progress=not args.no_progress, full=args.json)


#: Largest --digits of ``reference`` (working precision digits + 20; every digit printed is kept).
MAX_REFERENCE_DIGITS = 1000
#: Largest --n-terms of ``reference``: the mpmath assembly is O(N^2) multiple-precision
#: products (~1 s at N = 145 and 70 digits), the solve O(N^3) (~1 min at N = 1000).
MAX_REFERENCE_TERMS = 1000


def _decimal_radius(name: str, text: str) -> str:
    """``text`` if it is a finite decimal in the open interval (0, 1), read exactly (no float rounding)."""
    try:
        value = decimal.Decimal(text.strip())
    except decimal.InvalidOperation:
        raise ValueError(f"{name} must be a decimal number in (0, 1), got {text!r}") from None
    if not value.is_finite() or not 0 < value < 1:
        raise ValueError(f"{name} must lie in (0, 1) (open: the reference solves partial slip), got {text!r}")
    return text.strip()


#: The methods of ``reference``: the weak forms (truncated) and "fast", the converged solution.
REFERENCE_METHODS = (*SERIES_METHODS, "fast")


def _cmd_reference_fast(args) -> dict:
    """``reference --method fast``: the converged solution (Abel-Fredholm method in arbitrary precision)."""
    from ..verification.abel_fredholm_mp import MAX_DIGITS, solve_reference_abel_fredholm
    from ..verification.arbitrary_precision import parse_decimal, require_flint

    if args.n_terms is not None:
        raise UsageError("--n-terms is not accepted with --method fast (the converged solution has no truncation)")
    if not 1 <= args.digits <= MAX_DIGITS:
        raise UsageError(f"--digits must lie in [1, {MAX_DIGITS}] with --method fast, got {args.digits}")
    text = _decimal_radius("--stick-radius", args.stick_radius)
    for r in args.radii or ():
        parse_decimal("--radii", r, 0, 1)
    try:
        require_flint("reference --method fast")
    except ImportError as error:
        raise UsageError(str(error)) from None
    record = solve_reference_abel_fredholm(text, args.digits).as_dict(args.radii)
    record.update(stick_radius=text, n_terms=None, backend="flint")
    return record


def _cmd_reference(args) -> dict:
    import mpmath

    from .. import validation
    from ..verification.reference import solve_reference

    method = validation.choice("--method", args.method, REFERENCE_METHODS)
    if method == "fast":
        return _cmd_reference_fast(args)
    if args.radii is not None:
        raise UsageError("--radii is only available with --method fast")
    text = _decimal_radius("--stick-radius", args.stick_radius)
    digits = validation.positive_int("--digits", args.digits, MAX_REFERENCE_DIGITS)
    n_terms = validation.positive_int("--n-terms", 145 if args.n_terms is None else args.n_terms,
                                      MAX_REFERENCE_TERMS)
    solution = solve_reference(text, method, n_terms, digits)
    kept = digits
    if solution.solve_bound is not None and solution.solve_bound > 0:  # print only the digits the bound keeps
        kept = max(1, min(digits, int(math.floor(float(-mpmath.log10(solution.solve_bound))))))
    with mpmath.workdps(digits):
        torque = mpmath.nstr(solution.torque, kept, strip_zeros=False)
        omega = solution.rigid_rotation
        omega = None if omega is None else mpmath.nstr(omega, kept, strip_zeros=False)
    return {
        "stick_radius": text,
        "torque": torque,
        "rigid_rotation": omega,
        "digits": kept,
        "n_terms": n_terms,
        "method": method,
        "backend": solution.backend,
        "seconds": round(sum(solution.seconds.values()), 6),
    }


def _cmd_errata(args) -> list:
    from ..verification.errata import errata_table

    return errata_table()


def _add_solver_options(p) -> None:
    """--method, --n-terms, --radii, --model: shared by the subcommands that call ``solve``."""
    p.add_argument("--method", default=None, help=f"one of {', '.join(METHODS)} (default: most accurate)")
    p.add_argument("--n-terms", type=int, default=None, help=f"number of eigenfunctions (default {DEFAULT_N_TERMS})")
    p.add_argument("--radii", type=real_argument, nargs="+", help="also report traction and slip at these r/a")
    p.add_argument("--model", choices=MODELS, default=DEFAULT_MODEL,
                   help="cylinder (default): the flat-ended cylinders; half-space: two half-spaces under the same "
                   "uniform pressure (closed-form: no --method, no --n-terms)")


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(prog=PROG, description="Frictional torsional contact of flat-ended cylinders.")
    parser.add_argument("--version", action="version", version=f"{PROG} {__version__}")
    sub = parser.add_subparsers(dest="command", required=True, parser_class=_Parser)

    p = sub.add_parser("solve", help="solve for a stick radius or a torque")
    group = p.add_mutually_exclusive_group(required=True)
    group.add_argument("--stick-radius", type=real_argument, help="b/a in [0, 1]")
    group.add_argument("--torque", type=real_argument, help="T* = 2T/(f F a) in [-4/3, 4/3]")
    _add_solver_options(p)
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.set_defaults(handler=_cmd_solve)
    p = sub.add_parser("history", help="interface states along a torque history (memory rules)")
    source = p.add_mutually_exclusive_group(required=True)
    source.add_argument("--turning-points", type=real_argument, nargs="+", help="T* after each step, in [-4/3, 4/3]")
    source.add_argument("--signal", help="sampled T*: text/CSV file, one value per line, or a .npy array")
    p.add_argument("--output", help="with --signal: CSV of the twist and dissipated energy at every sample")
    p.add_argument("--no-progress", action="store_true", help="no progress bar on standard error")
    _add_solver_options(p)
    p.add_argument("--json", action="store_true", help="print JSON: a list of states, or one object for --signal")
    p.set_defaults(handler=_cmd_history)
    p = sub.add_parser("reference", help="high-precision solution: the truncated weak form, or (--method fast) "
                       "the converged Abel-Fredholm solution")
    p.add_argument("--stick-radius", required=True, help="b/a in (0, 1), read as a decimal")
    p.add_argument("--n-terms", type=int, default=None,
                   help=f"weak forms: number of eigenfunctions, 1 to {MAX_REFERENCE_TERMS} (default 145)")
    p.add_argument("--digits", type=int, default=50,
                   help=f"significant digits, 1 to {MAX_REFERENCE_DIGITS} (default 50; fewer if the solve keeps fewer; "
                   "fast: at most 100)")
    p.add_argument("--method", default="complete", help=f"one of {', '.join(REFERENCE_METHODS)} (default complete)")
    p.add_argument("--radii", nargs="+", help="fast only: also the traction and slip at these r/a (decimals in [0, 1])")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.set_defaults(handler=_cmd_reference)
    p = sub.add_parser("errata", help="computed verdicts on the paper's equations and statements")
    p.add_argument("--json", action="store_true", help="print a JSON list, one object per checked statement")
    p.set_defaults(handler=_cmd_errata)
    return parser


def _format_warning(message, category, filename, lineno, line=None):
    return f"warning ({category.__name__}): {message}\n"


def main(argv=None) -> int:
    parser = build_parser()
    saved_format = warnings.formatwarning
    warnings.formatwarning = _format_warning  # one line per accuracy warning
    try:
        args = parser.parse_args(argv)
        result = args.handler(args)
    except (UsageError, ValueError) as exc:
        print(f"{PROG}: error: {exc}", file=sys.stderr)
        return 2
    finally:
        warnings.formatwarning = saved_format
    result = _finite_record(result)
    if getattr(args, "json", False):
        print(json.dumps(result, allow_nan=False))
    elif isinstance(result, list):  # one record per line
        for record in result:
            print(json.dumps(record, allow_nan=False))
    else:
        for key, value in result.items():
            print(f"{key}: {value}")
    return 0
