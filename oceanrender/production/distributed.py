"""Frames on a Dask cluster: one task per frame, the writer on the client.

A sequence's frames are independent: any worker computes any frame from
(scene, seed, time) alone — the open sea's geometry from the seeded spectrum
at t = frame / fps, a coastal frame from the simulation's stored fields —
so each frame is one ``dask.distributed`` task. The design, and why:

* **One Mitsuba scene per worker process.** Loading a scene compiles its
  kernels (10–20 s here); a worker keeps the :class:`~oceanrender.pipeline.Sequence`
  it built for the first frame it was given in a process-wide cache and only
  moves the water mesh for the next (the cache is keyed by the scene's full
  settings, so a new scene replaces it).
* **Workers return frames; the client writes them.** A task returns the
  frame in memory (:class:`~oceanrender.pipeline.RenderedFrame`, 1.4 MB at
  320×180); the client writes its EXR and PNG atomically. Workers need no
  write access to the output folder, a frame is written by one process
  only, and a task re-run after its worker died cannot leave a second or
  half-written copy: every frame ends up on disk exactly once.
* **Dead workers.** The scheduler re-runs the tasks of a worker that died on
  the other workers (a worker's nanny also restarts it); a task that killed
  ``distributed.scheduler.allowed-failures + 1`` workers (default 4) is
  reported as failed and the other frames go on. A killed *client* loses
  only the frames in flight: the next run skips every frame already intact
  (:func:`~oceanrender.io.frames.frame_is_complete`).
* **Coastal scenes.** The sequential shallow-water simulation runs once,
  on the client, before any frame is submitted (or resumes from its
  checkpoints); workers read its per-frame fields from the store, so on a
  multi-machine cluster the output folder must be on a filesystem the
  workers share (the same path everywhere).
* **Threads.** One task at a time per worker process (Mitsuba's own thread
  pool renders the frame); on a LocalCluster each worker's Dr.Jit pool gets
  ``cores // workers`` threads so workers do not oversubscribe the cores.

Dask is imported lazily, inside the functions.
"""

from __future__ import annotations

import json
import os
import time
import uuid
from dataclasses import dataclass
from pathlib import Path
from typing import Callable

from ..scene import Scene

#: This worker process's loaded sequence: (cache key, Sequence). One at a time.
_WORKER_SEQUENCE: tuple[str, object] | None = None
#: This worker process's activated Mitsuba variant.
_WORKER_VARIANT: str | None = None


@dataclass(frozen=True)
class FrameResult:
    """What a frame task returns to the client.

    Attributes
    ----------
    rendered : RenderedFrame   The finished frame in memory.
    worker_pid : int           Process that computed it.
    setup_seconds : float      Time this task spent loading the worker's scene [s] (0 when reused).
    task_seconds : float       Wall time of the whole task on the worker [s].
    """

    rendered: object
    worker_pid: int
    setup_seconds: float
    task_seconds: float


def sequence_key(scene: Scene, variant: str, spp: int, resolution: tuple[int, int], store: str | None) -> str:
    """The cache key of a worker's loaded sequence: everything a frame's pixels depend on except the frame.

    The scene's frame range and output folder are left out: a worker keeps its
    scene across runs of other frames of the same sequence.
    """
    settings = scene.model_dump(mode="json")
    settings["output"].pop("frames"), settings["output"].pop("directory")
    return "|".join((json.dumps(settings, sort_keys=True), variant, str(int(spp)), f"{resolution[0]}x{resolution[1]}", str(store)))


def _activate_on_worker(variant: str, threads: int | None) -> None:
    global _WORKER_VARIANT
    if _WORKER_VARIANT != variant:
        from ..runtime.variants import activate_variant  # noqa: PLC0415

        info = activate_variant(variant)
        if info.variant != variant:  # pragma: no cover (activate_variant refuses a forced variant it cannot run)
            raise RuntimeError(f"worker could not activate Mitsuba variant {variant!r}")
        _WORKER_VARIANT = variant
    if threads:
        import drjit as dr  # noqa: PLC0415

        if dr.thread_count() != int(threads):
            dr.set_thread_count(int(threads))


def render_frame_task(scene: Scene, variant: str, spp: int, resolution: tuple[int, int], store: str | None,
                      frame: int, threads: int | None = None) -> FrameResult:
    """Compute one frame on a worker (the Dask task): reuse the worker's loaded scene when it is this one.

    Parameters
    ----------
    scene : Scene          The whole scene (validated on the client).
    variant : str          The concrete Mitsuba variant the client chose (e.g. ``"llvm_ad_spectral"``).
    spp : int              Samples per pixel.
    resolution : (int, int) Image size (width, height) [px].
    store : str or None    A coastal scene's simulation store (absolute path), else None.
    frame : int            Frame number; t = frame / fps [s].
    threads : int or None  Dr.Jit worker threads of this process (None: Dr.Jit's default, all cores).
    """
    global _WORKER_SEQUENCE
    tic = time.perf_counter()
    _activate_on_worker(variant, threads)
    from ..pipeline import Sequence  # noqa: PLC0415

    key = sequence_key(scene, variant, spp, resolution, store)
    setup = 0.0
    if _WORKER_SEQUENCE is None or _WORKER_SEQUENCE[0] != key:
        _WORKER_SEQUENCE = None  # free the previous scene before loading the next
        sequence = Sequence(scene, variant, spp=spp, resolution=resolution, first_frame=frame, coastal_store=store)
        _WORKER_SEQUENCE = (key, sequence)
        setup = time.perf_counter() - tic
    rendered = _WORKER_SEQUENCE[1].compute_frame(frame)
    return FrameResult(rendered=rendered, worker_pid=os.getpid(), setup_seconds=setup,
                       task_seconds=time.perf_counter() - tic)


def worker_threads(workers: int, cores: int | None = None) -> int:
    """Dr.Jit threads per worker process on one machine: ``cores // workers``, at least 1."""
    if workers < 1:
        raise ValueError(f"need at least one worker, got {workers}")
    return max(1, (cores or os.cpu_count() or 1) // workers)


#: Dask settings for render workers (also in ``scripts/dask.yaml`` for ``dask worker`` on other machines).
#: Dask's nanny sets ``MALLOC_TRIM_THRESHOLD_=65536`` in every worker's environment; glibc then
#: switches off its dynamic mmap threshold, every large array is mmap'ed and unmapped afresh,
#: and the frame's geometry stage (numpy on ~230k vertices) ran 2.7× slower (0.62 → 1.71 s
#: per frame, measured). ``None`` removes the variable; the thread limits for BLAS stay.
WORKER_CONFIG = {"distributed.nanny.pre-spawn-environ.MALLOC_TRIM_THRESHOLD_": None}


def local_cluster(workers: int):
    """A ``LocalCluster`` of ``workers`` processes, one task thread each, no dashboard, quiet logs.

    Its workers get :data:`WORKER_CONFIG`.
    """
    import logging  # noqa: PLC0415

    import dask  # noqa: PLC0415
    from dask.distributed import LocalCluster  # noqa: PLC0415

    if workers < 1:
        raise ValueError(f"need at least one worker, got {workers}")
    with dask.config.set(WORKER_CONFIG):
        return LocalCluster(n_workers=int(workers), threads_per_worker=1, processes=True, dashboard_address=None,
                            silence_logs=logging.ERROR)


@dataclass(frozen=True)
class FailedFrame:
    """A frame whose task failed on every try: the frame and the error, in one line."""

    frame: int
    error: str


def render_distributed(scene: Scene, out_dir: str | Path, variant: str, client, frames: tuple[int, int] | None = None,
                       spp: int | None = None, resolution: tuple[int, int] | None = None,
                       threads: int | None = None,
                       on_frame: Callable[[int, float, bool], None] | None = None,
                       on_result: Callable[[FrameResult], None] | None = None):
    """Render frames [start, end) of ``scene`` into ``out_dir`` on the Dask cluster of ``client``.

    Same files and resume rule as :func:`~oceanrender.pipeline.render_sequence`
    (frames already intact are skipped, each file is written atomically).
    ``on_frame(frame, seconds, skipped)`` is called once per frame as it is
    written (or found complete): one progress bar for the whole cluster.
    ``on_result(result)`` sees each :class:`FrameResult` before it is written.

    Returns
    -------
    SequenceReport
        ``rendered`` in completion order; ``stage_seconds`` summed over the
        workers' tasks (``"write"``: the client's); ``setup_seconds`` summed
        over the workers' scene loads; ``failed``: the :class:`FailedFrame`\\ s.
    """
    from dask.distributed import as_completed  # noqa: PLC0415

    from ..pipeline import SequenceReport, frame_paths, frames_to_render, simulate_coastal, write_frame  # noqa: PLC0415

    size = tuple(resolution or scene.output.resolution)
    spp = int(spp or scene.output.spp)
    report = SequenceReport(variant=variant)
    todo = frames_to_render(out_dir, frames or scene.output.frames, size, report, on_frame, scene.output.passes)
    if not todo:
        return report
    store = simulate_coastal(scene, out_dir, todo, report)
    store = None if store is None else str(store)
    token = uuid.uuid4().hex[:8]
    futures = {}
    for index, frame in enumerate(todo):
        future = client.submit(render_frame_task, scene, variant, spp, size, store, frame, threads,
                               key=f"oceanrender-frame-{frame:05d}-{token}", pure=False, priority=-index)
        futures[future] = frame
    for future in as_completed(list(futures)):
        frame = futures.pop(future)
        try:
            result = future.result()
        except Exception as exc:  # noqa: BLE001 (KilledWorker, or the task's own error: report, go on)
            report.failed.append(FailedFrame(frame, f"{type(exc).__name__}: {exc}".splitlines()[0]))
            continue
        finally:
            future.release()
        if on_result:
            on_result(result)
        rendered = result.rendered
        write = write_frame(frame_paths(out_dir, frame), rendered)
        for stage, value in rendered.seconds.items():
            report.stage_seconds[stage] += value
        report.stage_seconds["write"] += write
        report.setup_seconds += result.setup_seconds
        report.repaired_pixels += rendered.repaired
        report.rendered.append(frame)
        if on_frame:
            on_frame(frame, result.task_seconds + write, False)
    return report
