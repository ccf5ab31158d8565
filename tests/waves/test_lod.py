"""Tests for oceanrender.waves.lod and the sea's slope budget (oceanrender.waves.sea):
filter by wavenumber, conserve slope variance, resolve the peak, keep the seed."""

from functools import lru_cache
from pathlib import Path

import numpy as np
import pytest

from oceanrender.scene import load_scene, with_overrides
from oceanrender.surface.radial_mesh import RadialGrid
from oceanrender.waves.lod import (
    bilinear_power_gain,
    fade_wavenumber,
    level_cutoffs,
    level_resolution,
    level_weights,
)
from oceanrender.waves.sea import SeaSurface
from tests.tolerances import ROUNDOFF

ROOT = Path(__file__).resolve().parents[2]

#: Slope-budget tolerance (the issue's 5 %): the budget itself is exact in expectation;
#: the estimate from 40 000 points at 3 times has a sampling error of ~1–2 % of the total.
BUDGET = 0.05


@lru_cache(maxsize=None)
def default_sea() -> SeaSurface:
    return SeaSurface(load_scene(ROOT / "scenes" / "open_ocean.toml").ocean)


def test_level_weights_add_to_one_and_move_continuously():
    spacing = np.geomspace(1e-3, 1e4, 4001)
    w = level_weights(spacing, top=2.0, levels=6)
    np.testing.assert_allclose(w.sum(axis=0), 1.0, rtol=ROUNDOFF)
    assert np.all(w >= 0)
    # continuous in Δ: neighbouring spacings (0.2 % apart) change a weight by < 1 %
    assert np.max(np.abs(np.diff(w, axis=1))) < 0.01


def mode_weight(k, spacing, top=1.0, levels=12):
    """Effective amplitude weight of a mode of wavenumber k [rad/m] at vertex spacing Δ: Σ_j w_j 1[k < K_j]."""
    cutoffs = top / 2.0 ** np.arange(levels)
    w = level_weights(np.asarray(spacing, float), top, levels)
    return np.tensordot((k < cutoffs).astype(float), w, axes=1)


def test_resolution_rule_whole_at_8_vertices_gone_at_nyquist():
    spacing = np.geomspace(0.05, 50.0, 400)
    for k in (0.013, 0.1, 0.37, 0.99):
        weight = mode_weight(k, spacing)
        wavelength_in_vertices = 2 * np.pi / k / spacing
        assert np.all(weight[wavelength_in_vertices >= 8.0] == 1.0)
        assert np.all(weight[wavelength_in_vertices <= 2.0] == 0.0)
        assert np.all(np.diff(weight) <= 1e-12)  # never comes back as the spacing grows


def test_fade_wavenumber_is_a_quarter_of_the_vertex_frequency():
    np.testing.assert_allclose(fade_wavenumber(np.array([0.5, 2.0])), 2 * np.pi / (4 * np.array([0.5, 2.0])),
                               rtol=ROUNDOFF)


def test_bilinear_power_gain_against_direct_interpolation():
    """Interpolate a plane wave bilinearly from a grid at random points: its mean square over the wave's
    (1/2) is the gain (an independent Monte Carlo check of the closed form)."""
    rng = np.random.default_rng(5)
    cell = 0.7
    for kx, ky in ((0.5, 0.0), (1.2, 0.9), (np.pi / cell, 0.0), (2.0, -3.0)):
        x, y = rng.uniform(0, 500, 200_000), rng.uniform(0, 500, 200_000)
        phase = rng.uniform(0, 2 * np.pi, x.size)  # the gain is a mean over phases too
        i, j = np.floor(x / cell), np.floor(y / cell)
        fx, fy = x / cell - i, y / cell - j

        def wave(a, b):
            return np.cos(kx * a * cell + ky * b * cell + phase)

        value = ((1 - fx) * (1 - fy) * wave(i, j) + fx * (1 - fy) * wave(i + 1, j)
                 + (1 - fx) * fy * wave(i, j + 1) + fx * fy * wave(i + 1, j + 1))
        # Monte Carlo: 2e5 samples of a bounded variable, standard error < 0.3 % of the mean square
        np.testing.assert_allclose(np.mean(value**2) / 0.5, bilinear_power_gain(kx, ky, cell), rtol=0.01)


def test_level_cutoffs_and_grids():
    cutoffs = level_cutoffs(0.0, 0.45, 2 * np.pi / 2400)
    assert cutoffs[0] == 0.45 and cutoffs[-1] <= np.pi / 2400 < cutoffs[-2]
    np.testing.assert_allclose(np.array(cutoffs[:-1]) / np.array(cutoffs[1:]), 2.0, rtol=ROUNDOFF)
    # a level's grid has ≥ 6 points per wavelength of its cutoff, never more than the cascade's own
    for cutoff in cutoffs[1:-1]:
        n = level_resolution(cutoff, 2400.0, 1024)
        assert n <= 1024 and (n == 1024 or n * 2 * np.pi / (cutoff * 2400.0) >= 6.0)


def test_long_waves_reach_far_rings():
    """The issue's flat sea beyond 245 m (the old rule dropped the largest cascade there): with the filter
    the waves go on wherever the spacing resolves them; on the default mesh the ring at 400 m (6.5 m
    spacing) still carries a tenth of the sea's height variance, and the rendered ring shows it."""
    sea = default_sea()
    grid = RadialGrid.square_cells((0.0, 0.0), 0.5, 8000.0, 384)
    ring = int(np.searchsorted(grid.radii, 400.0))
    points = grid.points[1 + ring * 384: 1 + (ring + 1) * 384]
    spacing = grid.spacing[1 + ring * 384: 1 + (ring + 1) * 384]
    height = sea.sample(points[:, 0], points[:, 1], 0.0, spacing).displacement[:, 2]
    expected, _ = sea.resolved_variance(spacing[:1])
    assert expected[0] > 0.1 * sea.spectrum.elevation_variance()
    assert height.std() > 0.3 * np.sqrt(expected[0])  # and there is one (a 384-point ring of a random sea)


@pytest.mark.parametrize("distance", [0.5, 3.0, 20.0, 100.0, 400.0, 1500.0, 8000.0])
def test_slope_variance_is_conserved_along_a_ray(distance):
    """Along a ray from the camera to the horizon: the slopes the vertices carry (measured at 40 000
    random points with the spacing of the default mesh at that distance) plus the roughness the body
    gives them add up to the spectrum's total slope variance (independent quadrature of k² Ψ) within 5 %."""
    sea = default_sea()
    spacing = float(distance * 2 * np.pi / 384)  # square cells: Δ = r Δθ
    rng = np.random.default_rng(int(distance * 10))
    measured = []
    for t in (0.0, 3.7, 11.1):
        x, y = rng.uniform(-1200, 1200, (2, 40_000))
        s = sea.sample(x, y, t, np.full(x.shape, spacing))
        slope = -s.normals[:, :2] / s.normals[:, 2:]
        measured.append(np.mean(np.sum(slope**2, axis=1)))
    unresolved = float(sea.unresolved_slope_variance(np.array([spacing]))[0])
    total = sea.total_slope_variance
    assert abs(np.mean(measured) + unresolved - total) < BUDGET * total


def test_height_variance_where_the_mesh_resolves_the_peak():
    """Where waves down to a quarter of the peak wavelength are whole (8 Δ ≤ λp/4: r ≤ 60 m on the
    default mesh), the vertices carry the spectrum's height variance m0 (its own quadrature) within 5 %."""
    sea = default_sea()
    peak = 2 * np.pi * sea.spectrum.g / sea.spectrum.peak_frequency**2
    m0 = sea.spectrum.elevation_variance()
    rng = np.random.default_rng(3)
    for spacing in (0.01, peak / 32):
        x, y = rng.uniform(-1200, 1200, (2, 60_000))
        measured = np.mean([np.var(sea.sample(x, y, t, np.full(x.shape, spacing)).displacement[:, 2])
                            for t in (0.0, 5.0)])
        predicted, _ = sea.resolved_variance(np.array([spacing]))
        # 60 000 points over 2.4 km hold ~5000 peak wavelengths²: ~2 % sampling error of the realisation
        assert abs(measured - m0) < BUDGET * m0
        assert abs(predicted[0] - m0) < BUDGET * m0


def test_refined_grid_keeps_the_long_waves():
    """Seed-stable across grid refinement: doubling the cascades' points keeps the modes of the largest
    cascade (hashed noise), so the sea's long waves are the same (correlation > 0.99)."""
    scene = load_scene(ROOT / "scenes" / "open_ocean.toml")
    coarse = SeaSurface(with_overrides(scene, ocean={"resolution": 512}).ocean)
    fine = SeaSurface(with_overrides(scene, ocean={"resolution": 1024}).ocean)
    x, y = np.meshgrid(np.linspace(-1000, 1000, 200), np.linspace(-1000, 1000, 200))
    spacing = np.full(x.shape, 16.0)  # keeps waves > 32 m only: inside the coarse grid's first band (> 28 m)
    a = coarse.sample(x, y, 2.0, spacing).displacement[..., 2]
    b = fine.sample(x, y, 2.0, spacing).displacement[..., 2]
    assert np.corrcoef(a.ravel(), b.ravel())[0, 1] > 0.99
