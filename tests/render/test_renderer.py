"""Real Mitsuba renders at tiny sizes: film units, adapting white, per-frame updates."""

import math

import colour
import numpy as np
import pytest

from oceanrender.render.renderer import K_M, adapting_white_XYZ, repair_non_finite
from oceanrender.render.scene import CIE1931, perspective_sensor, sun_direction, sunsky_emitter, xyz_film
from tests.scenes import scene_from_dict
from oceanrender.vision.model import VisionModel
from tests.render.constant_sky import cmf_integrals, constant_sky_scene
from tests.tolerances import ROUNDOFF

pytestmark = pytest.mark.render


def test_sun_direction_convention():
    # Unit vectors (scale 1); cos 90° is 6e-17, not 0.
    np.testing.assert_allclose(sun_direction(90, 0), [0, 0, 1], atol=ROUNDOFF)
    np.testing.assert_allclose(sun_direction(0, 0), [0, 1, 0], atol=ROUNDOFF)  # north = +y
    np.testing.assert_allclose(sun_direction(0, 90), [1, 0, 0], atol=ROUNDOFF)  # east = +x
    assert np.linalg.norm(sun_direction(33, 123)) == pytest.approx(1)


def test_film_integrates_radiance_against_the_cmfs(variant):
    # A constant environment of spectral radiance 1 W m⁻² sr⁻¹ nm⁻¹ must give
    # X, Y, Z = ∫x̄ dλ, ∫ȳ dλ, ∫z̄ dλ ≈ 106.86 over 360-830 nm (exact XYZ, not RGB-derived).
    import mitsuba as mi

    scene = constant_sky_scene(32, 32, 64)
    film = np.array(mi.render(scene, seed=3))
    measured = film.reshape(-1, 3).mean(axis=0)
    # 65 536 spectral samples per channel: Monte Carlo error ≲ 0.5 %.
    np.testing.assert_allclose(measured, cmf_integrals(), rtol=0.01)


def test_adapting_white_is_daylight(variant):
    scene = scene_from_dict({"name": "t", "sun": {"elevation": 40.0}})
    white = adapting_white_XYZ(scene, spp=512)
    # Horizontal illuminance under a clear sky with the sun at 40°: roughly 50-100 klx.
    illuminance = math.pi * white[1]
    assert 4.0e4 < illuminance < 1.2e5
    # Its chromaticity lies within 0.01 in uv of the CIE daylight locus (CCT 4500-7500 K).
    cct = colour.xy_to_CCT(colour.XYZ_to_xy(white), method="Hernandez 1999")
    assert 4500 < cct < 7500
    daylight_xy = colour.temperature.CCT_to_xy_CIE_D(cct)
    uv = colour.xy_to_Luv_uv(colour.XYZ_to_xy(white))
    assert np.linalg.norm(uv - colour.xy_to_Luv_uv(daylight_xy)) < 0.01


def test_white_lambertian_under_the_adapting_illuminant_maps_to_display_white(variant):
    import mitsuba as mi

    settings = scene_from_dict({"name": "t", "sun": {"elevation": 35.0, "turbidity": 4.0}})
    white = adapting_white_XYZ(settings, spp=2048)
    camera = settings.camera.model_copy(update={"position": (0.0, 0.0, 2.0), "target": (0.0, 0.5, 0.0), "fov": 30.0})
    scene = mi.load_dict({
        "type": "scene",
        "integrator": {"type": "path", "max_depth": 2},
        "sensor": perspective_sensor(camera, xyz_film(16, 16), spp=256),
        "sky": sunsky_emitter(settings.sun),
        "ground": {"type": "disk", "to_world": mi.ScalarTransform4f().scale([1e4, 1e4, 1]),
                   "bsdf": {"type": "diffuse", "reflectance": {"type": "spectrum", "value": 1.0}}},
    })
    xyz = K_M * np.array(mi.render(scene, seed=1)).reshape(-1, 3).mean(axis=0)
    np.testing.assert_allclose(xyz, white, rtol=0.03)  # the same white, seen by a camera
    rgb = VisionModel().apply(xyz, white, adaptation_luminance=white[1])
    assert rgb.min() > 0
    np.testing.assert_allclose(rgb / rgb.mean(), 1.0, atol=0.02)  # neutral: R = G = B


def test_nan_pixels_are_repaired_from_neighbours():
    image = np.ones((5, 5, 3))
    image[2, 2] = np.nan
    image[0, 0, 1] = np.inf
    fixed, count = repair_non_finite(image)
    assert count == 2
    assert np.all(np.isfinite(fixed))
    np.testing.assert_allclose(fixed, 1.0)


def test_foam_layer_reflects_fresh_foam_on_its_fraction(variant):
    # A horizontal quad under a constant sky of radiance 1 W m⁻² sr⁻¹ nm⁻¹, seen from above: a Lambertian
    # layer of reflectance R(λ) returns R(λ) (one bounce, nothing occludes the sky). With vertex_foam = w
    # over a grey stand-in for the water (0.1), Y/∫ȳ is (1 − w) 0.1 + w ⟨R⟩_ȳ, R = 0.55 × Frouin's factor.
    import mitsuba as mi

    from oceanrender.optics.foam import foam_spectral_factor_Frouin1996
    from oceanrender.render.buffers import jit_floats
    from oceanrender.render.renderer import FOAM_ATTRIBUTE, foamy_surface_bsdf

    cmfs = colour.MSDS_CMFS[CIE1931].copy().trim(colour.SpectralShape(360, 830, 1))
    ybar = cmfs.values[:, 1]
    foam_y = float(np.sum(ybar * 0.55 * foam_spectral_factor_Frouin1996(cmfs.wavelengths)) / ybar.sum())
    stand_in = {"type": "diffuse", "reflectance": {"type": "spectrum", "value": 0.1}}
    for weight in (0.0, 0.4, 1.0):
        props = mi.Properties()
        props["bsdf"] = mi.load_dict(foamy_surface_bsdf(stand_in, 0.55))
        mesh = mi.Mesh("quad", 4, 2, props)
        mesh.add_attribute(FOAM_ATTRIBUTE, 1, jit_floats(np.full(4, weight)))
        params = mi.traverse(mesh)
        params["vertex_positions"] = jit_floats([[-50, -50, 0], [50, -50, 0], [50, 50, 0], [-50, 50, 0]])
        params["faces"] = mi.UInt32([0, 1, 2, 0, 2, 3])
        params.update()
        scene = mi.load_dict({
            "type": "scene",
            "integrator": {"type": "path", "max_depth": 2},
            "sensor": {"type": "perspective", "fov": 20.0,
                       "to_world": mi.ScalarTransform4f().look_at(origin=[0, 0, 5], target=[0, 0, 0], up=[0, 1, 0]),
                       "film": xyz_film(16, 16), "sampler": {"type": "independent", "sample_count": 256}},
            "environment": {"type": "constant", "radiance": {"type": "spectrum", "value": 1.0}},
            "quad": mesh,
        })
        y = np.array(mi.render(scene, seed=1))[..., 1].mean() / cmf_integrals()[1]
        # 65 536 samples of a cosine-weighted bounce and the spectral sampling: ≲ 1 % Monte Carlo error
        assert y == pytest.approx((1 - weight) * 0.1 + weight * foam_y, rel=0.02)
    assert 0.5 < foam_y < 0.55  # flat in the visible, falling beyond 555 nm


@pytest.mark.parametrize("pixels, spp", [(16384**2, 64), (1280 * 720, 4096), (8 * 6, 1), (4096**2, 1000)])
def test_sample_passes_stay_within_32_bit_sample_indices(pixels, spp):
    from oceanrender.render.renderer import MAX_SAMPLES_PER_PASS, sample_passes

    passes = sample_passes(pixels, spp, seed=2**32 - 1)
    assert sum(size for size, _ in passes) == spp
    assert all(size * pixels <= MAX_SAMPLES_PER_PASS or size == 1 for size, _ in passes)
    assert max(size for size, _ in passes) - min(size for size, _ in passes) <= 1  # even passes
    seeds = [seed for _, seed in passes]
    assert seeds[0] == 2**32 - 1 and len(set(seeds)) == len(seeds) and all(0 <= s < 2**32 for s in seeds)
    if pixels * spp <= MAX_SAMPLES_PER_PASS:
        assert passes == [(spp, 2**32 - 1)]  # a frame that fits renders in one pass, as before


WHITE_IN_A_PROCESS = """
from oceanrender.runtime.variants import activate_variant
activate_variant("llvm_ad_spectral")
from oceanrender.scene import scene_from_dict
from oceanrender.render.renderer import adapting_white_XYZ
print([x.hex() for x in adapting_white_XYZ(scene_from_dict({"name": "w"}), 16384).tolist()])
"""


def test_the_white_meter_reads_the_same_in_every_process(variant):
    """Three processes at once, the same scene and seed: identical adapting whites, bit for bit.

    A 1-pixel meter differed here (drjit sums a pixel's samples in the order its threads finish);
    a resumed sequence must colour its frames exactly as an uninterrupted one.
    """
    import subprocess
    import sys

    procs = [subprocess.Popen([sys.executable, "-c", WHITE_IN_A_PROCESS], stdout=subprocess.PIPE, text=True)
             for _ in range(3)]
    readings = [proc.communicate(timeout=300)[0].strip().splitlines()[-1] for proc in procs]
    assert all(proc.returncode == 0 for proc in procs)
    assert len(set(readings)) == 1, readings
