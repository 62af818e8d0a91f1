"""The half-space model against the cylinders: a table at a few torques, the numbers the text quotes.

Units: T* = 2T/(f F a); rotations in f p0 / G; energies per cycle in (f p0)^2 a^3 / G (G the shear modulus).  For
each torque T* of the table: the stick radius of both models; the contact's extra rotation
(cylinders: 2 omega beyond the uniform twist; half-spaces: the relative twist phi = 2 Omega and
its part beyond the bonded contact, phi - 3 pi T*/16); the energy per cycle of a fully reversed
torque of amplitude T* (range A = 2 T*); and the ratio f_fit / f that a half-space fit of the
cylinders' energy per cycle returns (``half_space.comparison``).  Plus a worked example in SI
units (plain arithmetic; it can switch to a specimen interface later).  Writes JSON with
metadata, a LaTeX table and LaTeX macros.
"""

import argparse
import math

from torsional_contact.contact_models.cylinder import point
from torsional_contact.half_space import closed_form as hs
from torsional_contact.model_comparison import apparent_friction_ratio, energy_per_cycle
from torsional_contact.provenance import write_json, write_macros, write_text
from torsional_contact.typeset import sci


def _row(torque: float) -> dict:
    b_cyl, omega, _ = point(torque, "fast", None)
    b_hs, big_omega, _ = hs.state(torque)
    amplitude = 2 * torque
    return {
        "torque": torque,
        "stick_radius_cylinder": b_cyl,
        "stick_radius_half_space": b_hs,
        "extra_rotation_cylinder": 2 * omega,  # 2 omega: beyond the monolithic shaft's uniform twist
        "relative_twist_half_space": 2 * big_omega,  # phi = 2 Omega: all of the half-spaces' twist
        "slip_twist_half_space": 2 * big_omega - 2 * hs.BONDED_COMPLIANCE * torque,  # phi - 3 pi T*/16
        "energy_cylinder": energy_per_cycle(amplitude, "cylinder"),
        "energy_half_space": energy_per_cycle(amplitude, "half-space"),
        "friction_ratio": apparent_friction_ratio(amplitude),
    }


def _num(x: float, digits: int = 3) -> str:
    """A table entry: 0, a decimal or scientific notation; +inf (no finite fit) as an en dash."""
    if math.isinf(x):
        return "--"
    return "0" if x == 0 else f"${sci(x, digits)}$"  # math mode: sci may give a \times10^{..}


def example(radius, normal_force, shear_modulus, friction, torque_range) -> dict:
    """The worked example: SI in, SI out (N, m, Pa, J)."""
    pressure = normal_force / (math.pi * radius**2)
    energy_unit = (friction * pressure) ** 2 * radius**3 / shear_modulus  # (f p0)^2 a^3 / G [J]
    rotation_unit = friction * pressure / shear_modulus  # f p0 / G [rad]
    amplitude = 2 * torque_range / (friction * normal_force * radius)  # A = Delta T* (range)
    kappa = apparent_friction_ratio(amplitude)
    b_cyl, omega, _ = point(amplitude / 2, "fast", None)
    _, big_omega, _ = hs.state(amplitude / 2)
    return {
        "pressure": pressure, "energy_unit": energy_unit, "rotation_unit": rotation_unit,
        "torque_range_normalised": amplitude,
        "energy": energy_per_cycle(amplitude, "cylinder") * energy_unit,
        "energy_half_space_true_friction": energy_per_cycle(amplitude, "half-space") * energy_unit,
        "friction_ratio": kappa, "fitted_friction": kappa * friction,
        "stick_radius_cylinder": b_cyl,
        "extra_rotation_cylinder": 2 * omega * rotation_unit,
        "relative_twist_half_space": 2 * big_omega * rotation_unit,
    }


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--torques", type=float, nargs="+", required=True, help="T* of the table rows")
    p.add_argument("--fit-ranges", type=float, nargs="+", required=True, help="ranges A of quoted friction ratios")
    p.add_argument("--radius", type=float, required=True, help="worked example: a [m]")
    p.add_argument("--normal-force", type=float, required=True, help="F [N]")
    p.add_argument("--shear-modulus", type=float, required=True, help="G, the shear modulus [Pa]")
    p.add_argument("--friction", type=float, required=True, help="the true f")
    p.add_argument("--torque-range", type=float, required=True, help="Delta T [N m], peak to peak")
    p.add_argument("--json", required=True)
    p.add_argument("--tex", required=True)
    p.add_argument("--macros", required=True)
    a = p.parse_args()

    rows = [_row(t) for t in a.torques]
    fits = {f"{r:g}": apparent_friction_ratio(r) for r in a.fit_ranges}
    worked = example(a.radius, a.normal_force, a.shear_modulus, a.friction, a.torque_range)
    onset = hs.state(1.0)
    constants = {
        "small_amplitude_coefficient": hs.SMALL_AMPLITUDE_COEFFICIENT,
        "small_amplitude_exponent": hs.SMALL_AMPLITUDE_EXPONENT,
        "small_amplitude_correction": hs.SMALL_AMPLITUDE_CORRECTION,
        "bonded_compliance": hs.BONDED_COMPLIANCE,
        "half_space_stick_radius_at_slip_onset": onset[0],
        "half_space_energy_at_range_2": energy_per_cycle(2.0, "half-space"),
    }
    write_json(a.json, {"rows": [{k: (None if isinstance(v, float) and math.isinf(v) else v) for k, v in r.items()}
                                 for r in rows],
                        "friction_ratio": {k: (None if math.isinf(v) else v) for k, v in fits.items()},
                        "example": worked, "constants": constants,
                        "example_input": {"radius": a.radius, "normal_force": a.normal_force,
                                          "shear_modulus": a.shear_modulus, "friction": a.friction,
                                          "torque_range": a.torque_range}},
               method="half-space closed forms (half_space.closed_form); cylinders: fast (curve interpolants)",
               precision="IEEE double")

    lines = [
        "% generated by workflow/scripts/half_space_table.py",
        r"\begin{tabular}{rrrrrrrrr}",
        r"\toprule",
        r"& \multicolumn{2}{c}{$b/a$} & \multicolumn{3}{c}{extra rotation [$fp_0/G$]}"
        r" & \multicolumn{2}{c}{$W(2T^*)$ [$(fp_0)^2a^3/G$]} & \\",
        r"$T^*$ & cyl. & h.-s. & cyl. $2\omega$ & h.-s. $\phi_\mathrm{h}$ & $\phi_\mathrm{h} - 3\pi T^*/16$"
        r" & cyl. & h.-s."
        r" & $f_\mathrm{fit}/f$\\",
        r"\midrule",
    ]
    for r in rows:
        lines.append(" & ".join([f"{r['torque']:g}", f"{r['stick_radius_cylinder']:.4f}",
                                 f"{r['stick_radius_half_space']:.4f}", _num(r["extra_rotation_cylinder"]),
                                 _num(r["relative_twist_half_space"]), _num(r["slip_twist_half_space"]),
                                 _num(r["energy_cylinder"]), _num(r["energy_half_space"]),
                                 _num(r["friction_ratio"])]) + r"\\")
    lines += [r"\bottomrule", r"\end{tabular}"]
    write_text(a.tex, "\n".join(lines) + "\n")

    values = {
        "hs-energy-coefficient": sci(hs.SMALL_AMPLITUDE_COEFFICIENT, 4),
        "hs-energy-exponent": f"{hs.SMALL_AMPLITUDE_EXPONENT}",
        "hs-energy-correction": sci(hs.SMALL_AMPLITUDE_CORRECTION, 4),
        "hs-bonded-compliance": sci(hs.BONDED_COMPLIANCE, 4),
        "hs-onset-stick-radius": f"{onset[0]:.4f}",
        "hs-onset-slip-width": f"{1 - onset[0]:.4f}",
        "hs-onset-twist": f"{2 * onset[1]:.4f}",
        "hs-energy-range-two": sci(constants["half_space_energy_at_range_2"], 3),
        "hs-table-rows": f"{len(rows)}",
    }
    for r in rows:
        key = f"{r['torque']:g}"
        values[f"hs-b-cyl-t{key}"] = f"{r['stick_radius_cylinder']:.4f}"
        values[f"hs-b-hs-t{key}"] = f"{r['stick_radius_half_space']:.4f}"
        values[f"hs-energy-ratio-t{key}"] = ("--" if r["energy_cylinder"] == 0
                                             else sci(r["energy_half_space"] / r["energy_cylinder"], 2))
    for key, kappa in fits.items():
        values[f"hs-fit-ratio-a{key}"] = "--" if math.isinf(kappa) else f"{kappa:.3f}"
    ex = worked
    values.update({
        "ex-radius-mm": f"{1e3 * a.radius:g}", "ex-force": f"{a.normal_force:g}",
        "ex-shear-modulus-gpa": f"{1e-9 * a.shear_modulus:g}", "ex-friction": f"{a.friction:g}",
        "ex-torque-range": f"{a.torque_range:g}", "ex-pressure-mpa": f"{1e-6 * ex['pressure']:.2f}",
        "ex-range-normalised": f"{ex['torque_range_normalised']:.3f}",
        "ex-energy-unit-mj": sci(1e3 * ex["energy_unit"], 3),
        "ex-energy-mj": sci(1e3 * ex["energy"], 3),
        "ex-energy-hs-mj": sci(1e3 * ex["energy_half_space_true_friction"], 3),
        "ex-friction-ratio": f"{ex['friction_ratio']:.3f}",
        "ex-fitted-friction": f"{ex['fitted_friction']:.3f}",
        "ex-stick-radius": f"{ex['stick_radius_cylinder']:.3f}",
        "ex-extra-rotation-urad": sci(1e6 * ex["extra_rotation_cylinder"], 3),
        "ex-twist-hs-urad": sci(1e6 * ex["relative_twist_half_space"], 3),
    })
    print("\n".join(f"{k} = {v}" for k, v in values.items()))
    write_macros(a.macros, values, "workflow/scripts/half_space_table.py")


if __name__ == "__main__":
    main()
