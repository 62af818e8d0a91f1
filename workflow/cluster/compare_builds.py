"""Compare two builds of the workflow (e.g. local and SLURM) file by file.

Every output must exist in both builds.  Outputs are compared byte for byte after removing what
legitimately changes from one run to the next:

* PDF: the /CreationDate, /ModDate and /ID entries (matplotlib and pdfTeX honour SOURCE_DATE_EPOCH
  for the dates, but the ID of pdfTeX also depends on the output file name);
* JSON: at any depth, every key whose name contains "second" or "time" (wall-clock timings, timer
  resolution, time ratios), "saving" (time saved, a ratio of timings), "load_average" (the
  machine's load when a benchmark ran), "worst_b" (the stick radius that took longest) or
  "repeats" (how many timed repeats fitted in a time budget); everything else, numbers included,
  must be identical;
* Markdown: sections whose heading mentions "seconds" and "Total run time" lines.

Files that record timings (the benchmark data, macros and tables, each job's timings, the
work-precision figure, the manuscript, which prints those tables, and Snakemake's report) are
compared too but are expected to differ (TIMING_OUTPUTS).  The LaTeX build directory and logs are
not compared.  The workflow tests use the same comparison for two clean local builds.  Exit status
0 when every other output is identical, 1 otherwise, 2 for bad arguments.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import re
import sys
from pathlib import Path

from torsional_contact.provenance import write_text

#: Outputs that record wall-clock timings (relative paths, glob patterns; a trailing "/" names a
#: whole folder): compared, but expected to differ from one run to the next.
TIMING_OUTPUTS = (
    "timings/",  # each job's own timings (the data lives elsewhere)
    "data/benchmark_*.json",  # benchmark data: every number in them is a time or a ratio of times
    "macros/benchmark*.tex",
    "macros/scenes.tex",
    "tables/scenes.tex",
    "macros/*_timing.tex",  # the arbitrary-precision references' run times
    "figures/work_precision.pdf",
    "figures/work_precision.png",
    "paper/ms.pdf",  # reads the histories benchmark's macros (the sizes of its signals)
    "paper/supplement.pdf",  # the speed section and the scene table
    "report.html",  # Snakemake's report records each job's run time
)
#: Outputs not compared: LaTeX intermediate files and logs.
EXCLUDED = ("paper/build/", "paper/build-supplement/", "paper/build-companion/", "logs/", "*.log")

_PDF_VOLATILE = re.compile(rb"/(CreationDate|ModDate)\s*\([^)]*\)|/ID\s*\[\s*<[0-9A-Fa-f]*>\s*<[0-9A-Fa-f]*>\s*\]")
_TIMING_KEY = re.compile(r"second|time|saving|load_average|worst_b|repeats", re.IGNORECASE)


def _matches(relpath: str, patterns) -> bool:
    """True when ``relpath`` is, matches (glob) or lies in (pattern ending in "/") one of ``patterns``."""
    return any(
        relpath.startswith(pattern) if pattern.endswith("/") else (Path(relpath).match(pattern) or relpath == pattern)
        for pattern in patterns
    )


def is_timing_output(relpath: str) -> bool:
    """True for an output that records wall-clock timings (TIMING_OUTPUTS)."""
    return _matches(relpath, TIMING_OUTPUTS)


def normalise_pdf(data: bytes) -> bytes:
    """PDF bytes without the creation/modification dates and the document ID."""
    return _PDF_VOLATILE.sub(b"", data)


def drop_timing_keys(value):
    """JSON value without the keys that hold timings or the machine's load (see above), recursively."""
    if isinstance(value, dict):
        return {k: drop_timing_keys(v) for k, v in value.items() if not _TIMING_KEY.search(k)}
    if isinstance(value, list):
        return [drop_timing_keys(v) for v in value]
    return value


def normalise_markdown(text: str) -> str:
    """Markdown without sections whose heading mentions seconds and without 'Total run time' lines."""
    kept, skipping_level = [], None
    for line in text.splitlines():
        heading = re.match(r"(#+)\s", line)
        if heading:
            level = len(heading.group(1))
            if skipping_level is not None and level <= skipping_level:
                skipping_level = None
            if skipping_level is None and "seconds" in line.lower():
                skipping_level = level
        if skipping_level is None and not line.startswith("Total run time"):
            kept.append(line)
    return "\n".join(kept)


def comparable(path: Path) -> bytes:
    """File content with run-dependent parts removed (see the module docstring)."""
    data = path.read_bytes()
    if path.suffix == ".pdf":
        return normalise_pdf(data)
    if path.suffix == ".json":
        return json.dumps(drop_timing_keys(json.loads(data)), sort_keys=True).encode()
    if path.suffix == ".md":
        return normalise_markdown(data.decode("utf-8")).encode()
    return data


def output_files(root: Path) -> set[str]:
    """Relative paths of the compared files under ``root``."""
    return {
        p.relative_to(root).as_posix()
        for p in root.rglob("*")
        if p.is_file() and not _matches(p.relative_to(root).as_posix(), EXCLUDED)
    }


def compare_builds(first: Path, second: Path) -> list[tuple[str, str]]:
    """(relative path, verdict) for every output of either build.

    Verdicts: "identical" (byte for byte), "identical-normalised" (after removing dates/timings),
    "timing-differs" (an output of TIMING_OUTPUTS that differs, as expected), "DIFFERS",
    "ONLY-IN-<name>" (missing from the other build).
    """
    a, b = output_files(first), output_files(second)
    verdicts = []
    for rel in sorted(a | b):
        if rel not in b:
            verdicts.append((rel, f"ONLY-IN-{first.name}"))
        elif rel not in a:
            verdicts.append((rel, f"ONLY-IN-{second.name}"))
        elif (first / rel).read_bytes() == (second / rel).read_bytes():
            verdicts.append((rel, "identical"))
        elif comparable(first / rel) == comparable(second / rel):
            verdicts.append((rel, "identical-normalised"))
        elif is_timing_output(rel):
            verdicts.append((rel, "timing-differs"))
        else:
            verdicts.append((rel, "DIFFERS"))
    return verdicts


def is_failure(verdict: str) -> bool:
    """True for a verdict that means the builds disagree on a deterministic output."""
    return verdict == "DIFFERS" or verdict.startswith("ONLY-IN-")


def report(first: Path, second: Path, verdicts) -> str:
    """Plain-text table: verdict, SHA-256 prefixes of both files, path; then a summary line."""
    def digest(path: Path) -> str:
        return hashlib.sha256(path.read_bytes()).hexdigest()[:12] if path.is_file() else "-" * 12

    lines = [f"# {first} vs {second}", f"{'verdict':22s} {first.name[:12]:12s} {second.name[:12]:12s} path"]
    for rel, verdict in verdicts:
        lines.append(f"{verdict:22s} {digest(first / rel)} {digest(second / rel)} {rel}")
    counts = {}
    for _, verdict in verdicts:
        counts[verdict] = counts.get(verdict, 0) + 1
    failures = sum(is_failure(v) for _, v in verdicts)
    summary = ", ".join(f"{n} {v}" for v, n in sorted(counts.items()))
    lines.append(f"{len(verdicts)} files: {summary}; {failures} deterministic outputs differ")
    return "\n".join(lines) + "\n"


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("first", type=Path, help="output folder of one build (e.g. the local build)")
    p.add_argument("second", type=Path, help="output folder of the other build (e.g. the SLURM build)")
    p.add_argument("--report", type=Path, help="also write the table to this file")
    a = p.parse_args(argv)
    for folder in (a.first, a.second):
        if not folder.is_dir():
            print(f"compare_builds: {folder} is not a directory", file=sys.stderr)
            return 2
    verdicts = compare_builds(a.first, a.second)
    text = report(a.first, a.second, verdicts)
    print(text, end="")
    if a.report:
        write_text(a.report, text)
    return 1 if any(is_failure(v) for _, v in verdicts) else 0


if __name__ == "__main__":
    sys.exit(main())
