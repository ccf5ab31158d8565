"""Binary PLY meshes: exact round trips, the file layout, and readers other than ours."""

import importlib

import numpy as np
import pytest

from oceanrender.io.ply import read_ply, write_ply
from oceanrender.surface.patch_mesh import water_body_faces
from tests.tolerances import ROUNDOFF32


def grid_mesh(rng, n=3):
    """A small closed water-body topology with random float positions and normals."""
    faces = water_body_faces(n)
    count = int(faces.max()) + 1
    positions = rng.normal(size=(count, 3)).astype(np.float32)
    normals = rng.normal(size=(count, 3))
    normals = (normals / np.linalg.norm(normals, axis=1, keepdims=True)).astype(np.float32)
    return positions, normals, faces


def test_round_trip_with_normals_and_comments(tmp_path, rng):
    positions, normals, faces = grid_mesh(rng)
    path = tmp_path / "m.ply"
    write_ply(path, positions, faces, normals, comments={"frame": 3, "units": "m"})
    mesh = read_ply(path)
    # Exact: a float32 file round trip.
    np.testing.assert_array_equal(mesh.positions, positions)
    np.testing.assert_array_equal(mesh.normals, normals)
    np.testing.assert_array_equal(mesh.faces, faces)
    assert mesh.positions.dtype == np.float32 and mesh.faces.dtype == np.uint32
    assert mesh.comments == ("frame: 3", "units: m")


def test_layout_is_binary_little_endian_float32_and_uchar_uint_lists(tmp_path, rng):
    positions, normals, faces = grid_mesh(rng, n=2)
    path = tmp_path / "m.ply"
    write_ply(path, positions, faces, normals)
    data = path.read_bytes()
    header, body = data.split(b"end_header\n", 1)
    assert header.decode("ascii").splitlines() == [
        "ply",
        "format binary_little_endian 1.0",
        f"element vertex {len(positions)}",
        *(f"property float {c}" for c in ("x", "y", "z", "nx", "ny", "nz")),
        f"element face {len(faces)}",
        "property list uchar uint vertex_indices",
    ]
    assert len(body) == len(positions) * 6 * 4 + len(faces) * (1 + 3 * 4)
    np.testing.assert_array_equal(np.frombuffer(body, "<f4", 3), positions[0])


def test_round_trip_without_normals(tmp_path, rng):
    positions, _, faces = grid_mesh(rng)
    write_ply(tmp_path / "m.ply", positions.astype(np.float64), faces.astype(np.int64))
    mesh = read_ply(tmp_path / "m.ply")
    assert mesh.normals is None
    np.testing.assert_array_equal(mesh.positions, positions)
    np.testing.assert_array_equal(mesh.faces, faces)


def test_invalid_meshes_are_refused_and_leave_no_file(tmp_path, rng):
    positions, normals, faces = grid_mesh(rng)
    path = tmp_path / "m.ply"
    with pytest.raises(ValueError, match="indices"):
        write_ply(path, positions, faces + len(positions))
    with pytest.raises(ValueError, match="normals"):
        write_ply(path, positions, faces, normals[:-1])
    with pytest.raises(ValueError, match="single-line"):
        write_ply(path, positions, faces, comments={"note": "two\nlines"})
    with pytest.raises(ValueError, match="positions"):
        write_ply(path, positions[:, :2], faces)
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("library", ["plyfile", "trimesh"])
def test_python_ply_libraries_read_it(tmp_path, rng, library):
    module = pytest.importorskip(library)
    positions, normals, faces = grid_mesh(rng)
    path = tmp_path / "m.ply"
    write_ply(path, positions, faces, normals)
    if library == "plyfile":
        data = module.PlyData.read(str(path))
        vertex = data["vertex"]
        read = np.stack([vertex[c] for c in "xyz"], -1)
        read_faces = np.stack(data["face"]["vertex_indices"])
    else:
        mesh = module.load(str(path), process=False)
        read, read_faces = np.asarray(mesh.vertices), np.asarray(mesh.faces)
    np.testing.assert_array_equal(read, positions)
    np.testing.assert_array_equal(read_faces, faces)


def test_mitsuba_reads_it(tmp_path, rng, variant):
    mi = importlib.import_module("mitsuba")
    positions, normals, faces = grid_mesh(rng)
    path = tmp_path / "m.ply"
    write_ply(path, positions, faces, normals)
    shape = mi.load_dict({"type": "ply", "filename": str(path)})
    assert shape.vertex_count() == len(positions) and shape.face_count() == len(faces)
    params = mi.traverse(shape)
    # Positions and faces: exact, Mitsuba keeps the file's float32 values and indices.
    np.testing.assert_array_equal(np.asarray(params["vertex_positions"]).reshape(-1, 3), positions)
    np.testing.assert_array_equal(np.asarray(params["faces"]).reshape(-1, 3), faces)
    # Mitsuba re-normalises the normals in float32 (its own rsqrt): unit vectors, scale 1.
    np.testing.assert_allclose(np.asarray(params["vertex_normals"]).reshape(-1, 3), normals, rtol=0, atol=ROUNDOFF32)
