"""Tests for oceanrender.waves.fractal: fBm statistics, periodicity, the fit, the blend."""

import numpy as np
import pytest

from oceanrender.waves import fractal
from oceanrender.waves.fft_ocean import FFTOcean, OceanGrid
from oceanrender.waves.fractal import (
    FBMParameters,
    blend_fractal,
    estimate_fbm_parameters,
    fractal_detail,
    structure_function,
    upsample_periodic,
)
from tests.tolerances import ROUNDOFF


def mean_structure_function(order, spacing, hurst, sigma, seeds):
    """Direction-averaged S at lags 1, 2, … M/8 cells, averaged over several realisations."""
    lags = 2 ** np.arange(order - 2)
    curves = [structure_function(fractal_detail(1 << order, spacing, hurst, sigma, seed), spacing, lags)
              for seed in seeds]
    return curves[0][0], np.mean([values for _, values in curves], axis=0)


@pytest.mark.parametrize("hurst", [0.3, 0.7])
def test_expected_structure_function_is_the_requested_power_law(hurst):
    # the recursion is linear: its expected S is Σ_l v_l B_l exactly, with no sampling noise
    order = 7
    m = 1 << order
    expected = np.tensordot(fractal._displacement_variances(order, hurst), fractal._structure_basis(order), 1)
    lags = np.arange(1, m // 8 + 1)
    axis = (expected[0, lags] + expected[lags, 0]) / 2 / lags ** (2 * hurst)
    diagonal = (expected[lags, lags] + expected[-lags, lags]) / 2 / (np.sqrt(2) * lags) ** (2 * hurst)
    tolerance = {0.3: 1e-3, 0.7: 1e-2}[hurst]  # calibration residuals 3e-4 and 5e-3
    assert np.abs(axis - 1).max() < tolerance and np.abs(diagonal - 1).max() < tolerance


@pytest.mark.parametrize("hurst", [0.3, 0.7])
def test_fit_recovers_the_generating_parameters(hurst):
    spacing, sigma = 0.2, 0.05  # lags 0.2–6.4 m: r₀ = 1 m inside the fitted range
    distances, values = mean_structure_function(8, spacing, hurst, sigma, range(16))
    slope, intercept = np.polyfit(np.log(distances), np.log(values), 1)
    # 12 batches of 16 seeds measured: std of H 0.008 (H = 0.3) and 0.017 (0.7), of σ 0.6 % and
    # 2.8 %; the bounds are ≥ 3.5 std. Saupe's uncalibrated rule misses σ by ~30 % at H = 0.7.
    assert slope / 2 == pytest.approx(hurst, abs=0.06)
    assert np.exp(intercept / 2) == pytest.approx(sigma, rel=0.10)
    # single realisations, through the public estimator
    estimates = np.array([estimate_fbm_parameters(fractal_detail(256, spacing, hurst, sigma, seed), spacing)
                          for seed in range(16)])
    assert np.mean(estimates[:, 0]) == pytest.approx(hurst, abs=0.06)
    assert np.median(estimates[:, 1]) == pytest.approx(sigma, rel=0.15)


def test_detail_is_periodic():
    # the seam (last column → first) must look like any other neighbour pair; a surface built on
    # a non-periodic grid would have S(M h) ≈ 64 S(h) across it (H = 0.5, M = 64)
    seam, inside = [], []
    for seed in range(32):
        z = fractal_detail(64, 0.1, 0.5, 0.02, seed)
        seam += [np.mean((z[:, 0] - z[:, -1]) ** 2), np.mean((z[0] - z[-1]) ** 2)]
        inside += [np.mean(np.diff(z, axis=1) ** 2), np.mean(np.diff(z, axis=0) ** 2)]
    assert np.mean(seam) / np.mean(inside) == pytest.approx(1.0, abs=0.2)


def test_seeded_reproducibility():
    first = fractal_detail(32, 0.05, 0.6, 0.01, seed=9)
    scale = np.abs(first).max()
    # the same computation on the same inputs: bit for bit
    np.testing.assert_array_equal(fractal_detail(32, 0.05, 0.6, 0.01, seed=9), first)
    assert np.abs(fractal_detail(32, 0.05, 0.6, 0.01, seed=10) - first).max() > 0.1 * scale
    assert first.shape == (32, 32) and abs(first.mean()) < ROUNDOFF * scale
    np.testing.assert_array_equal(fractal_detail((32, 32), 0.05, 0.6, 0.0, seed=9), 0.0)  # σ = 0: zeros
    # σ and h only scale: S ∝ σ² h^{2H} at a fixed lag in cells (the field crosses zero and has its mean
    # removed: compared relative to its scale)
    scaled = first * 3 * 4**0.6
    np.testing.assert_allclose(fractal_detail(32, 0.2, 0.6, 0.03, seed=9), scaled, rtol=0,
                               atol=ROUNDOFF * np.abs(scaled).max())


def test_estimator_on_a_plane_and_its_scaling(rng):
    # a plane of slope s: direction-averaged S = s² r²/2 exactly, so H = 1 and σ = s/√2 at r₀ = 1 m
    x, _ = np.meshgrid(np.arange(64) * 0.5, np.arange(64) * 0.5)
    plane = estimate_fbm_parameters(0.3 * x, 0.5, periodic=False)
    assert plane.hurst == pytest.approx(1.0, rel=ROUNDOFF)
    assert plane.sigma == pytest.approx(0.3 / np.sqrt(2), rel=ROUNDOFF)
    assert isinstance(plane, FBMParameters)
    # heights × c → σ × c; spacing × 2 → σ × 2^{−H} (S(r) = σ² (r/2)^{2H}); H unchanged
    field = rng.standard_normal((64, 64)).cumsum(axis=0).cumsum(axis=1)
    base = estimate_fbm_parameters(field, 0.1, periodic=False)
    scaled = estimate_fbm_parameters(5 * field, 0.2, periodic=False)
    assert scaled.hurst == pytest.approx(base.hurst, rel=ROUNDOFF)
    assert scaled.sigma == pytest.approx(5 * base.sigma * 2 ** -base.hurst, rel=ROUNDOFF)


def test_blend():
    base = FFTOcean(OceanGrid(64, 20.0), 4.0, 0.5, seed=2, small_wave_length=0.05).fields(1.0).height
    grid_spacing = 20.0 / 64
    hurst, sigma = estimate_fbm_parameters(base, grid_spacing)
    assert 0 < hurst < 1 and sigma > 0  # the FFT sea has an fBm range the detail can continue
    detail = fractal_detail(64, grid_spacing, hurst, sigma, seed=4)
    unchanged = blend_fractal(base, detail, 0.0)
    np.testing.assert_array_equal(unchanged, base)  # γ = 0: a copy of base
    assert unchanged is not base
    # the difference cancels base: its round-off is relative to base's scale
    np.testing.assert_allclose(blend_fractal(base, detail, 0.4) - base, 0.4 * detail, rtol=0,
                               atol=ROUNDOFF * np.abs(base).max())
    with pytest.raises(ValueError):
        blend_fractal(base, detail[:32, :32], 0.5)
    with pytest.raises(ValueError):
        blend_fractal(base, detail, -0.1)


def test_upsampling_is_exact_for_band_limited_fields():
    n, L, factor = 32, 10.0, 4
    coordinates = -L / 2 + L / n * np.arange(n)
    fine_coordinates = -L / 2 + L / (n * factor) * np.arange(n * factor)

    def wave(c):
        x, y = np.meshgrid(c, c)
        return 0.3 * np.cos(2 * np.pi * (3 * x - 5 * y) / L + 0.4) + 0.1 * np.sin(2 * np.pi * 7 * y / L)

    fine = upsample_periodic(wave(coordinates), factor)
    scale = 0.4  # the amplitudes' sum [m]
    np.testing.assert_allclose(fine, wave(fine_coordinates), rtol=0, atol=ROUNDOFF * scale)
    np.testing.assert_allclose(fine[::factor, ::factor], wave(coordinates), rtol=0, atol=ROUNDOFF * scale)


def test_validation():
    for shape in (48, 8, (32, 64), (32, 32, 32)):
        with pytest.raises(ValueError, match="2ⁿ"):
            fractal_detail(shape, 0.1, 0.5, 0.01, 0)
    for hurst in (0.0, 1.0, -0.2):
        with pytest.raises(ValueError, match="hurst"):
            fractal_detail(32, 0.1, hurst, 0.01, 0)
    for kwargs in (dict(sigma=-1.0), dict(spacing=0.0)):
        with pytest.raises(ValueError):
            fractal_detail(**(dict(shape=32, spacing=0.1, hurst=0.5, sigma=0.01, seed=0) | kwargs))
    with pytest.raises(ValueError, match="flat"):
        estimate_fbm_parameters(np.ones((32, 32)), 0.1)
    with pytest.raises(ValueError):
        estimate_fbm_parameters(np.zeros((8, 8)) + np.arange(8), 0.1)  # too small for lags 1 … N/8
    with pytest.raises(ValueError):
        upsample_periodic(np.zeros((4, 4)), 0)
