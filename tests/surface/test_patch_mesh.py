"""Tests for oceanrender.surface.patch_mesh: a closed, outward-oriented water body."""

from collections import Counter

import numpy as np
import pytest

from oceanrender.surface.patch_mesh import (
    signed_volume,
    water_body_face_count,
    water_body_faces,
    water_body_vertex_count,
    water_body_vertices,
)
from oceanrender.waves.fft_ocean import FFTOcean, OceanFields, OceanGrid
from tests.tolerances import ROUNDOFF32

#: Relative tolerance of volumes computed from float32 positions.
VOLUME_RTOL = 1e-5

#: float32 vertex coordinates, relative to their magnitude (the patch size L): a few ulp of
#: float32 (eps 1.2e-7). ROUNDOFF32 × L would admit 5 mm seams, near the displacements checked.
POSITION_RTOL = 8 * float(np.finfo(np.float32).eps)


def flat_fields(n):
    """OceanFields of a sea at rest on an n × n grid."""
    zero = np.zeros((n, n))
    normals = np.zeros((n, n, 3))
    normals[..., 2] = 1.0
    return OceanFields(zero, zero, zero, zero, zero, zero + 1.0, normals)


def ocean(n, choppiness, patch_size=50.0):
    return FFTOcean(OceanGrid(n, patch_size), 6.0, 0.5, seed=4, choppiness=choppiness, small_wave_length=0.2)


def directed_edges(faces):
    return [tuple(edge) for face in faces.tolist() for edge in zip(face, face[1:] + face[:1])]


@pytest.mark.parametrize("n", [1, 2, 5, 16])
def test_faces_are_closed_and_consistently_oriented(n):
    faces = water_body_faces(n)
    assert faces.dtype == np.uint32
    assert faces.shape == (water_body_face_count(n), 3) == (2 * n * n + 12 * n, 3)
    assert faces.max() == water_body_vertex_count(n) - 1
    assert np.unique(faces).size == water_body_vertex_count(n)  # every vertex used
    assert np.all((faces[:, 0] != faces[:, 1]) & (faces[:, 1] != faces[:, 2]) & (faces[:, 2] != faces[:, 0]))
    directed = Counter(directed_edges(faces))
    assert max(directed.values()) == 1  # no edge run twice the same way
    assert all((b, a) in directed for a, b in directed)  # each edge has its opposite
    undirected = Counter(tuple(sorted(edge)) for edge in directed)
    assert set(undirected.values()) == {2}  # manifold: two faces per edge
    V, E, F = water_body_vertex_count(n), len(undirected), len(faces)
    assert V - E + F == 2  # a sphere


def test_flat_sea_volume_and_orientation():
    n, L, depth = 8, 40.0, 7.5
    positions, normals = water_body_vertices(flat_fields(n), L, depth)
    faces = water_body_faces(n)
    assert positions.dtype == normals.dtype == np.float32
    assert positions.shape == normals.shape == (water_body_vertex_count(n), 3)
    assert signed_volume(positions, faces) == pytest.approx(L * L * depth, rel=VOLUME_RTOL)
    # covers the patch exactly, from −depth to 0
    np.testing.assert_allclose(positions.min(axis=0), [-L / 2, -L / 2, -depth], rtol=0, atol=POSITION_RTOL * L)
    np.testing.assert_allclose(positions.max(axis=0), [L / 2, L / 2, 0], rtol=0, atol=POSITION_RTOL * L)
    np.testing.assert_allclose(positions[-1], [0, 0, -depth], rtol=0, atol=POSITION_RTOL * L)  # bottom centre


def face_normals(positions, faces):
    p = positions.astype(np.float64)[faces]
    return np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])


def test_wavy_sea_volume_and_top_faces_up():
    n, L, depth = 64, 50.0, 10.0
    fields = ocean(n, choppiness=0.0).fields(3.0)
    positions, normals = water_body_vertices(fields, L, depth)
    faces = water_body_faces(n)
    # the piecewise-linear surface over the periodic grid: each grid point weighs (L/n)²
    expected = L * L * depth + L * L * fields.height.mean()
    assert signed_volume(positions, faces) == pytest.approx(expected, rel=VOLUME_RTOL)
    # with an arbitrary (non-zero-mean) offset the identity still holds, so it tests the mean term
    raised = OceanFields(fields.height + 0.7, *(getattr(fields, f) for f in
                         ("displacement_x", "displacement_y", "slope_x", "slope_y", "jacobian", "normals")))
    assert signed_volume(water_body_vertices(raised, L, depth)[0], faces) == pytest.approx(
        L * L * (depth + 0.7 + fields.height.mean()), rel=VOLUME_RTOL
    )
    top = face_normals(positions, faces[: 2 * n * n])
    assert np.all(top[:, 2] > 0)
    bottom = face_normals(positions, faces[-4 * n:])
    assert np.all(bottom[:, 2] < 0)
    np.testing.assert_allclose(np.linalg.norm(normals, axis=1), 1.0, rtol=0, atol=ROUNDOFF32)  # float32, scale 1


def test_choppy_sea_wraps_periodically_and_stays_closed():
    n, L, depth = 32, 50.0, 10.0
    sea = ocean(n, choppiness=1.0)
    fields = sea.fields(1.0)
    assert np.abs(fields.displacement_x).max() > 0.01  # the displacement is really there
    positions, normals = water_body_vertices(fields, L, depth)
    top = positions[: (n + 1) ** 2].reshape(n + 1, n + 1, 3)
    # row/column n repeats row/column 0, shifted by L
    np.testing.assert_allclose(top[:, n] - top[:, 0], np.broadcast_to([L, 0, 0], (n + 1, 3)), rtol=0,
                               atol=POSITION_RTOL * L)
    np.testing.assert_allclose(top[n] - top[0], np.broadcast_to([0, L, 0], (n + 1, 3)), rtol=0, atol=POSITION_RTOL * L)
    # float32 unit vectors (scale 1) whose x, y components cross zero
    np.testing.assert_allclose(normals[: (n + 1) ** 2].reshape(n + 1, n + 1, 3)[:n, :n], fields.normals, rtol=0,
                               atol=ROUNDOFF32)
    # the displaced top stays oriented up and the body encloses about L² depth
    faces = water_body_faces(n)
    assert np.all(face_normals(positions, faces[: 2 * n * n])[:, 2] > 0)
    assert signed_volume(positions, faces) == pytest.approx(L * L * depth, rel=0.01)
    # the skirt hangs straight below the displaced border, at the bottom
    ring = positions[(n + 1) ** 2: -1]
    assert np.all(ring[:, 2] == np.float32(-depth))  # set, not computed: exact
    np.testing.assert_array_equal(ring[:n, :2], top[0, :n, :2])  # south edge, west to east (copies: exact)


def test_vertices_refuse_a_bottom_above_the_troughs():
    fields = ocean(16, choppiness=0.0).fields(0.0)
    with pytest.raises(ValueError):
        water_body_vertices(fields, 50.0, 0.5 * abs(fields.height.min()))
    with pytest.raises(ValueError):
        water_body_vertices(fields, 50.0, 0.0)
