"""Tests for oceanrender.waves.cascades: band partition, variance, sampling, independence of patches."""

from functools import partial

import numpy as np
import pytest

from oceanrender.waves.cascades import (
    PATCH_SIZE_RATIO,
    CascadeOcean,
    annulus_fraction,
    cascade_band_edges,
    cascade_patch_sizes,
    commensurability,
)
from oceanrender.waves.fft_ocean import OceanGrid, time_amplitudes
from oceanrender.waves.wave_spectra import spectrum_Phillips2001
from tests.tolerances import ROUNDOFF

SPECTRUM = partial(spectrum_Phillips2001, wind_speed=8.0, wind_direction=0.3)


def sea(resolution=64, largest=800.0, count=3, **kwargs):
    return CascadeOcean(SPECTRUM, cascade_patch_sizes(largest, count), resolution, seed=2, dtype=np.float64, **kwargs)


def annulus_integral(spectrum, k_min, k_max, samples=2000, angles=90):
    """∫∫_{k_min ≤ |k| < k_max} Ψ dkx dky in polar coordinates: trapezoid in ln k, rectangle rule in θ
    (exact for the cos² spreading with ≥ 3 angles)."""
    log_k = np.linspace(np.log(max(k_min, 1e-4)), np.log(k_max), samples)
    k = np.exp(log_k)[:, None]
    theta = np.linspace(0.0, 2 * np.pi, angles, endpoint=False)
    psi = spectrum(k * np.cos(theta), k * np.sin(theta))
    return np.trapezoid(2 * np.pi * psi.mean(axis=1) * k[:, 0] ** 2, log_k)


def test_patch_sizes_are_incommensurate():
    sizes = np.array(cascade_patch_sizes(1000.0, 5))
    assert sizes[0] == 1000.0
    np.testing.assert_allclose(sizes[:-1] / sizes[1:], PATCH_SIZE_RATIO, rtol=ROUNDOFF)
    # every pair of the 5 patches: no fraction p/q, q ≤ 20, within 0.25/q² of their size ratio
    ratios = [sizes[i] / sizes[j] for i in range(5) for j in range(i + 1, 5)]
    assert commensurability(ratios, 20) > 0.25
    # the golden ratio cubed fails: φ⁶ = 17.94 ≈ 18, φ⁹ = 75.99 ≈ 76
    phi_cubed = 2 + np.sqrt(5)
    assert commensurability([phi_cubed**2], 1) < 0.06 and commensurability([phi_cubed**3], 1) < 0.014
    assert commensurability([2.5], 2) == 0.0
    for bad in [dict(largest=0.0), dict(count=0), dict(ratio=1.0)]:
        with pytest.raises(ValueError):
            cascade_patch_sizes(**(dict(largest=10.0, count=2) | bad))


def test_bands_partition_the_disk():
    ocean = sea()
    edges = ocean.band_edges
    assert edges[0] == 0 and np.all(np.diff(edges) > 0)
    assert edges[-1] == pytest.approx(ocean.grids[-1].nyquist_wavenumber)
    for i, grid in enumerate(ocean.grids):  # every band lies inside its patch's lattice
        assert edges[i + 1] <= grid.nyquist_wavenumber and edges[i + 1] > grid.dk
    # any wavenumber inside the disk belongs to exactly one band, with cell-area weights adding to 1
    rng = np.random.default_rng(1)
    kx, ky = rng.uniform(-edges[-1], edges[-1], (2, 20000))
    inside = np.hypot(kx, ky) < edges[-1]
    hard = sum(annulus_fraction(kx, ky, edges[i], edges[i + 1]) for i in range(len(edges) - 1))
    np.testing.assert_array_equal(hard, inside)  # sums of 0/1 indicators: exact
    soft = sum(annulus_fraction(kx, ky, edges[i], edges[i + 1], cell=0.01) for i in range(len(edges) - 1))
    np.testing.assert_allclose(soft[np.hypot(kx, ky) < edges[-1] - 0.01], 1.0, rtol=0, atol=ROUNDOFF)  # scale 1
    # a patch carries no variance outside its band
    for i, ocean_i in enumerate(ocean.cascades):
        k = ocean_i.grid.k
        outside = (k < edges[i] - ocean_i.grid.dk) | (k >= edges[i + 1] + ocean_i.grid.dk)
        assert np.all(ocean_i.spectrum_values[outside] == 0) and np.all(ocean_i.h0[outside] == 0)
    with pytest.raises(ValueError, match="empty band"):
        cascade_band_edges([OceanGrid(8, 100.0), OceanGrid(8, 1.0)])
    with pytest.raises(ValueError):
        cascade_band_edges([OceanGrid(64, 10.0), OceanGrid(64, 100.0)])


@pytest.mark.parametrize("resolution, largest", [(128, 800.0), (256, 2000.0)])
def test_total_variance_is_the_spectrum_integral_over_the_union_of_bands(resolution, largest):
    ocean = sea(resolution, largest)
    expected = annulus_integral(SPECTRUM, 0.0, ocean.band_edges[-1])
    # lattice sums with area-weighted edge cells: second-order midpoint-rule error, ≲ 0.5 % here
    assert ocean.elevation_variance == pytest.approx(expected, rel=0.01)
    for i, cascade in enumerate(ocean.cascades):  # each band too (bands crowd at their inner edge: 2.5 %)
        band = annulus_integral(SPECTRUM, ocean.band_edges[i], ocean.band_edges[i + 1])
        assert cascade.elevation_variance == pytest.approx(band, rel=0.025)


def test_parseval_of_the_sum():
    ocean = sea(64, 600.0)
    t = 7.0
    frame = ocean.frame(t)
    realised, interpolated = [], []
    for cascade, fields in zip(ocean.cascades, frame.fields):
        power = np.abs(time_amplitudes(cascade.h0, cascade.omega, t)) ** 2
        # each patch on its own grid: Parseval, exactly
        assert np.var(fields.height) == pytest.approx(np.sum(power), rel=ROUNDOFF)
        realised.append(np.sum(power))
        # between nodes, bilinear interpolation passes a mode with power gain
        # ∫₀¹ |1 − f + f e^{iθ}|² df = (2 + cos θ)/3 per axis, θ = k Δx
        h = cascade.grid.spacing
        gain = (2 + np.cos(cascade.grid.kx * h)) * (2 + np.cos(cascade.grid.ky * h)) / 9
        interpolated.append(np.sum(power * gain))
    # the sum at random points: incommensurate patches decorrelate over a large area, so the
    # variances of the (interpolated) patches add
    rng = np.random.default_rng(3)
    x, y = rng.uniform(-20 * ocean.patch_sizes[0], 20 * ocean.patch_sizes[0], (2, 400_000))
    total = frame.sample(x, y).height
    assert np.var(total) == pytest.approx(sum(interpolated), rel=0.02)
    assert sum(interpolated) < 0.97 * sum(realised)  # the interpolation loss is resolved by the check
    # and the summed sample is the sum of single-patch samples
    parts = sum(frame.sample(x[:1000], y[:1000], cascades=[i]).height for i in range(3))
    np.testing.assert_allclose(parts, total[:1000], rtol=0, atol=ROUNDOFF * np.abs(total).max())


def test_sampling_at_a_patch_nodes_reproduces_its_fields():
    ocean = sea(32, 400.0, choppiness=1.1)
    frame = ocean.frame(3.0)
    for i, grid in enumerate(ocean.grids):
        own = frame.fields[i]
        for shift in (0.0, 3.0):  # periodicity: the nodes of the neighbouring tiles too
            sample = frame.sample(grid.x + shift * grid.patch_size, grid.y - shift * grid.patch_size, cascades=[i])
            for name in ("height", "displacement_x", "displacement_y", "slope_x", "slope_y", "jacobian", "normals",
                         "jacobian_xx", "jacobian_yy", "jacobian_xy"):
                np.testing.assert_allclose(getattr(sample, name), getattr(own, name), rtol=0,
                                           atol=ROUNDOFF * np.abs(getattr(own, name)).max(), err_msg=f"{i} {name}")
    # between nodes the interpolation is bilinear: a node's neighbours bound the value on the segment
    grid = ocean.grids[0]
    half = frame.sample(grid.x[0, :-1] + grid.spacing / 2, grid.y[0, :-1], cascades=[0]).height
    heights = frame.fields[0].height
    # heights cross zero: compared relative to the field's scale, not elementwise
    np.testing.assert_allclose(half, (heights[0, :-1] + heights[0, 1:]) / 2, rtol=0,
                               atol=ROUNDOFF * np.abs(heights).max())


def test_summed_surface_is_consistent():
    ocean = sea(64, 500.0, choppiness=1.0)
    x, y = np.meshgrid(np.linspace(-300, 300, 40), np.linspace(-250, 350, 30))
    sample = ocean.fields_at(x, y, 2.0)
    assert sample.height.shape == x.shape and sample.normals.shape == (*x.shape, 3)
    np.testing.assert_allclose(np.linalg.norm(sample.normals, axis=-1), 1.0, rtol=0, atol=ROUNDOFF)  # scale 1
    # J is a difference of products of scale 1 (it may come near 0): absolute, on that scale
    np.testing.assert_allclose(sample.jacobian, sample.jacobian_xx * sample.jacobian_yy - sample.jacobian_xy**2,
                               rtol=0, atol=ROUNDOFF * np.abs(sample.jacobian_xx * sample.jacobian_yy).max())
    assert np.all(np.sign(sample.normals[..., 2]) == np.sign(sample.jacobian))
    assert ocean.significant_wave_height == pytest.approx(4 * np.sqrt(ocean.elevation_variance))


def test_changing_the_finest_resolution_leaves_the_coarse_patches_unchanged():
    a, b = sea((64, 64, 64)), sea((64, 64, 128))
    # exact: the coarse patches are the same computation on the same inputs (grids, bands, seed)
    assert a.band_edges[:-1] == b.band_edges[:-1]
    for i in (0, 1):
        np.testing.assert_array_equal(a.cascades[i].fields(5.0).height, b.cascades[i].fields(5.0).height)
    # the finest patch keeps its long waves too (seed-stable noise: each mode's amplitude is the same
    # computation from (seed, cascade, mode) on both grids, so bit for bit), the finer grid only adds modes
    ha, hb = a.cascades[2].h0, b.cascades[2].h0
    rows_a, rows_b = np.abs(a.grids[2].indices) < 32, np.abs(b.grids[2].indices) < 32
    inner = np.hypot(*np.meshgrid(a.grids[2].kx[0, rows_a], a.grids[2].kx[0, rows_a])) < a.band_edges[-1] * 0.9
    np.testing.assert_array_equal(ha[np.ix_(rows_a, rows_a)][inner], hb[np.ix_(rows_b, rows_b)][inner])


def test_loop_period_and_validation():
    T = 30.0
    ocean = sea(32, 300.0, loop_period=T)
    x, y = np.array([1.0, 123.4, -999.0]), np.array([0.0, 55.5, 10.0])
    a, b = ocean.fields_at(x, y, 4.2), ocean.fields_at(x, y, 4.2 + T)
    np.testing.assert_allclose(b.height, a.height, rtol=0, atol=ROUNDOFF * np.abs(a.height).max())
    with pytest.raises(ValueError):
        CascadeOcean(SPECTRUM, (100.0, 20.0), (64, 64, 64))
    with pytest.raises(ValueError):
        CascadeOcean(SPECTRUM, (100.0, 20.0), 64, band_edges=(0.0, 1.0))
    with pytest.raises(ValueError):
        CascadeOcean(SPECTRUM, (), 64)
