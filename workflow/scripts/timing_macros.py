"""The total wall time of a set of timing records as a manuscript macro (timings are kept apart from data).

Each record is a JSON with ``seconds_total`` (written by the scripts that time themselves).
"""

import argparse
import json

from torsional_contact.provenance import write_macros


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--timings", nargs="+", required=True)
    p.add_argument("--key", required=True, help="macro name")
    p.add_argument("--macros", required=True)
    a = p.parse_args()
    total = 0.0
    for path in a.timings:
        with open(path, encoding="utf-8") as handle:
            total += json.load(handle)["seconds_total"]
    write_macros(a.macros, {a.key: f"{total:.0f}"}, "workflow/scripts/timing_macros.py")


if __name__ == "__main__":
    main()
