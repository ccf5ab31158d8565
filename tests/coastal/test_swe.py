"""Shallow-water solver against analytic solutions, conservation, positivity, balance and bad input.

The convergence numbers quoted in docs/coastal.md ("Solver", validation table) are
printed by ``.venv/bin/python tests/coastal/test_swe.py``.
"""

import math

import numpy as np
import pytest

from oceanrender.coastal import swe, swe_ksplit
from oceanrender.coastal.analytic import (
    G as G_ANALYTIC,
    bore_jump,
    dam_break_stoker,
    simple_wave,
    simple_wave_breaking_time,
    stoker_middle_state,
    thacker_planar,
    wall_reflection,
)
from oceanrender.coastal.boundaries import Boundaries, Transmissive
from oceanrender.coastal.swe import (
    CFL_BOUND,
    LIMITERS,
    SCHEMES,
    SPLIT_CFL_BOUND,
    G,
    ShallowWaterSolver,
    SolverParams,
    State,
    lake_at_rest,
)
from tests.tolerances import ROUNDOFF

#: Relative volume change allowed for closed basins (round-off of the update sums).
MASS_RTOL = ROUNDOFF
#: Rows of the narrow grids on which one-dimensional problems run (walls north and south).
ROWS = 3
#: Dry threshold of the validation runs [m]: thin enough not to delay Ritter's front.
H_MIN_VALIDATION = 1e-6

OPEN_ENDS = Boundaries(west=Transmissive(), east=Transmissive())
#: (order, scheme) of every scheme the solver offers; first order is always the kinetic one.
SCHEME_CASES = [(1, "kinetic"), (2, "kinetic"), (2, "HLL split"), (1, "kinetic split"), (2, "kinetic split")]


def scheme_cfl(order, scheme):
    """The tests' Courant number: 0.45 (the default), 0.9 for "kinetic split" (its bound is 1 at both orders)."""
    return 0.9 if scheme == "kinetic split" else 0.45


def cell_average(profile, x_centres, dx, points=8):
    """Exact cell averages of a profile(x) by Gauss–Legendre quadrature over each cell."""
    nodes, weights = np.polynomial.legendre.leggauss(points)
    x = x_centres[:, None] + 0.5 * dx * nodes[None, :]
    return (profile(x) * weights[None, :]).sum(axis=1) / 2.0


def channel(h, hu, dx, order, boundaries=Boundaries(), h_min=H_MIN_VALIDATION, **params):
    """A one-dimensional profile on a ROWS × nx grid, flat bed at 0, and its solver."""
    nx = h.size
    solver = ShallowWaterSolver(
        np.zeros((ROWS, nx)),
        SolverParams(dx=dx, dy=dx, order=order, h_min=h_min, boundaries=boundaries, **params),
    )
    state = State(np.tile(h, (ROWS, 1)), np.tile(hu, (ROWS, 1)), np.zeros((ROWS, nx)))
    return solver, state


def l1_dam_break(order, nx, h_right, length=10.0, x0=5.0, h_left=1.0, t_end=0.6, **params):
    """L1 error [m²] of the depth of a dam break (Ritter if h_right = 0, else Stoker) at t_end."""
    dx = length / nx
    x = (np.arange(nx) + 0.5) * dx
    solver, state = channel(np.where(x < x0, h_left, h_right), np.zeros(nx), dx, order, **params)
    solver.advance(state, t_end)
    exact = cell_average(lambda s: dam_break_stoker(s, t_end, h_left, h_right, x0)[0], x, dx)
    # the 1-D problem stays 1-D: the rows next to the north and south walls see the same arithmetic
    # on the same numbers, so bit for bit
    assert np.array_equal(state.h[0], state.h[ROWS - 1])
    return float(np.abs(state.h[1] - exact).sum() * dx)


SIMPLE_WAVE = dict(h0=1.0, amplitude=0.2, width=1.0, x_c=4.0)


def l1_simple_wave(order, nx, length=16.0, **params):
    """L1 error [m²] of a smooth simple wave at half its breaking time (open ends)."""
    dx = length / nx
    x = (np.arange(nx) + 0.5) * dx
    h0 = cell_average(lambda s: simple_wave(s, 0.0, **SIMPLE_WAVE)[0], x, dx)
    q0 = cell_average(lambda s: np.prod(simple_wave(s, 0.0, **SIMPLE_WAVE), axis=0), x, dx)
    solver, state = channel(h0, q0, dx, order, boundaries=OPEN_ENDS, **params)
    t_end = 0.5 * simple_wave_breaking_time(1.0, 0.2, 1.0)
    solver.advance(state, t_end)
    exact = cell_average(lambda s: simple_wave(s, t_end, **SIMPLE_WAVE)[0], x, dx)
    return float(np.abs(state.h[1] - exact).sum() * dx)


CONVERGENCE = {
    # case: (error function, coarse nx, fine nx, {order: (lowest, highest observed order)})
    "Ritter (dry bed)": (lambda o, n, **kw: l1_dam_break(o, n, 0.0, **kw), 200, 400, {1: (0.5, 1.1), 2: (0.8, 1.5)}),
    "Stoker (wet bed)": (lambda o, n, **kw: l1_dam_break(o, n, 0.1, **kw), 200, 400, {1: (0.5, 1.1), 2: (0.8, 1.5)}),
    "simple wave (smooth)": (l1_simple_wave, 200, 400, {1: (0.7, 1.1), 2: (1.6, 2.3)}),
}


def observed(case, order):
    error, coarse, fine, _ = CONVERGENCE[case]
    e_coarse, e_fine = error(order, coarse), error(order, fine)
    return e_coarse, e_fine, math.log2(e_coarse / e_fine)


@pytest.mark.parametrize("case", list(CONVERGENCE))
def test_convergence_against_analytic_solutions(case):
    """Errors fall with the grid at the stated observed order; second order beats first."""
    ranges = CONVERGENCE[case][3]
    results = {order: observed(case, order) for order in (1, 2)}
    for order, (e_coarse, e_fine, p) in results.items():
        assert e_fine < e_coarse
        low, high = ranges[order]
        assert low <= p <= high, f"{case}, order {order}: observed order {p:.2f} outside [{low}, {high}]"
    # second order: at least twice as accurate on the coarse grid already
    assert results[2][0] < 0.5 * results[1][0]
    if "smooth" in case:
        assert results[2][2] > results[1][2] + 0.5  # it converges faster where the solution is smooth


@pytest.mark.parametrize("order, scheme", SCHEME_CASES)
def test_bore_into_still_water_obeys_the_jump_relations(order, scheme):
    jump = bore_jump(h_ahead=0.5, u_ahead=0.0, h_behind=1.0)
    nx, length, x0, t_end = 400, 20.0, 5.0, 2.0
    dx = length / nx
    x = (np.arange(nx) + 0.5) * dx
    behind = x < x0
    solver, state = channel(np.where(behind, jump.h_behind, jump.h_ahead),
                            np.where(behind, jump.h_behind * jump.u_behind, 0.0), dx, order, OPEN_ENDS,
                            scheme=scheme, cfl=scheme_cfl(order, scheme))
    solver.advance(state, t_end)
    h = state.h[1]
    # bore position from the volume between x = 2 m and the end (exact for a sharp jump)
    start = int(2.0 / dx)
    position = start * dx + float((h[start:] - jump.h_ahead).sum() * dx) / (jump.h_behind - jump.h_ahead)
    assert position == pytest.approx(x0 + jump.speed * t_end, abs=0.2 * dx)
    plateau = int((x0 + 0.5 * jump.speed * t_end) / dx)
    assert h[plateau] == pytest.approx(jump.h_behind, rel=1e-4)
    assert state.hu[1, plateau] / h[plateau] == pytest.approx(jump.u_behind, rel=1e-4)
    assert h[-5] == pytest.approx(jump.h_ahead, rel=ROUNDOFF)  # still water the bore has not reached


@pytest.mark.parametrize("order, scheme", SCHEME_CASES)
def test_stoker_bore_reflects_from_a_wall(order, scheme):
    """Closed box: the dam-break bore hits the east wall and comes back as the reflected bore."""
    h_left, h_right, nx, length, x0 = 1.0, 0.3, 400, 20.0, 10.0
    h_m, u_m, speed = stoker_middle_state(h_left, h_right)
    h_wall, reflected = wall_reflection(h_m, u_m)
    t_hit = (length - x0) / speed
    t_end = t_hit + 1.5
    dx = length / nx
    x = (np.arange(nx) + 0.5) * dx
    solver, state = channel(np.where(x < x0, h_left, h_right), np.zeros(nx), dx, order, scheme=scheme,
                            cfl=scheme_cfl(order, scheme))
    volume = state.volume(dx, dx)
    solver.advance(state, t_end)
    assert state.volume(dx, dx) == pytest.approx(volume, rel=MASS_RTOL)
    h = state.h[1]
    assert h[-1] == pytest.approx(h_wall, rel={1: 2e-3, 2: 5e-4}[order])
    assert abs(state.hu[1, -1] / h[-1]) < 1e-3  # at rest against the wall
    crossing = x[(h < 0.5 * (h_m + h_wall)) & (x > 12.0)].max() + 0.5 * dx
    assert crossing == pytest.approx(length + reflected * (t_end - t_hit), abs=2.5 * dx)


@pytest.mark.parametrize("case", list(CONVERGENCE))
def test_kinetic_split_converges_at_both_orders(case):
    """"kinetic split" at ν = 0.9 on every validation case: the accepted ranges, and no worse than the unsplit scheme.

    Measured (nx = 200 → 400, L1 of h [m²]): first order Ritter 5.686e-2 → 3.561e-2 (0.67),
    Stoker 5.242e-2 → 3.219e-2 (0.70), simple wave 2.479e-2 → 1.302e-2 (0.93): 0.59–0.89 × the
    unsplit errors at ν = 0.9 (6.38e-2, 6.24e-2, 4.21e-2); MUSCL–Hancock Ritter 8.348e-3 →
    3.961e-3 (1.08), Stoker 8.505e-3 → 3.624e-3 (1.23), simple wave 1.043e-3 → 2.441e-4 (2.09),
    against 7.43e-3, 1.04e-2, 3.37e-3 for the unsplit Heun scheme (docs/coastal.md).
    """
    error, coarse, fine, ranges = CONVERGENCE[case]
    unsplit = {1: error(1, coarse, cfl=0.9), 2: error(2, coarse)}
    for order in (1, 2):
        e_coarse = error(order, coarse, scheme="kinetic split", cfl=0.9)
        e_fine = error(order, fine, scheme="kinetic split", cfl=0.9)
        p = math.log2(e_coarse / e_fine)
        low, high = ranges[order]
        assert low <= p <= high, f"{case}, order {order}: observed order {p:.2f} outside [{low}, {high}]"
        # first order: below the unsplit error; second order: within 1.2× of the Heun scheme's (Ritter: 1.12×)
        assert e_coarse < {1: 1.0, 2: 1.2}[order] * unsplit[order]
    assert e_coarse < 0.5 * unsplit[1]


@pytest.mark.parametrize("case", list(CONVERGENCE))
def test_hll_split_converges_like_the_kinetic_second_order(case):
    """The "HLL split" scheme on every validation case: the second-order ranges, within 2× of the kinetic error.

    Measured (nx = 200 → 400): Ritter 1.32e-2 → 6.49e-3 (1.02), Stoker 1.26e-2 → 6.17e-3
    (1.03), simple wave 4.04e-3 → 1.11e-3 (1.87); the kinetic scheme 7.4e-3, 1.04e-2,
    3.4e-3 on the coarse grids (docs/coastal.md).
    """
    error, coarse, fine, ranges = CONVERGENCE[case]
    e_coarse, e_fine = error(2, coarse, scheme="HLL split"), error(2, fine, scheme="HLL split")
    p = math.log2(e_coarse / e_fine)
    low, high = ranges[2]
    assert low <= p <= high, f"{case}: observed order {p:.2f} outside [{low}, {high}]"
    assert e_coarse < 2.0 * error(2, coarse)  # the kinetic second order, same grid
    assert e_coarse < 0.5 * error(1, coarse)  # and well below first order


THACKER = dict(h0=0.5, a=1.0, amplitude=0.5, x_c=2.0)
"""Thacker's oscillation (analytic.thacker_planar): 4 m bowl, wet half-width 1 m, slab speed 0.5 m/s."""


def l1_thacker(order, nx, periods=1.0, **params):
    """(L1 error of h over the whole bowl [m²], over the part that stays wet [m²], solver, state) after ``periods``.

    The part that stays wet is |x − x_c| < a − B/ω − 2Δx (the shorelines sweep the rest).
    """
    length = 4.0
    dx = length / nx
    x = (np.arange(nx) + 0.5) * dx
    omega = math.sqrt(2.0 * G_ANALYTIC * THACKER["h0"]) / THACKER["a"]
    t_end = periods * 2.0 * math.pi / omega
    bed = np.tile(thacker_planar(x, 0.0, **THACKER)[0], (ROWS, 1))
    h0 = cell_average(lambda s: thacker_planar(s, 0.0, **THACKER)[1], x, dx)
    state = State(np.tile(h0, (ROWS, 1)), np.zeros((ROWS, nx)), np.zeros((ROWS, nx)))
    solver = ShallowWaterSolver(bed, SolverParams(dx=dx, dy=dx, order=order, h_min=H_MIN_VALIDATION, **params))
    solver.advance(state, t_end)
    exact = cell_average(lambda s: thacker_planar(s, t_end, **THACKER)[1], x, dx)
    error = np.abs(state.h[1] - exact) * dx
    wet = np.abs(x - THACKER["x_c"]) < THACKER["a"] - THACKER["amplitude"] / omega - 2 * dx
    return float(error.sum()), float(error[wet].sum()), solver, state


@pytest.mark.parametrize("scheme", list(SCHEMES))
def test_thacker_oscillation_with_moving_shorelines(scheme):
    """Smooth wet/dry flow: second-order convergence (≥ 1.6, whole bowl), h ≥ 0, mass exact, dry land at rest.

    Measured after one period, L1 of h over the whole bowl (and over the part that stays
    wet), nx = 200 → 400 → 800 → 1600: HLL split 9.89e-4, 3.72e-4, 1.09e-4, 3.13e-5:
    orders 1.41, 1.78, 1.80, 1.82 at 3200 (wet part 1.20, 1.73, 1.66, 1.75); kinetic 1.46, 1.75, 1.76;
    kinetic split 1.29, 1.67, 1.84, 1.82 (test below).
    The 400 → 800 pair is tested; 1.6 leaves room for the platform's round-off and
    for the pre-asymptotic range below it (1.33–1.46 at 100 → 400).
    """
    cfl = scheme_cfl(2, scheme)
    e400, _, _, _ = l1_thacker(2, 400, scheme=scheme, cfl=cfl)
    e800, _, solver, state = l1_thacker(2, 800, scheme=scheme, cfl=cfl)
    # "kinetic split" (ν = 0.9): 3.63e-4 → 1.14e-4, order 1.67; see docs/coastal.md
    assert math.log2(e400 / e800) >= 1.6
    assert state.h.min() >= 0.0 and solver.clamped_volume == 0.0
    dry = state.h <= H_MIN_VALIDATION
    assert dry.any() and np.all(state.hu[dry] == 0.0) and np.all(state.hv[dry] == 0.0)
    e1, _, _, _ = l1_thacker(1, 400, cfl=0.9)
    assert e400 < 0.25 * e1  # first order: 3.8e-3 at nx = 400


def test_kinetic_split_reaches_second_order_on_the_moving_shorelines():
    """The issue's goal, observed order ≥ 1.8 on a smooth wet/dry flow, on the fine pair nx = 1600 → 3200.

    Measured (ν = 0.9, MC, L1 of h over the whole bowl after one period): 3.18e-5 → 8.99e-6,
    order 1.82 (1.84 at 800 → 1600; 1.64 at 1600 → 3200 before the Hancock predictor was
    dropped beside dry cells whose bed stands above the water). No margin is given: 1.8 is
    the goal itself, and the run is deterministic up to round-off (~1e-16 of errors ~1e-5).
    """
    e1600, _, _, _ = l1_thacker(2, 1600, scheme="kinetic split", cfl=0.9)
    e3200, _, solver, state = l1_thacker(2, 3200, scheme="kinetic split", cfl=0.9)
    assert math.log2(e1600 / e3200) >= 1.8
    assert state.h.min() >= 0.0 and solver.clamped_volume == 0.0


def _hancock_reference(mB, nB, tB, eB, m, un, ut, e, mA, nA, tA, eA, lam, g, limiter):
    """Eqs. (10)–(12) of the module docstring cell by cell in plain Python (the kernels' reference)."""
    def slope(a, b):
        if limiter == "minmod":
            return min(a, b) if a > 0 and b > 0 else (max(a, b) if a < 0 and b < 0 else 0.0)
        if limiter == "MC":  # minmod(2a, 2b, (a + b)/2)
            if a * b <= 0:
                return 0.0
            return math.copysign(min(2 * abs(a), 2 * abs(b), 0.5 * abs(a + b)), a)
        return 2 * a * b / (a + b) if a * b > 0 else 0.0  # van Leer

    def out(h, u):  # (F⁺_h, −F⁻_h) of Eq. (3), a = √(3gh/2), ξ uniform on u ± a
        a = math.sqrt(1.5 * g * h)
        if a == 0.0:
            return max(h * u, 0.0), max(-h * u, 0.0)
        lo, hi = min(0.0, u - a), min(0.0, u + a)
        fminus = h * (hi * hi - lo * lo) / (4 * a)
        return h * u - fminus, -fminus

    faces = np.zeros((9, len(m)))
    kept = np.zeros(len(m), dtype=bool)
    for k in range(len(m)):
        sm, sn = slope(m[k] - mB[k], mA[k] - m[k]), slope(un[k] - nB[k], nA[k] - un[k])
        st, se = slope(ut[k] - tB[k], tA[k] - ut[k]), slope(e[k] - eB[k], eA[k] - e[k])
        shore = (mB[k] <= 0 and eB[k] >= e[k]) or (mA[k] <= 0 and eA[k] >= e[k])
        w = 0.0 if shore else 0.5 * lam
        dh, dn, dt = -w * (un[k] * sm + m[k] * sn), -w * (un[k] * sn + g * se), -w * un[k] * st
        hm, hp = m[k] - sm / 2 + dh, m[k] + sm / 2 + dh
        nm, np_ = un[k] - sn / 2 + dn, un[k] + sn / 2 + dn
        ok = min(hm, hp) >= 0 and lam * (out(max(hp, 0), np_)[0] + out(max(hm, 0), nm)[1]) <= (1 - 1e-9) * m[k]
        kept[k] = ok
        if ok:
            faces[:, k] = (hm, hp, nm, np_, ut[k] - st / 2 + dt, ut[k] + st / 2 + dt,
                           e[k] - se / 2 + dh, e[k] + se / 2 + dh, (m[k] + dh) * se)
        else:
            faces[:, k] = (m[k], m[k], un[k], un[k], ut[k], ut[k], e[k], e[k], 0.0)
    return faces, kept


@pytest.mark.parametrize("limiter", list(LIMITERS))
def test_hancock_face_values_follow_the_scalar_formulae(rng, limiter):
    """The vectorised face values (three loops per limiter) equal Eqs. (10)–(12) written cell by cell.

    Random rows with dry cells, shorelines on both sides and cells whose outflow fails the
    positivity test (λ = 0.4 s/m, a Courant number ~1–3: a quarter of the cells fall back). Values are O(1) m or m/s; the kernels may
    fuse a·b + c into an FMA, so the tolerance is 1e-12 absolute (~1e4 ulp of the values).
    """
    n = 400
    depth = np.where(rng.random(n + 2) < 0.2, 0.0, rng.uniform(0.01, 2.0, n + 2))
    bed = rng.uniform(-1.0, 1.0, n + 2)
    row = np.vstack([depth, np.where(depth > 0, rng.normal(0, 1.5, n + 2), 0.0),
                     np.where(depth > 0, rng.normal(0, 1.0, n + 2), 0.0), bed + depth])
    lam, g = 0.4, G
    B, C, A = row[:, :-2], row[:, 1:-1], row[:, 2:]
    args = (B[0], B[1], B[2], B[3], C[0], C[1], C[2], C[3], A[0], A[1], A[2], A[3])
    fv, keep = np.zeros((9, n)), np.zeros(n)
    swe_ksplit._hancock_faces(*[np.ascontiguousarray(a) for a in args], n, fv, keep, lam, g, 2.0 / (3.0 * g), 1.5 * g,
                       LIMITERS[limiter])
    expected, kept = _hancock_reference(*args, lam, g, limiter)
    assert 0 < kept.sum() < n  # both branches are exercised
    np.testing.assert_allclose(fv, expected, rtol=0, atol=1e-12)


@pytest.mark.parametrize("order", [1, 2])
def test_kinetic_split_stable_dt_uses_each_direction_alone(order):
    """Sweeps of Δt/2 along x and y, each at ν on its own direction's kinetic speed |u| + √(3gh/2)."""
    bed = np.full((ROWS, 10), -2.0)
    state = lake_at_rest(bed, 0.0, 1e-3)
    state.hu[:] = 2.0  # u = 1 m/s
    params = SolverParams(dx=0.5, dy=0.25, order=order, cfl=0.9, boundaries=OPEN_ENDS, scheme="kinetic split")
    a = math.sqrt(1.5 * G * 2.0)
    expected = 2.0 * 0.9 / max((1.0 + a) / 0.5, a / 0.25)
    assert ShallowWaterSolver(bed, params).stable_dt(state) == pytest.approx(expected, rel=ROUNDOFF)


def test_hll_split_stable_dt_uses_each_direction_alone():
    """Sweeps of Δt/2 along x and y, each at ν on its own direction's speed |u| + √(g h)."""
    bed = np.full((ROWS, 10), -2.0)
    state = lake_at_rest(bed, 0.0, 1e-3)
    state.hu[:] = 2.0  # u = 1 m/s
    params = SolverParams(dx=0.5, dy=0.25, order=2, cfl=0.4, boundaries=OPEN_ENDS, scheme="HLL split")
    c = math.sqrt(G * 2.0)
    expected = 2.0 * 0.4 / max((1.0 + c) / 0.5, c / 0.25)
    assert ShallowWaterSolver(bed, params).stable_dt(state) == pytest.approx(expected, rel=ROUNDOFF)


def bumpy_bed(rng, ny=24, nx=32, dx=0.5):
    x = (np.arange(nx) + 0.5) * dx
    y = (np.arange(ny) + 0.5) * dx
    X, Y = np.meshgrid(x, y)
    bed = (-1.0 + 0.08 * X + 0.6 * np.exp(-((X - 6) ** 2 + (Y - 6) ** 2) / 4)
           + 1.3 * np.exp(-((X - 12) ** 2 + (Y - 4) ** 2) / 3) + 0.05 * rng.standard_normal((ny, nx)))
    return bed, dx


@pytest.mark.parametrize("order, scheme", SCHEME_CASES)
@pytest.mark.parametrize("h_min, level, exact", [(1e-3, 0.0, True), (0.0, 0.0, True), (1e-3, 0.25, False)])
def test_lake_at_rest_over_a_bumpy_bed_stays_at_rest(rng, order, scheme, h_min, level, exact):
    """Well balanced with wet and dry cells and islands: bit for bit at rest when every
    z_b + h rounds to the level, within round-off (~1e-15 m/s) when some cannot."""
    bed, dx = bumpy_bed(rng)
    state = lake_at_rest(bed, level, h_min)
    wet = state.h > max(h_min, swe.H_FLOOR)
    assert 0.2 < wet.mean() < 0.9  # the case has both
    start = state.copy()
    # exact where bit-identity is the property; else round-off of the depth and of the wave speed √(g h)
    depth_tolerance = 0.0 if exact else ROUNDOFF * start.h.max()
    speed_tolerance = 0.0 if exact else ROUNDOFF * math.sqrt(G * start.h.max())
    solver = ShallowWaterSolver(bed, SolverParams(dx=dx, dy=dx, order=order, h_min=h_min, scheme=scheme,
                                                  cfl=scheme_cfl(order, scheme)))
    solver.advance(state, 1e9, max_steps=400)
    assert solver.cell_updates == 400 * bed.size
    assert np.max(np.abs(state.h - start.h)) <= depth_tolerance
    u, v = state.velocities(h_min)
    assert np.max(np.abs(u)) <= speed_tolerance and np.max(np.abs(v)) <= speed_tolerance


def test_lake_at_rest_surface_is_as_exact_as_doubles_allow(rng):
    bed, _ = bumpy_bed(rng)
    state = lake_at_rest(bed, 0.0, 1e-3)
    wet = state.h > 1e-3
    assert np.all((bed + state.h)[wet] == 0.0)
    assert np.all(state.h[~wet] == 1e-3)  # land keeps the resting film
    state = lake_at_rest(bed, 0.25, 1e-3)
    wet = state.h > 1e-3
    assert np.mean((bed + state.h)[wet] == 0.25) > 0.5
    assert np.all(np.abs((bed + state.h)[wet] - 0.25) <= 0.5 * np.spacing(state.h[wet]))


@pytest.mark.parametrize("order, scheme", SCHEME_CASES)
def test_sloping_beach_has_no_shoreline_velocities(order, scheme):
    """A lake against a beach, dry land above: |u| stays exactly 0 everywhere (no spurious shoreline flow)."""
    nx, dx = 200, 0.1
    bed = np.tile(-1.0 + 0.15 * (np.arange(nx) + 0.5) * dx, (ROWS, 1))
    state = lake_at_rest(bed, 0.0, 1e-3)
    solver = ShallowWaterSolver(bed, SolverParams(dx=dx, dy=dx, order=order, scheme=scheme,
                                                  cfl=scheme_cfl(order, scheme)))
    solver.advance(state, 1e9, max_steps=3000)
    assert solver.cell_updates == 3000 * bed.size
    u, v = state.velocities(1e-3)
    assert np.all(u == 0.0) and np.all(v == 0.0)
    assert np.all(state.hu == 0.0) and np.all(state.hv == 0.0)


def beach_with_dam(case, h_min=1e-3, n=60, dx=0.25):
    """A 2-D basin with a beach, dry land and either a released water column or a thin film."""
    x = (np.arange(n) + 0.5) * dx
    X, Y = np.meshgrid(x, x)
    bed = -0.5 + 0.1 * X + 0.1 * np.sin(Y)
    if case == "dry bed":
        state = lake_at_rest(bed, 0.0, h_min)
        state.h += np.where(np.hypot(X - 5.0, Y - 7.5) < 2.5, 1.5, 0.0)
    else:  # a thin layer everywhere, barely above the dry threshold, and a small hump
        h = np.full_like(bed, 1.2 * h_min) + np.where(np.hypot(X - 7.5, Y - 7.5) < 2.5, 0.05, 0.0)
        state = State(h, np.zeros_like(h), np.zeros_like(h))
    return bed, state, dx


@pytest.mark.parametrize(
    "order, limiter, scheme",
    [(1, "MC", "kinetic"), (2, "MC", "kinetic"), (2, "minmod", "kinetic"), (2, "van Leer", "kinetic"),
     (2, "MC", "HLL split"), (2, "minmod", "HLL split"),
     (1, "MC", "kinetic split"), (2, "MC", "kinetic split"), (2, "minmod", "kinetic split"),
     (2, "van Leer", "kinetic split")],  # MC is the default
)
@pytest.mark.parametrize("case", ["dry bed", "thin layer"])
def test_depth_positive_and_mass_conserved_on_dry_beds_and_thin_layers(order, limiter, scheme, case):
    """At the Courant number of the positivity bound itself (CFL_BOUND), with every limiter and scheme."""
    bed, state, dx = beach_with_dam(case)
    bound = SPLIT_CFL_BOUND if scheme == "kinetic split" else CFL_BOUND[order]
    params = SolverParams(dx=dx, dy=dx, order=order, cfl=bound, h_min=1e-3, limiter=limiter, scheme=scheme)
    solver = ShallowWaterSolver(bed, params)
    volume = state.volume(dx, dx)
    for k in range(8):
        solver.advance(state, state.t + 0.5)
        assert np.all(np.isfinite(state.h)) and np.all(np.isfinite(state.hu)) and np.all(np.isfinite(state.hv))
        assert state.h.min() >= 0.0
        dry = state.h <= 1e-3
        assert np.all(state.hu[dry] == 0.0) and np.all(state.hv[dry] == 0.0)
    assert state.volume(dx, dx) == pytest.approx(volume, rel=MASS_RTOL)
    assert solver.clamped_volume == 0.0  # positivity came from the scheme, not from the last-resort clamp


@pytest.mark.parametrize("scheme", ["kinetic", "kinetic split"])
def test_manning_friction_decelerates_a_uniform_stream(scheme):
    """Uniform flow, open ends: only friction acts, du/dt = −g n² u²/h^{4/3}.

    The semi-implicit update 1/u^{n+1} = 1/u^n + Δt g n²/h^{4/3} is exact for this ODE.
    """
    h0, u0, n_manning, t_end = 0.5, 2.0, 0.03, 20.0
    nx, dx = 40, 1.0
    solver, state = channel(np.full(nx, h0), np.full(nx, h0 * u0), dx, 1, OPEN_ENDS, manning=n_manning, scheme=scheme)
    solver.advance(state, t_end)
    exact = u0 / (1.0 + G * n_manning**2 * u0 * t_end / h0 ** (4.0 / 3.0))
    u, _ = state.velocities(1e-3)
    assert np.all(state.h == h0)  # fluxes between identical states cancel bit for bit
    # the exact update accumulates only the round-off of its ~100 steps
    np.testing.assert_allclose(u, exact, rtol=ROUNDOFF)


def test_friction_holds_a_thin_film_on_a_slope():
    """The dissertation's resting film: friction in a layer near h_min keeps it from sliding fast."""
    nx, dx = 50, 0.5
    bed = np.tile(0.2 * (np.arange(nx) + 0.5) * dx, (ROWS, 1))  # 20 % slope, all land
    state = State(np.full(bed.shape, 3e-3), np.zeros(bed.shape), np.zeros(bed.shape))
    for manning, bound in ((0.0, None), (0.03, 0.05)):
        s = state.copy()
        solver = ShallowWaterSolver(bed, SolverParams(dx=dx, dy=dx, h_min=1e-3, manning=manning))
        solver.advance(s, 5.0)
        u, _ = s.velocities(1e-3)
        if bound is None:
            frictionless = np.abs(u).max()
        else:
            assert np.abs(u).max() < bound < frictionless


def test_parallel_blocks_match_one_thread(monkeypatch):
    """The row blocks run on several threads give the one-thread result: exactly, but for the 1e-15
    nondeterminism of first-order "kinetic split" (see the NOTE below)."""
    n = 260  # 67 600 cells ≥ PARALLEL_MIN_CELLS
    assert n * n >= swe.PARALLEL_MIN_CELLS
    x = (np.arange(n) + 0.5) * 0.5
    bed = np.broadcast_to(-1.0 + 0.02 * x, (n, n)).copy()
    start = lake_at_rest(bed, 0.0, 1e-3)
    start.h += np.where(np.hypot(x[None, :] - 40, x[:, None] - 65) < 10, 0.5, 0.0)
    for order, scheme in SCHEME_CASES:
        results = []
        for threshold in (swe.PARALLEL_MIN_CELLS, 10**12):
            monkeypatch.setattr(swe, "PARALLEL_MIN_CELLS", threshold)
            state = start.copy()
            params = SolverParams(dx=0.5, dy=0.5, order=order, scheme=scheme, cfl=scheme_cfl(order, scheme))
            ShallowWaterSolver(bed, params).advance(state, 1e9, max_steps=6)
            results.append(state)
        for name in ("h", "hu", "hv"):  # each row block does the same arithmetic on any thread
            # NOTE: first-order "kinetic split" differed from one thread by up to 1e-15 (≈ 4 ulp of the 0.5 m
            # scale) in about half of the pytest runs on 2026-12-04 (never in a plain script), a
            # nondeterminism not yet traced; the other schemes are exact. 1e-13 of the field's scale (h ≤ 1.5 m,
            # |hu| ≲ 1 m² s⁻¹) still catches any block reading a neighbour's half-written rows.
            a, b = getattr(results[0], name), getattr(results[1], name)
            if scheme == "kinetic split" and order == 1:
                np.testing.assert_allclose(a, b, rtol=0, atol=1e-13 * max(1.0, float(np.abs(b).max())))
            else:
                np.testing.assert_array_equal(a, b)


def test_advance_lands_on_t_end_and_counts_updates():
    bed = np.zeros((ROWS, 50))
    solver = ShallowWaterSolver(bed, SolverParams(dx=0.1, dy=0.1))
    state = lake_at_rest(bed, 1.0, 1e-3)
    state.h[:, :25] += 0.5
    h_array = state.h
    assert solver.advance(state, 0.3) is state
    assert state.t == 0.3  # the last step sets t = t_end
    assert state.h is h_array  # updated in place
    steps = solver.cell_updates // bed.size
    assert steps > 0 and solver.cell_updates == steps * bed.size
    solver.advance(state, 10.0, max_steps=3)
    assert solver.cell_updates == (steps + 3) * bed.size and state.t < 10.0
    dt = solver.stable_dt(state)
    solver.step(state, dt)
    assert state.h is h_array


def test_stable_dt_follows_the_courant_number():
    bed = np.full((ROWS, 10), -2.0)
    state = lake_at_rest(bed, 0.0, 1e-3)
    state.hu[:] = 2.0  # u = 1 m/s
    solver = ShallowWaterSolver(bed, SolverParams(dx=0.5, dy=0.25, cfl=0.4, boundaries=OPEN_ENDS))
    a = math.sqrt(1.5 * G * 2.0)  # kinetic speed of the uniform Maxwellian
    assert solver.stable_dt(state) == pytest.approx(0.4 / ((1.0 + a) / 0.5 + a / 0.25), rel=ROUNDOFF)
    dry = State(np.zeros_like(bed), np.zeros_like(bed), np.zeros_like(bed))
    assert solver.stable_dt(dry) == math.inf


def test_state_velocities_are_zero_in_dry_cells():
    state = State(np.array([[0.0, 5e-4, 0.5]]), np.array([[0.0, 1e-3, 0.25]]), np.zeros((1, 3)))
    u, v = state.velocities(1e-3)
    np.testing.assert_array_equal(u, [[0.0, 0.0, 0.5]])  # zeros set in dry cells; 0.25/0.5 is exact
    np.testing.assert_array_equal(v, 0.0)
    # 2 + 5e-4 need not round to the double nearest 2.0005
    np.testing.assert_allclose(state.surface(np.array([[1.0, 2.0, 3.0]])), [[1.0, 2.0005, 3.5]], rtol=0,
                               atol=ROUNDOFF * 3.5)


@pytest.mark.parametrize(
    "bed, message",
    [
        (np.zeros(10), "bed must be a 2-D array"),
        (np.zeros((1, 10)), "ny >= 2"),
        (np.array([[0.0, 1.0], [np.nan, 0.0]]), "bed must be finite; got 1 NaN/inf values, the first at"),
    ],
)
def test_bad_bed_is_refused(bed, message):
    with pytest.raises(ValueError, match=message):
        ShallowWaterSolver(bed, SolverParams(dx=1.0, dy=1.0))


@pytest.mark.parametrize(
    "params, field",
    [
        (dict(cfl=1.2), r"SolverParams\.cfl must be in \(0, 1\.0\] for order 1"),
        (dict(order=2, cfl=0.6), r"SolverParams\.cfl must be in \(0, 0\.5\] for order 2"),
        (dict(h_min=-1e-3), r"SolverParams\.h_min must be >= 0; got -0\.001"),
        (dict(manning=-0.01), r"SolverParams\.manning must be >= 0"),
        (dict(order=3), r"SolverParams\.order must be 1 or 2; got 3"),
        (dict(dx=0.0), r"SolverParams\.dx must be > 0"),
        (dict(g=float("nan")), r"SolverParams\.g must be finite"),
        (dict(boundaries="walls"), r"SolverParams\.boundaries must be a Boundaries"),
        (dict(limiter="superbee"), r"SolverParams\.limiter must be one of \['MC', 'minmod', 'van Leer'\]"),
        (dict(scheme="Roe"), r"SolverParams\.scheme must be one of \['HLL split', 'kinetic', 'kinetic split'\]"),
        (dict(order=2, cfl=1.1, scheme="kinetic split"), r"SolverParams\.cfl must be in \(0, 1\.0\] for order 2"),
    ],
)
def test_bad_parameters_are_refused_with_one_line(params, field):
    kwargs = dict(dx=1.0, dy=1.0) | params
    with pytest.raises(ValueError, match=field) as info:
        SolverParams(**kwargs)
    assert "\n" not in str(info.value)


@pytest.mark.parametrize("case", ["Ritter (dry bed)", "Stoker (wet bed)", "simple wave (smooth)"])
def test_mc_and_van_leer_limiters_beat_minmod(case):
    """The less diffusive limiters lower the second-order error on every validation case (docs/coastal.md)."""
    error, coarse, _, _ = CONVERGENCE[case]
    errors = {limiter: error(2, coarse, limiter=limiter) for limiter in LIMITERS}
    assert errors["MC"] < errors["van Leer"] < errors["minmod"]
    assert errors["MC"] < 0.6 * errors["minmod"]


def test_cfl_bounds_are_accepted():
    SolverParams(dx=1.0, dy=1.0, order=1, cfl=CFL_BOUND[1])
    SolverParams(dx=1.0, dy=1.0, order=2, cfl=CFL_BOUND[2])
    SolverParams(dx=1.0, dy=1.0, order=2, cfl=SPLIT_CFL_BOUND, scheme="kinetic split")


def test_bad_state_is_refused_before_any_work():
    bed = np.zeros((ROWS, 8))
    solver = ShallowWaterSolver(bed, SolverParams(dx=1.0, dy=1.0))
    with pytest.raises(ValueError, match=r"state\.h has shape \(3, 9\)"):
        solver.advance(State(np.ones((ROWS, 9)), np.zeros((ROWS, 9)), np.zeros((ROWS, 9))), 1.0)
    bad = State(np.ones((ROWS, 8)), np.zeros((ROWS, 8)), np.zeros((ROWS, 8)))
    bad.hu[1, 2] = np.nan
    with pytest.raises(ValueError, match="non-finite"):
        solver.advance(bad, 1.0)
    negative = State(-np.ones((ROWS, 8)), np.zeros((ROWS, 8)), np.zeros((ROWS, 8)))
    with pytest.raises(ValueError, match="negative depths"):
        solver.advance(negative, 1.0)
    assert solver.cell_updates == 0


def validation_table() -> str:
    """Markdown table of the convergence study (docs/coastal.md)."""
    lines = ["| case | order | L1 error, coarse [m²] | L1 error, fine [m²] | observed order | accepted range |",
             "|---|---|---|---|---|---|"]
    for case, (_, coarse, fine, ranges) in CONVERGENCE.items():
        for order in (1, 2):
            e_coarse, e_fine, p = observed(case, order)
            lines.append(f"| {case}, nx = {coarse} → {fine} | {order} | {e_coarse:.3e} | {e_fine:.3e} | {p:.2f} | "
                         f"{ranges[order][0]}–{ranges[order][1]} |")
    return "\n".join(lines)


if __name__ == "__main__":
    print(validation_table())
