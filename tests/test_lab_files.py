"""Lab exports and unit strings at the front door: every export variant of one record reads as the plain CSV (or
says which option makes it read), every unit string is one number and one unit or a one-line refusal, and the
fit's outputs (text report, provenance, residuals, plot) are what a lab can file."""

from __future__ import annotations

import hashlib
import importlib.util
import json
import math
import os
import time

import numpy as np
import pytest
from cli_runner import run_in_process as run
from hypothesis import given, settings
from hypothesis import strategies as st
from lab_exports import VARIANTS, record, write_variant
from tolerances import EPS, assert_close

from torsional_contact import Specimen, extras, fit_loop, units
from torsional_contact.io.lab_files import read_lab_columns
from torsional_contact.io.text_tables import read_text_table

PREFIX = "torsional_contact: error: "
FIT = ["--radius", "5 mm", "--normal-force", "1 kN"]
#: A unit conversion of a written value: the written decimal (17 digits: 0.5 ulp), pint's factor (pi/180 against
#: math.pi/180: 1 ulp) and the product (0.5 ulp), twice over (writing and reading): 4 ulp; 8 ulp of headroom
CONVERSION = 8 * EPS


def one_error_line(status, out, err) -> str:
    assert status == 2 and out == "", (status, out, err)
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith(PREFIX), err
    return lines[0]


# --------------------------------------------------------------------------- every export reads as the plain CSV
@pytest.mark.parametrize("name", [name for name in VARIANTS if not VARIANTS[name].options])
def test_every_export_variant_reads_the_record(tmp_path, name):
    t, torque, twist = record()
    columns = read_lab_columns(write_variant(tmp_path, name), ["torque", "twist"], ["time"])
    assert_close(columns["torque"], torque, "unit conversion of written decimals", rtol=CONVERSION)
    assert_close(columns["twist"], twist, "unit conversion of written decimals", rtol=CONVERSION)
    assert_close(columns["time"], t, "written decimals", rtol=CONVERSION)
    report = columns["report"]
    variant = VARIANTS[name]
    assert report["rows"] == len(t)
    assert report["decimal_mark"] == ("," if variant.decimal_comma else ".")
    assert report["skipped_lines"] == len(variant.metadata)
    assert report["encoding"] == {"cp1252": "windows-1252"}.get(variant.encoding, "utf-8 with BOM" if variant.bom
                                                                 else "utf-8")
    assert report["columns"]["twist"]["header"] == variant.header[2]


def test_named_columns_say_which_option_and_read_with_it(tmp_path):
    path = write_variant(tmp_path, "named_columns")
    with pytest.raises(ValueError, match="no torque column .*say which with --torque-column NAME"):
        read_lab_columns(path, ["torque", "twist"])
    status, out, err = run(["fit", "--loop", str(path), *FIT])
    assert "--torque-column NAME" in one_error_line(status, out, err)
    columns = read_lab_columns(path, ["torque", "twist"], columns={"torque": "T_meas", "twist": "PHI_ENC"})
    _, torque, twist = record()
    assert_close(columns["twist"], twist, "written decimals", rtol=CONVERSION)
    assert_close(columns["torque"], torque, "written decimals", rtol=CONVERSION)


def _fit_json(path, *options) -> dict:
    status, out, err = run(["fit", "--loop", str(path), *FIT, *options, "--json"])
    assert status == 0, err
    return json.loads(out, parse_constant=lambda name: pytest.fail(f"JSON holds {name}"))


def _same_friction(tmp_path, name):
    plain = _fit_json(write_variant(tmp_path, "plain"))
    path = write_variant(tmp_path, name)
    fitted = _fit_json(path, *VARIANTS[name].options)
    # the variants hold the same doubles up to a few ulp of unit conversion; the fit moves f by its condition
    # number times that, far below the 1e-6 a lab reads
    assert abs(fitted["friction"]["value"] - plain["friction"]["value"]) <= 1e-6
    assert fitted["input"]["sha256"] == hashlib.sha256(path.read_bytes()).hexdigest()
    assert fitted["input"]["rows"] == plain["input"]["rows"] == len(record()[0])
    assert fitted["provenance"]["packages"]["torsional_contact"]


@pytest.mark.parametrize("name", ["german", "named_columns"])
def test_export_variants_give_the_friction_of_the_plain_csv(tmp_path, name):
    _same_friction(tmp_path, name)


@pytest.mark.slow
@pytest.mark.parametrize("name", [name for name in VARIANTS if name not in ("plain", "german", "named_columns")])
def test_every_export_variant_gives_the_friction_of_the_plain_csv(tmp_path, name):
    _same_friction(tmp_path, name)


# --------------------------------------------------------------------------- unit strings
#: The unit strings of the issue, each read right (value in SI) or refused (None).
UNIT_STRINGS = [
    ("5,0 mm", "length", None), ("0,5 N m", "torque", None), ("2 3 mm", "length", None), ("5 mm; 3", "length", None),
    ("mm", "length", None), ("(5 mm", "length", None), ("5 mm)", "length", None), ("5 mm^", "length", None),
    ("5 / 0 mm", "length", None), ("1/0", "length", None), ("1e300 N m", "torque", None),
    ("9**9**9 N m", "torque", None), ("5 %", "angle", None), ("5 mm", "length", 5e-3), ("1.8 N m", "torque", 1.8),
    ("1.8 Nm", "torque", 1.8), ("1.8 N-m", "torque", 1.8), ("1.8 N.m", "torque", 1.8), ("1.8 N·m", "torque", 1.8),
    ("1.8 N*m", "torque", 1.8), ("180 Deg", "angle", math.pi), ("180 DEG", "angle", math.pi),
    ("180 °", "angle", math.pi), ("2 RAD", "angle", 2.0), ("2 mrad", "angle", 2e-3), ("3 µm", "length", 3e-6),
    ("1 nm", "torque", None), ("1 N m/rad", "torque", None), ("x" * 1000, "length", None),
    ("5 mm\x1b[2J", "length", None), ("1e-300 m", "length", None), ("inf mm", "length", None),
]


@pytest.mark.parametrize("text, kind, value", UNIT_STRINGS)
def test_unit_strings_are_read_right_or_refused_in_a_second(text, kind, value):
    start = time.perf_counter()
    if value is None:
        with pytest.raises(ValueError, match="^--x") as caught:
            units.si_value("--x", text, kind)
        assert "\x1b" not in str(caught.value) and "\n" not in str(caught.value)
    else:
        assert_close(units.si_value("--x", text, kind), value, "one unit conversion", rtol=4 * EPS)
    assert time.perf_counter() - start < 1.0


def test_decimal_comma_hint_and_percent_twist():
    with pytest.raises(ValueError, match="decimal comma: write 5.0 mm"):
        units.si_value("radius", "5,0 mm", "length")
    with pytest.raises(ValueError, match="percentage, not an angle"):
        units.parse_unit("twist", "%", "angle")
    with pytest.raises(ValueError, match="radius"):
        Specimen(radius="5,0 mm", normal_force="1 kN", friction=0.6, shear_modulus="80 GPa")
    with pytest.raises(ValueError, match="torque_noise"):
        _, torque, twist = record()
        fit_loop(torque, twist, radius="5 mm", normal_force="1 kN", torque_noise="1e300 N m", twist_noise="1e-5 rad")


@pytest.mark.parametrize("option", ["--radius", "--normal-force", "--torque-noise"])
@pytest.mark.parametrize("text", [t for t, kind, v in UNIT_STRINGS if v is None and kind in ("length", "torque")
                                  and t != "1 nm"])  # a length: a radius of 1 nm reads
def test_cli_unit_strings_exit_2_with_one_line(tmp_path, option, text):
    path = write_variant(tmp_path, "plain")
    values = {"--radius": "5 mm", "--normal-force": "1 kN", "--torque-noise": "0.01 N m"}
    values[option] = text
    argv = ["fit", "--loop", str(path)] + [x for k, v in values.items() for x in (k, v)] + ["--twist-noise", "1e-5 rad"]
    start = time.perf_counter()
    line = one_error_line(*run(argv))
    assert time.perf_counter() - start < 1.0
    assert option in line and "\x1b" not in line


@pytest.mark.parametrize("unit", ["(N m", "N m)", "N m^", "1/0", "5 / 0 N m", "%", "9**9**9 N", "N; m", "furlong"])
def test_header_units_outside_the_grammar_exit_2(tmp_path, unit):
    path = tmp_path / "loop.csv"
    t, torque, twist = record()
    path.write_text(f"torque [{unit}],twist [rad]\n" + "".join(f"{q!r},{w!r}\n" for q, w in zip(torque, twist,
                                                                                              strict=True)))
    line = one_error_line(*run(["fit", "--loop", str(path), *FIT]))
    assert "line 1" in line and "torque" in line


# --------------------------------------------------------------------------- small defects
def test_bom_before_a_headerless_first_sample_keeps_it(tmp_path):
    samples = "0.0\n1.25\n-1.25\n1.25\n-1.25\n"
    plain, bom = tmp_path / "plain.txt", tmp_path / "bom.txt"
    plain.write_text(samples)
    bom.write_bytes(b"\xef\xbb\xbf" + samples.encode())
    results = [json.loads(run(["history", "--signal", str(p), "--json"])[1]) for p in (plain, bom)]
    assert results[0]["samples"] == results[1]["samples"] == 5
    assert results[1]["dissipated_energy"] == results[0]["dissipated_energy"] > 0
    table = read_text_table(bom)  # the lab reader: same samples, BOM reported
    assert table.encoding == "utf-8 with BOM" and len(table.rows) == 5


def test_states_through_a_symbolic_link_to_the_output_is_refused(tmp_path):
    signal = tmp_path / "signal.txt"
    signal.write_text("0\n1.25\n-1.25\n1.25\n")
    (tmp_path / "a.csv").write_text("keep\n")
    os.symlink("a.csv", tmp_path / "alias.csv")
    os.link(tmp_path / "a.csv", tmp_path / "hard.csv")
    for other in ("alias.csv", "hard.csv", "a.csv"):
        line = one_error_line(*run(["history", "--signal", str(signal), "--output", str(tmp_path / "a.csv"),
                                    "--states", str(tmp_path / other)]))
        assert "same file as --output" in line
    assert (tmp_path / "a.csv").read_text() == "keep\n"
    new = tmp_path / "new.csv"  # a new name and a dangling link to it: the same file too
    os.symlink("new.csv", tmp_path / "dangling.csv")
    one_error_line(*run(["history", "--signal", str(signal), "--output", str(new), "--states",
                         str(tmp_path / "dangling.csv")]))
    assert not new.exists()


def test_fit_outputs_naming_one_file_are_refused(tmp_path):
    path = write_variant(tmp_path, "plain")
    os.symlink("fit.png", tmp_path / "alias.png")
    line = one_error_line(*run(["fit", "--loop", str(path), *FIT, "--plot", str(tmp_path / "fit.png"),
                                "--residuals", str(tmp_path / "alias.png")]))
    assert "same file" in line
    assert "is the same file as the input" in one_error_line(*run(["fit", "--loop", str(path), *FIT, "--residuals",
                                                                   str(path)]))


@pytest.mark.parametrize("content, expected", [
    (b"torque [N m],twist [rad]\n", "a header and no data rows"),
    (b"torque [N m],twist [rad]\n0,0\n1,2,3\n", r"line 3: 3 field\(s\), the header has 2"),
    (b"torque [N m],twist [rad]\n0,0\n1\n", r"line 3: 1 field\(s\), the header has 2"),
    (b"\x1b]0;pwned\x07Rig 3\ntorque [N m],twist [rad]\n0,0\n1,abc\x1b[2J\n", "line 4: column 'twist"),
    (b"torque [N m],twist\x1b[2J [rad]\n0,0\n1,2\n", "no twist column"),
    (b"torque [N m],twist [%]\n0,0\n1,2\n", "percentage, not an angle"),
    (b"torque [N m],twist [N m]\n0,0\n1,2\n", "must be an angle"),
    (b"torque [N m],angle [deg],rotation [rad]\n0,0,0\n1,2,3\n", "could each be the twist: say which with "
                                                                  "--twist-column NAME"),
    (b"torque [N m],twist [rad]\n0,0\n0,1e300\n", "not a finite number|exceeds"),
])
def test_bad_exports_are_one_line_without_control_bytes(tmp_path, content, expected):
    path = tmp_path / "bad.csv"
    path.write_bytes(content)
    with pytest.raises(ValueError, match=expected):
        read_lab_columns(path, ["torque", "twist"])
    line = one_error_line(*run(["fit", "--loop", str(path), *FIT]))
    assert not any(ord(c) < 32 or 0x7f <= ord(c) < 0xa0 for c in line), repr(line)


def test_binary_inputs_are_named_as_such(tmp_path):
    npz = tmp_path / "record.npz"
    np.savez(npz, torque=np.zeros(30), twist=np.ones(30))
    for argv in (["fit", "--loop", str(npz), *FIT], ["history", "--signal", str(npz)]):
        line = one_error_line(*run(argv))
        assert "NumPy .npz" in line and "PK" not in line


def test_header_only_signal_is_one_line_without_a_numpy_warning(tmp_path):
    path = tmp_path / "header.txt"
    path.write_text("torque\n")
    line = one_error_line(*run(["history", "--signal", str(path)]))
    assert "a header line and no samples" in line


def test_constant_loop_names_the_file_not_a_numpy_repr(tmp_path):
    path = tmp_path / "flat.csv"
    path.write_text("torque [N m],twist [rad]\n" + "".join(f"0,{k * 1e-5}\n" for k in range(30)))
    line = one_error_line(*run(["fit", "--loop", str(path), *FIT]))
    assert str(path) in line and "np.float64" not in line and "constant (0 N m in every row)" in line


def test_gate_takes_units_like_every_other_option(tmp_path):
    path = tmp_path / "signal.csv"
    t = [k / 100 for k in range(201)]
    path.write_text("time [s],torque [N m]\n" + "".join(f"{a!r},{1.8 * math.sin(2 * math.pi * a)!r}\n" for a in t))
    specimen = ["--radius", "5 mm", "--normal-force", "1 kN", "--friction", "0.6", "--shear-modulus", "80 GPa"]
    status, out, err = run(["history", "--signal", str(path), *specimen, "--gate", "0.15 N m", "--json"])
    assert status == 0, err
    assert_close(json.loads(out)["gate"], 0.15, "one unit conversion", rtol=4 * EPS)
    assert "--gate" in one_error_line(*run(["history", "--signal", str(path), *specimen, "--gate", "0,15 N m"]))


def test_negative_torque_beyond_gross_slip_says_below(capsys):
    line = one_error_line(*run(["solve", "--torque", "-1e308"]))
    assert "below -4/3" in line and "above" not in line


def test_missing_extras_name_the_pypi_packages(monkeypatch):
    assert "python-flint" in extras.missing_message("reference", ["flint"], "reference")
    monkeypatch.setattr(extras.importlib.util, "find_spec", lambda name: None)
    with pytest.raises(extras.MissingExtraError, match="python-flint.*pip install 'torsional_contact\\[reference\\]'"):
        extras.require("reference", "the reference subcommand")
    with pytest.raises(extras.MissingExtraError, match="scikit-fem"):
        extras.require("fem", "the finite-element check")


def test_finite_element_module_without_scikit_fem_says_which_package(monkeypatch):
    import sys

    for name in [n for n in sys.modules if n == "skfem" or n.startswith("skfem.")
                 or n == "torsional_contact.verification.finite_element"]:
        monkeypatch.delitem(sys.modules, name)
    monkeypatch.setitem(sys.modules, "skfem", None)  # import skfem raises ModuleNotFoundError
    with pytest.raises(extras.MissingExtraError, match="scikit-fem.*torsional_contact\\[fem\\]"):
        __import__("torsional_contact.verification.finite_element")


# --------------------------------------------------------------------------- outputs a lab can file
def test_fit_text_report_is_readable_and_json_carries_provenance(tmp_path):
    path = write_variant(tmp_path, "german")
    status, out, err = run(["fit", "--loop", str(path), *FIT])
    assert status == 0, err
    assert "{'" not in out and "None" not in out and "True" not in out
    assert "friction f" in out and "semicolon-separated, decimal comma, windows-1252" in out
    assert "3 line(s) above it skipped" in out and '"Winkel [°]"' in out
    result = _fit_json(path, "--confidence", "0.9")
    assert result["confidence"] == 0.9
    low, high = result["friction"]["interval"]
    wide = _fit_json(path)["friction"]["interval"]
    assert wide[0] < low < high < wide[1]  # a 90 % interval inside the 95 % one
    assert result["input"]["columns"]["twist"] == {"header": "Winkel [°]", "unit": "°", "to_si": math.pi / 180,
                                                   "si_unit": "rad"}
    for bad in ("0", "1", "nan", "1.5"):
        assert "--confidence" in one_error_line(*run(["fit", "--loop", str(path), *FIT, "--confidence", bad]))


def test_residuals_are_noise_sized_and_the_plot_is_written(tmp_path):
    path = write_variant(tmp_path, "plain")
    residuals, plot = tmp_path / "residuals.csv", tmp_path / "fit.png"
    options = ["--residuals", str(residuals)]
    if importlib.util.find_spec("matplotlib") is not None:
        options += ["--plot", str(plot)]
    fitted = _fit_json(path, *options)
    table = read_lab_columns(residuals, ["torque"])
    _, torque, _ = record()
    assert_close(table["torque"], torque, "written to 16 digits", rtol=1e-15)
    names = read_text_table(residuals).header
    assert names == ["sample", "time [s]", "torque [N m]", "twist [rad]", "spike", "fitted_torque [N m]",
                     "torque_residual [N m]", "normalized_residual"]
    assert not read_text_table(residuals).column(4, "spike").any()
    normalised = read_text_table(residuals).column(7, "normalized_residual")
    # the record's noise is white and Gaussian at the levels the fit estimates: the normalised residuals are about
    # standard normal; their standard deviation from 721 samples has a standard error 1/sqrt(2 x 721) = 0.026
    # (4 standard errors: 0.11), and the fit's own noise scale moves it by |noise_scale - 1|
    assert abs(np.std(normalised) - 1.0) <= 0.11 + abs(fitted["noise_scale"] - 1.0)
    if "--plot" in options:
        assert plot.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
        assert fitted["outputs"] == {"--residuals": str(residuals), "--plot": str(plot)}


def test_spikes_removed_by_the_fit_are_marked_in_the_residuals(tmp_path):
    t, torque, twist = record()
    torque = list(torque)
    torque[100] += 1.5  # 150 times the torque noise: a spike the fit removes
    path = tmp_path / "spiky.csv"
    path.write_text("torque [N m],twist [rad]\n" + "".join(f"{q!r},{w!r}\n" for q, w in zip(torque, twist,
                                                                                              strict=True)))
    residuals = tmp_path / "r.csv"
    result = _fit_json(path, "--residuals", str(residuals))
    table = read_text_table(residuals)
    spike = table.column(3, "spike")
    assert result["spikes"] == int(spike.sum()) >= 1 and spike[100] == 1
    assert np.isnan(table.column(6, "normalized_residual")[spike == 1]).all()


def test_shipped_export_is_the_record_and_gives_its_friction(tmp_path):
    """notebooks/data/lab_export.csv is what workflow/scripts/make_lab_export.py writes from lab_loop.csv, and its
    fit (with the column options of the README) gives the friction of lab_loop.csv."""
    import importlib.util as util

    from lab_exports import RECORD, ROOT

    spec = util.spec_from_file_location("make_lab_export", ROOT / "workflow" / "scripts" / "make_lab_export.py")
    script = util.module_from_spec(spec)
    spec.loader.exec_module(script)
    shipped = ROOT / "notebooks" / "data" / "lab_export.csv"
    assert shipped.read_bytes() == script.export(RECORD.read_text(encoding="utf-8")).encode("utf-8")
    options = ["--torque-column", "Moment M_t", "--twist-column", "Drehwinkel phi"]
    export, plain = _fit_json(shipped, *options), _fit_json(RECORD)
    assert abs(export["friction"]["value"] - plain["friction"]["value"]) <= 1e-6
    assert export["input"]["skipped_lines"] == 5 and export["input"]["decimal_mark"] == ","


def test_history_reads_an_export_with_named_columns(tmp_path):
    specimen = ["--radius", "5 mm", "--normal-force", "1 kN", "--friction", "0.6", "--shear-modulus", "80 GPa"]
    plain, export = tmp_path / "plain.csv", tmp_path / "export.csv"
    torques = [0.0, 1.8, -1.8, 1.8, -1.8, 1.2]  # T* = 1.2: the cylinders slip
    plain.write_text("time [s],torque [N m]\n" + "".join(f"{k},{q!r}\n" for k, q in enumerate(torques)))
    export.write_bytes(("Rig: 3\r\nZeit [s];Moment M [N·m]\r\n" + "".join(
        f"{k};{q!r}\r\n".replace(".", ",") for k, q in enumerate(torques))).encode("cp1252"))
    assert "--torque-column NAME" in one_error_line(*run(["history", "--signal", str(export), *specimen]))
    results = [run(["history", "--signal", str(path), *specimen, *options, "--json"]) for path, options in
               ((plain, []), (export, ["--torque-column", "moment m"]))]
    assert [r[0] for r in results] == [0, 0], results
    first, second = (json.loads(r[1]) for r in results)
    assert first["dissipated_energy"] == second["dissipated_energy"] > 0
    assert "needs --signal and the specimen options" in one_error_line(
        *run(["history", "--turning-points", "0", "1", "--torque-column", "x"]))


# The fast reading (one pattern per separator, whole-column conversion) against the field-by-field reading it
# replaces, on lines drawn from what exports hold: the same lines of numbers, the same numbers, the same refusals.
_ATOMS = ["1", "2.5", "0,5", "-3e2", "+.5", "7.", "nan", "-Inf", "infinity", "x", "[N m]", " ", "\t", ";", ",",
          ".", '"', "\u00a0", "1,5,2", "e5", "1.2,3"]


@settings(max_examples=400, deadline=None)
@given(st.lists(st.lists(st.sampled_from(_ATOMS), min_size=1, max_size=12).map("".join), min_size=1, max_size=6))
def test_fast_line_scan_is_the_field_by_field_test(lines):
    from torsional_contact.io import text_tables as tt
    content = [(n, line) for n, line in enumerate(lines, start=1)]
    for delimiter in tt.DELIMITERS:
        slow = [i for i, (_, line) in enumerate(content) if tt._numeric(tt._fields(line, delimiter), delimiter)]
        assert list(tt._numeric_lines(content, delimiter)) == slow, delimiter


@settings(max_examples=400, deadline=None)
@given(st.lists(st.sampled_from(["1", "2.5", "0,5", ",5", "-3e2", "7.", "nan", "-Inf", "", "x", "1,5,2", "1.2,3",
                                 "e5", "+", "\u0663"]), min_size=1, max_size=8), st.booleans())
def test_whole_column_conversion_is_the_field_by_field_one(cells, comma):
    from torsional_contact.io import text_tables as tt
    table = tt.TextTable(label="t", path="t", sha256="", encoding="utf-8", delimiter=";",
                         decimal_mark="," if comma else ".", skipped_lines=0, header_line=None, header=None,
                         rows=[(n, [cell]) for n, cell in enumerate(cells, start=1)])
    expected = [tt._number(cell, comma) for cell in cells]
    if None in expected:
        first = expected.index(None)
        with pytest.raises(ValueError, match=f"line {first + 1}: column"):
            table.column(0, "c")
    else:
        np.testing.assert_array_equal(table.column(0, "c"), np.array(expected))


def test_per_cycle_plot_shows_each_cycle_and_its_friction(tmp_path):
    """With --per-cycle the plot has the cycles' loops beside the record and a row of f against the cycle number:
    the cycles are found by the sample ranges the per-cycle fit reports (start and end, both in the cycle)."""
    from torsional_contact.fitting.synthetic import Rig, noisy, twist_controlled
    from torsional_contact.io.fit_report import _cycles, cycle_friction

    if importlib.util.find_spec("matplotlib") is None:
        pytest.skip("matplotlib (the plots extra) not installed")
    rig = Rig(radius=0.005, normal_force=1000.0, friction=0.6, shear_modulus=80e9, compliance=4e-4, offset=1e-4)
    torque, twist = noisy(*twist_controlled(rig, 2.5e-3, cycles=4, samples_per_cycle=120),
                          0.005 * 4.0, 1e-5, np.random.default_rng(5))
    path = tmp_path / "cycles.csv"
    path.write_text("torque [N m],twist [rad]\n" + "".join(f"{float(q)!r},{float(w)!r}\n"
                                                           for q, w in zip(torque, twist, strict=True)))
    plots = {name: tmp_path / f"{name}.png" for name in ("whole", "per_cycle")}
    whole = _fit_json(path, "--plot", str(plots["whole"]))
    cycles = _fit_json(path, "--per-cycle", "--plot", str(plots["per_cycle"]))
    spans = _cycles(cycles)
    assert len(spans) == len(cycles["cycles"]) >= 2
    assert all(first < stop <= torque.size for first, stop in spans)
    assert _cycles(whole) == [] and cycle_friction(whole) == []
    per_cycle = cycle_friction(cycles)
    assert [n for n, *_ in per_cycle] == [c["cycle"] for c in cycles["cycles"]]
    for (_, value, lo, hi), cycle in zip(per_cycle, cycles["cycles"], strict=True):
        assert value == cycle["friction"]["value"] and [lo, hi] == cycle["friction"]["interval"]

    def height(png):  # the PNG header's height (rows of pixels)
        return int.from_bytes(png.read_bytes()[20:24], "big")

    # three rows of panels (3.2 in each) against two, at 150 dpi
    assert height(plots["per_cycle"]) == round(3 * 3.2 * 150) and height(plots["whole"]) == round(2 * 3.2 * 150)
