"""Running the command line inside the test process, with Python's own warning display (shared by the CLI tests)."""

from __future__ import annotations

import contextlib
import io
import sys
import warnings

from torsional_contact.io.cli import main


def print_warning(message, category, filename, lineno, file=None, line=None):
    """Python's own way of showing a warning (to sys.stderr, through warnings.formatwarning), not pytest's."""
    sys.stderr.write(warnings.formatwarning(message, category, filename, lineno, line))


def run_in_process(argv) -> tuple[int, str, str]:
    """``main(argv)``: (exit status, standard output, standard error); an escaping exception fails the test."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err), warnings.catch_warnings():
        warnings.simplefilter("always")
        warnings.showwarning = print_warning
        status = main(argv)
    return status, out.getvalue(), err.getvalue()
