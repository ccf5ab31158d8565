"""The CPU real-time model: Eq. 20 exactly, Eq. 22, the Fresnel LUT, the sun glint, land and sky pixels."""

import math

import numpy as np
import pytest

from oceanrender.optics.fresnel import N_AIR, reflectance_Fresnel
from oceanrender.realtime.bake import BakeSettings
from oceanrender.realtime.gbuffer import KIND_LAND, KIND_SKY, KIND_WATER, GBuffer
from oceanrender.realtime.model import (
    distribution_Beckmann,
    realtime_terms,
    render_realtime,
    sample_envmap,
    sample_lut_1d,
    sample_lut_2d,
    sun_glint,
)
from tests.tolerances import ROUNDOFF

from . import SMALL, synthetic_light, synthetic_lut_set

N = 1.333


def gbuffer(rng, kind, depth=np.inf, path=np.inf, rock=0.0, shape=(4, 6)):
    """A G-buffer of random downward views onto slightly tilted surfaces."""
    ray = np.stack([rng.uniform(-0.5, 0.5, shape), rng.uniform(0.2, 1.0, shape), rng.uniform(-1.0, -0.15, shape)], -1)
    ray /= np.linalg.norm(ray, axis=-1, keepdims=True)
    normal = np.stack([rng.uniform(-0.2, 0.2, shape), rng.uniform(-0.2, 0.2, shape), np.ones(shape)], -1)
    normal /= np.linalg.norm(normal, axis=-1, keepdims=True)
    full = lambda v: np.broadcast_to(np.asarray(v, dtype=np.float64), shape).copy()  # noqa: E731
    zeros3 = np.zeros(shape + (3,))
    return GBuffer(kind=full(kind).astype(np.uint8), ray=ray, position=zeros3, normal=normal, geo_normal=normal,
                   distance=full(10.0), cos_view=np.clip(np.sum(normal * -ray, -1), 0, 1), depth=full(depth),
                   path_length=full(path), refracted=zeros3, bottom_position=zeros3, rock=full(rock))


@pytest.fixture(scope="module")
def open_sea():
    """An open-sea LUT set (no seafloor) whose sky has the same radiance in every direction."""
    sky = 0.05 * np.ones(95)
    return synthetic_lut_set(coastal=False, light=synthetic_light(constant_sky=sky))


@pytest.fixture(scope="module")
def coastal():
    return synthetic_lut_set()


@pytest.mark.parametrize("gamma", [1.0, 0.6])
def test_open_sea_with_exact_fresnel_is_eq_20(open_sea, rng, gamma):
    g = gbuffer(rng, KIND_WATER)
    rgb = render_realtime(g, open_sea, gamma=gamma, fresnel="exact", glint=False, masking=False)
    F = reflectance_Fresnel(g.cos_view, N_AIR, N) ** gamma
    sky = open_sea["sky"].data[0, 0].astype(np.float64)  # every texel holds the same colour
    deep = open_sea["T0"].data[0, -1].astype(np.float64)  # T0(h = ∞), the last texel
    expected = sky * F[..., None] + deep * (1 - F[..., None])  # Eq. 20
    np.testing.assert_allclose(rgb, expected, rtol=ROUNDOFF)  # colours > 0
    # Exact: one spectrum through the same code for every texel, stored in float32.
    assert np.all(open_sea["sky"].data == open_sea["sky"].data[0, 0])


def test_fresnel_lut_interpolates_the_exact_reflectance_closely():
    luts = synthetic_lut_set(BakeSettings(depth_texels=3, path_texels=3, fresnel_texels=256, sky_size=(8, 4),
                                          ripple_texels=8, ripple_patch=1.0))
    mu = np.linspace(0.0, 1.0, 10001)
    error = np.abs(sample_lut_1d(luts["fresnel"], mu)[..., 0] - reflectance_Fresnel(mu, N_AIR, N))
    assert error.max() < 3e-4
    # At the nodes the float64 weights are 1 and 0 up to round-off; reflectance, scale 1.
    np.testing.assert_allclose(sample_lut_1d(luts["fresnel"], luts["fresnel"].columns.values)[..., 0],
                               luts["fresnel"].data[0, :, 0], rtol=0, atol=ROUNDOFF)


def test_coastal_water_is_eq_22(coastal, rng):
    h, l = 0.6, 0.9
    sand = gbuffer(rng, KIND_WATER, depth=h, path=l, rock=0.0)
    rock = gbuffer(rng, KIND_WATER, depth=h, path=l, rock=1.0)
    a, b = realtime_terms(sand, coastal, masking=False), realtime_terms(rock, coastal, masking=False)
    T0 = sample_lut_1d(coastal["T0"], h)
    T1 = sample_lut_2d(coastal["T1"], l, h)
    R0 = coastal.rgb("reference_albedo_rgb")
    expected = T0 + T1 * (coastal.rgb("sand_albedo_rgb") - R0)  # Eq. 22
    np.testing.assert_allclose(a.C_water, np.broadcast_to(expected, a.C_water.shape), rtol=ROUNDOFF)
    # A difference of two colours (cancellation): round-off relative to the colours' scale.
    np.testing.assert_allclose(b.C_water - a.C_water,
                               np.broadcast_to(T1 * (coastal.rgb("rock_albedo_rgb") - coastal.rgb("sand_albedo_rgb")),
                                               a.C_water.shape), rtol=0, atol=ROUNDOFF * np.abs(a.C_water).max())
    # A refracted ray that never meets the seafloor sees the water column only.
    lost = realtime_terms(gbuffer(rng, KIND_WATER, depth=h, path=np.inf), coastal, masking=False)
    np.testing.assert_allclose(lost.C_water, np.broadcast_to(T0, lost.C_water.shape), rtol=ROUNDOFF)
    # Sand in thin water is brighter than sand under deep water, and rock darker than sand.
    deep = realtime_terms(gbuffer(rng, KIND_WATER, depth=5.0, path=7.0), coastal, masking=False)
    assert np.all(a.C_water.sum(-1) > deep.C_water.sum(-1)) and np.all(b.C_water.sum(-1) < a.C_water.sum(-1))


def test_land_and_sky_pixels(coastal, rng):
    g = gbuffer(rng, KIND_LAND, rock=0.0)
    flat = GBuffer(**{**g.__dict__, "normal": np.broadcast_to([0.0, 0.0, 1.0], g.normal.shape).copy()})
    rgb = render_realtime(flat, coastal)
    sun_z = coastal.constants["sun_direction"][2]
    expected = coastal.rgb("sand_albedo_rgb") * (coastal.rgb("sun_irradiance_rgb") * sun_z
                                                 + coastal.rgb("sky_irradiance_rgb"))
    np.testing.assert_allclose(rgb, np.broadcast_to(expected, rgb.shape), rtol=ROUNDOFF)
    sky = gbuffer(rng, KIND_SKY)
    np.testing.assert_allclose(render_realtime(sky, coastal), sample_envmap(coastal["sky"], sky.ray), rtol=ROUNDOFF)


def test_reflections_below_the_horizon_see_the_horizon_sky(coastal, rng):
    g = gbuffer(rng, KIND_WATER)
    ray = np.broadcast_to(np.array([0.0, np.cos(0.05), -np.sin(0.05)]), g.ray.shape).copy()  # 3° down
    normal = np.broadcast_to(np.array([0.0, 0.03, 1.0]) / np.hypot(0.03, 1.0), g.ray.shape).copy()  # tilted away
    steep = GBuffer(**{**g.__dict__, "ray": ray, "normal": normal, "cos_view": np.sum(normal * -ray, -1)})
    mirror = ray + 2 * steep.cos_view[..., None] * normal
    assert np.all(steep.cos_view > 0) and np.all(mirror[..., 2] < 0)  # seen from the front, mirrored into the sea
    T_refl = realtime_terms(steep, coastal, masking=False).T_refl
    assert np.all(T_refl.sum(-1) > 0)
    horizon = mirror.copy()
    horizon[..., 2] = 1e-3
    horizon /= np.linalg.norm(horizon, axis=-1, keepdims=True)
    # The test's horizon direction and the model's differ in the last bits; sky colours > 0.
    np.testing.assert_allclose(T_refl, sample_envmap(coastal["sky"], horizon), rtol=ROUNDOFF)


def test_beckmann_distribution_is_normalised():
    theta = np.linspace(0.0, math.pi / 2, 20001)
    for alpha in (0.05, 0.2, 0.5):
        integral = np.trapezoid(distribution_Beckmann(np.cos(theta), alpha) * np.cos(theta) * np.sin(theta), theta)
        assert 2 * math.pi * integral == pytest.approx(1.0, rel=1e-4)


def test_sun_glint_reflects_the_fresnel_share_of_the_sun():
    """Sun at the zenith over a level, slightly rough surface: ∫ L cos θ_v dω_v = F(0) E_sun."""
    theta = np.linspace(0.0, math.pi / 2, 4001)[1:]
    phi = 0.0  # isotropic: one azimuth suffices
    view = np.stack([np.sin(theta) * math.cos(phi), np.sin(theta) * math.sin(phi), np.cos(theta)], -1)
    normal = np.broadcast_to([0.0, 0.0, 1.0], view.shape)
    E_sun = np.ones(3) / math.pi  # so that π · sun_rgb = 1
    L = sun_glint(normal, view, np.array([0.0, 0.0, 1.0]), 0.1, N, E_sun)[..., 0]
    flux = 2 * math.pi * np.trapezoid(L * np.cos(theta) * np.sin(theta), theta)
    assert flux == pytest.approx(reflectance_Fresnel(1.0, N_AIR, N), rel=0.02)
    # No glint when the sun is below the mean surface.
    assert np.all(sun_glint(normal, view, np.array([0.0, 0.6, -0.8]), 0.1, N, E_sun) == 0)  # exact: switched off


def test_unknown_fresnel_source_is_refused(coastal, rng):
    with pytest.raises(ValueError, match="fresnel"):
        realtime_terms(gbuffer(rng, KIND_WATER), coastal, fresnel="table")


def test_small_settings_are_small():
    assert SMALL.depth_texels < 64  # keeps these tests fast


def test_foam_blends_lambertian_foam_over_the_water(coastal, rng):
    """B = 0: the water alone; B = 1: fresh foam's albedo under sun and sky; between: the linear blend
    the renderer's blendbsdf makes (Koepke 1984's coverage model)."""
    from dataclasses import replace

    from oceanrender.realtime.model import diffuse_light

    g = gbuffer(rng, KIND_WATER, depth=0.6, path=0.9)
    water = render_realtime(g, coastal)
    foam_rgb = coastal.rgb("foam_albedo_rgb")
    assert np.all((foam_rgb > 0.45) & (foam_rgb < 0.6))  # fresh foam: 0.55 in the visible, less towards the red
    light = diffuse_light(g.normal.reshape(-1, 3), coastal).reshape(g.normal.shape)
    for B in (0.0, 0.3, 1.0):
        foamy = render_realtime(replace(g, foam=np.full(g.shape, B)), coastal)
        np.testing.assert_allclose(foamy, (1 - B) * water + B * foam_rgb * light, rtol=ROUNDOFF)
    # Land and sky pixels ignore a foam value.
    sky = gbuffer(rng, KIND_SKY)
    np.testing.assert_array_equal(render_realtime(replace(sky, foam=np.ones(sky.shape)), coastal),
                                  render_realtime(sky, coastal))


def test_masking_weights_eq_20_by_smiths_g1_of_the_view(coastal, rng):
    """With masking, the water's Eq. 20 terms are G₁(n·v; α) times those without (Walter et al. 2007, Eq. 27):
    ≈ 1 at steep views, well below 1 at grazing ones."""
    from oceanrender.realtime.model import masking_Smith_Beckmann

    g = gbuffer(rng, KIND_WATER, depth=0.6, path=0.9)
    alpha = coastal.constants["surface_roughness_alpha"]
    with_, without = realtime_terms(g, coastal), realtime_terms(g, coastal, masking=False)
    G = masking_Smith_Beckmann(g.cos_view, alpha)[..., None]
    np.testing.assert_allclose(with_.T_refl, G * without.T_refl, rtol=ROUNDOFF)
    np.testing.assert_allclose(with_.C_water, G * without.C_water, rtol=ROUNDOFF)
    np.testing.assert_array_equal(with_.glint, without.glint)  # the glint has its own G₁(v) G₁(s)
    # Walter et al.'s rational G₁ at a = cot θ / α: 1 for a ≥ 1.6; 0.38 at a = 0.134 (88°, α = 0.26).
    assert masking_Smith_Beckmann(np.cos(np.radians(60.0)), 0.2) == 1.0
    a = 1.0 / (0.26 * np.tan(np.radians(88.0)))
    expected = (3.535 * a + 2.181 * a**2) / (1 + 2.276 * a + 2.577 * a**2)
    assert expected == pytest.approx(0.3802, abs=1e-4)
    assert masking_Smith_Beckmann(np.cos(np.radians(88.0)), 0.26) == pytest.approx(expected, rel=ROUNDOFF)
