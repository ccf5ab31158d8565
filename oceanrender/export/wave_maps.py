"""Per-frame sea-surface geometry files: float32 EXR maps, PLY meshes, a JSON sidecar.

For frame number ``NNNN`` (zero-padded to 4 digits, like Blender's caches)
:func:`export_frame_maps` writes into one folder:

========================  ===========================================================
``height_NNNN.exr``       Y = elevation η above the mean sea level [m]
``disp_NNNN.exr``         R = Dx (east) [m], G = η (up) [m], B = Dy (north) [m]
``normal_NNNN.exr``       R = nx (east), G = nz (up), B = ny (north): unit normal [-]
``jacobian_NNNN.exr``     Y = Jacobian J of the horizontal map [-]; J ≤ 0 where it folds
``foam_NNNN.exr``         R = G = B = foam coverage in [0, 1] [-] (only when given)
========================  ===========================================================

:func:`export_frame_mesh` adds ``mesh_NNNN.ply`` and :func:`write_geometry_json`
the sidecar ``geometry.json`` (files, channels, units, axes, parameters, frame
times). Every file is written atomically.

Axes and Blender: oceanrender is right-handed with x east, y north, z up, as is
Blender's world. Blender's Ocean modifier bake, however, stores its maps in its
simulation frame, which is y-up: its ``disp_NNNN.exr`` holds (R, G, B) =
(Dx, height, Dy) and the modifier moves a vertex by (R, B, G) (``MOD_ocean.cc``:
``co[2] += disp[1]; co[0] += disp[0]; co[1] += disp[2]``), its ``normal_NNNN.exr``
is y-up as well, and it reads the R channel of ``foam_NNNN.exr`` as foam
coverage in [0, 1]. The Blender-named files here follow that layout exactly
(hence G = up), so a folder of them is a Blender ocean cache; the files with
oceanrender's own names (``height_``, ``jacobian_``) carry one quantity in Y.

Texel layout: column i and row r of every map hold the grid point
x = −L/2 + i L/N, y = −L/2 + (N − 1 − r) L/N, i.e. the *top* row is the north
edge, as in Blender's bake (Blender's image rows run bottom-up and it writes
the last row first). That is the fields' ``[iy, ix]`` array flipped upside
down; :func:`read_frame_maps` flips it back. The maps are periodic: column N
would repeat column 0.

Using the maps as a Blender ocean cache (from the Blender sources; not tested
with Blender here): add an Ocean modifier with Size × Spatial Size = L [m]
(e.g. Size 1, Spatial Size L), so that its texture coordinate
u = x / L + 1/2 puts u = 0 at x = −L/2 like ours; give Choppiness any value
> 0 (Blender applies the horizontal displacement only then; its magnitude is
not used with a cache, λ is already in the maps); bake it once for the frame
range A … B into the export folder (the bake is what switches the modifier to
reading a cache), then run the export into that folder (overwriting Blender's
``disp_``, ``normal_``, ``foam_`` files) and reload the .blend file; leave
Generate Foam off unless foam maps were exported. Frames are Blender scene
frames. Blender units are then metres.

References
----------
.. [1] Blender source, ``source/blender/modifiers/intern/MOD_ocean.cc``
   (``doOcean``) and ``source/blender/blenkernel/intern/ocean.cc``
   (``cache_filepath``, ``BKE_ocean_bake``, ``BKE_ocean_cache_eval_uv``),
   https://projects.blender.org/blender/blender
"""

from __future__ import annotations

import dataclasses
import functools
import json
import math
from collections.abc import Mapping
from pathlib import Path

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..io.frames import atomic_path, read_exr, write_exr
from ..io.ply import write_ply
from ..surface.patch_mesh import water_body_faces, water_body_vertices
from ..waves.fft_ocean import FFTOcean, OceanFields

__all__ = [
    "MAP_FILES",
    "MESH_FILE",
    "SIDECAR_FILE",
    "REQUIRED_METADATA",
    "ocean_metadata",
    "frame_file",
    "export_frame_maps",
    "read_frame_maps",
    "export_frame_mesh",
    "write_geometry_json",
    "export_geometry_sequence",
]

#: Map name → (file name pattern, {channel: meaning}); one table drives writer, reader and sidecar.
MAP_FILES: dict[str, tuple[str, dict[str, str]]] = {
    "height": ("height_{frame:04d}.exr", {"Y": "elevation η above the mean sea level [m]"}),
    "disp": (
        "disp_{frame:04d}.exr",
        {"R": "displacement x, east [m]", "G": "elevation z, up [m]", "B": "displacement y, north [m]"},
    ),
    "normal": (
        "normal_{frame:04d}.exr",
        {"R": "unit normal x, east [-]", "G": "unit normal z, up [-]", "B": "unit normal y, north [-]"},
    ),
    "jacobian": (
        "jacobian_{frame:04d}.exr",
        {"Y": "Jacobian J of the horizontal map [-]; J ≤ 0 where the surface folds"},
    ),
    "foam": ("foam_{frame:04d}.exr", {c: "foam coverage in [0, 1] [-]" for c in "RGB"}),
}

#: File name pattern of the per-frame water-body mesh.
MESH_FILE = "mesh_{frame:04d}.ply"

#: Name of the JSON sidecar describing a geometry export.
SIDECAR_FILE = "geometry.json"

#: Metadata keys every map must carry (:func:`ocean_metadata` provides them).
REQUIRED_METADATA = ("patch_size_m", "time_s", "spectrum", "seed")

_ROW_ORDER = "top row = north edge: row r, column i hold x = -L/2 + i L/N, y = -L/2 + (N - 1 - r) L/N"
_INT32 = (-(2**31), 2**31 - 1)


def ocean_metadata(ocean: FFTOcean, t: float | None = None) -> dict[str, object]:
    """The parameters of an FFT ocean (and the time) as export metadata.

    Parameters
    ----------
    ocean : FFTOcean
        The ocean the fields come from.
    t : float, optional
        Time of the frame [s]; left out for the sidecar, which lists the times.

    Returns
    -------
    dict
        ``patch_size_m``, ``resolution``, ``spectrum`` (name),
        ``spectrum_parameters`` (the spectrum's own parameter names, in the
        project's units: m, s, rad, m s⁻¹), ``choppiness``, ``depth_m``,
        ``seed``, ``dtype``, ``loop_period_s`` and ``cascade`` where the ocean
        has them, and with ``t``, ``time_s``.

    Notes
    -----
    With a ``spectrum_function``, the name and parameters come from it: a
    :func:`functools.partial` gives its function's name and keywords, a
    dataclass (e.g. ``DirectionalSpectrum``) its ``method`` and fields.
    """
    function = getattr(ocean, "spectrum_function", None)
    if function is None:
        spectrum = ocean.spectrum
        parameters = {
            "wind_speed": ocean.wind_speed,
            "wind_direction": ocean.wind_direction,
            "alpha": ocean.alpha,
            "small_wave_length": ocean.small_wave_length,
            "g": ocean.g,
        }
    else:
        spectrum, parameters = _describe_spectrum(function)
    metadata: dict[str, object] = {
        "patch_size_m": float(ocean.grid.patch_size),
        "resolution": int(ocean.grid.resolution),
        "spectrum": spectrum,
        "spectrum_parameters": parameters,
        "choppiness": float(ocean.choppiness),
        "depth_m": float(ocean.depth),
        "seed": int(ocean.seed),
        "dtype": np.dtype(ocean.dtype).name,
    }
    # NOTE: read with getattr: FFTOcean gains fields while this module is stable
    if getattr(ocean, "loop_period", None) is not None:
        metadata["loop_period_s"] = float(ocean.loop_period)
    if getattr(ocean, "cascade", None) is not None:
        metadata["cascade"] = int(ocean.cascade)
    if t is not None:
        metadata["time_s"] = float(t)
    return metadata


def _describe_spectrum(function: object) -> tuple[str, dict[str, object]]:
    """(name, parameters) of a spectrum callable."""
    if isinstance(function, functools.partial):
        return getattr(function.func, "__name__", repr(function.func)), dict(function.keywords)
    if dataclasses.is_dataclass(function):
        values = {f.name: getattr(function, f.name) for f in dataclasses.fields(function)}
        return str(values.pop("method", type(function).__name__)), values
    return getattr(function, "__name__", type(function).__name__), {}


def frame_file(kind: str, frame: int) -> str:
    """File name of map ``kind`` (a key of :data:`MAP_FILES`, or ``"mesh"``) for a frame."""
    if int(frame) != frame or frame < 0:
        raise ValueError(f"frame must be a non-negative integer, got {frame!r}")
    if kind == "mesh":
        return MESH_FILE.format(frame=int(frame))
    if kind not in MAP_FILES:
        raise ValueError(f"unknown map {kind!r}; known: {', '.join(map(repr, [*MAP_FILES, 'mesh']))}")
    return MAP_FILES[kind][0].format(frame=int(frame))


def _flatten(metadata: Mapping[str, object], prefix: str = "") -> dict[str, object]:
    """Nested mappings as ``a.b`` keys."""
    flat: dict[str, object] = {}
    for key, value in metadata.items():
        if isinstance(value, Mapping):
            flat.update(_flatten(value, f"{prefix}{key}."))
        else:
            flat[f"{prefix}{key}"] = value
    return flat


def _header_metadata(metadata: Mapping[str, object]) -> dict[str, object]:
    """Metadata as EXR header values that read back exactly."""
    header: dict[str, object] = {}
    for key, value in _flatten(metadata).items():
        if isinstance(value, (bool, np.bool_, str)):
            header[key] = value
        elif isinstance(value, (int, np.integer)):
            # NOTE: write_exr stores ints as 32-bit attributes (2**40 reads back 0):
            # larger ones, e.g. seeds, go in as text.
            header[key] = int(value) if _INT32[0] <= value <= _INT32[1] else str(int(value))
        elif isinstance(value, (float, np.floating)):
            # NOTE: ... and floats as 32-bit ones; repr keeps every digit of a time or length.
            header[key] = repr(float(value))
        else:
            header[key] = json.dumps(_json_value(value), ensure_ascii=False)
    return header


def _json_value(value: object) -> object:
    """Plain JSON types; non-finite floats as the strings "inf", "-inf", "nan"."""
    if isinstance(value, Mapping):
        return {str(k): _json_value(v) for k, v in value.items()}
    if isinstance(value, (list, tuple, np.ndarray)):
        return [_json_value(v) for v in value]
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    if isinstance(value, (int, np.integer)):
        return int(value)
    if isinstance(value, (float, np.floating)):
        return float(value) if math.isfinite(value) else str(float(value))
    return str(value)


def _image(array: ArrayLike) -> NDArray[np.float32]:
    """An ``[iy, ix]`` field as image rows, north at the top."""
    return np.ascontiguousarray(np.asarray(array, dtype=np.float32)[::-1])


def export_frame_maps(
    out_dir: str | Path,
    frame: int,
    fields: OceanFields,
    metadata: Mapping[str, object],
    foam: ArrayLike | None = None,
) -> dict[str, Path]:
    """Write one frame's float32 EXR maps (see the module docstring for the layout).

    Parameters
    ----------
    out_dir : str or Path
        Folder, created if needed.
    frame : int
        Frame number ≥ 0, zero-padded to 4 digits in the file names.
    fields : OceanFields
        The surface at the frame's time, N × N, ``[iy, ix]``.
    metadata : mapping
        Written into every file's header (``oceanrender:`` attributes; nested
        mappings as ``a.b`` keys; floats as exact text). Must hold
        :data:`REQUIRED_METADATA`; see :func:`ocean_metadata`. ``frame``,
        ``resolution``, ``map``, ``channels`` and ``row_order`` are added.
    foam : array_like, shape (N, N), optional
        Foam coverage in [0, 1] [-]; writes ``foam_NNNN.exr``.

    Returns
    -------
    dict
        Map name → path written.
    """
    missing = [key for key in REQUIRED_METADATA if key not in metadata]
    if missing:
        raise ValueError(f"metadata lacks {', '.join(missing)} (see ocean_metadata)")
    n = fields.resolution
    if "resolution" in metadata and metadata["resolution"] != n:
        raise ValueError(f"metadata resolution {metadata['resolution']} differs from the fields' {n}")
    maps = {
        "height": {"Y": _image(fields.height)},
        "disp": {"R": _image(fields.displacement_x), "G": _image(fields.height), "B": _image(fields.displacement_y)},
        "normal": {c: _image(fields.normals[..., axis]) for c, axis in zip("RGB", (0, 2, 1))},
        "jacobian": {"Y": _image(fields.jacobian)},
    }
    if foam is not None:
        coverage = np.asarray(foam, dtype=np.float64)
        if coverage.shape != (n, n):
            raise ValueError(f"foam must have shape {(n, n)}, got {coverage.shape}")
        if not np.all((coverage >= 0) & (coverage <= 1)):
            raise ValueError("foam coverage must lie in [0, 1]")
        maps["foam"] = {c: _image(coverage) for c in "RGB"}

    base = {**metadata, "frame": int(frame), "resolution": n, "row_order": _ROW_ORDER}
    out_dir = Path(out_dir)
    written = {}
    for kind, channels in maps.items():
        path = out_dir / frame_file(kind, frame)
        meaning = "; ".join(f"{c}={text}" for c, text in MAP_FILES[kind][1].items())
        write_exr(path, channels, _header_metadata({**base, "map": kind, "channels": meaning}))
        written[kind] = path
    return written


def read_frame_maps(out_dir: str | Path, frame: int) -> tuple[dict[str, NDArray[np.float32]], dict[str, object]]:
    """Read back what :func:`export_frame_maps` wrote, in the fields' layout.

    Returns
    -------
    maps : dict
        ``height``, ``jacobian`` and (if written) ``foam`` as (N, N) ``[iy, ix]``;
        ``displacement`` as (N, N, 3) (Dx, Dy, η) and ``normals`` as (N, N, 3)
        (nx, ny, nz), z up [m, -].
    metadata : dict
        The height map's header attributes, as stored (floats as text).
    """
    out_dir = Path(out_dir)
    (height, metadata), (disp, _), (normal, _), (jacobian, _) = (
        read_exr(out_dir / frame_file(kind, frame)) for kind in ("height", "disp", "normal", "jacobian")
    )
    maps = {
        "height": height["Y"][::-1],
        "displacement": np.stack([disp["R"], disp["B"], disp["G"]], -1)[::-1],
        "normals": np.stack([normal["R"], normal["B"], normal["G"]], -1)[::-1],
        "jacobian": jacobian["Y"][::-1],
    }
    foam_path = out_dir / frame_file("foam", frame)
    if foam_path.is_file():
        maps["foam"] = read_exr(foam_path)[0]["R"][::-1]
    return maps, metadata


def export_frame_mesh(
    out_dir: str | Path,
    frame: int,
    positions: ArrayLike,
    normals: ArrayLike | None,
    faces: ArrayLike,
    metadata: Mapping[str, object] | None = None,
) -> Path:
    """Write one frame's mesh as ``mesh_NNNN.ply`` (binary little-endian, float32, z up, m).

    Parameters
    ----------
    out_dir : str or Path
        Folder, created if needed.
    frame : int
        Frame number ≥ 0.
    positions : array_like, shape (V, 3)
        Vertex positions [m], e.g. from :func:`oceanrender.surface.patch_mesh.water_body_vertices`.
    normals : array_like, shape (V, 3), or None
        Unit vertex normals [-].
    faces : array_like of int, shape (F, 3)
        Triangles, e.g. :func:`oceanrender.surface.patch_mesh.water_body_faces`.
    metadata : mapping, optional
        Written as ``comment key: value`` header lines (nested keys as ``a.b``).

    Returns
    -------
    Path
        The file written.
    """
    path = Path(out_dir) / frame_file("mesh", frame)
    comments = {"frame": int(frame), "units": "m", "axes": "x east, y north, z up"}
    for key, value in _header_metadata(metadata or {}).items():
        # PLY headers are ASCII: escape anything else as a JSON string
        comments[key] = value if str(value).isascii() else json.dumps(str(value))
    write_ply(path, positions, faces, normals, comments)
    return path


def write_geometry_json(
    out_dir: str | Path,
    frame_times: Mapping[int, float],
    metadata: Mapping[str, object],
    *,
    foam: bool = False,
    mesh: bool = False,
) -> Path:
    """Write ``geometry.json``, describing an export's files, units, axes and parameters.

    Parameters
    ----------
    out_dir : str or Path
        Export folder.
    frame_times : mapping of int to float
        Frame number → time [s] of every exported frame.
    metadata : mapping
        Ocean parameters (:func:`ocean_metadata` without ``t``); must hold
        ``patch_size_m`` and ``resolution``. A ``time_s`` entry is dropped in
        favour of ``frame_times``.
    foam, mesh : bool, optional
        Whether the export has foam maps / PLY meshes.

    Returns
    -------
    Path
        The file written (atomically).
    """
    for key in ("patch_size_m", "resolution"):
        if key not in metadata:
            raise ValueError(f"metadata lacks {key} (see ocean_metadata)")
    size, n = float(metadata["patch_size_m"]), int(metadata["resolution"])
    maps = [kind for kind in MAP_FILES if kind != "foam" or foam]
    files: dict[str, object] = {
        kind: {"pattern": MAP_FILES[kind][0], "format": "OpenEXR, float32, single part", "channels": MAP_FILES[kind][1]}
        for kind in maps
    }
    if mesh:
        files["mesh"] = {
            "pattern": MESH_FILE,
            "format": "PLY binary_little_endian 1.0: vertex float x y z nx ny nz; face list uchar uint vertex_indices",
            "content": "closed water body of oceanrender.surface.patch_mesh: top surface, side walls, flat bottom; "
            "triangles counter-clockwise seen from outside",
        }
    document = {
        "format": "oceanrender geometry export",
        "version": 1,
        "frames": [{"frame": int(f), "time_s": float(t)} for f, t in sorted(frame_times.items())],
        "files": files,
        "units": {
            "length": "m",
            "time": "s",
            "angle": "rad",
            "normal": "unit vector [-]",
            "jacobian": "[-]",
            "foam": "[-], in [0, 1]",
        },
        "axes": {
            "x": "east",
            "y": "north",
            "z": "up",
            "handedness": "right-handed (as Blender's world)",
            "channel_order": "files named like Blender's ocean cache (disp_, normal_, foam_) use its y-up "
            "channel order: R = x, G = z (up), B = y; a surface point moves to (x + R, y + B, G)",
        },
        "grid": {
            "resolution": n,
            "patch_size_m": size,
            "spacing_m": size / n,
            "first_point_m": [-size / 2, -size / 2],
            "periodic": True,
            "texels": _ROW_ORDER,
        },
        "parameters": _json_value({k: v for k, v in metadata.items() if k != "time_s"}),
        "blender": {
            "ocean_modifier": {
                "size_times_spatial_size_m": size,
                "choppiness": "any value > 0",
                "cache_path": "this folder",
            },
            "note": "bake the modifier once over the same frames into this folder, then export into it and reload; "
            "see oceanrender.export.wave_maps",
        },
    }
    path = Path(out_dir) / SIDECAR_FILE
    with atomic_path(path, ".json") as tmp:
        tmp.write_text(json.dumps(document, indent=2, ensure_ascii=False, allow_nan=False) + "\n", encoding="utf-8")
    return path



def export_geometry_sequence(
    out_dir: str | Path,
    ocean: FFTOcean,
    frame_times: Mapping[int, float],
    *,
    mesh_depth: float | None = None,
    sea: Mapping[str, object] | None = None,
) -> list[Path]:
    """Export the maps (and meshes) of every frame, plus ``geometry.json``: what the CLI calls.

    Parameters
    ----------
    out_dir : str or Path
        Export folder, created if needed.
    ocean : FFTOcean
        The sea; ``ocean.fields(t)`` is evaluated once per frame.
    frame_times : mapping of int to float
        Frame number (≥ 0) → time [s], e.g. ``{f: f / fps for f in range(a, b + 1)}``.
    mesh_depth : float, optional
        Also write ``mesh_NNNN.ply``, the closed water body of
        :mod:`oceanrender.surface.patch_mesh` with its flat bottom at z = −mesh_depth [m].
    sea : mapping, optional
        The whole sea this patch belongs to (its form and statistics), written
        into ``geometry.json`` as ``ocean``.

    Returns
    -------
    list of Path
        The files written, sidecar first.

    Notes
    -----
    Every argument is checked before the first file is written; the sidecar
    goes first, so a partial export is still described. Each file is atomic,
    so an interrupted export can be rerun over the same folder.
    """
    if not frame_times:
        raise ValueError("no frames to export")
    for frame, t in frame_times.items():
        frame_file("height", frame)  # refuses negative or fractional frame numbers
        if not math.isfinite(t):
            raise ValueError(f"frame {frame}: time must be finite [s], got {t!r}")
    times = {int(f): float(t) for f, t in frame_times.items()}
    if mesh_depth is not None and not (math.isfinite(mesh_depth) and mesh_depth > 0):
        raise ValueError(f"mesh_depth must be a positive depth [m], got {mesh_depth!r}")

    metadata = ocean_metadata(ocean)
    written = [write_geometry_json(out_dir, times, {**metadata, **({"ocean": dict(sea)} if sea else {})},
                                   mesh=mesh_depth is not None)]
    faces = None if mesh_depth is None else water_body_faces(ocean.grid.resolution)
    for frame, t in sorted(times.items()):
        fields = ocean.fields(t)
        frame_metadata = {**metadata, "time_s": t}
        written += export_frame_maps(out_dir, frame, fields, frame_metadata).values()
        if faces is not None:
            positions, normals = water_body_vertices(fields, ocean.grid.patch_size, mesh_depth)
            written.append(export_frame_mesh(out_dir, frame, positions, normals, faces, frame_metadata))
    return written
