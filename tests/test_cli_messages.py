"""What users read: help texts, error messages naming the argument and the value, advice in warnings,
and signal files with a header or several columns."""

from __future__ import annotations

import contextlib
import io
import json
import math
import warnings

import numpy as np
import pytest
from cli_runner import run_in_process as run

import torsional_contact as tc
from torsional_contact.diagnostics import ResolutionWarning
from torsional_contact.io.cli import MAX_REFERENCE_TERMS, build_parser
from torsional_contact.io.signal_files import read_signal


def help_text(*argv) -> str:
    out = io.StringIO()
    with contextlib.redirect_stdout(out), pytest.raises(SystemExit) as caught:
        build_parser().parse_args([*argv, "--help"])
    assert caught.value.code == 0
    return " ".join(out.getvalue().split())


# --------------------------------------------------------------------------- help texts
@pytest.mark.parametrize("command", ["solve", "history"])
def test_n_terms_help_does_not_claim_a_default_for_the_default_method(command):
    text = help_text(command)
    n_terms = text[text.rindex("--n-terms N_TERMS") :]  # the option's entry, after the usage line
    n_terms = n_terms[: n_terms.index("--radii")]
    assert "published and complete weak forms" in n_terms and "default 145" in n_terms
    assert "not used by the default method (fast" in n_terms


@pytest.mark.parametrize("command", ["solve", "history"])
def test_help_says_what_null_means(command):
    assert "rigid_rotation is null at spinning (|T*| = 4/3, stick radius 0), where the Python API gives inf" in \
        help_text(command)


def test_rigid_rotation_at_spinning_is_null_in_json_and_inf_in_the_api():
    assert math.isinf(tc.solve(torque=4 / 3).rigid_rotation)
    status, out, _ = run(["solve", "--stick-radius", "0", "--json"])
    assert status == 0
    record = json.loads(out)
    assert record["regime"] == "gross-slip" and record["rigid_rotation"] is None


def test_history_help_names_the_file_options():
    text = help_text("history")
    for phrase in ("# comments, a header line of names", "--column", "--parents", "/dev/stdout", "never the input"):
        assert phrase in text, phrase


# --------------------------------------------------------------------------- errors naming the argument
@pytest.mark.parametrize("argv, value", [
    (["solve", "--stick-radius", "0.6", "--radii", "1.5"], "1.5"),
    (["solve", "--torque", "1.2", "--radii", "0.3", "-0.25"], "-0.25"),
    (["history", "--turning-points", "0", "1.2", "--radii", "2"], "2.0"),
])
def test_radii_out_of_range_names_the_option_and_the_value(argv, value):
    status, out, err = run(argv)
    assert status == 2 and out == ""
    assert err.startswith("torsional_contact: error: --radii must be finite and lie in [0, 1]") and value in err
    assert len(err.splitlines()) == 1


@pytest.mark.parametrize("method", ["stress", "displacement"])
@pytest.mark.parametrize("r_shape, z_shape", [((3,), (4,)), ((2, 3), (3, 2)), ((5,), (5, 2))])
def test_mismatched_r_z_shapes_name_r_and_z(method, r_shape, z_shape):
    solution = tc.solve(stick_radius=0.5)
    r, z = np.full(r_shape, 0.5), np.full(z_shape, 0.1)
    with pytest.raises(ValueError) as caught:
        getattr(solution, method)(r, z)
    message = str(caught.value)
    assert f"r of shape {r_shape}" in message and f"z of shape {z_shape}" in message
    ok_r, ok_z = np.full((5, 1), 0.5), np.full((1, 3), 0.1)  # shapes that broadcast still work
    assert np.shape(getattr(solution, method)(ok_r, ok_z)[0] if method == "stress" else
                    getattr(solution, method)(ok_r, ok_z)) == (5, 3)


def test_coordinates_name_the_offending_value():
    solution = tc.solve(stick_radius=0.5)
    with pytest.raises(ValueError, match=r"^r must be finite and lie in \[0, 1\].*got 1\.25 \(element 2\)$"):
        solution.traction([0.1, 0.2, 1.25])
    with pytest.raises(ValueError, match=r"^z must be finite and >= 0.*got -0\.5$"):
        solution.stress(0.5, -0.5)


# --------------------------------------------------------------------------- the reference's advice
def test_reference_advice_at_tiny_stick_radius_points_to_the_default_method():
    from torsional_contact.verification import reference

    assert reference.AFFORDABLE_TERMS == MAX_REFERENCE_TERMS
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        reference.solve_reference("1e-300", "complete", 4, 10)
    message = next(str(w.message) for w in caught if issubclass(w.category, ResolutionWarning))
    assert "use the default method" in message and "reference --method fast" in message
    assert "e+" not in message and "3e300" not in message  # no count that no computer could use
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        reference.solve_reference("0.02", "complete", 4, 10)
    message = next(str(w.message) for w in caught if issubclass(w.category, ResolutionWarning))
    from torsional_contact.solvers.weak_form import terms_to_resolve

    assert message.endswith(f"use n_terms >= {terms_to_resolve(0.02)}")  # affordable: the count itself
    assert terms_to_resolve(0.02) <= reference.AFFORDABLE_TERMS


def test_reference_advice_on_the_command_line_is_one_line():
    status, out, err = run(["reference", "--stick-radius", "1e-200", "--n-terms", "3", "--digits", "8"])
    lines = err.splitlines()
    advice = [line for line in lines if line.startswith("warning (ResolutionWarning)")]
    assert status == 0 and len(advice) == 1 and "use the default method" in advice[0]


# --------------------------------------------------------------------------- signal files: header, columns
SIGNAL = [0.0, 1.2, -1.2, 1.2]


@pytest.mark.parametrize("text, column", [
    ("torque\n0\n1.2\n-1.2\n1.2\n", None),  # a header line is skipped
    ("# T* record\ntorque\n0\n\n1.2\n-1.2\n# end\n1.2\n", None),  # comments and blanks around it
    ("time,torque\n0,0\n1,1.2\n2,-1.2\n3,1.2\n", "2"),
    ("time,torque\n0,0\n1,1.2\n2,-1.2\n3,1.2\n", "torque"),
    ('"time";"torque";"load"\n0;0;9\n1;1.2;9\n2;-1.2;9\n3;1.2;9\n', "torque"),
    ("0\t0\t5\n1\t1.2\t5\n2\t-1.2\t5\n3\t1.2\t5\n", 2),
    ("0 0\n1   1.2\n2 -1.2\n3 1.2\n", "2"),
    ("time,torque\r\n0,0\r\n1,1.2\r\n2,-1.2\r\n3,1.2\r\n", "torque"),  # Windows line ends
])
def test_header_and_column(tmp_path, text, column):
    path = tmp_path / "signal.csv"
    path.write_text(text)
    np.testing.assert_array_equal(read_signal(path, column=column), SIGNAL)


def test_npy_column(tmp_path):
    path = tmp_path / "signal.npy"
    np.save(path, np.column_stack([np.arange(4.0), SIGNAL]))
    np.testing.assert_array_equal(read_signal(path, column=2), SIGNAL)
    with pytest.raises(ValueError, match="2 columns"):
        read_signal(path)


@pytest.mark.parametrize("text, column, match", [
    ("time,torque\n0,0\n1,1.2\n", None, r"2 columns \('time', 'torque'\): choose the torque with --column N\|NAME"),
    ("time,torque\n0,0\n1,1.2\n", "3", r"--column must be a column number in \[1, 2\].*got '3'"),
    ("time,torque\n0,0\n1,1.2\n", "load", r"one of the header's names \('time', 'torque'\).*got 'load'"),
    ("0,0\n1,1.2\n", "torque", r"--column 'torque' is a name, but .* has no header line"),
    ("time,torque\n0,0\n1\n", "2", r"line 3: 1 field\(s\), column 2 wanted"),
    ("time,torque\n0,0\n1,x\n", "2", r"line 3: 'x' is not a number"),
    ("time,torque\n0,0\n1,1.5\n", "torque", r"line 3: 1\.5 lies outside \[-4/3, 4/3\]"),
])
def test_column_errors(tmp_path, text, column, match):
    path = tmp_path / "signal.csv"
    path.write_text(text)
    with pytest.raises(ValueError, match=match):
        read_signal(path, column=column)


def test_the_message_says_comments_and_headers_are_allowed(tmp_path):
    path = tmp_path / "signal.txt"
    path.write_text("0\n1.2\nabc\n")
    with pytest.raises(ValueError) as caught:
        read_signal(path)
    assert "lines starting with # are skipped" in str(caught.value)
    assert "a first line of names is a header" in str(caught.value)


def test_cli_column(tmp_path):
    path = tmp_path / "record.csv"
    path.write_text("time,torque\n" + "".join(f"{i},{v}\n" for i, v in enumerate(SIGNAL)))
    status, out, err = run(["history", "--signal", str(path), "--column", "torque", "--json"])
    assert status == 0, err
    assert json.loads(out)["samples"] == 4
    status, out, err = run(["history", "--signal", str(path), "--json"])
    assert status == 2 and out == "" and "--column" in err and len(err.splitlines()) == 1
    status, out, err = run(["history", "--turning-points", "0", "1.2", "--column", "2"])
    assert status == 2 and "--column needs --signal" in err
    status, out, err = run(["history", "--signal", str(path), "--column", "2", "--parents"])
    assert status == 2 and "--parents needs --output" in err
