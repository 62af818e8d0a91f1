"""The build-time table of Snakemake's report: what a clean build and the test suite cost, per rule.

Reads the JSON of workflow/checks/benchmark_build.py (a timed clean build of the configuration and
the README's test command, wall and CPU seconds; optionally a baseline checkout measured in the same
run) and writes an HTML table.  Without that JSON (a build nobody timed) the table says how to make it.
"""

import argparse
import html
import json

from torsional_contact.provenance import write_text

STYLE = ("<style>body{font-family:sans-serif;font-size:14px} table{border-collapse:collapse;margin:8px 0}"
         "td,th{border:1px solid #bbb;padding:2px 8px;text-align:right} td:first-child,th:first-child"
         "{text-align:left}</style>")


def _cell(value, digits=1) -> str:
    return "" if value is None else f"{value:.{digits}f}"


def _rows(table) -> str:
    return "\n".join("<tr>" + "".join(f"<td>{html.escape(str(v))}</td>" for v in row) + "</tr>" for row in table)


def build_table(this: dict, baseline: dict | None) -> str:
    """Per rule: jobs, wall and CPU seconds summed over its jobs, its longest job (and the baseline's)."""
    base = {row["rule"]: row for row in (baseline or {}).get("rules", [])}
    head = ["rule", "jobs", "wall s", "CPU s", "longest job s"] + (["baseline CPU s"] if baseline else [])
    table = []
    for row in this["rules"]:
        line = [row["rule"], row["jobs"], _cell(row["wall_seconds"]), _cell(row["cpu_seconds"]),
                _cell(row["longest_job_seconds"])]
        if baseline:
            line.append(_cell(base.pop(row["rule"], {}).get("cpu_seconds")))
        table.append(line)
    for name, row in base.items():  # rules only the baseline has
        table.append([name, "", "", "", "", _cell(row["cpu_seconds"])])
    table.append(["Snakemake itself (scheduling, checksums, shell)", "", "", _cell(this["snakemake_cpu_seconds"]),
                  ""] + ([_cell(baseline["snakemake_cpu_seconds"])] if baseline else []))
    header = "<tr>" + "".join(f"<th>{h}</th>" for h in head) + "</tr>"
    return f"<table>{header}\n{_rows(table)}</table>"


def summary(name: str, result: dict) -> str:
    parts = []
    if "build" in result:
        b = result["build"]
        parts.append(f"clean build of {html.escape(b['configfile'])}: <b>{b['wall_seconds_median']:.0f} s wall, "
                     f"{b['cpu_seconds_median']:.0f} CPU-s</b> (median of {b['repeats']}; load average "
                     f"{b['load_average_before']:.1f} when it started)")
    if "tests" in result:
        t = result["tests"]
        parts.append(f"test suite (<code>bash workflow/test.sh</code>): <b>{t['wall_seconds_median']:.0f} s wall, "
                     f"{t['cpu_seconds_median']:.0f} CPU-s</b> (median of {t['repeats']}, exit status {t['status']})")
    return f"<p>{html.escape(name)}: " + "; ".join(parts) + "</p>"


def tests_table(tests: dict) -> str:
    table = [[row["file"], row["tests"], _cell(row["seconds"])] for row in tests["files"]]
    return ("<table><tr><th>test module</th><th>tests</th><th>summed s (two workers)</th></tr>\n"
            f"{_rows(table)}</table>")


def render(data: dict | None) -> str:
    if data is None:
        body = ("<p>This build was not timed. <code>.venv/bin/python workflow/checks/benchmark_build.py --clean</code> "
                "times a clean build of the configuration and the test suite and writes "
                "<code>timings/build_benchmark.json</code>; the next run of the workflow puts the table here.</p>")
        return f"<!DOCTYPE html><html><head><meta charset='utf-8'>{STYLE}</head><body>{body}</body></html>\n"
    this, baseline = data["this"], data.get("baseline")
    body = [f"<p>{data['cores']} cores. Wall and CPU (user + system) seconds; CPU seconds are the more robust "
            "figure on a shared machine. Per rule: summed over its jobs, each measured around its process "
            "(start-up included).</p>", summary("this checkout", this)]
    if baseline:
        body.append(summary(f"baseline ({data.get('baseline_checkout', '')})", baseline))
        body.append("<p>baseline / this: " + ", ".join(f"{html.escape(k)} {v:.2f}" for k, v in data["ratios"].items())
                    + "</p>")
    if "build" in this:
        body.append(build_table(this["build"], (baseline or {}).get("build")))
    if "tests" in this:
        body.append(tests_table(this["tests"]))
    return f"<!DOCTYPE html><html><head><meta charset='utf-8'>{STYLE}</head><body>{''.join(body)}</body></html>\n"


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--benchmark", nargs="?", help="JSON of workflow/checks/benchmark_build.py (if measured)")
    p.add_argument("--html", required=True)
    a = p.parse_args()
    data = None
    if a.benchmark:
        with open(a.benchmark, encoding="utf-8") as handle:
            data = json.load(handle)
    write_text(a.html, render(data))
    print(f"wrote {a.html}")


if __name__ == "__main__":
    main()
