"""Floating objects: the wave plane under a hull and its damped response (oceanrender.waves.floating)."""

import math

import numpy as np
import pytest

from tests.scenes import scene_from_dict
from oceanrender.waves.floating import (RESPONSE_HISTORY_TAUS, floating_pose, footprint, response_weights,
                                        wave_plane)
from oceanrender.waves.gerstner import WaveComponent
from oceanrender.waves.sea import SeaSurface
from oceanrender.waves.wave_spectra import dispersion_relation

from ..tolerances import ROUNDOFF


def test_response_weights_are_the_critically_damped_impulse_response():
    lags, w = response_weights(2.0)
    assert w.sum() == pytest.approx(1.0, abs=ROUNDOFF)
    # Mean delay of h(s) = s e^{-s/τ}/τ² is 2τ; truncated at 8τ (tail 3e-3 of the area) and trapezoid-summed
    # at τ/4 steps: within 2 % of 2τ.
    assert (lags * w).sum() == pytest.approx(4.0, rel=0.02)
    assert lags[-1] == pytest.approx(RESPONSE_HISTORY_TAUS * 2.0)
    assert response_weights(0.0)[1].tolist() == [1.0]
    with pytest.raises(ValueError, match="response_time"):
        response_weights(-1.0)


def _one_wave_sea(amplitude=0.5, wavelength=80.0, direction_deg=30.0):
    """A sum-of-sines sea holding one long wave (its components replaced)."""
    sea = SeaSurface(scene_from_dict({"name": "f", "ocean": {"model": "sum of sines", "wave_count": 1}}).ocean)
    k = 2 * math.pi / wavelength
    d = math.radians(direction_deg)
    sea.components = [WaveComponent(amplitude, k * math.cos(d), k * math.sin(d), 0.4)]
    return sea, k * math.cos(d), k * math.sin(d)


def test_wave_plane_of_a_long_wave_is_its_tangent_plane():
    # A hull of 8 m on an 80 m wave: the least-squares plane over the footprint is the wave's tangent plane at
    # the centre to O((k L)²) ≈ 0.4 of the curvature term: compare with the closed-form height and slope there.
    sea, kx, ky = _one_wave_sea()
    t = 1.3
    omega = float(dispersion_relation(math.hypot(kx, ky)))
    centre = np.array([3.0, -2.0])
    points = centre + footprint((-4.0, 4.0), (-1.5, 1.5))
    h, a, b = wave_plane(sea, points, t, spacing=1.0)
    phase = kx * centre[0] + ky * centre[1] - omega * t + 0.4
    # Height: the mean of cos over the footprint differs from cos at the centre by ≤ (k·4 m)²/6 of the amplitude.
    assert h == pytest.approx(0.5 * math.cos(phase), abs=0.5 * (2 * math.pi / 80 * 4) ** 2 / 6 + 1e-9)
    slope = -0.5 * math.sin(phase) * np.array([kx, ky])
    np.testing.assert_allclose([a, b], slope, atol=0.5 * math.hypot(kx, ky) * (2 * math.pi / 80 * 4) ** 2 / 6)


def test_pose_follows_the_plane_without_damping_and_is_a_function_of_time():
    sea, kx, ky = _one_wave_sea(direction_deg=90.0)  # the wave runs north: along a north-heading bow
    points = footprint((-5.0, 5.0), (-1.5, 1.5))
    t = 2.0
    pose = floating_pose(sea, points, lambda s: np.array([0.0, 0.0]), 0.0, t, 0.0, 1.0)
    world = np.stack([-points[:, 1], points[:, 0]], -1)  # heading 0: forward is north, left is west
    h, a, b = wave_plane(sea, world, t, 1.0)
    assert pose.heave == pytest.approx(h, abs=ROUNDOFF)  # footprint centred on the origin
    assert pose.pitch == pytest.approx(math.degrees(math.atan(b)), abs=ROUNDOFF)  # bow north: dη/dy
    assert pose.roll == pytest.approx(math.degrees(math.atan(-a)), abs=ROUNDOFF)  # left is west: −dη/dx
    # Damped: another sea object and no earlier call give the same bits (Dask workers, resumed runs).
    damped = floating_pose(sea, points, lambda s: np.array([0.0, 0.0]), 0.0, t, 1.0, 1.0)
    again = floating_pose(_one_wave_sea(direction_deg=90.0)[0], points, lambda s: np.array([0.0, 0.0]), 0.0, t, 1.0, 1.0)
    assert damped == again
    # A response time much longer than the wave period averages the heave out.
    slow = floating_pose(sea, points, lambda s: np.array([0.0, 0.0]), 0.0, t, 20.0, 1.0)
    assert abs(slow.heave) < 0.1 * 0.5
