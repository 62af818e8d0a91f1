"""Convergence: error of T* (against the converged fast solution) against the resolution,
with the observed orders of the weak forms (N sweep) and the exponential decay of the
Abel-Fredholm method (node sweep); reads the benchmark JSON."""


import numpy as np

from torsional_contact.io.plotting import figure_parser, load_data, plt, save_figure, use_style

FLOOR = 1e-16


def main():
    p = figure_parser(__doc__, data=True)
    a = p.parse_args()
    results = load_data(a.data)["results"]
    use_style(a.style)
    fig, (left, right) = plt.subplots(1, 2, figsize=(8.0, 3.2))
    colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for result, color in zip(results, colors, strict=False):
        b = result["stick_radius"]
        for method, marker in (("complete", "o-"), ("published", "s:")):
            rows = [r for r in result["rows"] if r["method"] == method]
            n = np.array([r["resolution"] for r in rows], dtype=float)
            err = np.array([max(r["torque_error"], FLOOR) for r in rows])
            label = f"{method}, $b/a={b:g}$"
            if method == "complete" and n.size >= 2:
                order = -np.polyfit(np.log(n), np.log(err), 1)[0]
                label += f" (order {order:.2f})"
            left.loglog(n, err, marker, color=color, label=label)
        rows = [r for r in result["rows"] if r["method"] == "fast"]
        right.semilogy([r["resolution"] for r in rows], [max(r["torque_error"], FLOOR) for r in rows], "D-",
                       color=color, label=f"$b/a = {b:g}$")
    sizes = sorted({r["resolution"] for r in results[0]["rows"] if r["method"] == "complete"})
    left.set_xticks(sizes, [str(n) for n in sizes])
    left.minorticks_off()
    left.set_xlabel("number of terms N")
    left.set_ylabel(r"$|T^* - T^*_{\rm converged}|$")
    left.legend(fontsize=6)
    right.set_xlabel("Nystrom nodes")
    right.set_ylabel(r"$|T^* - T^*_{\rm converged}|$")
    right.legend(fontsize=7, title="Abel-Fredholm")
    fig.tight_layout()
    save_figure(fig, a.pdf, a.png)


if __name__ == "__main__":
    main()
