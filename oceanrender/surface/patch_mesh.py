"""A closed water-body triangle mesh built from FFT ocean fields.

The water body is the volume between the displaced sea surface of one periodic
patch and a flat bottom at z = −depth: a watertight, consistently oriented
mesh with outward normals, as a Mitsuba dielectric boundary around a medium
needs. The topology (:func:`water_body_faces`) depends on the grid size only,
so a renderer builds it once and updates the vertex positions per frame
(:func:`water_body_vertices`).

Vertex layout for an n × n field, V = (n + 1)² + 4n + 1:

* ``[0, (n+1)²)``: top surface, row-major ``[iy, ix]`` with iy, ix = 0 … n;
  the vertex (iy, ix) sits at (x_ix + λDx, y_iy + λDy, η) with
  x_ix = −L/2 + ix L/n and the field sampled at (iy mod n, ix mod n): the
  periodic field wraps, so row/column n repeats row/column 0 shifted by L.
* ``[(n+1)², (n+1)² + 4n)``: bottom ring, directly below the top border
  vertices (counter-clockwise seen from above, starting at the corner
  (−L/2, −L/2)), at z = −depth.
* ``(n+1)² + 4n``: bottom centre, below the mean of the ring.

Faces, F = 2n² + 12n: 2n² top triangles, 8n side-wall triangles and a fan of
4n bottom triangles; all counter-clockwise seen from outside.

Conventions: z up, lengths in m, float32 positions and normals (Mitsuba's).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..waves.fft_ocean import OceanFields

__all__ = [
    "water_body_vertex_count",
    "water_body_face_count",
    "water_body_faces",
    "heightfield_body_faces",
    "water_body_vertices",
    "signed_volume",
]


def water_body_vertex_count(n: int) -> int:
    """Number of vertices V = (n + 1)² + 4n + 1 of the water body of an n × n field [-]."""
    return (n + 1) ** 2 + 4 * n + 1


def water_body_face_count(n: int) -> int:
    """Number of triangles F = 2n² + 12n of the water body of an n × n field [-]."""
    return 2 * n * n + 12 * n


def _border_ring(n: int, nx: int | None = None) -> tuple[NDArray[np.int64], NDArray[np.int64]]:
    """Top-grid (iy, ix) of the 2(n + nx) border vertices of an n × nx-cell grid, counter-clockwise from +z."""
    ny, nx = n, n if nx is None else nx
    east, north = np.arange(nx), np.arange(ny)
    iy = np.concatenate([np.zeros(nx, int), north, np.full(nx, ny), north[::-1] + 1])  # south, east, north, west
    ix = np.concatenate([east, np.full(ny, nx), east[::-1] + 1, np.zeros(ny, int)])
    return iy, ix


def heightfield_body_faces(ny: int, nx: int) -> NDArray[np.uint32]:
    """Triangles of a closed body over an ny × nx-cell heightfield, shape (2 ny nx + 6(ny + nx), 3).

    Vertex layout: the (ny + 1) × (nx + 1) top grid row-major ``[iy, ix]``
    (x east along ix, y north along iy), then the bottom ring of 2(ny + nx)
    vertices below the top border (counter-clockwise from +z, starting at the
    south-west corner), then the bottom centre. Every triangle is
    counter-clockwise seen from outside.
    """
    if int(ny) != ny or int(nx) != nx or ny < 1 or nx < 1:
        raise ValueError(f"ny and nx must be positive integers, got {ny!r}, {nx!r}")
    stride = nx + 1
    iy, ix = np.meshgrid(np.arange(ny), np.arange(nx), indexing="ij")
    v00 = (iy * stride + ix).ravel()
    v10, v01 = v00 + 1, v00 + stride  # east and north neighbours
    v11 = v01 + 1
    top = np.concatenate([np.stack([v00, v10, v11], 1), np.stack([v00, v11, v01], 1)])

    ring_iy, ring_ix = _border_ring(ny, nx)
    count = len(ring_iy)
    t0 = ring_iy * stride + ring_ix  # top border vertex r
    t1 = np.roll(t0, -1)  # top border vertex r + 1
    b0 = (ny + 1) * stride + np.arange(count)  # bottom ring vertex r
    b1 = np.roll(b0, -1)
    centre = (ny + 1) * stride + count
    # the ring runs counter-clockwise, so the outside is on its right
    sides = np.concatenate([np.stack([b0, b1, t1], 1), np.stack([b0, t1, t0], 1)])
    bottom = np.stack([np.full(count, centre), b1, b0], 1)  # normal −z
    return np.concatenate([top, sides, bottom]).astype(np.uint32)


def water_body_faces(n: int) -> NDArray[np.uint32]:
    """Triangles of the closed water body of an n × n field, shape (2n² + 12n, 3).

    Parameters
    ----------
    n : int
        Grid points per side of the ocean fields [-].

    Returns
    -------
    ndarray, uint32
        Vertex indices (see the module docstring for the layout), each triangle
        counter-clockwise seen from outside the water.
    """
    if int(n) != n or n < 1:
        raise ValueError(f"n must be a positive integer, got {n!r}")
    return heightfield_body_faces(n, n)


def water_body_vertices(
    fields: OceanFields, patch_size: float, depth: float
) -> tuple[NDArray[np.float32], NDArray[np.float32]]:
    """Vertex positions and normals of the closed water body (see the module docstring).

    Parameters
    ----------
    fields : OceanFields
        Ocean fields on an n × n grid (``displacement_*`` already scaled by λ).
    patch_size : float
        Side L of the periodic patch [m].
    depth : float
        Depth of the flat bottom below the mean sea level [m]; must exceed the
        deepest trough.

    Returns
    -------
    positions : ndarray, float32, shape ((n+1)² + 4n + 1, 3)
        Vertex positions [m].
    normals : ndarray, float32, shape ((n+1)² + 4n + 1, 3)
        Unit vertex normals [-]: ``fields.normals`` on the top surface,
        (0, 0, −1) on the bottom ring and centre.

    Notes
    -----
    The side walls share their upper vertices with the sea surface, so their
    interpolated vertex normals blend the surface normal with (0, 0, −1).
    The walls close the volume; where they can be seen, render the mesh with
    face normals. The bottom fan assumes the displaced border is star-shaped
    around its mean, which holds unless the choppy displacement near the
    border is comparable to L.
    """
    n = fields.resolution
    if not depth > 0:
        raise ValueError(f"depth must be > 0 [m], got {depth!r}")
    wrap = np.arange(n + 1) % n
    coordinate = -patch_size / 2 + patch_size / n * np.arange(n + 1)
    top = np.empty((n + 1, n + 1, 3))
    top[..., 0] = coordinate[None, :] + fields.displacement_x[np.ix_(wrap, wrap)]
    top[..., 1] = coordinate[:, None] + fields.displacement_y[np.ix_(wrap, wrap)]
    top[..., 2] = fields.height[np.ix_(wrap, wrap)]
    if not np.all(top[..., 2] > -depth):
        raise ValueError(f"depth {depth} m does not clear the deepest trough {top[..., 2].min():.3g} m")

    ring_iy, ring_ix = _border_ring(n)
    ring = top[ring_iy, ring_ix].copy()
    ring[:, 2] = -depth
    centre = np.array([[*ring[:, :2].mean(axis=0), -depth]])
    positions = np.concatenate([top.reshape(-1, 3), ring, centre])

    down = np.zeros((4 * n + 1, 3))
    down[:, 2] = -1.0
    normals = np.concatenate([fields.normals[np.ix_(wrap, wrap)].reshape(-1, 3), down])
    return positions.astype(np.float32), normals.astype(np.float32)


def signed_volume(positions: ArrayLike, faces: ArrayLike) -> float:
    """Signed volume enclosed by a closed triangle mesh [m³].

    Parameters
    ----------
    positions : array_like, shape (V, 3)
        Vertex positions [m].
    faces : array_like, shape (F, 3)
        Vertex indices of the triangles.

    Returns
    -------
    float
        Σ det(v0, v1, v2)/6 over the triangles (divergence theorem) [m³];
        positive when the triangles are counter-clockwise seen from outside.

    References
    ----------
    .. [1] C. Zhang and T. Chen, "Efficient feature extraction for 2D/3D objects
       in mesh representation", Proc. ICIP 2001, vol. 3, 935–938,
       doi:10.1109/ICIP.2001.958278.
    """
    p = np.asarray(positions, dtype=np.float64)
    v0, v1, v2 = (p[np.asarray(faces)[:, i]] for i in range(3))
    return float(np.einsum("ij,ij->", v0, np.cross(v1, v2)) / 6)  # tetrahedra on the origin, [1]
