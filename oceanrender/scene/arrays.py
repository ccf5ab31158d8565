"""The arrays a scene names or defines: bathymetry, initial water surface, seafloor cover.

A ``[coastal]`` section gives its bed and initial surface as analytic shapes (a
plane beach, the still level) or as array files (``.npy`` or EXR); the files are
read and checked here when the scene is loaded (:func:`check_coastal_inputs`),
before any work starts, and every later stage builds the same arrays from the
same settings.

Conventions: arrays (ny, nx), rows south → north, columns west → east; cell
(j, i) centred at origin + ((i + ½) dx, (j + ½) dy); lengths in m.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
from numpy.typing import NDArray

#: EXR channels tried, in order, for a single-valued array.
EXR_CHANNELS = ("Z", "Y", "R", "V")


def read_array(path: str | Path) -> NDArray[np.float64]:
    """A 2-D float array from a ``.npy`` file or the first of Z/Y/R/V in an EXR [file units: m]."""
    path = Path(path)
    if path.suffix.lower() == ".npy":
        array = np.load(path, allow_pickle=False)
    else:
        from ..io.frames import read_exr  # noqa: PLC0415

        channels, _ = read_exr(path)
        name = next((c for c in EXR_CHANNELS if c in channels), None)
        if name is None:
            raise ValueError(f"no channel among {', '.join(EXR_CHANNELS)} (has {', '.join(sorted(channels))})")
        array = channels[name]
    array = np.asarray(array, dtype=np.float64)
    if array.ndim != 2:
        raise ValueError(f"expected a 2-D array, got shape {array.shape}")
    return array


def check_array(array: NDArray, shape: tuple[int, int]) -> NDArray[np.float64]:
    """``array`` if it has ``shape`` (ny, nx) and only finite values; else ValueError."""
    if array.shape != tuple(shape):
        raise ValueError(f"expected shape (ny, nx) = {tuple(shape)} to match [coastal] cells, got {array.shape}")
    bad = int(np.count_nonzero(~np.isfinite(array)))
    if bad:
        raise ValueError(f"{bad} NaN or infinite values")
    return array


def cell_centres(shape: tuple[int, int], spacing: tuple[float, float], origin: tuple[float, float]):
    """World x [m] of the columns and y [m] of the rows of a (ny, nx) cell grid."""
    ny, nx = shape
    dx, dy = spacing
    x0, y0 = origin
    return x0 + (np.arange(nx) + 0.5) * dx, y0 + (np.arange(ny) + 0.5) * dy


def coastal_cell_centres(coastal) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """World x [m] of the columns and y [m] of the rows of a ``[coastal]`` grid (:func:`cell_centres`)."""
    return cell_centres(coastal.shape, coastal.spacing, coastal.origin)


def plane_beach(y: NDArray, x: NDArray, still_level: float, shoreline_y: float, slope: float,
                offshore_depth: float) -> NDArray[np.float64]:
    """Bed elevation z_b(y, x) [m] of a plane beach rising towards −y, floored at ``offshore_depth``.

    z_b = max(still_level − slope (y − shoreline_y), still_level − offshore_depth).
    """
    z = still_level - slope * (np.asarray(y, float)[:, None] - shoreline_y)
    z = np.maximum(z, still_level - offshore_depth)
    return np.broadcast_to(z, (len(y), len(x))).copy()


def bathymetry(coastal) -> NDArray[np.float64]:
    """Bed elevation z_b (ny, nx) [m] from the settings (analytic or file)."""
    if coastal.bathymetry == "plane beach":
        x, y = coastal_cell_centres(coastal)
        return plane_beach(y, x, coastal.still_level, coastal.shoreline_y, coastal.slope, coastal.offshore_depth)
    return check_array(read_array(coastal.bathymetry), coastal.shape)


def initial_depth(coastal, bed: NDArray) -> NDArray[np.float64]:
    """Initial water depth h = max(η₀ − z_b, 0) [m]; η₀ the still level or the file's surface."""
    if coastal.initial_surface == "still":
        eta = np.full(bed.shape, coastal.still_level)
    else:
        eta = check_array(read_array(coastal.initial_surface), coastal.shape)
    return np.maximum(eta - bed, 0.0)


def check_coastal_inputs(coastal) -> None:
    """Read and check every array input (shape, finiteness); ValueError naming the key.

    Raises
    ------
    ValueError
        ``"<key>: <problem>"`` for the first bad input.
    """
    for key in ("bathymetry", "initial_surface"):
        value = getattr(coastal, key)
        if value in ("plane beach", "still"):
            continue
        if not Path(value).is_file():
            raise ValueError(f"{key}: file not found: {value}")
        try:
            check_array(read_array(value), coastal.shape)
        except (OSError, ValueError, RuntimeError) as exc:
            raise ValueError(f"{key}: {value}: {exc}") from None
    bed = bathymetry(coastal)
    if not np.any(initial_depth(coastal, bed) > coastal.h_min):
        raise ValueError("bathymetry: no cell is below the still level: there is no water")


def rock_mask(coastal) -> NDArray[np.float64]:
    """Rock coverage (ny, nx) in [0, 1] [-]: a smooth random pattern covering ``rock_cover`` of the floor.

    A sum of 48 random plane waves of wavelengths 0.6–6 m (a Gaussian random
    field), thresholded at the quantile that leaves ``rock_cover`` of the cells
    as rock, with a soft edge over 0.1 standard deviations.
    """
    rng = np.random.default_rng(coastal.seed)
    x, y = coastal_cell_centres(coastal)
    field = np.zeros((len(y), len(x)))
    for _ in range(48):
        k = 2.0 * np.pi / rng.uniform(0.6, 6.0)
        theta, phase = rng.uniform(0, 2 * np.pi, 2)
        field += np.cos(k * (np.cos(theta) * x[None, :] + np.sin(theta) * y[:, None]) + phase)
    field /= field.std()
    if coastal.rock_cover <= 0:
        return np.zeros_like(field)
    if coastal.rock_cover >= 1:
        return np.ones_like(field)
    threshold = np.quantile(field, 1.0 - coastal.rock_cover)
    return np.clip((field - threshold) / 0.1 + 0.5, 0.0, 1.0)
