"""LUT baking: axes, colorimetry, the limits of T0 and T1, Fresnel, sky map, ripple maps."""

import math

import numpy as np
import pytest

from oceanrender.optics.fresnel import N_AIR, diffuse_reflectance_Fresnel, reflectance_Fresnel
from oceanrender.optics.report import REPORT_WAVELENGTHS
from oceanrender.optics.seafloor import linear_reflectance
from oceanrender.pipeline import vision_for_scene
from oceanrender.realtime.bake import BakeSettings, water_column
from oceanrender.realtime.luts import (
    K_M,
    Axis,
    Lut,
    VisionState,
    WaterColumn,
    albedo_display_rgb,
    bake_fresnel,
    bake_ripples,
    bake_T0,
    bake_T1,
    direction_to_envmap_uv,
    envmap_directions,
    refract,
    spectra_to_XYZ,
)
from oceanrender.realtime.model import sample_envmap
from tests.tolerances import ROUNDOFF, ROUNDOFF32

from . import SMALL, synthetic_light, synthetic_scene

N = 1.333
#: Φ (VisionState) goes through the vision model, which computes in float32: display
#: colours (T0, T1, Φ itself) carry float32 round-off, compared with ROUNDOFF32.
EPS32 = float(np.finfo(np.float32).eps)
DEPTH = Axis("depth", "h", "m", 65, "rational", scale=2.0)
PATH = Axis("in-water path length", "l", "m", 33, "rational", scale=4.0)


@pytest.fixture(scope="module")
def column():
    return water_column(synthetic_scene(), synthetic_light())


@pytest.fixture(scope="module")
def phi():
    light = synthetic_light()
    return VisionState(vision_for_scene(synthetic_scene()), light.white_XYZ, 2000.0)


def surface_irradiance(column: WaterColumn, R0: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Closed forms at a bottom at depth 0: E_d(0⁻) and E_u(0⁻) with internal reflection [W m⁻² nm⁻¹].

    E_s = E_sun μ_s (1 − F(μ_s)), E_dif = E_sky (1 − r̄_aw) + r̄_wa E_u and E_u = R0 (E_s + E_dif).
    """
    mu_s = math.cos(math.radians(column.sun_zenith))
    S0 = column.sun_irradiance * mu_s * (1 - reflectance_Fresnel(mu_s, N_AIR, N))
    D0 = column.sky_irradiance * (1 - diffuse_reflectance_Fresnel(N_AIR, N))
    rho = diffuse_reflectance_Fresnel(N, N_AIR)
    E_d = (S0 + D0) / (1 - rho * R0)
    return E_d, R0 * E_d


def test_rational_axis_maps_zero_and_infinity_to_the_end_texels():
    assert DEPTH.values[0] == 0.0 and np.isinf(DEPTH.values[-1])
    assert DEPTH.value(0.5) == pytest.approx(2.0)  # x = s at u = 1/2
    np.testing.assert_allclose(DEPTH.coordinate(DEPTH.values), DEPTH.nodes, rtol=0, atol=ROUNDOFF)  # in [0, 1]
    # Hardware texture coordinates hit the texel centres (i + 0.5)/N at the nodes.
    np.testing.assert_allclose(DEPTH.texcoord(DEPTH.values), (np.arange(65) + 0.5) / 65, rtol=0, atol=ROUNDOFF)  # in [0, 1]
    assert Axis.from_description(DEPTH.describe()) == DEPTH
    linear = Axis("cos", "mu", "1", 5, "linear", 0.0, 1.0)
    np.testing.assert_allclose(linear.values, [0, 0.25, 0.5, 0.75, 1.0])
    with pytest.raises(ValueError, match="scale"):
        Axis("depth", "h", "m", 8, "rational", scale=0.0)
    with pytest.raises(ValueError, match="mapping"):
        Axis("depth", "h", "m", 8, "log")


def test_spectra_to_XYZ_of_an_equal_energy_spectrum():
    flat = np.ones_like(REPORT_WAVELENGTHS)  # 1 W m⁻² sr⁻¹ nm⁻¹
    X, Y, Z = spectra_to_XYZ(flat, REPORT_WAVELENGTHS)
    assert Y == pytest.approx(K_M * 106.857, rel=2e-3)  # ∫ȳ dλ = 106.857 nm over 360–830 nm
    assert X / (X + Y + Z) == pytest.approx(1 / 3, abs=1e-3) and Y / (X + Y + Z) == pytest.approx(1 / 3, abs=1e-3)


def test_vision_state_is_linear(phi, rng):
    """Eq. 22 adds display colours: Φ must be linear for a fixed adaptation state."""
    a, b = rng.uniform(0, 3000, (2, 10, 3))
    # float32 inside Φ; random XYZ give display channels near 0: relative to the colours' scale.
    scale = np.abs(phi(a + b)).max()
    np.testing.assert_allclose(phi(a + b), phi(a) + phi(b), rtol=0, atol=ROUNDOFF32 * scale)
    np.testing.assert_allclose(phi(2.5 * a), 2.5 * phi(a), rtol=0, atol=ROUNDOFF32 * 2.5 * np.abs(phi(a)).max())


def test_T0_at_zero_depth_is_the_bottom_under_the_surface_light(column, phi):
    R0 = linear_reflectance(column.wavelengths, (0.25, 0.45))
    _, E_u = surface_irradiance(column, R0)
    expected = phi.spectra(E_u / (np.pi * N**2), column.wavelengths)
    T0 = bake_T0(column, phi, DEPTH, R0)
    np.testing.assert_allclose(T0[0], expected, rtol=ROUNDOFF32)


def test_T0_at_infinite_depth_is_deep_water_whatever_the_bottom(column, phi):
    black = bake_T0(column, phi, DEPTH, 0.0)
    sand = bake_T0(column, phi, DEPTH, 0.4)
    np.testing.assert_array_equal(black[-1], sand[-1])  # exact: the bottom term is × exp(−∞) = 0
    # The bottom's share fades monotonically with depth (clear blue water still shows it at 100 m).
    weights = np.array([0.2126, 0.7152, 0.0722])
    share = (sand - black) @ weights
    assert share[0] > 0.1 and share[-1] == 0.0
    # Never grows, up to a few float32 ulp of the largest texel (the smallest steps are ~1e-4).
    assert np.all(np.diff(share) <= 8 * EPS32 * np.abs(sand).max())
    # ... and at depths beyond any light's reach the texel is the deep value.
    deep = bake_T0(column, phi, Axis("depth", "h", "m", 2, "linear", 1e4, 2e4), 0.4)
    np.testing.assert_allclose(deep[0], sand[-1], rtol=ROUNDOFF32)  # finite vs infinite column; channels > 0


def test_T1_limits(column, phi):
    T1 = bake_T1(column, phi, DEPTH, PATH, 0.3)
    # Zero depth and zero path: a white bottom right under the surface, lit by E_d(0⁻).
    E_d, _ = surface_irradiance(column, np.full_like(column.wavelengths, 0.3))
    np.testing.assert_allclose(T1[0, 0], phi.spectra(E_d / (np.pi * N**2), column.wavelengths), rtol=ROUNDOFF32)
    # Infinite depth (no light reaches the bottom) or infinite path (none comes back): black,
    # exactly (× exp(−∞) = 0, and Φ is linear).
    assert np.all(T1[-1] == 0.0) and np.all(T1[:, -1] == 0.0)
    # T1(h, l) decays with l at every depth.
    Y = T1 @ np.array([0.2126, 0.7152, 0.0722])
    assert np.all(np.diff(Y[:-1], axis=1) < 0)


def test_T1_attenuation_is_exp_minus_c_l_for_grey_water(column, phi):
    flat = np.ones_like(column.wavelengths)
    grey = WaterColumn(column.wavelengths, 0.15 * flat, 0.05 * flat, 0.02 * flat, column.sun_irradiance,
                       column.sky_irradiance, column.sun_zenith, N)
    T1 = bake_T1(grey, phi, DEPTH, PATH)
    l = PATH.values[5]
    # T1 falls by 1e11 down the depth axis: each texel relative to its own brightest channel
    # (float32 inside Φ; a dark texel's small channels carry its round-off, not their own).
    expected = np.exp(-0.2 * l) * T1[:, 0]
    texel = np.abs(expected).max(axis=-1, keepdims=True)
    assert np.all(np.abs(T1[:, 5] - expected) <= ROUNDOFF32 * texel)


def test_T0_and_T1_agree_at_zero_depth_for_a_grey_bottom(column, phi):
    """At h = 0, Eq. 22 must give the bottom itself: T0(0) = R0 T1(0, 0) for a grey R0."""
    T0 = bake_T0(column, phi, DEPTH, 0.35)
    T1 = bake_T1(column, phi, DEPTH, PATH, 0.35)
    np.testing.assert_allclose(T0[0], 0.35 * T1[0, 0], rtol=ROUNDOFF32)


def test_fresnel_lut_ends_and_gamma_channel():
    axis = Axis("cos", "mu", "1", 129, "linear", 0.0, 1.0)
    lut = bake_fresnel(axis, N, 0.7)
    assert lut[-1, 0] == pytest.approx(((N - 1) / (N + 1)) ** 2, rel=ROUNDOFF)  # normal incidence
    assert lut[0, 0] == pytest.approx(1.0)  # grazing
    np.testing.assert_allclose(lut[:, 1], lut[:, 0] ** 0.7, rtol=ROUNDOFF)  # F ≥ 0.02
    assert np.all(np.diff(lut[:, 0]) < 0)


def test_envmap_directions_round_trip_and_bilinear_lookup(rng):
    d = envmap_directions(16, 8)
    u, v = direction_to_envmap_uv(d)
    # Texture coordinates in [0, 1]: scale 1.
    np.testing.assert_allclose(u, (np.arange(16) + 0.5)[None, :] / 16 * np.ones((8, 1)), rtol=0, atol=ROUNDOFF)
    np.testing.assert_allclose(v, (np.arange(8) + 0.5)[:, None] / 8 * np.ones((1, 16)), rtol=0, atol=ROUNDOFF)
    assert d[0, 0, 2] > 0.98 and d[-1, 0, 2] < -0.98  # row 0 is the zenith
    np.testing.assert_allclose(d[4, 4], [math.sin(np.pi * 4.5 / 8) * math.sin(2 * np.pi * 4.5 / 16),
                                         math.sin(np.pi * 4.5 / 8) * math.cos(2 * np.pi * 4.5 / 16),
                                         math.cos(np.pi * 4.5 / 8)], rtol=0, atol=ROUNDOFF)  # unit vector
    data = rng.uniform(0, 1, (8, 16, 3)).astype(np.float32)
    lut = Lut("sky", data, ("R", "G", "B"), None, None, "test")
    # Texel centres return the texels (float64 bilinear weights 1 and 0 up to round-off; texels
    # are uniform in [0, 1), some near 0: relative to the texels' scale).
    np.testing.assert_allclose(sample_envmap(lut, d), data, rtol=0, atol=ROUNDOFF * np.abs(data).max())
    # Across the azimuth seam (u = 0 = 1) the lookup wraps: halfway between the last and the first column.
    seam = np.array([0.0, 1.0, 0.0]) * math.sin(np.pi * 4.5 / 8) + np.array([0, 0, math.cos(np.pi * 4.5 / 8)])
    halfway = 0.5 * (data[4, 0].astype(np.float64) + data[4, -1])  # in float64, as the lookup
    np.testing.assert_allclose(sample_envmap(lut, seam), halfway, rtol=0, atol=ROUNDOFF * np.abs(data).max())


def test_refraction_through_a_tilted_facet_matches_snell():
    for tilt in np.radians([0.0, 5.0, 20.0, 40.0]):
        n = np.array([math.sin(tilt), 0.0, math.cos(tilt)])
        t = refract(np.array([0.0, 0.0, -1.0]), n, 1 / N)
        theta_t = math.asin(math.sin(tilt) / N)
        # The ray bends towards the inward normal, −tan(θi − θt) off the vertical per unit depth.
        assert t[0] / abs(t[2]) == pytest.approx(-math.tan(tilt - theta_t), abs=ROUNDOFF)  # a slope, scale 1
        assert np.linalg.norm(t) == pytest.approx(1.0)
    assert np.all(np.isnan(refract(np.array([math.sin(1.2), 0, -math.cos(1.2)]), np.array([0, 0, -1.0]), N)))


def test_ripple_maps_are_tileable_and_carry_the_spectrum_slopes():
    from oceanrender.waves.sea import directional_spectrum

    scene = synthetic_scene(ocean={"wind_speed": 4.0, "wind_direction": -90.0, "fetch": 20000.0})
    maps = bake_ripples(directional_spectrum(scene.ocean), 1.0, 64, k_min=np.pi / 0.125, n_water=N, seed=3)
    assert maps.normals.shape == (64, 64, 3) and maps.offsets.shape == (64, 64, 2)
    np.testing.assert_allclose(np.linalg.norm(maps.normals, axis=-1), 1.0, rtol=ROUNDOFF)
    assert maps.mean_square_slope == pytest.approx(maps.expected_mean_square_slope, rel=0.25)
    # Seamless: the jump across the tile edge is like any jump between neighbouring texels.
    inside = np.mean(np.abs(np.diff(maps.normals[..., 0], axis=1)))
    seam = np.mean(np.abs(maps.normals[:, 0, 0] - maps.normals[:, -1, 0]))
    assert 0.5 * inside < seam < 2.0 * inside
    # A ripple that tilts the normal towards +x moves the seafloor image towards −x.
    assert np.corrcoef(maps.normals[..., 0].ravel(), maps.offsets[..., 0].ravel())[0, 1] < -0.99


def test_albedo_rgb_is_one_for_white_and_the_albedo_for_grey(column, phi):
    E = column.horizontal_irradiance
    np.testing.assert_allclose(albedo_display_rgb(np.ones_like(E), E, column.wavelengths, phi), 1.0, rtol=1e-6)
    np.testing.assert_allclose(albedo_display_rgb(np.full_like(E, 0.3), E, column.wavelengths, phi), 0.3, rtol=1e-6)
    sand = albedo_display_rgb(linear_reflectance(column.wavelengths, (0.25, 0.45)), E, column.wavelengths, phi)
    assert sand[0] > sand[1] > sand[2]  # reddish sand: more reflectance at long wavelengths


def test_bake_settings_are_validated():
    with pytest.raises(ValueError, match="ripple_texels"):
        BakeSettings(ripple_texels=33)
    with pytest.raises(ValueError, match="gamma"):
        BakeSettings(gamma=0.0)
    assert SMALL.describe()["depth_scale_m"] == 2.0
