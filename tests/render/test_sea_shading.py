"""Shading every water hit from the sea's fields (issue 40): the device-side lookups against the numpy sea."""

import math

import numpy as np
import pytest

from oceanrender.render.sea_shading import (LACE_EDGE, SHADING_SPACING_PER_FOOTPRINT, SeaShading, level_tables,
                                            pixel_angle)
from oceanrender.surface.open_sea import WaterBody, polar_grid_sample
from tests.scenes import scene_from_dict
from tests.tolerances import ROUNDOFF32

pytestmark = pytest.mark.render


def radial_sea(**ocean):
    """Two 64² cascades on a radial mesh, foam on: every path of the field shading, cheaply."""
    return scene_from_dict({"name": "t", "ocean": {"resolution": 64, "patch_size": 96.0, "cascades": 2,
                                                   "wind_speed": 10.0, **ocean},
                            "mesh": {"kind": "radial", "outer_radius": 400.0, "segments": 48},
                            "foam": {"enabled": True, "radius": 30.0, "history": 0.5},
                            "camera": {"position": [3.0, -2.0, 6.0], "target": [3.0, 30.0, 0.0]}})


def interactions(points, camera, up=(0.0, 0.0, 1.0)):
    """Surface interactions at rest points (z = 0, geometric normal ``up``) seen from ``camera``."""
    import drjit as dr
    import mitsuba as mi

    x, y = np.asarray(points, float).T
    si = dr.zeros(mi.SurfaceInteraction3f, len(x))
    si.p = mi.Point3f(x, y, np.zeros_like(x))
    si.uv = mi.Point2f(x, y)
    n = mi.Normal3f(*up)
    si.n = n
    si.sh_frame = mi.Frame3f(n)
    to_camera = dr.normalize(mi.Vector3f(*[float(c) for c in camera]) - si.p)
    si.wi = si.sh_frame.to_local(to_camera)
    return si


@pytest.fixture(scope="module")
def body_and_fields():
    scene = radial_sea()
    body = WaterBody(scene)
    geometry = body.frame(0.75)
    return scene, body, geometry.shading


def test_level_tables_pack_every_level(body_and_fields):
    _, body, fields = body_and_fields
    positions, normals, offsets, sizes, spacings = level_tables(fields.cascades)
    total = sum(level.shape[0] * level.shape[1] for c in fields.cascades for level in c.levels)  # nodes
    assert positions.size == 3 * total and normals.size == 5 * total
    width = max(c.level_count for c in fields.cascades)
    for c, cascade in enumerate(fields.cascades):
        for j, level in enumerate(cascade.levels):
            n = level.shape[0]
            entry, nodes = c * width + j, level.reshape(n * n, -1)
            assert sizes[entry] == n
            assert spacings[entry] == pytest.approx(cascade.patch_size / n)
            first = int(offsets[entry])
            np.testing.assert_array_equal(positions[3 * first: 3 * (first + n * n)], nodes[:, :3].ravel())
            np.testing.assert_array_equal(normals[5 * first: 5 * (first + n * n)], nodes[:, 3:].ravel())
        assert sizes[c * width + cascade.level_count - 1] == 0  # the empty last level


@pytest.mark.parametrize("footprint", [0.02, 0.3, 4.0])
def test_hit_normals_are_the_sea_filtered_at_the_footprint(variant, body_and_fields, footprint, rng):
    # At a footprint w the shading is the sea as a mesh of spacing Δ = w/2 would carry it
    # (SeaSurface.sample with that spacing): the same levels, weights and normal formula.
    import drjit as dr
    import mitsuba as mi

    scene, body, fields = body_and_fields
    camera = np.array([3.0, -2.0, 6.0])
    points = rng.uniform(-40.0, 40.0, (400, 2))
    # the distance d that makes w = d θ_px / √cos θ equal to ``footprint``, per point, is not a
    # free choice: instead put the camera straight above each point at height d.
    angle = 1e-3
    si = interactions(points, camera)
    heights = footprint / angle
    si.wi = mi.Vector3f(0.0, 0.0, 1.0)  # looking straight down: cos θ = 1
    shading = SeaShading(fields, camera, angle)
    shading.camera = mi.Point3f(mi.Float(points[:, 0]), mi.Float(points[:, 1]), mi.Float(np.full(len(points), heights)))
    n, alpha, top = shading.normal(si)
    spacing = SHADING_SPACING_PER_FOOTPRINT * footprint
    expected = body.sea.sample(points[:, 0] + fields.origin[0], points[:, 1] + fields.origin[1], 0.75,
                               np.full(len(points), spacing))
    got = np.column_stack([np.array(n.x), np.array(n.y), np.array(n.z)])
    # float32 fields and arithmetic on the device: normals (scale 1) to ROUNDOFF32 × 10
    np.testing.assert_allclose(got, expected.normals, atol=10 * ROUNDOFF32)
    assert np.all(np.array(top))
    # α: the table of √(unresolved variance) at that spacing, linear in log Δ (within 1 %)
    exact = float(np.sqrt(body.sea.unresolved_slope_variance(np.array([spacing]))[0]))
    assert np.array(alpha) == pytest.approx(exact, rel=0.01)
    dr.eval()


def test_parallax_moves_a_hit_to_where_its_ray_meets_the_fine_surface(variant, body_and_fields, rng):
    # A ray from the camera meets the mesh — here the sea filtered to a mesh spacing of 6 m — at
    # p over rest point x₀; the fields at Δ put the surface at P(x) = (x + D_x, y + D_y, η). Two
    # Newton steps land on a rest point x* whose P(x*) lies on the ray: its distance from the ray is
    # of higher order in the offset (measured against the offset |P(x₀) − p| itself). A hit
    # already on the fine surface stays where it is.
    import drjit as dr
    import mitsuba as mi

    scene, body, fields = body_and_fields
    camera = np.array([3.0, -2.0, 6.0])
    points = rng.uniform(-10.0, 10.0, (2000, 2)) + np.asarray(fields.origin) + [0.0, 20.0]
    spacing = 0.5  # [m]: Δ (the test sea's finest waves are ~3 m long)

    def surface(rest_points, h):
        sample = body.sea.sample(rest_points[:, 0], rest_points[:, 1], 0.75, np.full(len(rest_points), h))
        return np.column_stack([rest_points, np.zeros(len(rest_points))]) + sample.displacement

    p = surface(points, 6.0)
    si = interactions(points, camera)
    si.p = mi.Point3f(*(mi.Float(p[:, k]) for k in range(3)))
    si.wi = si.sh_frame.to_local(dr.normalize(mi.Vector3f(*(float(c) for c in camera)) - si.p))
    shading = SeaShading(fields, camera, 1e-3)
    rest = mi.Point2f(mi.Float(points[:, 0]), mi.Float(points[:, 1]))
    moved = shading.parallax(si, rest, mi.Float(spacing), mi.Bool(True))
    xs = np.column_stack([np.array(moved.x, float), np.array(moved.y, float)])

    def off_ray(q):
        d = (p - camera) / np.linalg.norm(p - camera, axis=1, keepdims=True)
        return np.linalg.norm(np.cross(q - camera, d), axis=1)

    before, after = off_ray(surface(points, spacing)), off_ray(surface(xs, spacing))
    # sub-mesh waves of slope s ~0.1 seen at ~20° (c = cot ~3): one step leaves ~(c s)² of the offset
    assert np.median(before) > 0.05  # [m]: there was an offset to remove
    assert np.median(after) < 0.1 * np.median(before)
    assert np.quantile(after, 0.9) < 0.3 * np.quantile(before, 0.9)
    # a hit already on the fine surface: P(x₀) itself
    on = surface(points, spacing)
    si.p = mi.Point3f(*(mi.Float(on[:, k]) for k in range(3)))
    stay = shading.parallax(si, rest, mi.Float(spacing), mi.Bool(True))
    # float32 world coordinates of ~30 m (ROUNDOFF32 × 30 m × 100 operations: 0.1 mm), amplified where the
    # ray grazes a facet (the Newton system's determinant → 0) for a few: those within 1 % of Δ
    err = np.hypot(np.array(stay.x, float) - points[:, 0], np.array(stay.y, float) - points[:, 1])
    assert np.quantile(err, 0.99) < 1e-4 and err.max() < 0.01 * spacing
    dr.eval()


def test_slope_budget_is_kept_at_every_footprint(variant, body_and_fields, rng):
    # What the footprint resolves (the normal's slopes) plus α² is the spectrum's total
    # mean-square slope at every footprint (Bruneton et al. 2010, Eq. 4): the resolved part
    # measured over 20 000 random points of the field (sampling error ~2 %; 10 % allowed for the
    # fields' own realisation on 64² grids).
    import mitsuba as mi

    scene, body, fields = body_and_fields
    total = body.sea.total_slope_variance
    points = rng.uniform(-300.0, 300.0, (20000, 2))
    angle = 1e-3
    for footprint in (0.05, 0.5, 5.0):
        shading = SeaShading(fields, (0.0, 0.0, 1.0), angle)
        si = interactions(points, (0.0, 0.0, 1.0))
        si.wi = mi.Vector3f(0.0, 0.0, 1.0)
        shading.camera = mi.Point3f(mi.Float(points[:, 0]), mi.Float(points[:, 1]),
                                    mi.Float(np.full(len(points), footprint / angle)))
        n, alpha, _ = shading.normal(si)
        nx, ny, nz = (np.array(c, float) for c in (n.x, n.y, n.z))
        resolved = np.mean((nx / nz) ** 2 + (ny / nz) ** 2)  # slopes of the displaced surface
        assert resolved + float(np.mean(np.array(alpha)) ** 2) == pytest.approx(total, rel=0.10)


def test_skirt_and_bottom_keep_vertex_shading(variant, body_and_fields):
    import mitsuba as mi

    _, _, fields = body_and_fields
    shading = SeaShading(fields, (0.0, 0.0, 5.0), 1e-3)
    for up in ((1.0, 0.0, 0.0), (0.0, 0.0, -1.0)):
        si = interactions([[1.0, 2.0], [5.0, -3.0]], (0.0, 0.0, 5.0), up=up)
        _, _, top = shading.normal(si)
        assert not np.any(np.array(top))
        assert np.all(np.array(shading.foam_at(si)) == 0)
    del mi


def test_foam_lookup_matches_the_grid_and_keeps_the_mean_cover(variant, body_and_fields, rng):
    # B at a hit is the polar grid's B there (the numpy lookup the vertices use); drawn as lace
    # (weight = clip((B − L)/ε + ½, 0, 1), L uniform), foam covers the fraction B on average.
    import mitsuba as mi

    scene, body, fields = body_and_fields
    foam = fields.foam
    assert foam is not None and foam.fresh.size == 1 + foam.rings * foam.segments
    constant = np.full_like(foam.fresh, 0.3)
    from dataclasses import replace

    flat = replace(fields, foam=replace(foam, fresh=constant))
    shading = SeaShading(flat, (0.0, 0.0, 5.0), 1e-3)
    points = rng.uniform(-10.0, 10.0, (40000, 2)) + np.asarray(foam.center)
    si = interactions(points, (0.0, 0.0, 5.0))
    weight = np.array(shading.foam_at(si))
    # 40 000 points of a tile with ~10⁴ lace cells per 64 m²: mean within 0.02 of B (sampling)
    assert weight.mean() == pytest.approx(0.3, abs=0.02)
    assert np.mean((weight > 0) & (weight < 1)) < 3 * LACE_EDGE  # mostly covered or clear: structure, not grey
    # the grid's own B, through the lace with L = 0 (every texel below B: weight = clip(B/ε + ½))
    no_lace = replace(fields, foam=replace(foam, lace=np.zeros_like(foam.lace)))
    shading = SeaShading(no_lace, (0.0, 0.0, 5.0), 1e-3)
    grid_points = rng.uniform(-35.0, 35.0, (5000, 2)) + np.asarray(foam.center)
    si = interactions(grid_points, (0.0, 0.0, 5.0))
    got = np.array(shading.foam_at(si))
    grid = body.foam_grid_at(0.75)
    from dataclasses import replace as rep

    local = rep(grid, center=foam.center)
    fresh = polar_grid_sample(local, foam.fresh, grid_points[:, 0], grid_points[:, 1], foam.outside)
    np.testing.assert_allclose(got, np.clip(fresh / LACE_EDGE + 0.5, 0.0, 1.0), atol=10 * ROUNDOFF32 / LACE_EDGE)
    del mi


def _joined(fields, geometry, tau, scale, offset, sea_normals=None, sea_positions=None):
    """The shading fields of ``geometry``'s body as a joined body with constant (τ_s, A, C)."""
    from dataclasses import replace

    from oceanrender.surface.frame import JoinShading

    count = len(geometry.positions)
    normals = geometry.normals if sea_normals is None else sea_normals
    positions = geometry.positions if sea_positions is None else sea_positions
    return replace(fields, join=JoinShading(np.asarray(normals, np.float32), np.asarray(positions, np.float32),
                                            np.full(count, tau, np.float32),
                                            np.full(count, scale, np.float32), np.full(count, offset, np.float32)))


def _mesh_hits(geometry, body, fields, points):
    """(surface interactions of vertical rays at world points (x, y) with the body's mesh, its attributes on it;
    the scene, to be kept alive while they are used: they point into its mesh)."""
    from dataclasses import replace

    import mitsuba as mi

    from oceanrender.render.renderer import water_mesh

    mesh = water_mesh(body.faces, replace(geometry, shading=fields), {"type": "diffuse"})
    scene = mi.load_dict({"type": "scene", "water": mesh})
    x, y = np.asarray(points, float).T
    ray = mi.Ray3f(mi.Point3f(x, y, np.full_like(x, 20.0)), mi.Vector3f(0.0, 0.0, -1.0))
    si = scene.ray_intersect(ray)
    assert np.all(np.array(si.is_valid()))
    return si, scene


def test_a_joined_body_takes_the_sea_s_detail_scaled_by_its_taper(variant, body_and_fields, rng):
    # The coast inside the sea (JoinShading): s = s_body + τ_s (s_fields − s_sea). Where the body is
    # the sea (its normals the sea's) and τ_s = 1 the shading is the sea's own; where τ_s = 0 it is
    # the body's interpolated vertex normal; the foam is A·B_grid + C. Real mesh hits (the attributes
    # are interpolated by Mitsuba). Float32 slopes of scale ≤ ~1: 100 × ROUNDOFF32.
    import mitsuba as mi

    scene, body, fields = body_and_fields
    geometry = body.frame(0.75)
    camera = (3.0, -2.0, 6.0)
    points = rng.uniform(-20.0, 20.0, (500, 2)) + np.asarray(fields.origin)
    hits = []

    def normals(shading_fields):
        si, keep = _mesh_hits(geometry, body, shading_fields, points)
        shading = SeaShading(shading_fields, camera, 1e-3)
        n, _, top = shading.normal(si)
        assert np.all(np.array(top))
        hits.append(keep)
        return np.column_stack([np.array(c, float) for c in (n.x, n.y, n.z)]), si, shading

    sea, _, _ = normals(fields)
    same, _, _ = normals(_joined(fields, geometry, 1.0, 1.0, 0.0))
    np.testing.assert_allclose(same, sea, atol=100 * ROUNDOFF32)
    flat, si, _ = normals(_joined(fields, geometry, 0.0, 0.0, 0.0))
    body_normal = np.column_stack([np.array(c, float) for c in (si.sh_frame.n.x, si.sh_frame.n.y, si.sh_frame.n.z)])
    np.testing.assert_allclose(flat, body_normal, atol=100 * ROUNDOFF32)
    assert np.max(np.abs(sea - body_normal)) > 0.05  # the fields do add detail to the vertex normals
    # the camera hit's parallax too: the same fine surface where the body is the sea
    def moved(shading_fields):
        si, keep = _mesh_hits(geometry, body, shading_fields, points)
        area, _, _ = SeaShading(shading_fields, camera, 1e-3)._area_at(si, True, parallax=True)
        hits.append(keep)
        return np.column_stack([np.array(c, float) for c in (area.x, area.y, area.z)])

    np.testing.assert_allclose(moved(_joined(fields, geometry, 1.0, 1.0, 0.0, sea_positions=geometry.positions)),
                               moved(fields), atol=100 * ROUNDOFF32)
    # half the detail: the slope halfway between the body's and the fields'
    half, _, _ = normals(_joined(fields, geometry, 0.5, 1.0, 0.0))
    slope = [-n[:, :2] / n[:, 2:] for n in (half, sea, body_normal)]
    np.testing.assert_allclose(slope[0], 0.5 * (slope[1] + slope[2]), atol=1e-3)  # det(I + τ(J − I)) only scales
    # foam: A·B + C through the lace, as the sea's own foam grid scaled and offset
    from dataclasses import replace

    _, si, shading = normals(_joined(fields, geometry, 1.0, 0.5, 0.2))
    foam = fields.foam
    shifted = replace(fields, foam=replace(foam, fresh=0.5 * foam.fresh + 0.2, outside=0.5 * foam.outside + 0.2))
    expected = np.array(SeaShading(shifted, camera, 1e-3).foam_at(si))
    np.testing.assert_allclose(np.array(shading.foam_at(si)), expected, atol=10 * ROUNDOFF32 / LACE_EDGE)
    del mi


def test_pixel_angle():
    # 60° across 1280 px: 2 tan 30° / 1280 = 0.902 mrad
    assert pixel_angle(60.0, 1280) == pytest.approx(2 * math.tan(math.radians(30)) / 1280)


@pytest.mark.slow
def test_field_shaded_frame_is_split_and_keeps_the_vertex_frame_s_mean(variant):
    # The small sea (a 256² patch, 0.5 m vertex spacing, seen from 5 m): shaded from the fields
    # at every hit, the ``split`` integrator still splits it (the wrapper is its dielectric), and
    # the frame's mean luminance stays the vertex-shaded frame's: both carry the spectrum's whole
    # slope variance (resolved + α²). 32×18 px at 64 spp, two seeds each: the means' Monte Carlo
    # error is ~1 %; 4 % allowed for the different split of slopes between normal and α.
    from dataclasses import replace

    import mitsuba as mi

    from oceanrender.pipeline import Sequence
    from oceanrender.render.renderer import WATER_ID, WaterRenderer

    scene = scene_from_dict({"name": "t", "output": {"resolution": [32, 18], "spp": 64},
                             "camera": {"target": [0.0, 30.0, 0.0]}})
    sequence = Sequence(scene, variant)
    geometry = sequence.geometry(0)
    assert geometry.shading is not None
    means = {}
    for mode, geo in (("fields", geometry), ("vertex", replace(geometry, shading=None))):
        renderer = WaterRenderer.build(scene, sequence.iops, sequence.faces, geo, roughness=sequence.roughness,
                                       sun_lobe_alpha=sequence.sun_lobe_alpha, spp=64)
        water = next(s for s in renderer.scene.shapes() if s.id() == WATER_ID)
        assert getattr(water.bsdf(), "wraps_dielectric", False) == (mode == "fields")
        assert renderer.scene.integrator().split_setup(renderer.scene, None) is not None
        means[mode] = np.mean([renderer.render_xyz(64, seed)[0][..., 1].mean() for seed in (0, 1)])
    assert means["fields"] == pytest.approx(means["vertex"], rel=0.04)
    del mi


def test_a_hit_s_shading_is_evaluated_once_and_is_the_bsdf_s_own(variant, body_and_fields, rng):
    # A hit prepared once (the frame and the α and foam textures evaluated once, in a symbolic
    # branch, then shared by sample, eval, pdf: what the split integrator and trace_path do) is
    # the BSDF evaluated call by call, and both are the wrapper whose nested BSDF evaluates its
    # textures itself. Same float32 arithmetic: values (scale: their maximum) to ROUNDOFF32.
    import drjit as dr
    import mitsuba as mi

    from oceanrender.render.renderer import field_shaded_surface
    from oceanrender.render.sea_shading import _classes

    from dataclasses import replace

    scene, body, fields = body_and_fields
    camera = (3.0, -2.0, 6.0)
    # foam B = 0.3 everywhere (drawn as lace: about a third of the hits are foam)
    fields = replace(fields, foam=replace(fields.foam, fresh=np.full_like(fields.foam.fresh, 0.3)))
    shading = SeaShading(fields, camera, pixel_angle(60.0, 320))
    geometry = body.frame(0.75)
    bsdf = field_shaded_surface(geometry, 1.333, 0.1, 0.8, shading)
    assert len(bsdf.textures) == 2  # α and foam
    plain = _classes()[0](mi.Properties()).attach(bsdf.nested, shading)  # textures evaluated by the nested BSDF
    # points over the foam grid's centre, so some hits are foam
    points = rng.uniform(-12.0, 12.0, (512, 2)) + np.asarray(fields.foam.center)
    si = interactions(points, camera)
    si.wavelengths = mi.Spectrum(550.0)
    foam = np.array(next(t for t in bsdf.textures if type(t).__name__ == "SeaFoam").compute(si))
    assert 0.02 < np.mean(foam > 0) < 0.98  # both foam and water among the hits
    ctx = mi.BSDFContext()
    wo = mi.Vector3f(*(np.asarray(c, np.float32) for c in rng.normal(size=(3, len(points)))))
    wo = dr.normalize(wo)
    u1, u2 = mi.Float(rng.uniform(size=len(points))), mi.Point2f(*rng.uniform(size=(2, len(points))))
    prepared = bsdf.prepared(si, True, parallax=False, branch=True)

    def spectrum(value):
        return np.array(value[0] if dr.size_v(value) > 1 else value)

    results = []
    for b in (prepared, bsdf, plain):
        value, pdf = b.eval_pdf(ctx, si, wo)
        bs, weight = b.sample(ctx, si, u1, u2)
        results.append([spectrum(value), np.array(pdf), np.array(b.pdf(ctx, si, bs.wo)), spectrum(weight),
                        np.array(bs.wo.x), np.array(b.eval(ctx, si, wo)[0] if dr.size_v(mi.Spectrum) > 1
                                                        else b.eval(ctx, si, wo))])
        assert all(t.current is None for t in bsdf.textures)  # nothing left set after a call
    for other in results[1:]:
        for got, expected in zip(results[0], other):
            assert np.any(expected != 0)
            np.testing.assert_allclose(got, expected, rtol=0, atol=ROUNDOFF32 * np.max(np.abs(expected)))


@pytest.mark.slow
def test_a_path_s_hits_on_the_sea_are_prepared_once_with_the_same_result(variant, monkeypatch):
    # trace_path given the sea's BSDF (its hits prepared once per step, in a symbolic branch)
    # renders what it renders calling the BSDF per method: the same random numbers and the same
    # float32 arithmetic. 24×14 px at 8 spp; pixel values (scale: the frame's mean) to 100 ×
    # ROUNDOFF32 (float32 sums of different order along paths of several vertices).
    import oceanrender.render.underwater as underwater
    from oceanrender.pipeline import Sequence

    scene = scene_from_dict({"name": "t", "output": {"resolution": [24, 14], "spp": 8},
                             "camera": {"target": [0.0, 30.0, 0.0]}})
    sequence = Sequence(scene, variant)
    sequence.renderer.update_water(sequence.geometry(0))
    shared = sequence.renderer.render_xyz(8, 3)[0]
    trace_path = underwater.trace_path

    def per_call(*args, water_surface=None, **kwargs):
        return trace_path(*args, **kwargs)

    monkeypatch.setattr(underwater, "trace_path", per_call)
    separate = sequence.renderer.render_xyz(8, 3)[0]
    assert np.all(np.isfinite(shared))
    np.testing.assert_allclose(shared, separate, rtol=0, atol=100 * ROUNDOFF32 * float(np.mean(separate)))
