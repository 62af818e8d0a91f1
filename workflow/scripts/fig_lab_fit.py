"""A measured loop and its fit: the lab record (notebooks/data/lab_loop.csv) with the torque of the
fitted model, and the normalised residuals against the sample number.

The residuals are those the command line's ``--residuals`` writes (``io.fit_report.residual_columns``): each
sample's distance from the fitted curve in noise units, errors in both channels (the fit's orthogonal distance
to first order in the noise), about standard normal where the model and the noise levels hold; the panel
marks +-1 and +-2 and gives their rms.  The fitted values and their intervals are quoted in the text
(generated macros), not typed in the figure.

Units: torque N m, twist mrad.  ``fit_loop`` (``torsional_contact.fitting``) with the noise levels
estimated from the record; the generating parameters are in notebooks/data/lab_loop.json.
"""

import json
import warnings

import numpy as np
from _plotting import figure_parser, save_figure, subplots, use_style

from torsional_contact import fit_loop
from torsional_contact.io.fit_report import residual_columns
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
    distance = residual_columns(fit, columns)["normalized_residual"]  # noise units (the CLI's --residuals)
    use_style(a.style)
    fig, (loop, residual) = subplots(1, 2, figsize=(6.2, 3.0), gridspec_kw={"width_ratios": [1.4, 1]})  # printed size
    loop.plot(twist * 1e3, torque, ".", markersize=2, color="0.55", label=f"record ({torque.size} samples)")
    loop.plot(twist * 1e3, fit.fitted_torque, "-", linewidth=1.0, label="fitted model")
    loop.set_xlabel(r"twist $\theta$ [mrad]")
    loop.set_ylabel(r"torque $T$ [N m]")
    # the legend above the axes: the loop fills its box
    loop.legend(fontsize=8, loc="lower left", bbox_to_anchor=(0.0, 1.0), ncol=2, frameon=False, borderaxespad=0.2)
    residual.plot(np.arange(torque.size), distance, ".", markersize=2, color="0.3")
    residual.axhspan(-2.0, 2.0, color="0.94", linewidth=0, zorder=0)  # the +-2 and +-1 bands of standard normal noise
    residual.axhspan(-1.0, 1.0, color="0.86", linewidth=0, zorder=0)
    residual.axhline(0.0, color="0.6", linewidth=0.6)
    bound = max(4.0, float(np.ceil(np.nanmax(np.abs(distance)))))
    residual.set_ylim(-bound, bound)
    residual.set_yticks(np.arange(-bound, bound + 1))
    residual.set_xlabel("sample $i$")
    residual.set_ylabel(r"residual $d_i$ [noise units]")
    rms = float(np.sqrt(np.nanmean(distance**2)))
    residual.set_title(f"rms of $d_i$: {rms:.2f} (noise alone: 1)", fontsize=8, loc="left")
    fig.tight_layout()
    save_figure(fig, a.pdf, a.png)


if __name__ == "__main__":
    main()
