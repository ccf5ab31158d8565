"""Writing a camera pose and a sun into a loaded Mitsuba scene (``render/scene.py``),
tested against scenes built at that pose."""

import numpy as np
import pytest

from oceanrender.scene.motion import CameraKey, CameraPath, SunAngles, SunKey, SunPath
from tests.tolerances import ROUNDOFF32

# --- writing poses into loaded Mitsuba scenes ------------------------------------------------

def flat_sea():
    s = 1.0e4
    positions = np.array([[-s, -s, 0], [s, -s, 0], [s, s, 0], [-s, s, 0]], np.float32)
    normals = np.tile(np.array([0, 0, 1], np.float32), (4, 1))
    from oceanrender.surface.frame import FrameGeometry

    return np.array([[0, 1, 2], [0, 2, 3]], np.uint32), FrameGeometry(positions, normals, None)


@pytest.mark.render
def test_apply_camera_equals_a_scene_built_at_that_pose(variant):
    from oceanrender.render.denoise import FeatureRenderer
    from oceanrender.render.scene import apply_camera
    from tests.scenes import scene_from_dict

    scene = scene_from_dict({"name": "t", "camera": {"position": [0, 0, 1], "target": [0, 100, 1], "fov": 40}})
    faces, geometry = flat_sea()
    moving = FeatureRenderer.build(scene, faces, geometry, resolution=(24, 16), spp=4, water_albedo=0.5)
    path = CameraPath((CameraKey(0, (0, 0, 1), (0, 100, 1), 40), CameraKey(2, (5, 0, 10), (0, 30, -20), 70)))
    pose = path.at(1.3)
    apply_camera(moving.params, pose)
    fixed_camera = scene.camera.model_copy(update={"position": tuple(pose.position), "target": tuple(pose.target),
                                                   "fov": pose.fov})
    fresh = FeatureRenderer.build(scene, faces, geometry, resolution=(24, 16), spp=4, water_albedo=0.5,
                                  camera=fixed_camera)
    a, b = moving.render(seed=5), fresh.render(seed=5)
    # float32 AOVs (unit normals, albedo ≤ 1: scale 1); the two camera transforms are built
    # by different code, so the rays may differ in their last bits.
    np.testing.assert_allclose(a.normal, b.normal, atol=ROUNDOFF32)
    np.testing.assert_allclose(a.albedo, b.albedo, atol=ROUNDOFF32)
    assert (a.albedo.sum(-1) > 0).mean() > 0.6  # looking down now: mostly sea


@pytest.mark.render
def test_apply_sun_equals_a_scene_built_with_that_sun(variant):
    import mitsuba as mi

    from oceanrender.render.scene import apply_sun, sunsky_emitter, xyz_film
    from tests.scenes import scene_from_dict

    def white_plane(sun):
        return mi.load_dict({
            "type": "scene",
            "integrator": {"type": "path", "max_depth": 2},
            "sensor": {"type": "radiancemeter", "origin": [0, 0, 1], "direction": [0, 0, -1],
                       "film": {**xyz_film(1, 1), "rfilter": {"type": "box"}},
                       "sampler": {"type": "independent", "sample_count": 256}},
            "sky": sunsky_emitter(sun),
            "ground": {"type": "disk", "to_world": mi.ScalarTransform4f().scale([1e4, 1e4, 1]),
                       "bsdf": {"type": "diffuse", "reflectance": {"type": "spectrum", "value": 1.0}}},
        })

    high = scene_from_dict({"name": "t", "sun": {"elevation": 70.0, "azimuth": 100.0}}).sun
    low = high.model_copy(update={"elevation": 15.0, "azimuth": 250.0})
    scene = white_plane(high)
    before = np.array(mi.render(scene, seed=1)).ravel()
    params = mi.traverse(scene)
    apply_sun(params, SunPath((SunKey(0, 70, 100), SunKey(1, 15, 250))).at(1.0))
    after = np.array(mi.render(scene, seed=1)).ravel()
    fresh = np.array(mi.render(white_plane(low), seed=1)).ravel()
    np.testing.assert_allclose(after, fresh, rtol=0.03)
    assert after[1] < 0.6 * before[1]  # a low sun lights the plane less (cosine law)
    with pytest.raises(ValueError, match="above the horizon"):
        apply_sun(params, SunAngles(-1.0, 0.0))
