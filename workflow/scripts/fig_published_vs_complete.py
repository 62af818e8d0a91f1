"""The reconstructed printed scheme against the complete weak form and the converged solution at one b/a.

Top: slip s(r) (units f p0 a / mu) and traction sigma_zt(r, 0) (units f p0); bottom: their
distance from the converged (Abel-Fredholm) solution on a log axis, so that the complete weak
form, which lies on the converged curve at plotting scale, stays visible.  The printed system
(eq. 38, no rigid-rotation mode) is drawn with two closures (``solvers.weak_form``): traction
continuity at r = b, under which it slips backwards on the stick disc (u = alpha r, alpha < 0)
and carries traction 1 - alpha r > 1 on the slip annulus, and the torque of the traction
actually present, under which alpha -> 0 but the slip next to r = b is negative and T* is low.
Values outside a panel's range are drawn at its edge with a triangle marker.
"""

import warnings

import numpy as np
from _plotting import figure_parser, save_figure, subplots, use_style

from torsional_contact import solve
from torsional_contact.backends import Published
from torsional_contact.diagnostics import UnphysicalResultWarning
from torsional_contact.solvers.weak_form import solve_series

#: Smallest difference drawn in the lower panels (below it: rounding of the converged solution).
FLOOR = 1e-7


def printed_scheme(b, n_terms, closure):
    """(slip, traction, T*) callables of the printed system with a closure."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UnphysicalResultWarning)
        backend = Published(solve_series(b, "published", n_terms, closure))
    return (lambda r: 2.0 * backend.displacement(r)), backend.traction, backend.torque


def clipped(ax, x, y, lo, hi, **style):
    """Plot y clipped to [lo, hi]; clipped points are marked at the edge with triangles."""
    line, = ax.plot(x, np.clip(y, lo, hi), **style)
    for edge, marker, mask in ((hi, "^", y > hi), (lo, "v", y < lo)):
        if mask.any():
            every = max(1, mask.sum() // 6)
            ax.plot(x[mask][::every], np.full(mask.sum(), edge)[::every], ls="none", marker=marker, ms=4,
                    color=line.get_color(), clip_on=False)
    return line


def main():
    p = figure_parser(__doc__)
    p.add_argument("--stick-radius", type=float, required=True)
    p.add_argument("--n-terms", type=int, required=True)
    a = p.parse_args()
    b, n = a.stick_radius, a.n_terms

    r = np.linspace(0, 1, 1001)
    converged = solve(stick_radius=b)
    complete = solve(stick_radius=b, method="complete", n_terms=n)
    cases = [
        ("converged (Abel–Fredholm)", converged.slip, converged.traction, converged.torque,
         dict(color="k", lw=2.0)),
        (f"complete weak form, $N = {n}$", complete.slip, complete.traction, complete.torque,
         dict(color="C0", lw=1.2, ls=(0, (5, 2)))),
        ("printed scheme, closure (C1), $q(b) = 1$", *printed_scheme(b, n, "traction"),
         dict(color="C1", lw=1.3)),
        ("printed scheme, closure (C3), torque", *printed_scheme(b, n, "torque"),
         dict(color="C2", lw=1.3, ls=(0, (1, 1.2)))),
    ]
    use_style(a.style)
    fig, axes = subplots(2, 2, figsize=(6.2, 4.5), sharex=True)  # printed at its size (text width 6.3 in)
    (slip_ax, trac_ax), (dslip_ax, dtrac_ax) = axes
    s_ref, q_ref = converged.slip(r), converged.traction(r)
    slip_range = (-0.08, 0.2)
    trac_range = (-0.05, 1.1)
    for name, slip, traction, torque, style in cases:
        label = f"{name}: $T^* = {torque:.4f}$"
        with warnings.catch_warnings():  # the weak forms' Gibbs overshoot is what the figure shows
            warnings.simplefilter("ignore", UnphysicalResultWarning)
            s, q = slip(r), traction(r)
        clipped(slip_ax, r, s, *slip_range, label=label, **style)
        clipped(trac_ax, r, q, *trac_range, **style)
        if slip is not converged.slip:
            thin = {**style, "lw": 0.8}
            dslip_ax.semilogy(r, np.maximum(np.abs(s - s_ref), FLOOR), **thin)
            dtrac_ax.semilogy(r, np.maximum(np.abs(q - q_ref), FLOOR), **thin)
    for ax in axes.ravel():
        ax.axvline(b, color="0.5", lw=0.8)
        ax.set_xlim(0, 1)
    slip_ax.axhline(0, color="0.3", lw=0.6)
    trac_ax.axhline(1, color="0.3", lw=0.6)
    slip_ax.set_ylim(*slip_range)
    trac_ax.set_ylim(*trac_range)
    slip_ax.set_ylabel(r"slip $s\,\mu/(f p_0 a)$")
    trac_ax.set_ylabel(r"$\sigma_{\theta z}(r,0)/f p_0$")
    dslip_ax.set_ylabel(r"|slip − converged| $\mu/(f p_0 a)$")
    dtrac_ax.set_ylabel(r"|traction − converged|$/f p_0$")
    for ax in (dslip_ax, dtrac_ax):
        ax.set_xlabel(r"$r/a$")
        ax.set_ylim(FLOOR, 1.0)
    for ax, tag in zip(axes.ravel(), "abcd", strict=True):  # above the frame: off the curves and reference lines
        ax.set_title(f"({tag})", loc="left", pad=3)
    handles, labels = slip_ax.get_legend_handles_labels()
    floor = f"$10^{{{round(np.log10(FLOOR))}}}$"
    fig.legend(handles, labels, title=f"$b/a = {b:g}$; differences below {floor} drawn at that floor",
               ncol=2, loc="lower center", frameon=False, fontsize=7.5, title_fontsize=8)
    fig.tight_layout(rect=(0, 0.13, 1, 1))  # the legend below the panels, off the data
    save_figure(fig, a.pdf, a.png)


if __name__ == "__main__":
    main()
