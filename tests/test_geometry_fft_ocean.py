"""Tests for oceanrender.geometry.fft_ocean: normalisation, reality, derivatives, motion."""

import numpy as np
import pytest
import scipy.fft

from oceanrender.geometry.fft_ocean import (
    FFTOcean,
    OceanGrid,
    elevation_variance,
    initial_amplitudes,
    negate_wavenumber,
    ocean_fields,
    time_amplitudes,
)
from oceanrender.geometry.spectra import (
    dispersion_relation,
    elevation_variance_Phillips2001,
    significant_wave_height_Phillips2001,
    spectrum_Phillips2001,
)

#: Tolerance of identities that hold exactly up to float64 round-off.
EXACT_RTOL = 1e-10


def smooth_ocean(resolution=64, choppiness=0.0, seed=1, t=1.7):
    """A well-resolved sea: ℓ = 3 m suppresses waves shorter than the grid resolves."""
    return FFTOcean(
        OceanGrid(resolution, 100.0), 5.0, 0.3, seed=seed, choppiness=choppiness, small_wave_length=3.0
    ), t


def direct_sum(grid, coefficients, points_x, points_y):
    """Σ_k c(k) exp(i k·x) evaluated by brute force at the given points."""
    phase = np.exp(1j * (np.multiply.outer(points_x, grid.kx) + np.multiply.outer(points_y, grid.ky)))
    return np.einsum("...ij,ij->...", phase, coefficients)


def test_grid_layout():
    grid = OceanGrid(8, 40.0)
    assert grid.dk == pytest.approx(2 * np.pi / 40)
    np.testing.assert_allclose(grid.kx[0], grid.dk * np.array([0, 1, 2, 3, -4, -3, -2, -1]))
    np.testing.assert_array_equal(grid.ky, grid.kx.T)
    np.testing.assert_allclose(grid.x[0], -20 + 5 * np.arange(8))
    np.testing.assert_array_equal(grid.y[:, 0], grid.x[0])
    mask = grid.mode_mask
    assert not mask[0, 0] and not mask[4].any() and not mask[:, 4].any()
    assert mask.sum() == 7 * 7 - 1
    with pytest.raises(ValueError):
        grid.kx[0, 0] = 1.0  # cached arrays are read-only
    for bad in [(1, 10.0), (8, 0.0), (8, np.nan)]:
        with pytest.raises(ValueError):
            OceanGrid(*bad)


def test_amplitudes_are_hermitian_and_the_surface_real():
    ocean, t = smooth_ocean(choppiness=1.0)
    h = time_amplitudes(ocean.h0, ocean.omega, t)
    np.testing.assert_array_equal(negate_wavenumber(h), np.conj(h))
    surface = scipy.fft.ifft2(h, norm="forward")
    assert np.abs(surface.imag).max() / np.abs(surface.real).max() < EXACT_RTOL
    # every derived field is real too: the packed pairs must not leak into each other
    packed = scipy.fft.ifft2(ocean.grid.spectral_operators * h, norm="forward")
    fields = ocean.fields(t)
    np.testing.assert_allclose(packed[1].real, fields.slope_x, rtol=0, atol=1e-14)
    np.testing.assert_allclose(packed[1].imag, fields.slope_y, rtol=0, atol=1e-14)


def test_seed_reproducibility():
    grid = OceanGrid(32, 50.0)
    psi = spectrum_Phillips2001(grid.kx, grid.ky, 7.0, 1.0)
    first = initial_amplitudes(grid, psi, seed=11)
    np.testing.assert_array_equal(initial_amplitudes(grid, psi, seed=11), first)
    assert not np.allclose(initial_amplitudes(grid, psi, seed=12), first)
    np.testing.assert_array_equal(FFTOcean(grid, 7.0, 1.0, seed=11).fields(3.0).height,
                                  FFTOcean(grid, 7.0, 1.0, seed=11).fields(3.0).height)
    assert np.all(first[~grid.mode_mask] == 0)


def test_parseval_exact():
    ocean, t = smooth_ocean()
    h = time_amplitudes(ocean.h0, ocean.omega, t)
    eta = ocean.fields(t).height
    assert eta.mean() == pytest.approx(0.0, abs=1e-15)
    assert np.var(eta) == pytest.approx(np.sum(np.abs(h) ** 2), rel=EXACT_RTOL)


def test_parseval_expectation():
    grid = OceanGrid(128, 300.0)
    psi = spectrum_Phillips2001(grid.kx, grid.ky, 6.0, 0.4)
    expected = elevation_variance(grid, psi)
    omega = dispersion_relation(grid.k)
    variances = [np.var(ocean_fields(grid, initial_amplitudes(grid, psi, seed), omega, 4.2, 0.0).height)
                 for seed in range(20)]
    # Per pair {k, −k}: 2|h̃(k)|² with |h̃(k)|² ~ s_k Exp(1), s_k = Ψ(k) Δk², so one
    # variance has mean Σ s_k and standard deviation √(2 Σ s_k²); the mean of 20
    # seeds is within 5 of those standard deviations / √20 with probability 1 − 6e-7.
    s = psi * grid.mode_mask * grid.dk**2
    sigma = np.sqrt(2 * np.sum(s**2) / len(variances))
    assert abs(np.mean(variances) - expected) < 5 * sigma
    assert 5 * sigma < 0.05 * expected  # the check has teeth (4.3 % here)


def test_significant_wave_height_of_a_large_patch():
    ocean = FFTOcean(OceanGrid(512, 1000.0), 10.0, 0.0, seed=3)
    closed = significant_wave_height_Phillips2001(10.0)
    # band limit: the grid drops k > π N / L = 1.6 rad/m (tail ≈ 1/(k_max L_w)² ≈ 0.4 % of m0)
    assert ocean.elevation_variance == pytest.approx(elevation_variance_Phillips2001(10.0), rel=0.01)
    # one realisation: relative std of Hs ≈ 1.6 % here (see test_parseval_expectation)
    assert 4 * np.std(ocean.fields(0.0).height) == pytest.approx(closed, rel=0.10)


def test_zero_choppiness():
    ocean, t = smooth_ocean(choppiness=0.0)
    fields = ocean.fields(t)
    assert np.all(fields.displacement_x == 0) and np.all(fields.displacement_y == 0)
    np.testing.assert_array_equal(fields.jacobian, 1.0)
    expected = np.stack([-fields.slope_x, -fields.slope_y, np.ones_like(fields.slope_x)], axis=-1)
    expected /= np.linalg.norm(expected, axis=-1, keepdims=True)
    np.testing.assert_allclose(fields.normals, expected, rtol=0, atol=1e-14)


def fourth_order_gradient(field, spacing):
    """Periodic fourth-order central differences (∂/∂x, ∂/∂y) on [iy, ix] arrays."""
    def d(axis):
        r = lambda s: np.roll(field, -s, axis=axis)  # noqa: E731
        return (-r(2) + 8 * r(1) - 8 * r(-1) + r(-2)) / (12 * spacing)
    return d(1), d(0)


def test_slopes_match_finite_differences():
    ocean, t = smooth_ocean(resolution=256)
    fields = ocean.fields(t)
    gx, gy = fourth_order_gradient(fields.height, ocean.grid.spacing)
    # truncation error (k h)⁴/30 with the spectrum cut at k ≈ 1/ℓ: ~1e-5 of the slopes
    scale = np.abs(fields.slope_x).max()
    assert np.abs(gx - fields.slope_x).max() < 1e-3 * scale
    assert np.abs(gy - fields.slope_y).max() < 1e-3 * scale


@pytest.mark.parametrize("choppiness", [0.0, 1.3])
def test_fields_match_direct_fourier_sums(choppiness):
    grid = OceanGrid(16, 30.0)  # Nyquist-free check of packing, origin shift and signs
    ocean = FFTOcean(grid, 6.0, -2.0, seed=5, choppiness=choppiness)
    t = 2.3
    fields = ocean.fields(t)
    h = time_amplitudes(ocean.h0, ocean.omega, t)
    k = np.where(grid.k == 0, 1.0, grid.k)

    def direct(multiplier):
        values = direct_sum(grid, multiplier * h, grid.x, grid.y)
        assert np.abs(values.imag).max() < 1e-12
        return values.real

    lam = choppiness
    np.testing.assert_allclose(fields.height, direct(1.0), atol=1e-12)
    np.testing.assert_allclose(fields.slope_x, direct(1j * grid.kx), atol=1e-12)
    np.testing.assert_allclose(fields.slope_y, direct(1j * grid.ky), atol=1e-12)
    np.testing.assert_allclose(fields.displacement_x, lam * direct(-1j * grid.kx / k), atol=1e-12)
    np.testing.assert_allclose(fields.displacement_y, lam * direct(-1j * grid.ky / k), atol=1e-12)
    dxx, dyy, dxy = (lam * direct(m) for m in (grid.kx**2 / k, grid.ky**2 / k, grid.kx * grid.ky / k))
    np.testing.assert_allclose(fields.jacobian, (1 + dxx) * (1 + dyy) - dxy**2, atol=1e-12)


def test_choppy_normals_are_unit_up_and_orthogonal_to_the_displaced_surface():
    # steeper than smooth_ocean (slopes ~0.04 rms) yet resolved: ℓ = 0.3 m on a 0.08 m grid
    grid, t = OceanGrid(256, 20.0), 1.0
    ocean = FFTOcean(grid, 3.0, 0.3, seed=1, choppiness=1.0, small_wave_length=0.3)
    fields = ocean.fields(t)
    n = fields.normals
    np.testing.assert_allclose(np.linalg.norm(n, axis=-1), 1.0, rtol=1e-14)
    assert fields.jacobian.min() > 0  # not folded, so every normal points up
    assert np.all(n[..., 2] > 0)
    # tangents ∂P/∂x, ∂P/∂y of P = (x + λDx, y + λDy, η) by finite differences
    h = grid.spacing
    px, py = fourth_order_gradient(fields.displacement_x, h)
    qx, qy = fourth_order_gradient(fields.displacement_y, h)
    ex, ey = fourth_order_gradient(fields.height, h)
    tangents = (np.stack([1 + px, qx, ex], axis=-1), np.stack([py, 1 + qy, ey], axis=-1))

    def worst_cosine(normals):
        return max(np.abs(np.sum(normals * tangent, axis=-1) / np.linalg.norm(tangent, axis=-1)).max()
                   for tangent in tangents)

    assert worst_cosine(n) < 1e-4
    # the normal of the undisplaced height field fails the same check: the test has teeth
    flat = np.stack([-fields.slope_x, -fields.slope_y, np.ones_like(fields.slope_x)], axis=-1)
    assert worst_cosine(flat / np.linalg.norm(flat, axis=-1, keepdims=True)) > 1e-3


def test_mean_jacobian_is_one():
    # mean(J) = 1 + λ² Σ (kx² ky² − (kx ky)²)/k² |h̃|² = 1 exactly: the periodic
    # displacement neither gains nor loses horizontal area
    ocean, t = smooth_ocean(choppiness=2.0)
    jacobian = ocean.fields(t).jacobian
    assert jacobian.mean() == pytest.approx(1.0, rel=EXACT_RTOL)
    assert jacobian.std() > 1e-3


def test_single_mode_travels_at_the_phase_speed():
    grid = OceanGrid(32, 64.0)
    h0 = np.zeros((32, 32), complex)
    h0[0, 4] = 0.5 + 0.2j  # k = (4 Δk, 0): wavelength 16 m
    omega = dispersion_relation(grid.k)
    speed = omega[0, 4] / grid.k[0, 4]
    t = 3 * grid.spacing / speed  # three cells
    eta0 = ocean_fields(grid, h0, omega, 0.0, 0.0).height
    eta = ocean_fields(grid, h0, omega, t, 0.0).height
    # Tessendorf's e^{+iωt}: the h̃₀(k) wave runs along −k, here towards −x
    np.testing.assert_allclose(eta, np.roll(eta0, -3, axis=1), atol=1e-12)
    assert np.abs(eta - eta0).max() > 0.1


def test_ocean_validates_parameters():
    grid = OceanGrid(8, 10.0)
    with pytest.raises(ValueError, match="Phillips 2001"):
        FFTOcean(grid, 5.0, 0.0, spectrum="nope")
    for bad in [dict(wind_speed=-1.0), dict(depth=0.0), dict(choppiness=-0.5)]:
        with pytest.raises(ValueError):
            FFTOcean(grid, **({"wind_speed": 5.0, "wind_direction": 0.0} | bad))
    with pytest.raises(ValueError):
        initial_amplitudes(grid, np.ones((4, 4)), seed=0)


def test_single_precision_agrees_with_double():
    grid = OceanGrid(128, 200.0)
    double = FFTOcean(grid, 8.0, 0.2, seed=2, choppiness=0.9)
    single = FFTOcean(grid, 8.0, 0.2, seed=2, choppiness=0.9, dtype=np.float32)
    t = 5000.0  # large ωt: the phase is reduced to one cycle in float64 first
    a, b = double.fields(t), single.fields(t)
    for name in ("height", "displacement_x", "displacement_y", "slope_x", "slope_y", "jacobian", "normals"):
        x, y = getattr(a, name), getattr(b, name)
        assert y.dtype == np.float32
        # float32 transforms of N² terms: errors ~1e-7 √(log N) of the field's scale
        assert np.abs(x - y).max() < 1e-5 * np.abs(x).max(), name
    with pytest.raises(ValueError):
        FFTOcean(grid, 8.0, 0.2, dtype=np.int32)
