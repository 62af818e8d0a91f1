"""Command line: ``python -m torsional_contact <subcommand> ...`` (CONTRACT.md).

Bad input exits with status 2 and one line on standard error; nothing is printed
on standard output.  Accuracy warnings are printed as one line each on stderr.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
import warnings

import numpy as np

from . import __version__
from .formulations import METHODS
from .solution import DEFAULT_N_TERMS, solve

__all__ = ["main", "build_parser"]

PROG = "torsional_contact"


class UsageError(Exception):
    """Bad command-line input (exit status 2)."""


class _Parser(argparse.ArgumentParser):
    def error(self, message):  # one line, no usage dump
        raise UsageError(message)


def _json_number(value):
    return value if isinstance(value, float) and math.isfinite(value) else None


def _cmd_solve(args) -> dict:
    solution = solve(
        stick_radius=args.stick_radius,
        torque=args.torque,
        method=args.method,
        n_terms=args.n_terms,
    )
    out = solution.as_dict()
    if args.radii is not None:
        radii = np.asarray(args.radii, dtype=float)
        out["radii"] = radii.tolist()
        out["traction"] = [_json_number(float(v)) for v in solution.traction(radii)]
        out["slip"] = [_json_number(float(v)) for v in solution.slip(radii)]
    return out


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(prog=PROG, description="Frictional torsional contact of flat-ended cylinders.")
    parser.add_argument("--version", action="version", version=f"{PROG} {__version__}")
    sub = parser.add_subparsers(dest="command", required=True, parser_class=_Parser)

    p = sub.add_parser("solve", help="solve for a stick radius or a torque")
    group = p.add_mutually_exclusive_group(required=True)
    group.add_argument("--stick-radius", type=float, help="b/a in [0, 1]")
    group.add_argument("--torque", type=float, help="T* = 2T/(f F a) in [-4/3, 4/3]")
    p.add_argument("--method", default=None, help=f"one of {', '.join(METHODS)} (default: most accurate)")
    p.add_argument("--n-terms", type=int, default=None, help=f"number of eigenfunctions (default {DEFAULT_N_TERMS})")
    p.add_argument("--radii", type=float, nargs="+", help="also report traction and slip at these r/a")
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.set_defaults(handler=_cmd_solve)
    return parser


def _format_warning(message, category, filename, lineno, line=None):
    return f"warning ({category.__name__}): {message}\n"


def main(argv=None) -> int:
    parser = build_parser()
    warnings.formatwarning = _format_warning
    try:
        args = parser.parse_args(argv)
        result = args.handler(args)
    except (UsageError, ValueError) as exc:
        print(f"{PROG}: error: {exc}", file=sys.stderr)
        return 2
    if getattr(args, "json", False):
        print(json.dumps(result, allow_nan=False))
    else:
        for key, value in result.items():
            print(f"{key}: {value}")
    return 0
