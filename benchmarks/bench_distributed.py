"""Dask overhead per frame and frames per hour: single process vs LocalCluster, side by side in one run.

Run: ``.venv/bin/python benchmarks/bench_distributed.py [SCENE] [--frames N]``
(default: the default scene at its preview settings, 6 timed frames per
configuration). Renders into temporary folders. Three configurations, each
warmed up first (scene load and JIT compilation are reported apart, as
setup), then timed on the same N frames:

1. ``single``: this process, :func:`oceanrender.pipeline.Sequence` + atomic
   writes, Dr.Jit on all cores (what ``oceanrender render`` does);
2. ``dask ×1``: a LocalCluster of one worker process with all cores, frames
   as tasks, the client writing (what ``--workers 1`` does), one frame at a
   time, alternating with 1. frame by frame: the per-frame Dask overhead is
   the paired difference of wall times as a share of the single process's
   frame time; the worker-side task time is also recorded, so the time on
   the client beyond the task (submission, scheduling, transfer of the
   frame, writing) is measured directly too;
3. ``dask ×W``: a LocalCluster of W worker processes (default 2), each
   with cores // W Dr.Jit threads (what ``--workers W`` does).

Prints a Markdown table for BENCHMARKS.md.
"""

from __future__ import annotations

import argparse
import os
import platform
import statistics
import tempfile
import time
import warnings
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def warm_workers(client, scene, variant, spp, size, threads) -> float:
    """Load the scene and compile its kernels on every worker (a frame outside the timed range); seconds."""
    from oceanrender.production.distributed import render_frame_task

    tic = time.perf_counter()
    futures = [client.submit(render_frame_task, scene, variant, spp, size, None, 1000 + i, threads,
                             workers=[address], allow_other_workers=False, pure=False)
               for i, address in enumerate(client.scheduler_info()["workers"])]
    client.gather(futures)
    return time.perf_counter() - tic


def time_cluster(scene, variant, workers: int, threads: int, frames: range, tmp: Path) -> dict:
    from dask.distributed import Client

    from oceanrender.production.distributed import local_cluster, render_distributed

    size = tuple(scene.output.resolution)
    tic = time.perf_counter()
    with local_cluster(workers) as cluster, Client(cluster) as client:
        start = time.perf_counter() - tic
        setup = warm_workers(client, scene, variant, scene.output.spp, size, threads)
        tasks = []
        tic = time.perf_counter()
        report = render_distributed(scene, tmp, variant, client, frames=(frames.start, frames.stop),
                                    threads=threads, on_result=tasks.append)
        wall = time.perf_counter() - tic
    assert sorted(report.rendered) == list(frames) and not report.failed
    computed = sum(t.task_seconds for t in tasks)
    stages = {stage: sum(t.rendered.seconds[stage] for t in tasks) / len(frames) for stage in tasks[0].rendered.seconds}
    return {"stages": stages, "wall": wall, "per_frame": wall / len(frames), "cluster_start": start, "setup": setup,
            "task_per_frame": computed / len(frames), "write_per_frame": report.stage_seconds["write"] / len(frames)}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scene", nargs="?", default=str(ROOT / "scenes" / "open_ocean.toml"))
    parser.add_argument("--frames", type=int, default=6, help="timed frames per configuration")
    parser.add_argument("--workers", type=int, default=2, help="worker processes of the multi-worker cluster")
    args = parser.parse_args()
    warnings.filterwarnings("ignore", message=".*Matplotlib.*")

    from oceanrender.scene import load_scene
    from oceanrender.pipeline import STAGES, Sequence, frame_paths
    from oceanrender.production.distributed import worker_threads
    from oceanrender.runtime.variants import activate_variant

    scene = load_scene(args.scene)
    variant = activate_variant(scene.render.variant).variant
    cores = os.cpu_count() or 1
    frames = range(1, args.frames + 1)
    width, height = scene.output.resolution
    print(f"# {Path(args.scene).name}: {width}x{height}, {scene.output.spp} spp, variant {variant}, "
          f"{args.frames} timed frames per configuration, {cores} cores, {platform.processor() or platform.machine()}, "
          f"load average at start {os.getloadavg()[0]:.2f}")

    results = {}
    pairs = []
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        tic = time.perf_counter()
        sequence = Sequence(scene, variant)
        sequence.render_frame(0, frame_paths(tmp / "single", 0), {s: 0.0 for s in STAGES})
        setup = time.perf_counter() - tic
        seconds = {s: 0.0 for s in STAGES}
        # Per-frame overhead: single process and a one-worker cluster (both warm, same cores), frame by
        # frame in alternation, so that the machine's drift over the run falls on both alike.
        from dask.distributed import Client

        from oceanrender.production.distributed import local_cluster, render_distributed

        size = tuple(scene.output.resolution)
        with local_cluster(1) as cluster, Client(cluster) as client:
            dask_setup = warm_workers(client, scene, variant, scene.output.spp, size, cores)
            tasks = []
            for frame in frames:
                tic = time.perf_counter()
                sequence.render_frame(frame, frame_paths(tmp / "single", frame), seconds)
                single_s = time.perf_counter() - tic
                tic = time.perf_counter()
                render_distributed(scene, tmp / "dask1", variant, client, frames=(frame, frame + 1), threads=cores,
                                   on_result=tasks.append)
                pairs.append((single_s, time.perf_counter() - tic, tasks[-1].task_seconds))
        del sequence
        single_wall = sum(p[0] for p in pairs)
        dask_wall = sum(p[1] for p in pairs)
        results["single"] = {"stages": {k: v / len(frames) for k, v in seconds.items() if k != "write"},
                             "wall": single_wall, "per_frame": single_wall / len(frames), "cluster_start": 0.0,
                             "setup": setup, "task_per_frame": single_wall / len(frames),
                             "write_per_frame": seconds["write"] / len(frames)}
        results["dask ×1"] = {"stages": {k: sum(t.rendered.seconds[k] for t in tasks) / len(frames)
                                         for k in tasks[0].rendered.seconds},
                              "wall": dask_wall, "per_frame": dask_wall / len(frames), "cluster_start": float("nan"),
                              "setup": dask_setup, "task_per_frame": sum(p[2] for p in pairs) / len(frames),
                              "write_per_frame": float("nan")}
        results[f"dask ×{args.workers}"] = time_cluster(scene, variant, args.workers,
                                                        worker_threads(args.workers, cores), frames,
                                                        tmp / f"dask{args.workers}")

    single = results["single"]["per_frame"]
    print()
    print("| configuration | s / frame (wall) | frames / hour | vs single | worker task s / frame | "
          "client write s / frame | setup s (load + JIT, per worker in parallel) | cluster start s |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    for name, r in results.items():
        print(f"| {name} | {r['per_frame']:.2f} | {3600 / r['per_frame']:.0f} | {single / r['per_frame']:.2f}× | "
              f"{r['task_per_frame']:.2f} | {r['write_per_frame']:.3f} | {r['setup']:.1f} | {r['cluster_start']:.1f} |")
    print()
    print("Per frame on the process that rendered it [s]: " + "; ".join(
        f"{name}: " + ", ".join(f"{k} {v:.2f}" for k, v in r["stages"].items() if v) for name, r in results.items()))
    ratios = sorted((d - t) / t for t, d, _ in pairs)
    beyond = sorted((d - task) for _, d, task in pairs)
    print()
    print("Dask overhead per frame, one worker vs this process, frame by frame in alternation "
          f"({len(pairs)} pairs): (t_dask − t_single) / t_single median {100 * statistics.median(ratios):+.2f} % "
          f"(range {100 * ratios[0]:+.2f} … {100 * ratios[-1]:+.2f} %); time on the client beyond the worker's "
          f"task (submit, schedule, transfer, write): median {statistics.median(beyond):.3f} s / frame = "
          f"{100 * statistics.median(beyond) / results['single']['per_frame']:.2f} % of a frame")


if __name__ == "__main__":
    main()
