"""Paths a run reads and writes: input files that cannot hurt, output folders that work, temporaries of our own.

* :func:`check_input_file` — a path a scene names must be a readable regular
  file of bounded size: no device (``/dev/zero``), FIFO (``/dev/stdin``),
  folder, NUL byte or over-long name, so that reading it can neither hang nor
  exhaust memory.
* :func:`check_output_folder` — an output folder is created (if needed) and
  probed with a real file before any work, and must have room for at least
  the first files of the run.
* :func:`temporary_name` / :func:`remove_stale_temporaries` — temporary files
  carry the host and process that made them, so that two runs on one folder
  never delete each other's files in flight: clean-up removes only
  temporaries of processes of this host that are no longer running.
* :func:`umask_mode` — the mode a new file gets under the process's umask
  (``tempfile.mkstemp`` makes 0600 files whatever the umask).

All sizes are in bytes.
"""

from __future__ import annotations

import errno
import os
import secrets
import shutil
import socket
import stat
from pathlib import Path

#: The longest file-name component most file systems allow [bytes] (POSIX NAME_MAX on ext4, xfs, btrfs).
NAME_MAX = 255
#: The longest path accepted [bytes] (Linux PATH_MAX).
PATH_MAX = 4096
#: Marker between a file's own name and the owner part of its temporary name.
TEMPORARY_MARK = ".tmp-"


class PathProblem(ValueError):
    """A path that cannot be used; the message is one line without the key (the caller adds it)."""


def name_problem(path: str) -> str | None:
    """Why ``path`` cannot name a file on this system (a NUL byte, longer than PATH_MAX or NAME_MAX), or None."""
    if "\x00" in path:
        return "the path holds a NUL byte"
    if len(os.fsencode(path)) > PATH_MAX:
        return f"the path is longer than {PATH_MAX} bytes"
    long = next((part for part in Path(path).parts if len(os.fsencode(part)) > NAME_MAX), None)
    if long is not None:
        return f"a name in the path is longer than {NAME_MAX} bytes ({len(os.fsencode(long))})"
    return None


def check_input_file(path: str | Path, max_bytes: int) -> Path:
    """``path`` if it is a readable regular file of at most ``max_bytes``; else :class:`PathProblem`.

    Symbolic links are followed; what they point to must be a regular file.
    """
    text = os.fspath(path)
    problem = name_problem(text)
    if problem:
        raise PathProblem(problem)
    try:
        info = os.stat(text)
    except OSError as exc:
        raise PathProblem(f"cannot open {text} ({exc.strerror or exc})") from None
    if stat.S_ISDIR(info.st_mode):
        raise PathProblem(f"{text} is a folder, expected a file")
    if not stat.S_ISREG(info.st_mode):
        raise PathProblem(f"{text} is not a regular file (a device, FIFO or socket)")
    if info.st_size > max_bytes:
        raise PathProblem(f"{text} has {info.st_size} bytes, more than the {max_bytes} accepted")
    if not os.access(text, os.R_OK):
        raise PathProblem(f"{text} is not readable")
    return Path(text)


def check_output_folder(folder: str | Path, needed_bytes: int = 0) -> Path:
    """Create ``folder`` (and its parents) if needed and probe it with a file; return it.

    Parameters
    ----------
    needed_bytes : int
        Free space the folder's file system must have [bytes].

    Raises
    ------
    PathProblem
        A name that is too long, a part of the path that is a file, a folder
        that cannot be created or written, or too little free space.
    """
    text = os.fspath(folder)
    problem = name_problem(text)
    if problem:
        raise PathProblem(problem)
    folder = Path(text)
    for part in [folder, *folder.parents]:
        if part.exists() and not part.is_dir():
            raise PathProblem(f"{part} exists and is not a folder")
    try:
        folder.mkdir(parents=True, exist_ok=True)
        probe = folder / temporary_name("write-probe", "")
        with open(probe, "wb") as handle:
            handle.write(b"oceanrender")
        probe.unlink()
    except OSError as exc:
        raise PathProblem(f"cannot write into {folder} ({exc.strerror or exc})") from None
    free = shutil.disk_usage(folder).free
    if free < needed_bytes:
        raise PathProblem(f"{folder} has {free / 2**20:.1f} MiB free, the run needs at least "
                          f"{needed_bytes / 2**20:.1f} MiB")
    return folder


def absolute(path: str | Path) -> Path:
    """``path`` made absolute against the working folder, literally: no ``~``, ``$VAR`` or glob expansion.

    The one form of an output path handed to every writer, so that no library
    (imageio expands a leading ``~``) can send a file elsewhere.
    """
    return Path(os.path.abspath(os.fspath(path)))


def check_inside(path: str | Path, root: str | Path) -> Path:
    """``path`` resolved, if it lies inside ``root`` (resolved); else :class:`PathProblem`.

    Both are taken literally (:func:`absolute`); a name the file system cannot
    hold (a NUL byte, over-long) is a :class:`PathProblem` too.
    """
    for text in (os.fspath(path), os.fspath(root)):
        problem = name_problem(text)
        if problem:
            raise PathProblem(problem)
    resolved, base = absolute(path).resolve(), absolute(root).resolve()
    if resolved != base and base not in resolved.parents:
        raise PathProblem(f"{path} resolves to {resolved}, outside {base}")
    return resolved


def _owner() -> str:
    host = "".join(c if c.isalnum() else "_" for c in socket.gethostname())[:40] or "host"
    return f"{host}-{os.getpid()}"


def temporary_name(stem: str, suffix: str) -> str:
    """A hidden temporary file name for ``stem`` owned by this host and process: ``.stem.tmp-HOST-PID-RAND suffix``."""
    return f".{stem}{TEMPORARY_MARK}{_owner()}-{secrets.token_hex(4)}{suffix}"


def _pid_running(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:  # another account's live process
        return True
    return True


def is_stale_temporary(path: Path) -> bool:
    """Whether ``path`` is one of our temporaries whose process, on this host, has ended."""
    name = path.name
    if not name.startswith(".") or TEMPORARY_MARK not in name:
        return False
    owner = name.split(TEMPORARY_MARK, 1)[1]
    host, _, rest = owner.rpartition("-")  # rest: RAND(+suffix); host: HOST-PID
    host, _, pid = host.rpartition("-")
    if host != _owner().rpartition("-")[0] or not pid.isdigit():
        return False  # another machine's file (a shared folder): its owner cleans it
    return int(pid) != os.getpid() and not _pid_running(int(pid))


def remove_stale_temporaries(folder: str | Path) -> list[Path]:
    """Delete the temporaries in ``folder`` left by ended processes of this host; the paths removed."""
    folder = Path(folder)
    if not folder.is_dir():
        return []
    stale = sorted(path for path in folder.iterdir() if is_stale_temporary(path))
    for path in stale:
        path.unlink(missing_ok=True)
    return stale


def umask_mode(base: int = 0o666) -> int:
    """``base`` with the process's umask applied: the mode ``open()`` would give a new file.

    The umask is read from ``/proc/self/status`` (Linux ≥ 4.7), which leaves it
    untouched; elsewhere it is set and restored at once (a brief window in which
    another thread's new files would get mode ``base``).
    """
    try:
        with open("/proc/self/status", encoding="ascii") as handle:
            for line in handle:
                if line.startswith("Umask:"):
                    return base & ~int(line.split()[1], 8)
    except (OSError, ValueError):
        pass
    mask = os.umask(0)
    os.umask(mask)
    return base & ~mask


def is_disk_full(exc: OSError) -> bool:
    """Whether an OSError means the file system is full (ENOSPC, EDQUOT)."""
    return exc.errno in (errno.ENOSPC, errno.EDQUOT)
