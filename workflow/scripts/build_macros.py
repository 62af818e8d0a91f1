"""Macros describing the build itself (configuration, versions, machine) for the manuscript."""

import argparse
import os
import platform
from importlib import metadata

from torsional_contact import asymptotics, solve
from torsional_contact.provenance import latex_escape, write_macros
from torsional_contact.typeset import sci

#: How the manuscript names the method of the field figures.
METHOD_NAMES = {"fast": "Abel--Fredholm method", "complete": "complete weak form, $N = {n}$",
                "published": "published weak form (38), $N = {n}$"}


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--n-terms", type=int, required=True)
    p.add_argument("--method", required=True)
    p.add_argument("--contour-stick-radius", type=float, required=True)
    p.add_argument("--output", required=True)
    a = p.parse_args()
    versions = {name: metadata.version(name) for name in ("numpy", "scipy", "mpmath", "matplotlib", "snakemake")}
    write_macros(a.output, {
        "n-terms": a.n_terms,
        "figure-method": METHOD_NAMES[a.method].format(n=a.n_terms),
        "contour-b": f"{a.contour_stick_radius:g}",
        "contour-torque": f"{solve(stick_radius=a.contour_stick_radius).torque:.4f}",
        "python-version": platform.python_version(),
        **{f"version-{k}": latex_escape(v) for k, v in versions.items()},
        # where the solver switches from the Abel-Fredholm method to the expansions about the two limits
        "switch-onset-scalars": sci(asymptotics.ONSET_SCALARS, 0, always=True),
        "switch-onset-fields": sci(asymptotics.ONSET_FIELDS, 0, always=True),
        "switch-spinning": sci(asymptotics.SPINNING_SWITCH, 0, always=True),
        "onset-work-coefficient": f"{asymptotics.ONSET_WORK_COEFFICIENT:.7f}",
        "spinning-rotation-constant": f"{asymptotics.spinning_rotation_constant():.6f}",
        "machine": latex_escape(f"{platform.system()} {platform.machine()}, {os.cpu_count()} cores"),
    }, "workflow/scripts/build_macros.py")


if __name__ == "__main__":
    main()
