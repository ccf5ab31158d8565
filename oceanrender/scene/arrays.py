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
#: Largest array file a scene may name [bytes] (a 16384² float64 grid is 2 GiB).
MAX_ARRAY_BYTES = 2 << 30
#: Largest initial speed a scene may give [m s⁻¹] (a tsunami bore runs at ~10; beyond 30 is a typo).
MAX_INITIAL_SPEED = 30.0
#: Most elements an array file may hold (its header is read, and checked, before its data).
MAX_ARRAY_ELEMENTS = 16384 * 16384


def check_npy_header(path: Path, shape: tuple[int, int] | None = None) -> None:
    """Check a ``.npy`` header before reading its data: 2-D, plain numbers, a size the file holds.

    The header (NumPy's format, ``numpy.lib.format``) names dtype and shape; a
    file whose header claims more data than it holds, a structured or object
    dtype, or a shape other than ``shape`` (ny, nx) is refused with ValueError
    before any allocation.
    """
    fmt = np.lib.format
    with open(path, "rb") as handle:
        try:
            version = fmt.read_magic(handle)
            read_header = {(1, 0): fmt.read_array_header_1_0, (2, 0): fmt.read_array_header_2_0}.get(version)
            if read_header is None:
                raise ValueError(f"unsupported .npy format version {version}")
            header_shape, _fortran, dtype = read_header(handle)
        except (ValueError, EOFError, SyntaxError, TypeError) as exc:
            raise ValueError(f"not a readable .npy file ({str(exc).splitlines()[0] if str(exc) else 'bad header'})") \
                from None
        data_offset = handle.tell()
    if dtype.fields is not None or dtype.subdtype is not None or dtype.kind not in "fiu":
        raise ValueError(f"expected an array of real numbers (float or int), got dtype {dtype}")
    if len(header_shape) != 2:
        raise ValueError(f"expected a 2-D array, got shape {header_shape}")
    if shape is not None and tuple(header_shape) != tuple(shape):
        raise ValueError(f"expected shape (ny, nx) = {tuple(shape)} to match [coastal] cells, got {header_shape}")
    elements = int(header_shape[0]) * int(header_shape[1])
    if elements > MAX_ARRAY_ELEMENTS:
        raise ValueError(f"expected at most {MAX_ARRAY_ELEMENTS} elements, the header claims {elements}")
    if path.stat().st_size - data_offset != elements * dtype.itemsize:
        raise ValueError(f"the file holds {path.stat().st_size - data_offset} bytes of data, its header claims "
                         f"{elements * dtype.itemsize} (truncated or padded)")


def check_exr_header(path: Path, shape: tuple[int, int] | None = None) -> None:
    """Check an EXR's data window before reading its pixels: at most :data:`MAX_ARRAY_ELEMENTS`, ``shape``."""
    import OpenEXR  # noqa: PLC0415

    try:
        with OpenEXR.File(str(path), header_only=True) as exr:
            window = exr.header().get("dataWindow")
    except Exception as exc:  # noqa: BLE001 (OpenEXR raises RuntimeError or its own types on a bad file)
        raise ValueError(f"not a readable EXR file ({str(exc).splitlines()[0] if str(exc) else 'bad header'})") \
            from None
    if window is None:
        raise ValueError("not a readable EXR file (no data window)")
    (x0, y0), (x1, y1) = (tuple(int(v) for v in corner) for corner in window)
    size = (y1 - y0 + 1, x1 - x0 + 1)
    if size[0] * size[1] > MAX_ARRAY_ELEMENTS:
        raise ValueError(f"expected at most {MAX_ARRAY_ELEMENTS} pixels, the header claims {size[0] * size[1]}")
    if shape is not None and size != tuple(shape):
        raise ValueError(f"expected shape (ny, nx) = {tuple(shape)} to match [coastal] cells, got {size}")


def read_array(path: str | Path, shape: tuple[int, int] | None = None) -> NDArray[np.float64]:
    """A 2-D float array from a ``.npy`` file or the first of Z/Y/R/V in an EXR [file units: m].

    The file is checked first (:func:`oceanrender.io.paths.check_input_file`:
    a regular readable file under :data:`MAX_ARRAY_BYTES`), then its header
    (dtype, 2-D, ``shape`` if given, the data it claims), then read.
    """
    from ..io.paths import PathProblem, check_input_file  # noqa: PLC0415

    try:
        path = check_input_file(path, MAX_ARRAY_BYTES)
    except PathProblem as exc:
        raise ValueError(str(exc)) from None
    if path.suffix.lower() == ".npy":
        check_npy_header(path, shape)
        array = np.load(path, allow_pickle=False)
    else:
        from ..io.frames import read_exr  # noqa: PLC0415

        check_exr_header(path, shape)
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
    return check_array(read_array(coastal.bathymetry, coastal.shape), coastal.shape)


def initial_surface(coastal) -> NDArray[np.float64]:
    """Initial surface elevation η₀ (ny, nx) [m]: the still level, or the file's surface."""
    if coastal.initial_surface == "still":
        return np.full(coastal.shape, float(coastal.still_level))
    return check_array(read_array(coastal.initial_surface, coastal.shape), coastal.shape)


def initial_depth(coastal, bed: NDArray) -> NDArray[np.float64]:
    """Initial water depth h = max(η₀ − z_b, 0) [m] (:func:`initial_surface`)."""
    return np.maximum(initial_surface(coastal) - bed, 0.0)


def initial_velocities(coastal) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Initial velocities (u, v) [m s⁻¹] along the grid's axes from ``initial_u``/``initial_v``: a uniform
    value or an array file (ny, nx) each."""
    out = []
    for key in ("initial_u", "initial_v"):
        value = getattr(coastal, key)
        if isinstance(value, str):
            out.append(check_array(read_array(value, coastal.shape), coastal.shape))
        else:
            out.append(np.full(coastal.shape, float(value)))
    return out[0], out[1]


def initial_discharges(coastal, depth: NDArray) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Initial discharges (hu, hv) [m² s⁻¹] from ``initial_u``/``initial_v`` [m s⁻¹] and the depth h [m].

    Each velocity is a uniform value or an array file (ny, nx) along the grid's
    axes (:func:`initial_velocities`); cells with h ≤ ``h_min`` (land) get none,
    as the solver requires.
    """
    wet = np.asarray(depth) > coastal.h_min
    u, v = initial_velocities(coastal)
    return np.where(wet, u * depth, 0.0), np.where(wet, v * depth, 0.0)


def offshore_depth(coastal, bed: NDArray) -> float:
    """Mean still-water depth [m] of the wet cells along the offshore side of the bed (ny, nx) [m]."""
    row = {"north": bed[-1, :], "south": bed[0, :], "east": bed[:, -1], "west": bed[:, 0]}[coastal.offshore_side]
    depth = coastal.still_level - np.asarray(row, float)
    wet = depth > coastal.h_min
    if not np.any(wet):
        raise ValueError(f"offshore_side: the {coastal.offshore_side} side is dry: no sea can enter there")
    return float(np.mean(depth[wet]))


def check_velocity(velocity: NDArray, limit: float) -> None:
    """ValueError unless every |velocity| ≤ ``limit`` [m s⁻¹] (first bad cell named)."""
    bad = np.abs(velocity) > limit
    if np.any(bad):
        j, i = np.argwhere(bad)[0]
        raise ValueError(f"expected speeds within ±{limit:g} m/s, got {velocity[j, i]:g} at cell (row {j}, "
                         f"column {i})")


def check_coastal_inputs(coastal) -> None:
    """Read and check every array input (shape, finiteness); ValueError naming the key.

    Raises
    ------
    ValueError
        ``"<key>: <problem>"`` for the first bad input.
    """
    for key in ("bathymetry", "initial_surface", "initial_u", "initial_v"):
        value = getattr(coastal, key)
        if not isinstance(value, str) or value in ("plane beach", "still"):
            continue
        try:
            array = check_array(read_array(value, coastal.shape), coastal.shape)
            if key.startswith("initial_") and key != "initial_surface":
                check_velocity(array, MAX_INITIAL_SPEED)
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
