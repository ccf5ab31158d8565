"""Export of the camera-following sea mesh for real-time engines (PLY + JSON).

The offline renders extend the sea to the horizon with a camera-centred radial
grid of fixed triangulation (:class:`oceanrender.surface.radial_mesh.RadialGrid`,
after the dissertation's camera-following mesh, ch. 3): rings whose radius grows
geometrically so that cells stay square, and per-ring levels of detail that
filter each FFT cascade by wavenumber to what the local vertex spacing resolves
(:mod:`oceanrender.waves.lod`: waves ≥ 8 vertices long whole, ≤ 2 gone), with the
slopes filtered out carried by a per-ring roughness. This module writes exactly
that mesh and its precomputed LOD table, so a shader can reproduce the offline sea:

* ``camera_mesh.ply`` — the top surface at rest, z = 0, in camera-relative
  horizontal coordinates [m] (the engine translates it with the camera in x, y),
  triangles counter-clockwise seen from above (normals +z);
* ``camera_mesh.json`` — layout (vertex 0 is the centre, then ring j's
  ``segments`` vertices at indices 1 + j·segments …), ring radii and vertex
  spacing [m], the cascades' patch sizes, grid cells and band edges [m, rad/m],
  each cascade's level cutoffs K_j [rad/m], for every ring the weight of each
  level of each cascade, and the ring's Beckmann α (the slopes it does not carry).

Displacing a vertex: p = p_rest + camera_xy + Σ_i Σ_j w_ij(ring) · D_ij(p_rest + camera_xy, t),
with D_ij cascade i's displacement map low-passed to |k| < K_j (level 0 is the
map ``oceanrender geometry`` exports; a shader gets level j from the map's
mip level j, a box-filter approximation of the exact spectral cut used offline).
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from ..io.frames import atomic_path
from ..io.ply import write_ply
from ..surface.radial_mesh import RadialGrid, radial_body_faces
from ..waves.lod import FADE_VERTICES_PER_WAVELENGTH
from ..waves.sea import SeaSurface


def camera_mesh_top_faces(rings: int, segments: int) -> np.ndarray:
    """Triangles of the top surface only (the centre fan and the ring quads), uint32 (F, 3)."""
    count = segments + 2 * segments * (rings - 1)
    return radial_body_faces(rings, segments)[:count]


def camera_mesh_table(scene) -> dict:
    """The JSON description of the scene's camera-following mesh and its LOD weights and roughness."""
    mesh = scene.mesh
    grid = RadialGrid.square_cells((0.0, 0.0), mesh.inner_radius, mesh.outer_radius, mesh.segments)
    spacing = grid.spacing[1:].reshape(grid.rings, grid.segments)[:, 0]
    sea = SeaSurface(scene.ocean)
    if sea.cascades is None:
        raise ValueError("the camera-mesh LOD table is for the FFT sea ([ocean] model = 'FFT')")
    patches = [float(p) for p in sea.cascades.patch_sizes]
    alpha = np.sqrt(sea.unresolved_slope_variance(spacing))
    return {
        "description": "camera-following sea mesh with fixed triangulation (oceanrender.export.camera_mesh)",
        "units": {"length": "m", "wavenumber": "rad/m"},
        "layout": "vertex 0: centre; ring j (0-based) vertex k at index 1 + j*segments + k, angle 2*pi*k/segments "
                  "counter-clockwise from +x (east); +y north, z up; positions relative to the camera's x, y",
        "rings": int(grid.rings),
        "segments": int(grid.segments),
        "inner_radius_m": float(mesh.inner_radius),
        "outer_radius_m": float(mesh.outer_radius),
        "ring_radius_m": [float(r) for r in grid.radii],
        "ring_spacing_m": [float(s) for s in spacing],
        "cascade_patch_size_m": patches,
        "cascade_cell_m": [float(g.spacing) for g in sea.cascades.grids],
        "cascade_band_edges_rad_m": [float(k) for k in sea.cascades.band_edges],
        "cascade_level_cutoffs_rad_m": [[float(k) for k in levels.cutoffs] for levels in sea.levels],
        "lod_rule": f"per cascade, level coordinate s = clip(log2(k_top * {FADE_VERTICES_PER_WAVELENGTH:g} * spacing "
                    "/ (2 pi)), 0, levels - 1); weight 1 - frac(s) on level floor(s) and frac(s) on the next. "
                    "Waves at least 8 vertices long are whole, at most 2 (Nyquist) gone (oceanrender.waves.lod)",
        "lod_weight_per_ring": [[[float(w) for w in levels.weights(np.array([s]), (1,))[:, 0]] for levels in sea.levels]
                                for s in spacing],
        "centre_vertex_lod_weight": [[float(w) for w in levels.weights(np.array([mesh.inner_radius]), (1,))[:, 0]]
                                     for levels in sea.levels],
        "roughness_rule": "Beckmann alpha = sqrt(total slope variance of the spectrum (60 km .. 1 mm) - slope "
                          "variance the ring's vertices carry), so the two add up to the spectrum's at every ring",
        "total_slope_variance": float(sea.total_slope_variance),
        "ring_beckmann_alpha": [float(a) for a in alpha],
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
