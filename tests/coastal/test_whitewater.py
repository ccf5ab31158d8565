"""Tests for oceanrender.coastal.whitewater: bore dissipation against the jump relations, and where it is white."""

import numpy as np
import pytest

from oceanrender.coastal.analytic import bore_jump, dam_break_stoker
from oceanrender.coastal.boundaries import Boundaries, Transmissive
from oceanrender.coastal.swe import ShallowWaterSolver, SolverParams, State
from oceanrender.coastal.whitewater import (
    SEAWATER_DENSITY,
    bore_dissipation_rate,
    bore_power_per_length,
    whitewater_coverage,
)
from tests.tolerances import ROUNDOFF

G = 9.81


@pytest.mark.parametrize(("h1", "h2"), [(0.5, 1.0), (0.2, 0.26), (1.0, 3.0)])
def test_bore_power_is_the_flux_times_the_head_loss(h1, h2):
    # Independent route: the Rankine–Hugoniot bore of coastal.analytic; P = ρ g Q ΔH, Q = h₁ (s − u₁)
    jump = bore_jump(h_ahead=h1, u_ahead=0.0, h_behind=h2)
    expected = SEAWATER_DENSITY * G * h1 * jump.speed * jump.head_loss
    assert bore_power_per_length(h1, h2) == pytest.approx(expected, rel=1e-9)  # two closed forms, float64
    assert bore_power_per_length(h2, h1) == pytest.approx(expected, rel=ROUNDOFF)  # either order
    assert bore_power_per_length(h1, h1) == 0.0 and bore_power_per_length(0.0, h2) == 0.0


def rows(profile, count=3):
    return np.tile(profile, (count, 1))


def test_only_the_bore_of_stokers_dam_break_is_white():
    # Exact Stoker solution at t = 1 s on 2 cm cells: a rarefaction (smooth, diverging) and a bore.
    dx, t = 0.02, 1.0
    x = (np.arange(600) + 0.5) * dx - 6.0
    h, u = dam_break_stoker(x, t, 1.0, 0.4)
    rate = bore_dissipation_rate(rows(h), rows(h * u), rows(np.zeros_like(h)), (dx, dx), 1e-3)[1]
    white = whitewater_coverage(rate, 100.0) > 0
    from oceanrender.coastal.analytic import stoker_middle_state

    h_m, _, speed = stoker_middle_state(1.0, 0.4)
    front = speed * t
    assert white.any() and np.all(np.abs(x[white] - front) < 2 * dx)  # at the bore, nowhere else
    # integrated across the front, D is the bore's P per unit length: the jump is one cell face here
    assert np.sum(rate) * dx == pytest.approx(bore_power_per_length(0.4, h_m), rel=ROUNDOFF)
    # the rarefaction: the flow diverges, no dissipation at all
    fan = (x > -np.sqrt(G) * t + 2 * dx) & (x < 0.5 * front)
    assert np.all(rate[fan] == 0)


def test_still_and_diverging_water_dissipate_nothing(rng):
    h = rng.uniform(0.1, 1.0, (20, 30))
    assert np.all(bore_dissipation_rate(h, 0 * h, 0 * h, (0.1, 0.1), 1e-3) == 0)
    x = np.linspace(0, 1, 30)
    u = np.tile(x, (20, 1))  # u grows with x everywhere: expanding flow
    assert np.all(bore_dissipation_rate(h, h * u, 0 * h, (0.1, 0.1), 1e-3) == 0)


def test_coverage_ramps_from_the_threshold():
    np.testing.assert_allclose(whitewater_coverage([0.0, 50.0, 100.0, 141.42135623730951, 200.0, 1e4], 100.0),
                               [0, 0, 0, 0.5, 1, 1], atol=ROUNDOFF)
    with pytest.raises(ValueError):
        whitewater_coverage(1.0, 0.0)


def test_solver_bore_is_white_where_the_analytic_bore_is():
    # The shallow-water solver's own captured bore: the criterion finds it within a few cells of
    # Stoker's front and nowhere in the smooth rarefaction.
    nx, dx, t_end = 400, 0.025, 0.8
    x = (np.arange(nx) + 0.5) * dx - 5.0
    h0 = np.where(x < 0, 1.0, 0.4)
    solver = ShallowWaterSolver(np.zeros((3, nx)), SolverParams(
        dx=dx, dy=dx, order=2, h_min=1e-3, boundaries=Boundaries(west=Transmissive(), east=Transmissive())))
    state = State(rows(h0), np.zeros((3, nx)), np.zeros((3, nx)))
    solver.advance(state, t_end)
    rate = bore_dissipation_rate(state.h, state.hu, state.hv, (dx, dx), 1e-3)[1]
    white = whitewater_coverage(rate, 100.0) > 0
    from oceanrender.coastal.analytic import stoker_middle_state

    front = stoker_middle_state(1.0, 0.4)[2] * t_end
    assert white.any() and np.all(np.abs(x[white] - front) < 4 * dx)  # captured over 2–3 cells
