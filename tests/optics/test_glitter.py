"""Sun glitter (oceanrender.optics.glitter): Cox & Munk's relation, its inversion, and renders of the
glitter scene whose glitter width follows the sea's total slope variance."""

import math
from pathlib import Path

import numpy as np
import pytest

from oceanrender.optics.glitter import fit_slope_variance, glitter_geometry, glitter_radiance_CoxMunk1954
from oceanrender.render.scene import sun_direction
from tests.tolerances import ROUNDOFF

ROOT = Path(__file__).resolve().parents[2]


def pixel_directions(position, target, fov_deg, width, height):
    """Unit directions of the pixel centres' rays of a pinhole camera, horizontal fov, z up (row 0 on top)."""
    forward = np.subtract(target, position).astype(float)
    forward /= np.linalg.norm(forward)
    right = np.cross(forward, [0.0, 0.0, 1.0])
    right /= np.linalg.norm(right)
    up = np.cross(right, forward)
    half = math.tan(math.radians(fov_deg) / 2)
    x = ((np.arange(width) + 0.5) / width * 2 - 1) * half
    y = (1 - (np.arange(height) + 0.5) / height * 2) * half * height / width
    d = forward + x[None, :, None] * right + y[:, None, None] * up
    return d / np.linalg.norm(d, axis=-1, keepdims=True)


def test_mirror_facet_is_flat_for_the_specular_direction():
    sun = sun_direction(20.0, 0.0)
    mirror = np.array([-sun[0], -sun[1], sun[2]])  # the camera sees the sun's mirror image: o = reflect(s)
    tan2, cos_o, cos_i = glitter_geometry(mirror[None], sun)
    np.testing.assert_allclose(tan2, 0.0, atol=ROUNDOFF)
    np.testing.assert_allclose(cos_i, sun[2], rtol=ROUNDOFF)


def test_radiance_integrates_to_the_reflected_irradiance_of_a_flat_sea():
    """∫ L cos θ_o dΩ_o over the upper hemisphere → ρ E_sun cos θ_s as σ² → 0 (all the sun mirrored)."""
    sun = sun_direction(50.0, 0.0)
    theta = np.linspace(0, np.pi / 2, 1500)[1:]
    phi = np.linspace(0, 2 * np.pi, 1501)[:-1]
    t, p = np.meshgrid(theta, phi, indexing="ij")
    o = np.stack([np.sin(t) * np.cos(p), np.sin(t) * np.sin(p), np.cos(t)], axis=-1)
    L = glitter_radiance_CoxMunk1954(o, sun, 1e-3)
    flux = np.sum(L * np.cos(t) * np.sin(t)) * (theta[1] - theta[0]) * (phi[1] - phi[0])
    from oceanrender.optics.fresnel import reflectance_Fresnel
    expected = reflectance_Fresnel(sun[2], 1.0, 1.333) * sun[2]
    # narrow lobe (σ = 0.03) on a 0.06° grid: quadrature error < 1 %
    assert flux == pytest.approx(expected, rel=0.01)


@pytest.mark.parametrize("mss", [0.02, 0.05, 0.08])
def test_fit_recovers_the_slope_variance_of_cox_munk_radiance(mss):
    d = pixel_directions([0, 0, 6.0], [0, 100, -6.3], 60.0, 160, 90)
    down = d[..., 2] < 0
    o = -d[down]
    L = glitter_radiance_CoxMunk1954(o, sun_direction(12.0, 0.0), mss)
    # exact model, finite bins: the binned least-squares fit is within 2 %
    assert fit_slope_variance(L, o, sun_direction(12.0, 0.0)) == pytest.approx(mss, rel=0.02)


@pytest.mark.slow
@pytest.mark.render
def test_glitter_width_follows_the_total_slope_variance(variant):
    """The glitter scene, sun only (sky_scale 0) so the water's radiance is the sun's glitter (plus a
    little sunlight scattered in the water): the slope variance fitted to it by Cox & Munk's relation
    equals the sea's total slope variance (resolved waves + per-vertex roughness) within 25 %, and it
    widens from 4 to 12 m/s wind."""
    from oceanrender.pipeline import Sequence
    from oceanrender.scene import load_scene, with_overrides

    base = load_scene(ROOT / "scenes" / "glitter_low_sun.toml")
    width, height = 96, 54
    fitted, totals = [], []
    for wind in (4.0, 12.0):
        scene = with_overrides(base, ocean={"wind_speed": wind, "resolution": 256, "patch_size": 600.0,
                                            "cascades": 3},
                               foam={"enabled": False}, sun={"sky_scale": 0.0}, render={"white_spp": 64})
        sequence = Sequence(scene, variant, spp=32, resolution=(width, height))
        xyz, _ = sequence.renderer.render_xyz(spp=32, seed=1)
        d = pixel_directions(scene.camera.position, scene.camera.target, scene.camera.fov, width, height)
        water = d[..., 2] < -0.02  # rows clearly below the horizon
        sun = sun_direction(scene.sun.elevation, scene.sun.azimuth)
        fitted.append(fit_slope_variance(xyz[..., 1][water], -d[water], sun))
        totals.append(sequence.body.total_slope_variance(0.0))
    # 25 %: the render adds in-water scattered sunlight under the glitter's wings, its resolved slopes
    # are those of one realisation, and masking-shadowing (G < 1) trims the wings at grazing angles.
    for f, t in zip(fitted, totals):
        assert f == pytest.approx(t, rel=0.25)
    assert fitted[1] > 1.5 * fitted[0]  # Elfouhaily: σ² 0.025 → 0.069 from 4 to 12 m/s
