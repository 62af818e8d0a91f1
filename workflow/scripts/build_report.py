"""Snakemake's own HTML report of this build: every figure and notebook with its caption and rule.

Runs ``snakemake --report`` on the finished build (the report rule depends on every other
deliverable) with the build's effective configuration, without taking the workflow lock
(the parent run holds it).  Written through ``torsional_contact.provenance.atomic_path``.
"""

import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile

import yaml

from torsional_contact.provenance import atomic_path


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--config-json", required=True, help="the build's effective configuration, as JSON")
    p.add_argument("--targets", nargs="+", required=True, help="the deliverables the report covers")
    p.add_argument("--output", required=True)
    a = p.parse_args()
    config = json.loads(a.config_json)
    directory = os.path.dirname(os.path.abspath(a.output))
    with tempfile.TemporaryDirectory(dir=directory) as scratch:  # private scratch: the configuration, the report
        configfile = os.path.join(scratch, "config.yaml")
        with open(configfile, "w", encoding="utf-8") as handle:
            yaml.safe_dump(config, handle)
        partial = os.path.join(scratch, "report.html")
        command = [sys.executable, "-m", "snakemake", "--nolock", "--configfile", configfile,
                   "--report", partial, *a.targets]
        subprocess.run(command, check=True)
        with atomic_path(a.output, label="--output") as tmp:  # the one writer: atomic, never over a directory
            shutil.copyfile(partial, tmp)
    print(f"wrote {a.output}")


if __name__ == "__main__":
    main()
