"""The coast inside the open sea: the sea's long waves, the solver's side, the terrain beyond, the blend."""

from __future__ import annotations

import math

import numpy as np
import pytest

from oceanrender.coastal import embedding
from oceanrender.coastal.embedding import (BREAKER_INDEX_RMS, DomainFrame, SeaModes, blend_weight, depth_taper,
                                           incident_from_modes, sea_long_modes, terrain_height)
from oceanrender.scene import SceneError, load_scene
from tests.scenes import scene_from_dict
from oceanrender.waves.lod import bilinear_power_gain
from oceanrender.waves.sea import SeaSurface
from tests.tolerances import ROUNDOFF, ROUNDOFF32

#: A small FFT sea in 8 m of water: 256 m patch, 64 points, two cascades.
OCEAN = {"model": "FFT", "spectrum": "JONSWAP 1973", "wind_speed": 8.0, "wind_direction": -80.0,
         "patch_size": 256.0, "resolution": 64, "cascades": 2, "wave_depth": 8.0, "seed": 5,
         "swell_height": 0.8, "swell_period": 9.0, "swell_direction": -90.0}


def small_sea() -> SeaSurface:
    return SeaSurface(scene_from_dict({"name": "e", "ocean": OCEAN}).ocean)


def test_the_long_modes_are_the_fft_seas_own_waves():
    """Summed directly, the first cascade's modes give its FFT field at its grid points, at any time.

    The level's amplitudes are drawn from Ψ/g (interpolation gain); the modes
    carry the spectrum's own amplitude, so the comparison divides by √g. The FFT
    runs in the sea's precision (complex64 by default): ROUNDOFF32 of the field's
    largest value.
    """
    sea = small_sea()
    ocean = sea.levels[0].oceans[0]
    modes = sea_long_modes(sea, math.inf)
    grid = ocean.grid
    gain = bilinear_power_gain(modes.kx, modes.ky, grid.spacing)
    raw = SeaModes(modes.kx, modes.ky, modes.amplitude / np.sqrt(gain), modes.phase, modes.omega, modes.choppiness)
    for t in (0.0, 7.3, 1234.5):
        fields = ocean.fields(t)
        direct = raw.fields(grid.x, grid.y, t, method="direct")
        for ours, theirs in zip(direct, (fields.height, fields.displacement_x, fields.displacement_y,
                                         fields.slope_x, fields.slope_y)):
            scale = np.abs(theirs).max()
            np.testing.assert_allclose(ours, theirs, rtol=0, atol=ROUNDOFF32 * scale)


def test_the_fft_sum_of_the_modes_equals_the_direct_sum():
    """32 points per shortest wavelength: linear interpolation keeps a wave to 1 − cos(π/32) = 0.48 %."""
    sea = small_sea()
    modes = sea_long_modes(sea, 0.2)
    rng = np.random.default_rng(1)
    x, y = rng.uniform(-400, 400, 500), rng.uniform(-400, 400, 500)
    direct = modes.fields(x, y, 11.0, method="direct")
    fft = modes.fields(x, y, 11.0, method="fft")
    bound = 1.0 - math.cos(math.pi / 32)
    for ours, theirs, limit in zip(fft, direct, modes._multipliers()):
        # each field's error is at most the bound × Σ |multiplier| a_n (every wave at its worst point)
        worst = bound * np.sum(np.abs(limit) * modes.amplitude)
        assert np.abs(ours - theirs).max() <= worst


def test_the_solver_side_sees_the_seas_long_waves_in_its_own_frame():
    """Rotated 30°, moved, and on the solver's clock τ = spinup + t: the side's η is the inward modes' η."""
    sea = small_sea()
    modes = sea_long_modes(sea, 0.2)
    frame = DomainFrame(origin=(-35.0, 20.0), rotation=30.0, size=(60.0, 40.0))
    spinup = 12.5
    wave = incident_from_modes(modes, frame, "north", spinup, ramp_time=0.0)
    xi = np.linspace(0.0, 60.0, 25)
    zeta = np.full_like(xi, 40.0)
    x, y = frame.to_world(xi, zeta)
    klx, kly = frame.vector_to_local(modes.kx, modes.ky)
    inward = modes.subset(np.sin(np.arctan2(kly, klx)) < 0)  # north side: travelling towards −ζ
    assert 0 < len(wave.amplitudes) == inward.count < modes.count
    for t in (0.0, 3.3, 40.0):
        side = wave.elevation(spinup + t, xi, zeta, depth=8.0)
        sea_side = inward.fields(x, y, t, method="direct")[0]
        np.testing.assert_allclose(side, sea_side, rtol=0, atol=ROUNDOFF * 1e3 * inward.amplitude.sum())


def test_frame_round_trip_and_rotation():
    frame = DomainFrame(origin=(10.0, -5.0), rotation=90.0, size=(4.0, 2.0))
    x, y = frame.to_world(1.0, 0.0)  # one metre along the grid's x axis = world +y
    assert x == pytest.approx(10.0, abs=ROUNDOFF) and y == pytest.approx(-4.0, abs=ROUNDOFF)
    xi, zeta = frame.to_local(x, y)
    assert xi == pytest.approx(1.0, abs=ROUNDOFF) and zeta == pytest.approx(0.0, abs=ROUNDOFF)


def test_blend_weight_is_one_inside_zero_outside_and_its_gradient_is_exact():
    frame = DomainFrame(origin=(0.0, 0.0), rotation=20.0, size=(100.0, 80.0))
    rng = np.random.default_rng(2)
    xi, zeta = rng.uniform(-20, 120, 4000), rng.uniform(-20, 100, 4000)
    x, y = frame.to_world(xi, zeta)
    w, wx, wy = blend_weight(frame, "north", 15.0, x, y)
    inside = (xi >= 15) & (xi <= 85) & (zeta <= 65) & (zeta >= 0)
    outside = (xi < 0) | (xi > 100) | (zeta < 0) | (zeta > 80)
    assert np.all(w[inside] == 1.0) and np.all(w[outside] == 0.0)
    assert np.all((w >= 0) & (w <= 1))
    e = 1e-5  # central differences of a cubic: error ~e² × 6/width³ ≪ the gradient's scale 1/width
    band = (xi > 1) & (xi < 99) & (zeta < 79) & (zeta > 1)
    fx = (blend_weight(frame, "north", 15.0, x + e, y)[0] - blend_weight(frame, "north", 15.0, x - e, y)[0]) / (2 * e)
    fy = (blend_weight(frame, "north", 15.0, x, y + e)[0] - blend_weight(frame, "north", 15.0, x, y - e)[0]) / (2 * e)
    np.testing.assert_allclose(wx[band], fx[band], rtol=0, atol=1e-6 / 15.0)
    np.testing.assert_allclose(wy[band], fy[band], rtol=0, atol=1e-6 / 15.0)


def test_depth_taper_saturates_at_the_breaker_index_and_vanishes_on_land():
    """τ H_rms → γ d in shallow water (Thornton & Guza 1983), τ → 1 in deep water, 0 on land."""
    h_rms = 0.8
    d = np.array([-1.0, 0.0, 1e-4, 1e-3, 40.0])
    tau, slope = depth_taper(d, h_rms)
    assert tau[0] == 0.0 and tau[1] == 0.0
    np.testing.assert_allclose(tau[2:4] * h_rms / (BREAKER_INDEX_RMS * d[2:4]), 1.0, rtol=1e-5)  # tanh z = z(1 − z²/3)
    assert tau[4] == pytest.approx(1.0, abs=ROUNDOFF)
    e = 1e-6
    dd = np.array([0.3, 1.0, 2.5])
    numeric = (depth_taper(dd + e, h_rms)[0] - depth_taper(dd - e, h_rms)[0]) / (2 * e)
    np.testing.assert_allclose(depth_taper(dd, h_rms)[1], numeric, rtol=1e-7)


def test_terrain_continues_the_bed_and_deepens_offshore():
    frame = DomainFrame(origin=(0.0, 0.0), rotation=0.0, size=(20.0, 10.0))
    spacing = (1.0, 1.0)
    y = (np.arange(10) + 0.5)[:, None] * np.ones((1, 20))
    bed = 1.0 - 0.1 * y  # rising to the south, 0 at y = 10
    args = (bed, frame, spacing, "north", 0.0, 0.05, 3.0)
    # the cell centres: the bed itself
    xc, yc = (np.arange(20) + 0.5)[None, :] * np.ones((10, 1)), y
    np.testing.assert_allclose(terrain_height(*args, xc, yc), bed, rtol=0, atol=ROUNDOFF)
    # along the coast: the edge profile continues
    np.testing.assert_allclose(terrain_height(*args, np.full(10, -50.0), y[:, 0]), bed[:, 0], rtol=0, atol=ROUNDOFF)
    # offshore: the last row's 0.05 m at the side, falling 0.05 per metre beyond it, down to −3 m
    z = terrain_height(*args, np.full(3, 5.0), np.array([10.0, 20.0, 500.0]))
    np.testing.assert_allclose(z, [0.05, 0.05 - 0.05 * 10.0, -3.0], rtol=0, atol=ROUNDOFF)


def test_the_long_wave_cutoff_keeps_the_solver_near_shallow_water():
    c = scene_from_dict({"name": "e", "coastal": {"offshore_depth": 6.0, "cells": [40, 30],
                                                  "size": [40.0, 30.0]}}).coastal
    k = embedding.long_wave_cutoff(c, 6.0)
    assert k * 6.0 <= embedding.LONG_WAVE_KD * (1 + ROUNDOFF)
    assert 2 * math.pi / k >= embedding.CELLS_PER_WAVELENGTH * 1.0


BAY = {"name": "bay", "ocean": OCEAN, "mesh": {"kind": "radial", "segments": 64},
       "coastal": {"waves": "open sea", "offshore_depth": 8.0, "slope": 0.25, "cells": [40, 30], "size": [80.0, 60.0],
                   "origin": [-40.0, -20.0]}}


@pytest.mark.parametrize("change, key", [
    ({"mesh": {"kind": "patch"}}, "[mesh] kind"),
    ({"ocean": {**OCEAN, "model": "Gerstner"}}, "[ocean] model"),
    ({"ocean": {k: v for k, v in OCEAN.items() if k != "wave_depth"}}, "[ocean] wave_depth"),
    ({"water": {"depth": 20.0}}, "[water] depth"),
    ({"coastal": {**BAY["coastal"], "still_level": 0.5}}, "[coastal] still_level"),
])
def test_bad_open_sea_scenes_are_refused_in_one_line_naming_the_key(change, key):
    with pytest.raises(SceneError) as error:
        scene_from_dict({**BAY, **change}, "bay.toml")
    message = str(error.value)
    assert "\n" not in message and message.startswith("bay.toml: ") and key in message


def test_the_sea_must_share_the_offshore_depth(tmp_path):
    """Checked against the bed when the scene is loaded: the side's mean depth (8 m here) within 5 %."""
    def value(v):
        return repr(v) if not isinstance(v, str) else f'"{v}"'

    sections = {**BAY, "ocean": {**OCEAN, "wave_depth": 7.0}}
    text = 'name = "bay"\n' + "".join(
        f"[{name}]\n" + "".join(f"{k} = {value(v)}\n" for k, v in table.items())
        for name, table in sections.items() if isinstance(table, dict))
    path = tmp_path / "bay.toml"
    path.write_text(text)
    with pytest.raises(SceneError) as error:
        load_scene(path)
    assert "[ocean] wave_depth" in str(error.value) and "8 m" in str(error.value) and "\n" not in str(error.value)


def test_an_open_sea_scene_loads():
    scene = scene_from_dict(BAY)
    assert scene.coastal.waves == "open sea"
