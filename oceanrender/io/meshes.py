"""Reading the meshes of a scene's objects (OBJ, PLY, glTF/GLB) with ``trimesh``.

``trimesh`` (MIT) reads all four formats with numpy alone, merges the nodes of a
glTF scene with their transforms, and gives vertex normals and texture
coordinates where the file has them; writing a reader per format here would only
repeat it. A file is read once and checked: a non-empty triangle mesh with finite
vertices, faces that index them, and, for floating, a closed surface.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from .paths import PathProblem, check_input_file

__all__ = ["MESH_SUFFIXES", "MAX_MESH_BYTES", "MAX_MESH_TRIANGLES", "MeshProblem", "TriangleMesh", "read_mesh"]

#: File suffixes read, lower case.
MESH_SUFFIXES = (".obj", ".ply", ".gltf", ".glb")
#: Largest mesh file accepted [bytes] and most triangles (a bound on memory, not on detail).
MAX_MESH_BYTES = 512 * 1024 * 1024
MAX_MESH_TRIANGLES = 20_000_000


class MeshProblem(ValueError):
    """A mesh file that cannot be used; one line, without the key (the caller adds it)."""


@dataclass(frozen=True)
class TriangleMesh:
    """A triangle mesh in its file's own frame.

    Attributes
    ----------
    vertices : (V, 3) ndarray    Positions [file units; metres in a scene].
    faces : (F, 3) ndarray       Vertex indices, counter-clockwise seen from outside.
    normals : (V, 3) ndarray     Unit vertex normals [-].
    uv : (V, 2) ndarray or None  Texture coordinates, where the file has them.
    closed : bool                Every edge is shared by exactly two faces (a watertight hull).
    """

    vertices: NDArray[np.float64]
    faces: NDArray[np.int64]
    normals: NDArray[np.float64]
    uv: NDArray[np.float64] | None
    closed: bool


def read_mesh(path: str | Path) -> TriangleMesh:
    """Read a mesh file (OBJ, PLY, glTF, GLB) into one :class:`TriangleMesh`; :class:`MeshProblem` if unusable."""
    import trimesh  # noqa: PLC0415

    try:
        path = check_input_file(path, MAX_MESH_BYTES)
    except PathProblem as exc:
        raise MeshProblem(str(exc)) from None
    suffix = path.suffix.lower()
    if suffix not in MESH_SUFFIXES:
        raise MeshProblem(f"{path}: expected a mesh file ending in {', '.join(MESH_SUFFIXES)}, got {suffix or 'none'!r}")
    try:
        loaded = trimesh.load(str(path), force="mesh", process=False)
    except Exception as exc:  # noqa: BLE001 - trimesh raises many types on a broken file
        raise MeshProblem(f"{path}: not a readable {suffix[1:].upper()} mesh ({type(exc).__name__}: {exc})") from None
    if not isinstance(loaded, trimesh.Trimesh) or len(loaded.faces) == 0:
        raise MeshProblem(f"{path}: holds no triangles")
    if len(loaded.faces) > MAX_MESH_TRIANGLES:
        raise MeshProblem(f"{path}: {len(loaded.faces)} triangles, more than the {MAX_MESH_TRIANGLES} accepted")
    vertices = np.asarray(loaded.vertices, dtype=np.float64)
    faces = np.asarray(loaded.faces, dtype=np.int64)
    if not np.all(np.isfinite(vertices)):
        raise MeshProblem(f"{path}: has non-finite vertex positions")
    if faces.min() < 0 or faces.max() >= len(vertices):
        raise MeshProblem(f"{path}: has faces that index no vertex")
    normals = np.asarray(loaded.vertex_normals, dtype=np.float64)
    uv = getattr(loaded.visual, "uv", None)
    uv = None if uv is None or len(uv) != len(vertices) else np.asarray(uv, dtype=np.float64)
    return TriangleMesh(vertices, faces, normals, uv, bool(loaded.is_watertight))
