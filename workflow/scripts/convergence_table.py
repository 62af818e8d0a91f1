"""The n_terms convergence table of T*(b), omega(b) and the interface traction.

Prints the table; optionally writes JSON (with metadata) and manuscript macros.
"""

import argparse

import numpy as np

from torsional_contact.provenance import write_json, write_macros
from torsional_contact.typeset import sci
from torsional_contact.verification.convergence import format_table, n_terms_study


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--stick-radius", type=float, default=0.6)
    p.add_argument("--method", required=True, help="the weak form studied (published or complete)")
    p.add_argument("--max-n", type=int, default=2320)
    p.add_argument("--json", help="JSON file (written atomically)")
    p.add_argument("--macros")
    a = p.parse_args()
    sizes = [n for n in (145, 290, 580, 1160, 2320, 4640) if n <= a.max_n]
    study = n_terms_study(a.stick_radius, sizes, method=a.method)
    print(f"b/a = {a.stick_radius}, method = {a.method}")
    print(format_table(study))
    if a.json:
        record = {k: (np.where(np.isfinite(v), v, None).tolist() if isinstance(v, np.ndarray) else v)
                  for k, v in study.items()}
        write_json(a.json, record, method=f"{a.method} weak form, regularity by traction continuity at r = b",
                   precision="IEEE double")
    if a.macros:
        write_macros(a.macros, {
            "conv-b": f"{a.stick_radius:g}",
            "conv-n-max": sizes[-1],
            "conv-torque-n145": f"{study['torque'][0]:.6f}",
            "conv-torque-nmax": f"{study['torque'][-1]:.6f}",
            "conv-order-torque": f"{np.nanmean(study['order_torque']):.2f}",
            "conv-order-omega": f"{np.nanmean(study['order_rigid_rotation']):.2f}",
            "conv-change-145-nmax": sci(abs(study["torque"][-1] - study["torque"][0])),
        }, "workflow/scripts/convergence_table.py")


if __name__ == "__main__":
    main()
