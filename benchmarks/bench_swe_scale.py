"""Real-time factor of the first-order shallow-water solver on a 1000 × 600 grid of 0.5 m cells.

Run: ``.venv/bin/python benchmarks/bench_swe_scale.py [--seconds 30] [--spinup 110] [--order 1] [--scheme NAME]``.

The case (issue 18's scale goal): a plane beach 500 m × 300 m, 1000 × 600 cells of
0.5 m, bed rising from −6 m at the west side at a slope of 1:62.5 (shoreline at
x = 375 m, dry land behind it, covered by the h_min film), a 0.5 m, 8 s wave train
entering through the west side (``IncidentWave.wave_train``, ramped over one period),
walls on the other three sides, h_min = 1 mm, Manning n = 0.02, first order at
ν = 0.9 (``--scheme "kinetic split"``: the split first-order sweeps, ν = 0.9 per sweep).
After ``--spinup`` simulated seconds (untimed: numba compilation and the arrival of the
waves: a long wave needs ∫ dx/√(g h) ≈ 98 s from the west side to the shoreline, so the
default 110 s times the run-up and backwash of the first crests), ``--seconds`` simulated
seconds are timed with
:meth:`ShallowWaterSolver.advance`; the result is simulated seconds per wall second
(goal ≥ 2 on the 2-core machine, with ``numba.get_num_threads()`` row blocks). The
load average is printed beside it: other work on the cores lowers the rate.
Cell-updates/s count a step once (the split scheme's four sweeps of Δt/2 included), so
they compare the cost per step, and the real-time factor the cost per simulated second.
"""

from __future__ import annotations

import argparse
import os
import time

import numba
import numpy as np

from oceanrender.coastal.boundaries import Boundaries, IncidentWave, Wall
from oceanrender.coastal.swe import ShallowWaterSolver, SolverParams, lake_at_rest


def plane_beach(nx: int = 1000, ny: int = 600, dx: float = 0.5, h_min: float = 1e-3):
    """Bed [m] and lake-at-rest state of the benchmark beach."""
    x = (np.arange(nx) + 0.5) * dx
    bed = np.broadcast_to(-6.0 + x / 62.5, (ny, nx)).copy()
    return bed, lake_at_rest(bed, 0.0, h_min)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=30.0, help="timed simulated time [s]")
    parser.add_argument("--spinup", type=float, default=110.0,
                        help="untimed simulated time first [s]; the waves reach the shoreline after ~98 s")
    parser.add_argument("--order", type=int, default=1)
    parser.add_argument("--cfl", type=float, default=None, help="default: 0.9 (order 1), 0.45 (order 2)")
    parser.add_argument("--scheme", default="kinetic",
                        help="scheme (swe.SCHEMES); at order 1 'kinetic split' selects the split sweeps")
    args = parser.parse_args()
    bed, state = plane_beach()
    sea = IncidentWave.wave_train(amplitude=0.5, period=8.0, direction_deg=0.0, ramp_time=8.0)
    cfl = args.cfl if args.cfl is not None else (0.9 if args.order == 1 or args.scheme == "kinetic split" else 0.45)
    params = SolverParams(dx=0.5, dy=0.5, order=args.order, cfl=cfl, h_min=1e-3, manning=0.02,
                          scheme=args.scheme,
                          boundaries=Boundaries(west=sea, east=Wall(), south=Wall(), north=Wall()))
    solver = ShallowWaterSolver(bed, params)
    solver.advance(state, args.spinup)
    load = os.getloadavg()
    before = solver.cell_updates
    start, start_cpu = time.perf_counter(), time.process_time()
    solver.advance(state, args.spinup + args.seconds)
    wall, cpu = time.perf_counter() - start, time.process_time() - start_cpu
    steps = (solver.cell_updates - before) // bed.size
    shore = bed[0] <= 0.0  # initially wet (the shoreline is at x = 375 m)
    wet_now = state.h[:, ~shore] > 1e-3
    print(f"1000 × 600 cells of 0.5 m, order {args.order} ({params.scheme}), "
          f"ν = {cfl}, {numba.get_num_threads()} threads, load average {load[0]:.2f} / {os.getloadavg()[0]:.2f} "
          f"(before / after)")
    print(f"simulated {args.seconds:g} s in {wall:.2f} s wall ({cpu:.2f} s CPU), {steps} steps "
          f"(Δt ≈ {args.seconds / steps:.4f} s), {bed.size * steps / wall / 1e6:.1f} M cell-updates/s")
    print(f"real-time factor: {args.seconds / wall:.2f} × (simulated s per wall s; goal ≥ 2); "
          f"min h {state.h.min():.3g} m, finite {bool(np.isfinite(state.h).all())}, "
          f"max run-up {float((bed + state.h)[state.h > 1e-3][bed[state.h > 1e-3] > 0].max(initial=0.0)):.3f} m, "
          f"flooded land cells now {int(wet_now.sum())} (waves on the beach: {bool(wet_now.any())}), "
          f"retries {solver.retries}, clamped volume {solver.clamped_volume:.2g} m³")


if __name__ == "__main__":
    main()
