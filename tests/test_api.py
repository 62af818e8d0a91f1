"""The public interface (docs/conventions.md): solve(), Solution, regimes, mirror, bad input, CLI."""

import json
import math
import subprocess
import sys

import numpy as np
import pytest
from tolerances import EPS, assert_close, assert_within, torque_accuracy

from torsional_contact import ResolutionWarning, solve
from torsional_contact.io.cli import main


@pytest.mark.parametrize(
    "kwargs, match",
    [
        ({"stick_radius": math.nan}, "stick_radius must be finite"),
        ({"stick_radius": math.inf}, "stick_radius must be finite"),
        ({"stick_radius": -0.1}, r"stick_radius must lie in \[0, 1\]"),
        ({"stick_radius": 1.5}, r"stick_radius must lie in \[0, 1\]"),
        ({"stick_radius": "0.5"}, "stick_radius must be a real number"),
        ({"torque": math.nan}, "torque must be finite"),
        ({"torque": -math.inf}, "torque must be finite"),
        ({"torque": 1.34}, "spin"),
        ({"torque": -2.0}, "spin"),
        ({"torque": 1.2, "stick_radius": 0.5}, "exactly one"),
        ({}, "exactly one"),
        ({"torque": 1.2, "n_terms": 0}, "n_terms must be an integer >= 1"),
        ({"torque": 1.2, "n_terms": 14.5}, "n_terms must be an integer >= 1"),
        ({"torque": 1.2, "method": "exact"}, "method must be one of"),
        ({"torque": 1.2, "method": None, "n_terms": True}, "n_terms"),
    ],
)
def test_bad_input_raises_value_error_naming_the_argument(kwargs, match):
    with pytest.raises(ValueError, match=match):
        solve(**kwargs)


def test_regimes_and_their_fields():
    stick = solve(torque=0.7)
    assert (stick.regime, stick.stick_radius, stick.rigid_rotation) == ("stick", 1.0, 0.0)
    r = np.linspace(0, 1, 11)
    # the bilateral field T* r, T* r z in closed form: a few ulp
    assert_close(stick.traction(r), 0.7 * r, "closed form: 4 ulp", rtol=4 * EPS)
    assert np.all(stick.slip(r) == 0.0)
    assert_close(stick.displacement(r, 0.3), 0.7 * r * 0.3, "closed form: 4 ulp", rtol=4 * EPS)
    assert solve(torque=1.0).regime == "stick"
    spin = solve(torque=-4 / 3)
    assert (spin.regime, spin.stick_radius, spin.rigid_rotation) == ("gross-slip", 0.0, -math.inf)
    assert np.all(spin.traction(np.linspace(0.1, 0.9, 9)) == -1.0)  # traction -1 everywhere (the friction limit)
    sigma_zt, sigma_rt = spin.stress(0.5, np.array([0.5, 1.0, 3.0]))
    assert np.all(np.isfinite(sigma_zt)) and np.all(np.isfinite(sigma_rt))
    partial = solve(torque=1.23)
    assert partial.regime == "partial-slip" and 0.6 < partial.stick_radius < 0.62  # b(1.23) = 0.60388
    assert partial.torque == 1.23


def test_negative_torque_mirrors_positive():
    pos, neg = solve(torque=1.27), solve(torque=-1.27)
    assert neg.stick_radius == pos.stick_radius
    assert neg.rigid_rotation == -pos.rigid_rotation
    r, z = np.linspace(0, 1, 7), np.array([0.0, 0.1, 0.7])[:, None]
    np.testing.assert_array_equal(neg.traction(r), -pos.traction(r))
    np.testing.assert_array_equal(neg.slip(r), -pos.slip(r))
    for a, b in zip(neg.stress(r, z), pos.stress(r, z), strict=True):
        np.testing.assert_array_equal(a, -b)
    np.testing.assert_array_equal(neg.displacement(r, z), -pos.displacement(r, z))


def test_inverse_problem_round_trip():
    for torque in (1.01, 1.1, 1.23, 1.3, 1.33):
        b = solve(torque=torque, n_terms=300).stick_radius
        # a round trip through the same solver: T* moves by at most its accuracy, twice
        assert_within(abs(solve(stick_radius=b, n_terms=300).torque - torque), 2 * torque_accuracy(b),
                      "2 x solver T* accuracy")


def test_inverse_problem_warns_when_the_slip_annulus_is_unresolved():
    with pytest.warns(ResolutionWarning, match="slip annulus"):
        s = solve(torque=1.0001, n_terms=145, method="complete")
    assert 0.999 < s.stick_radius < 1.0


def test_fields_far_from_the_interface_return_to_uniform_torsion():
    s = solve(stick_radius=0.5)
    r = np.linspace(0, 1, 21)
    sigma_zt, sigma_rt = s.stress(r, 8.0)
    # the slowest Dini mode decays like exp(-8 lam_1) = 1e-18; what is left is the fields' truncation tolerance
    # and the rounding of T* r z (8 ulp of 10)
    bound = s.tolerance + math.exp(-8 * 5.1356) + 8 * EPS * 10
    assert_close(sigma_zt, s.torque * r, "fields' tolerance + exp(-8 lam_1)", atol=bound)
    assert_close(sigma_rt, 0.0, "fields' tolerance + exp(-8 lam_1)", atol=bound)
    u = s.displacement(r, 8.0)
    assert_close(u, s.torque * r * 8.0 + s.rigid_rotation * r, "fields' tolerance + rounding", atol=bound)


def test_per_point_truncation_meets_its_tolerance():
    s = solve(stick_radius=0.4, n_terms=400)
    r = np.linspace(0, 1, 41)[:, None]
    z = np.array([1e-3, 0.01, 0.05, 0.2])[None, :]
    full = solve(stick_radius=0.4, n_terms=400, tolerance=0.0)  # sum every term
    # the library's promise: the omitted tail at each point is below ``tolerance`` (DEFAULT_TOLERANCE = 1e-12)
    for a, b in zip(s.stress(r, z), full.stress(r, z), strict=True):
        assert_close(a, b, "the per-point truncation tolerance asked for", atol=s.tolerance)
    assert_close(s.displacement(r, z), full.displacement(r, z), "the per-point truncation tolerance",
                 atol=s.tolerance)


def test_stress_satisfies_equilibrium_and_lateral_traction_free():
    s = solve(stick_radius=0.55, n_terms=300)
    # sigma_rt(1, z) = 0 (eq. 9): every term has J2(lam_n) = 0 at the rounded zeros, |J2'| lam_n ulp(lam_n) each,
    # times |c_n| lam_n^2: a 300-term sum below 300 x 300^2 x 1e3 x EPS; and the fields' tolerance
    assert_within(float(np.max(np.abs(s.stress(1.0, np.linspace(0.01, 1, 30))[1]))), s.tolerance + 300 * EPS * 1e3,
                  "fields' tolerance + J2 at the rounded zeros")
    # equilibrium d(sigma_rt)/dr + 2 sigma_rt / r + d(sigma_zt)/dz = 0 by central differences: O(h^2) with
    # derivatives ~ 1/z^3 at z = 0.08, and each field value within the fields' tolerance, divided by h
    r, z, h = 0.37, 0.08, 1e-5
    d_rt_dr = (s.stress(r + h, z)[1] - s.stress(r - h, z)[1]) / (2 * h)
    d_zt_dz = (s.stress(r, z + h)[0] - s.stress(r, z - h)[0]) / (2 * h)
    differences = 2 * (h**2 / z**3 + 2 * s.tolerance / (2 * h))
    assert_within(abs(d_rt_dr + 2 * s.stress(r, z)[1] / r + d_zt_dz), differences, "central differences + tolerance")
    # Hooke's law sigma_zt = du/dz (units f p0 and f p0 a / mu)
    du_dz = (s.displacement(r, z + h) - s.displacement(r, z - h)) / (2 * h)
    assert_within(abs(du_dz - s.stress(r, z)[0]), differences, "central differences + tolerance")


@pytest.mark.parametrize("bad_r, bad_z", [(1.2, 0.0), (-0.1, 0.0), (0.5, -1.0), (math.nan, 0.0), (0.5, math.inf)])
def test_field_coordinates_are_validated(bad_r, bad_z):
    s = solve(stick_radius=0.5)
    with pytest.raises(ValueError, match="must"):
        s.stress(bad_r, bad_z)


def run_cli(*args):
    return subprocess.run([sys.executable, "-m", "torsional_contact", *args], capture_output=True, text=True)


def test_cli_solve_json():
    out = run_cli("solve", "--stick-radius", "0.6", "--json")
    assert out.returncode == 0, out.stderr
    data = json.loads(out.stdout)
    assert {"stick_radius", "torque", "rigid_rotation", "regime", "method"} <= data.keys()
    # the same computation in a subprocess, printed with 17 digits: the same double (a few ulp across processes)
    assert_within(abs(data["torque"] - solve(stick_radius=0.6).torque), 4 * EPS, "the same computation")
    out = run_cli("solve", "--torque", "1.23", "--json", "--method", "published")
    assert out.returncode == 0 and json.loads(out.stdout)["rigid_rotation"] is None


@pytest.mark.parametrize(
    "args",
    [
        ["solve", "--torque", "nan"],
        ["solve", "--torque", "inf"],
        ["solve", "--torque", "1.5"],
        ["solve", "--stick-radius", "2"],
        ["solve", "--stick-radius", "abc"],
        ["solve", "--torque", "1.2", "--stick-radius", "0.5"],
        ["solve"],
        ["solve", "--torque", "1.2", "--method", "bogus"],
        ["solve", "--torque", "1.2", "--n-terms", "0"],
        ["solve", "--torque", "1.2", "--radii", "2"],
        ["nonsense"],
    ],
)
def test_cli_bad_input_exit_2_one_line_nothing_on_stdout(args, capsys):
    assert main(args) == 2
    captured = capsys.readouterr()
    assert captured.out == ""
    assert len(captured.err.strip().splitlines()) == 1 and "error" in captured.err
