"""The camera-centred radial water body: closed, oriented, square cells."""

from collections import Counter

import numpy as np
import pytest

from oceanrender.surface.patch_mesh import signed_volume
from oceanrender.surface.radial_mesh import RadialGrid, radial_body_faces, radial_body_vertices


def flat(grid):
    displacement = np.zeros((grid.top_vertex_count, 3))
    normals = np.tile([0.0, 0.0, 1.0], (grid.top_vertex_count, 1))
    return displacement, normals


@pytest.mark.parametrize(("rings", "segments"), [(2, 3), (3, 8), (10, 32)])
def test_closed_and_consistently_oriented(rings, segments):
    faces = radial_body_faces(rings, segments)
    vertex_count = 1 + rings * segments + segments + 1
    assert faces.dtype == np.uint32 and faces.max() == vertex_count - 1
    directed = Counter((a, b) for f in faces.tolist() for a, b in zip(f, f[1:] + f[:1]))
    assert max(directed.values()) == 1
    assert all((b, a) in directed for a, b in directed)
    edges = {tuple(sorted(e)) for e in directed}
    assert vertex_count - len(edges) + len(faces) == 2  # a sphere


def test_flat_volume_is_the_polygon_prism():
    grid = RadialGrid((3.0, -2.0), 0.5, 100.0, rings=12, segments=64)
    positions, normals = radial_body_vertices(grid, *flat(grid), depth=20.0)
    faces = radial_body_faces(grid.rings, grid.segments)
    polygon_area = 0.5 * grid.segments * grid.outer_radius**2 * np.sin(2 * np.pi / grid.segments)
    assert signed_volume(positions, faces) == pytest.approx(polygon_area * 20.0, rel=1e-5)  # float32 positions
    p = positions.astype(float)[faces]
    n = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    top = np.all(np.abs(p[:, :, 2]) < 1e-9, axis=1)  # z is exactly 0 on the flat top, −20 m below
    assert np.all(n[top, 2] > 0)  # the sea surface faces up
    assert normals.shape == positions.shape


def test_square_cells_and_geometric_rings():
    grid = RadialGrid.square_cells((0.0, 0.0), 1.0, 5000.0, segments=256)
    ratios = grid.radii[1:] / grid.radii[:-1]
    np.testing.assert_allclose(ratios, ratios[0])
    angular = 2 * np.pi * grid.radii / grid.segments
    radial = np.diff(grid.radii)
    np.testing.assert_allclose(radial / angular[:-1], 1.0, atol=0.01)
    assert grid.radii[-1] == pytest.approx(5000.0)
    assert np.all(np.diff(grid.spacing[1:: grid.segments]) > 0)  # cells grow outwards


def test_refuses_bad_input():
    with pytest.raises(ValueError, match="radii"):
        RadialGrid((0, 0), 10.0, 5.0, 4, 8)
    grid = RadialGrid((0, 0), 1.0, 10.0, 3, 8)
    displacement, normals = flat(grid)
    displacement[:, 2] = -3.0
    with pytest.raises(ValueError, match="deepest trough"):
        radial_body_vertices(grid, displacement, normals, depth=2.0)
