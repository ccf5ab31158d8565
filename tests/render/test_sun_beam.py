"""The sun's beam traced on the device (issue 41) against the numpy light tracing of the same sea."""

import numpy as np
import pytest

from oceanrender.render.scene import sun_direction
from oceanrender.render.sun_beam import device_plane_irradiance
from oceanrender.surface.sunlight import facet_power, plane_irradiance, refracted_beam
from tests.scenes import scene_from_dict
from tests.tolerances import ROUNDOFF32

pytestmark = pytest.mark.render


def test_device_planes_are_the_numpy_light_tracing_of_the_same_sea(variant):
    # The small sea (one 128 m patch, 7 m/s) shaded from its fields, sun 40° high: the device's
    # planes 1 and 3 m down equal numpy's (surface.sunlight) fed by the numpy sea sampled at the
    # same rest points and spacing. Float32 fields and arithmetic on the device against float64:
    # cells (scale: the plane's mean) within 100 × ROUNDOFF32 on average, 1000 × at the worst
    # cell (a landing point a few µm across a cell's edge moves its share).
    from oceanrender.pipeline import Sequence

    scene = scene_from_dict({"name": "t", "output": {"resolution": [16, 9]}, "render": {"surface_shading": "fields"},
                             "water": {"surface_roughness": "auto"}})
    sequence = Sequence(scene, variant)
    sequence.point(0)
    sequence.renderer.update_water(sequence.geometry(0))
    shading = sequence.renderer.shading
    assert shading is not None
    sun = sun_direction(40.0, 30.0)
    h, side, cell, n_water = 0.01, 4.0, 0.04, 1.34
    depths, cells = [-1.0, -3.0], (60, 60)
    origins = [(-1.2, -1.2), (-1.2, -2.0)]
    device = device_plane_irradiance(shading, sun, n_water, (-2.0, -2.0, side), h, depths, cell, cells, origins,
                                     attenuation=0.05)
    count = int(np.ceil(side / h))
    x = -2.0 + (np.arange(count) + 0.5) * h
    xx, yy = np.meshgrid(x, x)
    surface = sequence.body.sea.sample(xx.ravel(), yy.ravel(), 0.0, np.full(xx.size, h))
    normals = surface.normals
    area = normals * (surface.jacobian / normals[:, 2])[:, None]
    directions, transmittance = refracted_beam(normals, sun, n_water)
    power = facet_power(area, sun, 1.0, h * h) * transmittance
    points = np.column_stack([xx.ravel() + surface.displacement[:, 0], yy.ravel() + surface.displacement[:, 1],
                              surface.displacement[:, 2]])
    for k, (z, origin) in enumerate(zip(depths, origins)):
        expected = plane_irradiance(points, directions, power, [z], origin, cell, cells, attenuation=0.05,
                                    periodic=False)[0]
        assert expected.mean() > 0.5 * np.sin(np.radians(40.0))  # the beam is there
        difference = np.abs(device[k] - expected)
        assert difference.mean() <= 100 * ROUNDOFF32 * expected.mean()
        assert difference.max() <= 1000 * ROUNDOFF32 * expected.mean()


def floor_scene(cell):
    """A 3 m deep clear sea over a floor of albedo 0.5, sun 60° high, seen from 2.5 m up (the small sea)."""
    return scene_from_dict({"name": "floor", "output": {"resolution": [32, 18], "spp": 128},
                            "render": {"caustic_cell": cell, "caustic_window": 16.0, "in_water_fraction": 0.5},
                            "water": {"depth": 3.0, "bottom_albedo": 0.5, "iop_table": "pure_seawater.csv"},
                            "sun": {"elevation": 60.0, "azimuth": 20.0},
                            "camera": {"position": [0.0, 0.0, 2.5], "target": [0.0, 5.0, -3.0], "fov": 60.0}})


def test_the_floor_s_sun_from_the_map_keeps_the_unbiased_mean(variant):
    # The in-water pass of the floor scene with the sun's beam on the floor from the map
    # (2 cm cells) and without (the path tracer's connections through the surface): the map
    # replaces exactly the paths floor → surface → sun, so the frame's mean is the same.
    # 32×18 px at 256 spp, two seeds each: the means' Monte Carlo error is ~0.5 % (measured
    # 0.06 % apart at 64×36 and 1024 spp); 3 % allowed for it and the cells' resolution.
    from oceanrender.pipeline import Sequence
    from oceanrender.render.renderer import film_to_absolute_XYZ, render_passes

    means = {}
    for cell in (0.02, 0.0):
        sequence = Sequence(floor_scene(cell), variant)
        sequence.point(0)
        sequence.renderer.update_water(sequence.geometry(0))
        renderer = sequence.renderer
        assert (renderer.floor_caustics is not None) == (cell > 0)
        if cell > 0:
            # the map: the beam is on the floor (of the order of the sun's horizontal irradiance
            # times Fresnel's transmittance and the window's share) and the waves shape it
            e0 = np.asarray(renderer.floor_caustics.irradiance)
            assert 0.5 * np.sin(np.radians(60)) < e0.mean() < 1.05 * np.sin(np.radians(60))
            assert e0.std() > 0.05 * e0.mean()
        films = [render_passes(renderer.scene, 256, seed, renderer.in_water) for seed in (3, 4)]
        means[cell] = np.mean([film_to_absolute_XYZ(f[..., :3])[..., 1].mean() for f in films])
    print(f"floor map: in-water mean {means[0.02]:.6g} cd/m2, path tracer alone {means[0.0]:.6g}")
    assert means[0.02] == pytest.approx(means[0.0], rel=0.03)


def test_the_volume_s_sun_from_the_planes_keeps_the_unbiased_mean(variant):
    # The floor scene's water made green coastal (scattering b ≈ 1 m⁻¹: the sun scattered once in
    # the water is a large part of the in-water light), its floor map off, the volume's planes on
    # (20 cm cells, every 0.5 m down to the floor): the frame's in-water mean stays the unbiased
    # one. 32×18 px at 256 spp, two seeds each; 3 % for the Monte Carlo error (~1 %) and the cells.
    from oceanrender.pipeline import Sequence
    from oceanrender.render.renderer import film_to_absolute_XYZ, render_passes

    means = {}
    for cell in (0.2, 0.0):
        scene = scene_from_dict({"name": "volume", "output": {"resolution": [32, 18], "spp": 128},
                                 "render": {"caustic_cell": 0.0, "shaft_cell": cell, "shaft_depth": 3.0,
                                            "caustic_window": 16.0, "in_water_fraction": 0.5},
                                 "water": {"depth": 3.0, "bottom_albedo": 0.5},
                                 "composition": {"preset": "green coastal"},
                                 "sun": {"elevation": 60.0, "azimuth": 20.0},
                                 "camera": {"position": [0.0, 0.0, 2.5], "target": [0.0, 5.0, -3.0], "fov": 60.0}})
        sequence = Sequence(scene, variant)
        sequence.point(0)
        sequence.renderer.update_water(sequence.geometry(0))
        renderer = sequence.renderer
        assert (renderer.volume_beam is not None) == (cell > 0)
        films = [render_passes(renderer.scene, 256, seed, renderer.in_water) for seed in (3, 4)]
        means[cell] = np.mean([film_to_absolute_XYZ(f[..., :3])[..., 1].mean() for f in films])
    print(f"volume planes: in-water mean {means[0.2]:.6g} cd/m2, path tracer alone {means[0.0]:.6g}")
    assert means[0.2] == pytest.approx(means[0.0], rel=0.03)
