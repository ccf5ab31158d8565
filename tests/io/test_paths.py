"""Input files that cannot hurt, output folders that work, temporaries of our own, the umask."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from oceanrender.io import paths
from oceanrender.io.paths import PathProblem


def test_a_regular_file_within_the_limit_is_accepted(tmp_path):
    path = tmp_path / "table.csv"
    path.write_bytes(b"x" * 100)
    assert paths.check_input_file(path, 100) == path


@pytest.mark.parametrize(
    "make, message",
    [
        (lambda d: "/dev/zero", "not a regular file"),
        (lambda d: (os.mkfifo(d / "fifo"), d / "fifo")[1], "not a regular file"),
        (lambda d: d, "is a folder"),
        (lambda d: d / "missing.csv", "No such file or directory"),
        (lambda d: str(d / "a\x00b"), "NUL byte"),
        (lambda d: d / ("n" * 300), "longer than 255 bytes"),
        (lambda d: ((d / "big").write_bytes(b"x" * 101), d / "big")[1], "has 101 bytes, more than the 100 accepted"),
    ],
)
def test_files_that_could_hang_or_exhaust_a_reader_are_refused(tmp_path, make, message):
    with pytest.raises(PathProblem, match=message) as info:
        paths.check_input_file(make(tmp_path), 100)
    assert "\n" not in str(info.value)


def test_an_output_folder_is_created_and_probed(tmp_path):
    folder = paths.check_output_folder(tmp_path / "a" / "b", needed_bytes=1)
    assert folder.is_dir() and list(folder.iterdir()) == []  # the probe is gone


@pytest.mark.parametrize(
    "make, message",
    [
        (lambda d: ((d / "file").write_text("x"), d / "file")[1], "exists and is not a folder"),
        (lambda d: ((d / "file").write_text("x"), d / "file" / "sub")[1], "exists and is not a folder"),
        (lambda d: Path("/dev/null"), "exists and is not a folder"),
        (lambda d: Path("/proc/oceanrender-out"), "cannot write into"),  # read-only even for root
        (lambda d: d / ("n" * 300), "longer than 255 bytes"),
    ],
)
def test_unusable_output_folders_are_refused(tmp_path, make, message):
    with pytest.raises(PathProblem, match=message):
        paths.check_output_folder(make(tmp_path))


def test_an_output_folder_without_room_is_refused(tmp_path):
    free = __import__("shutil").disk_usage(tmp_path).free
    with pytest.raises(PathProblem, match="MiB free, the run needs at least"):
        paths.check_output_folder(tmp_path, needed_bytes=free * 2)


def test_check_inside_refuses_what_resolves_outside(tmp_path):
    (tmp_path / "root").mkdir()
    (tmp_path / "root" / "link").symlink_to(tmp_path)
    assert paths.check_inside(tmp_path / "root" / "scene", tmp_path / "root") == (tmp_path / "root" / "scene")
    for escape in ("..", "link", "a/../../b"):
        with pytest.raises(PathProblem, match="outside"):
            paths.check_inside(tmp_path / "root" / escape, tmp_path / "root")


def test_temporary_names_are_unique_and_carry_their_owner():
    names = {paths.temporary_name("frame_0001", ".exr") for _ in range(1000)}
    assert len(names) == 1000
    name = next(iter(names))
    assert name.startswith(".frame_0001.tmp-") and name.endswith(".exr") and f"-{os.getpid()}-" in name


def test_clean_up_removes_only_temporaries_of_ended_processes(tmp_path):
    ended = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"], capture_output=True, text=True)
    dead_pid = int(ended.stdout)
    mine = tmp_path / paths.temporary_name("frame_0000", ".exr")
    alive_other = tmp_path / mine.name.replace(f"-{os.getpid()}-", f"-{os.getppid()}-")  # a live process
    dead = tmp_path / mine.name.replace(f"-{os.getpid()}-", f"-{dead_pid}-")
    foreign = tmp_path / ".frame_0000.tmp-otherhost-1-abcd.exr"  # another machine's, on a shared folder
    user_file = tmp_path / "frame_0000.exr"
    for path in (mine, alive_other, dead, foreign, user_file):
        path.write_bytes(b"x")
    assert paths.remove_stale_temporaries(tmp_path) == [dead]
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(p.name for p in (mine, alive_other, foreign, user_file))


@pytest.mark.parametrize("mask, mode", [(0o022, 0o644), (0o077, 0o600), (0o002, 0o664)])
def test_umask_mode_is_what_open_gives(tmp_path, mask, mode):
    old = os.umask(mask)
    try:
        assert paths.umask_mode() == mode
        (tmp_path / "f").write_bytes(b"")
        assert (tmp_path / "f").stat().st_mode & 0o777 == mode
    finally:
        os.umask(old)


def test_check_inside_takes_paths_literally_and_names_unusable_ones(tmp_path, monkeypatch):
    """'~' is a folder name, not $HOME; a NUL byte is a PathProblem, not numpy's or os's ValueError (issue 39)."""
    from oceanrender.io.paths import PathProblem, absolute, check_inside

    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("HOME", str(tmp_path / "home"))
    assert absolute("~/x/$HOME") == tmp_path / "~" / "x" / "$HOME"
    assert check_inside("~/tilde/scene", "~/tilde") == tmp_path / "~" / "tilde" / "scene"
    with pytest.raises(PathProblem, match="NUL"):
        check_inside("a\x00b/scene", "a\x00b")
