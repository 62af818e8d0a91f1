"""Property-based tests of the command line: nothing a user types damages a file or prints a traceback.

Hypothesis generates argument lists, signal files and output paths of every kind (regular
file, symbolic links, FIFO read by a thread, device nodes made with os.mknod when root, a
directory, a missing directory, a path under a file, the input itself) in a fresh temporary
directory, runs ``torsional_contact.io.cli.main`` in-process with captured standard output and
error, and checks: exit status 0 or 2; no exception escapes (the in-process form of "no
traceback"); an error is one line naming what is wrong, with nothing on standard output; and no
file outside the declared output changed (contents, inode types, symbolic link targets and
permission bits of the whole tree, before and after).

The number of examples comes from the profile ``TORSIONAL_HYPOTHESIS_PROFILE``: "fast" (the
default, a bounded number for the fast tier) or "ci" (more, set by .ci/run).  A few cases run as
real subprocesses (``python -m torsional_contact``): descriptors, a closed pipe, /dev/full as
standard output, Ctrl-C, an unreadable input, read-only and full file systems.
"""

from __future__ import annotations

import contextlib
import errno
import hashlib
import json
import math
import os
import shutil
import signal
import stat
import subprocess
import sys
import tempfile
import threading
import time

import pytest
from cli_runner import run_in_process
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from torsional_contact.units import registry

IS_ROOT = os.geteuid() == 0
PROFILES = {"fast": 40, "ci": 600}
PROFILE = os.environ.get("TORSIONAL_HYPOTHESIS_PROFILE", "fast")
if PROFILE not in PROFILES:
    raise ValueError(f"TORSIONAL_HYPOTHESIS_PROFILE must be one of {', '.join(PROFILES)}, got {PROFILE!r}")
PROPERTY = settings(max_examples=PROFILES[PROFILE], deadline=None, derandomize=False,
                    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                                           HealthCheck.function_scoped_fixture])
PREFIX = "torsional_contact: error: "
HEADER = "sample,torque,rigid_rotation,dissipated_energy"


# --------------------------------------------------------------------------- helpers
def snapshot(root) -> dict:
    """Every entry under ``root``: (file type, permission bits, content digest / link target / device)."""
    state = {}
    for directory, subdirectories, files in os.walk(root):
        for name in subdirectories + files:
            path = os.path.join(directory, name)
            info = os.lstat(path)
            if stat.S_ISREG(info.st_mode):
                with open(path, "rb") as handle:
                    value = hashlib.sha256(handle.read()).hexdigest()
            elif stat.S_ISLNK(info.st_mode):
                value = os.readlink(path)
            elif stat.S_ISCHR(info.st_mode) or stat.S_ISBLK(info.st_mode):
                value = info.st_rdev
            else:
                value = None
            state[os.path.relpath(path, root)] = (stat.S_IFMT(info.st_mode), stat.S_IMODE(info.st_mode), value)
    return state


class FifoReader(threading.Thread):
    def __init__(self, path):
        super().__init__(daemon=True)
        self.path, self.data = path, b""

    def run(self):
        with open(self.path, "rb") as handle:
            self.data = handle.read()

    def finish(self) -> bytes:
        """The bytes read; a reader the command never opened is released by opening the write end once."""
        deadline = time.monotonic() + 10
        while self.is_alive() and time.monotonic() < deadline:
            try:
                os.close(os.open(self.path, os.O_WRONLY | os.O_NONBLOCK))
            except OSError as exc:  # ENXIO: the reader has not opened yet
                assert exc.errno == errno.ENXIO
            self.join(timeout=0.05)
        assert not self.is_alive()
        return self.data


def check_streams(status: int, out: str, err: str, *, must_name: str | None = None) -> None:
    """Exit 0 or 2; warnings one line each; an error one line with nothing on standard output."""
    assert status in (0, 2), (status, err)
    assert "Traceback" not in err
    lines = err.splitlines()
    warnings_ = [line for line in lines if line.startswith("warning (")]
    errors = [line for line in lines if not line.startswith("warning (")]
    if status == 2:
        assert out == "", out
        assert len(errors) == 1 and errors[0].startswith(PREFIX), err
        if must_name is not None:
            assert must_name in errors[0], (must_name, errors[0])
    else:
        assert errors == [], err
        assert out.strip(), "a successful command prints its result"
    assert all(len(w) > len("warning (") for w in warnings_)


@contextlib.contextmanager
def working_directory():
    """A fresh temporary directory as the current directory."""
    previous = os.getcwd()
    with tempfile.TemporaryDirectory(prefix="torsional-cli-") as root:
        os.chdir(root)
        try:
            yield root
        finally:
            os.chdir(previous)


# --------------------------------------------------------------------------- history --signal, generated
#: Output kinds: those refused whatever else the command line says, and those written.
REFUSED = {"directory", "empty", "dot", "under-file", "missing-parent", "input", "symlink-to-input",
           "hardlink-to-input", "dangling-without-directory", "full-device"}
WRITTEN = ["none", "new", "regular", "symlink", "dangling", "fifo", "missing-parent-with-parents", "null-device"]
OUTPUT_KINDS = sorted(REFUSED | set(WRITTEN))
if not IS_ROOT:
    OUTPUT_KINDS = [k for k in OUTPUT_KINDS if not k.endswith("-device")]

torque = st.floats(-4 / 3, 4 / 3, allow_nan=False).map(lambda v: round(v, 6))
bad_token = st.sampled_from(["nan", "inf", "-inf", "1.5", "-2", "abc", "1e400", "0x1", "1..2", "é", "--", "4/3"])


@st.composite
def signal_files(draw):
    """(text, facts): a signal file and what is true of it (valid or not, its columns and header names)."""
    values = draw(st.lists(torque, min_size=0, max_size=25))
    if draw(st.booleans()):  # plateaus (equal samples in a row), the case that once failed with --output
        values = [v for v in values for _ in range(draw(st.integers(1, 3)))]
    columns = draw(st.sampled_from([1, 2]))
    separator = draw(st.sampled_from([",", ";", "\t", " "])) if columns == 2 else None
    header = draw(st.sampled_from([None, "names"]))
    rows = [f"{i / 1000:g}{separator}{v!r}" if columns == 2 else repr(v) for i, v in enumerate(values)]
    corrupt = draw(st.booleans()) and bool(rows)
    if corrupt:
        k = draw(st.integers(0, len(rows) - 1))
        token = draw(bad_token)
        rows[k] = f"{k / 1000:g}{separator}{token}" if columns == 2 else token
    if draw(st.booleans()):  # comments and blank lines
        at = draw(st.integers(0, len(rows)))
        rows[at:at] = ["# a comment", "", "   "]
    names = ["time", "torque"] if columns == 2 else ["torque"]
    if header:
        rows.insert(0, (separator or ",").join(names) if columns == 2 else "torque")
    text = "\n".join(rows) + draw(st.sampled_from(["\n", "", "\n\n"]))
    return text, {"valid": bool(values) and not corrupt, "columns": columns,
                  "names": names if header else None}


@st.composite
def history_commands(draw):
    text, facts = draw(signal_files())
    source = draw(st.sampled_from(["file", "file", "file", "symlink", "missing", "directory"]))
    output = draw(st.sampled_from(OUTPUT_KINDS))
    column = draw(st.sampled_from([None, None, "1", "2", "0", "3", "torque", "time", "nope"]))
    method = draw(st.sampled_from([None, None, "fast", "complete", "published", "bogus"]))
    n_terms = draw(st.sampled_from([None, None, "1", "20", "0", "-3", "20000", "x"]))  # 20000: above every limit
    flags = draw(st.lists(st.sampled_from(["--json", "--no-progress"]), unique=True))
    junk = draw(st.sampled_from([None] * 6 + ["--bogus", "extra", "--turning-points", "--output"]))
    parents = output == "missing-parent-with-parents" or draw(st.integers(0, 9)) == 0
    order = draw(st.permutations(range(6)))
    return dict(text=text, facts=facts, source=source, output=output, column=column, method=method,
                n_terms=n_terms, flags=flags, junk=junk, parents=parents, order=order)


def make_output(kind: str, root: str) -> tuple[str | None, str | None]:
    """Create what ``kind`` needs in ``root``: (--output argument, the file it ends in when written)."""
    target = os.path.join(root, "out.csv")
    if kind == "none":
        return None, None
    if kind == "new":
        return "out.csv", target
    if kind == "regular":
        with open(target, "w") as handle:
            handle.write("old table\n")
        return "out.csv", target
    if kind == "symlink":
        os.mkdir("results")
        with open("results/table.csv", "w") as handle:
            handle.write("old table\n")
        os.symlink("results/table.csv", "out.csv")
        return "out.csv", os.path.join(root, "results", "table.csv")
    if kind == "dangling":
        os.symlink("fresh.csv", "out.csv")
        return "out.csv", os.path.join(root, "fresh.csv")
    if kind == "dangling-without-directory":
        os.symlink("nowhere/fresh.csv", "out.csv")
        return "out.csv", None
    if kind == "fifo":
        os.mkfifo("pipe")
        return "pipe", None
    if kind in ("null-device", "full-device"):
        os.mknod("device", stat.S_IFCHR | 0o666, os.makedev(1, 3 if kind == "null-device" else 7))
        return "device", None
    if kind == "directory":
        os.mkdir("folder")
        return "folder", None
    if kind == "empty":
        return "", None
    if kind == "dot":
        return ".", None
    if kind == "under-file":
        with open("plain.txt", "w") as handle:
            handle.write("plain\n")
        return "plain.txt/out.csv", None
    if kind == "missing-parent":  # refused unless --parents
        return "no/such/dir/out.csv", os.path.join(root, "no", "such", "dir", "out.csv")
    if kind == "missing-parent-with-parents":
        return "made/here/out.csv", os.path.join(root, "made", "here", "out.csv")
    if kind == "input":
        return "signal.csv", None
    if kind == "symlink-to-input":
        os.symlink("signal.csv", "out.csv")
        return "out.csv", None
    if kind == "hardlink-to-input":
        os.link("signal.csv", "out.csv")
        return "out.csv", None
    raise AssertionError(kind)


def expected_success(case) -> bool:
    """Whether everything in the command line is right (then the command must succeed)."""
    facts, column = case["facts"], case["column"]
    if column is None:
        column_ok = facts["columns"] == 1
    elif column.isdigit():
        column_ok = 1 <= int(column) <= facts["columns"]
    else:
        column_ok = facts["names"] is not None and column in facts["names"]
    n_terms_ok = case["n_terms"] is None or (case["n_terms"] not in ("x", "0", "-3", "20000"))
    return (facts["valid"] and column_ok and case["source"] in ("file", "symlink") and case["junk"] is None
            and case["method"] in (None, "fast") and n_terms_ok
            and not refused(case) and not (case["parents"] and case["output"] == "none"))


def refused(case) -> bool:
    """Whether the output is refused whatever the rest of the command line says."""
    if case["output"] in ("input", "symlink-to-input", "hardlink-to-input"):
        return case["source"] in ("file", "symlink")  # signal.csv is the input only when --signal names it
    return case["output"] in REFUSED and not (case["output"] == "missing-parent" and case["parents"])


@PROPERTY
@given(case=history_commands())
def test_history_signal_never_damages_a_file(case):
    with working_directory() as root:
        with open("signal.csv", "w") as handle:
            handle.write(case["text"])
        signal_arg = {"file": "signal.csv", "symlink": "signal-link.csv", "missing": "absent.csv",
                      "directory": "signal-dir"}[case["source"]]
        if case["source"] == "symlink":
            os.symlink("signal.csv", signal_arg)
        elif case["source"] == "directory":
            os.mkdir(signal_arg)
        output, final = make_output(case["output"], root)
        groups = [["--signal", signal_arg], [] if output is None else ["--output", output],
                  [] if case["column"] is None else ["--column", case["column"]],
                  [] if case["method"] is None else ["--method", case["method"]],
                  [] if case["n_terms"] is None else ["--n-terms", case["n_terms"]],
                  case["flags"] + (["--parents"] if case["parents"] else [])]
        argv = ["history"] + [token for k in case["order"] for token in groups[k]]
        if case["junk"] is not None:
            argv.append(case["junk"])
        before = snapshot(root)
        reader = None
        if case["output"] == "fifo":
            reader = FifoReader(os.path.join(root, "pipe"))
            reader.start()
        try:
            status, out, err = run_in_process(argv)
        finally:
            received = reader.finish() if reader is not None else None
        after = snapshot(root)

        clean_parse = case["junk"] is None and case["n_terms"] != "x"
        check_streams(status, out, err, must_name="--output" if refused(case) and clean_parse
                      and case["output"] != "full-device" else None)
        if refused(case):
            assert status == 2, (argv, err)
        if expected_success(case):
            assert status == 0, (argv, err)
        changed = {path for path in before.keys() | after.keys() if before.get(path) != after.get(path)}
        if status == 2:
            assert changed == set(), (argv, changed)  # nothing written half-way
            return
        allowed = set()
        if final is not None:  # the file written, and the directories --parents made for it
            rel = os.path.relpath(final, root)
            made = {rel[:i] for i in range(len(rel)) if rel[i] == os.sep}
            allowed = {rel} | {path for path in made if path not in before}
        assert changed <= allowed, (argv, changed - allowed)
        if output is not None:
            if final is not None:
                with open(final) as handle:
                    table = handle.read().splitlines()
                assert table[0] == HEADER and len(table) >= 2
                assert stat.S_ISREG(os.lstat(final).st_mode)
            if case["output"] == "fifo":
                assert received.decode().splitlines()[0] == HEADER
        if "--json" in case["flags"]:
            record = json.loads(out)
            assert record["samples"] >= 1


# --------------------------------------------------------------------------- every subcommand, generated
number_text = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True).map(repr),
    st.floats(-1.5, 1.5).map(lambda v: f"{v:.3g}"),
    st.integers(-3, 3).map(str),
    st.sampled_from(["0.6", "1.23", "-1e-1", "4/3", "", "nan", "abc", "1.5", "1", "0", "-0", "1e-300", "0.999999"]),
    st.text(max_size=4),
)


@st.composite
def commands(draw):
    """solve, history --turning-points, reference (small) and errata (its arguments only), with generated values."""
    command = draw(st.sampled_from(["solve", "history", "reference", "errata", "bogus"]))
    argv = [command]
    if command == "solve":
        argv += [draw(st.sampled_from(["--stick-radius", "--torque"])), draw(number_text)]
        argv += draw(st.sampled_from([[], ["--method", "fast"], ["--method", "complete", "--n-terms", "12"],
                                      ["--method", "published", "--n-terms", draw(number_text)], ["--method", "x"]]))
        if draw(st.booleans()):
            argv += ["--radii", *draw(st.lists(number_text, min_size=1, max_size=3))]
    elif command == "history":
        argv += ["--turning-points", *draw(st.lists(number_text, min_size=1, max_size=4))]
        if draw(st.booleans()):
            argv += ["--radii", draw(number_text)]
        if draw(st.integers(0, 4)) == 0:
            argv += draw(st.sampled_from([["--output", "x.csv"], ["--parents"], ["--column", "1"]]))
    elif command == "reference":
        argv += ["--stick-radius", draw(st.one_of(number_text, st.sampled_from(["0.3", "0.6", "0.9"])))]
        argv += ["--n-terms", draw(st.sampled_from(["1", "4", "8", "0", "x", "1001"])),
                 "--digits", draw(st.sampled_from(["5", "12", "0", "1001", "y"]))]
        argv += draw(st.sampled_from([[], ["--method", "published"], ["--method", "nope"], ["--radii", "0.5"]]))
    elif command == "errata":  # the full table takes a minute: only arguments that are refused
        argv += draw(st.sampled_from([["--bogus"], ["extra"], ["--json", "--json=1"]]))
    if draw(st.booleans()):
        argv.append("--json")
    return argv


@PROPERTY
@given(argv=commands())
def test_every_subcommand_exits_0_or_2_with_one_line(argv):
    with working_directory() as root:
        before = snapshot(root)
        status, out, err = run_in_process(argv)
        check_streams(status, out, err)
        assert snapshot(root) == before == {}
    if argv[0] in ("errata", "bogus"):
        assert status == 2


# --------------------------------------------------------------------------- unit strings and header units, generated
#: The unit strings that labs type and that were once evaluated as expressions, and spellings that must read.
UNIT_CASES = ["5,0 mm", "0,5 N m", "2 3 mm", "5 mm; 3", "mm", "(5 mm", "5 mm)", "5 mm^", "5 / 0 mm", "1/0",
              "1e300 N m", "9**9**9 N m", "9**9**9", "5 mm\x1b[2J", "1e-300 m", "inf mm", "nan N", "5 %", "-5 mm",
              "5 mm", "1 kN", "0.01 N m", "1e-5 rad", "1.8 Nm", "1.8 N-m", "1.8 N.m", "1.8 N·m", "1 DEG", "1 RAD",
              "2 mrad", "3 µm", "0.5 in", "1 nm", "1 N m/rad", "x" * 100, ""]
UNIT_NAMES = ["mm", "m", "N", "kN", "N m", "Nm", "N-m", "N·m", "rad", "mrad", "deg", "DEG", "Deg", "°", "%", "s",
              "GPa", "nm", "furlong", "1/0", "(N", "N)", "m^", "N m; 3"]
unit_text = st.one_of(
    st.sampled_from(UNIT_CASES),
    st.builds(lambda number, unit, space: f"{number}{space}{unit}", number_text, st.sampled_from(UNIT_NAMES),
              st.sampled_from(["", " ", "  "])),
    st.text(max_size=12),
)
header_unit = st.one_of(st.sampled_from(UNIT_NAMES), st.text(max_size=8).filter(lambda u: "]" not in u))


def small_loop(torque_unit: str, twist_unit: str, separator: str = ",") -> str:
    """A 30-sample loop in stick (a line with noise-free twist) under a header with the given units."""
    rows = [f"{0.05 * math.sin(k / 4):.6f}{separator}{1e-3 * math.sin(k / 4) + 1e-6 * k:.9f}" for k in range(30)]
    return f"torque [{torque_unit}]{separator}twist [{twist_unit}]\n" + "\n".join(rows) + "\n"


@PROPERTY
@given(radius=unit_text, force=unit_text, noise=st.one_of(st.none(), unit_text),
       torque_unit=header_unit, twist_unit=header_unit, separator=st.sampled_from([",", ";", "\t"]))
def test_unit_strings_and_header_units_exit_0_or_2_within_a_second(radius, force, noise, torque_unit, twist_unit,
                                                                    separator):
    with working_directory() as root:
        with open("loop.csv", "w", encoding="utf-8", newline="") as handle:
            handle.write(small_loop(torque_unit, twist_unit, separator))
        before = snapshot(root)
        registry()  # built once per process (about half a second): not what the second bounds
        argv = ["fit", "--loop", "loop.csv", "--radius", radius, "--normal-force", force, "--json"]
        if noise is not None:
            argv += ["--torque-noise", noise]
        start = time.perf_counter()
        status, out, err = run_in_process(argv)
        seconds = time.perf_counter() - start
        check_streams(status, out, err)
        assert snapshot(root) == before
    if status == 2:
        assert seconds < 1.0, (argv, seconds)
        assert not any(ord(c) < 32 for c in err.rstrip("\n")), repr(err)
    else:
        json.loads(out, parse_constant=lambda name: pytest.fail(f"JSON holds {name}"))


# --------------------------------------------------------------------------- cases that need real processes
PYTHON = [sys.executable, "-m", "torsional_contact"]


def signal_file(directory, n=40) -> str:
    path = os.path.join(directory, "signal.csv")
    with open(path, "w") as handle:
        handle.write("\n".join(repr(1.3 * ((-1) ** (i // 10)) * (i % 10) / 10) for i in range(n)) + "\n")
    return path


def one_error_line(run, *names) -> str:
    assert run.returncode == 2, run.stderr
    assert run.stdout in ("", b"", None)
    err = run.stderr.decode() if isinstance(run.stderr, bytes) else run.stderr
    lines = err.splitlines()
    assert len(lines) == 1 and lines[0].startswith(PREFIX), err
    for name in names:
        assert name in lines[0], (name, lines[0])
    return lines[0]


def test_output_dev_stdout_is_written_not_replaced(tmp_path):
    path = signal_file(tmp_path)
    run = subprocess.run(PYTHON + ["history", "--signal", path, "--output", "/dev/stdout", "--json"],
                         capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stderr
    lines = run.stdout.splitlines()
    assert lines[0] == HEADER and len(lines) == 40 + 2  # the table, then the JSON summary
    assert json.loads(lines[-1])["samples"] == 40
    assert os.path.islink("/dev/stdout")  # still the link to /proc/self/fd/1, not a file


def test_output_dev_fd_and_proc_self_fd(tmp_path):
    path = signal_file(tmp_path)
    for form in ("/dev/fd/{fd}", "/proc/self/fd/{fd}"):
        read_end, write_end = os.pipe()  # the child inherits write_end under the same number
        try:
            run = subprocess.run(PYTHON + ["history", "--signal", path, "--output", form.format(fd=write_end)],
                                 capture_output=True, text=True, timeout=120, pass_fds=(write_end,))
        finally:
            os.close(write_end)
        with os.fdopen(read_end, "rb") as handle:
            table = handle.read().decode().splitlines()
        assert run.returncode == 0, run.stderr
        assert table[0] == HEADER and len(table) == 41


@pytest.mark.parametrize("argv", [
    ["solve", "--stick-radius", "0.6", "--radii", *[f"{k / 20000:.5f}" for k in range(20001)], "--json"],
    ["history", "--signal", "{signal}", "--output", "/dev/stdout", "--no-progress"],
    ["solve", "--help"],
])
def test_closed_standard_output_ends_quietly(tmp_path, argv):
    """``... | head -c1``: status 141 (SIGPIPE's), nothing on standard error; no traceback."""
    path = signal_file(tmp_path, n=50_000)
    argv = [a.format(signal=path) for a in argv]
    process = subprocess.Popen(PYTHON + argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    first = process.stdout.read(1)
    process.stdout.close()
    _, err = process.communicate(timeout=120)
    assert first
    if argv[-1] == "--help" and process.returncode == 0:  # the help fitted in the pipe before it closed
        assert err == b""
        return
    assert process.returncode == 141, err
    assert err == b""


@pytest.mark.parametrize("argv", [
    ["solve", "--torque", "1.23", "--json"],
    ["history", "--turning-points", "0", "1.23", "-1", "--json"],
    ["reference", "--stick-radius", "0.6", "--n-terms", "10", "--digits", "10"],
    ["errata", "--help"],
    ["--version"],
])
def test_standard_output_on_dev_full(argv):
    with open("/dev/full", "w") as full:
        run = subprocess.run(PYTHON + argv, stdout=full, stderr=subprocess.PIPE, text=True, timeout=300)
    line = one_error_line(run, "standard output", "No space left on device")
    assert line == f"{PREFIX}standard output: No space left on device"


def _sigint_as_at_a_terminal():
    """Ctrl-C's default disposition in the child: a test run started in the background (``cmd &``) ignores SIGINT,
    the children inherit that, and Python then never raises KeyboardInterrupt."""
    signal.signal(signal.SIGINT, signal.SIG_DFL)


def test_ctrl_c_is_one_line_and_status_130():
    process = subprocess.Popen(PYTHON + ["reference", "--stick-radius", "0.5", "--n-terms", "1000", "--digits",
                                         "200"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                               preexec_fn=_sigint_as_at_a_terminal)
    time.sleep(3)
    process.send_signal(signal.SIGINT)
    out, err = process.communicate(timeout=60)
    assert process.returncode == 130, err
    assert out == "" and err == "torsional_contact: interrupted\n"


def test_input_errors_name_the_option_and_the_path(tmp_path):
    for argv, names in [
        (["history", "--signal", str(tmp_path / "absent.csv")], ["--signal", "absent.csv", "No such file"]),
        (["history", "--signal", str(tmp_path)], ["--signal", str(tmp_path), "Is a directory"]),
        (["history", "--signal", str(tmp_path / "absent.npy")], ["--signal", "absent.npy", "No such file"]),
        (["history", "--signal", "a\0b.csv"], ["--signal", "NUL character"]),
    ]:
        status, out, err = run_in_process(argv)
        check_streams(status, out, err)
        assert status == 2 and all(n in err for n in names), err


@pytest.mark.parametrize("output, reason", [
    ("/proc/out.csv", "cannot create a file in /proc" if IS_ROOT else "directory /proc is not writable"),
    ("", "is empty: name a file"),
    (".", "names a directory, not a file"),
])
def test_outputs_from_the_trial_are_one_line(tmp_path, output, reason):
    """The outputs that gave 21-29-line tracebacks: one line naming --output, nothing written, nothing printed."""
    path = signal_file(tmp_path)
    before = snapshot(tmp_path)
    status, out, err = run_in_process(["history", "--signal", path, "--output", output, "--json"])
    check_streams(status, out, err, must_name="--output")
    assert status == 2 and reason in err and snapshot(tmp_path) == before
    assert not os.path.exists("/proc/out.csv")


def test_unreadable_input_names_the_option(tmp_path):
    path = signal_file(tmp_path)
    os.chmod(path, 0)
    argv = PYTHON + ["history", "--signal", path]
    if IS_ROOT:
        if shutil.which("setpriv") is None:
            pytest.skip("needs setpriv(1) to drop root's override of permission bits")
        argv = ["setpriv", "--bounding-set", "-dac_override,-dac_read_search", *argv]
    run = subprocess.run(argv, capture_output=True, text=True, timeout=120)
    one_error_line(run, "--signal", path, "Permission denied")


def in_mount_namespace(script: str, cwd) -> subprocess.CompletedProcess:
    if not IS_ROOT or shutil.which("unshare") is None or subprocess.run(["unshare", "--mount", "true"]).returncode:
        pytest.skip("needs root and a private mount namespace (unshare)")
    return subprocess.run(["unshare", "--mount", "sh", "-c", script], cwd=cwd, capture_output=True, text=True,
                          timeout=300)


def test_read_only_file_system_is_one_line(tmp_path):
    signal_file(tmp_path)
    os.mkdir(tmp_path / "area")
    python = " ".join(PYTHON)
    run = in_mount_namespace("mount --bind area area && mount -o remount,ro,bind area && "
                             f"{python} history --signal signal.csv --output area/out.csv", tmp_path)
    one_error_line(run, "--output area/out.csv", "read-only file system")
    assert os.listdir(tmp_path / "area") == []


def test_full_file_system_is_one_line_and_keeps_the_old_table(tmp_path):
    signal_file(tmp_path, n=20_000)  # a table of about 1.5 MB
    os.mkdir(tmp_path / "area")
    python = " ".join(PYTHON)
    run = in_mount_namespace(f"mount -t tmpfs -o size=256k tmpfs area && echo old > area/out.csv && "
                             f"{python} history --signal signal.csv --output area/out.csv; echo status=$?; "
                             "ls -a area; cat area/out.csv", tmp_path)
    out = run.stdout.splitlines()
    assert out[0] == "status=2" and out[1:] == [".", "..", "out.csv", "old"], run.stdout
    assert run.stderr.splitlines() == [f"{PREFIX}--output area/out.csv: No space left on device"]


def test_ci_runs_the_longer_profile():
    """.ci/run selects the "ci" profile, so that CI tries more examples than the fast tier."""
    from pathlib import Path

    ci = (Path(__file__).resolve().parents[1] / ".ci" / "run").read_text()
    assert "export TORSIONAL_HYPOTHESIS_PROFILE=ci" in ci
    assert PROFILES["ci"] >= 10 * PROFILES["fast"]
