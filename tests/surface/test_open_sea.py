"""The scene's water body: patch and radial layouts, LOD fading, foam from folding."""

import numpy as np
import pytest

from oceanrender.scene import scene_from_dict
from oceanrender.surface.open_sea import WaterBody
from oceanrender.surface.patch_mesh import signed_volume
from oceanrender.waves.sea import lod_weight
from tests.tolerances import ROUNDOFF, ROUNDOFF32


def scene(**sections):
    base = {"ocean": {"resolution": 32, "patch_size": 64.0, "cascades": 2, "wind_speed": 10.0}}
    base.update(sections)
    return scene_from_dict({"name": "t", **base})


def test_lod_weight_limits():
    assert lod_weight(np.array([0.1]), 1.0)[0] == 1.0
    assert lod_weight(np.array([1.0]), 1.0)[0] == 1.0
    assert lod_weight(np.array([2.0]), 1.0)[0] == pytest.approx(0.5)
    assert lod_weight(np.array([4.0]), 1.0)[0] == 0.0


@pytest.mark.parametrize("kind", ["patch", "radial"])
def test_body_is_closed_with_positive_volume(kind):
    s = scene(mesh={"kind": kind, "outer_radius": 500.0, "segments": 32}, water={"depth": 20.0})
    body = WaterBody(s)
    geometry = body.frame(1.5)
    assert geometry.positions.shape == geometry.normals.shape == (body.vertex_count, 3)
    assert signed_volume(geometry.positions, body.faces) > 0
    assert np.all(np.isfinite(geometry.positions)) and geometry.foam is None


def test_patch_body_matches_the_single_fft_patch():
    # one cascade on its own grid: the sampled surface is the FFT field itself
    s = scene(ocean={"resolution": 16, "patch_size": 40.0, "cascades": 1})
    body = WaterBody(s)
    surface = body.surface(2.0)
    fields = body.sea.cascades.cascades[0].fields(2.0)
    # the cascades are float32; the body sums and recombines them in float64
    np.testing.assert_allclose(surface.displacement[..., 2], fields.height, rtol=0,
                               atol=ROUNDOFF32 * np.abs(fields.height).max())
    np.testing.assert_allclose(surface.jacobian, fields.jacobian, rtol=0, atol=ROUNDOFF32)  # J: scale 1


def test_far_vertices_drop_the_fine_waves():
    s = scene(mesh={"kind": "radial", "outer_radius": 5000.0, "segments": 64})
    body = WaterBody(s)
    surface = body.surface(0.0)
    far = body.spacing > 4 * body.sea.cascades.grids[0].spacing
    assert far.any()
    scale = np.abs(surface.displacement).max()  # of the near vertices, which keep their waves
    np.testing.assert_allclose(surface.displacement[far], 0.0, rtol=0, atol=ROUNDOFF * scale)
    np.testing.assert_allclose(surface.normals[far], np.tile([0.0, 0.0, 1.0], (far.sum(), 1)), rtol=0,
                               atol=ROUNDOFF)  # unit vectors: scale 1


def test_foam_forms_only_where_the_surface_folds():
    calm = scene(foam={"enabled": True, "threshold": -1.0})
    assert np.all(WaterBody(calm).frame(1.0).foam == 0)
    foamy = scene(ocean={"resolution": 32, "patch_size": 64.0, "cascades": 1, "wind_speed": 10.0, "choppiness": 2.0},
                  foam={"enabled": True, "threshold": 0.8})
    body = WaterBody(foamy)
    foam = body.frame(1.0).foam
    assert foam.max() > 0 and foam.min() >= 0 and foam.max() <= 1
    top = (body.sea.settings.resolution + 1) ** 2
    assert np.all(foam[top:] == 0)  # skirt and bottom carry none
    # deterministic from t alone: the same frame twice gives the same foam (the same code path
    # on the same inputs, so bit for bit)
    np.testing.assert_array_equal(foam, body.frame(1.0).foam)


def test_fractal_detail_blends_onto_the_sea():
    base = scene(ocean={"resolution": 32, "patch_size": 64.0, "cascades": 1, "wind_speed": 10.0})
    with_detail = scene(ocean={"resolution": 32, "patch_size": 64.0, "cascades": 1, "wind_speed": 10.0,
                               "fractal_gamma": 0.5, "fractal_size": 64})
    a, b = WaterBody(base), WaterBody(with_detail)
    fractal = b.sea.fractal
    assert 0.05 <= fractal.hurst <= 0.95 and fractal.sigma > 0
    sa, sb = a.surface(1.0), b.surface(1.0)
    detail, _, _ = fractal.sample(b.rest_x, b.rest_y)
    # ζ = η + γ η_fractal exactly, and the horizontal displacement is untouched
    height_scale = np.abs(sa.displacement[..., 2]).max()
    np.testing.assert_allclose(sb.displacement[..., 2], sa.displacement[..., 2] + 0.5 * detail, rtol=0,
                               atol=ROUNDOFF * height_scale)
    np.testing.assert_allclose(sb.displacement[..., :2], sa.displacement[..., :2], rtol=0,
                               atol=ROUNDOFF * np.abs(sa.displacement[..., :2]).max())
    # the detail's slopes tilt the normals (unit vectors, scale 1) far beyond round-off
    assert np.abs(sb.normals - sa.normals).max() > 1e-3
