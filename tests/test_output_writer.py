"""The one writer of user-named files (``torsional_contact.output``) and the modules built on it.

Each kind of path is made for real in a temporary directory (regular file, symbolic links,
FIFO with a reader thread, device nodes made with os.mknod when root, descriptors) and the
test checks what was written and that nothing else changed.  Interrupts are real signals sent
to a subprocess that is in the middle of a write.
"""

from __future__ import annotations

import errno
import json
import os
import re
import shutil
import signal
import stat
import subprocess
import sys
import textwrap
import threading
from pathlib import Path

import numpy as np
import pytest

from torsional_contact import output, provenance
from torsional_contact.output import OutputError, atomic_path, open_output, resolve_output, write_bytes

ROOT = Path(__file__).resolve().parents[1]
IS_ROOT = os.geteuid() == 0


def leftovers(directory) -> list[str]:
    """Temporary files of the writer left anywhere under ``directory``."""
    return sorted(str(p) for p in Path(directory).rglob("*") if p.name.startswith((".tmp-", "torsional-contact-")))


class FifoReader(threading.Thread):
    """Reads a FIFO to its end in the background (the writer blocks until a reader opens it)."""

    def __init__(self, path):
        super().__init__(daemon=True)
        self.path, self.data = path, None

    def run(self):
        with open(self.path, "rb") as handle:
            self.data = handle.read()

    def finish(self):
        """Join; if the writer never opened the FIFO, open and close its write end so that the reader ends."""
        if self.is_alive():
            try:
                fd = os.open(self.path, os.O_WRONLY | os.O_NONBLOCK)
                os.close(fd)
            except OSError as exc:  # no reader yet (ENXIO): it is about to open; try once more after a pause
                assert exc.errno == errno.ENXIO
        self.join(timeout=10)
        assert not self.is_alive()
        return self.data


def make_device(path, minor):
    """A character device node like /dev/null (minor 3) or /dev/full (minor 7); root only."""
    if not IS_ROOT:
        pytest.skip("device nodes need root (os.mknod)")
    os.mknod(path, stat.S_IFCHR | 0o666, os.makedev(1, minor))
    try:
        os.close(os.open(path, os.O_WRONLY))
    except PermissionError:
        pytest.skip("the temporary file system does not allow device nodes (nodev)")


# --------------------------------------------------------------------------- regular files
def test_regular_file_is_replaced_atomically_keeping_its_mode(tmp_path):
    target = tmp_path / "out.txt"
    target.write_text("old\n")
    os.chmod(target, 0o640)
    inode = target.stat().st_ino
    with open_output(target, label="--output") as handle:
        handle.write("half")
        assert target.read_text() == "old\n"  # readers see the old content until the rename
        handle.write(" and whole\n")
    assert target.read_text() == "half and whole\n"
    assert stat.S_IMODE(target.stat().st_mode) == 0o640
    assert target.stat().st_ino != inode  # a new file renamed over the old one
    assert leftovers(tmp_path) == []


def test_new_file_gets_the_umask_mode(tmp_path):
    umask = os.umask(0o022)
    try:
        write_bytes(tmp_path / "new.bin", b"\x00\x01")
    finally:
        os.umask(umask)
    assert (tmp_path / "new.bin").read_bytes() == b"\x00\x01"
    assert stat.S_IMODE((tmp_path / "new.bin").stat().st_mode) == 0o644


def test_failure_in_the_middle_keeps_the_old_file_and_no_temporary(tmp_path):
    target = tmp_path / "out.txt"
    target.write_text("old\n")
    with pytest.raises(RuntimeError, match="boom"), open_output(target) as handle:
        handle.write("new")
        raise RuntimeError("boom")
    assert target.read_text() == "old\n"
    with pytest.raises(RuntimeError, match="boom"), atomic_path(target) as tmp:
        Path(tmp).write_text("new")
        raise RuntimeError("boom")
    assert target.read_text() == "old\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out.txt"]
    assert output._TEMPORARIES == set()


def test_atomic_path_keeps_the_extension_for_savefig(tmp_path):
    with atomic_path(tmp_path / "figure.pdf") as tmp:
        assert tmp.endswith(".pdf") and os.path.dirname(tmp) == str(tmp_path)
        Path(tmp).write_bytes(b"%PDF")
    assert (tmp_path / "figure.pdf").read_bytes() == b"%PDF"


# --------------------------------------------------------------------------- symbolic links
def test_symlink_is_written_through_atomically_beside_its_target(tmp_path):
    (tmp_path / "data").mkdir()
    (tmp_path / "links").mkdir()
    target = tmp_path / "data" / "result.csv"
    target.write_text("old\n")
    link = tmp_path / "links" / "result.csv"
    link.symlink_to("../data/result.csv")
    chain = tmp_path / "chain.csv"
    chain.symlink_to(link)
    with atomic_path(chain, label="--output") as tmp:
        assert os.path.dirname(tmp) == str(tmp_path / "data")  # beside the final target
        Path(tmp).write_text("new\n")
    assert target.read_text() == "new\n"
    assert os.readlink(link) == "../data/result.csv" and os.readlink(chain) == str(link)
    provenance.write_text(link, "newer\n")
    assert target.read_text() == "newer\n" and link.is_symlink()
    assert leftovers(tmp_path) == []


def test_dangling_symlink_creates_its_target_if_its_directory_exists(tmp_path):
    link = tmp_path / "out.csv"
    link.symlink_to("real.csv")
    provenance.write_text(link, "x\n")
    assert link.is_symlink() and (tmp_path / "real.csv").read_text() == "x\n"
    lost = tmp_path / "lost.csv"
    lost.symlink_to("nowhere/real.csv")
    with pytest.raises(OutputError, match=r"^--output .*lost\.csv: is a dangling symbolic link whose target's "
                       r"directory .*nowhere does not exist$"):
        provenance.write_text(lost, "x\n", label="--output", parents=True)  # never create through a link
    assert not (tmp_path / "nowhere").exists()


def test_symlink_loop_is_refused(tmp_path):
    (tmp_path / "a").symlink_to("b")
    (tmp_path / "b").symlink_to("a")
    with pytest.raises(OutputError, match="--output .*: Too many levels of symbolic links"):
        resolve_output(tmp_path / "a", label="--output")


# --------------------------------------------------------------------------- FIFOs, devices, descriptors
def test_fifo_is_written_in_place(tmp_path):
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    reader = FifoReader(fifo)
    reader.start()
    provenance.write_text(fifo, "through the pipe\n")
    assert reader.finish() == b"through the pipe\n"
    assert stat.S_ISFIFO(os.lstat(fifo).st_mode)
    reader = FifoReader(fifo)  # atomic_path: a temporary file elsewhere, copied into the FIFO
    reader.start()
    with atomic_path(fifo) as tmp:
        assert not tmp.startswith(str(tmp_path))
        Path(tmp).write_bytes(b"copied")
    assert reader.finish() == b"copied"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["pipe"] and output._TEMPORARIES == set()


def test_sample_table_into_a_fifo(tmp_path):
    from torsional_contact.io.signal_files import write_sample_table

    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    reader = FifoReader(fifo)
    reader.start()
    rows = 100_000  # several chunks and more than a pipe's buffer
    write_sample_table(fifo, "i,x", [np.arange(rows), np.linspace(0, 1, rows)], integer_columns=(0,), chunk=30_000)
    lines = reader.finish().decode().splitlines()
    assert lines[0] == "i,x" and len(lines) == rows + 1 and lines[-1].startswith(f"{rows - 1},1.0")
    assert stat.S_ISFIFO(os.lstat(fifo).st_mode)


def test_device_node_is_written_in_place_never_replaced(tmp_path):
    null = tmp_path / "null"
    make_device(null, 3)
    provenance.write_text(null, "discarded\n")
    with atomic_path(null) as tmp:
        Path(tmp).write_text("discarded too\n")
    info = os.lstat(null)
    assert stat.S_ISCHR(info.st_mode) and info.st_rdev == os.makedev(1, 3)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["null"]


def test_full_device_is_an_error_naming_the_option_and_stays_a_device(tmp_path):
    full = tmp_path / "full"
    make_device(full, 7)
    with pytest.raises(OutputError, match=r"^--output .*full: No space left on device$") as caught:
        provenance.write_text(full, "x" * 100_000, label="--output")
    assert caught.value.errno == errno.ENOSPC
    with pytest.raises(OutputError, match="No space left on device"), atomic_path(full, label="--png") as tmp:
        Path(tmp).write_bytes(b"x" * 100_000)
    info = os.lstat(full)
    assert stat.S_ISCHR(info.st_mode) and info.st_rdev == os.makedev(1, 7)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["full"] and output._TEMPORARIES == set()


@pytest.mark.parametrize("form", ["/dev/fd/{fd}", "/proc/self/fd/{fd}", "/proc/{pid}/fd/{fd}"])
def test_descriptor_paths_write_to_the_open_descriptor(form):
    read_end, write_end = os.pipe()
    try:
        path = form.format(fd=write_end, pid=os.getpid())
        target = resolve_output(path)
        assert target.kind == "descriptor" and target.descriptor == write_end
        provenance.write_text(path, "via the descriptor\n")
        assert os.read(read_end, 100) == b"via the descriptor\n"
    finally:
        os.close(read_end)
        os.close(write_end)


def test_descriptor_not_open_or_read_only_is_refused():
    read_end, write_end = os.pipe()
    os.close(write_end)
    try:
        with pytest.raises(OutputError, match=rf"^--output /dev/fd/{read_end}: file descriptor {read_end} is not "
                           "open for writing$"):
            resolve_output(f"/dev/fd/{read_end}", label="--output")
    finally:
        os.close(read_end)
    with pytest.raises(OutputError, match=f"file descriptor {write_end} is not open"):
        resolve_output(f"/proc/self/fd/{write_end}", label="--output")


def test_dev_stdout_appends_to_what_the_shell_opened(tmp_path):
    """``--output /dev/stdout >> log``: the writer uses descriptor 1 as it is (append mode, offset)."""
    log = tmp_path / "log.txt"
    log.write_text("kept\n")
    code = "from torsional_contact.provenance import write_text; print('printed first'); " \
           "write_text('/dev/stdout', 'table\\n')"
    with open(log, "a") as handle:
        subprocess.run([sys.executable, "-c", code], stdout=handle, check=True)
    assert log.read_text() == "kept\nprinted first\ntable\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["log.txt"]


# --------------------------------------------------------------------------- refusals
@pytest.mark.parametrize(
    "make, name, reason",
    [
        (None, "", "is empty: name a file"),
        (None, ".", "names a directory, not a file"),
        (None, "..", "names a directory, not a file"),
        ("dir", "d/", "names a directory, not a file"),
        ("dir", "d", "is a directory"),
        ("symlink-dir", "ld", "is a directory"),
        ("file", "f/out.csv", r"f is not a directory"),
        ("file", "f/deeper/out.csv", r"f is not a directory"),
        (None, "missing/out.csv", r"directory .*missing does not exist \(create it first, or use --parents\)"),
        (None, "a\0b", "contains a NUL character"),
    ],
)
def test_refused_paths(tmp_path, monkeypatch, make, name, reason):
    monkeypatch.chdir(tmp_path)
    if make == "dir":
        (tmp_path / "d").mkdir()
    elif make == "symlink-dir":
        (tmp_path / "d").mkdir()
        (tmp_path / "ld").symlink_to("d")
    elif make == "file":
        (tmp_path / "f").write_text("precious\n")
    before = sorted(p.name for p in tmp_path.iterdir())
    with pytest.raises(OutputError) as caught:
        provenance.write_text(name, "x\n", label="--output")
    message = str(caught.value)
    assert "\n" not in message and message.startswith("--output ")
    assert re.search(reason, message), message
    assert sorted(p.name for p in tmp_path.iterdir()) == before
    if make == "file":
        assert (tmp_path / "f").read_text() == "precious\n"


def test_missing_parents_are_created_only_when_asked(tmp_path):
    target = tmp_path / "a" / "b" / "out.csv"
    with pytest.raises(OutputError, match=r"directory .*/a does not exist \(create it first, or pass parents=True\)"):
        provenance.write_text(target, "x\n")
    assert not (tmp_path / "a").exists()
    provenance.write_text(target, "x\n", parents=True)
    assert target.read_text() == "x\n"
    with pytest.raises(RuntimeError), open_output(tmp_path / "c" / "out.csv", parents=True):
        raise RuntimeError("the directories are made only when writing starts")
    assert (tmp_path / "c").is_dir()  # made for the write that failed; the file itself is not there
    assert not (tmp_path / "c" / "out.csv").exists()


def test_a_socket_is_refused(tmp_path):
    import socket

    path = tmp_path / "s"
    with socket.socket(socket.AF_UNIX) as server:
        server.bind(str(path))
        with pytest.raises(OutputError, match="is a socket, not a file"):
            provenance.write_text(path, "x")


@pytest.mark.parametrize("how", ["same", "symlink", "hardlink", "relative"])
def test_the_input_itself_is_refused(tmp_path, monkeypatch, how):
    monkeypatch.chdir(tmp_path)
    source = tmp_path / "signal.csv"
    source.write_text("0\n1.2\n")
    out = {"same": source, "symlink": tmp_path / "link.csv", "hardlink": tmp_path / "hard.csv",
           "relative": Path("sub/../signal.csv")}[how]
    (tmp_path / "sub").mkdir()
    if how == "symlink":
        out.symlink_to(source)
    elif how == "hardlink":
        os.link(source, out)
    with pytest.raises(OutputError, match=r"is the same file as the input of --signal \(.*signal\.csv\): write "
                       r"elsewhere$"):
        provenance.write_text(out, "x\n", label="--output", inputs=[("--signal", str(source))])
    assert source.read_text() == "0\n1.2\n"
    other = tmp_path / "copy.csv"
    shutil.copy(source, other)  # the same content in another file is not the input
    provenance.write_text(other, "y\n", inputs=[str(source)])
    assert other.read_text() == "y\n"


def without_override(argv, **kwargs) -> subprocess.CompletedProcess:
    """Run ``argv`` obeying permission bits: as root, without the capabilities that override them (setpriv)."""
    if IS_ROOT:
        if shutil.which("setpriv") is None:
            pytest.skip("needs setpriv(1) to drop root's override of permission bits")
        argv = ["setpriv", "--bounding-set", "-dac_override,-dac_read_search", *argv]
    return subprocess.run(argv, capture_output=True, text=True, timeout=120, **kwargs)


def test_unwritable_places_are_refused(tmp_path):
    (tmp_path / "locked").mkdir()
    (tmp_path / "read-only.csv").write_text("mine\n")
    os.chmod(tmp_path / "read-only.csv", 0o444)
    os.chmod(tmp_path / "locked", 0o555)
    code = textwrap.dedent("""
        from torsional_contact.output import OutputError
        from torsional_contact.provenance import write_text
        for path in ("locked/out.csv", "read-only.csv"):
            try:
                write_text(path, "x", label="--output")
            except OutputError as exc:
                print(exc)
    """)
    try:
        run = without_override([sys.executable, "-c", code], cwd=tmp_path)
    finally:
        os.chmod(tmp_path / "locked", 0o755)
    assert run.returncode == 0, run.stderr
    assert run.stdout.splitlines() == [f"--output locked/out.csv: directory {tmp_path}/locked is not writable",
                                       "--output read-only.csv: is read-only"]
    assert (tmp_path / "read-only.csv").read_text() == "mine\n"
    assert sorted(p.name for p in (tmp_path / "locked").iterdir()) == []


def unshare_mount(script: str, cwd) -> subprocess.CompletedProcess:
    """Run ``script`` (sh) in a private mount namespace, or skip where that is not allowed."""
    if not IS_ROOT or shutil.which("unshare") is None:
        pytest.skip("needs root and unshare(1) for a private mount namespace")
    probe = subprocess.run(["unshare", "--mount", "true"], capture_output=True)
    if probe.returncode != 0:
        pytest.skip("mount namespaces are not available here")
    return subprocess.run(["unshare", "--mount", "sh", "-c", script], cwd=cwd, capture_output=True, text=True,
                          timeout=120)


def test_read_only_file_system_is_refused(tmp_path):
    area = tmp_path / "area"
    area.mkdir()
    (area / "old.csv").write_text("old\n")
    code = ("from torsional_contact.provenance import write_text\n"
            "for p in ('area/new.csv', 'area/old.csv'):\n"
            "    try: write_text(p, 'x', label='--output')\n"
            "    except OSError as exc: print(exc)\n")
    run = unshare_mount(f"mount --bind area area && mount -o remount,ro,bind area && {sys.executable} -c \"{code}\"",
                        tmp_path)
    assert run.returncode == 0, run.stderr
    assert run.stdout.splitlines() == [f"--output area/new.csv: {area} is on a read-only file system",
                                       f"--output area/old.csv: {area} is on a read-only file system"]
    assert sorted(p.name for p in area.iterdir()) == ["old.csv"] and (area / "old.csv").read_text() == "old\n"


def test_full_file_system_keeps_the_old_file_and_no_temporary(tmp_path):
    area = tmp_path / "area"
    area.mkdir()
    code = ("from torsional_contact.provenance import write_text\n"
            "try: write_text('area/out.csv', 'y' * 1000000, label='--output')\n"
            "except OSError as exc: print(exc)\n"
            "import os; print(sorted(os.listdir('area')), open('area/out.csv').read().strip())\n")
    run = unshare_mount(f"mount -t tmpfs -o size=64k tmpfs area && echo old > area/out.csv && "
                        f"{sys.executable} -c \"{code}\"", tmp_path)
    assert run.returncode == 0, run.stderr
    assert run.stdout.splitlines() == ["--output area/out.csv: No space left on device", "['out.csv'] old"]


# --------------------------------------------------------------------------- interrupts
WRITER = textwrap.dedent("""
    import sys, time
    from torsional_contact.output import open_output, atomic_path
    how, path = sys.argv[1], sys.argv[2]
    if how == "open_output":
        with open_output(path, label="--output") as handle:
            handle.write("partial")
            handle.flush()
            print("writing", flush=True)
            time.sleep(60)
    else:
        with atomic_path(path) as tmp:
            open(tmp, "w").write("partial")
            print("writing", flush=True)
            time.sleep(60)
""")


@pytest.mark.parametrize("how", ["open_output", "atomic_path"])
@pytest.mark.parametrize("signum", [signal.SIGINT, signal.SIGTERM, signal.SIGHUP])
def test_no_temporary_survives_an_interrupt(tmp_path, how, signum):
    target = tmp_path / "out.csv"
    target.write_text("old\n")
    # the signal at its default in the child: a test run started in the background ignores SIGINT, one under nohup
    # SIGHUP, and children inherit that (the writer rightly leaves an ignored signal ignored)
    process = subprocess.Popen([sys.executable, "-c", WRITER, how, str(target)], stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, text=True,
                               preexec_fn=lambda: signal.signal(signum, signal.SIG_DFL))
    try:
        assert process.stdout.readline() == "writing\n"
        assert len(leftovers(tmp_path)) == 1  # the temporary file exists now
        process.send_signal(signum)
        process.wait(timeout=30)
    finally:
        process.kill()
        process.communicate()
    expected = {signal.SIGINT: (-signal.SIGINT, 1), signal.SIGTERM: (128 + signal.SIGTERM,),
                signal.SIGHUP: (128 + signal.SIGHUP,)}[signum]
    assert process.returncode in expected  # Python ends an uncaught KeyboardInterrupt by SIGINT itself
    assert leftovers(tmp_path) == [] and sorted(p.name for p in tmp_path.iterdir()) == ["out.csv"]
    assert target.read_text() == "old\n"


def test_a_handler_of_the_caller_is_kept(tmp_path):
    """SIGTERM handled by the application (e.g. Snakemake's own) is left alone, and restored after the write."""
    seen = []
    previous = signal.signal(signal.SIGTERM, lambda signum, frame: seen.append(signum))
    try:
        with open_output(tmp_path / "x.txt") as handle:
            assert signal.getsignal(signal.SIGTERM) is not output._exit_on_signal
            os.kill(os.getpid(), signal.SIGTERM)
            handle.write("done")
        assert seen == [signal.SIGTERM] and (tmp_path / "x.txt").read_text() == "done"
    finally:
        signal.signal(signal.SIGTERM, previous)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    with open_output(tmp_path / "y.txt") as handle:
        assert signal.getsignal(signal.SIGTERM) is output._exit_on_signal
        handle.write("y")
    assert signal.getsignal(signal.SIGTERM) == signal.SIG_DFL
    signal.signal(signal.SIGTERM, previous)


# --------------------------------------------------------------------------- the modules built on the writer
def test_provenance_writers_keep_their_signatures(tmp_path):
    provenance.write_json(tmp_path / "a.json", {"x": 1}, method="m")
    record = json.loads((tmp_path / "a.json").read_text())
    assert record["x"] == 1 and record["metadata"]["method"] == "m"
    provenance.write_macros(tmp_path / "m.tex", {"k": "1"}, "test")
    assert "res@k" in (tmp_path / "m.tex").read_text()
    with provenance.atomic_path(tmp_path / "t.dat", ".part") as tmp:
        assert tmp.endswith(".part")
        Path(tmp).write_text("t")
    assert (tmp_path / "t.dat").read_text() == "t"
    with pytest.raises(OSError, match="is a directory"):  # OutputError is an OSError, as before
        provenance.write_json(tmp_path, {"x": 1})


def test_provenance_records_the_installed_versions():
    """The package versions (read once per process) are those the installed metadata gives now."""
    from importlib import metadata

    packages = provenance.provenance(method="m")["packages"]
    for name in provenance._PACKAGES:
        try:
            expected = metadata.version(name)
        except metadata.PackageNotFoundError:
            expected = None
        assert packages[name] == expected
    assert list(packages)[: len(provenance._PACKAGES)] == list(provenance._PACKAGES)
    packages["numpy"] = "changed"  # each record gets its own dictionary
    assert provenance.provenance()["packages"]["numpy"] != "changed"


def test_save_figure_through_the_writer(tmp_path, monkeypatch):
    monkeypatch.syspath_prepend(str(ROOT / "workflow" / "scripts"))  # the workflow's figure helpers
    import matplotlib.pyplot as plt
    from _plotting import save_figure, subplots

    open_before = plt.get_fignums()
    (tmp_path / "figures").mkdir()
    link = tmp_path / "fig.pdf"
    link.symlink_to("figures/fig.pdf")
    fig, ax = subplots()
    ax.plot([0, 1], [0, 1])
    save_figure(fig, link, tmp_path / "fig.png")
    assert link.is_symlink() and (tmp_path / "figures" / "fig.pdf").read_bytes().startswith(b"%PDF")
    assert (tmp_path / "fig.png").read_bytes().startswith(b"\x89PNG")
    fig, ax = subplots()
    with pytest.raises(OutputError, match=r"^--pdf .*figures: is a directory$"):
        save_figure(fig, tmp_path / "figures")
    assert plt.get_fignums() == open_before  # the helper's figures are not pyplot's: none left open, even on failure
    assert leftovers(tmp_path) == []


#: Writes a workflow script may make without the writer: private scratch files of its own.
SCRATCH_WRITES = {
    ("build_report.py", 'open(configfile, "w"'),  # the configuration handed to snakemake, in a TemporaryDirectory
    ("benchmark_histories.py", "open(files[name], \"wb\")"),  # benchmark inputs, in a TemporaryDirectory
    ("benchmark_build.py", "shim.write_text("),  # the timing wrappers, in a TemporaryDirectory
    ("benchmark_build.py", 'open(log, "w")'),  # Snakemake's and the suite's logs, in the same TemporaryDirectory
    ("_plotting.py", "fig.savefig(tmp,"),  # the figure writer itself: into the temporary name of atomic_path
    # the Snakefile's cache of import statements in .snakemake (no user's path), through its own temporary file
    ("dependencies.py", "temporary.write_text(json.dumps(keep))"),
    ("dependencies.py", "os.replace(temporary, CACHE)"),
}
DIRECT_WRITE = re.compile(r"open\([^)]*[\"'][wax]b?\+?[\"']|\.savefig\(|np\.save(txt|z)?\(|\.to_csv\(|"
                          r"os\.(replace|rename)\(|shutil\.(move|copy\w*)\(|\.write_(text|bytes)\(|json\.dump\(")


def test_workflow_scripts_write_only_through_the_writer():
    """Every output of a workflow script goes through provenance / output / workflow/scripts/_plotting.py."""
    found = []
    for script in sorted((ROOT / "workflow").rglob("*.py")):
        for line in script.read_text().splitlines():
            match = DIRECT_WRITE.search(line)
            if match and not any(script.name == name and text in line for name, text in SCRATCH_WRITES):
                found.append(f"{script.relative_to(ROOT)}: {line.strip()}")
    found = [f for f in found if "shutil.copyfile(partial, tmp)" not in f]  # build_report: into atomic_path's name
    assert found == []
