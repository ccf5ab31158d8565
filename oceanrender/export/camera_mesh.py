"""Export of the camera-following sea mesh for real-time engines (PLY + JSON).

The offline renders extend the sea to the horizon with a camera-centred radial
grid of fixed triangulation (:class:`oceanrender.surface.radial_mesh.RadialGrid`,
after the dissertation's camera-following mesh, ch. 3): rings whose radius grows
geometrically so that cells stay square, and per-ring levels of detail that fade
out the FFT cascades too fine for the local vertex spacing
(:func:`oceanrender.waves.sea.lod_weight`). This module writes exactly that
mesh and its precomputed LOD table, so a shader can reproduce the offline sea:

* ``camera_mesh.ply`` — the top surface at rest, z = 0, in camera-relative
  horizontal coordinates [m] (the engine translates it with the camera in x, y),
  triangles counter-clockwise seen from above (normals +z);
* ``camera_mesh.json`` — layout (vertex 0 is the centre, then ring j's
  ``segments`` vertices at indices 1 + j·segments …), ring radii and vertex
  spacing [m], the cascades' patch sizes and grid cells [m], and for every ring
  the weight in [0, 1] with which each cascade's displacement is added there.

Displacing a vertex: p = p_rest + camera_xy + Σ_i w_i(ring) · D_i(p_rest + camera_xy, t),
with D_i the displacement map of cascade i (``oceanrender geometry`` exports them).
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from ..io.frames import atomic_path
from ..io.ply import write_ply
from ..surface.radial_mesh import RadialGrid, radial_body_faces
from ..waves.cascades import cascade_patch_sizes
from ..waves.sea import lod_weight


def camera_mesh_top_faces(rings: int, segments: int) -> np.ndarray:
    """Triangles of the top surface only (the centre fan and the ring quads), uint32 (F, 3)."""
    count = segments + 2 * segments * (rings - 1)
    return radial_body_faces(rings, segments)[:count]


def camera_mesh_table(scene) -> dict:
    """The JSON description of the scene's camera-following mesh and its LOD weights."""
    mesh, ocean = scene.mesh, scene.ocean
    grid = RadialGrid.square_cells((0.0, 0.0), mesh.inner_radius, mesh.outer_radius, mesh.segments)
    spacing = grid.spacing[1:].reshape(grid.rings, grid.segments)[:, 0]
    patches = [float(p) for p in cascade_patch_sizes(ocean.patch_size, ocean.cascades)]
    cells = [p / ocean.resolution for p in patches]
    weights = [[float(lod_weight(np.array([s]), cell)[0]) for cell in cells] for s in spacing]
    return {
        "description": "camera-following sea mesh with fixed triangulation (oceanrender.export.camera_mesh)",
        "units": {"length": "m"},
        "layout": "vertex 0: centre; ring j (0-based) vertex k at index 1 + j*segments + k, angle 2*pi*k/segments "
                  "counter-clockwise from +x (east); +y north, z up; positions relative to the camera's x, y",
        "rings": int(grid.rings),
        "segments": int(grid.segments),
        "inner_radius_m": float(mesh.inner_radius),
        "outer_radius_m": float(mesh.outer_radius),
        "ring_radius_m": [float(r) for r in grid.radii],
        "ring_spacing_m": [float(s) for s in spacing],
        "cascade_patch_size_m": patches,
        "cascade_cell_m": cells,
        "lod_rule": "w = clip(1 - log2(spacing / cell) / 2, 0, 1): 1 where vertices are as fine as the "
                    "cascade's grid, 0 where four times coarser (oceanrender.waves.sea.lod_weight)",
        "lod_weight_per_ring": weights,
        "centre_vertex_lod_weight": [float(lod_weight(np.array([mesh.inner_radius]), c)[0]) for c in cells],
        "vertex_count": int(grid.top_vertex_count),
        "face_count": int(len(camera_mesh_top_faces(grid.rings, grid.segments))),
        "scene": scene.name,
    }


def export_camera_mesh(scene, out_dir: str | Path) -> tuple[Path, Path]:
    """Write ``camera_mesh.ply`` and ``camera_mesh.json`` into ``out_dir`` (atomically); return their paths."""
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    mesh = scene.mesh
    grid = RadialGrid.square_cells((0.0, 0.0), mesh.inner_radius, mesh.outer_radius, mesh.segments)
    positions = np.column_stack([grid.points, np.zeros(grid.top_vertex_count)])
    normals = np.tile([0.0, 0.0, 1.0], (grid.top_vertex_count, 1))
    faces = camera_mesh_top_faces(grid.rings, grid.segments)
    ply = out / "camera_mesh.ply"
    write_ply(ply, positions, faces, normals, comments={"scene": scene.name, "layout": "see camera_mesh.json"})
    table = camera_mesh_table(scene)
    path = out / "camera_mesh.json"
    with atomic_path(path, ".json") as tmp:
        tmp.write_text(json.dumps(table, indent=2))
    return ply, path
