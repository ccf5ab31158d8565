"""Frame files: atomic writes, round trips and the resume check."""

import os

import numpy as np
import pytest

from oceanrender.io.frames import FRAME_CHANNELS, atomic_path, frame_is_complete, read_exr, write_exr, write_png


def frame_channels(rng, width=6, height=4):
    return {name: rng.random((height, width)).astype(np.float32) for name in FRAME_CHANNELS}


def test_exr_round_trip_with_metadata(tmp_path, rng):
    channels = frame_channels(rng)
    path = tmp_path / "f.exr"
    write_exr(path, channels, {"scene": "s", "frame": 7, "time_s": 0.25, "flag": True})
    back, meta = read_exr(path)
    for name in FRAME_CHANNELS:
        np.testing.assert_array_equal(back[name], channels[name])  # exact: a float32 file round trip
    assert meta == {"scene": "s", "frame": 7, "time_s": 0.25, "flag": "true"}


def test_atomic_write_leaves_nothing_on_failure(tmp_path):
    target = tmp_path / "out.exr"
    with pytest.raises(RuntimeError):
        with atomic_path(target, ".exr") as tmp:
            tmp.write_bytes(b"partial")
            raise RuntimeError("killed mid-write")
    assert list(tmp_path.iterdir()) == []


def test_frame_complete_only_when_both_files_read_back(tmp_path, rng):
    exr, png = tmp_path / "frame_0000.exr", tmp_path / "frame_0000.png"
    assert not frame_is_complete(exr, png, (6, 4))
    write_exr(exr, frame_channels(rng))
    assert not frame_is_complete(exr, png, (6, 4))
    write_png(png, (rng.random((4, 6, 3)) * 255).astype(np.uint8))
    assert frame_is_complete(exr, png, (6, 4))
    assert not frame_is_complete(exr, png, (6, 4), ("depth.Z",)), "a frame without a pass it asks for is redone"
    write_exr(exr, {**frame_channels(rng), "depth.Z": rng.random((4, 6))})
    write_png(png, (rng.random((4, 6, 3)) * 255).astype(np.uint8))
    assert frame_is_complete(exr, png, (6, 4), ("depth.Z",))
    assert not frame_is_complete(exr, png, (8, 4)), "wrong size must not count as done"
    exr.write_bytes(exr.read_bytes()[:40])  # a truncated file, as after a crash
    assert not frame_is_complete(exr, png, (6, 4))


def test_png_must_be_8_bit(tmp_path):
    with pytest.raises(TypeError, match="uint8"):
        write_png(tmp_path / "x.png", np.zeros((2, 2, 3), dtype=np.float32))


@pytest.mark.parametrize("mask, mode", [(0o022, 0o644), (0o027, 0o640)])
def test_frames_honour_the_umask(tmp_path, mask, mode):
    """Atomic writes go through a private temporary; the final file still gets the umask's mode."""
    old = os.umask(mask)
    try:
        write_png(tmp_path / "f.png", np.zeros((2, 3, 3), np.uint8))
        write_exr(tmp_path / "f.exr", {name: np.zeros((2, 3), np.float32) for name in FRAME_CHANNELS})
    finally:
        os.umask(old)
    assert {p.name: p.stat().st_mode & 0o777 for p in tmp_path.iterdir()} == {"f.png": mode, "f.exr": mode}


def test_frames_go_exactly_where_they_are_named_whatever_the_name(tmp_path, monkeypatch):
    """A relative '~/…' is a folder of the working folder for every writer: imageio would expand it (issue 39)."""
    home = tmp_path / "home"
    home.mkdir()
    monkeypatch.setenv("HOME", str(home))
    monkeypatch.chdir(tmp_path)
    rgb8 = np.full((4, 6, 3), 200, np.uint8)
    write_png("~/tilde/frame_0000.png", rgb8)
    write_exr("~/tilde/frame_0000.exr", {name: np.ones((4, 6), np.float32) for name in FRAME_CHANNELS})
    written = tmp_path / "~" / "tilde"
    assert sorted(p.name for p in written.iterdir()) == ["frame_0000.exr", "frame_0000.png"]
    assert (written / "frame_0000.png").stat().st_size > 0 and list(home.iterdir()) == []
    assert frame_is_complete("~/tilde/frame_0000.exr", "~/tilde/frame_0000.png", (6, 4))
