"""Throughput of the shallow-water core: cell-updates per second at 1000 × 1000, first and second order.

Run: ``.venv/bin/python benchmarks/bench_swe_core.py [--n 1000] [--steps 20] [--repeats 3]``.

The case is a circular dam break on a sloping beach (:func:`beach_dam_break`): a
1000 m × 1000 m basin, 1 m cells, bed rising from −10 m in the west to +5 m in the
east (dry land over the last third, covered by the h_min film), a 4 m high column of
water of radius 100 m released at rest, walls on all sides. It has deep and dry
cells, shoreline and a moving bore, so every branch of the kernels runs.

Each order is warmed up (compilation and a few steps), then timed over ``--steps``
steps of :meth:`ShallowWaterSolver.advance` (adaptive Δt, the fused CFL reduction
included), repeated ``--repeats`` times; the table gives the median and the best
wall-clock rate, and the rate per CPU-second of the process (all its threads), which
is what the same code reaches per core when it has the cores to itself. Threads:
``numba.get_num_threads()`` row blocks (set NUMBA_NUM_THREADS to change); ``--threads 1``
forces one block. The load average before each order is printed: other work on the
two cores lowers the wall-clock rate. Prints a Markdown table for docs/coastal.md.
"""

from __future__ import annotations

import argparse
import os
import platform
import time

import numba
import numpy as np

from oceanrender.coastal import swe
from oceanrender.coastal.swe import ShallowWaterSolver, SolverParams, lake_at_rest


def beach_dam_break(n: int, h_min: float = 1e-3):
    """Bed [m], initial state and cell size [m] of the benchmark case on an n × n grid."""
    dx = 1000.0 / n
    x = (np.arange(n) + 0.5) * dx
    y = (np.arange(n) + 0.5) * dx
    bed = np.broadcast_to(-10.0 + 15.0 * x / 1000.0, (n, n)).copy()
    state = lake_at_rest(bed, 0.0, h_min)
    r = np.hypot(x[None, :] - 400.0, y[:, None] - 500.0)
    state.h += np.where(r < 100.0, 4.0, 0.0)
    return bed, state, dx


def measure(order: int, n: int, steps: int, repeats: int) -> dict:
    bed, state0, dx = beach_dam_break(n)
    solver = ShallowWaterSolver(bed, SolverParams(dx=dx, dy=dx, order=order, cfl=0.45))
    warm = state0.copy()
    solver.advance(warm, 1e9, max_steps=3)  # compile + warm caches
    times, cpu = [], []
    load = os.getloadavg()[0]
    for _ in range(repeats):
        state = warm.copy()
        before = solver.cell_updates
        start, start_cpu = time.perf_counter(), time.process_time()
        solver.advance(state, 1e9, max_steps=steps)
        elapsed, elapsed_cpu = time.perf_counter() - start, time.process_time() - start_cpu
        times.append(elapsed / (solver.cell_updates - before))
        cpu.append(elapsed_cpu / (solver.cell_updates - before))
    per_update = np.array(times)
    return {
        "order": order,
        "load": load,
        "median": 1.0 / np.median(per_update),
        "best": 1.0 / per_update.min(),
        "per_cpu": 1.0 / np.median(cpu),
        "step_ms": np.median(per_update) * n * n * 1e3,
        "sim_dt": state.t / (steps + 3),
        "min_h": float(state.h.min()),
        "finite": bool(np.isfinite(state.h).all()),
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=1000)
    parser.add_argument("--steps", type=int, default=20)
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--orders", type=int, nargs="+", default=[1, 2])
    parser.add_argument("--threads", type=int, default=None, help="1: one row block (no threads)")
    args = parser.parse_args()
    if args.threads == 1:
        swe.PARALLEL_MIN_CELLS = 1 << 62
    elif args.threads:
        numba.set_num_threads(args.threads)
    print(
        f"{platform.processor() or platform.machine()}, {os.cpu_count()} CPUs, numba {numba.__version__}, "
        f"{1 if args.threads == 1 else numba.get_num_threads()} row blocks/threads, "
        f"grid {args.n} × {args.n}, {args.steps} steps × {args.repeats}"
    )
    print()
    print("| order | cell-updates/s (median) | best | per CPU-second | ms per step | Δt [s] | min h [m] | finite "
          "| load avg |")
    print("|---|---|---|---|---|---|---|---|---|")
    for order in args.orders:
        r = measure(order, args.n, args.steps, args.repeats)
        print(
            f"| {r['order']} | {r['median'] / 1e6:.1f} M | {r['best'] / 1e6:.1f} M | {r['per_cpu'] / 1e6:.1f} M | "
            f"{r['step_ms']:.1f} | {r['sim_dt']:.3g} | {r['min_h']:.3g} | {r['finite']} | {r['load']:.1f} |"
        )


if __name__ == "__main__":
    main()
