"""The contact models side by side: slip onset, twist, energy per cycle and the friction a wrong-model fit returns.

Units: T* = 2T/(f F a); b in a; G the shear modulus, p-bar = F/(pi a^2) the mean pressure; relative twist in
f p-bar / G (half-space models: n Omega, the rotation of remote points, n the elastic bodies; cylinders: 2 omega,
the twist the interface adds beyond the shafts' uniform twist); energy per cycle W in (f p-bar)^2 a^3 / G; A the
torque range.
Every number comes from the model table (``models.MODELS``: each model's ``monotonic`` numbers and
``energy_per_cycle``) and ``model_comparison.apparent_friction_ratio`` (f_fit / f of a friction read
from partial-slip dissipation with the wrong model; a gross-slip plateau gives the true f under
either).  Writes the figure (vector PDF, PNG), a LaTeX table, LaTeX macros and JSON with metadata.
"""

import math

import numpy as np
from _plotting import figure_parser, save_figure, subplots, use_style

from torsional_contact import models
from torsional_contact.model_comparison import apparent_friction_ratio
from torsional_contact.provenance import write_json, write_macros, write_text
from torsional_contact.typeset import sci

#: The models compared, in the order of the figure's legend.
NAMES = ("cylinder", "half-space", "hertz", "flat-punch")
#: The fits shown: (true model, assumed model).
FITS = (("cylinder", "half-space"), ("hertz", "half-space"), ("flat-punch", "half-space"), ("hertz", "cylinder"))
#: |f_fit / f - 1| above which a wrong-model fit is said to matter (the band of the figure).
MATTERS = 0.05
#: Fractions A / (2 T*_gs) of the true contact's gross-slip range at which the text quotes f_fit / f.
QUOTED = (0.1, 0.5, 0.8, 0.9, 0.95)
#: The fraction that stands for the gross-slip limit A -> 2 T*_gs (the fit at spinning itself is degenerate).
GROSS_LIMIT = 1 - 1e-6


def _twist(contact, tau):
    """(b, relative twist) of the monotonic loading to the torques tau (module docstring)."""
    b, omega, _ = contact.monotonic().points(tau)
    return b, contact.elastic_bodies * omega


def _window(fractions, kappa):
    """The first and last fraction of the gross-slip range where |kappa - 1| > MATTERS (None if nowhere)."""
    bad = np.abs(np.asarray(kappa) - 1.0) > MATTERS
    if not bad.any():
        return None
    return float(fractions[np.argmax(bad)]), float(fractions[len(bad) - 1 - np.argmax(bad[::-1])])


def main():
    p = figure_parser(__doc__)
    p.add_argument("--n-points", type=int, required=True, help="torques per curve")
    p.add_argument("--fit-points", type=int, required=True, help="ranges per friction-fit curve")
    p.add_argument("--json", required=True)
    p.add_argument("--tex", required=True)
    p.add_argument("--macros", required=True)
    a = p.parse_args()

    contacts = {name: models.get(name) for name in NAMES}
    curves, rows = {}, []
    for name, c in contacts.items():
        gross, onset = c.gross_slip_torque, c.slip_onset_torque
        tau = gross * np.linspace(0.0, 1.0, a.n_points + 1)[:-1]
        b, twist = _twist(c, tau)
        ranges = 2 * gross * np.geomspace(1e-3, 1 - 1e-6, a.n_points)
        energy = c.energy_per_cycle(ranges)
        curves[name] = {"torque": tau, "stick_radius": b, "twist": twist, "range": ranges, "energy": energy}
        half = 0.5 * gross
        rows.append({
            "model": name, "description": c.description, "elastic_bodies": c.elastic_bodies,
            "slip_onset_torque": onset, "gross_slip_torque": gross,
            "stick_radius_at_half_gross": float(_twist(c, np.array([half]))[0][0]),
            "energy_at_gross_range": float(c.energy_per_cycle(gross)),  # a fully reversed amplitude of half gross
        })

    fits = []
    fractions = np.linspace(0.02, 0.98, a.fit_points)
    for true, assumed in FITS:
        truth = contacts[true]
        kappa = np.array([apparent_friction_ratio(2 * truth.gross_slip_torque * x, true_model=true,
                                                  assumed_model=assumed) for x in fractions])
        quoted = {x: apparent_friction_ratio(2 * truth.gross_slip_torque * x, true_model=true, assumed_model=assumed)
                  for x in (*QUOTED, GROSS_LIMIT)}
        fits.append({"true": true, "assumed": assumed, "fraction": fractions, "ratio": kappa,
                     "window": _window(fractions, kappa), "quoted": quoted})

    # ------------------------------------------------------------------ figure
    use_style(a.style)
    fig, axes = subplots(2, 2, figsize=(6.2, 5.4), layout="constrained")  # printed at its size (text width 6.3 in)
    (ax_twist, ax_b), (ax_energy, ax_fit) = axes
    labels = {"cylinder": "cylinders", "half-space": "half-spaces, uniform $p$", "hertz": "Hertz (sphere on flat)",
              "flat-punch": "rigid flat punch"}
    colours = {name: f"C{k}" for k, name in enumerate(NAMES)}
    for name, cv in curves.items():
        ax_twist.plot(cv["twist"], cv["torque"], color=colours[name], label=labels[name])
        ax_b.plot(cv["torque"] / contacts[name].gross_slip_torque, cv["stick_radius"], color=colours[name])
        positive = cv["energy"] > 0
        ax_energy.loglog(cv["range"][positive], cv["energy"][positive], color=colours[name])
    # margins round the data: the stuck parts (vertical in (a), b = 1 in (b)) are not hidden by the frame
    ax_twist.set_xlim(-0.12, 3.0)
    ax_twist.set_ylim(-0.06, 1.7)
    ax_twist.set_xlabel(r"relative twist $G\varphi/(f\bar p)$")
    ax_twist.set_ylabel(r"torque $T^* = 2T/(fFa)$")
    ax_twist.set_title("(a) monotonic loading", fontsize=9)
    ax_b.set_xlim(-0.04, 1.04)
    ax_b.set_ylim(0.15, 1.06)
    ax_b.set_xlabel(r"$T^*/T^*_\mathrm{gs}$ (fraction of the gross-slip torque)")
    ax_b.set_ylabel(r"stick radius $b/a$")
    ax_b.set_title("(b) slip onset and spread", fontsize=9)
    ax_energy.set_xlabel(r"torque range $A = \Delta T^*$")
    ax_energy.set_ylabel(r"energy per cycle $WG/((f\bar p)^2a^3)$")
    ax_energy.set_ylim(1e-10, 3e2)
    ax_energy.set_title("(c) energy per cycle (Masing)", fontsize=9)
    # one legend of the models for (a)-(c), above the panels
    fig.legend(*ax_twist.get_legend_handles_labels(), loc="outside upper center", ncol=4, fontsize=7.5,
               frameon=False)
    # (d): the colour of the true contact, solid when read as half-spaces, dashed when read as cylinders
    short = {"cylinder": "cylinders", "half-space": "half-spaces", "hertz": "Hertz", "flat-punch": "punch"}
    for fit in fits:
        ax_fit.plot(fit["fraction"], fit["ratio"], color=colours[fit["true"]],
                    linestyle="-" if fit["assumed"] == "half-space" else "--",
                    label=f"{short[fit['true']]} as {short[fit['assumed']]}")
    ax_fit.axhspan(1 - MATTERS, 1 + MATTERS, color="0.78", zorder=0, linewidth=0,
                   label=rf"within {100 * MATTERS:g}$\,\%$ of $f$")
    ax_fit.set_yscale("log")
    ax_fit.set_xlim(-0.02, 1.02)
    ax_fit.set_xlabel(r"$A/(2T^*_\mathrm{gs})$ of the true contact")
    ax_fit.set_ylabel(r"apparent friction $f_\mathrm{fit}/f$")
    ax_fit.set_title("(d) friction from a wrong-model fit", fontsize=9)
    # up to half a decade or more above the largest ratio: the band of agreement about 2 pt high as printed, the
    # legend in the empty upper left
    top = max(float(np.max(f["ratio"][np.isfinite(f["ratio"])], initial=1.0)) for f in fits)
    ax_fit.set_ylim(1e-2, 10 ** math.ceil(math.log10(top) + 0.5))
    ax_fit.legend(fontsize=7.5, loc="upper left", labelspacing=0.3)
    save_figure(fig, a.pdf, a.png)

    # ------------------------------------------------------------------ data, table, macros
    write_json(a.json, {
        "models": rows,
        "fits": [{"true": f["true"], "assumed": f["assumed"], "fraction": f["fraction"].tolist(),
                  "friction_ratio": [None if math.isinf(k) else float(k) for k in f["ratio"]],
                  "window": f["window"],
                  "quoted": {f"{x:g}": None if math.isinf(k) else float(k) for x, k in f["quoted"].items()}}
                 for f in fits],
        "matters": MATTERS,
    }, method="model table: monotonic interpolants and W(A) = 4 W_mono(A/2) (Masing); Brent's method for the fits",
        resolution=f"{a.n_points} torques per curve, {a.fit_points} ranges per fit", precision="IEEE double")
    text = {"cylinder": r"$\frac{4}{3}$", "half-space": r"$\frac{4}{3}$", "hertz": r"$\frac{3\pi}{8}$",
            "flat-punch": r"$\frac{\pi}{2}$"}
    onset_text = {"cylinder": "1", "half-space": "0", "hertz": "0", "flat-punch": r"$\frac{4}{3}$"}
    law = {"cylinder": r"$\frac{\pi^4}{3}(\frac{A}{2}-1)^3$", "half-space": r"$\frac{27\pi^4}{131072}A^4$",
           "hertz": r"$\frac{3\pi^2}{512}A^3$", "flat-punch": r"$\frac{9\pi^2}{16}(\frac{A}{2}-\frac{4}{3})^2$"}
    # room for the stacked fractions of the last column (the float's group ends the setting)
    lines = ["% generated by workflow/scripts/models_comparison.py", r"\renewcommand{\arraystretch}{1.5}",
             r"\begin{tabular}{lrrrrl}", r"\toprule",
             r"model & $n$ & $T^*_\mathrm{onset}$ & $T^*_\mathrm{gs}$ & $b(T^*_\mathrm{gs}/2)$"
             r" & $W(A)$ near onset\\", r"\midrule"]
    for r in rows:
        lines.append(" & ".join([labels[r["model"]].replace("$p$", r"$p$"), str(r["elastic_bodies"]),
                                 onset_text[r["model"]], text[r["model"]], f"{r['stick_radius_at_half_gross']:.4f}",
                                 law[r["model"]]]) + r"\\")
    lines += [r"\bottomrule", r"\end{tabular}"]
    write_text(a.tex, "\n".join(lines) + "\n")
    values = {"models-matters": f"{100 * MATTERS:g}"}
    for r in rows:
        key = r["model"]
        values[f"models-{key}-gross"] = f"{r['gross_slip_torque']:.4f}"
        values[f"models-{key}-onset"] = f"{r['slip_onset_torque']:.4f}"
        values[f"models-{key}-b-half"] = f"{r['stick_radius_at_half_gross']:.3f}"
        values[f"models-{key}-energy-gross"] = sci(r["energy_at_gross_range"], 3)
        # where slip starts, as a fraction of the gross-slip range (below it a model dissipates nothing)
        values[f"models-{key}-onset-fraction"] = f"{r['slip_onset_torque'] / r['gross_slip_torque']:.2f}"
    # f_fit / f at stated ranges and in the gross-slip limit (not the ends of the sampled grid: the ratio tends to
    # 0 in small cycles of a Hertzian contact and is unbounded at the onset of the cylinders and the punch);
    # "--" where no finite friction fits (the true contact dissipates nothing)
    for f in fits:
        key = f"models-fit-{f['true']}-as-{f['assumed']}"
        for x, k in f["quoted"].items():
            name = "gross" if x == GROSS_LIMIT else f"{x:g}"
            values[f"{key}-at-{name}"] = "--" if math.isinf(k) else f"{k:#.3g}"
        finite = [k for k in (*f["ratio"], f["quoted"][GROSS_LIMIT]) if math.isfinite(k)]
        values[f"{key}-least-error"] = f"{100 * min(abs(k - 1) for k in finite):.2g}" if finite else "--"
    write_macros(a.macros, values, "workflow/scripts/models_comparison.py")


if __name__ == "__main__":
    main()
