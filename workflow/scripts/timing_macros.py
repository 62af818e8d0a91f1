"""A wall time of a set of timing records as a manuscript macro (timings are kept apart from data).

Each record is a JSON written by a script that times itself; ``--field`` names the time in it
(default ``seconds_total``) and ``--statistic`` how the records combine (sum or max).
"""

import argparse
import json

from torsional_contact.provenance import write_macros


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--timings", nargs="+", required=True)
    p.add_argument("--key", required=True, help="macro name")
    p.add_argument("--field", required=True, help="the time in each record")
    p.add_argument("--statistic", choices=("sum", "max"), required=True, help="how the times add up")
    p.add_argument("--macros", required=True)
    a = p.parse_args()
    times = []
    for path in a.timings:
        with open(path, encoding="utf-8") as handle:
            times.append(float(json.load(handle)[a.field]))
    value = sum(times) if a.statistic == "sum" else max(times)
    write_macros(a.macros, {a.key: f"{value:.0f}"}, "workflow/scripts/timing_macros.py")


if __name__ == "__main__":
    main()
