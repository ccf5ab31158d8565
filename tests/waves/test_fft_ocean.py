"""Tests for oceanrender.waves.fft_ocean (and .noise): normalisation, reality, derivatives, motion,
seed stability, looping, engines."""

import importlib.util
from functools import partial

import numpy as np
import pytest
import scipy.fft
import scipy.stats

from oceanrender.waves.fft_ocean import (
    ENGINES,
    FFT_BACKENDS,
    FFTOcean,
    OceanGrid,
    elevation_variance,
    initial_amplitudes,
    negate_wavenumber,
    ocean_fields,
    quantised_frequency,
    time_amplitudes,
)
from oceanrender.waves.noise import mode_gaussian, splitmix64
from oceanrender.waves.wave_spectra import (
    dispersion_relation,
    elevation_variance_Phillips2001,
    significant_wave_height_Phillips2001,
    spectrum_Phillips2001,
)
from tests.tolerances import ROUNDOFF, ROUNDOFF32

#: Phases ω t of the unreduced synthesis at t + 3T reach ~400 rad and carry ~ω t ε of
#: absolute error, ~10× that of phases reduced to one cycle [relative to the field's scale].
LARGE_PHASE_ROUNDOFF = 10 * ROUNDOFF


def smooth_ocean(resolution=64, choppiness=0.0, seed=1, t=1.7):
    """A well-resolved sea: ℓ = 3 m suppresses waves shorter than the grid resolves."""
    return FFTOcean(
        OceanGrid(resolution, 100.0), 5.0, 0.3, seed=seed, choppiness=choppiness, small_wave_length=3.0,
        dtype=np.float64,
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
    assert np.abs(surface.imag).max() / np.abs(surface.real).max() < ROUNDOFF
    # every derived field is real too: the packed pairs must not leak into each other
    packed = scipy.fft.ifft2(ocean.grid.spectral_operators * h, norm="forward")
    fields = ocean.fields(t)
    slope_scale = max(np.abs(fields.slope_x).max(), np.abs(fields.slope_y).max())
    np.testing.assert_allclose(packed[1].real, fields.slope_x, rtol=0, atol=ROUNDOFF * slope_scale)
    np.testing.assert_allclose(packed[1].imag, fields.slope_y, rtol=0, atol=ROUNDOFF * slope_scale)


def test_seed_reproducibility():
    grid = OceanGrid(32, 50.0)
    psi = spectrum_Phillips2001(grid.kx, grid.ky, 7.0, 1.0)
    first = initial_amplitudes(grid, psi, seed=11)
    # the same computation on the same inputs: bit for bit
    np.testing.assert_array_equal(initial_amplitudes(grid, psi, seed=11), first)
    assert np.abs(initial_amplitudes(grid, psi, seed=12) - first).max() > 0.1 * np.abs(first).max()
    np.testing.assert_array_equal(FFTOcean(grid, 7.0, 1.0, seed=11).fields(3.0).height,
                                  FFTOcean(grid, 7.0, 1.0, seed=11).fields(3.0).height)
    assert np.all(first[~grid.mode_mask] == 0)


def test_parseval_exact():
    ocean, t = smooth_ocean()
    h = time_amplitudes(ocean.h0, ocean.omega, t)
    eta = ocean.fields(t).height
    assert eta.mean() == pytest.approx(0.0, abs=ROUNDOFF * np.abs(eta).max())
    assert np.var(eta) == pytest.approx(np.sum(np.abs(h) ** 2), rel=ROUNDOFF)


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
    # λ = 0 multiplies the displacement spectra by 0: exact zeros, and J = 1 exactly
    assert np.all(fields.displacement_x == 0) and np.all(fields.displacement_y == 0)
    np.testing.assert_array_equal(fields.jacobian, 1.0)
    expected = np.stack([-fields.slope_x, -fields.slope_y, np.ones_like(fields.slope_x)], axis=-1)
    expected /= np.linalg.norm(expected, axis=-1, keepdims=True)
    np.testing.assert_allclose(fields.normals, expected, rtol=0, atol=ROUNDOFF)  # unit vectors: scale 1


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
    ocean = FFTOcean(grid, 6.0, -2.0, seed=5, choppiness=choppiness, dtype=np.float64)
    t = 2.3
    fields = ocean.fields(t)
    h = time_amplitudes(ocean.h0, ocean.omega, t)
    k = np.where(grid.k == 0, 1.0, grid.k)

    def direct(multiplier):
        values = direct_sum(grid, multiplier * h, grid.x, grid.y)
        assert np.abs(values.imag).max() <= ROUNDOFF * np.abs(values).max()
        return values.real

    def check(actual, expected):  # the fields cross zero: relative to each field's scale
        np.testing.assert_allclose(actual, expected, rtol=0, atol=ROUNDOFF * np.abs(expected).max())

    lam = -choppiness  # displaced by −λD (D of Tessendorf's eq. 29): sharp crests, see OceanSynthesis
    check(fields.height, direct(1.0))
    check(fields.slope_x, direct(1j * grid.kx))
    check(fields.slope_y, direct(1j * grid.ky))
    check(fields.displacement_x, lam * direct(-1j * grid.kx / k))
    check(fields.displacement_y, lam * direct(-1j * grid.ky / k))
    dxx, dyy, dxy = (lam * direct(m) for m in (grid.kx**2 / k, grid.ky**2 / k, grid.kx * grid.ky / k))
    np.testing.assert_allclose(fields.jacobian, (1 + dxx) * (1 + dyy) - dxy**2, rtol=0, atol=ROUNDOFF)  # scale 1


def test_choppy_normals_are_unit_up_and_orthogonal_to_the_displaced_surface():
    # steeper than smooth_ocean (slopes ~0.04 rms) yet resolved: ℓ = 0.3 m on a 0.08 m grid
    grid, t = OceanGrid(256, 20.0), 1.0
    ocean = FFTOcean(grid, 3.0, 0.3, seed=1, choppiness=1.0, small_wave_length=0.3, dtype=np.float64)
    fields = ocean.fields(t)
    n = fields.normals
    np.testing.assert_allclose(np.linalg.norm(n, axis=-1), 1.0, rtol=0, atol=ROUNDOFF)  # scale 1
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

    assert worst_cosine(n) < 1e-4  # the finite differences' truncation error: 5e-5 measured
    # the normal of the undisplaced height field fails the same check: the test has teeth
    flat = np.stack([-fields.slope_x, -fields.slope_y, np.ones_like(fields.slope_x)], axis=-1)
    assert worst_cosine(flat / np.linalg.norm(flat, axis=-1, keepdims=True)) > 1e-3


def test_mean_jacobian_is_one():
    # mean(J) = 1 + λ² Σ (kx² ky² − (kx ky)²)/k² |h̃|² = 1 exactly: the periodic
    # displacement neither gains nor loses horizontal area
    ocean, t = smooth_ocean(choppiness=2.0)
    jacobian = ocean.fields(t).jacobian
    assert jacobian.mean() == pytest.approx(1.0, rel=ROUNDOFF)
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
    # e^{−iωt} (Tessendorf's eq. 26 has e^{+iωt}): the variance at k runs along +k, here towards +x
    np.testing.assert_allclose(eta, np.roll(eta0, 3, axis=1), rtol=0, atol=ROUNDOFF * np.abs(eta0).max())
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
    double = FFTOcean(grid, 8.0, 0.2, seed=2, choppiness=0.9, dtype=np.float64)
    single = FFTOcean(grid, 8.0, 0.2, seed=2, choppiness=0.9, dtype=np.float32)
    t = 5000.0  # large ωt: the phase is reduced to one cycle in float64 first
    a, b = double.fields(t), single.fields(t)
    for name in ("height", "displacement_x", "displacement_y", "slope_x", "slope_y", "jacobian", "normals"):
        x, y = getattr(a, name), getattr(b, name)
        assert y.dtype == np.float32
        # float32 transforms of N² terms: errors ~1e-7 √(log N) of the field's scale (5e-7 measured)
        assert np.abs(x - y).max() < ROUNDOFF32 * np.abs(x).max(), name
    with pytest.raises(ValueError):
        FFTOcean(grid, 8.0, 0.2, dtype=np.int32)


# --- seed-stable noise, loop period, spectrum callables, engines and backends -------------------------


def test_splitmix64_reference_values_and_noise_statistics():
    # SplitMix64 seeded with 0 (state advanced by the golden gamma first): published first outputs
    assert int(splitmix64(np.uint64(0))) == 0xE220A8397B1DCDAF
    assert int(splitmix64(np.uint64(0x9E3779B97F4A7C15))) == 0x6E789E6AA1B965F4
    n = np.arange(-200, 200)
    xi = mode_gaussian(7, 0, n[None, :], n[:, None])
    parts = np.concatenate([xi.real.ravel(), xi.imag.ravel()])  # 320 000 draws
    assert abs(parts.mean()) < 5 / np.sqrt(parts.size)
    assert abs(parts.var() - 1) < 5 * np.sqrt(2 / parts.size)
    assert abs(np.corrcoef(xi.real.ravel(), xi.imag.ravel())[0, 1]) < 5 / np.sqrt(xi.size)
    assert abs(np.corrcoef(xi.real[:, 1:].ravel(), xi.real[:, :-1].ravel())[0, 1]) < 5 / np.sqrt(xi.size)
    assert scipy.stats.kstest(parts, "norm").pvalue > 1e-3
    # a pure function of (seed, cascade, nx, ny): order and shape of the request do not matter
    assert mode_gaussian(7, 0, 3, -5) == xi[200 - 5, 200 + 3]
    assert mode_gaussian(7, 1, 3, -5) != mode_gaussian(7, 0, 3, -5)
    assert mode_gaussian(8, 0, 3, -5) != mode_gaussian(7, 0, 3, -5)


def test_refining_the_grid_keeps_the_large_waves():
    L, t = 200.0, 3.3
    coarse, fine = OceanGrid(128, L), OceanGrid(256, L)
    spectrum = partial(spectrum_Phillips2001, wind_speed=9.0, wind_direction=0.4)
    h_coarse = initial_amplitudes(coarse, spectrum(coarse.kx, coarse.ky), seed=5)
    h_fine = initial_amplitudes(fine, spectrum(fine.kx, fine.ky), seed=5)
    # the modes common to both grids (|n| < 64, the coarse grid's Nyquist excluded) are identical:
    # seed-stable noise, the same computation for the same mode on either grid, so bit for bit
    common = (np.abs(fine.indices[None, :]) < 64) & (np.abs(fine.indices[:, None]) < 64)
    rows, coarse_rows = np.abs(fine.indices) < 64, np.abs(coarse.indices) < 64  # same order: 0 … 63, −63 … −1
    np.testing.assert_array_equal(h_fine[np.ix_(rows, rows)], h_coarse[np.ix_(coarse_rows, coarse_rows)])
    # the low-pass of the fine sea is the coarse sea, at the coarse grid's points
    omega = dispersion_relation(fine.k)
    low_pass = ocean_fields(fine, h_fine * common, omega, t, 1.0)
    reference = ocean_fields(coarse, h_coarse, dispersion_relation(coarse.k), t, 1.0)
    for name in ("height", "displacement_x", "slope_y", "jacobian"):
        np.testing.assert_allclose(getattr(low_pass, name)[::2, ::2], getattr(reference, name), rtol=0,
                                   atol=ROUNDOFF * np.abs(getattr(reference, name)).max())
    # and the fine sea adds only short waves to it
    full = ocean_fields(fine, h_fine, omega, t, 1.0).height[::2, ::2]
    assert np.std(full - reference.height) < 0.2 * np.std(reference.height)


def test_loop_period_repeats_the_sea_exactly():
    T = 20.0
    ocean = FFTOcean(OceanGrid(64, 150.0), 8.0, 0.7, seed=3, choppiness=1.2, loop_period=T, dtype=np.float64)
    free = FFTOcean(OceanGrid(64, 150.0), 8.0, 0.7, seed=3, choppiness=1.2, dtype=np.float64)
    omega_0 = 2 * np.pi / T
    change = free.omega - ocean.omega
    assert np.all((change >= 0) & (change < omega_0))
    cycles = np.round(ocean.omega / omega_0)  # whole numbers of cycles in T, up to max(cycles)
    np.testing.assert_allclose(ocean.omega / omega_0, cycles, rtol=0, atol=ROUNDOFF * cycles.max())
    for t in [0.0, 1.37, 55.5]:
        a, b = ocean.fields(t), ocean.fields(t + T)
        # without the reduction t mod T: the quantised phases alone make the sea repeat
        c = ocean.synthesis(t + 3 * T)
        for name in ("height", "displacement_x", "displacement_y", "slope_x", "jacobian", "normals"):
            scale = np.abs(getattr(a, name)).max()
            np.testing.assert_allclose(getattr(b, name), getattr(a, name), rtol=0, atol=ROUNDOFF * scale)
            np.testing.assert_allclose(getattr(c, name), getattr(ocean.synthesis(t), name), rtol=0,
                                       atol=LARGE_PHASE_ROUNDOFF * scale)
    # the free sea does not repeat after T
    assert np.abs(free.fields(1.37 + T).height - free.fields(1.37).height).max() > 1e-3
    np.testing.assert_array_equal(quantised_frequency(free.omega, None), free.omega)  # None: ω untouched
    with pytest.raises(ValueError):
        quantised_frequency(free.omega, 0.0)
    with pytest.raises(ValueError):
        FFTOcean(OceanGrid(8, 10.0), 5.0, 0.0, loop_period=-1.0)


def test_spectrum_function_replaces_the_phillips_parameters():
    grid = OceanGrid(32, 80.0)
    named = FFTOcean(grid, 7.0, 1.0, seed=4, small_wave_length=0.5, dtype=np.float64)
    spectrum = partial(spectrum_Phillips2001, wind_speed=7.0, wind_direction=1.0, small_wave_length=0.5)
    called = FFTOcean(grid, seed=4, spectrum_function=spectrum, dtype=np.float64)
    # exact: both evaluate spectrum_Phillips2001 with the same arguments on the same grid
    np.testing.assert_array_equal(called.spectrum_values, named.spectrum_values)
    np.testing.assert_array_equal(called.fields(2.0).height, named.fields(2.0).height)
    with pytest.raises(ValueError):
        FFTOcean(grid, spectrum_function=3.0)


@pytest.mark.parametrize("dtype, rtol", [(np.float64, ROUNDOFF), (np.float32, ROUNDOFF32)])
@pytest.mark.parametrize("resolution, choppiness", [(32, 1.1), (15, 0.7), (16, 0.0)])
def test_engines_and_fft_libraries_agree(dtype, rtol, resolution, choppiness):
    grid = OceanGrid(resolution, 60.0)
    reference = FFTOcean(grid, 7.0, 0.2, seed=8, choppiness=choppiness, dtype=dtype, engine="numpy",
                         fft_backend="scipy").fields(4.0)
    variants = [dict(engine=e, fft_backend=b, workers=w) for e in ENGINES for b in FFT_BACKENDS for w in (1, 3)
                if importlib.util.find_spec(b) is not None]
    for variant in variants:
        fields = FFTOcean(grid, 7.0, 0.2, seed=8, choppiness=choppiness, dtype=dtype, **variant).fields(4.0)
        for name in ("height", "displacement_x", "displacement_y", "slope_x", "slope_y", "jacobian", "normals",
                     "jacobian_xx", "jacobian_yy", "jacobian_xy"):
            x, y = getattr(fields, name), getattr(reference, name)
            assert x.dtype == dtype
            # relative to the field's scale (all-zero fields at λ = 0 must be zero everywhere)
            np.testing.assert_allclose(x, y, rtol=0, atol=rtol * np.abs(y).max(), err_msg=f"{variant} {name}")
    with pytest.raises(ValueError, match="numpy"):
        FFTOcean(grid, 7.0, 0.2, engine="nope")
    with pytest.raises(ValueError, match="scipy"):
        FFTOcean(grid, 7.0, 0.2, fft_backend="nope")


def test_fields_can_be_computed_into_the_previous_frame():
    ocean = FFTOcean(OceanGrid(32, 50.0), 6.0, 0.0, seed=1, choppiness=0.9, dtype=np.float64)
    first = ocean.fields(1.0)
    expected = ocean.fields(2.0)
    again = ocean.fields(2.0, out=first)
    assert np.shares_memory(again.height, first.height) and again.normals is first.normals
    for name in ("height", "displacement_y", "jacobian", "normals"):  # the same computation, only stored elsewhere
        np.testing.assert_array_equal(getattr(again, name), getattr(expected, name))
    single = FFTOcean(OceanGrid(32, 50.0), 6.0, 0.0, seed=1, choppiness=0.9)  # float32
    with pytest.raises(ValueError):
        single.fields(1.0, out=first)


def test_frames_held_by_the_caller_are_never_overwritten():
    ocean = FFTOcean(OceanGrid(32, 50.0), 6.0, 0.0, seed=1, choppiness=0.9)
    first = ocean.fields(1.0)
    saved = {name: getattr(first, name).copy() for name in ("height", "slope_x", "displacement_y", "jacobian",
                                                            "normals", "jacobian_xx")}
    second = ocean.fields(2.0)
    for name, values in saved.items():
        np.testing.assert_array_equal(getattr(first, name), values)
        assert not np.shares_memory(getattr(second, name), getattr(first, name))
    # a frame nobody holds any more is recycled; one array still held is not
    height = second.height
    storage = id(second.slope_x.base)
    del first, second
    third = ocean.fields(3.0)
    assert id(third.slope_x.base) == storage
    assert not np.shares_memory(third.height, height)


def test_a_one_sided_spectrum_travels_down_wind():
    # all variance around k₀ = (±0.5 rad/m, 0): the wave groups must run along k₀, at the
    # deep-water group speed c/2 (the phase speed is checked with a single mode above)
    grid = OceanGrid(128, 400.0)
    speed = np.sqrt(9.81 / 0.5) / 2
    dt = 20 * grid.spacing / speed  # twenty cells

    def correlation_peak(k0):
        spectrum = lambda kx, ky: np.exp(-((kx - k0) ** 2 + ky**2) / (2 * 0.05**2))  # noqa: E731
        ocean = FFTOcean(grid, seed=2, choppiness=0.0, spectrum_function=spectrum, dtype=np.float64)
        before, after = ocean.fields(0.0).height, ocean.fields(dt).height
        shifts = np.arange(-40, 41)
        correlation = [np.sum(after * np.roll(before, s, axis=1)) for s in shifts]
        return shifts[np.argmax(correlation)]

    # the envelope moves 20 cells; the correlation peaks on the carrier crest (4 cells apart) nearest to it
    assert abs(correlation_peak(0.5) - 20) <= 2
    assert abs(correlation_peak(-0.5) + 20) <= 2


def test_choppy_waves_have_sharp_crests_and_round_troughs():
    # Gerstner / Lagrangian kinematics: particles crowd towards crests, so the
    # horizontal map compresses (J < 1) where η is high and stretches in troughs.
    ocean = FFTOcean(OceanGrid(128, 100.0), 9.0, 0.4, seed=2, choppiness=1.0, dtype=np.float64)
    fields = ocean.fields(1.7)
    assert np.corrcoef(fields.jacobian.ravel(), fields.height.ravel())[0, 1] < -0.5
    crests = fields.height > np.quantile(fields.height, 0.95)
    troughs = fields.height < np.quantile(fields.height, 0.05)
    assert fields.jacobian[crests].mean() < 1 < fields.jacobian[troughs].mean()


def test_a_named_spectrum_uses_the_depth_and_refuses_what_it_cannot_use():
    """Issue 23 item 4: FFTOcean(spectrum="TMA 1985", depth=d) used to give JONSWAP exactly (the depth was
    dropped); it is built by the same function as the scene files now."""
    from oceanrender.waves.wave_spectra import DirectionalSpectrum

    grid = OceanGrid(32, 200.0)
    tma = FFTOcean(grid, 9.0, 0.3, spectrum="TMA 1985", depth=5.0, dtype=np.float64)
    jonswap = FFTOcean(grid, 9.0, 0.3, spectrum="JONSWAP 1973", depth=5.0, dtype=np.float64)
    direct = DirectionalSpectrum("TMA 1985", wind_speed=9.0, wind_direction=0.3, depth=5.0)(grid.kx, grid.ky)
    np.testing.assert_array_equal(tma.spectrum_values, direct)
    # The Kitaigorodskii depth function takes variance away in 5 m of water.
    assert tma.elevation_variance < 0.9 * jonswap.elevation_variance
    with pytest.raises(ValueError, match="alpha"):
        FFTOcean(grid, 9.0, 0.3, spectrum="JONSWAP 1973", alpha=0.01).spectrum_values


def test_surface_tension_enters_the_dispersion_relation():
    """ω² = (g k + σ k³/ρ) tanh kd (Lamb 1932): with σ = 0.074 N/m the phase speed has its minimum
    √(2 √(g σ/ρ)) ≈ 0.231 m/s at λ ≈ 1.70 cm; without, ω = √(g k)."""
    from oceanrender.waves.wave_spectra import GRAVITY, SEAWATER_DENSITY, SEAWATER_SURFACE_TENSION

    grid = OceanGrid(64, 1.0)  # waves from 1 m down to 3 cm
    plain = FFTOcean(grid, 5.0, 0.0, dtype=np.float64)
    capillary = FFTOcean(grid, 5.0, 0.0, surface_tension=SEAWATER_SURFACE_TENSION, dtype=np.float64)
    k = grid.k
    np.testing.assert_allclose(plain.omega, np.sqrt(GRAVITY * k), rtol=1e-12)
    expected = np.sqrt(GRAVITY * k + SEAWATER_SURFACE_TENSION / SEAWATER_DENSITY * k**3)
    np.testing.assert_allclose(capillary.omega, expected, rtol=1e-12)
    k_m = np.sqrt(SEAWATER_DENSITY * GRAVITY / SEAWATER_SURFACE_TENSION)
    c_min = float(np.sqrt(GRAVITY * k_m + SEAWATER_SURFACE_TENSION / SEAWATER_DENSITY * k_m**3) / k_m)
    assert c_min == pytest.approx(0.231, abs=0.001) and 2 * np.pi / k_m == pytest.approx(0.0170, abs=2e-4)
