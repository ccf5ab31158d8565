"""Binary little-endian PLY triangle meshes: an atomic writer and a reader for tests.

The files hold one ``vertex`` element with float32 ``x y z`` and, optionally,
``nx ny nz``, and one ``face`` element with a ``uchar`` count and ``uint``
indices (``property list uchar uint vertex_indices``), the layout Mitsuba's
``ply`` shape, Blender, MeshLab, trimesh and plyfile read. Lengths are in the
caller's unit (m in oceanrender); z up.

References
----------
.. [1] G. Turk, "The PLY Polygon File Format", 1994,
   https://paulbourke.net/dataformats/ply/
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Mapping

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .frames import atomic_path

__all__ = ["PlyMesh", "write_ply", "read_ply"]

#: PLY scalar type names [1] and their little-endian numpy types.
_PLY_TYPES = {
    "char": "i1", "int8": "i1", "uchar": "u1", "uint8": "u1",
    "short": "<i2", "int16": "<i2", "ushort": "<u2", "uint16": "<u2",
    "int": "<i4", "int32": "<i4", "uint": "<u4", "uint32": "<u4",
    "float": "<f4", "float32": "<f4", "double": "<f8", "float64": "<f8",
}  # fmt: skip


@dataclass(frozen=True)
class PlyMesh:
    """A polygon mesh as read from a PLY file.

    Attributes
    ----------
    positions : ndarray, float32, shape (V, 3)
        Vertex positions.
    faces : ndarray, uint32, shape (F, k)
        Vertex indices of each face (all faces have k corners).
    normals : ndarray, float32, shape (V, 3), or None
        Vertex normals, if the file has them.
    comments : tuple of str
        The header's comment lines, without the ``comment`` keyword.
    """

    positions: NDArray[np.float32]
    faces: NDArray[np.uint32]
    normals: NDArray[np.float32] | None
    comments: tuple[str, ...]


def write_ply(
    path: str | Path,
    positions: ArrayLike,
    faces: ArrayLike,
    normals: ArrayLike | None = None,
    comments: Mapping[str, object] | None = None,
) -> None:
    """Write a binary little-endian PLY mesh atomically.

    Parameters
    ----------
    path : str or Path
        Destination; written to a temporary file in the same folder, then renamed.
    positions : array_like, shape (V, 3)
        Vertex positions, stored as float32.
    faces : array_like of int, shape (F, k), 3 ≤ k ≤ 255
        Vertex indices in [0, V), stored as uint32.
    normals : array_like, shape (V, 3), optional
        Vertex normals, stored as float32.
    comments : mapping, optional
        Written as ``comment key: value`` header lines (single-line text only).
    """
    p = np.asarray(positions, dtype=np.float32)
    f = np.asarray(faces)
    if p.ndim != 2 or p.shape[1] != 3:
        raise ValueError(f"positions must have shape (V, 3), got {p.shape}")
    if f.ndim != 2 or not 3 <= f.shape[1] <= 255:
        raise ValueError(f"faces must have shape (F, k) with 3 ≤ k ≤ 255, got {f.shape}")
    if f.size and not (np.issubdtype(f.dtype, np.integer) and f.min() >= 0 and f.max() < len(p)):
        raise ValueError(f"faces must be integer indices in [0, {len(p)})")
    columns = [p]
    properties = ["x", "y", "z"]
    if normals is not None:
        n = np.asarray(normals, dtype=np.float32)
        if n.shape != p.shape:
            raise ValueError(f"normals must have the shape of positions {p.shape}, got {n.shape}")
        columns.append(n)
        properties += ["nx", "ny", "nz"]

    lines = ["ply", "format binary_little_endian 1.0"]
    for key, value in (comments or {}).items():
        text = f"{key}: {value}"
        if "\n" in text or "\r" in text or not text.isascii():
            raise ValueError(f"PLY comments must be single-line ASCII, got {text!r}")
        lines.append(f"comment {text}")
    lines.append(f"element vertex {len(p)}")
    lines += [f"property float {name}" for name in properties]
    lines += [f"element face {len(f)}", "property list uchar uint vertex_indices", "end_header"]
    header = ("\n".join(lines) + "\n").encode("ascii")

    vertices = np.ascontiguousarray(np.concatenate(columns, axis=1), dtype="<f4")
    face_records = np.empty(len(f), dtype=[("count", "u1"), ("indices", "<u4", (f.shape[1],))])
    face_records["count"] = f.shape[1]
    face_records["indices"] = f
    with atomic_path(path, ".ply") as tmp, open(tmp, "wb") as stream:
        stream.write(header)
        stream.write(vertices.tobytes())
        stream.write(face_records.tobytes())


def read_ply(path: str | Path) -> PlyMesh:
    """Read a binary little-endian PLY mesh with a uniform face size.

    Parameters
    ----------
    path : str or Path
        A file as :func:`write_ply` writes it; other binary little-endian files
        work if their vertex properties are scalars including ``x y z`` and all
        faces have the same number of corners.

    Returns
    -------
    PlyMesh
    """
    data = Path(path).read_bytes()
    end = data.find(b"end_header")
    if not data.startswith(b"ply") or end < 0:
        raise ValueError(f"{path}: not a PLY file")
    body_start = data.index(b"\n", end) + 1
    lines = data[:end].decode("ascii").splitlines()
    if "format binary_little_endian 1.0" not in (line.strip() for line in lines):
        raise ValueError(f"{path}: only binary_little_endian 1.0 PLY files are supported")

    comments, elements = [], []  # elements: [name, count, [(property, type or (count, index type))]]
    for line in lines[1:]:
        words = line.split()
        if not words or words[0] == "format":
            continue
        if words[0] == "comment":
            comments.append(line.strip()[len("comment") :].strip())
        elif words[0] == "element":
            elements.append([words[1], int(words[2]), []])
        elif words[0] == "property" and words[1] == "list":
            elements[-1][2].append((words[4], (_PLY_TYPES[words[2]], _PLY_TYPES[words[3]])))
        elif words[0] == "property":
            elements[-1][2].append((words[2], _PLY_TYPES[words[1]]))

    offset, arrays = body_start, {}
    for name, count, properties in elements:
        lists = [(prop, kind) for prop, kind in properties if isinstance(kind, tuple)]
        if not lists:
            dtype = np.dtype([(prop, kind) for prop, kind in properties])
            arrays[name] = np.frombuffer(data, dtype, count, offset)
        elif len(properties) == 1:
            prop, (count_type, index_type) = lists[0]
            corners = int(np.frombuffer(data, count_type, 1, offset)[0]) if count else 3
            dtype = np.dtype([("count", count_type), (prop, index_type, (corners,))])
            records = np.frombuffer(data, dtype, count, offset)
            if np.any(records["count"] != corners):
                raise ValueError(f"{path}: faces with different corner counts are not supported")
            arrays[name] = records
        else:
            raise ValueError(f"{path}: element {name!r} mixes a list with other properties")
        offset += dtype.itemsize * count
    if offset != len(data):
        raise ValueError(f"{path}: {len(data) - offset} bytes left after the last element")

    vertex = arrays["vertex"]
    positions = np.stack([vertex[c] for c in "xyz"], -1).astype(np.float32)
    normals = None
    if all(c in vertex.dtype.names for c in ("nx", "ny", "nz")):
        normals = np.stack([vertex[c] for c in ("nx", "ny", "nz")], -1).astype(np.float32)
    face = arrays.get("face")
    if face is None:
        faces = np.zeros((0, 3), np.uint32)
    else:
        index_name = face.dtype.names[1]
        faces = np.asarray(face[index_name], dtype=np.uint32).reshape(len(face), -1)
    return PlyMesh(positions, faces, normals, tuple(comments))
