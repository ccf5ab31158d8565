"""Sides of the shallow-water grid: ghost cells, incident waves, absorption and validation."""

import dataclasses
import math

import numpy as np
import pytest

from oceanrender.coastal.analytic import simple_wave
from oceanrender.coastal.boundaries import (
    SIDES,
    Boundaries,
    BoundaryPlan,
    IncidentWave,
    Transmissive,
    Wall,
)
from oceanrender.coastal.swe import G, ShallowWaterSolver, SolverParams, State, lake_at_rest
from tests.tolerances import ROUNDOFF

ROWS = 3
DEPTH = 1.0


def flat_channel(nx, dx, order, west, east, start=None):
    bed = np.full((ROWS, nx), -DEPTH)
    solver = ShallowWaterSolver(bed, SolverParams(dx=dx, dy=dx, order=order,
                                                  boundaries=Boundaries(west=west, east=east)))
    return solver, lake_at_rest(bed, 0.0, 1e-3) if start is None else start


def wave_heights(solver, state, period, samples=40):
    """Advance one period in ``samples`` stops: (η − DEPTH of the middle row per stop, half its range per cell)."""
    record = []
    for _ in range(samples):
        solver.advance(state, state.t + period / samples)
        record.append(state.h[1] - DEPTH)
    record = np.array(record)
    return record, 0.5 * (record.max(axis=0) - record.min(axis=0))


def test_wall_ghosts_mirror_and_transmissive_ghosts_copy(rng):
    ny, nx, K = 5, 6, 2
    bed = rng.uniform(-2, -1, (ny, nx))
    h, hu, hv = rng.uniform(0.5, 1.0, (ny, nx)), rng.normal(size=(ny, nx)), rng.normal(size=(ny, nx))
    plan = BoundaryPlan(Boundaries(west=Wall(), east=Transmissive(), south=Wall(), north=Transmissive()),
                        bed, 1.0, 1.0, G, 1e-3, K)
    columns, rows = plan.new_ghosts()
    plan.fill(0.0, h, hu, hv, columns, rows)
    for k in range(K):  # ghosts are copies and negations of cells: exact
        np.testing.assert_array_equal(columns[0, 0, k], h[:, k])  # west wall: mirror of cell k
        np.testing.assert_array_equal(columns[0, 1, k], -hu[:, k])  # normal discharge reversed
        np.testing.assert_array_equal(columns[0, 2, k], hv[:, k])
        np.testing.assert_array_equal(columns[1, :, k], np.stack([h, hu, hv])[:, :, -1])  # east: copy
        np.testing.assert_array_equal(rows[0, 2, k], -hv[k, :])  # south wall reverses hv
        np.testing.assert_array_equal(rows[1, :, k], np.stack([h, hu, hv])[:, -1, :])
        np.testing.assert_array_equal(plan.zpad[2:-2, 1 - k], bed[:, k])  # mirrored bed
    np.testing.assert_array_equal(plan.walls, [1, 0, 1, 0])


def test_absorbing_sides_keep_a_lake_exactly_at_rest():
    sea = IncidentWave.absorbing(0.0)
    solver, state = flat_channel(40, 0.5, 2, sea, sea)
    solver.advance(state, 20.0)
    # exact: fluxes between identical states and still incoming water cancel bit for bit
    assert np.all(state.h == DEPTH) and np.all(state.hu == 0.0)


@pytest.mark.parametrize("order", [1, 2])
def test_incident_wave_train_enters_with_its_amplitude(order):
    """Flat channel, 1 m deep: a 2 cm, 6 s train from the west; absorbing east side."""
    amplitude, period, nx, dx = 0.02, 6.0, 200, 0.25
    train = IncidentWave.wave_train(amplitude, period, ramp_time=period)
    solver, state = flat_channel(nx, dx, order, train, IncidentWave.absorbing(0.0))
    solver.advance(state, 5 * period)
    record, height = wave_heights(solver, state, period)
    near = int(1.0 / dx)  # 1 m (4 cells) inside the side
    assert height[near] == pytest.approx(amplitude, rel=0.03)
    assert abs(record[:, near].mean()) < 0.02 * amplitude  # no set-up or drift of the mean level
    # farther in, the amplitude only decays (numerical dissipation), it never grows; 40 samples a
    # period under-read the amplitude by up to a (1 − cos(π/40)) ≈ 6e-5 m
    assert np.all(np.diff(height[near: nx - 20]) < 1e-4)


@pytest.mark.parametrize("order", [1, 2])
@pytest.mark.parametrize("east, limit", [(IncidentWave.absorbing(0.0), 0.005), (Transmissive(), 0.08)])
def test_outgoing_pulse_leaves_with_small_reflection(order, east, limit):
    """A right-running simple-wave pulse (2 cm) crosses the east side; what stays behind is reflection."""
    amplitude, nx, dx = 0.02, 160, 0.25
    x = (np.arange(nx) + 0.5) * dx
    h, u = simple_wave(x, 0.0, DEPTH, amplitude, 2.0, x_c=20.0)
    start = State(np.tile(h, (ROWS, 1)), np.tile(h * u, (ROWS, 1)), np.zeros((ROWS, nx)))
    solver, state = flat_channel(nx, dx, order, IncidentWave.absorbing(0.0), east, start)
    solver.advance(state, 30.0 / math.sqrt(G * DEPTH))  # the pulse has left through the east side
    assert np.abs(state.h - DEPTH).max() < limit * amplitude


def test_incident_forcing_follows_the_wave_phase_along_the_side():
    """The ghost forcing on the west side is η_in(0, y, t): the along-side phase sets the direction."""
    ny, nx, dx = 16, 8, 0.5
    bed = np.full((ny, nx), -2.0)
    wave = IncidentWave.wave_train(0.1, 5.0, direction_deg=25.0, phase=0.3)
    plan = BoundaryPlan(Boundaries(west=wave), bed, dx, dx, G, 1e-3, 1)
    forcing, _ = plan._incident[0]
    y = (np.arange(ny) + 0.5) * dx
    for t in (0.0, 1.3, 7.0):
        eta, u = forcing.forcing(t)
        # cosines crossing zero: relative to the amplitude (0.1 m) and to its velocity
        np.testing.assert_allclose(eta, wave.elevation(t, 0.0, y, 2.0), rtol=0, atol=ROUNDOFF * 0.1)
        # linear long wave: normal velocity √(g/d) η cos θ
        u_scale = math.sqrt(G / 2.0) * 0.1
        np.testing.assert_allclose(u, math.sqrt(G / 2.0) * math.cos(math.radians(25.0)) * eta, rtol=0,
                                   atol=ROUNDOFF * u_scale)
    k = (2 * math.pi / 5.0) / math.sqrt(G * 2.0)
    theta = math.radians(25.0)
    # the cosine is near a zero here (−0.025): relative to the amplitude 0.1 m
    assert wave.elevation(2.0, 1.0, 3.0, 2.0) == pytest.approx(
        0.1 * math.cos(k * (math.cos(theta) + 3.0 * math.sin(theta)) - 2 * math.pi / 5.0 * 2.0 + 0.3), rel=0,
        abs=ROUNDOFF * 0.1)


def test_wave_train_is_one_component_and_ramps_smoothly():
    train = IncidentWave.wave_train(0.5, 4.0, direction_deg=90.0, still_level=0.2, ramp_time=8.0)
    same = IncidentWave.from_components([0.5], [2 * math.pi / 4.0], [math.pi / 2], [0.0], still_level=0.2,
                                        ramp_time=8.0)
    # the same component by two formulas (radians(90°) against π/2): equal to round-off, field by field
    for field in dataclasses.fields(IncidentWave):
        a, b = getattr(train, field.name), getattr(same, field.name)
        assert a == (b if b is None else pytest.approx(b, rel=ROUNDOFF, abs=ROUNDOFF * math.pi)), field.name
    assert train.ramp(0.0) == 0.0 and train.ramp(4.0) == pytest.approx(0.5) and train.ramp(9.0) == 1.0
    assert IncidentWave.absorbing().amplitudes == ()


@pytest.mark.parametrize("order", [1, 2])
def test_waves_run_up_a_beach_without_negative_depth(order):
    """The open sea drives waves up a 1:10 beach with dry land: no NaN, h ≥ 0, real run-up."""
    nx, dx = 160, 0.25
    x = (np.arange(nx) + 0.5) * dx
    bed = np.tile(np.minimum(-1.0 + 0.1 * np.maximum(x - 15.0, 0.0), 1.5), (ROWS, 1))
    sea = IncidentWave.wave_train(0.1, 5.0, ramp_time=5.0)
    solver = ShallowWaterSolver(bed, SolverParams(dx=dx, dy=dx, order=order, boundaries=Boundaries(west=sea)))
    state = lake_at_rest(bed, 0.0, 1e-3)
    highest = -np.inf
    for _ in range(12):
        solver.advance(state, state.t + 2.5)
        assert np.all(np.isfinite(state.h)) and state.h.min() >= 0.0
        wet = state.h > 1e-3
        highest = max(highest, float(bed[wet].max()))
    assert highest > 0.05  # the shoreline climbed above the still level
    assert solver.clamped_volume == 0.0


@pytest.mark.parametrize(
    "make, message",
    [
        (lambda: IncidentWave([0.1, 0.2], [1.0], [0.0], [0.0]), "equal lengths"),
        (lambda: IncidentWave([-0.1], [1.0], [0.0], [0.0]), r"IncidentWave\.amplitudes must be >= 0"),
        (lambda: IncidentWave([0.1], [0.0], [0.0], [0.0]), r"IncidentWave\.omegas must be > 0"),
        (lambda: IncidentWave([0.1], [1.0], [np.nan], [0.0]), r"IncidentWave\.directions must be finite"),
        (lambda: IncidentWave.wave_train(0.1, -2.0), "period must be > 0"),
        (lambda: IncidentWave(ramp_time=-1.0), r"IncidentWave\.ramp_time must be >= 0"),
        (lambda: Boundaries(north="open"), r"Boundaries\.north must be Wall\(\), Transmissive\(\)"),
    ],
)
def test_bad_sides_are_refused(make, message):
    with pytest.raises(ValueError, match=message):
        make()


def test_sides_are_in_solver_order():
    b = Boundaries(west=Transmissive(), north=IncidentWave.absorbing())
    assert SIDES == ("west", "east", "south", "north")
    assert [type(s).__name__ for s in b.sides()] == ["Transmissive", "Wall", "Wall", "IncidentWave"]
