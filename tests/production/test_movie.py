"""Movies and contact sheets from a sequence folder: frame count, size, colour, gaps refused, atomic writes."""

import imageio.v3 as iio
import numpy as np
import pytest

from oceanrender.production.movie import (
    SequenceError,
    evenly_spaced,
    find_frames,
    pad_to_even,
    sheet_layout,
    write_contact_sheet,
    write_movie,
)


def write_sequence(folder, numbers, size=(33, 21)):
    """Frames with a left-to-right ramp and a per-frame brightness, so frames differ."""
    folder.mkdir(parents=True, exist_ok=True)
    width, height = size
    for n in numbers:
        image = np.zeros((height, width, 3), np.uint8)
        image[..., 0] = np.linspace(20, 230, width, dtype=np.uint8)[None, :]
        image[..., 1] = 30 + 15 * (n % 10)
        image[..., 2] = 120
        iio.imwrite(folder / f"frame_{n:04d}.png", image)
    return folder


def test_movie_has_every_frame_at_even_size(tmp_path):
    frames = write_sequence(tmp_path / "seq", range(3, 10))
    report = write_movie(frames, tmp_path / "out" / "seq.mp4", fps=12.0)
    assert report.frames == 7 and report.first_frame == 3
    assert report.size == (34, 22) and report.padded
    assert report.duration == pytest.approx(7 / 12)
    decoded = list(iio.imiter(report.path, plugin="FFMPEG"))
    assert len(decoded) == 7
    assert decoded[0].shape == (22, 34, 3)
    meta = iio.immeta(report.path, plugin="FFMPEG")
    assert meta["fps"] == pytest.approx(12.0)
    assert meta["codec"] == "h264"
    # Colours survive the BT.709 Y'CbCr round trip within a few 8-bit levels (flat regions).
    original = iio.imread(frames / "frame_0005.png")
    assert np.abs(decoded[2][5:15, 5:30].astype(int) - original[5:15, 5:30]).mean() < 4


def test_movie_of_even_frames_is_not_padded(tmp_path):
    frames = write_sequence(tmp_path / "seq", range(2), size=(32, 18))
    report = write_movie(frames, tmp_path / "a.mp4", fps=24)
    assert report.size == (32, 18) and not report.padded


def test_gap_in_numbering_is_refused_naming_folder_and_frame(tmp_path):
    frames = write_sequence(tmp_path / "seq", [0, 1, 2, 4, 5, 7])
    with pytest.raises(SequenceError) as info:
        write_movie(frames, tmp_path / "a.mp4", fps=24)
    message = str(info.value)
    assert str(frames) in message and "frame_0003.png is missing" in message and "\n" not in message
    assert not (tmp_path / "a.mp4").exists()
    assert list(tmp_path.glob(".*")) == []  # no temporary left behind


def test_expected_range_must_be_complete(tmp_path):
    frames = write_sequence(tmp_path / "seq", range(0, 4))
    assert find_frames(frames, expected=(1, 3)).numbers == (1, 2)
    with pytest.raises(SequenceError, match="frame_0004.png is missing"):
        find_frames(frames, expected=(0, 6))


def test_empty_or_missing_folder_is_refused(tmp_path):
    (tmp_path / "empty").mkdir()
    (tmp_path / "empty" / "frame_0000.exr").write_bytes(b"")  # only PNGs count
    with pytest.raises(SequenceError, match="no frame_NNNN.png"):
        write_movie(tmp_path / "empty", tmp_path / "a.mp4", fps=24)
    with pytest.raises(SequenceError, match="not a folder"):
        write_contact_sheet(tmp_path / "nowhere", tmp_path / "s.png")


def test_frames_of_different_sizes_are_refused(tmp_path):
    frames = write_sequence(tmp_path / "seq", range(2))
    write_sequence(frames, [2], size=(40, 21))
    with pytest.raises(SequenceError, match="frame_0002.png: 40x21"):
        write_movie(frames, tmp_path / "a.mp4", fps=24)
    assert not (tmp_path / "a.mp4").exists()


def test_bad_fps_is_refused(tmp_path):
    frames = write_sequence(tmp_path / "seq", range(2))
    for fps in (0.0, -1.0, float("nan")):
        with pytest.raises(ValueError, match="fps"):
            write_movie(frames, tmp_path / "a.mp4", fps=fps)


def test_contact_sheet_size_and_labels(tmp_path):
    frames = write_sequence(tmp_path / "seq", range(10, 17), size=(64, 36))
    report = write_contact_sheet(frames, tmp_path / "sheet.png", columns=3, thumb_width=40, margin=4, label_height=14)
    # 7 frames in 3 columns: 3 rows; thumbnails 40 × round(40·36/64) = 40 × 22.
    assert report.layout.thumb == (40, 22)
    expected = (3 * 40 + 4 * 4, 3 * (22 + 14) + 4 * 4)
    assert report.size == expected
    sheet = iio.imread(tmp_path / "sheet.png")
    assert sheet.shape == (expected[1], expected[0], 3)
    assert report.frames == tuple(range(10, 17))
    # the label strip under the first thumbnail has light text pixels on the dark background
    x, y = report.layout.origin(0)
    strip = sheet[y + 22:y + 22 + 14, x:x + 40]
    assert strip.max() > 150 and np.median(strip) < 60
    # the first thumbnail is the first frame, downscaled (ramp left to right)
    thumb = sheet[y:y + 22, x:x + 40, 0].astype(int)
    assert thumb[:, -3:].mean() > thumb[:, :3].mean() + 100


def test_contact_sheet_samples_long_sequences_evenly(tmp_path):
    frames = write_sequence(tmp_path / "seq", range(20), size=(16, 10))
    report = write_contact_sheet(frames, tmp_path / "sheet.png", columns=4, thumb_width=16, max_frames=5)
    assert report.frames == (0, 5, 10, 14, 19)  # first and last included
    assert report.layout.rows == 2


def test_helpers():
    assert evenly_spaced(3, 10) == [0, 1, 2]
    assert evenly_spaced(101, 3) == [0, 50, 100]
    assert pad_to_even(np.zeros((3, 5, 3))).shape == (4, 6, 3)
    assert pad_to_even(np.zeros((4, 6, 3))).shape == (4, 6, 3)
    assert sheet_layout(2, (100, 50), columns=6, thumb_width=10).columns == 2
    with pytest.raises(ValueError):
        sheet_layout(0, (100, 50))
