"""Everything a run needs, checked before any work starts: data, sea, memory, output folders.

:func:`oceanrender.scene.load_scene` checks each value on its own (ranges,
finiteness, files the scene names). What needs the physics of a stage above
``scene/`` is checked here, once the command line has been applied and before
any stage allocates or writes:

* the water's tables (:func:`check_tables`): every IOP table read and checked
  for shape, finiteness and sign, the composition's components resolved;
* the open sea against its water body (:func:`check_sea`): the flat bottom
  below the deepest troughs, judged on the spectrum's elevation σ (a Gaussian sea
  exceeds 8σ at a point with probability ~10⁻¹⁵). The camera may be anywhere above
  the bottom: each frame renders from the side of the surface its pinhole is on;
* memory (:func:`memory_estimate`, :func:`check_memory`): the stages' peak
  memory from the scene's sizes, with per-unit costs measured by
  ``benchmarks/bench_memory.py`` (BENCHMARKS.md, "Memory"), against the memory
  available now; refused with the estimate;
* output folders (:func:`check_output`): created and probed with a real file,
  with room for the first frame's files.

Each failure is a :class:`~oceanrender.scene.SceneError` of one line naming
the file, the key and what was expected. Sizes in bytes, lengths in m.
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .scene import Scene, SceneError

GiB = float(1 << 30)
MiB = float(1 << 20)

#: Peak bytes per FFT grid point and cascade (spectrum, fields and level pyramids), measured.
BYTES_PER_FFT_POINT = 204.0
#: Peak bytes per vertex of the radial water body (sampling every cascade, normals, foam, Mitsuba's buffers), measured.
BYTES_PER_MESH_VERTEX = 960.0
#: Peak bytes per shallow-water cell (state, fluxes, ghosts, work arrays), measured.
BYTES_PER_COASTAL_CELL = 74.0
#: The same for ``scheme = "dg"`` (nine P1 coefficients and numpy's temporaries per stage), measured as the
#: growth of peak RSS from 300² to 600² cells (docs/coastal.md).
BYTES_PER_DG_CELL = 1040.0
#: Peak bytes per pixel of a frame: Mitsuba's film, XYZ, the vision model, EXR and PNG buffers, measured.
#: (Samples cost none: the split integrator's paths are loops inside one drjit kernel, measured too.)
BYTES_PER_PIXEL = 220.0
#: What a render process holds whatever the scene: Python, numpy, Mitsuba, drjit and its LLVM JIT.
FIXED_BYTES = 1.5 * GiB
#: Share of the memory available now that a run may plan to use.
MEMORY_SHARE = 0.8

#: Elevation σ multiple: the bottom must lie below −8σ (see the module docstring).
TROUGH_SIGMAS = 8.0


@dataclass(frozen=True)
class MemoryItem:
    """One stage's share of a run's peak memory: the scene key that sizes it, what it is, bytes."""

    key: str
    what: str
    bytes: float


def available_memory() -> float:
    """Memory available to a new allocation now [bytes]: MemAvailable of /proc/meminfo, else physical memory."""
    try:
        with open("/proc/meminfo", encoding="ascii") as handle:
            for line in handle:
                if line.startswith("MemAvailable:"):
                    return float(line.split()[1]) * 1024.0
    except OSError:
        pass
    return float(os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES"))


def mesh_vertices(scene: Scene) -> int:
    """Top vertices of the scene's water body [-] (the radial grid of [mesh], or the FFT patch; the coast's grid,
    or with ``waves = "open sea"`` the radial grid it sits in, with its terrain on the same vertices)."""
    if scene.coastal is not None and scene.coastal.waves != "open sea":
        return (scene.coastal.cells[0] + 1) * (scene.coastal.cells[1] + 1)
    if scene.mesh.kind == "radial":
        ratio = 1.0 + 2.0 * math.pi / scene.mesh.segments  # RadialGrid.square_cells
        rings = math.ceil(math.log(scene.mesh.outer_radius / scene.mesh.inner_radius) / math.log(ratio)) + 1
        top = 1 + max(rings, 2) * scene.mesh.segments
        return 2 * top if scene.coastal is not None else top  # the coast's terrain has the body's top vertices
    return (scene.ocean.resolution + 1) ** 2


def memory_estimate(scene: Scene, renders: bool = True) -> list[MemoryItem]:
    """The run's peak memory by stage [bytes], from the scene's sizes and the measured per-unit costs.

    ``renders`` False leaves out the renderer (commands that only simulate or export).
    """
    ocean, items = scene.ocean, [MemoryItem("(whole run)", "Python, Mitsuba and drjit", FIXED_BYTES)]
    if ocean.model == "FFT":
        points = ocean.resolution ** 2 * ocean.cascades
        items.append(MemoryItem("[ocean] resolution", f"FFT sea: {ocean.resolution}² points × {ocean.cascades} "
                                f"cascade(s)", points * BYTES_PER_FFT_POINT))
    if scene.coastal is not None:
        cells = scene.coastal.cells[0] * scene.coastal.cells[1]
        dg = scene.coastal.scheme == "dg"
        per_cell = BYTES_PER_DG_CELL if dg else BYTES_PER_COASTAL_CELL
        items.append(MemoryItem("[coastal] cells", f"shallow water{' (DG P1)' if dg else ''}: {cells} cells",
                                cells * per_cell))
    key = "[coastal] cells" if scene.coastal is not None and scene.coastal.waves != "open sea" else (
        "[mesh] segments" if scene.mesh.kind == "radial" else "[ocean] resolution")
    vertices = mesh_vertices(scene)
    if renders:
        items.append(MemoryItem(key, f"water body: {vertices} vertices", vertices * BYTES_PER_MESH_VERTEX))
        width, height = scene.output.resolution
        pixels = width * height
        items.append(MemoryItem("[output] resolution", f"frame: {width}x{height} pixels",
                                pixels * (BYTES_PER_PIXEL + 4 * scene.output.spectral_bands)))
    return items


def check_memory(scene: Scene, source: str, renders: bool = True, available: float | None = None) -> None:
    """Refuse a run whose :func:`memory_estimate` exceeds :data:`MEMORY_SHARE` of the memory available."""
    items = memory_estimate(scene, renders)
    total = sum(item.bytes for item in items)
    budget = MEMORY_SHARE * (available_memory() if available is None else available)
    if total > budget:
        largest = max(items[1:], key=lambda item: item.bytes)
        raise SceneError(f"{source}: {largest.key}: the run needs about {total / GiB:.1f} GiB ({largest.what}: "
                         f"{largest.bytes / GiB:.1f} GiB), more than the {budget / GiB:.1f} GiB it may use here; "
                         f"expected a smaller value")


#: Seconds per sample of the camera's pass on one core (split integrator, first lobe; default scene), measured
#: by ``benchmarks/bench_time_estimate.py`` (BENCHMARKS.md, "Time estimate") [s].
SECONDS_PER_SAMPLE_CORE = 7.7e-6
#: Seconds per sample and expected in-water vertex of the in-water lobe on one core, measured likewise [s].
SECONDS_PER_WATER_VERTEX_CORE = 4.5e-6
#: Fixed seconds of one render call (one pass: scene update, kernel launch, film read-back), measured likewise [s].
SECONDS_PER_RENDER_CALL = 1.24
#: The GPU's throughput against the 2-core CPU's on the same scene (57.5 against 0.69 M samples/s, H200,
#: ../shared/NOTES.md) [-].
GPU_SPEED_UP_OVER_TWO_CORES = 83.0
#: Seconds per FFT grid point and cascade of one frame's geometry (fields, level pyramids, foam history), measured [s].
SECONDS_PER_FFT_POINT = 1.7e-7
#: A run's fixed set-up: Mitsuba's scene load, kernel compilation, the adapting white [s], measured (CPU; GPU).
SETUP_SECONDS = {"cpu": 9.0, "gpu": 40.0}


@dataclass(frozen=True)
class TimeEstimate:
    """A run's expected wall time [s], from the scene's sizes and the measured per-unit costs.

    Attributes
    ----------
    setup : float        Scene load, compilation, white and the first frame's adaptation window [s].
    per_frame : float    Each further frame: geometry, its meter, its samples [s].
    total : float        ``setup + frames × per_frame`` [s].
    key : str            The scene key that dominates the time.
    """

    setup: float
    per_frame: float
    total: float
    key: str

    def line(self) -> str:
        """``about 42 s (set-up 9 s, then 11 s per frame)``, for the run's first line."""
        return f"about {_duration(self.total)} (set-up {_duration(self.setup)}, then {_duration(self.per_frame)} per frame)"


def _duration(seconds: float) -> str:
    if seconds < 90:
        return f"{seconds:.0f} s"
    if seconds < 5400:
        return f"{seconds / 60:.0f} min"
    if seconds < 2 * 86400:
        return f"{seconds / 3600:.1f} h"
    return f"{seconds / 86400:.0f} days"


def expected_water_vertices(scene: Scene) -> float:
    """Expected scattering vertices of a path in the water before it is absorbed [-], at 550 nm.

    1 / (1 − ω₀) with ω₀ = b/c the single-scattering albedo: in an unbounded medium each
    collision scatters with probability ω₀ and absorbs otherwise, so the number of
    collisions is geometric with mean 1/(1 − ω₀). Capped by ``[render] max_depth``
    (a bounded water body and Russian roulette end paths sooner: an upper estimate).
    """
    from .optics.scene_water import water_optics  # noqa: PLC0415

    optics = water_optics(scene)
    iops = getattr(optics, "iops", optics)
    albedo = float(np.interp(550.0, iops.wavelengths, iops.scattering / (iops.absorption + iops.scattering)))
    return float(min(1.0 / max(1.0 - albedo, 1e-9), scene.render.max_depth))


def time_estimate(scene: Scene, variant: str, meter_samples: int, cores: int | None = None) -> TimeEstimate:
    """The run's wall time [s], before any work, from measured per-unit costs (the time's :func:`memory_estimate`).

    Per frame: the FFT sea's geometry, the adaptation meter (``meter_samples`` samples per pass, both
    passes in full, one frame per frame; the first frame meters its whole window), and the samples: the
    camera's pass at ``spp`` and the in-water lobe at ``in_water_fraction`` × spp, each
    sample costing in proportion to its expected vertices in the water
    (:func:`expected_water_vertices`). CPU costs scale with ``cores``; a ``cuda`` variant
    runs the samples :data:`GPU_SPEED_UP_OVER_TWO_CORES` times faster than two cores.
    A coastal scene's simulation is not included. An estimate within about 2× (BENCHMARKS.md).
    """
    from .vision.temporal import adaptation_window  # noqa: PLC0415

    cores = cores or len(os.sched_getaffinity(0))
    gpu = variant.startswith("cuda")
    per_sample = (SECONDS_PER_SAMPLE_CORE + SECONDS_PER_WATER_VERTEX_CORE * scene.render.in_water_fraction
                  * expected_water_vertices(scene))
    per_sample /= GPU_SPEED_UP_OVER_TWO_CORES * 2 if gpu else cores
    width, height = scene.output.resolution
    pixels = width * height
    passes = 2 if (scene.render.integrator == "split" and scene.render.in_water_fraction < 1) else 1
    call = SECONDS_PER_RENDER_CALL / (GPU_SPEED_UP_OVER_TWO_CORES if gpu else 1.0)
    render = passes * call + pixels * scene.output.spp * per_sample
    geometry = 0.0
    if scene.ocean.model == "FFT":
        geometry = SECONDS_PER_FFT_POINT * scene.ocean.resolution ** 2 * scene.ocean.cascades * 2.0 / min(cores, 2)
    vision = scene.vision
    follows = vision.adaptation_luminance == "frame" and vision.adaptation_time > 0
    per_meter_sample = SECONDS_PER_SAMPLE_CORE + SECONDS_PER_WATER_VERTEX_CORE * expected_water_vertices(scene)
    per_meter_sample /= GPU_SPEED_UP_OVER_TWO_CORES * 2 if gpu else cores
    meter = (geometry + passes * call + meter_samples * per_meter_sample) if follows else 0.0
    start, end = scene.output.frames
    window = len(adaptation_window(start, vision.adaptation_time, scene.output.fps)) if follows else 0
    setup = SETUP_SECONDS["gpu" if gpu else "cpu"] + max(window - 1, 0) * meter
    per_frame = (meter if follows else geometry) + render  # the meter's geometry is the frame's, reused
    key = "[output] spp" if render >= max(geometry, meter) else (
        "[ocean] resolution" if geometry >= meter else "[vision] adaptation_luminance")
    return TimeEstimate(setup, per_frame, setup + (end - start) * per_frame, key)


def check_tables(scene: Scene, source: str) -> None:
    """Read and check the scene's tables (IOP table, components, objects' reflectances) before any work."""
    from .optics.scene_water import water_composition  # noqa: PLC0415
    from .optics.tables import SpectralDataError  # noqa: PLC0415
    from .optics.water import pure_seawater_iops  # noqa: PLC0415

    try:
        pure_seawater_iops(scene.water.iop_table)
    except SpectralDataError as exc:
        raise SceneError(f"{source}: [water] iop_table: {exc}") from None
    try:
        water_composition(scene)
    except (SpectralDataError, ValueError) as exc:
        raise SceneError(f"{source}: [composition]: {exc}") from None
    if scene.environment is not None:
        from .render.environment import EnvironmentMapProblem, read_environment_map  # noqa: PLC0415

        try:
            read_environment_map(scene.environment.map)
        except EnvironmentMapProblem as exc:
            raise SceneError(f"{source}: [environment] map: {exc}") from None
    from .optics.tables import read_reflectance_table  # noqa: PLC0415

    for obj in scene.objects:
        if obj.albedo_spectrum is not None:
            try:
                read_reflectance_table(obj.albedo_spectrum)
            except SpectralDataError as exc:
                raise SceneError(f"{source}: [[objects]] {obj.name} albedo_spectrum: {exc}") from None


def check_sea(scene: Scene, source: str) -> None:
    """The open sea fits its water body: its bottom below −8σ of the elevation [m]."""
    if scene.coastal is not None and scene.coastal.waves != "open sea":
        return
    from .waves.sea import elevation_std  # noqa: PLC0415

    sigma = elevation_std(scene.ocean)
    if not math.isfinite(sigma):
        raise SceneError(f"{source}: [ocean]: the spectrum's elevation variance is not finite; expected a sea "
                         f"with finite waves (check wind_speed, fetch, swell_height)")
    floor = TROUGH_SIGMAS * sigma
    if scene.water.depth < floor:
        raise SceneError(f"{source}: [water] depth: {scene.water.depth:g} m is above the deepest troughs of the sea; "
                         f"expected ≥ {floor:.3g} m ({TROUGH_SIGMAS:g} σ, σ = {sigma:.3g} m of the [ocean] spectrum)")
    # NOTE: no check of the camera against the crests: each frame renders from the side of the surface its
    # pinhole is on (WaterRenderer.camera_in_water), so a camera path may cross the surface.


#: Bytes per grid point and cascade of one frame of wave maps: 4 EXR maps × 3 float32 channels (export/wave_maps.py).
GEOMETRY_FRAME_BYTES_PER_POINT = 4 * 3 * 4
#: Bytes per cell of one stored coastal frame, rounded up from the .npz fields (h, hu, hv: 3 float64) and the
#: EXR (h, η, u, v, bed: 5 float32), 44 B, to leave room for the checkpoint.
COASTAL_FRAME_BYTES_PER_CELL = 96
#: Room kept beyond a run's first files, for sidecars, metadata and PNGs [bytes].
SLACK_BYTES = 16 * MiB


def geometry_frame_bytes(scene: Scene) -> float:
    """One frame of ``oceanrender geometry``'s wave maps, all cascades [bytes]."""
    return scene.ocean.cascades * scene.ocean.resolution ** 2 * GEOMETRY_FRAME_BYTES_PER_POINT + SLACK_BYTES


def coastal_frame_bytes(scene: Scene) -> float:
    """One stored frame of the coastal simulation (fields and EXR) [bytes]."""
    return scene.coastal.cells[0] * scene.coastal.cells[1] * COASTAL_FRAME_BYTES_PER_CELL + SLACK_BYTES


def frame_bytes(scene: Scene) -> float:
    """Largest size of one rendered frame's files [bytes]: EXR (6 float32 channels), PNG, spectral EXR."""
    width, height = scene.output.resolution
    return width * height * (6 * 4 + 3 + 4 * scene.output.spectral_bands) + 64 * 1024


def check_output(folder: str | Path, source: str, key: str, needed_bytes: float = SLACK_BYTES) -> Path:
    """Create and probe an output folder (see :func:`oceanrender.io.paths.check_output_folder`)."""
    from .io.paths import PathProblem, check_output_folder  # noqa: PLC0415

    try:
        return check_output_folder(folder, int(needed_bytes))
    except PathProblem as exc:
        raise SceneError(f"{source}: {key}: {exc}; expected a folder that can be written") from None
