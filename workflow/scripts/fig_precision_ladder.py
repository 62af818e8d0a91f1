"""Precision ladder figure: error of the double-precision Abel-Fredholm solve() against the
converged 30-digit solution over the stick radius (T*, omega, interface traction and slip), and
the truth's own convergence in the number of Nystrom nodes; reads precision_ladder.json."""

import numpy as np
from _plotting import figure_parser, load_data, rcParams, save_figure, subplots, use_style

FLOOR = 1e-18  # exact zeros are drawn here, with open markers (said in the legend)
CONVERGENCE_FLOOR = 1e-50  # the same in panel (c) (the truth carries ~45 digits)


def plot_errors(ax, x, errors, marker, label, color):
    """Errors on a log axis; exact zeros at FLOOR with open markers of the same color."""
    shown = [(b, e) for b, e in zip(x, errors, strict=True) if e > 0]
    zeros = [b for b, e in zip(x, errors, strict=True) if e == 0]
    ax.semilogy([b for b, _ in shown], [e for _, e in shown], marker, color=color, label=label, ms=3)
    if zeros:
        ax.semilogy(zeros, [FLOOR] * len(zeros), marker[0], color=color, mfc="none", ms=5,
                    label=f"{label}: exactly 0 (drawn at $10^{{{round(np.log10(FLOOR))}}}$)")


def main():
    p = figure_parser(__doc__, data=True)
    a = p.parse_args()
    data = load_data(a.data)
    rows = data["double_fast"]
    b = [r["stick_radius"] for r in rows]
    use_style(a.style)
    fig, (left, middle, right) = subplots(1, 3, figsize=(6.3, 3.7))  # printed at the text width
    colors = rcParams["axes.prop_cycle"].by_key()["color"]
    plot_errors(left, b, [r["torque_error"] for r in rows], "o-", r"$|\Delta T^*|$", colors[0])
    plot_errors(left, b, [r["rigid_rotation_error"] for r in rows], "s--", r"$|\Delta\omega|\,\mu/fp_0$", colors[1])
    plot_errors(middle, b, [r["traction_error"] for r in rows], "o-", r"max$_r\,|\Delta q|/fp_0$", colors[2])
    plot_errors(middle, b, [r["slip_error"] for r in rows], "s--", r"max$_r\,|\Delta s|\,\mu/(fp_0a)$", colors[3])
    for ax in (left, middle):
        ax.set_xlabel("stick radius $b/a$")
        ax.set_ylabel("absolute difference")
        ax.axhline(2.2e-16, color="0.5", lw=0.6, ls=":", label="double-precision eps")
        ax.legend(fontsize=7.5, loc="upper center", bbox_to_anchor=(0.5, -0.22), ncol=1, frameon=False)
    left.set_title(f"(a) $T^*$, $\\omega$ vs {data['digits']} digits", fontsize=8)
    middle.set_title(f"(b) interface, {rows[0]['n_radii']} points", fontsize=8)
    conv = data["convergence"]
    styles = dict(zip(sorted({r["working_digits"] for r in conv}), ("-", "--", ":", "-."), strict=False))
    for k, radius in enumerate(sorted({r["stick_radius"] for r in conv})):
        for digits, ls in styles.items():
            sel = [r for r in conv if r["stick_radius"] == radius and r["working_digits"] == digits]
            if not sel:
                continue
            right.semilogy([r["n_nodes"] for r in sel], [max(r["torque_error"], CONVERGENCE_FLOOR) for r in sel],
                           "o" + ls, color=colors[k], ms=3, label=f"$b/a={radius:g}$, {digits} digits")
            zeros = [r["n_nodes"] for r in sel if r["torque_error"] == 0]
            if zeros:
                right.semilogy(zeros, [CONVERGENCE_FLOOR] * len(zeros), "o", color=colors[k], mfc="none", ms=5)
    right.set_xlabel("Nystr\u00f6m nodes $n$")
    right.set_ylabel(r"$|T^*_n - T^*_{\rm ref}|$")
    right.set_title("(c) arbitrary precision", fontsize=8)
    if conv:  # line style = working precision: long handles so that it shows
        right.legend(fontsize=7.5, loc="upper center", bbox_to_anchor=(0.5, -0.22), ncol=1, frameon=False,
                     handlelength=3.0)
    fig.tight_layout()
    save_figure(fig, a.pdf, a.png)


if __name__ == "__main__":
    main()
