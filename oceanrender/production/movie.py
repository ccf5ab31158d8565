"""Movies and contact sheets from a finished frame sequence.

A sequence folder (``<out>/<scene>/``, written by ``oceanrender render``)
holds ``frame_NNNN.png`` files (8-bit sRGB after the vision model). This
module turns them into

* an H.264 MP4 (``yuv420p``, even dimensions, the scene's frame rate) through
  imageio's FFMPEG plugin, which drives the ffmpeg binary shipped inside the
  ``imageio-ffmpeg`` wheel, and
* a contact sheet: one PNG with a grid of downscaled frames, each labelled
  with its frame number.

Both are written to a temporary name in the target folder and renamed into
place, so a killed run never leaves a half-written movie under its final
name. A folder with no frames, or with a gap in the numbering, is refused
before anything is written, with one line naming the folder and the first
missing frame.
"""

from __future__ import annotations

import math
import re
import time
from dataclasses import dataclass
from pathlib import Path

import imageio.v3 as iio
import numpy as np

from ..io.frames import atomic_path

#: File names of sequence frames: ``frame_`` + at least four digits + ``.png``.
FRAME_PATTERN = re.compile(r"^frame_(\d{4,})\.png$")

#: Constant rate factor of libx264 [-]: 0 lossless … 51 worst; 18 is "visually lossless"
#: in x264's documentation, and the frames are already 8-bit.
DEFAULT_CRF = 18

#: ffmpeg output options: BT.709 Y'CbCr matrix, limited ("tv") range, tagged as sRGB (IEC 61966-2-1)
#: so players decode the colours the PNGs hold; ``+faststart`` puts the index first (streamable).
COLOUR_OPTIONS = (
    "-vf", "scale=out_color_matrix=bt709:out_range=tv",
    "-colorspace", "bt709", "-color_primaries", "bt709", "-color_trc", "iec61966-2-1", "-color_range", "tv",
    "-movflags", "+faststart",
)


class SequenceError(ValueError):
    """A sequence folder that cannot become a movie; the message is one line for the user."""


@dataclass(frozen=True)
class FrameSequence:
    """The numbered PNG frames of a sequence folder, in order, without gaps.

    Attributes
    ----------
    folder : Path            The sequence folder.
    numbers : tuple of int   Frame numbers, consecutive and increasing.
    paths : tuple of Path    ``frame_NNNN.png`` of each number.
    """

    folder: Path
    numbers: tuple[int, ...]
    paths: tuple[Path, ...]

    def __len__(self) -> int:
        return len(self.numbers)


def find_frames(frames_dir: str | Path, expected: tuple[int, int] | None = None) -> FrameSequence:
    """The ``frame_NNNN.png`` files of a sequence folder, checked for gaps.

    Parameters
    ----------
    frames_dir : str or Path
        The sequence folder.
    expected : (int, int), optional
        Half-open frame range [start, end) that must be complete (the scene's
        ``[output] frames``). Without it, the frames found must run from the
        lowest to the highest number without a gap.

    Returns
    -------
    FrameSequence

    Raises
    ------
    SequenceError
        The folder does not exist or holds no frames, or a frame is missing
        (the message names the folder and the first missing frame).
    """
    folder = Path(frames_dir)
    if not folder.is_dir():
        raise SequenceError(f"{folder}: not a folder")
    found = {int(m.group(1)): folder / m.group(0)
             for m in (FRAME_PATTERN.match(p.name) for p in folder.iterdir()) if m}
    if expected is not None:
        start, end = expected
        if end <= start:
            raise SequenceError(f"{folder}: empty frame range [{start}, {end})")
        numbers = range(start, end)
    else:
        if not found:
            raise SequenceError(f"{folder}: no frame_NNNN.png files")
        numbers = range(min(found), max(found) + 1)
    missing = [n for n in numbers if n not in found]
    if missing:
        span = f"frames {numbers[0]:04d}-{numbers[-1]:04d}"
        more = f" and {len(missing) - 1} more" if len(missing) > 1 else ""
        raise SequenceError(f"{folder}: frame_{missing[0]:04d}.png is missing{more} ({span})")
    return FrameSequence(folder=folder, numbers=tuple(numbers), paths=tuple(found[n] for n in numbers))


def read_frame(path: Path) -> np.ndarray:
    """An (H, W, 3) uint8 RGB frame (grey is expanded, alpha dropped)."""
    image = np.asarray(iio.imread(path, plugin="pillow"))
    if image.dtype != np.uint8:
        raise SequenceError(f"{path}: expected an 8-bit PNG, got {image.dtype}")
    if image.ndim == 2:
        image = np.repeat(image[..., None], 3, axis=-1)
    return np.ascontiguousarray(image[..., :3])


def pad_to_even(image: np.ndarray) -> np.ndarray:
    """Pad an (H, W, C) image by one replicated row/column where H or W is odd.

    ``yuv420p`` stores chroma at half resolution in both directions, so
    H.264 in that format needs even dimensions. Padding (rather than
    scaling) keeps every rendered pixel unresampled.
    """
    height, width = image.shape[:2]
    return np.pad(image, ((0, height % 2), (0, width % 2), (0, 0)), mode="edge")


@dataclass(frozen=True)
class MovieReport:
    """What :func:`write_movie` wrote.

    Attributes
    ----------
    path : Path                  The MP4.
    frames : int                 Frames in the movie [-].
    first_frame : int            Number of its first frame [-].
    fps : float                  Frame rate [s⁻¹].
    size : (int, int)            Video (width, height) [px], even.
    padded : bool                Whether the frames were padded to even size.
    duration : float             frames / fps [s].
    seconds : float              Wall time of the encoding [s].
    """

    path: Path
    frames: int
    first_frame: int
    fps: float
    size: tuple[int, int]
    padded: bool
    duration: float
    seconds: float


def write_movie(frames_dir: str | Path, out_path: str | Path, fps: float, expected: tuple[int, int] | None = None,
                crf: int = DEFAULT_CRF) -> MovieReport:
    """Encode a sequence folder's PNG frames as an H.264 MP4, atomically.

    Parameters
    ----------
    frames_dir : str or Path
        Sequence folder with ``frame_NNNN.png`` files.
    out_path : str or Path
        The MP4 to write (its folder is created).
    fps : float
        Frame rate [s⁻¹]: the scene's ``[output] fps``.
    expected : (int, int), optional
        Frame range [start, end) that must be complete (see :func:`find_frames`).
    crf : int
        libx264 constant rate factor, 0 (lossless) to 51 [-].

    Returns
    -------
    MovieReport

    Raises
    ------
    SequenceError
        No frames, a missing frame, or frames of different sizes.
    ValueError
        ``fps`` not positive or ``crf`` out of range.
    """
    if not (math.isfinite(fps) and fps > 0):
        raise ValueError(f"fps must be a positive number [s⁻¹], got {fps}")
    if not 0 <= crf <= 51:
        raise ValueError(f"crf must be in [0, 51], got {crf}")
    sequence = find_frames(frames_dir, expected)
    first = read_frame(sequence.paths[0])
    height, width = first.shape[:2]
    tic = time.perf_counter()
    import imageio.v2 as iio2  # noqa: PLC0415 (the FFMPEG plugin lives in the v2 API)

    with atomic_path(out_path, ".mp4") as tmp:
        writer = iio2.get_writer(
            tmp, format="FFMPEG", mode="I", fps=float(fps), codec="libx264", pixelformat="yuv420p",
            quality=None, macro_block_size=2, ffmpeg_log_level="error",
            output_params=["-crf", str(int(crf)), *COLOUR_OPTIONS],
        )
        try:
            for path in sequence.paths:
                frame = first if path == sequence.paths[0] else read_frame(path)
                if frame.shape[:2] != (height, width):
                    raise SequenceError(f"{path}: {frame.shape[1]}x{frame.shape[0]} px, but the sequence is "
                                        f"{width}x{height} px")
                writer.append_data(pad_to_even(frame))
        finally:
            writer.close()
    return MovieReport(path=Path(out_path), frames=len(sequence), first_frame=sequence.numbers[0], fps=float(fps),
                       size=(width + width % 2, height + height % 2), padded=bool(width % 2 or height % 2),
                       duration=len(sequence) / float(fps), seconds=time.perf_counter() - tic)


@dataclass(frozen=True)
class SheetLayout:
    """Geometry of a contact sheet [px].

    Thumbnails of ``thumb`` = (width, height) sit on a grid of ``columns`` ×
    ``rows`` cells; each cell is the thumbnail plus a label strip of
    ``label_height`` below it, and cells are separated (and surrounded) by
    ``margin``. So the sheet is
    ``columns·thumb_w + (columns + 1)·margin`` wide and
    ``rows·(thumb_h + label_height) + (rows + 1)·margin`` high.
    """

    columns: int
    rows: int
    thumb: tuple[int, int]
    label_height: int
    margin: int

    @property
    def size(self) -> tuple[int, int]:
        """Sheet (width, height) [px]."""
        width = self.columns * self.thumb[0] + (self.columns + 1) * self.margin
        height = self.rows * (self.thumb[1] + self.label_height) + (self.rows + 1) * self.margin
        return width, height

    def origin(self, index: int) -> tuple[int, int]:
        """Top-left (x, y) [px] of the ``index``-th thumbnail (row-major)."""
        row, column = divmod(index, self.columns)
        return (self.margin + column * (self.thumb[0] + self.margin),
                self.margin + row * (self.thumb[1] + self.label_height + self.margin))


def sheet_layout(count: int, frame_size: tuple[int, int], columns: int = 6, thumb_width: int = 160,
                 margin: int = 4, label_height: int = 16) -> SheetLayout:
    """Layout of a contact sheet of ``count`` frames of ``frame_size`` = (W, H) [px].

    The thumbnail keeps the frame's aspect ratio: height = round(thumb_width·H/W),
    at least 1 px. ``columns`` is reduced to ``count`` when there are fewer frames.
    """
    if count < 1 or columns < 1 or thumb_width < 1 or margin < 0 or label_height < 0:
        raise ValueError(f"need count, columns, thumb_width ≥ 1 and margin, label_height ≥ 0; got {count}, "
                         f"{columns}, {thumb_width}, {margin}, {label_height}")
    width, height = frame_size
    columns = min(columns, count)
    thumb = (int(thumb_width), max(1, round(thumb_width * height / width)))
    return SheetLayout(columns=columns, rows=math.ceil(count / columns), thumb=thumb,
                       label_height=int(label_height), margin=int(margin))


def evenly_spaced(count: int, limit: int | None) -> list[int]:
    """Indices of at most ``limit`` of ``count`` items, evenly spaced, first and last included."""
    if limit is None or count <= limit:
        return list(range(count))
    if limit < 2:
        return [0]
    return sorted({round(i * (count - 1) / (limit - 1)) for i in range(limit)})


@dataclass(frozen=True)
class ContactSheetReport:
    """What :func:`write_contact_sheet` wrote: the PNG, its layout, which frame numbers it shows."""

    path: Path
    layout: SheetLayout
    frames: tuple[int, ...]

    @property
    def size(self) -> tuple[int, int]:
        """Sheet (width, height) [px]."""
        return self.layout.size


def write_contact_sheet(frames_dir: str | Path, out_path: str | Path, columns: int = 6, thumb_width: int = 160,
                        max_frames: int | None = 48, expected: tuple[int, int] | None = None,
                        margin: int = 4, label_height: int = 16,
                        background: tuple[int, int, int] = (24, 24, 24)) -> ContactSheetReport:
    """A PNG grid of downscaled frames labelled with their numbers, written atomically.

    Parameters
    ----------
    frames_dir : str or Path
        Sequence folder with ``frame_NNNN.png`` files.
    out_path : str or Path
        The PNG to write.
    columns : int
        Thumbnails per row [-].
    thumb_width : int
        Width of each thumbnail [px]; the height keeps the frames' aspect ratio.
    max_frames : int or None
        At most this many frames, evenly spaced over the sequence with the
        first and the last included; None shows every frame.
    expected : (int, int), optional
        Frame range [start, end) that must be complete (see :func:`find_frames`).
    margin, label_height : int
        Gap between cells and height of the label strip [px] (see :class:`SheetLayout`).
    background : (int, int, int)
        8-bit sRGB colour of the sheet.

    Returns
    -------
    ContactSheetReport
    """
    from PIL import Image, ImageDraw, ImageFont  # noqa: PLC0415

    sequence = find_frames(frames_dir, expected)
    chosen = evenly_spaced(len(sequence), max_frames)
    first = read_frame(sequence.paths[chosen[0]])
    layout = sheet_layout(len(chosen), (first.shape[1], first.shape[0]), columns, thumb_width, margin, label_height)
    sheet = Image.new("RGB", layout.size, tuple(background))
    draw = ImageDraw.Draw(sheet)
    font = ImageFont.load_default(size=max(8, label_height - 4)) if label_height else None
    for slot, index in enumerate(chosen):
        frame = first if slot == 0 else read_frame(sequence.paths[index])
        # NOTE: Lanczos on 8-bit sRGB values (not linear light): a preview, not a measurement.
        thumb = Image.fromarray(frame).resize(layout.thumb, Image.Resampling.LANCZOS)
        x, y = layout.origin(slot)
        sheet.paste(thumb, (x, y))
        if font is not None:
            draw.text((x + 2, y + layout.thumb[1] + 1), f"{sequence.numbers[index]:04d}", fill=(230, 230, 230),
                      font=font)
    with atomic_path(out_path, ".png") as tmp:
        sheet.save(tmp, format="PNG")
    return ContactSheetReport(path=Path(out_path), layout=layout,
                              frames=tuple(sequence.numbers[i] for i in chosen))
