"""Frame files: atomic EXR and PNG writing, reading back, resume checks.

Every file is written to a temporary name in the same folder and renamed
into place (``os.replace`` is atomic on POSIX), so a killed run never leaves
a half-written frame under a final name. The temporary name carries this host
and process (:func:`oceanrender.io.paths.temporary_name`), so a second run on
the same folder never takes it for a leftover, and the file gets the mode the
umask gives (not ``mkstemp``'s 0600), so a shared output folder stays readable.
"""

from __future__ import annotations

import os
from contextlib import contextmanager
from pathlib import Path
from typing import Iterator, Mapping

import imageio.v3 as iio
import numpy as np
import OpenEXR

from .paths import absolute, temporary_name, umask_mode

#: Channels of every frame EXR, in order: absolute CIE 1931 XYZ [cd m⁻² for Y]
#: and linear display sRGB after the vision model [display-relative, 1 = white].
FRAME_CHANNELS = ("X", "Y", "Z", "R", "G", "B")


@contextmanager
def atomic_path(path: str | Path, suffix: str) -> Iterator[Path]:
    """Yield a temporary path next to ``path``; rename it onto ``path`` on success.

    Both are absolute (:func:`~oceanrender.io.paths.absolute`: no ``~`` or ``$VAR`` expansion), so a
    writer that interprets names cannot put the file anywhere else.
    """
    path = absolute(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp_path = path.parent / temporary_name(path.stem, suffix)
    os.close(os.open(tmp_path, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600))
    try:
        yield tmp_path
        os.chmod(tmp_path, umask_mode())
        os.replace(tmp_path, path)
    finally:
        if tmp_path.exists():
            tmp_path.unlink()


def _header_value(value: object) -> object:
    if isinstance(value, (bool, np.bool_)):
        return str(bool(value)).lower()
    if isinstance(value, (int, np.integer)):
        return int(value)
    if isinstance(value, (float, np.floating)):
        return float(value)
    return str(value)


def write_exr(path: str | Path, channels: Mapping[str, np.ndarray], metadata: Mapping[str, object] | None = None) -> None:
    """Write float32 channels (each (H, W)) and string/number metadata atomically.

    Metadata keys are stored as EXR header attributes prefixed ``oceanrender:``.
    """
    header = {"compression": OpenEXR.ZIP_COMPRESSION, "type": OpenEXR.scanlineimage}
    for key, value in (metadata or {}).items():
        header[f"oceanrender:{key}"] = _header_value(value)
    data = {name: np.ascontiguousarray(array, dtype=np.float32) for name, array in channels.items()}
    with atomic_path(path, ".exr") as tmp, OpenEXR.File(header, data) as exr:
        exr.write(str(tmp))


def read_exr(path: str | Path) -> tuple[dict[str, np.ndarray], dict[str, object]]:
    """Read an EXR: (channels by name, oceanrender metadata without prefix)."""
    with OpenEXR.File(str(path), separate_channels=True) as exr:
        # NOTE: the header dict is emptied when the file closes: copy what we need inside.
        metadata = {key.split(":", 1)[1]: value for key, value in exr.header().items() if key.startswith("oceanrender:")}
        channels = {name: np.array(channel.pixels) for name, channel in exr.channels().items()}
    return channels, metadata


def write_png(path: str | Path, rgb8: np.ndarray) -> None:
    """Write an (H, W, 3) uint8 image as PNG, atomically."""
    if rgb8.dtype != np.uint8:
        raise TypeError(f"PNG frames are 8-bit: expected uint8, got {rgb8.dtype}")
    # NOTE: imageio expands a leading '~' of a path it is given (its Request): it writes into the handle of the
    # exact file made here instead, so no library reinterprets the name.
    with atomic_path(path, ".png") as tmp, open(tmp, "wb") as handle:
        iio.imwrite(handle, rgb8, extension=".png")


def frame_is_complete(exr_path: str | Path, png_path: str | Path, size: tuple[int, int],
                      extra_channels: tuple[str, ...] = ()) -> bool:
    """Whether a frame's EXR and PNG both exist and read back intact at ``size``.

    Parameters
    ----------
    size : (int, int)
        Expected (width, height) [pixels].
    extra_channels : tuple of str
        Channels the EXR must also hold (the scene's render passes).
    """
    width, height = size
    if not (Path(exr_path).is_file() and Path(png_path).is_file()):
        return False
    try:
        channels, _ = read_exr(exr_path)
        with open(png_path, "rb") as handle:  # a handle, not a name imageio would expand ('~')
            image = iio.imread(handle, plugin="pillow", extension=".png")
    except Exception:  # noqa: BLE001 (any unreadable file means: render again)
        return False
    needed = (*FRAME_CHANNELS, *extra_channels)
    if any(name not in channels for name in needed):
        return False
    if any(channels[name].shape != (height, width) for name in needed):
        return False
    return image.shape[:2] == (height, width)
