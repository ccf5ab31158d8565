"""Closed-form shallow-water solutions: conservation laws, jump relations and limits they must satisfy."""

import math

import numpy as np
import pytest

from oceanrender.coastal.analytic import (
    G,
    bore_jump,
    dam_break_ritter,
    dam_break_stoker,
    simple_wave,
    simple_wave_breaking_time,
    stoker_middle_state,
    thacker_paraboloid,
    thacker_planar,
    wall_reflection,
)
from tests.tolerances import ROUNDOFF


def _integral(f, x):
    return float(np.trapezoid(f, x))


def test_ritter_conserves_mass_and_places_the_front():
    x = np.linspace(-10.0, 20.0, 300001)
    for t in (0.3, 1.0, 2.0):
        h, u = dam_break_ritter(x, t, h_left=2.0, x0=0.0)
        assert _integral(h, x) == pytest.approx(2.0 * 10.0, rel=1e-8)  # water that was behind the dam
        front = 2.0 * math.sqrt(G * 2.0) * t
        assert x[h > 0].max() == pytest.approx(front, abs=1e-3)
        assert np.all(u[h == 0] == 0)


def test_ritter_is_continuous_at_the_rarefaction_head():
    c0 = math.sqrt(G * 1.5)
    head = -c0 * 0.7
    h, u = dam_break_ritter(np.array([head - 1e-9, head + 1e-9]), 0.7, h_left=1.5)
    assert h[0] == pytest.approx(h[1], abs=1e-8)
    assert u[1] == pytest.approx(0.0, abs=1e-8)


def test_stoker_middle_state_satisfies_both_waves():
    h_l, h_r = 1.0, 0.1
    h_m, u_m, s = stoker_middle_state(h_l, h_r)
    # rarefaction: the Riemann invariant u + 2c is carried from the still left state
    assert u_m + 2.0 * math.sqrt(G * h_m) == pytest.approx(2.0 * math.sqrt(G * h_l), rel=ROUNDOFF)
    # bore: Rankine–Hugoniot mass and momentum between (h_m, u_m) and (h_r, 0)
    assert s * (h_m - h_r) == pytest.approx(h_m * u_m, rel=ROUNDOFF)
    # the momentum jump is the equation brentq solves for h_m (xtol 1e-15 m, rtol 4ε)
    momentum = h_m * u_m**2 + 0.5 * G * h_m**2 - 0.5 * G * h_r**2
    assert s * h_m * u_m == pytest.approx(momentum, rel=ROUNDOFF)


def test_stoker_conserves_mass_and_matches_ritter_when_dry():
    x = np.linspace(-10.0, 20.0, 300001)
    h, _ = dam_break_stoker(x, 1.2, h_left=1.0, h_right=0.2)
    dx = x[1] - x[0]  # the trapezoid rule is off by ≤ jump × dx/2 at the bore
    assert _integral(h, x) == pytest.approx(1.0 * 10.0 + 0.2 * 20.0, abs=dx)
    # exact: with h_right = 0 Stoker's solution hands over to Ritter's, the same computation
    np.testing.assert_array_equal(dam_break_stoker(x, 0.5, 1.0, 0.0)[0], dam_break_ritter(x, 0.5, 1.0)[0])


def test_dam_breaks_at_t0_are_the_initial_step():
    x = np.array([-1.0, 1.0])
    np.testing.assert_array_equal(dam_break_stoker(x, 0.0, 1.0, 0.3)[0], [1.0, 0.3])
    np.testing.assert_array_equal(dam_break_ritter(x, 0.0, 1.0)[0], [1.0, 0.0])


@pytest.mark.parametrize("u_ahead", [0.0, 0.7, -0.4])
def test_bore_jump_satisfies_rankine_hugoniot(u_ahead):
    j = bore_jump(h_ahead=0.5, u_ahead=u_ahead, h_behind=1.3)
    mass = j.speed * (j.h_behind - j.h_ahead) - (j.h_behind * j.u_behind - j.h_ahead * j.u_ahead)
    flux = lambda h, u: h * u**2 + 0.5 * G * h**2  # noqa: E731
    momentum = j.speed * (j.h_behind * j.u_behind - j.h_ahead * j.u_ahead) - (
        flux(j.h_behind, j.u_behind) - flux(j.h_ahead, j.u_ahead)
    )
    # residuals of differences of terms of the size of the discharge and the momentum flux behind
    assert abs(mass) < ROUNDOFF * abs(j.speed) * j.h_behind
    assert abs(momentum) < ROUNDOFF * flux(j.h_behind, j.u_behind)
    assert j.froude > 1 and j.head_loss > 0  # a bore is supercritical relative to the water ahead
    # the energy jump, s [E] − [F_E], is the power lost in the bore: g × (discharge through it) × head loss
    q = j.h_ahead * (j.speed - j.u_ahead)
    energy = lambda h, u: 0.5 * h * u**2 + 0.5 * G * h**2  # noqa: E731
    e_flux = lambda h, u: u * (0.5 * h * u**2 + G * h**2)  # noqa: E731
    loss = j.speed * (energy(j.h_behind, j.u_behind) - energy(j.h_ahead, j.u_ahead)) - (
        e_flux(j.h_behind, j.u_behind) - e_flux(j.h_ahead, j.u_ahead)
    )
    assert -loss == pytest.approx(G * q * j.head_loss, rel=1e-10)  # a difference of energy fluxes ~10× larger


def test_weak_bore_moves_at_the_long_wave_speed():
    j = bore_jump(1.0, 0.0, 1.0 + 1e-7)
    assert j.speed == pytest.approx(math.sqrt(G), rel=1e-6)  # √(g h)(1 + 3ε/4 + …) with ε = 1e-7


def test_wall_reflection_brings_the_stream_to_rest():
    h_wall, speed = wall_reflection(0.6, 1.4)
    j = bore_jump(0.6, -1.4, h_wall)  # mirror frame
    assert j.u_behind == pytest.approx(0.0, abs=ROUNDOFF * 1.4)  # scale: the stream's 1.4 m/s
    assert speed == pytest.approx(-j.speed, rel=ROUNDOFF) and speed < 0
    # weak limit: linear reflection doubles the velocity head, h_wall − h ≈ u √(h/g)
    h_weak, _ = wall_reflection(1.0, 1e-4)
    assert h_weak - 1.0 == pytest.approx(1e-4 * math.sqrt(1.0 / G), rel=1e-3)


def test_simple_wave_keeps_its_riemann_invariant_and_mass():
    h0, a, w = 1.0, 0.2, 1.0
    t_b = simple_wave_breaking_time(h0, a, w)
    x = np.linspace(-10.0, 30.0, 200001)
    h_init, u_init = simple_wave(x, 0.0, h0, a, w)
    np.testing.assert_allclose(h_init, h0 + a * np.exp(-(x**2)), rtol=ROUNDOFF)
    for t in (0.3 * t_b, 0.9 * t_b):
        h, u = simple_wave(x, t, h0, a, w)
        np.testing.assert_allclose(u - 2.0 * np.sqrt(G * h), -2.0 * math.sqrt(G * h0), rtol=ROUNDOFF)
        assert _integral(h - h0, x) == pytest.approx(_integral(h_init - h0, x), rel=1e-6)
    with pytest.raises(ValueError, match="before breaking"):
        simple_wave(x, 1.01 * t_b, h0, a, w)


@pytest.mark.parametrize(
    "call, name",
    [
        (lambda: dam_break_ritter([0.0], 1.0, h_left=-1.0), "h_left"),
        (lambda: stoker_middle_state(1.0, 2.0), "h_left > h_right"),
        (lambda: bore_jump(1.0, 0.0, 0.5), "h_behind > h_ahead"),
        (lambda: wall_reflection(1.0, 0.0), "u_stream"),
    ],
)
def test_refuses_impossible_states(call, name):
    with pytest.raises(ValueError, match=name):
        call()


def test_thacker_planar_conserves_volume_and_solves_the_equations():
    """Volume constant, surface planar, and the residuals of (1a)–(1b) vanish on the wet part."""
    params = dict(h0=0.5, a=1.0, amplitude=0.5, x_c=2.0)
    omega = math.sqrt(2.0 * G * 0.5)
    x = np.linspace(0.0, 4.0, 400001)
    volume = _integral(thacker_planar(x, 0.0, **params)[1], x)
    assert volume == pytest.approx(4.0 / 3.0 * 0.5 * 1.0, rel=1e-9)  # ∫ h0 (1 − ξ²/a²) dξ = 4 h0 a / 3
    xs = np.linspace(1.8, 2.2, 41)  # stays wet: |ξ| < a − B/ω ≈ 0.84 m
    for t in (0.1, 0.7, 1.3):
        assert _integral(thacker_planar(x, t, **params)[1], x) == pytest.approx(volume, rel=1e-9)
        bed, h, u = thacker_planar(xs, t, **params)
        eta = bed + h
        assert np.ptp(np.diff(eta) / np.diff(xs)) < 1e-9  # a plane
        dt, dx = 1e-5, 1e-5
        _, hp, up = thacker_planar(xs, t + dt, **params)
        _, hm, um = thacker_planar(xs, t - dt, **params)
        bx_p, hx_p, _ = thacker_planar(xs + dx, t, **params)
        bx_m, hx_m, _ = thacker_planar(xs - dx, t, **params)
        mass = (hp - hm) / (2 * dt) + u * (hx_p - hx_m) / (2 * dx)  # u is uniform: ∂x(hu) = u ∂x h
        momentum = (up - um) / (2 * dt) + G * ((bx_p + hx_p) - (bx_m + hx_m)) / (2 * dx)  # u_t + g η_x
        assert np.abs(mass).max() < 1e-6 and np.abs(momentum).max() < 1e-5
    # the shorelines move with the water: x± = x_c − (B/ω) cos ωt ± a
    _, h, u = thacker_planar(x, 0.4, **params)
    wet = x[h > 0]
    centre = 2.0 - (0.5 / omega) * math.cos(omega * 0.4)
    assert wet.min() == pytest.approx(centre - 1.0, abs=2e-5) and wet.max() == pytest.approx(centre + 1.0, abs=2e-5)
    assert np.all(u[h == 0] == 0.0) and u[h > 0][0] == pytest.approx(0.5 * math.sin(omega * 0.4), rel=ROUNDOFF)


def test_thacker_paraboloid_solves_the_2d_equations_with_a_circling_wet_disc():
    """Thacker's 2D planar surface: the residuals of the 2D equations (centred differences, step 1e-5; the
    velocity is uniform, so ∂x(hu) = u ∂x h) vanish on the wet part, the volume is that of the paraboloid's
    still water (π h0 a²/2) at every time, and the wet disc of radius a circles the centre at radius eta."""
    params = dict(h0=0.1, a=1.0, eta=0.5, x_c=2.0, y_c=2.0)
    omega = math.sqrt(2.0 * G * 0.1)
    grid = np.linspace(0.0, 4.0, 2001)
    X, Y = np.meshgrid(grid, grid)
    cell = (grid[1] - grid[0]) ** 2
    xs, ys = np.meshgrid(np.linspace(1.9, 2.1, 11), np.linspace(1.9, 2.1, 11))  # wet at all times (|r| < a − eta)
    e = 1e-5
    for t in (0.0, 0.6, 1.7):
        _, h, _, _ = thacker_paraboloid(X, Y, t, **params)
        # a midpoint sum over a kinked profile: relative to the volume, 1e-4 at this grid
        assert h.sum() * cell == pytest.approx(math.pi * 0.1 * 1.0 / 2.0, rel=1e-4)
        wet = h > 0
        centre = (0.5 * math.cos(omega * t), 0.5 * math.sin(omega * t))
        assert X[wet].mean() - 2.0 == pytest.approx(centre[0], abs=1e-3)
        assert Y[wet].mean() - 2.0 == pytest.approx(centre[1], abs=1e-3)
        f = lambda dx=0.0, dy=0.0, dt=0.0: thacker_paraboloid(xs + dx, ys + dy, t + dt, **params)  # noqa: E731
        bed, h, u, v = f()
        ht = (f(dt=e)[1] - f(dt=-e)[1]) / (2 * e)
        hx = (f(dx=e)[1] - f(dx=-e)[1]) / (2 * e)
        hy = (f(dy=e)[1] - f(dy=-e)[1]) / (2 * e)
        ex = ((f(dx=e)[0] + f(dx=e)[1]) - (f(dx=-e)[0] + f(dx=-e)[1])) / (2 * e)
        ey = ((f(dy=e)[0] + f(dy=e)[1]) - (f(dy=-e)[0] + f(dy=-e)[1])) / (2 * e)
        ut = (f(dt=e)[2] - f(dt=-e)[2]) / (2 * e)
        vt = (f(dt=e)[3] - f(dt=-e)[3]) / (2 * e)
        # finite differences of O(1) fields with step 1e-5: truncation ~1e-10, round-off ~1e-11
        assert np.abs(ht + u * hx + v * hy).max() < 1e-6
        assert np.abs(ut + G * ex).max() < 1e-5 and np.abs(vt + G * ey).max() < 1e-5
    with pytest.raises(ValueError, match="eta"):
        thacker_paraboloid(0.0, 0.0, 0.0, h0=0.1, a=1.0, eta=1.0)


def test_synolakis_solitary_wave_starts_with_its_front_at_the_beach_toe():
    """Synolakis (1987): the crest at X₁ = X₀ + L from the shoreline so that η = H/20 at the toe X₀ = d cot β,
    u = √(g/d) η; the run-up law grows as H^{5/4} and √(cot β)."""
    import math

    from oceanrender.coastal.analytic import solitary_runup, solitary_wave

    H, d, cot = 0.0185, 1.0, 19.85
    gamma = math.sqrt(3.0 * H / 4.0)
    x1 = d * cot + math.acosh(math.sqrt(20.0)) / gamma
    eta, u = solitary_wave(np.array([-x1, -d * cot]), H, d, cot)
    assert eta[0] == pytest.approx(H, rel=1e-12)
    assert eta[1] == pytest.approx(H / 20.0, rel=1e-9)  # the front at the toe
    assert u[0] == pytest.approx(math.sqrt(9.81 / d) * H, rel=1e-12)
    assert solitary_runup(2 * H, d, cot) / solitary_runup(H, d, cot) == pytest.approx(2**1.25, rel=1e-12)
    assert solitary_runup(H, d, 4 * cot) / solitary_runup(H, d, cot) == pytest.approx(2.0, rel=1e-12)
    with pytest.raises(ValueError, match="height"):
        solitary_runup(-0.1, d, cot)
