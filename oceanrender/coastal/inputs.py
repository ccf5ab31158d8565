"""Inputs of a coastal simulation from the scene: bathymetry, initial surface, waves, seafloor.

Pure functions of :class:`~oceanrender.config.scene.CoastalSettings` (and the
[ocean] spectrum for spectral waves); file arrays are read by
:func:`read_array` and checked by :func:`check_coastal_inputs` when the scene
is loaded, before any work starts.

Conventions: arrays (ny, nx), rows south → north, columns west → east; cell
(j, i) centred at origin + ((i + ½) dx, (j + ½) dy); lengths in m.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from .boundaries import Boundaries, IncidentWave, Transmissive, Wall
from .mesh import cell_centres as grid_cell_centres

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


def cell_centres(coastal) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """World x [m] of the columns and y [m] of the rows (:func:`oceanrender.coastal.mesh.cell_centres`)."""
    return grid_cell_centres(coastal.shape, coastal.spacing, coastal.origin)


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
        x, y = cell_centres(coastal)
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


_SIDE_NORMAL_IN = {"north": -np.pi / 2, "south": np.pi / 2, "east": np.pi, "west": 0.0}


def incident_waves(coastal, ocean_spectrum=None, g: float = 9.81) -> IncidentWave:
    """The waves entering through ``offshore_side`` [m, s, rad].

    'train': one linear wave of height ``wave_height`` (amplitude H/2) and period
    ``wave_period`` travelling along ``wave_direction``. 'spectrum': ``wave_count``
    components drawn from the [ocean] directional spectrum Ψ(k) [m⁴] with
    amplitudes √(2 Ψ Δk²) (as the sum-of-sines sea), keeping those that travel
    into the domain; ω from the linear dispersion relation at the offshore
    depth. 'none': an absorbing side at the still level. A smooth start over
    two periods (or 5 s) avoids a shock at t = 0.
    """
    if coastal.waves == "none":
        return IncidentWave.absorbing(coastal.still_level)
    if coastal.waves == "train":
        return IncidentWave.wave_train(coastal.wave_height / 2.0, coastal.wave_period,
                                       direction_deg=coastal.wave_direction, still_level=coastal.still_level,
                                       ramp_time=2.0 * coastal.wave_period)
    from ..geometry.gerstner import wave_components_from_spectrum  # noqa: PLC0415

    if ocean_spectrum is None:
        raise ValueError("waves = 'spectrum' needs the [ocean] spectrum")
    dx, dy = coastal.spacing
    depth = coastal.offshore_depth
    # Band: from waves 4 domain sizes long to those 8 cells long (shorter ones are unresolved).
    k_min = 2.0 * np.pi / (4.0 * max(coastal.size))
    k_max = 2.0 * np.pi / (8.0 * max(dx, dy))
    components = wave_components_from_spectrum(ocean_spectrum, 4 * coastal.wave_count, coastal.seed, k_min, k_max)
    inward = _SIDE_NORMAL_IN[coastal.offshore_side]
    kept = [c for c in components
            if np.cos(np.arctan2(c.wavenumber_y, c.wavenumber_x) - inward) > 0.2]
    kept = sorted(kept, key=lambda c: -c.amplitude)[: coastal.wave_count]
    if not kept:
        raise ValueError("the [ocean] spectrum has no waves travelling into the domain through the offshore side")
    k = np.array([np.hypot(c.wavenumber_x, c.wavenumber_y) for c in kept])
    omega = np.sqrt(g * k * np.tanh(k * depth))  # linear dispersion relation (e.g. Dean & Dalrymple 1991, Eq. 4.19)
    return IncidentWave.from_components(
        amplitudes=[c.amplitude for c in kept], omegas=omega,
        directions_rad=[np.arctan2(c.wavenumber_y, c.wavenumber_x) for c in kept],
        phases=[c.phase for c in kept], still_level=coastal.still_level, wavenumbers=k,
        ramp_time=5.0)


def boundaries(coastal, ocean_spectrum=None) -> Boundaries:
    """Solver boundaries: incident waves on the offshore side, ``lateral`` beside it, a wall opposite."""
    opposite = {"north": "south", "south": "north", "east": "west", "west": "east"}[coastal.offshore_side]
    sides = {}
    for side in ("north", "south", "east", "west"):
        if side == coastal.offshore_side:
            sides[side] = incident_waves(coastal, ocean_spectrum)
        elif side == opposite:
            sides[side] = Wall()
        else:
            sides[side] = Wall() if coastal.lateral == "wall" else Transmissive()
    return Boundaries(**sides)


def rock_mask(coastal) -> NDArray[np.float64]:
    """Rock coverage (ny, nx) in [0, 1] [-]: a smooth random pattern covering ``rock_cover`` of the floor.

    A sum of 48 random plane waves of wavelengths 0.6–6 m (a Gaussian random
    field), thresholded at the quantile that leaves ``rock_cover`` of the cells
    as rock, with a soft edge over 0.1 standard deviations.
    """
    rng = np.random.default_rng(coastal.seed)
    x, y = cell_centres(coastal)
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
