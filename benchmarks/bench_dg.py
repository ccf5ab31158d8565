"""The dissertation's cost claim for its DG scheme, measured (issue 44, item 3; the 1D part).

One run, side by side, on Stoker's dam break (1 m onto 0.1 m, x ∈ [0, 10] m, dam at 5 m, t = 0.6 s,
flat frictionless bed, open ends):

* ``oceanrender.coastal.dg`` at degree 1 (RKDG P1, minmod and TVB) and degree 0 (the first-order kinetic
  FVS scheme of the same code: the dissertation's "first order");
* the project's finite-volume solver (``coastal.swe``, numba) on a 3-row channel: first order, the
  second-order "kinetic" (MUSCL + Heun) and "kinetic split" (MUSCL–Hancock) schemes;
* PyClaw's classic second-order solver (clawpack 5.14, Fortran; MC limiter) on the same channel, when it
  imports: run this under ``.venv-bench`` (``scripts/bench_swe_env.sh``), which has it and the project.

Printed per scheme and grid: L1 of h [m²], steps, wall time (best of ``--repeats``) and the cost per
cell-update [ns] (wall time / (steps × cells); a DG cell-update is two stages of two coefficients each).
Then the time to reach ``--target`` L1 on Stoker, log-log interpolated between the two grids that bracket it;
for the 3-row finite-volume channel also per row, the 1D-equivalent. Writes ``benchmarks/results/bench_dg.md``.

Usage: ``.venv-bench/bin/python benchmarks/bench_dg.py [--repeats 2] [--target 0.005]`` (~1 min on 2 cores;
``.venv/bin/python`` leaves the PyClaw rows out).
"""

from __future__ import annotations

import argparse
import math
import os
import pathlib
import sys
import time

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

LENGTH, X0, H_LEFT, H_RIGHT, T_END = 10.0, 5.0, 1.0, 0.1, 0.6
ROWS = 3


def exact_means(n: int) -> np.ndarray:
    from oceanrender.coastal.analytic import dam_break_stoker

    dx = LENGTH / n
    x = (np.arange(n) + 0.5) * dx
    nodes, weights = np.polynomial.legendre.leggauss(8)
    return sum(w * dam_break_stoker(x + 0.5 * dx * xi, T_END, H_LEFT, H_RIGHT, X0)[0] for xi, w in zip(nodes, weights)) / 2


def run_dg(n: int, degree: int, limiter: str):
    from oceanrender.coastal.dg import DGParams, DGSolver1D, DGState

    dx = LENGTH / n
    x = (np.arange(n) + 0.5) * dx
    state = DGState(np.where(x < X0, H_LEFT, H_RIGHT), np.zeros(n), np.zeros(n), np.zeros(n))
    solver = DGSolver1D(np.zeros(n + 1), DGParams(dx=dx, degree=degree, limiter=limiter, cfl=0.3 if degree else 0.9))
    start = time.perf_counter()
    steps = solver.advance(state, T_END)
    return time.perf_counter() - start, steps, n, state.h0


def run_fv(n: int, order: int, scheme: str):
    from oceanrender.coastal.boundaries import Boundaries, Transmissive
    from oceanrender.coastal.swe import SolverParams, ShallowWaterSolver, State

    dx = LENGTH / n
    x = (np.arange(n) + 0.5) * dx
    cfl = 0.9 if (order == 1 or scheme == "kinetic split") else 0.45
    solver = ShallowWaterSolver(np.zeros((ROWS, n)), SolverParams(
        dx=dx, dy=dx, order=order, scheme=scheme, cfl=cfl, h_min=1e-6,
        boundaries=Boundaries(west=Transmissive(), east=Transmissive())))
    state = State(np.tile(np.where(x < X0, H_LEFT, H_RIGHT), (ROWS, 1)), np.zeros((ROWS, n)), np.zeros((ROWS, n)))
    start = time.perf_counter()
    solver.advance(state, T_END)
    elapsed = time.perf_counter() - start
    return elapsed, solver.cell_updates // (ROWS * n), ROWS * n, state.h[1]


def run_pyclaw(n: int):
    """PyClaw's classic solver, order 2 (Lax–Wendroff with the MC limiter, dimensionally split, its default
    CFL control; Roe with entropy fix) on the same 3-row channel, open (extrapolating) ends."""
    import tempfile

    from clawpack import pyclaw, riemann  # in .venv-bench only (scripts/bench_swe_env.sh)

    dx = LENGTH / n
    here = os.getcwd()
    with tempfile.TemporaryDirectory(prefix="bench_dg_pyclaw_") as scratch:
        os.chdir(scratch)  # NOTE: importing and running pyclaw writes pyclaw.log in the working directory
        try:
            solver = pyclaw.ClawSolver2D(riemann.shallow_roe_with_efix_2D)
            solver.order = 2
            solver.limiters = pyclaw.limiters.tvd.MC
            solver.dimensional_split = True
            solver.bc_lower = [pyclaw.BC.extrap, pyclaw.BC.wall]
            solver.bc_upper = [pyclaw.BC.extrap, pyclaw.BC.wall]
            solver.dt_initial = 0.1 * dx / (3.0 * math.sqrt(9.81 * H_LEFT))
            solver.max_steps = 100000
            solver.verbosity = 0
            domain = pyclaw.Domain([pyclaw.Dimension(0.0, LENGTH, n, name="x"),
                                    pyclaw.Dimension(0.0, ROWS * dx, ROWS, name="y")])
            state = pyclaw.State(domain, 3)
            state.problem_data.update(grav=9.81, dry_tolerance=1e-3, sea_level=0.0)
            x_c, _ = state.grid.p_centers
            state.q[0] = np.where(x_c < X0, H_LEFT, H_RIGHT)
            state.q[1] = 0.0
            state.q[2] = 0.0
            solution = pyclaw.Solution(state, domain)
            solver.setup(solution)
            start = time.perf_counter()
            solver.evolve_to_time(solution, T_END)
            elapsed = time.perf_counter() - start
        finally:
            os.chdir(here)
    return elapsed, int(solver.status["numsteps"]), ROWS * n, solution.state.q[0][:, 1].copy()


def pyclaw_available() -> bool:
    try:
        import clawpack.pyclaw  # noqa: F401
    except ImportError:
        return False
    return True


SCHEMES = {
    "DG P1, minmod (the dissertation's)": (lambda n: run_dg(n, 1, "minmod"), (100, 200, 400, 800, 1600), 1),
    "DG P1, TVB": (lambda n: run_dg(n, 1, "TVB"), (100, 200, 400, 800, 1600), 1),
    "first-order FVS, same code (DG P0)": (lambda n: run_dg(n, 0, "minmod"), (400, 800, 1600, 3200, 6400), 1),
    "FV first order (swe, 3 rows)": (lambda n: run_fv(n, 1, "kinetic"), (400, 800, 1600, 3200, 6400), ROWS),
    "FV kinetic MUSCL + Heun (swe, 3 rows)": (lambda n: run_fv(n, 2, "kinetic"), (100, 200, 400, 800, 1600), ROWS),
    "FV MUSCL-Hancock, kinetic split (swe, 3 rows)": (lambda n: run_fv(n, 2, "kinetic split"), (100, 200, 400, 800, 1600), ROWS),
    "PyClaw order 2, MC (3 rows)": (run_pyclaw, (100, 200, 400, 800, 1600), ROWS),
}


def time_to(target: float, rows: list[tuple[int, float, float]]) -> float:
    """Wall time at L1 = target, log-log interpolated between the bracketing grids; NaN if not bracketed."""
    for (n0, e0, t0), (n1, e1, t1) in zip(rows, rows[1:]):
        if e0 >= target >= e1:
            f = math.log(e0 / target) / math.log(e0 / e1)
            return math.exp(math.log(t0) + f * math.log(t1 / t0))
    return float("nan")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=2)
    parser.add_argument("--target", type=float, default=0.005)
    args = parser.parse_args()
    load = os.getloadavg()[0]
    lines = [f"Stoker dam break, t = {T_END} s; 2026-12-05; load {load:.1f}; best of {args.repeats}", "",
             "| scheme | cells | L1 of h [m²] | steps | wall [s] | ns per cell-update |", "|---|---:|---:|---:|---:|---:|"]
    summary = {}
    for name, (run, grids, rows) in SCHEMES.items():
        if run is run_pyclaw and not pyclaw_available():
            lines.append(f"| {name} | — | not installed (run under .venv-bench: scripts/bench_swe_env.sh) | | | |")
            print(lines[-1], flush=True)
            continue
        run(grids[0])  # compile (numba) and warm up
        rows_out = []
        for n in grids:
            best = None
            for _ in range(args.repeats):
                elapsed, steps, cells, h = run(n)
                best = elapsed if best is None else min(best, elapsed)
            error = float(np.abs(h - exact_means(n)).sum() * LENGTH / n)
            per = 1e9 * best / (steps * cells)
            rows_out.append((n, error, best))
            lines.append(f"| {name} | {n}{' × 3' if rows > 1 else ''} | {error:.3e} | {steps} | {best:.3f} | {per:.0f} |")
            print(lines[-1], flush=True)
        summary[name] = (rows_out, rows)
    lines += ["", f"Time to L1 = {args.target:g} m² (log-log between the bracketing grids):", "",
              "| scheme | time [s] | per row (1D-equivalent) [s] |", "|---|---:|---:|"]
    for name, (rows_out, rows) in summary.items():
        t = time_to(args.target, rows_out)
        lines.append(f"| {name} | {t:.3f} | {t / rows:.3f} |")
    text = "\n".join(lines) + "\n"
    print("\n".join(lines[-len(summary) - 4:]))
    out = ROOT / "benchmarks" / "results" / "bench_dg.md"
    out.write_text(text)
    print(f"wrote {out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
