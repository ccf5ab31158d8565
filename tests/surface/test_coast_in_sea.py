"""The coast inside the open sea: one body that is the FFT sea far out, the solver's surface inside, no seam."""

from __future__ import annotations

import numpy as np
import pytest

from oceanrender.coastal.embedding import terrain_height
from oceanrender.coastal.simulation import run_simulation
from tests.scenes import scene_from_dict
from oceanrender.surface.coast_in_sea import DRY_DROP, CoastInSea
from oceanrender.surface.open_sea import WaterBody
from tests.coastal.test_embedding import BAY
from tests.tolerances import ROUNDOFF

SCENE = {**BAY, "output": {"frames": [0, 1]}, "water": {"depth": 50.0}, "ocean": {**BAY["ocean"], "choppiness": 0.0},
         "coastal": {**BAY["coastal"], "spinup": 6.0, "blend_width": 12.0, "rotation": 15.0}}


@pytest.fixture(scope="module")
def body(tmp_path_factory) -> CoastInSea:
    scene = scene_from_dict(SCENE)
    store = tmp_path_factory.mktemp("bay")
    run_simulation(scene, store)
    return CoastInSea(scene, store)


def test_far_from_the_coast_the_body_is_the_open_sea(body):
    """Where w = 0 and both tapers are 1 the vertices are the FFT sea's, bit for bit: every vertex over water
    deeper than 20 m outside the domain (the continued beach's shoaling strip is not)."""
    mine = body.frame(0.0).positions
    sea = WaterBody(body.scene).frame(0.0).positions
    g = body.mesh
    far = np.flatnonzero((g.w == 0) & (g.tau_s == 1) & (g.tau_l == 1))
    deep = np.flatnonzero((g.w == 0) & (g.terrain < -20.0))
    assert deep.size > 0 and np.isin(deep, far).all()
    np.testing.assert_array_equal(mine[far], sea[far])


def _across_offshore_side(body, offsets):
    """World points on a line across the offshore (north) side, at ζ = Ly + offsets [m]."""
    frame = body.domain
    xi = np.repeat(np.linspace(10.0, 70.0, 7), len(offsets))
    zeta = np.tile(frame.size[1] + np.asarray(offsets), 7)
    return frame.to_world(xi, zeta)


def test_no_jump_in_height_or_slope_across_the_join(body):
    """1 mm either side of the domain's offshore edge: heights within 1 mm × the steepest slope, slopes equal.

    The join is continuous with continuous first derivatives by construction
    (a C¹ weight, continuous fields); over 2 mm a smooth surface changes its
    height by at most 2 mm × |∇z| and its slope by 2 mm × its curvature
    (k² a ≲ 0.1 m⁻¹ for these waves): 2e-4.
    """
    x, y = _across_offshore_side(body, [-1e-3, 1e-3])
    disp, slope, wet = body.surface_at(x, y, 0.0)
    assert wet.all()
    inner, outer = disp[0::2], disp[1::2]
    steepest = np.abs(slope).max()
    assert np.abs(inner[:, 2] - outer[:, 2]).max() <= 2e-3 * steepest + ROUNDOFF
    assert np.abs(slope[0::2] - slope[1::2]).max() <= 2e-4


def test_the_slopes_are_the_derivatives_of_the_heights(body):
    """The product-rule slopes against central differences of z, across the blend zone and the shoaling sea.

    Without chop (λ = 0) the slope of z at a rest point is ∇z. The ingredients'
    own slopes are interpolated slope fields, not derivatives of interpolated
    heights, so the central differences run over e = 1 m (half a solver cell, a
    quarter of the sea's 4 m grid) and agree to O((k e)²) ≈ 5 % plus the
    interpolation's O(k Δ)² differences: 15 % of the largest slope.
    """
    frame = body.domain
    xi, zeta = np.meshgrid(np.linspace(20.0, 60.0, 5), np.linspace(35.0, 75.0, 9))
    x, y = frame.to_world(xi.ravel(), zeta.ravel())
    e = 1.0
    _, slope, wet = body.surface_at(x, y, 0.0)
    zx = (body.surface_at(x + e, y, 0.0)[0][:, 2] - body.surface_at(x - e, y, 0.0)[0][:, 2]) / (2 * e)
    zy = (body.surface_at(x, y + e, 0.0)[0][:, 2] - body.surface_at(x, y - e, 0.0)[0][:, 2]) / (2 * e)
    scale = np.abs(slope[wet]).max()
    assert np.abs(slope[wet, 0] - zx[wet]).max() <= 0.15 * scale
    assert np.abs(slope[wet, 1] - zy[wet]).max() <= 0.15 * scale


def test_inside_the_domain_the_surface_is_the_solvers_plus_the_short_waves(body):
    frame = body.domain
    xi, zeta = np.meshgrid(np.linspace(16.0, 64.0, 5), np.linspace(38.0, 46.0, 3))
    x, y = frame.to_world(xi.ravel(), zeta.ravel())
    g = body.geometry(x, y)
    assert np.all(g.w == 1.0)
    disp, _, wet = body.surface_at(x, y, 0.0)
    sea = body.sea_body.sea.sample(x, y, 0.0)
    long = body.modes.fields(x, y, 0.0)
    solver = body.solver_fields(0.0, x, y, g.terrain)[0]
    expected = solver + g.tau_s * (sea.displacement[:, 2] - long[0])
    np.testing.assert_allclose(disp[wet, 2], expected[wet], rtol=0, atol=ROUNDOFF * 10)


def test_land_lies_above_the_water_and_the_terrain_is_on_the_same_triangles(body):
    disp, _, wet = body.surface(0.0)
    g = body.mesh
    assert (~wet).any() and wet.any()
    assert np.all(disp[~wet, 2] <= g.terrain[~wet] - DRY_DROP)
    terrain = body.terrain()
    top = g.x.size
    c = body.coastal
    expected = terrain_height(body.coast.bed, body.domain, c.spacing, c.offshore_side, c.still_level, c.outer_slope,
                              c.outer_depth, g.x, g.y)
    np.testing.assert_allclose(terrain.positions[:top, 2], expected, rtol=0, atol=1e-5 * np.abs(expected).max())
    assert terrain.faces.max() == len(terrain.positions) - 1
    np.testing.assert_array_equal(terrain.faces, body.faces[: len(terrain.faces)])
    assert terrain.positions[:, 2].min() > -body.scene.water.depth  # inside the closed body


def test_where_only_one_side_is_wet_in_the_blend_the_depths_are_blended(body):
    """Beside the shoreline in the lateral blend, the solver's swash keeps (1 − w)·0 + w·its depth of water.

    z = z_b + (1 − w) max(z_sea − z_b, 0) + w max(z_solver − z_b, 0) there (the height blend
    would sink a thin film under the beach once w < 1); its slopes are the derivatives of z
    (central differences over 0.1 m). Tolerance 20 % of the largest slope: the solver's slope
    field is interpolated apart from its depth, which differs from differences of z by up to
    22 % of the scale where only the solver is wet (w = 1, measured; 15 % at these points);
    taking the dry side's gradient instead of the wet side's would be off by the whole
    bed slope, ~100 % of the scale here.
    """
    frame, c = body.domain, body.coastal
    lx, ly = frame.size
    xi, zeta = np.meshgrid(np.linspace(0.05, lx - 0.05, 200), np.linspace(0.05, ly - 0.05, 200))
    x, y = frame.to_world(xi.ravel(), zeta.ravel())
    g = body.geometry(x, y)
    long = body.modes.fields(x, y, 0.0)[0]
    short = body.sea_body.sea.sample(x, y, 0.0).displacement[:, 2] - long
    bed = g.terrain - c.still_level
    a = g.tau_s * short + g.tau_l * long - bed
    b = g.tau_s * short + body.solver_fields(0.0, x, y, g.terrain)[0] - bed
    mixed = (g.w > 0) & (g.w < 1) & ((a > 0) != (b > 0))
    assert mixed.sum() >= 50  # the fixture's swash reaches into the lateral blends
    disp, slope, wet = body.surface_at(x[mixed], y[mixed], 0.0)
    depth = (1 - g.w[mixed]) * np.maximum(a[mixed], 0) + g.w[mixed] * np.maximum(b[mixed], 0)
    kept = wet
    assert kept.sum() >= 20
    assert np.abs(disp[kept, 2] - c.still_level - bed[mixed][kept] - depth[kept]).max() <= ROUNDOFF * 10.0
    e = 0.1
    xm, ym = x[mixed][kept], y[mixed][kept]
    zx = (body.surface_at(xm + e, ym, 0.0)[0][:, 2] - body.surface_at(xm - e, ym, 0.0)[0][:, 2]) / (2 * e)
    zy = (body.surface_at(xm, ym + e, 0.0)[0][:, 2] - body.surface_at(xm, ym - e, 0.0)[0][:, 2]) / (2 * e)
    # only where the four neighbours are wet too (a dry neighbour sits at the terrain − DRY_DROP)
    both = np.all([body.surface_at(xm + dx, ym + dy, 0.0)[2] for dx, dy in ((e, 0), (-e, 0), (0, e), (0, -e))], axis=0)
    assert both.sum() >= 10
    scale = np.abs(slope[kept][both]).max()
    assert np.abs(slope[kept][both, 0] - zx[both]).max() <= 0.2 * scale
    assert np.abs(slope[kept][both, 1] - zy[both]).max() <= 0.2 * scale


def test_field_shading_joins_the_sea_s_detail_as_the_geometry_joins_its_waves(body):
    """With field shading (the default) the frame carries the sea's fields and how the body joins them
    (JoinShading): where the body is the sea (w = 0, τ = 1) the sea's normals are the body's own (so a hit is
    shaded as the open sea's, tests/render/test_sea_shading.py) and the foam is the sea's (A = 1, C = 0);
    dry points take nothing; inside the domain the solver's white water is C ∈ [0, w]."""
    frame = body.frame(0.0)
    assert frame.shading is not None and body.sea_body.shades_from_fields
    join = frame.shading.join
    g = body.mesh
    top = g.x.size
    far = np.flatnonzero((g.w == 0) & (g.tau_s == 1) & (g.tau_l == 1))
    # float32 unit normals recomputed from the same slopes: roundoff of their scale 1
    np.testing.assert_allclose(join.sea_normals[far], frame.normals[far], atol=10 * np.finfo(np.float32).eps)
    _, _, wet = body.surface(0.0)
    wet_far = far[wet[far]]
    assert wet_far.size > 0
    assert np.all(join.short_taper[wet_far] == 1) and np.all(join.foam_scale[wet_far] == 1)
    assert np.all(join.foam_offset[far] == 0)
    dry = np.flatnonzero(~wet)
    assert dry.size > 0
    assert not np.any(join.short_taper[dry]) and not np.any(join.foam_scale[dry]) and not np.any(join.foam_offset[dry])
    inside = np.flatnonzero(wet & (g.w > 0))
    assert inside.size > 0
    assert np.all(join.foam_offset[inside] >= 0) and np.all(join.foam_offset[inside] <= g.w[inside] + 1e-6)
    np.testing.assert_allclose(join.foam_scale[:top][wet], ((1 - g.w) * g.tau_s)[wet], rtol=1e-6)
    assert len(join.sea_normals) == len(frame.positions) == len(frame.shading.texcoords)
