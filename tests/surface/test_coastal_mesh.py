"""Coastal meshes: a closed, outward water body over the terrain; dry cells under the land."""

import numpy as np
import pytest

from oceanrender.surface.coastal_mesh import (
    DRY_DROP,
    terrain_mesh,
    water_body_faces,
    water_body_vertices,
    water_surface_heights,
)
from oceanrender.surface.patch_mesh import heightfield_body_faces, signed_volume
from oceanrender.surface.patch_mesh import water_body_faces as patch_faces
from tests.tolerances import ROUNDOFF, ROUNDOFF32

SPACING, ORIGIN = (0.5, 0.25), (-3.0, 10.0)

#: float32 vertex coordinates, relative to their magnitude: a few ulp of float32 (eps 1.2e-7),
#: far below the cells (ROUNDOFF32 of 13 m would be a millimetre).
POSITION_RTOL = 8 * float(np.finfo(np.float32).eps)


def beach(ny=12, nx=9):
    y = ORIGIN[1] + (np.arange(ny) + 0.5) * SPACING[1]
    bed = np.broadcast_to(0.4 - 0.3 * (y - y[0])[:, None], (ny, nx)).copy()
    depth = np.maximum(0.0 - bed, 0.0)
    return bed, depth


def edges(faces):
    e = np.concatenate([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]]])
    return e


def test_water_body_is_closed_and_oriented_outwards():
    bed, depth = beach()
    faces = water_body_faces(bed.shape)
    positions, normals = water_body_vertices(bed, depth, SPACING, ORIGIN, h_min=1e-3)
    # Watertight and consistently oriented: every directed edge appears once, its reverse once.
    e = edges(faces.astype(np.int64))
    directed = set(map(tuple, e))
    assert len(directed) == len(e)
    assert all((b, a) in directed for a, b in directed)
    # Outward normals ⇒ positive signed volume, equal to the prism volume over the grid's span.
    assert signed_volume(positions, faces) > 0
    np.testing.assert_allclose(np.linalg.norm(normals, axis=1), 1.0, rtol=0, atol=ROUNDOFF32)  # float32, scale 1


def test_heightfield_faces_generalise_the_square_patch():
    np.testing.assert_array_equal(heightfield_body_faces(7, 7), patch_faces(7))
    faces = heightfield_body_faces(3, 5)
    assert faces.shape == (2 * 3 * 5 + 6 * (3 + 5), 3)


def test_dry_cells_lie_under_the_terrain_and_wet_cells_at_the_surface():
    bed, depth = beach()
    z = water_surface_heights(bed, depth, h_min=1e-3)
    wet = depth > 1e-3
    assert wet.any() and (~wet).any()
    scale = np.abs(bed).max()  # elevations cross 0 at the still level: relative to the terrain's relief
    np.testing.assert_allclose(z[wet], (bed + depth)[wet], rtol=0, atol=ROUNDOFF * scale)
    np.testing.assert_allclose(z[~wet], bed[~wet] - DRY_DROP, rtol=0, atol=ROUNDOFF * scale)
    positions, _ = water_body_vertices(bed, depth, SPACING, ORIGIN, h_min=1e-3)
    t_positions, t_faces, t_normals = terrain_mesh(bed, SPACING, ORIGIN)
    ny, nx = bed.shape
    # Same vertices in x, y; the terrain is open (no walls) with upward normals.
    np.testing.assert_allclose(positions[: ny * nx, :2], t_positions[:, :2], rtol=0,
                               atol=POSITION_RTOL * np.abs(t_positions[:, :2]).max())
    assert len(t_faces) == 2 * (ny - 1) * (nx - 1)
    assert np.all(t_normals[:, 2] > 0)
    # Cell centres at origin + (i + ½) Δ.
    assert t_positions[0, 0] == pytest.approx(ORIGIN[0] + SPACING[0] / 2)
    assert t_positions[nx, 1] == pytest.approx(ORIGIN[1] + 1.5 * SPACING[1])


def test_shading_normals_follow_water_and_beach_not_the_hidden_drop():
    bed, depth = beach()
    _, normals = water_body_vertices(bed, depth, SPACING, ORIGIN, h_min=1e-3)
    ny, nx = bed.shape
    top = normals[: ny * nx].reshape(ny, nx, 3)
    # Flat still water: vertical normals in the wet interior; the beach tilts towards −y… at most its slope.
    wet = depth > 1e-3
    interior = wet & np.roll(wet, 1, 0) & np.roll(wet, -1, 0)
    np.testing.assert_allclose(top[interior][:, 2], 1.0, rtol=0, atol=ROUNDOFF32)  # float32 unit vectors: scale 1
    slope_cos = 1.0 / np.hypot(1.0, 0.3)
    assert np.all(top[..., 2] >= slope_cos - ROUNDOFF32)
