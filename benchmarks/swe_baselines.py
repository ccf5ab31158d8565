"""ANUGA 4.1 and PyClaw 5.14 harnesses for the dam-break benchmark of :mod:`bench_swe`.

Each harness builds one dam break (:class:`DamBreak`) in the external solver,
times only its time stepping, and returns a :class:`RunResult` with the
cell- (or triangle-) updates per second and the L1 error of depth against the
analytic solution. Neither package is a dependency of oceanrender: they live in
the separate virtual environment made by ``scripts/bench_swe_env.sh``.

The harnesses are plain functions (:func:`run_anuga`, :func:`run_pyclaw`).
``benchmarks/bench_swe.py`` calls them through this file's small command line,
one subprocess per configuration, so that ``OMP_NUM_THREADS=1`` is in the
environment before the compiled extensions load, a crash (or a run that never
ends) in one solver cannot take the benchmark down, and memory is returned
between runs::

    OMP_NUM_THREADS=1 .venv-bench/bin/python benchmarks/swe_baselines.py \\
        --solver pyclaw --case stoker --nx 1000 --ny 100 --scheme 1 --repeats 3

prints one JSON object (a :class:`RunResult`) on its last line.

Counting
--------
* ANUGA: triangles × ``domain.number_of_steps`` (the steps its ``evolve``
  generator took between the first yield, at t = 0, and the last, at
  ``t_end``); the clock runs over that loop only (mesh generation, quantity
  set-up and ANUGA's own first-yield initialisation are excluded).
  ``DE1`` is a two-stage Runge–Kutta method: one step = two flux evaluations.
* PyClaw: cells × ``solver.status['numsteps']`` of
  ``ClawSolver2D.evolve_to_time``, after ``solver.setup``. One step is one
  dimensionally split (x sweep, then y sweep) step.

References
----------
.. [1] A. Ritter (1892), "Die Fortpflanzung der Wasserwellen", Zeitschrift des
   Vereines Deutscher Ingenieure 36(33), 947–954.
.. [2] J. J. Stoker (1957), *Water Waves*, Interscience, New York, ch. 10.
.. [3] S. Roberts et al., ANUGA, https://github.com/anuga-community/anuga_core
.. [4] D. I. Ketcheson et al. (2012), "PyClaw: accessible, extensible, scalable
   tools for wave propagation problems", SIAM J. Sci. Comput. 34(4),
   C210–C231, doi:10.1137/110856976.
"""

from __future__ import annotations

import argparse
import dataclasses
import importlib.metadata
import json
import math
import os
import sys
import tempfile
import time

import numpy as np

#: Gravitational acceleration used by every solver in the benchmark [m s⁻²].
G = 9.81


# --------------------------------------------------------------------------
# The problem
# --------------------------------------------------------------------------
@dataclasses.dataclass(frozen=True)
class DamBreak:
    """An instantaneous dam break on a flat, frictionless bed in a walled box.

    Water of depth ``h_left`` for x < ``x0`` and ``h_right`` beyond, at rest,
    walls on all four sides; run to ``t_end``, before any wave reaches a wall,
    so the solution is the 1-D Riemann solution in x (Ritter for a dry bed,
    Stoker for a wet one) at every y.
    """

    name: str
    length: float  # along x [m]
    width: float  # along y [m]
    x0: float  # dam position [m]
    h_left: float  # [m]
    h_right: float  # [m]; 0 is a dry bed
    t_end: float  # [s]

    def __post_init__(self):
        if not (0.0 < self.x0 < self.length and self.h_left > 0.0 and 0.0 <= self.h_right < self.h_left):
            raise ValueError(f"invalid dam break {self}")
        c = math.sqrt(G * self.h_left)
        # NOTE: the rarefaction head moves left at √(g h_l), the front (or shock,
        # slower) right at most 2√(g h_l): both must stay inside the box.
        if self.x0 - c * self.t_end <= 0.0 or self.x0 + 2.0 * c * self.t_end >= self.length:
            raise ValueError(f"{self.name}: waves reach a wall before t_end = {self.t_end} s")

    def initial_depth(self, x):
        """Depth at t = 0 [m] at positions ``x`` [m]."""
        return np.where(np.asarray(x) < self.x0, self.h_left, self.h_right)


#: The benchmark's problems (see bench_swe.py's docstring).
CASES = {
    "ritter": DamBreak("ritter", 10.0, 1.0, 5.0, 1.0, 0.0, 0.5),
    "stoker": DamBreak("stoker", 10.0, 1.0, 5.0, 1.0, 0.1, 0.5),
    "square-ritter": DamBreak("square-ritter", 100.0, 100.0, 50.0, 1.0, 0.0, 2.0),
    "square-stoker": DamBreak("square-stoker", 100.0, 100.0, 50.0, 1.0, 0.1, 2.0),
}


# --------------------------------------------------------------------------
# Analytic solutions (private copies; bench_swe prefers oceanrender's own)
# --------------------------------------------------------------------------
def dam_break_ritter(x, t, h_left, x0=0.0, g=G):
    """Depth [m] and velocity [m s⁻¹] of Ritter's dry-bed dam break [1].

    Parameters
    ----------
    x : array_like   Position [m].
    t : float   Time after the break, > 0 [s].
    h_left : float   Depth behind the dam [m].
    x0 : float   Dam position [m].
    g : float   Gravitational acceleration [m s⁻²].
    """
    return dam_break_stoker(x, t, h_left, 0.0, x0=x0, g=g)


def dam_break_stoker(x, t, h_left, h_right, x0=0.0, g=G):
    """Depth [m] and velocity [m s⁻¹] of the wet-bed dam break (Stoker [2]).

    A left rarefaction, a constant middle state (h_m, u_m) and a right shock;
    ``h_right = 0`` gives Ritter's solution (no middle state, no shock).

    Parameters
    ----------
    x : array_like   Position [m].
    t : float   Time after the break, > 0 [s].
    h_left, h_right : float   Depths either side of the dam, h_left > h_right ≥ 0 [m].
    x0 : float   Dam position [m].
    g : float   Gravitational acceleration [m s⁻²].
    """
    xi = (np.asarray(x, dtype=float) - x0) / t
    c_l = math.sqrt(g * h_left)
    h = np.full_like(xi, h_left)
    u = np.zeros_like(xi)
    if h_right <= 0.0:
        tail, front, h_m, u_m = 2.0 * c_l, 2.0 * c_l, 0.0, 2.0 * c_l
    else:
        h_m = _stoker_middle_depth(h_left, h_right, g)
        u_m = 2.0 * (c_l - math.sqrt(g * h_m))  # Riemann invariant across the rarefaction
        tail = u_m - math.sqrt(g * h_m)
        front = h_m * u_m / (h_m - h_right)  # shock speed (Rankine–Hugoniot, mass)
    fan = (xi >= -c_l) & (xi < tail)
    h[fan] = (2.0 * c_l - xi[fan]) ** 2 / (9.0 * g)
    u[fan] = 2.0 / 3.0 * (xi[fan] + c_l)
    mid = (xi >= tail) & (xi < front)
    h[mid], u[mid] = h_m, u_m
    ahead = xi >= front
    h[ahead], u[ahead] = h_right, 0.0
    return h, u


def _stoker_middle_depth(h_left, h_right, g):
    """Middle-state depth h_m [m]: rarefaction velocity = shock velocity (bisection)."""

    def mismatch(h_m):
        u_rarefaction = 2.0 * (math.sqrt(g * h_left) - math.sqrt(g * h_m))
        u_shock = (h_m - h_right) * math.sqrt(0.5 * g * (h_m + h_right) / (h_m * h_right))
        return u_rarefaction - u_shock

    lo, hi = h_right, h_left  # mismatch(lo) > 0 > mismatch(hi)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if mismatch(mid) > 0.0 else (lo, mid)
    return 0.5 * (lo + hi)


def analytic_depth(case: DamBreak, x, analytic=None):
    """Exact depth [m] of ``case`` at ``x`` [m] and ``case.t_end``.

    ``analytic`` is a module with ``dam_break_ritter``/``dam_break_stoker``
    (oceanrender.coastal.analytic); None uses the private copies above.
    """
    ritter = getattr(analytic, "dam_break_ritter", dam_break_ritter)
    stoker = getattr(analytic, "dam_break_stoker", dam_break_stoker)
    if case.h_right == 0.0:
        return np.asarray(ritter(x, case.t_end, case.h_left, x0=case.x0, g=G)[0])
    return np.asarray(stoker(x, case.t_end, case.h_left, case.h_right, x0=case.x0, g=G)[0])


def l1_error(case: DamBreak, x, h, area, analytic=None):
    """Relative L1 error of depth: ∫|h − h_exact| dA / (h_left · length · width) [-].

    ``x`` [m] are the cell centres (or triangle centroids), ``h`` [m] the
    depths there and ``area`` [m²] the cell areas. Since the exact solution
    depends on x only, this equals the L1 error of the y-averaged depth
    relative to h_left · length. NaN if any depth is not finite.
    """
    h = np.asarray(h, dtype=float)
    if not np.all(np.isfinite(h)):
        return math.nan
    exact = analytic_depth(case, x, analytic)
    return float(np.sum(np.abs(h - exact) * area) / (case.h_left * case.length * case.width))


# --------------------------------------------------------------------------
# Results
# --------------------------------------------------------------------------
@dataclasses.dataclass
class RunResult:
    """One solver configuration on one case; ``wall_s`` is the best of ``walls``."""

    solver: str
    version: str
    case: str
    scheme: str  # order / flow algorithm, as the table prints it
    grid: str  # e.g. "1000×100" or "rectangular_cross 500×50"
    cells: int  # cells or triangles
    steps: int = 0
    wall_s: float = math.nan  # time stepping only, best of the repeats [s]
    walls: list = dataclasses.field(default_factory=list)  # every repeat [s]
    l1: float = math.nan
    threads: str = "1"
    status: str = "ok"  # ok | failed | not installed | error | skipped
    note: str = ""

    @property
    def updates_per_s(self) -> float:
        """Cell- (or triangle-) updates per second of the best repeat [s⁻¹]."""
        if self.status != "ok" or not self.wall_s > 0.0:
            return math.nan
        return self.cells * self.steps / self.wall_s


def _version(dist: str) -> str:
    try:
        return importlib.metadata.version(dist)
    except importlib.metadata.PackageNotFoundError:
        return "-"


def _not_installed(solver, case, scheme, grid, cells, error):
    return RunResult(solver, "-", case.name, scheme, grid, cells, threads="-", status="not installed",
                     note=f"not installed (run scripts/bench_swe_env.sh): {error}")


# --------------------------------------------------------------------------
# ANUGA
# --------------------------------------------------------------------------
def run_anuga(case: DamBreak, nx: int, ny: int, algorithm: str = "DE0", repeats: int = 3,
              compute_mode: str | None = None) -> RunResult:
    """Dam break in ANUGA on a ``rectangular_cross`` mesh of nx × ny squares (4 nx ny triangles).

    Parameters
    ----------
    case : DamBreak   The problem.
    nx, ny : int   Squares along x and y; each is cut into 4 triangles by its diagonals.
    algorithm : str   ANUGA flow algorithm ('DE0': second-order space, Euler
        time, its default; 'DE1': second-order space, RK2 time).
    repeats : int   Timed runs; the best is kept.
    compute_mode : str or None   ANUGA's 'legacy' or 'unified' kernels; None keeps its default.
    """
    grid, cells = f"rectangular_cross {nx}×{ny}", 4 * nx * ny
    try:
        import anuga  # noqa: PLC0415
    except Exception as error:  # noqa: BLE001  (any import failure means: not usable)
        return _not_installed("ANUGA", case, f"{algorithm}, {compute_mode or 'default mode'}", grid, cells, error)
    anuga.set_omp_num_threads(int(os.environ.get("OMP_NUM_THREADS", "1")), verbose=False)
    result = RunResult("ANUGA", _version("anuga"), case.name, algorithm, grid, cells,
                       threads=f"{anuga.get_omp_num_threads()} (OpenMP)")
    for _ in range(repeats):
        domain = anuga.rectangular_cross_domain(nx, ny, len1=case.length, len2=case.width)
        domain.set_flow_algorithm(algorithm)
        if compute_mode is not None:
            domain.set_compute_mode(compute_mode)
        domain.set_store(False)  # no .sww output
        domain.set_quantity("elevation", 0.0)
        domain.set_quantity("friction", 0.0)
        domain.set_quantity("stage", lambda x, y: case.initial_depth(x))
        wall = anuga.Reflective_boundary(domain)
        domain.set_boundary({"left": wall, "right": wall, "top": wall, "bottom": wall})
        evolve = domain.evolve(yieldstep=case.t_end, finaltime=case.t_end)
        next(evolve)  # t = 0: ANUGA's own initialisation, untimed
        steps0 = domain.number_of_steps
        start = time.perf_counter()
        for _ in evolve:
            pass
        result.walls.append(time.perf_counter() - start)
        result.steps = domain.number_of_steps - steps0
    result.wall_s = min(result.walls)
    h = domain.quantities["stage"].centroid_values - domain.quantities["elevation"].centroid_values
    x = domain.centroid_coordinates[:, 0] + domain.geo_reference.xllcorner
    result.l1 = l1_error(case, x, h, domain.areas, _project_analytic())
    result.scheme = f"{algorithm}, {domain.get_compute_mode()}"
    notes = [f"compute mode {domain.get_compute_mode()}", f"{domain.timestepping_method} time stepping",
             f"CFL {domain.CFL}"]
    if not np.all(np.isfinite(h)):
        result.status, notes = "failed", ["NaN in depth", *notes]
    elif h.min() < 0.0:
        notes.append(f"min depth {h.min():.2e} m")
    result.note = "; ".join(notes)
    return result


# --------------------------------------------------------------------------
# PyClaw
# --------------------------------------------------------------------------
def run_pyclaw(case: DamBreak, nx: int, ny: int, order: int = 1, repeats: int = 3,
               riemann_solver: str = "shallow_roe_with_efix_2D") -> RunResult:
    """Dam break in PyClaw's classic (Fortran) 2-D solver on an nx × ny grid.

    Parameters
    ----------
    case : DamBreak   The problem.
    nx, ny : int   Cells along x and y.
    order : int   1 (Godunov) or 2 (Lax–Wendroff with the MC limiter).
    repeats : int   Timed runs; the best is kept.
    riemann_solver : str   Name of the Riemann solver in ``clawpack.riemann``.

    Notes
    -----
    Dimensionally split steps (``solver.dimensional_split = True``), PyClaw's
    default CFL control (``cfl_desired`` 0.9, ``cfl_max`` 1.0, reject and
    retry). A run stops at the first non-finite depth, or when PyClaw gives up
    (it raises once ``max_steps`` is reached, which a NaN state does since its
    time step becomes NaN); either is recorded as a failure, with the step.
    """
    scheme = f"order {order}, {riemann_solver}"
    grid, cells = f"{nx}×{ny}", nx * ny
    try:
        from clawpack import pyclaw, riemann  # noqa: PLC0415
    except Exception as error:  # noqa: BLE001
        return _not_installed("PyClaw", case, scheme, grid, cells, error)
    result = RunResult("PyClaw", _version("clawpack"), case.name, scheme, grid, cells,
                       threads=f"{os.environ.get('OMP_NUM_THREADS', '?')} (OMP_NUM_THREADS)")
    c_max = 3.0 * math.sqrt(G * case.h_left)  # |u| + c ≤ 3 √(g h_l) in both solutions
    expected_steps = case.t_end * c_max / (0.9 * min(case.length / nx, case.width / ny))
    for _ in range(repeats):
        solver = pyclaw.ClawSolver2D(getattr(riemann, riemann_solver))
        solver.order = order
        solver.limiters = pyclaw.limiters.tvd.MC
        solver.dimensional_split = True
        solver.bc_lower = [pyclaw.BC.wall, pyclaw.BC.wall]
        solver.bc_upper = [pyclaw.BC.wall, pyclaw.BC.wall]
        solver.max_steps = int(5 * expected_steps) + 100
        solver.dt_initial = 0.1 * min(case.length / nx, case.width / ny) / c_max
        x_dim = pyclaw.Dimension(0.0, case.length, nx, name="x")
        y_dim = pyclaw.Dimension(0.0, case.width, ny, name="y")
        domain = pyclaw.Domain([x_dim, y_dim])
        state = pyclaw.State(domain, 3)
        state.problem_data.update(grav=G, dry_tolerance=1e-3, sea_level=0.0)
        x_c, _ = state.grid.p_centers  # NOTE: PyClaw arrays are q[eqn, i (x), j (y)]
        state.q[0] = case.initial_depth(x_c)
        state.q[1] = 0.0
        state.q[2] = 0.0
        solution = pyclaw.Solution(state, domain)
        solver.setup(solution)
        start = time.perf_counter()
        error = None
        try:
            solver.evolve_to_time(solution, case.t_end)
        except Exception as exc:  # noqa: BLE001  (PyClaw raises plain Exception)
            error = exc
        result.walls.append(time.perf_counter() - start)
        result.steps = int(solver.status.get("numsteps", 0))
        h = solution.state.q[0]
        if error is not None or not np.all(np.isfinite(solution.state.q)):
            result.status = "failed"
            first_bad = _first_nan_step(pyclaw, riemann, riemann_solver, case, nx, ny, order)
            result.note = (f"NaN in depth at step {first_bad}" if first_bad else "non-finite state") + (
                f"; PyClaw stopped: {str(error).splitlines()[0][:80]}" if error else "") + (
                f"; t reached {solution.t:.3g} s of {case.t_end} s")
            result.l1 = math.nan
            result.wall_s = min(result.walls)
            return result  # a failing configuration is not repeated
    result.wall_s = min(result.walls)
    x_c = solution.state.grid.p_centers[0]
    area = (case.length / nx) * (case.width / ny)
    result.l1 = l1_error(case, x_c, h, area, _project_analytic())
    result.note = f"dimensional split, cfl_desired {solver.cfl_desired}, MC limiter" if order == 2 else (
        f"dimensional split, cfl_desired {solver.cfl_desired}")
    if h.min() < 0.0:
        result.note += f"; min depth {h.min():.2e} m"
    return result


def _first_nan_step(pyclaw, riemann, riemann_solver, case, nx, ny, order, max_steps=50):
    """Re-run step by step (untimed) to find the first step with a non-finite state; None if > max_steps."""
    solver = pyclaw.ClawSolver2D(getattr(riemann, riemann_solver))
    solver.order = order
    solver.limiters = pyclaw.limiters.tvd.MC
    solver.dimensional_split = True
    solver.bc_lower = [pyclaw.BC.wall, pyclaw.BC.wall]
    solver.bc_upper = [pyclaw.BC.wall, pyclaw.BC.wall]
    solver.dt_variable = False  # one fixed step at a time
    c_max = 3.0 * math.sqrt(G * case.h_left)
    solver.dt_initial = 0.9 * min(case.length / nx, case.width / ny) / c_max
    domain = pyclaw.Domain([pyclaw.Dimension(0.0, case.length, nx, name="x"),
                            pyclaw.Dimension(0.0, case.width, ny, name="y")])
    state = pyclaw.State(domain, 3)
    state.problem_data.update(grav=G, dry_tolerance=1e-3, sea_level=0.0)
    state.q[0] = case.initial_depth(state.grid.p_centers[0])
    state.q[1:] = 0.0
    solution = pyclaw.Solution(state, domain)
    solver.setup(solution)
    for step in range(1, max_steps + 1):
        try:
            solver.evolve_to_time(solution, solution.t + solver.dt)
        except Exception:  # noqa: BLE001
            return step
        if not np.all(np.isfinite(solution.state.q)):
            return step
    return None


def _project_analytic():
    """oceanrender.coastal.analytic if it exists, else None (the private copies are used)."""
    try:
        from oceanrender.coastal import analytic  # noqa: PLC0415
    except ImportError:
        return None
    return analytic


# --------------------------------------------------------------------------
# Command line: one configuration per process (used by bench_swe.py)
# --------------------------------------------------------------------------
def main(argv=None) -> int:
    """Run one configuration and print its RunResult as JSON on the last line."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--solver", choices=["anuga", "pyclaw"], required=True)
    parser.add_argument("--case", choices=sorted(CASES), required=True)
    parser.add_argument("--nx", type=int, required=True, help="cells (PyClaw) or squares (ANUGA) along x")
    parser.add_argument("--ny", type=int, required=True)
    parser.add_argument("--scheme", required=True,
                        help="PyClaw: order 1 or 2; ANUGA: flow algorithm (DE0, DE1, ...)")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--riemann", default="shallow_roe_with_efix_2D", help="PyClaw Riemann solver")
    parser.add_argument("--compute-mode", default=None, help="ANUGA compute mode (legacy/unified)")
    args = parser.parse_args(argv)
    case = CASES[args.case]
    if args.solver == "anuga":
        result = run_anuga(case, args.nx, args.ny, args.scheme, args.repeats, args.compute_mode)
    else:
        # NOTE: importing pyclaw opens a log file, pyclaw.log, in the working
        # directory: keep it out of the repository.
        cwd = os.getcwd()
        with tempfile.TemporaryDirectory(prefix="bench_swe_pyclaw_") as scratch:
            os.chdir(scratch)
            try:
                result = run_pyclaw(case, args.nx, args.ny, int(args.scheme), args.repeats, args.riemann)
            finally:
                os.chdir(cwd)
    print(json.dumps(dataclasses.asdict(result)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
