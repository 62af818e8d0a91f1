"""Convergence of the weak-form solutions with the number of terms N.

Without an exact solution the observed order p comes from successive differences at
doubling N: if Q(N) = Q + C N^-p, then |Q(N) - Q(N/2)| / |Q(2N) - Q(N)| = 2^p.
The Richardson estimate Q(2N) + (Q(2N) - Q(N)) / (2^p - 1) gives a rough error bar.
"""

from __future__ import annotations

import numpy as np

from ..solution import solve_cylinder

__all__ = ["n_terms_study", "format_table"]


def n_terms_study(stick_radius=0.6, n_terms=(145, 290, 580, 1160, 2320), radii=(0.3, 0.59, 0.8, 1.0),
                  method="complete"):
    """T*, omega and the interface traction at ``radii`` for each N, with observed orders.

    Parameters
    ----------
    stick_radius : float
        b/a.
    n_terms : sequence of int
        Increasing N; consecutive ratios of 2 give meaningful orders.
    radii : sequence of float
        r/a at which the interface traction sigma_zt(r, 0)/(f p0) is reported.
    method : str

    Returns
    -------
    dict with arrays ``n_terms``, ``torque``, ``rigid_rotation``, ``traction`` (N x radii),
    and ``order_torque``, ``order_rigid_rotation``, ``order_traction`` (observed p between
    consecutive triples; nan where undefined).
    """
    n_terms = np.asarray(n_terms, dtype=int)
    radii = np.asarray(radii, dtype=float)
    torque, omega, traction = [], [], []
    for n in n_terms:
        s = solve_cylinder(stick_radius=stick_radius, method=method, n_terms=int(n))
        torque.append(s.torque)
        omega.append(s.rigid_rotation)
        traction.append(s.traction(radii))
    torque, omega, traction = np.array(torque), np.array(omega), np.array(traction)

    def order(values):
        d = np.abs(np.diff(values, axis=0))
        ratio = np.log(n_terms[2:] / n_terms[1:-1]).reshape((-1,) + (1,) * (values.ndim - 1))
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.log(d[:-1] / d[1:]) / ratio

    return {
        "stick_radius": float(stick_radius),
        "method": method,
        "n_terms": n_terms,
        "radii": radii,
        "torque": torque,
        "rigid_rotation": omega,
        "traction": traction,
        "order_torque": order(torque),
        "order_rigid_rotation": order(omega),
        "order_traction": order(traction),
    }


def format_table(study) -> str:
    """Markdown table of an ``n_terms_study``: values, differences and observed orders."""
    radii = study["radii"]
    head = ["N", "T*", "dT*", "p(T*)", "omega", "p(omega)"] + [f"q({r:g})" for r in radii]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for i, n in enumerate(study["n_terms"]):
        d_t = f"{study['torque'][i] - study['torque'][i - 1]:.2e}" if i else ""
        p_t = f"{study['order_torque'][i - 2]:.2f}" if i >= 2 else ""
        p_w = f"{study['order_rigid_rotation'][i - 2]:.2f}" if i >= 2 else ""
        row = [str(n), f"{study['torque'][i]:.10f}", d_t, p_t, f"{study['rigid_rotation'][i]:.10f}", p_w]
        row += [f"{v:.8f}" for v in study["traction"][i]]
        lines.append("| " + " | ".join(row) + " |")
    return "\n".join(lines)
