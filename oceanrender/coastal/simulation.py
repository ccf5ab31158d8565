"""Running a coastal simulation for a scene: per-frame fields on disk, checkpoints, exact resume.

The simulation is sequential; its products are files, so that rendering (and
any number of render workers) reads the frames' fields instead of recomputing
them, and so that a killed run resumes from its last checkpoint:

* ``frame_NNNN.npz`` — float64 arrays ``h``, ``hu``, ``hv`` (depth [m],
  discharges [m² s⁻¹]) and ``bed`` [m] at the frame's time, plus ``t`` [s]
  (scene time: frame / fps) and the grid (``dx``, ``dy``, ``x0``, ``y0``) [m];
* ``frame_NNNN.exr`` — the same as float32 channels ``h``, ``eta`` (surface
  elevation, bed where dry), ``u``, ``v`` [m s⁻¹] and ``bed``, with metadata;
* ``checkpoint.npz`` — the solver state (``h``, ``hu``, ``hv``, ``t`` = τ [s])
  at a stop of the schedule below;
* ``simulation.json`` — the settings the files were made with (a changed
  [coastal] or [ocean] section, fps or :data:`STORE_VERSION` starts the
  simulation anew).

Every file is written atomically (temporary name, then rename). The solver
steps exactly onto each stop (its last step before a stop is shortened), so
the stored surface *is* the surface at the frame time: no interpolation in
time is needed.

The simulation clock τ [s] starts at 0 ``spinup`` seconds before frame 0:
τ = spinup + t, t = frame / fps.

**Resume is exact** (bit for bit, fields and EXRs): the adaptive time steps
depend on where the solver must stop, so every run stops at the same canonical
schedule, :func:`stop_times`, a pure function of the scene — every frame time
τ(f) for f = 0, 1, 2, … (stored or not, wanted or not) and the fixed checkpoint
times k · checkpoint_interval between them. Checkpoints are only written at
stops of that schedule, and a run resumes from one only when it lies on the
schedule at or before the first frame to compute (else from τ = 0), so a
resumed run makes the same sequence of :meth:`~.swe.ShallowWaterSolver.advance`
calls, from the same state, as an uninterrupted one. A frame counts as stored
only when its ``.npz`` and (with EXRs) its ``.exr`` both read back; an EXR lost
after its ``.npz`` was written is rewritten from the ``.npz`` by the function
that writes it during the simulation (:func:`write_frame_exr`), so its bytes
are those of an uninterrupted run.
"""

from __future__ import annotations

import bisect
import hashlib
import json
import time
import zipfile
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

import numpy as np

from ..io.frames import atomic_path, read_exr
from ..io.frames import write_exr as write_exr_file
from ..io.paths import remove_stale_temporaries
from ..scene import arrays
from . import inputs
from .dg2d import DG2DParams
from .dg_coast import DGCoastSolver, P1State, corners_from_centres, p1_initial_state
from .swe import H_FLOOR, ShallowWaterSolver, SolverParams, State

#: Format version of the stored fields. 2: the canonical stop schedule (:func:`stop_times`);
#: stores of version 1 stopped elsewhere, so their fields differ and are recomputed.
STORE_VERSION = 2

#: Checkpoint times closer than this to a frame time are that frame's stop [s].
SAME_STOP_S = 1e-9

#: Arrays every frame ``.npz`` holds.
FIELD_KEYS = ("h", "hu", "hv", "bed", "t")

#: Channels every frame EXR holds.
EXR_CHANNELS = ("h", "eta", "u", "v", "bed")


def frame_time(coastal, fps: float, frame: int) -> float:
    """Simulation time τ = spinup + frame / fps [s] of a frame (``coastal``: the scene's [coastal] section)."""
    return coastal.spinup + frame / fps


def stop_times(coastal, fps: float, last_frame: int) -> list[tuple[float, int | None]]:
    """The canonical stops of the solver up to frame ``last_frame``: [(τ [s], frame or None)], increasing in τ.

    The stops are every frame time τ(f) = spinup + f / fps [s] for f = 0 … last_frame
    (all of them, whichever frames are wanted) and the checkpoint times
    k · checkpoint_interval [s], k = 1, 2, …, below τ(last_frame) (frame None);
    a checkpoint time within :data:`SAME_STOP_S` of a frame time is that frame's
    stop. The list for a later last frame starts with this one (the stops do
    not depend on where a run ends), so every run of a scene passes through the
    same stops, computed with the same floating-point operations.

    Parameters
    ----------
    coastal : CoastalSettings
        Its ``spinup`` [s] and ``checkpoint_interval`` [s].
    fps : float
        Frames per second [s⁻¹].
    last_frame : int
        The last frame the run needs, ≥ 0.
    """
    if last_frame < 0:
        raise ValueError(f"last_frame must be >= 0; got {last_frame}")
    frames = [frame_time(coastal, fps, f) for f in range(last_frame + 1)]
    stops: list[tuple[float, int | None]] = [(tau, f) for f, tau in enumerate(frames)]
    interval = coastal.checkpoint_interval
    k = 1
    while (tau := k * interval) < frames[-1] - SAME_STOP_S:
        i = bisect.bisect_left(frames, tau)
        near = [frames[j] for j in (i - 1, i) if 0 <= j < len(frames)]
        if all(abs(tau - other) > SAME_STOP_S for other in near):
            stops.append((tau, None))
        k += 1
    stops.sort(key=lambda stop: stop[0])
    return stops


def checkpoint_due(previous: float, tau: float, interval: float) -> bool:
    """Whether the stop τ [s] reached from the stop ``previous`` [s] passed a checkpoint time k · interval."""
    return int((tau + SAME_STOP_S) // interval) > int((previous + SAME_STOP_S) // interval)


def solver_for_scene(scene) -> tuple[ShallowWaterSolver | DGCoastSolver, np.ndarray, State]:
    """(solver, bed z_b [m], initial state at τ = 0) of the scene's [coastal] section.

    With ``scheme = "dg"`` the solver is :class:`.dg_coast.DGCoastSolver`, the bed its P1
    bed's cell means and the state a :class:`.dg_coast.P1State`."""
    coastal = scene.coastal
    dx, dy = coastal.spacing
    if coastal.scheme == "dg":
        return _dg_solver_for_scene(scene)
    params = SolverParams(dx=dx, dy=dy, order=coastal.order, cfl=coastal.cfl, h_min=coastal.h_min,
                          limiter=coastal.limiter, scheme=coastal.scheme,
                          manning=coastal.manning, boundaries=inputs.boundaries(coastal, scene.ocean))
    bed = arrays.bathymetry(coastal)
    h = arrays.initial_depth(coastal, bed)
    hu, hv = arrays.initial_discharges(coastal, h)
    state = State(h=h, hu=hu, hv=hv, t=0.0)
    return ShallowWaterSolver(bed, params), bed, state


def _dg_solver_for_scene(scene) -> tuple[DGCoastSolver, np.ndarray, P1State]:
    """:func:`solver_for_scene` for ``scheme = "dg"``."""
    coastal = scene.coastal
    dx, dy = coastal.spacing
    corners = corners_from_centres(arrays.bathymetry(coastal))
    tvb = {} if coastal.tvb_m is None else {"tvb_m": coastal.tvb_m}  # left out: DG2DParams' own M
    params = DG2DParams(dx=dx, dy=dy, cfl=coastal.cfl, limiter=coastal.limiter, h_dry=max(coastal.h_min, H_FLOOR),
                        manning=coastal.manning, boundaries=inputs.boundaries(coastal, scene.ocean), **tvb)
    solver = DGCoastSolver(corners, params)
    if coastal.initial_surface == "still":
        surface = coastal.still_level
    else:  # the file's surface per cell
        surface = arrays.initial_surface(coastal)
    u, v = arrays.initial_velocities(coastal)
    state = p1_initial_state(corners, surface, u, v, params.h_dry)
    return solver, solver.bed, state


def settings_digest(scene) -> str:
    """SHA-256 of everything the simulation depends on ([coastal] and [ocean] sections, fps, STORE_VERSION)."""
    payload = {"coastal": scene.coastal.model_dump(), "ocean": scene.ocean.model_dump(),
               "fps": scene.output.fps, "version": STORE_VERSION}
    return hashlib.sha256(json.dumps(payload, sort_keys=True, default=str).encode()).hexdigest()


def _atomic_save_npz(path: Path, **arrays) -> None:
    with atomic_path(path, ".npz") as tmp:
        np.savez(tmp, **arrays)


def frame_field_path(store: Path, frame: int) -> Path:
    """Path of a frame's ``.npz`` fields."""
    return Path(store) / f"frame_{frame:04d}.npz"


def frame_exr_path(store: Path, frame: int) -> Path:
    """Path of a frame's EXR."""
    return Path(store) / f"frame_{frame:04d}.exr"


def read_frame_fields(store: str | Path, frame: int) -> dict[str, np.ndarray]:
    """The stored fields of a frame (see the module docstring)."""
    with np.load(frame_field_path(Path(store), frame)) as data:
        return {key: data[key] for key in data.files}


def _fields_ok(path: Path, shape: tuple[int, int]) -> bool:
    """Whether a frame ``.npz`` opens, holds :data:`FIELD_KEYS` and its depth has the grid's shape (ny, nx)."""
    try:
        with np.load(path) as data:
            return all(key in data.files for key in FIELD_KEYS) and data["h"].shape == shape
    except (OSError, ValueError, EOFError, KeyError, zipfile.BadZipFile):
        return False


def _exr_ok(path: Path, shape: tuple[int, int]) -> bool:
    """Whether a frame EXR reads back with :data:`EXR_CHANNELS`, each of the grid's shape (ny, nx)."""
    if not path.is_file():
        return False
    try:
        channels, _ = read_exr(path)
    except Exception:  # noqa: BLE001 (any unreadable file means: write it again)
        return False
    return all(name in channels and channels[name].shape == shape for name in EXR_CHANNELS)


def write_frame_exr(path: Path, scene, frame: int, h: np.ndarray, hu: np.ndarray, hv: np.ndarray,
                    bed: np.ndarray) -> None:
    """Write a frame's EXR from its float64 fields h [m], hu, hv [m² s⁻¹] and bed [m], atomically.

    The only writer of frame EXRs, during the simulation and when an EXR is
    rewritten from its stored ``.npz``: the same fields give the same bytes.
    """
    coastal = scene.coastal
    dx, dy = coastal.spacing
    state = State(h=h, hu=hu, hv=hv)
    u, v = state.velocities(coastal.h_min)
    wet = state.h > coastal.h_min
    write_exr_file(path, {"h": state.h, "eta": np.where(wet, bed + state.h, bed), "u": u, "v": v, "bed": bed},
                   {"scene": scene.name, "frame": frame, "time_s": frame / scene.output.fps, "dx_m": dx,
                    "dy_m": dy, "x0_m": coastal.origin[0], "y0_m": coastal.origin[1], "h_min_m": coastal.h_min,
                    "channels": "h depth [m]; eta surface [m] (bed where dry); u, v [m/s]; bed [m]"})


def _rewrite_exr(store: Path, scene, frame: int) -> None:
    fields = read_frame_fields(store, frame)
    write_frame_exr(frame_exr_path(store, frame), scene, frame, fields["h"], fields["hu"], fields["hv"],
                    fields["bed"])


def _resume_state(checkpoint: Path, schedule: list[tuple[float, int | None]], tau_first: float,
                  shape: tuple[int, int]) -> State | None:
    """The checkpoint's state if it lies on the schedule at or before τ_first [s] and reads back; else None."""
    if not checkpoint.is_file():
        return None
    try:
        with np.load(checkpoint) as data:
            t = float(data["t"])
            if t > tau_first or t not in {tau for tau, _ in schedule}:
                return None
            fields = dict(h=data["h"].copy(), hu=data["hu"].copy(), hv=data["hv"].copy(), t=t)
            state = P1State(**fields, slopes=data["slopes"].copy()) if "slopes" in data.files else State(**fields)
    except (OSError, ValueError, EOFError, KeyError, zipfile.BadZipFile):
        return None
    return state if state.h.shape == shape else None


@dataclass
class SimulationReport:
    """What a run did: frames simulated, found and with their EXR rewritten; the resume τ [s]; cell updates; seconds."""

    simulated: list[int]
    found: list[int]
    resumed_from: float | None
    cell_updates: int
    seconds: float
    exr_rewritten: list[int] = field(default_factory=list)


def run_simulation(scene, store: str | Path, frames: tuple[int, int] | None = None,
                   write_exr: bool = True, on_progress: Callable[[float, float], None] | None = None
                   ) -> SimulationReport:
    """Simulate the scene's coastal zone up to the last missing frame, storing every wanted frame's fields.

    Frames whose ``.npz`` (and, with ``write_exr``, EXR) are already stored
    with the same settings are kept; a frame whose ``.npz`` is stored but whose
    EXR is missing or unreadable gets its EXR rewritten from the ``.npz``. The
    solver stops at the canonical :func:`stop_times`, from ``checkpoint.npz``
    when that lies on them at or before the first missing frame's τ, else from
    τ = 0, so the fields are bit-identical to an uninterrupted run's.
    ``on_progress(τ, τ_end)`` is called after each stop [s].
    """
    coastal = scene.coastal
    store = Path(store)
    store.mkdir(parents=True, exist_ok=True)
    remove_stale_temporaries(store)  # only those of ended processes: a second run may share the store
    start, end = frames or scene.output.frames
    digest = settings_digest(scene)
    meta_path = store / "simulation.json"
    if meta_path.is_file():
        try:
            same = json.loads(meta_path.read_text()).get("digest") == digest
        except (OSError, ValueError):
            same = False
        if not same:  # settings changed: everything stored is stale
            for old in list(store.glob("frame_*.npz")) + list(store.glob("frame_*.exr")) + [store / "checkpoint.npz"]:
                old.unlink(missing_ok=True)
    with atomic_path(meta_path, ".json") as tmp:
        tmp.write_text(json.dumps({"digest": digest, "scene": scene.name, "coastal": coastal.model_dump(),
                                   "version": STORE_VERSION}, indent=2, default=str))

    shape = coastal.shape
    fields_ok = {f: _fields_ok(frame_field_path(store, f), shape) for f in range(start, end)}
    broken_exr = [f for f in range(start, end)
                  if write_exr and fields_ok[f] and not _exr_ok(frame_exr_path(store, f), shape)]
    for frame in broken_exr:
        _rewrite_exr(store, scene, frame)
    found = [f for f in range(start, end) if fields_ok[f]]
    missing = [f for f in range(start, end) if not fields_ok[f]]
    report = SimulationReport(simulated=[], found=found, resumed_from=None, cell_updates=0, seconds=0.0,
                              exr_rewritten=broken_exr)
    if not missing:
        return report

    tic = time.perf_counter()
    solver, bed, state = solver_for_scene(scene)
    fps = scene.output.fps
    schedule = stop_times(coastal, fps, missing[-1])
    tau_end = schedule[-1][0]
    checkpoint = store / "checkpoint.npz"
    resumed = _resume_state(checkpoint, schedule, frame_time(coastal, fps, missing[0]), shape)
    if resumed is not None:
        state = resumed
        report.resumed_from = state.t
    dx, dy = coastal.spacing
    grid = {"dx": dx, "dy": dy, "x0": coastal.origin[0], "y0": coastal.origin[1]}
    wanted = set(missing)
    previous = state.t
    for tau, frame in schedule:
        if tau < state.t:
            continue  # before the checkpoint the run resumes from (a stop at it stores its frame from it)
        state = solver.advance(state, tau)
        if frame in wanted:
            _atomic_save_npz(frame_field_path(store, frame), h=state.h, hu=state.hu, hv=state.hv, bed=bed,
                             t=frame / fps, **grid)
            if write_exr:
                write_frame_exr(frame_exr_path(store, frame), scene, frame, state.h, state.hu, state.hv, bed)
            report.simulated.append(frame)
        if checkpoint_due(previous, tau, coastal.checkpoint_interval) or tau == tau_end:
            extra = {"slopes": state.slopes} if isinstance(state, P1State) else {}
            _atomic_save_npz(checkpoint, h=state.h, hu=state.hu, hv=state.hv, t=state.t, **extra)
        previous = tau
        if on_progress:
            on_progress(state.t, tau_end)
    report.cell_updates = solver.cell_updates
    report.seconds = time.perf_counter() - tic
    return report
