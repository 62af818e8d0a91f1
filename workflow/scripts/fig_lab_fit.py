"""A measured loop and its fit: the lab record (notebooks/data/lab_loop.csv) with the torque of the
fitted model, and the residuals, with f, G and the compliance and their 95 % intervals.

Units: torque N m, twist mrad.  ``fit_loop`` (``torsional_contact.fitting``) with the noise levels
estimated from the record; the generating parameters are in notebooks/data/lab_loop.json.
"""

import json
import warnings

import numpy as np
from _plotting import figure_parser, save_figure, subplots, use_style

from torsional_contact import fit_loop
from torsional_contact.io.lab_files import read_lab_columns


def main():
    p = figure_parser(__doc__)
    p.add_argument("--loop", required=True, help="lab CSV: time [s], torque [N m], twist [mrad]")
    p.add_argument("--truth", required=True, help="JSON of the generating parameters")
    a = p.parse_args()
    truth = json.loads(open(a.truth, encoding="utf-8").read())
    columns = read_lab_columns(a.loop, ["torque", "twist"], ["time"])
    torque, twist = columns["torque"], columns["twist"]
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # a noise-limited fit would be a wrong figure: fail the job
        fit = fit_loop(torque, twist, radius=truth["radius"], normal_force=truth["normal_force"])
    use_style(a.style)
    fig, (loop, residual) = subplots(1, 2, figsize=(6.2, 3.0), gridspec_kw={"width_ratios": [1.4, 1]})  # printed size
    loop.plot(twist * 1e3, torque, ".", markersize=2, color="0.55", label="record")
    loop.plot(twist * 1e3, fit.fitted_torque, "-", linewidth=1.0, label="fitted model")
    loop.set_xlabel(r"twist $\theta$ [mrad]")
    loop.set_ylabel(r"torque $T$ [N m]")
    # the fitted values and their intervals are quoted in the text (generated macros), not typed in the figure
    loop.set_title(f"fit of {torque.size} samples", fontsize=8, loc="left")
    loop.legend(fontsize=8, loc="upper left")  # above the rising branch: empty
    residual.plot(np.arange(torque.size), torque - fit.fitted_torque, ".", markersize=2, color="0.3")
    residual.axhline(0.0, color="0.6", linewidth=0.6)
    residual.set_xlabel("sample")
    residual.set_ylabel(r"torque residual $T_i - T_{\mathrm{model}}$ [N m]")
    residual.set_title(f"rms {fit.torque_residual_rms:.3g} N m, noise {fit.noise['torque']:.3g} N m", fontsize=8)
    fig.tight_layout()
    save_figure(fig, a.pdf, a.png)


if __name__ == "__main__":
    main()
