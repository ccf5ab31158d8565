"""Shallow-water solver side by side with ANUGA 4.1 and PyClaw 5.14: throughput and accuracy.

Run: ``bash scripts/bench_swe_env.sh`` once (a separate virtualenv, .venv-bench,
with anuga, clawpack built with gfortran, and oceanrender), then
``.venv-bench/bin/python benchmarks/bench_swe.py [--quick] [--big-baselines]``.
Prints a Markdown table and a ratio summary, and writes both to
``benchmarks/results/bench_swe.md``. ``--quick`` uses small grids (under a
minute); without it the run takes tens of minutes on 2 cores (ANUGA dominates).

Problems (the same for all three solvers; :data:`swe_baselines.CASES`)
---------------------------------------------------------------------
* ``ritter``: a 10 m × 1 m channel (x along 10 m), flat frictionless bed, walls
  on all four sides, dam at x = 5 m, 1 m of water behind it and a **dry** bed
  beyond; run to t = 0.5 s, before any wave reaches a wall. Exact solution:
  Ritter (1892).
* ``stoker``: the same with a **wet** bed, 0.1 m beyond the dam; exact
  solution: Stoker (1957). It exists because PyClaw's Riemann solvers divide by
  the depth and fail on a dry bed (recorded as a failure, with the step, never
  hidden).
* ``square-ritter`` / ``square-stoker``: a 100 m × 100 m box, dam at x = 50 m,
  run to t = 2 s: the 1000 × 1000 headline grid (dx = 0.1 m).

Grids: ours and PyClaw on 1000 × 100 cells (dx = dy = 1 cm, 100 000 cells) in
the channel, ANUGA on a ``rectangular_cross`` mesh of 500 × 50 squares of
2 cm, each cut into 4 triangles by its diagonals (100 000 triangles). Ours on
1000 × 1000 for the headline; the other two there only with
``--big-baselines`` (PyClaw 1000 × 1000 cells, ANUGA 500 × 500 squares =
1 000 000 triangles). ``--quick``: 200 × 20 cells, 100 × 10 squares (4 000
triangles) and 200 × 200 for the square.

Accuracy
--------
Relative L1 error of depth at t_end, E = ∫|h − h_exact| dA / (h_left L W),
over cell centres (triangle centroids for ANUGA) weighted by cell area. The
exact solution depends on x only, so E is also the L1 error of the
y-averaged depth relative to h_left · L. The exact solution is
``oceanrender.coastal.analytic`` when it exists (it is checked against the
private copies in swe_baselines.py and any difference is reported), else those
copies.

Throughput
----------
Updates per second = cells (or triangles) × time steps / wall time of the time
stepping only, the best of ``--repeats`` runs (3 by default: the machine is
shared, so times are noisy). Excluded: mesh or grid generation, initial
conditions, solver construction, numba compilation (an untimed warm-up run of
ours, on the same grid, comes first), ANUGA's initialisation up to the first
yield of ``evolve``, and PyClaw's ``solver.setup``. A step is one full time step
whatever its stages: ANUGA DE0 is forward Euler, DE1 two-stage Runge–Kutta;
PyClaw's classic solver takes dimensionally split steps (an x sweep and a y
sweep); ours counts ``solver.cell_updates`` (cells × steps).

* Ours: ``oceanrender.coastal.swe.ShallowWaterSolver``, order 1 and 2 (MC
  limiter, the default), CFL 0.9 × the positivity bound (0.9 at order 1, 0.45
  at order 2: :data:`OURS_CFL`), h_min = 1e-5 m (:data:`OURS_H_MIN`; the
  solver stays positive and NaN-free with it, and the default 1 mm would delay
  Ritter's front), walls, with ``numba.get_num_threads()`` threads (the
  count is in the table), and again with 1 thread (per-core comparison).
* ANUGA: flow algorithms DE0 (second order in space, forward Euler; ANUGA's
  default) and DE1 (second order in space and time), its default ('legacy')
  compute mode and also 'unified' for DE0, OpenMP threads set to 1
  (``anuga.set_omp_num_threads(1)``, ``OMP_NUM_THREADS=1``).
* PyClaw: ``ClawSolver2D`` (classic, Fortran) with
  ``riemann.shallow_roe_with_efix_2D``, ``solver.order`` 1 and 2 (MC limiter),
  ``OMP_NUM_THREADS=1``; PyClaw's own CFL control (cfl_desired 0.9).

Time to solution at equal accuracy (``--accuracy``)
---------------------------------------------------
Error per cell differs between the schemes, so updates per second alone do not
say who is faster. With ``--accuracy`` ours is also run on the channel cases at
the resolutions :data:`SWEEP` (nx = 100 … 2240 in steps of about √2, ny = nx / 10), coarse to fine,
until its L1 error is at most the smallest of the baselines' (or its wall time
exceeds the slowest baseline's); for every
baseline row the report gives the coarsest of our grids (per order) whose L1
error is ≤ theirs and their wall time ÷ ours. ``--sweep-threads 1`` runs ours on
one thread, as the baselines are.

``--scheme NAME [NAME ...]`` runs ours at second order with each of those schemes
(``swe.SCHEMES``: "kinetic", the default, "HLL split", "kinetic split") in the same
run, each swept and reported on its own rows ("order 2, NAME"); "kinetic split" also
adds a first-order sweep with the split first-order scheme. Ours run at 0.9 × the
scheme's positivity bound (:data:`OURS_CFL`).

``--only REGEX`` runs only the rows whose label (as printed on stderr, e.g.
"PyClaw square-stoker order 1") matches, to redo a few rows.

Our solver is imported once, at its first row: a run measures the
oceanrender.coastal.swe of that moment.

Each external configuration runs in its own subprocess (swe_baselines.py's
command line), with ``OMP_NUM_THREADS=1`` set before its extensions load; a
solver that is not installed gives rows saying so.
"""

from __future__ import annotations

import argparse
import dataclasses
import datetime
import importlib.metadata
import json
import math
import os
import platform
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from swe_baselines import CASES, DamBreak, RunResult, analytic_depth, l1_error  # noqa: E402

HERE = Path(__file__).resolve().parent
RESULTS = HERE / "results" / "bench_swe.md"
NOT_INSTALLED = "not installed (run scripts/bench_swe_env.sh)"


@dataclasses.dataclass(frozen=True)
class Sizes:
    """Grids of one benchmark mode."""

    channel: tuple[int, int]  # ours and PyClaw, cells (nx, ny)
    channel_anuga: tuple[int, int]  # ANUGA rectangular_cross squares (4 triangles each)
    square: tuple[int, int]  # headline grid, cells
    square_anuga: tuple[int, int]


FULL = Sizes((1000, 100), (500, 50), (1000, 1000), (500, 500))
QUICK = Sizes((200, 20), (100, 10), (200, 200), (100, 100))


# --------------------------------------------------------------------------
# Our solver
# --------------------------------------------------------------------------
def _project_analytic():
    try:
        from oceanrender.coastal import analytic  # noqa: PLC0415
    except ImportError:
        return None
    return analytic


OURS_CFL = {1: 0.9, 2: 0.45}
"""Courant number of ours per order: 0.9 × the positivity bound (swe.CFL_BOUND: 1 and ½); "kinetic split"
runs at 0.9 at both orders (0.9 × swe.SPLIT_CFL_BOUND)."""

SPLIT_CFL = 0.9
"""Courant number of "kinetic split" at both orders (``--split-cfl``; its positivity bound is 1)."""

OURS_SCHEME: str | None = None
"""Second-order scheme of ours (a key of swe.SCHEMES; None: SolverParams' default); ``--scheme`` sets it."""

OURS_H_MIN = 1e-5
"""Dry threshold of ours [m]: physically small, so that it does not delay Ritter's front (docs/coastal.md)."""


def run_ours(case: DamBreak, nx: int, ny: int, order: int, repeats: int, threads: int | None = None,
             cfl: float | None = None, h_min: float = OURS_H_MIN, ours_scheme: str | None = None) -> RunResult:
    """Dam break with oceanrender's solver on nx × ny cells; best of ``repeats`` timed runs.

    ``ours_scheme``: a key of swe.SCHEMES for this run (None: OURS_SCHEME, the first ``--scheme``).
    """
    ours_scheme = OURS_SCHEME if ours_scheme is None else ours_scheme
    scheme = f"order {order}" if ours_scheme is None else f"order {order}, {ours_scheme}"
    grid = f"{nx}×{ny}"
    if cfl is None:
        cfl = SPLIT_CFL if ours_scheme == "kinetic split" else OURS_CFL[order]
    try:
        import numba  # noqa: PLC0415
        from oceanrender.coastal.boundaries import Boundaries, Wall  # noqa: PLC0415
        from oceanrender.coastal.swe import ShallowWaterSolver, SolverParams, State  # noqa: PLC0415
    except ImportError as error:
        return RunResult("oceanrender", _version("oceanrender"), case.name, scheme, grid, nx * ny,
                         threads=f"{threads} (numba)" if threads else "numba default",
                         status="not available", note=f"oceanrender.coastal.swe not importable: {error}")
    default_threads = numba.get_num_threads()
    numba.set_num_threads(threads or default_threads)
    try:
        result = RunResult("oceanrender", _version("oceanrender"), case.name, scheme, grid, nx * ny,
                           threads=f"{numba.get_num_threads()} (numba, {_threading_layer()})")
        dx, dy = case.length / nx, case.width / ny
        extra = {} if ours_scheme is None else {"scheme": ours_scheme}
        params = SolverParams(dx=dx, dy=dy, order=order, cfl=cfl, h_min=h_min, manning=0.0,
                              boundaries=Boundaries(west=Wall(), east=Wall(), south=Wall(), north=Wall()), **extra)
        solver = ShallowWaterSolver(np.zeros((ny, nx)), params)
        x = (np.arange(nx) + 0.5) * dx  # cell centres; axis 1 is x
        h0 = np.ascontiguousarray(np.broadcast_to(case.initial_depth(x), (ny, nx)), dtype=float)

        def fresh():
            return State(h=h0.copy(), hu=np.zeros_like(h0), hv=np.zeros_like(h0), t=0.0)

        solver.advance(fresh(), 0.02 * case.t_end)  # warm-up: numba compilation, untimed
        for _ in range(repeats):
            state = fresh()
            before = solver.cell_updates
            start = time.perf_counter()
            state = solver.advance(state, case.t_end)
            result.walls.append(time.perf_counter() - start)
            result.steps = round((solver.cell_updates - before) / (nx * ny))
        result.wall_s = min(result.walls)
        h = np.asarray(state.h)
        x_cells = np.broadcast_to(x, h.shape)
        result.l1 = l1_error(case, x_cells, h, dx * dy, _project_analytic())
        notes = [f"CFL {params.cfl}, h_min {params.h_min} m" + (f", {params.scheme}, {params.limiter}" if order == 2 else "")]
        if not np.all(np.isfinite(h)):
            result.status, notes = "failed", ["NaN in depth", *notes]
        elif h.min() < 0.0:
            notes.append(f"min depth {h.min():.2e} m")
        if abs(state.t - case.t_end) > 1e-9 * max(1.0, case.t_end):
            notes.append(f"stopped at t = {state.t:.6g} s")
        mass_error = (h.sum() - h0.sum()) / h0.sum()
        notes.append(f"mass error {mass_error:.1e}")
        if getattr(solver, "clamped_volume", 0.0):
            notes.append(f"clamped volume {solver.clamped_volume:.1e} m³")
        if getattr(solver, "retries", 0):
            notes.append(f"{solver.retries} second-order step retries over all runs")
        result.note = "; ".join(notes)
    except Exception as error:  # noqa: BLE001  (a solver under construction may raise anything)
        result = RunResult("oceanrender", _version("oceanrender"), case.name, scheme, grid, nx * ny,
                           threads=f"{numba.get_num_threads()} (numba)", status="error",
                           note=f"{type(error).__name__}: {str(error)[:160]}")
    finally:
        numba.set_num_threads(default_threads)
    return result


def _threading_layer() -> str:
    import numba  # noqa: PLC0415

    try:
        return numba.threading_layer()
    except ValueError:  # no parallel region has run yet
        return "layer not chosen yet"


# --------------------------------------------------------------------------
# The baselines, one subprocess each
# --------------------------------------------------------------------------
def _installed(module: str) -> bool:
    """Whether ``module`` imports, tested in a subprocess (keeps its libraries out of this one)."""
    code = f"import {module}"
    # NOTE: in the temporary folder: importing pyclaw creates pyclaw.log in the working directory.
    return subprocess.run([sys.executable, "-c", code], capture_output=True, env=_baseline_env(),
                          cwd=tempfile.gettempdir(), timeout=300).returncode == 0


def _baseline_env() -> dict:
    env = dict(os.environ)
    env["OMP_NUM_THREADS"] = "1"
    return env


def run_baseline(solver: str, case: DamBreak, nx: int, ny: int, scheme: str, repeats: int,
                 timeout_s: float, **options) -> RunResult:
    """One ANUGA or PyClaw configuration via ``swe_baselines.py`` in a subprocess with OMP_NUM_THREADS=1."""
    cmd = [sys.executable, str(HERE / "swe_baselines.py"), "--solver", solver, "--case", case.name,
           "--nx", str(nx), "--ny", str(ny), "--scheme", scheme, "--repeats", str(repeats)]
    for key, value in options.items():
        cmd += [f"--{key.replace('_', '-')}", str(value)]
    name = {"anuga": "ANUGA", "pyclaw": "PyClaw"}[solver]
    cells = 4 * nx * ny if solver == "anuga" else nx * ny
    grid = f"rectangular_cross {nx}×{ny}" if solver == "anuga" else f"{nx}×{ny}"
    try:
        done = subprocess.run(cmd, capture_output=True, text=True, env=_baseline_env(), timeout=timeout_s,
                              cwd=tempfile.gettempdir())
    except subprocess.TimeoutExpired:
        return RunResult(name, "-", case.name, scheme, grid, cells, status="failed",
                         note=f"no result within {timeout_s:.0f} s (killed)")
    lines = done.stdout.strip().splitlines()
    try:
        fields = json.loads(lines[-1])
    except (IndexError, json.JSONDecodeError):
        tail = (done.stderr.strip().splitlines() or ["no output"])[-1]
        return RunResult(name, "-", case.name, scheme, grid, cells, status="failed",
                         note=f"crashed (exit {done.returncode}): {tail[:120]}")
    return RunResult(**fields)


def build_jobs(sizes: Sizes, repeats: int, repeats_ours: int, big_baselines: bool):
    """Whether ANUGA and PyClaw import, and (label, thunk returning a RunResult) for every row, in run order."""
    anuga_ok, pyclaw_ok = _installed("anuga"), _installed("clawpack.pyclaw")
    jobs = []

    def anuga(case, n, scheme, repeats, timeout_s, **options):
        if not anuga_ok:
            mode = options.get("compute_mode") or "default mode"
            return lambda: RunResult("ANUGA", "-", case.name, f"{scheme}, {mode}", f"rectangular_cross {n[0]}×{n[1]}",
                                     4 * n[0] * n[1], threads="-", status="not installed", note=NOT_INSTALLED)
        return lambda: run_baseline("anuga", case, *n, scheme, repeats, timeout_s, **options)

    def pyclaw(case, n, order, repeats, timeout_s):
        if not pyclaw_ok:
            return lambda: RunResult("PyClaw", "-", case.name, f"order {order}, shallow_roe_with_efix_2D",
                                     f"{n[0]}×{n[1]}", n[0] * n[1], threads="-", status="not installed",
                                     note=NOT_INSTALLED)
        return lambda: run_baseline("pyclaw", case, *n, str(order), repeats, timeout_s)

    for name in ("ritter", "stoker"):
        case = CASES[name]
        for order in (1, 2):
            jobs.append((f"ours {name} order {order}",
                         lambda c=case, o=order: run_ours(c, *sizes.channel, o, repeats_ours)))
            jobs.append((f"ours {name} order {order}, 1 thread",
                         lambda c=case, o=order: run_ours(c, *sizes.channel, o, repeats_ours, threads=1)))
        for order in (1, 2):
            jobs.append((f"PyClaw {name} order {order}", pyclaw(case, sizes.channel, order, repeats, 1800)))
        jobs.append((f"ANUGA {name} DE0", anuga(case, sizes.channel_anuga, "DE0", repeats, 1800)))
        jobs.append((f"ANUGA {name} DE0 unified",
                     anuga(case, sizes.channel_anuga, "DE0", repeats, 1800, compute_mode="unified")))
        jobs.append((f"ANUGA {name} DE1", anuga(case, sizes.channel_anuga, "DE1", repeats, 1800)))
    for name in ("square-ritter", "square-stoker"):
        case = CASES[name]
        for order in (1, 2):
            jobs.append((f"ours {name} order {order}",
                         lambda c=case, o=order: run_ours(c, *sizes.square, o, repeats_ours)))
        jobs.append((f"ours {name} order 1, 1 thread",
                     lambda c=case: run_ours(c, *sizes.square, 1, repeats_ours, threads=1)))
        if big_baselines:
            for order in (1, 2):
                jobs.append((f"PyClaw {name} order {order}", pyclaw(case, sizes.square, order, repeats, 3600)))
            jobs.append((f"ANUGA {name} DE0", anuga(case, sizes.square_anuga, "DE0", repeats, 3600)))
    return anuga_ok, pyclaw_ok, jobs


# --------------------------------------------------------------------------
# Time to solution at equal accuracy
# --------------------------------------------------------------------------
SWEEP = (100, 140, 200, 280, 400, 560, 800, 1120, 1600, 2240)
"""Channel resolutions nx of ours in the equal-accuracy sweep (ny = nx / 10: square cells)."""


def accuracy_sweep(baselines: list[RunResult], repeats: int, threads: int | None, only=None,
                   schemes=(None,)) -> list[RunResult]:
    """Ours on the channel cases at the :data:`SWEEP` resolutions, order 1 and 2 (each of ``schemes``), coarse to fine.

    A sweep stops at the first resolution whose L1 error is at most the smallest of
    the baselines' on that case, or whose wall time exceeds the slowest baseline's
    (finer grids could then only give ratios below 1).
    """
    out = []
    for name in ("ritter", "stoker"):
        case = CASES[name]
        ok = [r for r in baselines if r.case == name and r.status == "ok" and math.isfinite(r.l1)]
        target = min((r.l1 for r in ok), default=0.0)
        slowest = max((r.wall_s for r in ok), default=math.inf)
        variants = [(1, None)] + [(1, s) for s in schemes if s == "kinetic split"] + [(2, s) for s in schemes]
        for order, scheme in variants:
            label = f"ours {name} order {order}" + (f", {scheme}" if scheme else "") + " sweep"
            if only and not re.search(only, label):
                continue
            for nx in SWEEP:
                t0 = time.perf_counter()
                result = run_ours(case, nx, max(2, nx // 10), order, repeats, threads=threads,
                                  ours_scheme=scheme or "kinetic")
                out.append(result)
                print(f"bench_swe: {label} {result.grid}: {result.status}, wall {_fmt(result.wall_s, '.3f')} s, "
                      f"L1 {_fmt(result.l1, '.2e')} ({time.perf_counter() - t0:.0f} s)", file=sys.stderr, flush=True)
                # NOTE: once ours takes longer than every baseline, finer grids can only give ratios < 1
                if result.status != "ok" or result.l1 <= target or result.wall_s > slowest:
                    break
    return out


def _cells(grid: str) -> int:
    nx, ny = grid.split()[-1].split("×")
    return int(nx) * int(ny)


def accuracy_summary(results: list[RunResult], sweep: list[RunResult]) -> str:
    """Per baseline row: the coarsest of our runs (each order) with L1 ≤ theirs, and their wall time ÷ ours."""
    lines = ["| case | theirs | their grid | their L1 | their wall s | ours | our grid | our L1 | our wall s "
             "| their wall ÷ ours |",
             "|---|---|---|---:|---:|---|---|---:|---:|---:|"]
    for theirs in results:
        if theirs.solver == "oceanrender" or theirs.case not in ("ritter", "stoker"):
            continue
        if theirs.status != "ok":
            lines.append(f"| {theirs.case} | {theirs.solver} {theirs.scheme} | {theirs.grid} | – | – | – | – | – | – "
                         f"| n/a ({theirs.status}) |")
            continue
        for variant in dict.fromkeys(r.scheme for r in sweep):  # "order 1, kinetic", "order 2, HLL split", …
            ours = sorted((r for r in sweep if r.case == theirs.case and r.scheme == variant
                           and r.status == "ok" and r.l1 <= theirs.l1), key=lambda r: _cells(r.grid))
            if not ours:
                finest = [r for r in sweep if r.case == theirs.case and r.scheme == variant]
                reached = f"not reached up to {finest[-1].grid}" if finest else "not run"
                lines.append(f"| {theirs.case} | {theirs.solver} {theirs.scheme} | {theirs.grid} | {theirs.l1:.2e} | "
                             f"{theirs.wall_s:.3f} | {variant} | {reached} | – | – | – |")
                continue
            r = ours[0]
            lines.append(f"| {theirs.case} | {theirs.solver} {theirs.scheme} | {theirs.grid} | {theirs.l1:.2e} | "
                         f"{theirs.wall_s:.3f} | {variant} | {r.grid} | {r.l1:.2e} | {r.wall_s:.3f} | "
                         f"×{theirs.wall_s / r.wall_s:.1f} |")
    return "\n".join(lines)


# --------------------------------------------------------------------------
# Report
# --------------------------------------------------------------------------
def _version(dist: str) -> str:
    try:
        return importlib.metadata.version(dist)
    except importlib.metadata.PackageNotFoundError:
        return "-"


def _fmt(value, spec):
    return "–" if value is None or (isinstance(value, float) and not math.isfinite(value)) else format(value, spec)


def table(results: list[RunResult]) -> str:
    """The Markdown table of every row."""
    lines = ["| case | solver | version | scheme | grid | cells | steps | wall s (best) | M updates/s | "
             "L1 rel. | threads | status | notes |",
             "|---|---|---|---|---|---:|---:|---:|---:|---:|---|---|---|"]
    for r in results:
        wall = f"{_fmt(r.wall_s, '.3f')} ({len(r.walls)}×)" if r.walls else "–"
        lines.append(
            f"| {r.case} | {r.solver} | {r.version} | {r.scheme} | {r.grid} | {r.cells:,} | "
            f"{r.steps if r.steps else '–'} | {wall} | {_fmt(r.updates_per_s / 1e6, '.2f')} | "
            f"{_fmt(r.l1, '.2e')} | {r.threads} | {r.status} | {r.note} |")
    return "\n".join(lines)


def _pick(results, case, solver, scheme_prefix, threads_one=None):
    """The matching row; among several (ANUGA's two compute modes), the fastest that ran."""
    rows = [r for r in results if r.case == case and r.solver == solver and r.scheme.startswith(scheme_prefix)
            and (threads_one is None or r.threads.startswith("1 ") == threads_one)]
    ok = [r for r in rows if r.status == "ok"]
    return max(ok, key=lambda r: r.updates_per_s) if ok else (rows[0] if rows else None)


def _ratio(ours, theirs) -> str:
    """Ours ÷ theirs: updates/s, time to t_end (their wall ÷ ours) and L1 error."""
    if ours is None or theirs is None:
        return "n/a"
    if theirs.status != "ok":
        return f"n/a ({theirs.solver} {theirs.status})"
    if ours.status != "ok":
        return f"n/a (ours {ours.status})"
    speed = ours.updates_per_s / theirs.updates_per_s
    wall = theirs.wall_s / ours.wall_s
    l1 = ours.l1 / theirs.l1 if theirs.l1 > 0 else math.nan
    return f"×{speed:.1f} updates/s, ×{wall:.1f} time to t_end, L1 ×{l1:.2f}"


def summary(results: list[RunResult]) -> str:
    """Ratio lines: ours ÷ ANUGA and ours ÷ PyClaw on the same case and grid size, then the headline."""
    out = []
    for case in ("ritter", "stoker", "square-ritter", "square-stoker"):
        for order, anuga_alg in ((1, "DE0"), (2, "DE1")):
            ours = _pick(results, case, "oceanrender", f"order {order}", threads_one=False)
            ours1 = _pick(results, case, "oceanrender", f"order {order}", threads_one=True)
            anuga = _pick(results, case, "ANUGA", anuga_alg)
            pyclaw = _pick(results, case, "PyClaw", f"order {order}")
            if ours is None or (anuga is None and pyclaw is None):
                continue
            parts = []
            for name, theirs in ((f"ANUGA {anuga_alg}", anuga), (f"PyClaw order {order}", pyclaw)):
                if theirs is not None:
                    one = f" (ours on 1 thread: {_ratio(ours1, theirs)})" if ours1 is not None else ""
                    parts.append(f"ours ÷ {name}: {_ratio(ours, theirs)}{one}")
            out.append(f"* {case} ({ours.grid}), order {order}: " + "; ".join(parts) + ".")
    best = {}
    for solver in ("ANUGA", "PyClaw"):
        ok = [r for r in results if r.solver == solver and r.status == "ok"]
        best[solver] = max(ok, key=lambda r: r.updates_per_s) if ok else None
    for case in ("square-ritter", "square-stoker"):
        for order in (1, 2):
            ours = _pick(results, case, "oceanrender", f"order {order}", threads_one=False)
            if ours is None:
                continue
            rate = f"{ours.updates_per_s / 1e6:.1f} M cell-updates/s" if ours.status == "ok" else ours.status
            parts = [f"* headline {case} {ours.grid}, order {order}: ours {rate}"
                     + (" (goal ≥ 50 M/s at order 1)" if order == 1 else "")]
            for solver, r in best.items():
                if r is not None and ours.status == "ok":
                    parts.append(f"÷ fastest {solver} row in this run ({r.scheme}, {r.case}, {r.grid}, "
                                 f"{r.updates_per_s / 1e6:.2f} M/s) = ×{ours.updates_per_s / r.updates_per_s:.1f}")
            out.append("; ".join(parts) + ".")
    return "\n".join(out)


def analytic_check() -> str:
    """Which analytic solution is used, and how far oceanrender's differs from the private copies."""
    analytic = _project_analytic()
    if analytic is None:
        return "Analytic solution: private copies in benchmarks/swe_baselines.py (oceanrender.coastal.analytic absent)."
    worst = 0.0
    for case in CASES.values():
        x = np.linspace(0.0, case.length, 20001)
        worst = max(worst, float(np.max(np.abs(analytic_depth(case, x, analytic) - analytic_depth(case, x)))))
    flag = "" if worst < 1e-9 else " — WARNING: they disagree"
    return (f"Analytic solution: oceanrender.coastal.analytic (max |difference| from the private copies "
            f"in swe_baselines.py: {worst:.1e} m{flag}).")


def header(args, sizes: Sizes, anuga_ok: bool, pyclaw_ok: bool, started, load_start, load_end, elapsed) -> str:
    try:
        import numba  # noqa: PLC0415

        numba_info = f"numba {numba.__version__}, {numba.get_num_threads()} threads, layer {_threading_layer()}"
    except ImportError:
        numba_info = "numba not installed"
    return "\n".join([
        f"# Shallow-water dam break: oceanrender vs ANUGA vs PyClaw ({'quick' if args.quick else 'full'})",
        "",
        f"Run started {started.isoformat(timespec='seconds')} on {platform.node() or 'this machine'}: "
        f"{platform.machine()}, {os.cpu_count()} CPUs, Python {platform.python_version()}, "
        f"numpy {np.__version__}, {numba_info}; anuga {_version('anuga') if anuga_ok else NOT_INSTALLED}, "
        f"clawpack {_version('clawpack') if pyclaw_ok else NOT_INSTALLED}. "
        f"Load average {load_start[0]:.2f} at start, {load_end[0]:.2f} at end; whole run {elapsed / 60:.1f} min. "
        f"Best of {args.repeats} timed runs per row ({args.repeats_ours} for ours; the machine is shared: "
        "times are noisy).",
        "",
        f"Grids: channel {sizes.channel[0]}×{sizes.channel[1]} cells (ours, PyClaw), rectangular_cross "
        f"{sizes.channel_anuga[0]}×{sizes.channel_anuga[1]} = {4 * sizes.channel_anuga[0] * sizes.channel_anuga[1]:,} "
        f"triangles (ANUGA); square {sizes.square[0]}×{sizes.square[1]} cells"
        + (f", ANUGA {4 * sizes.square_anuga[0] * sizes.square_anuga[1]:,} triangles." if args.big_baselines
           else " (ours only; `--big-baselines` adds the others)."),
        "L1 rel. = ∫|h − h_exact| dA / (h_left · L · W) at t_end. Updates/s = cells (triangles) × steps / "
        "wall time of the time stepping only. ANUGA and PyClaw run with OMP_NUM_THREADS=1.",
        analytic_check(),
    ])


def main(argv=None) -> int:
    global OURS_SCHEME, SPLIT_CFL
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="small grids, under a minute")
    parser.add_argument("--big-baselines", action="store_true",
                        help="also run ANUGA and PyClaw on the square headline grid (long)")
    parser.add_argument("--repeats", type=int, default=3, help="timed runs per row; the best is kept")
    parser.add_argument("--repeats-ours", type=int, default=5,
                        help="timed runs per row of ours (cheap, so more chances of a quiet moment)")
    parser.add_argument("--only", default=None, metavar="REGEX",
                        help="run only the rows whose label matches, e.g. 'PyClaw|ANUGA' or 'square'")
    parser.add_argument("--out", type=Path, default=RESULTS, help="Markdown file to write")
    parser.add_argument("--accuracy", action="store_true",
                        help="also sweep ours over channel resolutions (SWEEP) and report the wall time at equal "
                             "or better L1 error than each baseline row")
    parser.add_argument("--scheme", default=None, nargs="+",
                        help="second-order scheme(s) of ours (swe.SCHEMES: 'kinetic', 'HLL split', 'kinetic split'), "
                             "each swept in the same run; default: the solver's")
    parser.add_argument("--sweep-threads", type=int, default=None,
                        help="threads of ours in the sweep (default: numba's; 1 for a per-core comparison)")
    parser.add_argument("--split-cfl", type=float, default=SPLIT_CFL,
                        help="Courant number of 'kinetic split' on its kinetic speed |u| + sqrt(3gh/2), in (0, 1] "
                             f"(default {SPLIT_CFL}; 1 is 0.82 on |u| + sqrt(gh), PyClaw's measure)")
    args = parser.parse_args(argv)
    if not 0.0 < args.split_cfl <= 1.0:
        parser.error("--split-cfl must be in (0, 1]")
    SPLIT_CFL = args.split_cfl
    OURS_SCHEME = args.scheme[0] if args.scheme else None
    if args.repeats < 1 or args.repeats_ours < 1:
        parser.error("--repeats and --repeats-ours must be at least 1")
    sizes = QUICK if args.quick else FULL

    load_start, start, started = os.getloadavg(), time.perf_counter(), datetime.datetime.now()
    anuga_ok, pyclaw_ok, jobs = build_jobs(sizes, args.repeats, args.repeats_ours, args.big_baselines)
    if args.only:
        jobs = [(label, job) for label, job in jobs if re.search(args.only, label)]
    results = []
    for label, job in jobs:
        t0 = time.perf_counter()
        result = job()
        results.append(result)
        print(f"bench_swe: {label}: {result.status}, {_fmt(result.updates_per_s / 1e6, '.2f')} M/s, "
              f"L1 {_fmt(result.l1, '.2e')} ({time.perf_counter() - t0:.0f} s)", file=sys.stderr, flush=True)
    sweep = (accuracy_sweep(results, args.repeats_ours, args.sweep_threads, args.only, schemes=args.scheme or (None,))
             if args.accuracy else [])
    equal = [] if not sweep else [
        f"Time to solution at equal accuracy (channel cases; ours swept over nx = {', '.join(map(str, SWEEP))} "
        f"with ny = nx/10, CFL {OURS_CFL[1]} / {OURS_CFL[2]} at order 1 / 2 ({SPLIT_CFL} for kinetic split), h_min {OURS_H_MIN} m, "
        f"{args.sweep_threads or 'numba default'} thread(s)): for each baseline row, the coarsest of our "
        "grids whose L1 error is at most theirs, and their wall time ÷ ours (above 1: ours reaches their "
        "accuracy faster).",
        table(sweep),
        accuracy_summary(results, sweep),
    ]
    report = "\n\n".join([
        header(args, sizes, anuga_ok, pyclaw_ok, started, load_start, os.getloadavg(), time.perf_counter() - start),
        table(results),
        *equal,
        "Ratios, ours ÷ theirs on the same case and grid size: updates/s; time to t_end (their wall time ÷ "
        "ours: the solvers take different numbers of steps); L1 error (below 1: ours is more accurate). "
        "ANUGA: the faster of its two compute modes.",
        summary(results),
    ]) + "\n"
    print(report)
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(report, encoding="utf-8")
    print(f"bench_swe: written {args.out}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
