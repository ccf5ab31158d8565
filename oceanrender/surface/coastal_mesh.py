"""Meshes of the coastal zone: the closed water body over the terrain, and the terrain.

Both are heightfields over the solver's cell centres with the same
triangulation, so that where a cell is dry the water surface can be put a
little *below* the terrain (``dry_drop``) and disappears under the opaque
land. The water body keeps one fixed topology for the whole run (the renderer
updates vertex positions per frame, as for the open sea), dry cells are
removed from sight by the terrain, and the visible waterline is where the two
surfaces cross: between cell centres, linearly, not along cell edges — a
smooth shoreline instead of a staircase.

The water body is closed (side walls down to a flat base below the deepest
bed, and the base) and oriented outward, as a Mitsuba dielectric boundary
around a medium needs; the terrain lies inside it wherever there is water,
and the renderer gives it no medium of its own, so rays in the water that meet
the seafloor stay in the water.

Conventions: z up, lengths in m; cell (j, i) has its centre at
(x0 + (i + ½) dx, y0 + (j + ½) dy).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from ..scene.arrays import cell_centres
from .patch_mesh import _border_ring, heightfield_body_faces

#: How far below the bed the water surface is put in dry cells [m].
DRY_DROP = 0.02


def heightfield_normals(z: NDArray, dx: float, dy: float) -> NDArray[np.float64]:
    """Unit normals (ny, nx, 3) of the heightfield z(y, x) [m] by central differences (one-sided at edges)."""
    dz_dy, dz_dx = np.gradient(np.asarray(z, dtype=np.float64), dy, dx)
    n = np.stack([-dz_dx, -dz_dy, np.ones_like(dz_dx)], axis=-1)
    return n / np.linalg.norm(n, axis=-1, keepdims=True)


def water_body_faces(shape: tuple[int, int]) -> NDArray[np.uint32]:
    """Triangles of the coastal water body over a (ny, nx) cell grid (fixed for the whole run)."""
    ny, nx = shape
    return heightfield_body_faces(ny - 1, nx - 1)


def water_surface_heights(bed: NDArray, depth: NDArray, h_min: float, dry_drop: float = DRY_DROP) -> NDArray:
    """Heights [m] of the water-surface vertices: η = z_b + h where wet (h > h_min), z_b − ``dry_drop`` where dry."""
    return np.where(depth > h_min, bed + depth, bed - dry_drop)


def water_body_vertices(bed: NDArray, depth: NDArray, spacing: tuple[float, float], origin: tuple[float, float],
                        h_min: float, dry_drop: float = DRY_DROP) -> tuple[NDArray[np.float32], NDArray[np.float32]]:
    """Vertex positions [m] and unit normals of the closed coastal water body.

    Parameters
    ----------
    bed : ndarray (ny, nx)     Bed elevation z_b at the cell centres [m].
    depth : ndarray (ny, nx)   Water depth h [m].
    spacing : (dx, dy)         Cell size [m].
    origin : (x0, y0)          World position of the grid's south-west corner [m].
    h_min : float              Dry threshold of the solver [m].
    dry_drop : float           Depth of the water surface below the bed in dry cells [m].

    Returns
    -------
    positions, normals : ndarray float32, shape (ny nx + 2(ny + nx − 2) + 1, 3)

    Notes
    -----
    The normals of the surface come from the heightfield max(η, z_b) where wet
    and z_b where dry, so that the shading normals of the wet vertices next to
    the shoreline follow the water and the beach, not the hidden drop.
    """
    bed = np.asarray(bed, dtype=np.float64)
    depth = np.asarray(depth, dtype=np.float64)
    ny, nx = bed.shape
    x, y = cell_centres(bed.shape, spacing, origin)
    top = np.empty((ny, nx, 3))
    top[..., 0] = x[None, :]
    top[..., 1] = y[:, None]
    top[..., 2] = water_surface_heights(bed, depth, h_min, dry_drop)
    shading = np.where(depth > h_min, bed + depth, bed)
    normals_top = heightfield_normals(shading, spacing[0], spacing[1])

    base = float(bed.min()) - 1.0
    ring_iy, ring_ix = _border_ring(ny - 1, nx - 1)
    ring = top[ring_iy, ring_ix].copy()
    ring[:, 2] = base
    centre = np.array([[*ring[:, :2].mean(axis=0), base]])
    positions = np.concatenate([top.reshape(-1, 3), ring, centre])
    down = np.zeros((len(ring) + 1, 3))
    down[:, 2] = -1.0
    normals = np.concatenate([normals_top.reshape(-1, 3), down])
    return positions.astype(np.float32), normals.astype(np.float32)


def terrain_mesh(bed: NDArray, spacing: tuple[float, float], origin: tuple[float, float]):
    """(positions, faces, normals) of the terrain heightfield z_b over the cell centres (open surface, normals up)."""
    bed = np.asarray(bed, dtype=np.float64)
    ny, nx = bed.shape
    x, y = cell_centres(bed.shape, spacing, origin)
    positions = np.stack(np.broadcast_arrays(x[None, :], y[:, None], bed), axis=-1).reshape(-1, 3)
    faces = heightfield_body_faces(ny - 1, nx - 1)[: 2 * (ny - 1) * (nx - 1)]
    normals = heightfield_normals(bed, spacing[0], spacing[1]).reshape(-1, 3)
    return positions.astype(np.float32), faces, normals.astype(np.float32)
