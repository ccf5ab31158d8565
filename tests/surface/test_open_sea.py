"""The scene's water body: patch and radial layouts, LOD fading, foam from folding."""

import numpy as np
import pytest

from tests.scenes import scene_from_dict
from oceanrender.surface.open_sea import WaterBody
from oceanrender.surface.patch_mesh import signed_volume
from oceanrender.surface.radial_mesh import HORIZON_GAP_DEG
from tests.tolerances import ROUNDOFF, ROUNDOFF32


def scene(**sections):
    base = {"ocean": {"resolution": 32, "patch_size": 64.0, "cascades": 2, "wind_speed": 10.0}}
    base.update(sections)
    return scene_from_dict({"name": "t", **base})


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
    fields = body.sea.levels[0].oceans[0].fields(2.0)  # level 0 of the only cascade
    # the cascades are float32; the body sums and recombines them in float64
    np.testing.assert_allclose(surface.displacement[..., 2], fields.height, rtol=0,
                               atol=ROUNDOFF32 * np.abs(fields.height).max())
    np.testing.assert_allclose(surface.jacobian, fields.jacobian, rtol=0, atol=ROUNDOFF32)  # J: scale 1


def test_far_vertices_keep_only_the_waves_they_resolve():
    s = scene(mesh={"kind": "radial", "outer_radius": 5000.0, "segments": 64})
    body = WaterBody(s)
    surface = body.surface(0.0)
    # where even the longest wave (the largest patch) is at most 2 vertices long, nothing is left
    flat = body.spacing >= body.sea.cascades.patch_sizes[0] / 2
    assert flat.any() and not flat.all()
    scale = np.abs(surface.displacement).max()  # of the near vertices, which keep their waves
    np.testing.assert_allclose(surface.displacement[flat], 0.0, rtol=0, atol=ROUNDOFF * scale)
    np.testing.assert_allclose(surface.normals[flat], np.tile([0.0, 0.0, 1.0], (flat.sum(), 1)), rtol=0,
                               atol=ROUNDOFF)  # unit vectors: scale 1
    # vertices 8–64 m apart drop the 3 m waves of the finer cascade but keep the 64 m patch's long waves
    middle = (body.spacing > 8.0) & (body.spacing < 16.0)
    assert np.std(surface.displacement[middle, 2]) > 0.1 * np.std(surface.displacement[:, 2])


def test_every_vertex_carries_the_roughness_of_what_it_drops():
    s = scene(mesh={"kind": "radial", "outer_radius": 5000.0, "segments": 64})
    body = WaterBody(s)
    geometry = body.frame(0.0)
    top = body.radial.top_vertex_count
    total = body.sea.total_slope_variance
    expected = np.sqrt(body.sea.unresolved_slope_variance(body.spacing))
    np.testing.assert_allclose(geometry.roughness[:top], expected, rtol=ROUNDOFF32)  # stored as float32
    np.testing.assert_allclose(geometry.roughness[top:], np.sqrt(total), rtol=ROUNDOFF32)  # far ring, skirt
    assert geometry.roughness[0] < geometry.roughness[top - 1]  # the centre resolves more than the edge
    # with a fixed α in the scene, no per-vertex attribute
    fixed = WaterBody(scene(mesh={"kind": "radial", "outer_radius": 5000.0, "segments": 64},
                            water={"surface_roughness": 0.1}))
    assert fixed.frame(0.0).roughness is None


def test_the_sea_reaches_the_horizon():
    """The flat far ring lies beyond h / tan(gap): from the camera its edge is < HORIZON_GAP_DEG below
    the horizon, for camera heights from 0.5 m to 1 km."""
    for height in (0.5, 30.0, 1000.0):
        s = scene(mesh={"kind": "radial", "outer_radius": 2000.0, "segments": 32},
                  camera={"position": [0.0, 0.0, height], "target": [0.0, 100.0, height]})
        body = WaterBody(s)
        positions = body.frame(0.0).positions
        far = positions[body.radial.top_vertex_count: body.radial.top_vertex_count + 32]
        distance = np.hypot(far[:, 0], far[:, 1]) * np.cos(np.pi / 32)  # nearest point of a far edge
        gap = np.degrees(np.arctan(height / distance))
        assert np.all(gap <= HORIZON_GAP_DEG * (1 + ROUNDOFF32)) and np.all(far[:, 2] == 0)


def test_foam_forms_only_where_the_surface_folds():
    calm = scene(foam={"enabled": True, "criterion": "Jacobian", "threshold": -1.0})
    assert np.all(WaterBody(calm).frame(1.0).foam == 0)
    foamy = scene(ocean={"resolution": 32, "patch_size": 64.0, "cascades": 1, "wind_speed": 10.0, "choppiness": 2.0},
                  foam={"enabled": True, "criterion": "Jacobian", "threshold": 0.8})
    body = WaterBody(foamy)
    foam = body.frame(1.0).foam
    assert foam.max() > 0 and foam.min() >= 0 and foam.max() <= 1
    top = (body.sea.settings.resolution + 1) ** 2
    assert np.all(foam[top:] == 0)  # skirt and bottom carry none
    # deterministic from t alone: the same frame twice gives the same foam (the same code path
    # on the same inputs, so bit for bit)
    np.testing.assert_array_equal(foam, body.frame(1.0).foam)


def whitecap_scene(wind, **foam):
    return scene(ocean={"resolution": 64, "patch_size": 40.0, "cascades": 1, "wind_speed": wind},
                 foam={"enabled": True, "decay_time": 1.0, "history": 2.0, **foam})


def test_whitecaps_grow_with_the_wind_and_fresh_foam_is_part_of_the_coverage():
    # The crest-acceleration criterion has no wind-dependent constant: the whole sea's slopes (which grow
    # with the wind, Cox & Munk 1954) set how much breaks. Mean coverage over 3 times, 8 against 16 m/s.
    means = []
    for wind in (8.0, 16.0):
        body = WaterBody(whitecap_scene(wind))
        coverage = [body.vertex_foam(t) for t in (2.0, 2.5, 3.0)]
        for f, b in coverage:
            assert np.all((0 <= b) & (b <= f) & (f <= 1))
        means.append(np.mean([f.mean() for f, _ in coverage]))
    assert means[0] > 0
    assert means[1] > 2 * means[0]  # Monahan's law says 2^3.41 = 10.6x; the rendered figures are in docs/whitecaps.md


def test_resumed_frames_equal_uninterrupted_ones():
    # The history lives on a fixed time grid: a body that rendered frames 0..5 and a fresh one asked for
    # frame 5 alone give the same foam bit for bit (the kept Jacobians are the same computations).
    settings = whitecap_scene(12.0)
    fps = 24.0
    running = WaterBody(settings)
    for frame in range(6):
        sequence = running.frame(2.0 + frame / fps).foam
    resumed = WaterBody(settings).frame(2.0 + 5 / fps).foam
    np.testing.assert_array_equal(sequence, resumed)
    assert sequence.max() > 0


def test_foam_beyond_the_radius_is_the_tracked_mean():
    settings = scene(ocean={"resolution": 64, "patch_size": 40.0, "cascades": 1, "wind_speed": 16.0},
                     mesh={"kind": "radial", "outer_radius": 400.0, "segments": 64},
                     foam={"enabled": True, "decay_time": 1.0, "history": 2.0, "radius": 60.0},
                     render={"surface_shading": "vertex"})  # foam tracked at the mesh's vertices
    body = WaterBody(settings)
    coverage, fresh = body.vertex_foam(2.0)
    x, y, tracked = body.foam_points(2.0)
    far = ~tracked
    assert far.any() and tracked.any()
    n = x.size
    # every vertex beyond the radius has the tracked foam's area-weighted mean, the far ring too
    np.testing.assert_allclose(coverage[:n][far], coverage[:n][far][0], rtol=ROUNDOFF32)
    assert coverage[:n][far][0] > 0
    np.testing.assert_allclose(coverage[n: n + 64], coverage[:n][far][0], rtol=ROUNDOFF32)


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


def field_sea(**foam):
    return scene(ocean={"resolution": 32, "patch_size": 64.0, "cascades": 2, "wind_speed": 12.0},
                 mesh={"kind": "radial", "outer_radius": 300.0, "segments": 32},
                 foam={"enabled": True, "radius": 20.0, "history": 0.5, **foam},
                 camera={"position": [4.0, 1.0, 5.0], "target": [4.0, 30.0, 0.0]})


def test_shading_fields_carry_the_levels_and_rest_positions():
    body = WaterBody(field_sea())
    geometry = body.frame(0.5)
    fields = geometry.shading
    assert fields is not None and len(fields.cascades) == 2
    for cascade, levels in zip(fields.cascades, body.sea.levels):
        assert cascade.level_count == levels.count and cascade.band_top == levels.band_top
        f = levels.oceans[0].fields(0.5)
        # the channels of SHADING_CHANNELS: height, displacement, slopes, displacement gradient − identity
        for k, value in enumerate((f.height, f.displacement_x, f.displacement_y, f.slope_x, f.slope_y,
                                   f.jacobian_xx - 1, f.jacobian_yy - 1, f.jacobian_xy)):
            np.testing.assert_array_equal(cascade.levels[0][..., k], np.asarray(value).astype(np.float32))
    # texture coordinates: the top vertices' rest positions relative to the origin (the grid's centre)
    grid = body.grid_at(0.5)
    top = len(grid.points)
    np.testing.assert_allclose(fields.texcoords[:top] + fields.origin, grid.points, atol=ROUNDOFF32 * 300.0)
    assert fields.origin == (4.0, 1.0)
    # α: √(unresolved) at each tabulated spacing, increasing with the spacing
    assert np.all(np.diff(fields.alpha) >= -ROUNDOFF) and fields.alpha[-1] ** 2 == pytest.approx(
        body.sea.total_slope_variance, rel=1e-3)


def test_vertex_shading_has_no_fields():
    s = scene(ocean={"resolution": 32, "patch_size": 64.0, "cascades": 2},
              mesh={"kind": "radial", "outer_radius": 300.0, "segments": 32}, render={"surface_shading": "vertex"})
    assert WaterBody(s).frame(0.0).shading is None
    fixed = scene(water={"surface_roughness": 0.1})
    assert WaterBody(fixed).frame(0.0).shading is None


def test_crest_field_on_the_foam_grid_is_the_sea_s():
    # The compiled sum over levels equals SeaSurface's interpolation of the same levels (1 + xx + yy).
    body = WaterBody(field_sea())
    x, y = body.foam_grid_at(0.25).points[::97].T
    fast = body._crest_field(x, y, 0.25)
    spacing = np.full(x.shape, body.scene.foam.filter_spacing)
    xx, yy = body.sea._weighted(x, y, 0.25, spacing, slice(5, 7))
    np.testing.assert_allclose(fast, 1.0 + xx + yy, rtol=0, atol=ROUNDOFF32)


def test_foam_grid_is_finer_than_the_mesh_and_its_lookup_reproduces_it():
    from oceanrender.surface.open_sea import polar_grid_sample

    body = WaterBody(field_sea())
    grid = body.foam_grid_at(0.5)
    assert grid.segments > body.radial.segments and grid.outer_radius == 20.0
    coverage, fresh = body.foam_state(0.5)
    assert coverage.shape == (len(grid.points),) and np.all(fresh <= coverage + ROUNDOFF)
    x, y = grid.points.T
    np.testing.assert_allclose(polar_grid_sample(grid, fresh, x, y, -1.0), fresh, atol=ROUNDOFF)
    # beyond the last ring: the far value
    assert polar_grid_sample(grid, fresh, np.array([grid.center[0] + 25.0]), np.array([grid.center[1]]), -1.0)[0] == -1.0
    # the vertices take the grid's foam; the frame carries it for the renderer
    geometry = body.frame(0.5)
    assert geometry.foam is not None and geometry.shading.foam is not None
    assert geometry.shading.foam.fresh.size == len(grid.points)


def test_foam_lace_only_with_field_shading_and_foam():
    from oceanrender.surface.open_sea import LACE_SIZE, scene_foam_lace

    tile, size = scene_foam_lace(field_sea())
    assert size == LACE_SIZE and tile.ndim == 2 and 0.0 <= tile.min() and tile.max() < 1.0
    assert scene_foam_lace(scene(foam={"enabled": False})) is None
    assert scene_foam_lace(scene(foam={"enabled": True}, render={"surface_shading": "vertex"})) is None
    assert WaterBody(field_sea()).frame(0.0).foam_lace is not None


def test_smoothed_polar_keeps_the_mean_and_rounds_a_single_node():
    from oceanrender.surface.open_sea import smoothed_polar
    from oceanrender.surface.radial_mesh import RadialGrid

    grid = RadialGrid.square_cells((0.0, 0.0), 1.0, 50.0, 64)
    values = np.zeros(len(grid.points))
    values[1 + 30 * 64 + 63] = 1.0  # one node on ring 30, next to the angle's wrap
    smooth = smoothed_polar(grid, values, 1.0).astype(float)
    assert smooth.sum() == pytest.approx(1.0, rel=1e-6)
    rings = smooth[1:].reshape(grid.rings, 64)
    assert rings[30, 0] == pytest.approx(rings[30, 62], rel=1e-6)  # periodic in angle: symmetric across the wrap
    assert rings[29, 63] == pytest.approx(rings[30, 62], rel=1e-6)  # round: the same one cell away either way


def _layout(geometry):
    """Which arrays a frame has, their shapes and types, nested through its shading fields."""
    def shape(a):
        return None if a is None else (np.shape(a), np.asarray(a).dtype)

    fields = geometry.shading
    shading = None if fields is None else (
        [(c.patch_size, c.band_top, [shape(level) for level in c.levels]) for c in fields.cascades],
        shape(fields.spacing), shape(fields.alpha), shape(fields.texcoords), fields.join is None,
        None if fields.foam is None else (fields.foam.rings, fields.foam.segments, shape(fields.foam.fresh),
                                          shape(fields.foam.lace), fields.foam.lace_size))
    lace = None if geometry.foam_lace is None else (shape(geometry.foam_lace[0]), geometry.foam_lace[1])
    return (shape(geometry.positions), shape(geometry.normals), shape(geometry.foam), shape(geometry.roughness),
            shading, lace)


@pytest.mark.parametrize("sections", [
    {},
    {"foam": {"enabled": False}},
    {"render": {"surface_shading": "vertex"}},
    {"water": {"surface_roughness": 0.1}},
])
def test_the_calm_stand_in_has_the_frame_s_layout(sections):
    # The renderer is loaded with the stand-in while the real frame is computed: every array the frame has,
    # the stand-in has, with the same shape and type; and what a loaded scene keeps from its first geometry
    # (the skirt and bottom, from which the seafloor's extent is taken) is the frame's exactly.
    base = {"ocean": {"resolution": 32, "patch_size": 64.0, "cascades": 2, "wind_speed": 12.0},
            "mesh": {"kind": "radial", "outer_radius": 300.0, "segments": 32},
            "foam": {"enabled": True, "radius": 20.0, "history": 0.5},
            "camera": {"position": [4.0, 1.0, 5.0], "target": [4.0, 30.0, 0.0]}}
    body = WaterBody(scene_from_dict({"name": "t", **{**base, **sections}}))
    stand_in, frame = body.frame_layout(0.5), body.frame(0.5)
    assert _layout(stand_in) == _layout(frame)
    rest = len(body.grid_at(0.5).points)  # the top vertices; then the far ring, the skirt and the bottom
    np.testing.assert_array_equal(stand_in.positions[rest:], frame.positions[rest:])
    # the sea at rest: the top vertices at z = 0, facing up
    assert np.all(stand_in.positions[:rest, 2] == 0.0) and np.all(stand_in.normals[:rest, 2] == 1.0)


def test_the_patch_mesh_has_no_stand_in():
    assert WaterBody(scene(mesh={"kind": "patch"})).frame_layout(0.0) is None
