"""The one writer of files a user names (command line, workflow scripts, ``provenance``).

What happens at the path depends on what is there (symbolic links followed):

* a regular file, or a new name in an existing directory: replaced atomically, a temporary
  file beside it written, flushed, fsync'ed and renamed over it (the old file's permission
  bits and, where allowed, owner kept); readers see the old or the new content, never half
  (a file with several hard links is replaced under this name; its other names keep the old
  content);
* a symbolic link: written THROUGH to its final target, atomically beside the target; a
  dangling link creates its target when the target's directory exists;
* a FIFO, a character or block device: opened and written in place, never replaced;
* an open file descriptor, ``/dev/stdout``, ``/dev/stderr``, ``/dev/fd/N``,
  ``/proc/self/fd/N``: written through a duplicate of the descriptor (its offset and
  append mode respected), never replaced;
* refused with ``OutputError``, one line naming the argument and the path: ``""``, ``.``,
  ``..`` or a name ending in ``/``, a directory, a socket, a path under a regular file, a
  missing parent directory (unless ``parents=True``: command-line ``--parents``), a directory
  or file that cannot be written (read-only file system included), and a regular file that is
  one of the inputs (same device and inode: through symbolic and hard links).

Errors of the operating system while writing (no space left, ``/dev/full``, EIO ...) become
``OutputError`` too.  A temporary file never survives a failure: it is removed in ``finally``,
SIGINT raises KeyboardInterrupt as usual, and while a temporary file exists SIGTERM and SIGHUP
(if they have their default action) raise ``SystemExit(128 + signal number)`` so that the
clean-up runs; the signals are blocked while the temporary file is created and renamed, so none
slips between the creation and the bookkeeping.
"""

from __future__ import annotations

import contextlib
import dataclasses
import errno
import fcntl
import os
import re
import shutil
import signal
import stat
import sys
import tempfile
import threading

__all__ = ["OutputError", "Target", "resolve_output", "distinct_outputs", "open_output", "atomic_path", "write_bytes",
           "shown_path"]

#: Paths that name an open file descriptor of this process (group 2: the descriptor).
_DESCRIPTOR_PATH = re.compile(r"^/(dev/fd|proc/(?:self|thread-self|\d+)/fd)/(\d+)$")
_STANDARD_STREAMS = {"/dev/stdin": 0, "/dev/stdout": 1, "/dev/stderr": 2}
#: The signals whose default action would kill the process without running ``finally``.
_TERMINATING = tuple(getattr(signal, name) for name in ("SIGTERM", "SIGHUP") if hasattr(signal, name))
_BLOCKED = {signal.SIGINT, *_TERMINATING}
_MAX_LINKS = 40  # Linux's own limit on symbolic links followed in one lookup


def shown_path(path) -> str:
    """``path`` as printed in a one-line message: quoted when empty or not plainly printable."""
    text = os.fsdecode(path) if isinstance(path, bytes) else str(path)
    return text if text and text.isprintable() and text.strip() == text and "'" not in text else repr(text)


class OutputError(OSError):
    """A path that cannot be written as asked: ``str()`` is one line naming the argument and the path."""

    def __init__(self, label: str, path, reason: str, code: int | None = None):
        super().__init__(code, reason, os.fsdecode(path) if isinstance(path, bytes) else str(path))
        self.label = label
        self.path = self.filename
        self.reason = reason

    def __str__(self) -> str:
        return f"{self.label} {shown_path(self.path)}: {self.reason}"


@dataclasses.dataclass(frozen=True)
class Target:
    """Where a write goes.

    ``kind``: "file" (replaced atomically at ``final``, the path with every symbolic link
    resolved), "stream" (FIFO or device opened in place at ``final``) or "descriptor"
    (``descriptor`` duplicated).  ``create``: the missing directories to make first (``parents``).
    """

    path: str
    final: str
    kind: str
    descriptor: int | None = None
    create: tuple[str, ...] = ()


def _reason(exc: OSError) -> str:
    return exc.strerror or str(exc)


def _descriptor(path: str) -> int | None:
    """The descriptor a path such as /dev/stdout or /proc/self/fd/3 names (following links), else None."""
    current = os.path.abspath(path)
    for _ in range(_MAX_LINKS):
        if current in _STANDARD_STREAMS and not os.path.islink(current):
            return _STANDARD_STREAMS[current]
        match = _DESCRIPTOR_PATH.match(current)
        if match:
            pid = re.match(r"^/proc/(\d+)/", current)
            if pid is None or int(pid.group(1)) == os.getpid():
                return int(match.group(2))
            return None
        if not os.path.islink(current):
            return None
        current = os.path.normpath(os.path.join(os.path.dirname(current), os.readlink(current)))
    return None


def _input_identities(inputs) -> list[tuple[str, str, tuple[int, int]]]:
    """(label, path, (device, inode)) of every input that is a regular file; ``inputs``: paths or (label, path)."""
    found = []
    for item in inputs:
        label, path = item if isinstance(item, tuple) else ("the input", item)
        if path is None:
            continue
        try:
            info = os.stat(path)
        except (OSError, ValueError):  # an input that does not exist cannot be overwritten
            continue
        if stat.S_ISREG(info.st_mode):
            found.append((label, os.fspath(path), (info.st_dev, info.st_ino)))
    return found


def _refuse_input(label, path, info, inputs) -> None:
    for input_label, input_path, identity in _input_identities(inputs):
        if (info.st_dev, info.st_ino) == identity:
            what = "the input" if input_label == "the input" else f"the input of {input_label}"
            raise OutputError(label, path, f"is the same file as {what} ({shown_path(input_path)}): write elsewhere")


def _missing_directory_hint(label: str) -> str:
    return "create it first, or use --parents" if label.startswith("--") else "create it first, or pass parents=True"


def _check_directory(label: str, path: str, directory: str, parents: bool, dangling_link: bool) -> tuple[str, ...]:
    """Refuse unless ``directory`` exists and is writable; with ``parents``, the missing ones to create."""
    missing = []
    current = directory
    while True:
        try:
            info = os.stat(current)
        except FileNotFoundError:
            missing.append(current)
            parent = os.path.dirname(current)
            if parent == current:  # pragma: no cover - the root always exists
                raise OutputError(label, path, "no existing directory above it") from None
            current = parent
            continue
        except OSError as exc:
            raise OutputError(label, path, f"{shown_path(current)}: {_reason(exc)}", exc.errno) from None
        break
    if not stat.S_ISDIR(info.st_mode):
        raise OutputError(label, path, f"{shown_path(current)} is not a directory", errno.ENOTDIR)
    if missing and (dangling_link or not parents):
        first = missing[-1]
        if dangling_link:
            raise OutputError(label, path, f"is a dangling symbolic link whose target's directory "
                              f"{shown_path(directory)} does not exist", errno.ENOENT)
        raise OutputError(label, path, f"directory {shown_path(first)} does not exist "
                          f"({_missing_directory_hint(label)})", errno.ENOENT)
    if not os.access(current, os.W_OK | os.X_OK):
        if _read_only(current):
            raise OutputError(label, path, f"{shown_path(current)} is on a read-only file system", errno.EROFS)
        raise OutputError(label, path, f"directory {shown_path(current)} is not writable", errno.EACCES)
    return tuple(reversed(missing))


def _read_only(path: str) -> bool:
    try:
        return bool(os.statvfs(path).f_flag & os.ST_RDONLY)
    except OSError:
        return False


def resolve_output(path, *, label: str = "path", inputs=(), parents: bool = False) -> Target:
    """Where writing ``path`` goes, or ``OutputError`` (see the module's docstring); writes nothing.

    ``inputs``: the paths read by the same command (or ``(label, path)`` pairs); a regular
    file among them is refused as the output.
    """
    if isinstance(path, bytes):
        path = os.fsdecode(path)
    path = os.fspath(path)
    if path in ("", ".", "..") or path.endswith(("/", "/.", "/..")):
        raise OutputError(label, path, "names a directory, not a file" if path else "is empty: name a file")
    if "\0" in path:
        raise OutputError(label, path, "contains a NUL character")
    try:
        descriptor = _descriptor(path)
    except OSError as exc:
        raise OutputError(label, path, _reason(exc), exc.errno) from None
    if descriptor is not None:
        return _descriptor_target(label, path, descriptor, inputs)
    try:
        info = os.stat(path)
    except FileNotFoundError:
        info = None
    except NotADirectoryError:
        raise OutputError(label, path, f"{shown_path(_first_non_directory(path))} is not a directory",
                          errno.ENOTDIR) from None
    except OSError as exc:
        raise OutputError(label, path, _reason(exc), exc.errno) from None
    if info is None:  # a new name, or a dangling symbolic link
        final = os.path.realpath(path)
        create = _check_directory(label, path, os.path.dirname(final), parents, dangling_link=os.path.islink(path))
        return Target(path, final, "file", create=create)
    mode = info.st_mode
    if stat.S_ISDIR(mode):
        raise OutputError(label, path, "is a directory", errno.EISDIR)
    if stat.S_ISSOCK(mode):
        raise OutputError(label, path, "is a socket, not a file", errno.ENXIO)
    if stat.S_ISREG(mode):
        _refuse_input(label, path, info, inputs)
        final = os.path.realpath(path)
        _check_directory(label, path, os.path.dirname(final), False, dangling_link=False)
        if not os.access(final, os.W_OK):
            raise OutputError(label, path, "is read-only", errno.EACCES)
        return Target(path, final, "file")
    # FIFO, character or block device: written in place
    if not os.access(path, os.W_OK):
        reason = "is on a read-only file system" if _read_only(path) else "is not writable"
        raise OutputError(label, path, reason, errno.EACCES)
    return Target(path, path, "stream")


def _identity(target: Target):
    """What makes two file targets the same file: the existing file's (device, inode), else its resolved path."""
    try:
        info = os.stat(target.final)
    except OSError:
        return ("path", target.final)
    return ("inode", info.st_dev, info.st_ino) if stat.S_ISREG(info.st_mode) else ("path", target.final)


def distinct_outputs(outputs, *, inputs=(), parents: bool = False) -> list[Target]:
    """``resolve_output`` of every (label, path) of ``outputs`` (None paths skipped), refusing two that name the
    same file: the same path, a symbolic link to the other, a hard link of it.

    Two outputs to one file would leave only the last written.  FIFOs, devices and descriptors (e.g.
    /dev/null twice) are written in place and may repeat.  Raises ``OutputError`` naming both options.
    """
    targets, seen = [], {}
    for label, path in outputs:
        if path is None:
            continue
        target = resolve_output(path, label=label, inputs=inputs, parents=parents)
        if target.kind == "file":
            key = _identity(target)
            if key in seen:
                other_label, other_path = seen[key]
                raise OutputError(label, path, f"is the same file as {other_label} {shown_path(other_path)}: give two "
                                  "different files", errno.EEXIST)
            seen[key] = (label, path)
        targets.append(target)
    return targets


def _first_non_directory(path: str) -> str:
    """The first existing component of ``path`` that is not a directory (for ENOTDIR messages)."""
    parts = os.path.abspath(path).split(os.sep)
    for i in range(2, len(parts) + 1):
        prefix = os.sep.join(parts[:i])
        if os.path.exists(prefix) and not os.path.isdir(prefix):
            return prefix
    return path


def _descriptor_target(label, path, descriptor, inputs) -> Target:
    try:
        flags = fcntl.fcntl(descriptor, fcntl.F_GETFL)
        info = os.fstat(descriptor)
    except OSError:
        raise OutputError(label, path, f"file descriptor {descriptor} is not open", errno.EBADF) from None
    if stat.S_ISDIR(info.st_mode):
        raise OutputError(label, path, f"file descriptor {descriptor} is a directory", errno.EISDIR)
    if flags & os.O_ACCMODE == os.O_RDONLY:
        raise OutputError(label, path, f"file descriptor {descriptor} is not open for writing", errno.EBADF)
    if stat.S_ISREG(info.st_mode):
        _refuse_input(label, path, info, inputs)
    return Target(path, path, "descriptor", descriptor=descriptor)


# --------------------------------------------------------------------------- signals
def _exit_on_signal(signum, frame):
    raise SystemExit(128 + signum)


@contextlib.contextmanager
def _terminating_signals_raise():
    """While a temporary file exists: SIGTERM, SIGHUP raise SystemExit (main thread, default handlers only)."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    replaced = []
    for signum in _TERMINATING:
        if signal.getsignal(signum) == signal.SIG_DFL:
            signal.signal(signum, _exit_on_signal)
            replaced.append(signum)
    try:
        yield
    finally:
        for signum in replaced:
            signal.signal(signum, signal.SIG_DFL)


@contextlib.contextmanager
def _signals_blocked():
    """No signal handler runs inside (they run when the block ends): creation and bookkeeping stay together."""
    previous = signal.pthread_sigmask(signal.SIG_BLOCK, _BLOCKED)
    try:
        yield
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, previous)


# --------------------------------------------------------------------------- writing
def _make_directories(label: str, path: str, create) -> None:
    for directory in create:
        try:
            os.mkdir(directory)
        except FileExistsError:  # made meanwhile by someone else: what was asked for exists
            if not os.path.isdir(directory):
                raise OutputError(label, path, f"{shown_path(directory)} is not a directory", errno.ENOTDIR) from None
        except OSError as exc:
            raise OutputError(label, path, f"cannot create {shown_path(directory)}: {_reason(exc)}",
                              exc.errno) from None


def _new_file_mode(final: str) -> tuple[int, int | None, int | None]:
    """Permission bits (and owner) for the replacement: the old file's, or 0666 less the umask."""
    try:
        info = os.stat(final)
    except FileNotFoundError:
        umask = os.umask(0)
        os.umask(umask)
        return 0o666 & ~umask, None, None
    return stat.S_IMODE(info.st_mode), info.st_uid, info.st_gid


def _prepare_temporary(label, path, target: Target, suffix: str) -> tuple[int, str]:
    """A temporary file beside the final target with the final permissions: (descriptor, name)."""
    directory = os.path.dirname(target.final)
    try:
        with _signals_blocked():
            handle, tmp = tempfile.mkstemp(dir=directory, prefix=".tmp-", suffix=suffix)
            _TEMPORARIES.add(tmp)
    except OSError as exc:
        raise OutputError(label, path, f"cannot create a file in {shown_path(directory)}: {_reason(exc)}",
                          exc.errno) from None
    mode, uid, gid = _new_file_mode(target.final)
    os.fchmod(handle, mode)  # mkstemp's 0600 would make results unreadable to others
    if uid is not None and (uid, gid) != (os.geteuid(), os.getegid()):
        # keep the owner of a replaced file; only root (or a group member, for the group) may
        with contextlib.suppress(PermissionError):
            os.fchown(handle, uid, gid)
    return handle, tmp


#: Temporary files that exist right now (for tests and for the clean-up in ``finally``).
_TEMPORARIES: set[str] = set()


def _discard(tmp: str | None) -> None:
    if tmp is None:
        return
    with contextlib.suppress(FileNotFoundError):
        os.unlink(tmp)
    _TEMPORARIES.discard(tmp)


def _publish(tmp: str, final: str) -> None:
    """fsync ``tmp``, rename it onto ``final``, fsync the directory (durability of the rename)."""
    handle = os.open(tmp, os.O_RDONLY)
    try:
        os.fsync(handle)
    finally:
        os.close(handle)
    with _signals_blocked():
        os.replace(tmp, final)
        _TEMPORARIES.discard(tmp)
    directory = os.open(os.path.dirname(final), os.O_RDONLY)
    try:
        os.fsync(directory)
    except OSError as exc:  # some file systems cannot fsync a directory; the data itself is synced
        if exc.errno not in (errno.EINVAL, errno.ENOTSUP):
            raise
    finally:
        os.close(directory)


def _open_stream(label: str, target: Target) -> int:
    """A new descriptor writing to a FIFO, a device or an open descriptor, in place."""
    try:
        if target.kind == "descriptor":
            for stream in (sys.stdout, sys.stderr):  # what Python buffered comes first
                with contextlib.suppress(AttributeError, ValueError, OSError):
                    if stream.fileno() == target.descriptor:
                        stream.flush()
            return os.dup(target.descriptor)
        return os.open(target.final, os.O_WRONLY | os.O_NOCTTY)
    except OSError as exc:
        raise OutputError(label, target.path, _reason(exc), exc.errno) from None


@contextlib.contextmanager
def open_output(path, mode: str = "w", *, label: str = "path", inputs=(), parents: bool = False,
                encoding: str | None = "utf-8", target: Target | None = None):
    """A file object writing ``path`` as the module's docstring says; the content lands only on success.

    ``mode``: "w" (text, ``encoding``) or "wb".  An ``OSError`` raised while writing the handle
    (no space left ...) becomes ``OutputError`` naming ``label`` and ``path``.  ``target``: an
    earlier ``resolve_output`` result (it is checked again here, since the file system may have
    changed since).
    """
    if mode not in ("w", "wb"):
        raise ValueError(f"mode must be 'w' or 'wb', got {mode!r}")
    encoding = None if mode == "wb" else encoding
    target = resolve_output(path if target is None else target.path, label=label, inputs=inputs, parents=parents)
    if target.kind != "file":
        descriptor = _open_stream(label, target)
        try:
            with os.fdopen(descriptor, mode, encoding=encoding) as handle:
                yield handle
                handle.flush()
        except OutputError:
            raise
        except OSError as exc:
            raise OutputError(label, target.path, _reason(exc), exc.errno) from None
        return
    tmp = None
    with _terminating_signals_raise():
        try:
            _make_directories(label, target.path, target.create)
            descriptor, tmp = _prepare_temporary(label, target.path, target, "")
            with os.fdopen(descriptor, mode, encoding=encoding) as handle:
                yield handle
                handle.flush()
            _publish(tmp, target.final)
            tmp = None
        except OutputError:
            raise
        except OSError as exc:
            raise OutputError(label, target.path, _reason(exc), exc.errno) from None
        finally:
            _discard(tmp)


@contextlib.contextmanager
def atomic_path(path, suffix: str = "", *, label: str = "path", inputs=(), parents: bool = False):
    """Yield a temporary file name to write; on success its content lands at ``path`` (module docstring).

    For a regular file (or a symbolic link to one) the temporary file lies beside the final
    target and is renamed onto it; for a FIFO, a device or a descriptor it lies in the
    system's temporary directory and is copied in place.  ``suffix``: of the temporary name
    (default: ``path``'s extension, which e.g. ``savefig`` reads the format from).
    """
    path = os.fsdecode(path) if isinstance(path, bytes) else os.fspath(path)
    suffix = suffix or os.path.splitext(path)[1]
    target = resolve_output(path, label=label, inputs=inputs, parents=parents)
    tmp = None
    with _terminating_signals_raise():
        try:
            if target.kind == "file":
                _make_directories(label, path, target.create)
                descriptor, tmp = _prepare_temporary(label, path, target, suffix)
                os.close(descriptor)
            else:
                with _signals_blocked():
                    descriptor, tmp = tempfile.mkstemp(prefix="torsional-contact-", suffix=suffix)
                    _TEMPORARIES.add(tmp)
                os.close(descriptor)
        except OSError as exc:
            _discard(tmp)
            raise OutputError(label, path, _reason(exc), exc.errno) from None
        try:
            yield tmp
            if target.kind == "file":
                try:
                    _publish(tmp, target.final)
                except OSError as exc:
                    raise OutputError(label, path, _reason(exc), exc.errno) from None
                tmp = None
            else:
                with open(tmp, "rb") as source, open_output(path, "wb", label=label, inputs=inputs,
                                                            target=target) as sink:
                    shutil.copyfileobj(source, sink)
        finally:
            _discard(tmp)


def write_bytes(path, data: bytes, *, label: str = "path", inputs=(), parents: bool = False) -> None:
    """Write ``data`` to ``path`` through ``open_output``."""
    with open_output(path, "wb", label=label, inputs=inputs, parents=parents) as handle:
        handle.write(data)
