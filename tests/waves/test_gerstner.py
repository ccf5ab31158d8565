"""Tests for oceanrender.waves.gerstner: one-wave closed forms, Parseval, derivatives, limits."""

from functools import partial

import numpy as np
import pytest

from oceanrender.waves.fft_ocean import OceanFields
from oceanrender.waves.gerstner import (
    GERSTNER_STEEPNESS,
    WaveComponent,
    gerstner_fields,
    steepness_Finch2004,
    sum_of_sines_fields,
    wave_components_from_spectrum,
    wave_components_variance,
)
from oceanrender.waves.wave_spectra import GRAVITY, dispersion_relation, spectrum_Phillips2001
from tests.tolerances import ROUNDOFF

FIELD_NAMES = ("height", "displacement_x", "displacement_y", "slope_x", "slope_y", "jacobian", "normals")


def phillips(wind_speed=8.0, wind_direction=0.4):
    return partial(spectrum_Phillips2001, wind_speed=wind_speed, wind_direction=wind_direction)


def band_variance(spectrum, k_min, k_max):
    """∫∫ Ψ dkx dky over k_min ≤ |k| < k_max: trapezoids in ln k, a periodic sum in θ [m²]."""
    ln_k = np.linspace(np.log(k_min), np.log(k_max), 2001)
    theta = np.linspace(-np.pi, np.pi, 64, endpoint=False)  # periodic: the plain sum is exact for cos²
    k = np.exp(ln_k)[:, None]
    radial = spectrum(k * np.cos(theta), k * np.sin(theta)).sum(axis=1) * (2 * np.pi / theta.size) * k[:, 0] ** 2
    return np.trapezoid(radial, ln_k)


def some_components(count=24, seed=3, k_min=0.1, k_max=2.0):
    return wave_components_from_spectrum(phillips(), count, seed, k_min, k_max)


def test_one_component_is_the_analytic_cosine(rng):
    wave = WaveComponent(0.7, 0.3, -0.2, 1.1)
    x, y = rng.uniform(-50, 50, (2, 200))
    t, depth = 4.2, 12.0
    omega = dispersion_relation(np.hypot(0.3, -0.2), depth)
    theta = 0.3 * x - 0.2 * y - omega * t + 1.1
    fields = sum_of_sines_fields([wave], x, y, t, depth)
    assert isinstance(fields, OceanFields)
    # cosines cross zero: relative to their amplitudes a, a kx, a ky
    np.testing.assert_allclose(fields.height, 0.7 * np.cos(theta), rtol=0, atol=ROUNDOFF * 0.7)
    np.testing.assert_allclose(fields.slope_x, -0.7 * 0.3 * np.sin(theta), rtol=0, atol=ROUNDOFF * 0.7 * 0.3)
    np.testing.assert_allclose(fields.slope_y, 0.7 * 0.2 * np.sin(theta), rtol=0, atol=ROUNDOFF * 0.7 * 0.2)
    # a sum of sines has no horizontal displacement by construction: exact zeros and J = 1
    assert np.all(fields.displacement_x == 0) and np.all(fields.displacement_y == 0)
    np.testing.assert_array_equal(fields.jacobian, 1.0)
    assert wave.angular_frequency(depth) == pytest.approx(float(omega), rel=ROUNDOFF)


@pytest.mark.parametrize("depth", [np.inf, 3.0])
def test_one_component_travels_at_the_phase_speed(depth, rng):
    wave = WaveComponent(0.4, 0.5 * np.cos(2.0), 0.5 * np.sin(2.0), 0.3)
    k = wave.wavenumber
    speed = np.sqrt(GRAVITY * np.tanh(k * depth) / k)  # ω/k from ω² = g k tanh(k d)
    x, y = rng.uniform(-30, 30, (2, 100))
    t = 7.3
    later = sum_of_sines_fields([wave], x + speed * t * np.cos(2.0), y + speed * t * np.sin(2.0), t, depth)
    np.testing.assert_allclose(later.height, sum_of_sines_fields([wave], x, y, 0.0, depth).height, rtol=0,
                               atol=ROUNDOFF * wave.amplitude)  # phases of ~20 rad, scale: the amplitude
    # the deep-water speed would be wrong in 3 m of water: the depth reaches ω
    if np.isfinite(depth):
        deep = sum_of_sines_fields([wave], x + speed * t * np.cos(2.0), y + speed * t * np.sin(2.0), t)
        assert np.abs(deep.height - later.height).max() > 0.1


def test_drawn_variance_matches_the_band_integral():
    spectrum, k_min, k_max = phillips(), 0.02, 10.0  # the peak, k ≈ 1/L_w = 0.15 rad/m, inside the band
    expected = band_variance(spectrum, k_min, k_max)
    # stratified jitter, 32 × 32 cells: relative std ≈ 0.6 % per draw (50 seeds measured),
    # so 3 % is 5 std for one draw and 0.5 % is 4 std for the mean of 20
    variances = [wave_components_variance(wave_components_from_spectrum(spectrum, 1024, seed, k_min, k_max))
                 for seed in range(20)]
    assert np.all(np.abs(np.array(variances) / expected - 1) < 0.03)
    assert np.mean(variances) == pytest.approx(expected, rel=0.005)
    # cell centres: the midpoint rule in (ln k, θ), deterministic, O(h²)
    midpoint = wave_components_from_spectrum(spectrum, 1024, 0, k_min, k_max, jitter=False)
    assert wave_components_variance(midpoint) == pytest.approx(expected, rel=1e-3)
    # a_i = √(2 Ψ ΔA) with ΔA = k² Δln k Δθ, checked on one cell of a constant spectrum
    (single,) = wave_components_from_spectrum(lambda kx, ky: np.full_like(kx, 2.0), 1, 5, 1.0, 2.0)
    assert single.amplitude == pytest.approx(np.sqrt(2 * 2.0 * single.wavenumber**2 * np.log(2) * 2 * np.pi))


def test_the_spatial_variance_of_a_drawn_sea_is_the_components_variance():
    # distinct wavenumbers, incommensurate with the window: the sample variance of η over a large
    # patch tends to Σ a²/2: cross terms average out as 1/(Δk · size), within 1.5 % here for seeds 2–7
    components = wave_components_from_spectrum(phillips(), 64, 2, 0.3, 3.0)
    x, y = np.meshgrid(np.linspace(0, 400, 300), np.linspace(0, 400, 300))
    height = sum_of_sines_fields(components, x, y, 0.0).height
    assert np.var(height) == pytest.approx(wave_components_variance(components), rel=0.05)


def test_components_are_stratified_and_reproducible():
    spectrum, k_min, k_max = phillips(), 0.05, 5.0
    components = wave_components_from_spectrum(spectrum, 96, 7, k_min, k_max, directions=8)
    assert components == wave_components_from_spectrum(spectrum, 96, 7, k_min, k_max, directions=8)
    assert components != wave_components_from_spectrum(spectrum, 96, 8, k_min, k_max, directions=8)
    k = np.array([c.wavenumber for c in components])
    direction = np.array([c.direction for c in components])
    band = np.floor(np.log(k / k_min) / (np.log(k_max / k_min) / 12)).astype(int)
    sector = np.floor((direction + np.pi) / (2 * np.pi / 8)).astype(int)
    # one component in each of the 12 × 8 cells
    assert sorted(zip(band.tolist(), sector.tolist())) == [(i, j) for i in range(12) for j in range(8)]
    assert len(wave_components_from_spectrum(spectrum, 256, 1, k_min, k_max)) == 256


def test_patch_size_makes_the_sea_tile():
    spectrum, L = phillips(), 40.0
    free = wave_components_from_spectrum(spectrum, 64, 4, 2 * np.pi / L, 3.0)
    tiled = wave_components_from_spectrum(spectrum, 64, 4, 2 * np.pi / L, 3.0, patch_size=L)
    assert [c.amplitude for c in tiled] == [c.amplitude for c in free]  # the variance is kept exactly
    lattice = np.array([(c.wavenumber_x, c.wavenumber_y) for c in tiled]) / (2 * np.pi / L)
    np.testing.assert_allclose(lattice, np.rint(lattice), rtol=0, atol=ROUNDOFF * np.abs(lattice).max())
    x, y = np.meshgrid(np.linspace(-20, 20, 9), np.linspace(-20, 20, 7))
    amplitudes = sum(c.amplitude for c in tiled)  # the scale of the heights [m]
    for model in (sum_of_sines_fields, partial(gerstner_fields, steepness=0.5)):
        here = model(tiled, x, y, 2.0).height
        np.testing.assert_allclose(model(tiled, x + L, y - L, 2.0).height, here, rtol=0, atol=ROUNDOFF * amplitudes)
        assert np.abs(model(free, x + L, y, 2.0).height - model(free, x, y, 2.0).height).max() > 1e-3
    with pytest.raises(ValueError, match="2π/L"):
        wave_components_from_spectrum(spectrum, 64, 4, 0.1, 3.0, patch_size=L)


@pytest.mark.parametrize("normalisation", list(GERSTNER_STEEPNESS))
def test_gerstner_with_zero_steepness_is_the_sum_of_sines(normalisation, rng):
    components = some_components()
    x, y = rng.uniform(-40, 40, (2, 500))
    flat = sum_of_sines_fields(components, x, y, 3.3)
    gerstner = gerstner_fields(components, x, y, 3.3, steepness=0.0, normalisation=normalisation)
    # Q = 0 multiplies the displacement: exact zeros and J = 1
    np.testing.assert_array_equal(gerstner.displacement_x, 0.0)
    np.testing.assert_array_equal(gerstner.displacement_y, 0.0)
    np.testing.assert_array_equal(gerstner.jacobian, 1.0)
    for name in ("height", "slope_x", "slope_y", "normals"):  # two code paths: relative to each field's scale
        np.testing.assert_allclose(getattr(gerstner, name), getattr(flat, name), rtol=0,
                                   atol=ROUNDOFF * np.abs(getattr(flat, name)).max())


def test_one_gerstner_wave_is_a_trochoid():
    a, k, beta, phase, t = 0.5, 0.4, 0.7, 0.2, 1.9
    q = 0.8  # Q k a = 0.16
    wave = WaveComponent(a, k * np.cos(beta), k * np.sin(beta), phase)
    s = np.linspace(0, 2 * np.pi / k, 20001)  # one wavelength along the direction of travel
    fields = gerstner_fields([wave], s * np.cos(beta), s * np.sin(beta), t, steepness=q,
                             normalisation="Tessendorf 2001")
    theta = k * s - dispersion_relation(k) * t + phase
    # exact horizontal displacement −Q a k̂ sin θ (scale Q a), and J = 1 − Q k a cos θ (scale 1)
    np.testing.assert_allclose(fields.displacement_x, -q * a * np.cos(beta) * np.sin(theta), rtol=0,
                               atol=ROUNDOFF * q * a)
    np.testing.assert_allclose(fields.displacement_y, -q * a * np.sin(beta) * np.sin(theta), rtol=0,
                               atol=ROUNDOFF * q * a)
    np.testing.assert_allclose(fields.jacobian, 1 - q * k * a * np.cos(theta), rtol=0, atol=ROUNDOFF)
    # the profile (X, Z) along k̂ is a trochoid: rolling radius 1/k, tracing radius Q a; its curvature
    # is a k²/(1 ∓ Q k a)² at crest and trough, sharper crests than the sine's a k²
    X = s + fields.displacement_x * np.cos(beta) + fields.displacement_y * np.sin(beta)
    Z = fields.height
    dX, dZ = np.gradient(X, s), np.gradient(Z, s)
    curvature = (dX * np.gradient(dZ, s) - dZ * np.gradient(dX, s)) / (dX**2 + dZ**2) ** 1.5
    crest, trough = np.argmax(Z), np.argmin(Z)
    # np.gradient is second order: truncation (k Δs)² ≈ 1e-7 here
    assert -curvature[crest] == pytest.approx(a * k**2 / (1 - q * k * a) ** 2, rel=1e-4)
    assert curvature[trough] == pytest.approx(a * k**2 / (1 + q * k * a) ** 2, rel=1e-4)
    # each particle circles (Q = 1 in Tessendorf's form: a circle of radius a, Gerstner's orbit)
    times = np.linspace(0, 20, 50)
    orbit = [gerstner_fields([wave], 3.0, -1.0, time, steepness=1.0, normalisation="Tessendorf 2001")
             for time in times]
    radius = np.hypot([f.displacement_x for f in orbit], [f.displacement_y for f in orbit])
    np.testing.assert_allclose(np.hypot(radius, [f.height for f in orbit]), a, rtol=ROUNDOFF)


def test_finch_normalisation_of_one_wave():
    a, k, q = 0.3, 0.9, 0.6
    wave = WaveComponent(a, 0.0, k)
    assert steepness_Finch2004([a], [k], q) == pytest.approx([q / (k * a)])
    theta = np.linspace(-np.pi, np.pi, 101)
    fields = gerstner_fields([wave], 0.0, theta / k, 0.0, steepness=q)  # Finch is the default
    np.testing.assert_allclose(fields.jacobian, 1 - q * np.cos(theta), rtol=0, atol=ROUNDOFF)  # Q k a = q; scale 1
    # zero-amplitude waves neither count in N nor displace (their Q is exactly 0)
    assert steepness_Finch2004([a, 0.0], [k, 1.0], q).tolist() == pytest.approx([q / (k * a), 0.0], rel=ROUNDOFF,
                                                                                abs=0)


@pytest.mark.parametrize("qka", [0.5, 0.975, 1.0, 1.025, 1.5])
def test_one_wave_loops_only_when_qka_exceeds_one(qka):
    a, k = 0.25, 1.0
    wave = WaveComponent(a, k, 0.0)
    x = np.linspace(-np.pi, np.pi, 2001)  # includes the crest θ = 0
    fields = gerstner_fields([wave], x, 0.0, 0.0, steepness=qka / (k * a), normalisation="Tessendorf 2001")
    assert fields.jacobian.min() == pytest.approx(1 - qka, abs=ROUNDOFF)  # J: scale 1
    assert (fields.jacobian.min() < 0) == (qka > 1)
    assert np.all(np.isfinite(fields.normals))  # at the cusp (Q k a = 1) the normal is set to +z


def test_finch_normalisation_never_loops(rng):
    # twelve steep waves (k a = 0.3 each): Tessendorf's q = 1 folds them, Finch's q = 1 cannot
    angles = rng.uniform(-np.pi, np.pi, 12)
    k = rng.uniform(0.2, 1.0, 12)
    waves = [WaveComponent(0.3 / ki, ki * np.cos(b), ki * np.sin(b), p)
             for ki, b, p in zip(k, angles, rng.uniform(0, 2 * np.pi, 12))]
    x, y = rng.uniform(-100, 100, (2, 20000))
    finch = gerstner_fields(waves, x, y, 5.0, steepness=1.0, normalisation="Finch 2004").jacobian
    assert finch.min() >= -ROUNDOFF  # J ≥ 1 − q; J has scale 1
    assert finch.max() <= 2 + ROUNDOFF
    assert gerstner_fields(waves, x, y, 5.0, steepness=1.0, normalisation="Tessendorf 2001").jacobian.min() < 0


@pytest.mark.parametrize("model", ["sum of sines", "Gerstner"])
def test_analytic_derivatives_match_finite_differences(model, rng):
    components = some_components()
    evaluate = (sum_of_sines_fields if model == "sum of sines"
                else partial(gerstner_fields, steepness=0.7, normalisation="Tessendorf 2001"))
    x, y = rng.uniform(-40, 40, (2, 300))
    t, h = 2.5, 1e-4
    fields = evaluate(components, x, y, t)
    right, left = evaluate(components, x + h, y, t), evaluate(components, x - h, y, t)
    up, down = evaluate(components, x, y + h, t), evaluate(components, x, y - h, t)

    def d(name, plus, minus):
        return (getattr(plus, name) - getattr(minus, name)) / (2 * h)  # error (k h)²/6 ~ 1e-9 relative

    scale = np.abs(fields.slope_x).max() + np.abs(fields.slope_y).max()
    assert np.abs(d("height", right, left) - fields.slope_x).max() < 1e-6 * scale
    assert np.abs(d("height", up, down) - fields.slope_y).max() < 1e-6 * scale
    # tangents of P = (x + Dx, y + Dy, η) by finite differences: the Jacobian and the normal
    tx = np.stack([1 + d("displacement_x", right, left), d("displacement_y", right, left), fields.slope_x], -1)
    ty = np.stack([d("displacement_x", up, down), 1 + d("displacement_y", up, down), fields.slope_y], -1)
    # J and the cosines have scale 1; the differences' truncation error is ~1e-9 of it (see d)
    np.testing.assert_allclose(fields.jacobian, tx[:, 0] * ty[:, 1] - tx[:, 1] * ty[:, 0], rtol=0, atol=1e-7)
    for tangent in (tx, ty):
        cosine = np.sum(fields.normals * tangent, axis=-1) / np.linalg.norm(tangent, axis=-1)
        assert np.abs(cosine).max() < 1e-7
    if model == "Gerstner":  # the check has teeth: the height-field normal is not orthogonal to them
        assert np.abs(tx[:, :2] - [1, 0]).max() > 1e-2
        flat = sum_of_sines_fields(components, x, y, t).normals
        assert np.abs(np.sum(flat * tx, axis=-1)).max() > 1e-3


def test_normals_are_unit_and_point_up(rng):
    components = some_components(count=64, k_max=4.0)
    x, y = np.meshgrid(np.linspace(-30, 30, 64), np.linspace(-30, 30, 64))
    for fields in (sum_of_sines_fields(components, x, y, 1.0),
                   gerstner_fields(components, x, y, 1.0, steepness=1.0, normalisation="Finch 2004"),
                   gerstner_fields(components, x, y, 1.0, steepness=1.0, normalisation="Tessendorf 2001")):
        assert fields.normals.shape == (64, 64, 3)
        np.testing.assert_allclose(np.linalg.norm(fields.normals, axis=-1), 1.0, rtol=0, atol=ROUNDOFF)  # scale 1
        assert fields.jacobian.min() > 0  # not folded (this sea is gentle: k a ≪ 1)
        assert np.all(fields.normals[..., 2] > 0)


def test_points_broadcast_and_empty_seas():
    components = some_components(count=4)
    fields = gerstner_fields(components, np.linspace(0, 1, 3)[:, None], np.linspace(0, 1, 5)[None, :], 0.0)
    for name in FIELD_NAMES:
        assert getattr(fields, name).shape == ((3, 5, 3) if name == "normals" else (3, 5))
    point = sum_of_sines_fields(components, 1.0, 2.0, 0.0)
    assert point.height.shape == () and point.normals.shape == (3,)
    calm = gerstner_fields([], np.zeros(4), np.zeros(4), 0.0)  # an empty sum: exactly flat
    np.testing.assert_array_equal(calm.height, 0.0)
    np.testing.assert_array_equal(calm.normals, [[0.0, 0.0, 1.0]] * 4)


def test_validation():
    for bad in [(-0.1, 1.0, 0.0), (0.1, 0.0, 0.0), (np.nan, 1.0, 0.0)]:
        with pytest.raises(ValueError):
            WaveComponent(*bad)
    components = some_components(count=4)
    with pytest.raises(ValueError, match="'Finch 2004', 'Tessendorf 2001'"):
        gerstner_fields(components, 0.0, 0.0, 0.0, normalisation="Fournier 1986")
    with pytest.raises(ValueError):
        gerstner_fields(components, 0.0, 0.0, 0.0, steepness=-1.0)
    spectrum = phillips()
    for kwargs in [dict(count=10, directions=3), dict(count=0), dict(k_min=1.0, k_max=0.5), dict(k_min=0.0)]:
        arguments = dict(count=16, seed=0, k_min=0.1, k_max=1.0) | kwargs
        with pytest.raises(ValueError):
            wave_components_from_spectrum(spectrum, **arguments)
    with pytest.raises(ValueError, match="non-negative"):
        wave_components_from_spectrum(lambda kx, ky: -np.ones_like(kx), 4, 0, 0.1, 1.0)


def test_jacobian_matrix_entries_when_the_fields_carry_them(rng):
    components = some_components()
    x, y = rng.uniform(-20, 20, (2, 50))
    fields = gerstner_fields(components, x, y, 1.0, steepness=0.8, normalisation="Tessendorf 2001")
    if getattr(fields, "jacobian_xx", None) is None:
        pytest.skip("this OceanFields has no Jacobian-matrix entries")
    np.testing.assert_allclose(fields.jacobian_xx * fields.jacobian_yy - fields.jacobian_xy**2, fields.jacobian,
                               rtol=0, atol=ROUNDOFF * np.abs(fields.jacobian_xx * fields.jacobian_yy).max())
    flat = sum_of_sines_fields(components, x, y, 1.0)
    np.testing.assert_array_equal(flat.jacobian_xx, 1.0)
    np.testing.assert_array_equal(flat.jacobian_xy, 0.0)
