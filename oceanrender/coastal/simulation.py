"""Running a coastal simulation for a scene: per-frame fields on disk, checkpoints, resume.

The simulation is sequential; its products are files, so that rendering (and
any number of render workers) reads the frames' fields instead of recomputing
them, and so that a killed run resumes from its last checkpoint:

* ``frame_NNNN.npz`` — float64 arrays ``h``, ``hu``, ``hv`` (depth [m],
  discharges [m² s⁻¹]) and ``bed`` [m] at the frame's time, plus ``t`` [s]
  (scene time: frame / fps) and the grid (``dx``, ``dy``, ``x0``, ``y0``) [m];
* ``frame_NNNN.exr`` — the same as float32 channels ``h``, ``eta`` (surface
  elevation, bed where dry), ``u``, ``v`` [m s⁻¹] and ``bed``, with metadata;
* ``checkpoint.npz`` — the solver state at the latest frame (or checkpoint
  time) with the frame it belongs to;
* ``simulation.json`` — the settings the files were made with (a changed
  [coastal] or [ocean] section starts the simulation anew).

Every file is written atomically (temporary name, then rename). The solver
steps exactly onto each frame time (its last step before a frame is shortened),
so the stored surface *is* the surface at the frame time: no interpolation in
time is needed.

The simulation clock τ starts at 0 ``spinup`` seconds before frame 0:
τ = spinup + t, t = frame / fps.
"""

from __future__ import annotations

import hashlib
import json
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Callable

import numpy as np

from ..io.frames import atomic_path
from ..scene import arrays
from . import inputs
from .swe import ShallowWaterSolver, SolverParams, State

#: Format version of the stored fields.
STORE_VERSION = 1


def solver_for_scene(scene) -> tuple[ShallowWaterSolver, np.ndarray, State]:
    """(solver, bed z_b [m], initial state at τ = 0) of the scene's [coastal] section."""
    coastal = scene.coastal
    spectrum = None
    if coastal.waves == "spectrum":
        from ..waves.sea import directional_spectrum  # noqa: PLC0415

        spectrum = directional_spectrum(scene.ocean)
    dx, dy = coastal.spacing
    params = SolverParams(dx=dx, dy=dy, order=coastal.order, cfl=coastal.cfl, h_min=coastal.h_min,
                          limiter=coastal.limiter,
                          manning=coastal.manning, boundaries=inputs.boundaries(coastal, spectrum))
    bed = arrays.bathymetry(coastal)
    h = arrays.initial_depth(coastal, bed)
    state = State(h=h, hu=np.zeros_like(h), hv=np.zeros_like(h), t=0.0)
    return ShallowWaterSolver(bed, params), bed, state


def settings_digest(scene) -> str:
    """SHA-256 of everything the simulation depends on (the [coastal] and [ocean] sections, fps)."""
    payload = {"coastal": scene.coastal.model_dump(), "ocean": scene.ocean.model_dump(),
               "fps": scene.output.fps, "version": STORE_VERSION}
    return hashlib.sha256(json.dumps(payload, sort_keys=True, default=str).encode()).hexdigest()


def _atomic_save_npz(path: Path, **arrays) -> None:
    with atomic_path(path, ".npz") as tmp:
        np.savez(tmp, **arrays)


def frame_field_path(store: Path, frame: int) -> Path:
    """Path of a frame's ``.npz`` fields."""
    return Path(store) / f"frame_{frame:04d}.npz"


def read_frame_fields(store: str | Path, frame: int) -> dict[str, np.ndarray]:
    """The stored fields of a frame (see the module docstring)."""
    with np.load(frame_field_path(Path(store), frame)) as data:
        return {key: data[key] for key in data.files}


def _fields_ok(path: Path) -> bool:
    try:
        with np.load(path) as data:
            return all(key in data.files for key in ("h", "hu", "hv", "bed", "t"))
    except (OSError, ValueError, EOFError):
        return False


@dataclass
class SimulationReport:
    """What a run did: frames simulated and found, cell updates, seconds."""

    simulated: list[int]
    found: list[int]
    resumed_from: float | None
    cell_updates: int
    seconds: float


def run_simulation(scene, store: str | Path, frames: tuple[int, int] | None = None,
                   write_exr: bool = True, on_progress: Callable[[float, float], None] | None = None
                   ) -> SimulationReport:
    """Simulate the scene's coastal zone up to the last frame, storing every frame's fields.

    Frames whose fields are already stored (with the same settings) are kept;
    the run resumes from ``checkpoint.npz`` when it is ahead of the first
    missing frame. ``on_progress(τ, τ_end)`` is called after each frame and
    checkpoint [s].
    """
    from ..io.frames import write_exr as write_exr_file  # noqa: PLC0415

    coastal = scene.coastal
    store = Path(store)
    store.mkdir(parents=True, exist_ok=True)
    for stale in store.glob(".*.tmp*"):
        stale.unlink(missing_ok=True)
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

    found = [f for f in range(start, end) if _fields_ok(frame_field_path(store, f))]
    missing = [f for f in range(start, end) if f not in found]
    report = SimulationReport(simulated=[], found=found, resumed_from=None, cell_updates=0, seconds=0.0)
    if not missing:
        return report

    tic = time.perf_counter()
    solver, bed, state = solver_for_scene(scene)
    fps = scene.output.fps

    def tau(frame: int) -> float:
        return coastal.spinup + frame / fps

    checkpoint = store / "checkpoint.npz"
    if checkpoint.is_file():
        try:
            with np.load(checkpoint) as data:
                if float(data["t"]) <= tau(missing[0]) + 1e-9:
                    state = State(h=data["h"].copy(), hu=data["hu"].copy(), hv=data["hv"].copy(), t=float(data["t"]))
                    report.resumed_from = state.t
        except (OSError, ValueError, KeyError, EOFError):
            pass
    dx, dy = coastal.spacing
    grid = {"dx": dx, "dy": dy, "x0": coastal.origin[0], "y0": coastal.origin[1]}
    last_checkpoint = state.t
    for frame in range(missing[0], end):
        target = tau(frame)
        # Checkpoints between frames during a long spin-up.
        while target - state.t > coastal.checkpoint_interval:
            state = solver.advance(state, state.t + coastal.checkpoint_interval)
            _atomic_save_npz(checkpoint, h=state.h, hu=state.hu, hv=state.hv, t=state.t)
            last_checkpoint = state.t
            if on_progress:
                on_progress(state.t, tau(end - 1))
        state = solver.advance(state, target)
        t_scene = frame / fps
        if frame in missing:
            _atomic_save_npz(frame_field_path(store, frame), h=state.h, hu=state.hu, hv=state.hv, bed=bed,
                             t=t_scene, **grid)
            if write_exr:
                u, v = state.velocities(coastal.h_min)
                wet = state.h > coastal.h_min
                write_exr_file(store / f"frame_{frame:04d}.exr",
                               {"h": state.h, "eta": np.where(wet, bed + state.h, bed), "u": u, "v": v, "bed": bed},
                               {"scene": scene.name, "frame": frame, "time_s": t_scene, "dx_m": dx, "dy_m": dy,
                                "x0_m": grid["x0"], "y0_m": grid["y0"], "h_min_m": coastal.h_min,
                                "channels": "h depth [m]; eta surface [m] (bed where dry); u, v [m/s]; bed [m]"})
            report.simulated.append(frame)
        if state.t - last_checkpoint >= coastal.checkpoint_interval or frame == end - 1:
            _atomic_save_npz(checkpoint, h=state.h, hu=state.hu, hv=state.hv, t=state.t)
            last_checkpoint = state.t
        if on_progress:
            on_progress(state.t, tau(end - 1))
    report.cell_updates = solver.cell_updates
    report.seconds = time.perf_counter() - tic
    return report
