"""Camera and G-buffer by ray casting into the rendered scene (tiny coastal scene, real Mitsuba)."""

import numpy as np
import pytest

from oceanrender.coastal.simulation import run_simulation
from oceanrender.realtime.gbuffer import KIND_WATER, camera_for_scene
from oceanrender.realtime.reference import ReferenceRenderer
from tests.tolerances import ROUNDOFF

from . import synthetic_scene

pytestmark = pytest.mark.render

N = 1.333
#: Mitsuba's rays are float32: a few ulp per transform (ε32 relative to the coordinates' scale).
EPS32 = float(np.finfo(np.float32).eps)
VIEW = {"output": {"frames": [0, 3], "fps": 10.0, "resolution": [24, 16], "spp": 2},
        "render": {"white_spp": 64, "max_depth": 4, "integrator": "volpath"},
        "camera": {"position": [0.0, -1.0, 3.0], "target": [0.0, 2.5, 0.0], "fov": 60.0}}


def bed(coastal, y):
    """The plane beach z_b(y) of the tiny scene [m]."""
    return np.maximum(coastal.still_level - coastal.slope * (y - coastal.shoreline_y),
                      coastal.still_level - coastal.offshore_depth)


@pytest.fixture(scope="module")
def renderer(variant, tmp_path_factory):
    scene = synthetic_scene(**VIEW)
    store = tmp_path_factory.mktemp("store")
    run_simulation(scene, store)
    return ReferenceRenderer(scene, variant, coastal_store=store)


def test_camera_rays_are_mitsubas(renderer):
    import mitsuba as mi

    camera = renderer.camera
    j, i = np.mgrid[0:camera.height, 0:camera.width]
    sensor = renderer.sequence.renderer.scene.sensors()[0]
    uv = mi.Point2f(mi.Float(((i + 0.5) / camera.width).ravel()), mi.Float(((j + 0.5) / camera.height).ravel()))
    ray, _ = sensor.sample_ray(0.0, 0.5, uv, mi.Point2f(0.5, 0.5))
    # Unit vectors (scale 1); half a pixel is 0.03 rad.
    np.testing.assert_allclose(np.array(ray.d).T.reshape(camera.height, camera.width, 3), camera.ray_directions(),
                               atol=32 * EPS32)
    # Mitsuba starts its rays on the near-clip plane (1 cm), on the same lines through the camera.
    offset = np.array(ray.o).T - renderer.scene.camera.position
    # float32 origins: round-off on the scale of the camera's coordinates (3 m), not of the 1 cm offset.
    position_scale = np.abs(renderer.scene.camera.position).max()
    np.testing.assert_allclose(offset, np.linalg.norm(offset, axis=-1, keepdims=True) * np.array(ray.d).T,
                               atol=8 * EPS32 * position_scale)
    assert np.linalg.norm(offset, axis=-1).max() < 0.02
    assert camera_for_scene(renderer.scene.camera, (24, 16)).fov_y == pytest.approx(
        np.degrees(2 * np.arctan(np.tan(np.radians(30.0)) * 16 / 24)))


def test_gbuffer_depth_path_and_refraction_are_consistent(renderer):
    g = renderer.gbuffer(0)
    coastal = renderer.scene.coastal
    water = g.kind == KIND_WATER
    assert water.sum() > 100
    P, D, Nn, T, Pb = g.position[water], g.ray[water], g.normal[water], g.refracted[water], g.bottom_position[water]
    away = np.abs(P[:, 1] - 4.0) > 0.6  # the bed has a kink at the offshore depth
    # Depth: the vertical distance from the surface point down to the plane beach.
    np.testing.assert_allclose(g.depth[water][away], (P[:, 2] - bed(coastal, P[:, 1]))[away], atol=2e-3)
    # The refracted ray ends on the bed, l metres from the surface point.
    ends = np.isfinite(g.path_length[water])
    assert ends.mean() > 0.9
    l = g.path_length[water][ends]
    np.testing.assert_allclose(Pb[ends], P[ends] + l[:, None] * T[ends], atol=2e-3)
    on_bed = np.abs(Pb[ends][:, 1] - 4.0) > 0.6
    np.testing.assert_allclose(Pb[ends][on_bed, 2], bed(coastal, Pb[ends][on_bed, 1]), atol=2e-3)
    assert np.all(l >= g.depth[water][ends] - 2e-3)  # a slanted ray is never shorter than the vertical
    # Snell's law at the shading normal: n sin θ_t = sin θ_i, and the ray bends towards −N.
    sin_i = np.linalg.norm(np.cross(D, Nn), axis=-1)
    sin_t = np.linalg.norm(np.cross(T, Nn), axis=-1)
    np.testing.assert_allclose(N * sin_t, sin_i, rtol=0, atol=ROUNDOFF)  # float64 G-buffer; sines, scale 1
    assert np.all(np.sum(T * Nn, axis=-1) < 0)
    np.testing.assert_allclose(g.cos_view[water], np.sum(Nn * -D, axis=-1), rtol=0, atol=ROUNDOFF)  # scale 1


def test_gbuffer_agrees_with_mitsubas_aov_integrator(renderer):
    import mitsuba as mi

    from oceanrender.render.scene import perspective_sensor

    g = renderer.gbuffer(0)
    scene = renderer.sequence.renderer.scene
    film = {"type": "hdrfilm", "width": 24, "height": 16, "rfilter": {"type": "box"}, "pixel_format": "rgb"}
    aov = {"type": "scene", "integrator": {"type": "aov", "aovs": "dd:depth"},
           "sensor": perspective_sensor(renderer.scene.camera, film, 64)}
    aov.update({shape.id(): shape for shape in scene.shapes()})
    image = np.array(mi.render(mi.load_dict(aov), spp=64))
    distance = image[..., -1]  # the aov channel: distance along the ray, box-filtered over the pixel
    inside = (g.kind == KIND_WATER)[1:-1, 1:-1]
    ratio = distance[1:-1, 1:-1][inside] / g.distance[1:-1, 1:-1][inside]
    assert np.median(np.abs(ratio - 1)) < 0.01  # pixel-box average vs pixel centre


def test_gbuffer_follows_the_frame(renderer):
    first, later = renderer.gbuffer(0), renderer.gbuffer(2)
    both = (first.kind == KIND_WATER) & (later.kind == KIND_WATER)
    assert np.abs(first.position[both][:, 2] - later.position[both][:, 2]).max() > 1e-3  # the waves moved
    # The G-buffer sees the mesh the renderer holds: a surface point lies on the frame's water surface.
    positions = renderer.load(2).positions
    ny, nx = renderer.scene.coastal.shape
    top = positions[: ny * nx].reshape(ny, nx, 3)
    j = np.clip(np.searchsorted(top[:, 0, 1], later.position[both][:, 1]) - 1, 0, ny - 2)
    i = np.clip(np.searchsorted(top[0, :, 0], later.position[both][:, 0]) - 1, 0, nx - 2)
    low = np.minimum.reduce([top[j, i, 2], top[j + 1, i, 2], top[j, i + 1, 2], top[j + 1, i + 1, 2]])
    high = np.maximum.reduce([top[j, i, 2], top[j + 1, i, 2], top[j, i + 1, 2], top[j + 1, i + 1, 2]])
    z = later.position[both][:, 2]
    assert np.all((z >= low - 1e-4) & (z <= high + 1e-4))
