"""Command line: ``python -m torsional_contact <subcommand> ...`` (docs/conventions.md).

Bad input exits with status 2 and one line on standard error; nothing is printed
on standard output.  Accuracy warnings are printed as one line each on stderr.
Errors of the operating system (a file that cannot be read or written, a full disk, a
read-only file system, standard output on /dev/full) exit with status 2 and one line naming
the option and the path; an interrupt (Ctrl-C) exits with 130 and one line; standard output
closed early (``| head -c1``) ends the command quietly with status 141 (128 + SIGPIPE, what
the shell reports for a command that SIGPIPE killed).  Files named on the command line are
written by ``output`` (regular files atomically, symbolic links through, FIFOs and devices
in place; never over an input).

Optional packages: the subcommands ``reference`` and ``errata`` need the ``reference`` extra
(mpmath, python-flint); without it they exit with status 2 and one line naming the pip
command that installs it (``extras``).

Numbers: every subcommand's parser (``_Parser``) takes negative numbers in any form,
-1, -.5, -1e-1, -1E+3 (argparse alone reads "-1e-1" as an option), and the number
options use ``real_argument`` as their type, so that "nan", "inf" and non-numbers are
refused with exit status 2 naming the option.
"""

from __future__ import annotations

import argparse
import decimal
import errno
import json
import math
import os
import re
import sys
import warnings

import numpy as np

from .. import __version__, extras, models
from ..backends import DEFAULT_METHOD, DEFAULT_N_TERMS, METHODS
from ..dispatch import solve
from ..solvers.weak_form import WEAK_FORMS
from . import cli_units

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

    def _print_message(self, message, file=None):  # --help, --version: argparse would hide a failed write
        if message:
            (file or sys.stderr).write(message)


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


def _radii(values):
    """``--radii`` checked (in [0, 1]) before any solve: the message names the option and the value."""
    from .. import validation

    return None if values is None else validation.coordinates(np.asarray(values, dtype=float), names=("--radii",))


def _with_profiles(record, profile) -> dict:
    """The JSON of a result record with its profiles (if any) at the same level."""
    return {**record.as_dict(), **(profile.as_dict() if profile is not None else {})}


def _cmd_solve(args) -> dict:
    specimen = cli_units.specimen_from(args)
    if specimen is not None:
        return cli_units.solve_si(args, specimen)
    args.torque = cli_units.plain_number("--torque", args.torque)
    args.stick_radius = cli_units.plain_number("--stick-radius", args.stick_radius)
    _radii(args.radii)
    solution = solve(stick_radius=args.stick_radius, torque=args.torque, method=args.method, n_terms=args.n_terms,
                     model=args.model)
    return _with_profiles(solution.record(), cli_units.profiles(solution, args.radii))


def _cmd_history(args):
    """``history``: states at the given turning points, or the analysis of a sampled signal (``--signal``)."""
    from .. import validation
    from ..histories import history
    from .history_command import analyse_file

    specimen = cli_units.specimen_from(args)
    if specimen is not None:
        return cli_units.history_si(args, specimen)
    for option, value in (("--torque-column", args.torque_column), ("--time-column", args.time_column),
                          ("--encoding", args.encoding)):
        if value is not None:
            raise UsageError(f"{option} reads a lab export with units: it needs --signal and the specimen options "
                             "(for a file of T* values, --column chooses the column)")
    if args.signal is None:
        args.turning_points = [cli_units.plain_number("--turning-points", v) for v in args.turning_points]
        for option, value in (("--output", args.output), ("--states", args.states), ("--gate", args.gate),
                              ("--bin-width", args.bin_width), ("--column", args.column)):
            if value is not None:
                raise UsageError(f"{option} needs --signal (it applies to a sampled signal)")
        torques = validation.torque_sequence("--turning-points", args.turning_points,
                                             models.get(args.model).checked_torque)
        _radii(args.radii)
        states = history(torques, method=args.method, n_terms=args.n_terms, model=args.model)
        return [_with_profiles(state.record(), cli_units.profiles(state, args.radii, residual=True))
                for state in states]
    if args.radii is not None:
        raise UsageError("--radii applies to --turning-points only (profiles of a few states)")
    from ..output import distinct_outputs

    args.gate = cli_units.plain_number("--gate", args.gate)
    args.bin_width = cli_units.plain_number("--bin-width", args.bin_width)

    if args.parents and args.output is None and args.states is None:
        raise UsageError("--parents needs --output or --states (it creates their missing directories)")
    # refuse a bad table path, or two names of one file, before the analysis, not after it
    distinct_outputs((("--output", args.output), ("--states", args.states)), inputs=(("--signal", args.signal),),
                     parents=args.parents)
    return analyse_file(args.signal, method=args.method, n_terms=args.n_terms, model=args.model, output=args.output,
                        states=args.states, gate=0.0 if args.gate is None else args.gate, bin_width=args.bin_width,
                        progress=not args.no_progress, full=args.json, column=args.column,
                        parents=args.parents).as_dict()


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


def _cmd_reference_weak_form(args) -> dict:
    """``reference --method published|complete``: the truncated weak form in arbitrary precision."""
    import mpmath

    from .. import validation
    from ..verification.reference import solve_reference

    method = args.method
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


#: The methods of ``reference`` (arbitrary precision): the weak forms (truncated) and "fast", the converged
#: solution of the Abel-Fredholm method; name -> handler.
REFERENCE_METHODS = {**dict.fromkeys(WEAK_FORMS, _cmd_reference_weak_form), "fast": _cmd_reference_fast}


def _cmd_reference(args) -> dict:
    extras.require("reference", "the reference subcommand")
    from .. import validation

    return REFERENCE_METHODS[validation.choice("--method", args.method, REFERENCE_METHODS)](args)


def _cmd_errata(args) -> list:
    extras.require("reference", "the errata subcommand")
    from ..verification.errata import errata_table

    return errata_table()


#: The epilog of the subcommands that print solutions: what null means in their JSON.
NULL_EPILOG = ("JSON has no infinity: a number that is not finite prints as null. rigid_rotation is null at "
               "spinning (|T*| = 4/3, stick radius 0), where the Python API gives inf (the rotation is unbounded).")


def _add_solver_options(p) -> None:
    """--method, --n-terms, --radii, --model: shared by the subcommands that call ``solve``."""
    p.add_argument("--method", default=None,
                   help=f"one of {', '.join(METHODS)} (default: {DEFAULT_METHOD}, the most accurate)")
    p.add_argument("--n-terms", type=int, default=None,
                   help=f"published and complete weak forms: number of eigenfunctions (default {DEFAULT_N_TERMS}); "
                   "not used by the default method (fast: the interface values need no truncation)")
    p.add_argument("--radii", type=real_argument, nargs="+", help="also report traction and slip at these r/a")
    p.add_argument("--model", choices=models.names(), default=models.DEFAULT_MODEL,
                   help="the contact model: " + "; ".join(f"{name}: {contact.description}" for name, contact in
                                                          models.MODELS.items())
                   + f" (default {models.DEFAULT_MODEL}; --method and --n-terms apply to models with methods only)")


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(prog=PROG, description="Frictional torsional contact of flat-ended cylinders.")
    parser.add_argument("--version", action="version", version=f"{PROG} {__version__}")
    sub = parser.add_subparsers(dest="command", required=True, parser_class=_Parser)

    p = sub.add_parser("solve", help="solve for a stick radius or a torque", epilog=NULL_EPILOG)
    group = p.add_mutually_exclusive_group(required=True)
    group.add_argument("--stick-radius", type=cli_units.number_or_quantity,
                       help="b/a in [0, 1]; with the specimen options a length, e.g. '2 mm'")
    group.add_argument("--torque", type=cli_units.number_or_quantity,
                       help="T* = 2T/(f F a), within the model's gross-slip torque ([-4/3, 4/3] for the cylinders); "
                       "with the specimen options a torque, e.g. '1.8 N m'")
    _add_solver_options(p)
    cli_units.add_specimen_options(p)
    p.add_argument("--json", action="store_true", help="print one JSON object")
    p.set_defaults(handler=_cmd_solve)
    p = sub.add_parser("history", help="interface states along a torque history (memory rules)", epilog=NULL_EPILOG)
    source = p.add_mutually_exclusive_group(required=True)
    source.add_argument("--turning-points", type=cli_units.number_or_quantity, nargs="+",
                        help="T* after each step, within the model's gross-slip torque ([-4/3, 4/3] for the cylinders; "
                        "with the specimen options: torques, N m)")
    source.add_argument("--signal", help="sampled T*: text/CSV file, one value per line (# comments, a header line "
                        "of names and blank lines allowed) or a column of a CSV (--column), or a .npy array; with "
                        "the specimen options a CSV whose header carries units, e.g. 'time [s],torque [N m]'")
    p.add_argument("--column", help="with --signal: the column of T* in a CSV of several, a number from 1 or a name "
                   "of its header line")
    p.add_argument("--output", help="with --signal: table of the twist and dissipated energy at every sample "
                   "(.npz or .npy: binary, for long signals; any other name: CSV; a file, symbolic link, FIFO, "
                   "device or /dev/stdout; never the input)")
    p.add_argument("--states", help="with --signal: table of the states at every turning point (.npz, .npy or CSV; "
                   "the JSON lists them only for signals of at most 1000 turning points)")
    p.add_argument("--parents", action="store_true", help="create the missing directories of --output and --states")
    p.add_argument("--gate", type=cli_units.number_or_quantity, default=None,
                   help="with --signal: drop reversals smaller than this torque range before the memory rules "
                   "(hysteresis filter; changes the history: see docs/conventions.md; default 0, none; "
                   "with the specimen options in N m)")
    p.add_argument("--bin-width", type=cli_units.number_or_quantity, default=None,
                   help="with --signal: width in T* of the range and mean bins of the rainflow matrix in the JSON "
                   "(default: exact grouping up to 1000 turning points, else 0.05; with the specimen options in N m)")
    p.add_argument("--no-progress", action="store_true", help="no progress bar on standard error")
    _add_solver_options(p)
    cli_units.add_specimen_options(p)
    cli_units.add_fit_input_options(p, ("torque", "time"), " (--signal with the specimen options)")
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
    cli_units.add_fit_parser(sub, _Parser)
    return parser


def _one_line(text: str) -> str:
    """``text`` on one line (a path or a message may hold line breaks)."""
    return " ".join(str(text).splitlines()) or "(no message)"


def _format_warning(message, category, filename, lineno, line=None):
    return f"warning ({category.__name__}): {_one_line(message)}\n"


def _error(message: str, status: int = 2) -> int:
    print(f"{PROG}: error: {_one_line(message)}", file=sys.stderr)
    return status


def _quiet_standard_output() -> None:
    """After standard output failed: point it at /dev/null, so that Python's flush at exit reports nothing.

    Only for the process's own standard output (not one a caller substituted, e.g. pytest's capture).
    """
    if sys.stdout is sys.__stdout__ and sys.stdout is not None:
        try:
            devnull = os.open(os.devnull, os.O_WRONLY)
            os.dup2(devnull, sys.stdout.fileno())
            os.close(devnull)
        except (OSError, ValueError):  # standard output is gone already: nothing left to quieten
            return


def _print_result(args, result) -> None:
    if not getattr(args, "json", False) and hasattr(result, "text"):  # a report of its own (fit)
        print(result.text())
        sys.stdout.flush()
        return
    result = _finite_record(result)
    if getattr(args, "json", False):
        print(json.dumps(result, allow_nan=False))
    elif isinstance(result, list):  # one record per line
        for record in result:
            print(json.dumps(record, allow_nan=False))
    else:  # one "key: value" line each; nested values as JSON, never a Python repr
        for key, value in result.items():
            shown = json.dumps(value, allow_nan=False, ensure_ascii=False) if isinstance(value, (dict, list)) or \
                value is None or isinstance(value, bool) else value
            print(f"{key}: {shown}")
    sys.stdout.flush()


def _parse(parser, argv):
    """``parser.parse_args``; what --help and --version printed is flushed here, where its errors are caught."""
    try:
        return parser.parse_args(argv)
    except SystemExit:
        sys.stdout.flush()
        raise


def _standard_output_failed(exc: OSError) -> int:
    _quiet_standard_output()
    if exc.errno == errno.EPIPE:  # the reader went away (| head): end quietly, as SIGPIPE would
        return 141
    return _error(f"standard output: {exc.strerror or exc}")


def main(argv=None) -> int:
    """Run the command line; returns the exit status (0; 2 for bad input or a file error; 130; 141)."""
    saved_format = warnings.formatwarning
    warnings.formatwarning = _format_warning  # one line per accuracy warning
    try:
        parser = build_parser()
        try:
            args = _parse(parser, argv)
        except OSError as exc:  # printing --help or --version
            return _standard_output_failed(exc)
        except UsageError as exc:
            return _error(exc)
        try:
            result = args.handler(args)
        except OSError as exc:  # output's errors name the option and the path
            if exc.errno == errno.EPIPE:  # --output /dev/stdout, a FIFO: the reader went away
                _quiet_standard_output()
                return 141
            return _error(exc if exc.filename is not None else (exc.strerror or exc))
        except (UsageError, ValueError, extras.MissingExtraError) as exc:
            return _error(exc)
        except ModuleNotFoundError as exc:  # an optional package a subcommand needs: name the extra
            extra = extras.extra_for(exc.name or "")
            if extra is None:
                raise
            return _error(extras.missing_message(args.command, [exc.name], extra))
        try:
            _print_result(args, result)
        except OSError as exc:
            return _standard_output_failed(exc)
        return 0
    except KeyboardInterrupt:
        print(f"{PROG}: interrupted", file=sys.stderr)
        return 130
    finally:
        warnings.formatwarning = saved_format
