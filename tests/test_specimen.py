"""Physical units at the boundary: Specimen, SI states, lab CSV files and the command line's specimen options."""

from __future__ import annotations

import json
import math

import numpy as np
import pint
import pytest
from tolerances import EPS, assert_close

from torsional_contact import Specimen, history, solve
from torsional_contact.io.cli import main
from torsional_contact.io.lab_files import read_lab_columns

LAB = dict(radius="5 mm", normal_force="1 kN", friction=0.6, shear_modulus="80 GPa")
SPECIMEN_ARGS = ["--radius", "5 mm", "--normal-force", "1 kN", "--friction", "0.6", "--shear-modulus", "80 GPa"]
#: Every conversion below is a product or quotient of at most ~20 floats on either side (pint's unit factors and
#: prefixes, pi, powers of a, f p0 / mu), each rounding by at most one ulp (relative EPS): 2 x 20 EPS = 8.9e-15.
ROUNDING = 40 * EPS
#: The energies of the memory rules are sums of W_mono values up to the total dissipated: their rounding, 64 EPS of
#: the total (as in tests/test_history.py), plus the unit conversion.
SUMS = 64 * EPS + ROUNDING


def test_values_in_any_form_give_the_same_specimen():
    ureg = pint.UnitRegistry()
    a = Specimen(**LAB, gauge_length="20 mm")
    b = Specimen(radius=0.005, normal_force=1000.0, friction=0.6, shear_modulus=8e10, gauge_length=0.02)
    c = Specimen(radius=5 * ureg.mm, normal_force=1 * ureg.kN, friction=0.6, shear_modulus=80 * ureg.GPa,
                 gauge_length=2 * ureg.cm)
    for other in (b, c):
        for key, value in a.as_dict().items():
            if key == "model":
                assert getattr(other, key) == value == "cylinder"
            else:
                assert_close(getattr(other, key), value, "conversion rounding", rtol=ROUNDING)
    assert_close(a.pressure, 1000.0 / (math.pi * 0.005**2), "conversion rounding", rtol=ROUNDING)


@pytest.mark.parametrize("key, value, match", [
    ("radius", "1 kN", "radius must be a length.*force"),
    ("normal_force", "5 mm", "normal_force must be a force.*length"),
    ("shear_modulus", "80 mm", "shear_modulus must be a pressure.*length"),
    ("friction", "0.6 m", "friction must be a plain number.*length"),
    ("radius", -1.0, "radius must be finite and > 0"),
    ("radius", 0.0, "radius must be finite and > 0"),
    ("shear_modulus", math.nan, "shear_modulus must be finite"),
    ("normal_force", "lots", "normal_force: cannot read 'lots' as force"),
    ("friction", True, "friction must be a plain number"),
])
def test_bad_values_name_the_argument_and_the_dimension(key, value, match):
    with pytest.raises(ValueError, match=match):
        Specimen(**{**LAB, key: value})


def test_states_in_si_units_and_the_normalised_state_one_attribute_away():
    s = Specimen(**LAB, gauge_length="20 mm")
    state = s.solve(torque="1.8 N*m")
    t_star = 2 * 1.8 / (0.6 * 1000.0 * 0.005)
    assert_close(state.normalized.torque, t_star, "conversion rounding", rtol=ROUNDING)
    reference = solve(torque=t_star)
    assert_close(state.stick_radius, reference.stick_radius * 0.005, "conversion rounding", rtol=ROUNDING)
    f_p0 = 0.6 * 1000.0 / (math.pi * 0.005**2)
    assert_close(state.rigid_rotation, reference.rigid_rotation * f_p0 / 8e10, "conversion rounding", rtol=ROUNDING)
    assert_close(state.traction("2 mm"), float(reference.traction(0.4)) * f_p0, "conversion rounding", rtol=ROUNDING)
    record = state.as_dict()
    assert record["units"] == {"torque": "N m", "stick_radius": "m", "rigid_rotation": "rad", "twist": "rad"}
    assert_close(record["normalized"]["torque"], t_star, "conversion rounding", rtol=ROUNDING)
    with pytest.raises(ValueError, match="torque must lie in .* N m"):
        s.solve(torque="2.1 N m")
    with pytest.raises(ValueError, match="stick_radius must lie in"):
        s.solve(stick_radius="6 mm")


def test_twist_in_stick_is_the_uniform_twist_of_a_shaft():
    """(f p0 / mu)(T* L / a) = T L / (G J), J = pi a^4 / 2: the elastic shaft alone (omega = 0 in stick)."""
    s = Specimen(**LAB, gauge_length="20 mm")
    torque = 1.2  # N m, below the slip onset f F a / 2 = 1.5 N m
    state = s.solve(torque=torque)
    assert state.regime == "stick" and state.rigid_rotation == 0.0
    shaft = torque * 0.02 / (8e10 * math.pi * 0.005**4 / 2)
    assert_close(state.twist, shaft, "conversion rounding", rtol=ROUNDING)
    assert_close(s.shaft_compliance() * torque, shaft, "conversion rounding", rtol=ROUNDING)
    slipping = s.solve(torque=1.8)  # the contact adds 2 omega f p0 / mu
    # the difference cancels: both terms carry the conversions' rounding of the whole twist
    assert_close(slipping.twist - 1.8 * s.shaft_compliance(), 2 * slipping.rigid_rotation,
                 "conversion rounding of the twist (cancellation)", atol=2 * ROUNDING * slipping.twist)


def test_energies_in_joules():
    s = Specimen(**LAB)
    torques = [0.0, 1.8, -1.8, 1.8]
    states = s.history(torques)
    normalised = history([t / s.torque_scale for t in torques])
    scale = (0.6 * 1000.0 / (math.pi * 0.005**2)) ** 2 * 0.005**3 / 8e10
    for state, reference in zip(states, normalised, strict=True):
        assert_close(state.dissipated_energy, reference.dissipated_energy * scale, "conversion rounding", rtol=ROUNDING)
    # a closed cycle: the energy of the second full reversal equals W(2 T*_a) of the cycle
    per_cycle = states[3].dissipated_energy - states[1].dissipated_energy
    assert_close(s.energy_per_cycle(1.8), per_cycle, "sums of W_mono", atol=2 * SUMS * states[3].dissipated_energy)
    assert s.energy_per_cycle(1.4) == 0.0 and s.regime(1.4) == "stick"
    assert s.regime(1.8) == "partial-slip" and s.regime(2.0) == "gross-slip"
    signal = s.signal([0.0, 1.8, -1.8, 1.8, -1.8])
    assert_close(sum(c["energy"] * 1 for c in signal.cycles()), signal.dissipated_energy - states[1].dissipated_energy,
                 "sums of W_mono", atol=2 * SUMS * signal.dissipated_energy)



def test_half_space_model_in_si_units(capsys):
    """The half-space model through the specimen: the normalised closed forms times the same scales."""
    s = Specimen(**LAB, gauge_length="20 mm")
    torque_star = 1.8 / s.torque_scale
    state = s.solve(torque="1.8 N m", model="half-space")
    reference = solve(torque=torque_star, model="half-space")
    assert_close(state.stick_radius, reference.stick_radius * 0.005, "conversion rounding", rtol=ROUNDING)
    assert_close(state.rigid_rotation, reference.rigid_rotation * s.rotation_scale, "conversion rounding",
                 rtol=ROUNDING)
    # two half-spaces have no cross-sections: the twist is the relative rotation of remote points, 2 Omega
    assert_close(state.twist, 2.0 * reference.rigid_rotation * s.rotation_scale, "conversion rounding", rtol=ROUNDING)
    # a half-space slips at any torque: W(A) = 4 W_mono(A/2) of its own closed forms, per cycle
    states = s.history([0.0, 0.5, -0.5, 0.5], model="half-space")
    per_cycle = states[3].dissipated_energy - states[1].dissipated_energy
    assert per_cycle > 0
    assert_close(s.energy_per_cycle(0.5, model="half-space"), per_cycle, "sums of W_mono",
                 atol=2 * SUMS * states[3].dissipated_energy)
    assert s.regime(0.5, model="half-space") == "partial-slip" and s.regime(0.5) == "stick"
    assert main(["solve", "--torque", "1.8 N m", *SPECIMEN_ARGS, "--gauge-length", "20 mm", "--model", "half-space",
                 "--json"]) == 2
    assert "--gauge-length does not apply to model 'half-space'" in capsys.readouterr().err
    assert main(["solve", "--torque", "1.8 N m", *SPECIMEN_ARGS, "--model", "half-space", "--json"]) == 0
    record = json.loads(capsys.readouterr().out)
    assert record["model"] == "half-space"
    assert_close(record["rigid_rotation"], state.rigid_rotation, "conversion rounding", rtol=ROUNDING)
    assert_close(record["twist"], state.twist, "conversion rounding", rtol=ROUNDING)

def _write(path, text):
    path.write_text(text, encoding="utf-8")
    return str(path)


@pytest.mark.parametrize("unit, factor", [("N m", 1.0), ("N*m", 1.0), ("N·m", 1.0), ("Nm", 1.0), ("kN m", 1e3),
                                          ("N mm", 1e-3), ("Nmm", 1e-3), ("kNm", 1e3)])
def test_lab_file_unit_spellings(tmp_path, unit, factor):
    path = _write(tmp_path / "a.csv", f"# rig 3\ntime [ms],Torque [{unit}]\n0,0\n5,1.5\n10,-2\n")
    columns = read_lab_columns(path, ["torque"], ["time"])
    assert_close(columns["torque"], np.array([0.0, 1.5, -2.0]) * factor, "conversion rounding", rtol=ROUNDING)
    assert_close(columns["time"], [0.0, 0.005, 0.01], "conversion rounding", rtol=ROUNDING)


@pytest.mark.parametrize("content, match", [
    ("1,2\n3,4\n", "no header"),
    ("time [s],torque [furlong]\n0,1\n", "must be a torque"),
    ("time [s],torque [bogons]\n0,1\n", "cannot read"),
    ("time [s],torque\n0,1\n", "has no unit"),
    ("time [s],force [N]\n0,1\n", "no torque column .*--torque-column NAME"),
    ("time [s],torque [N m]\n0,0\n1,1\n1,2\n", "line 4: time 1 s does not increase"),
    ("time [s],torque [N m]\n0,0\n1,nan\n", r"line 3: column 'torque \[N m\]'.*not a finite number"),
    ("time [s],torque [N m]\n0,0\n1,abc\n", r"line 3: column 'torque \[N m\]'.*not a number"),
    ("", "no header and no data"),
])
def test_bad_lab_files(tmp_path, content, match):
    path = _write(tmp_path / "bad.csv", content)
    with pytest.raises(ValueError, match=match):
        read_lab_columns(path, ["torque"], ["time"])


def _cli(capsys, *args):
    code = main(list(args))
    out, err = capsys.readouterr()
    return code, out, err


def test_cli_solve_in_si_units(capsys):
    code, out, err = _cli(capsys, "solve", "--torque", "1.8 N*m", *SPECIMEN_ARGS, "--gauge-length", "20 mm", "--json")
    assert code == 0, err
    data = json.loads(out)
    assert {"stick_radius", "torque", "rigid_rotation", "regime", "twist", "units", "normalized"} <= data.keys()
    assert data["units"]["twist"] == "rad" and data["units"]["torque"] == "N m"
    state = Specimen(**LAB, gauge_length=0.02).solve(torque=1.8)
    assert_close(data["twist"], state.twist, "conversion rounding", rtol=ROUNDING)
    assert_close(data["normalized"]["torque"], 1.2, "conversion rounding", rtol=ROUNDING)
    code, out, err = _cli(capsys, "solve", "--torque", "1.23", "--json")  # without the options: unchanged
    assert code == 0 and "units" not in json.loads(out)


@pytest.mark.parametrize("args, match", [
    (["solve", "--torque", "1.8 N m", "--radius", "5 mm", "--normal-force", "1 kN", "--friction", "0.6"],
     "--shear-modulus is missing"),
    (["solve", "--torque", "1.8 N m"], "is not a plain number: values with units need the specimen options"),
    (["solve", "--torque", "1.8 N m", "--radius", "1 kN", "--normal-force", "1 kN", "--friction", "0.6",
      "--shear-modulus", "80 GPa"], "--radius must be a length"),
    (["solve", "--torque", "3 N m", *SPECIMEN_ARGS], "beyond it the cylinders spin"),
    (["solve", "--torque", "1.23", "--gauge-length", "2 cm"], "--gauge-length needs the specimen options"),
    (["fit", "--loop", "absent.csv", "--radius", "5 mm"], "required: --normal-force"),
])
def test_cli_usage_errors_are_one_line_and_exit_2(capsys, args, match):
    code, out, err = _cli(capsys, *args, "--json")
    assert code == 2 and out == ""
    assert len(err.strip().splitlines()) == 1
    assert __import__("re").search(match, err), err


def test_cli_history_signal_in_si_units(tmp_path, capsys):
    t = np.linspace(0.0, 2.0, 401)
    torque = 1.8 * np.sin(2 * np.pi * t)
    path = tmp_path / "lab.csv"
    rows = "".join(f"{a:.17g},{b * 1e3:.17g}\n" for a, b in zip(t, torque, strict=True))
    path.write_text("time [s],torque [N mm]\n" + rows)
    code, out, err = _cli(capsys, "history", "--signal", str(path), *SPECIMEN_ARGS, "--json")
    assert code == 0, err
    data = json.loads(out)
    s = Specimen(**LAB)
    reference = s.signal(torque)
    # the file holds the torque in N mm to 17 digits: read back and converted, each sample within 2 ulp of the
    # array's; the energy (sums of W at the turning torques) moves by its logarithmic slope in the torque times that
    # (the slope of W(A) at A = 2 x 1.8 N m by a central difference), plus the sums' and conversions' rounding
    up, down = s.energy_per_cycle(1.8 * (1 + 1e-4)), s.energy_per_cycle(1.8 * (1 - 1e-4))
    slope = math.log(up / down) / (math.log1p(1e-4) - math.log1p(-1e-4))
    inputs = slope * 2 * EPS + 2 * SUMS
    assert_close(data["dissipated_energy"], reference.dissipated_energy, "input rounding x slope + sums",
                 rtol=inputs)
    assert data["units"]["dissipated_energy"] == "J" and data["units"]["energy"] == "J"
    assert all("energy" in cycle for cycle in data["cycles"])
    assert_close(sum(c["energy"] for c in data["cycles"]), sum(c["energy"] for c in reference.cycles()),
                 "input rounding x slope + sums", rtol=inputs)
    one_column = tmp_path / "tstar.txt"  # the normalised one-column files keep working without the options
    one_column.write_text("\n".join(f"{v / 1.5:.17g}" for v in torque) + "\n")
    code, out, err = _cli(capsys, "history", "--signal", str(one_column), "--json")
    assert code == 0
    assert_close(json.loads(out)["dissipated_energy"] * s.energy_scale, reference.dissipated_energy,
                 "input rounding x slope + sums", rtol=inputs)
