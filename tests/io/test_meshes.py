"""Reading object meshes (oceanrender.io.meshes): OBJ, PLY, glTF/GLB through trimesh; bad files refused in one line."""

import numpy as np
import pytest
import trimesh

from oceanrender.io.meshes import MeshProblem, read_mesh


@pytest.mark.parametrize("suffix", [".obj", ".ply", ".glb", ".gltf"])
def test_every_format_reads_the_same_closed_box(tmp_path, suffix):
    box = trimesh.creation.box(extents=(4.0, 2.0, 1.0))
    path = tmp_path / f"box{suffix}"
    box.export(path)
    mesh = read_mesh(path)
    # A box keeps its extents whatever the format (OBJ/glTF may split vertices at sharp edges).
    np.testing.assert_allclose(mesh.vertices.max(0) - mesh.vertices.min(0), [4.0, 2.0, 1.0], rtol=1e-6)
    assert len(mesh.faces) == 12
    assert np.allclose(np.linalg.norm(mesh.normals, axis=1), 1.0)


def test_the_boat_and_buoy_of_the_example_scene_are_closed():
    from pathlib import Path

    folder = Path(__file__).resolve().parents[2] / "scenes" / "meshes"
    for name in ("boat.ply", "buoy.ply"):
        mesh = read_mesh(folder / name)
        assert mesh.closed and mesh.vertices[:, 2].min() < 0 < mesh.vertices[:, 2].max()


@pytest.mark.parametrize("content, suffix, expected", [
    (None, ".ply", "cannot open"),
    (b"solid nothing\n", ".stl", "expected a mesh file ending in"),
    (b"this is not a mesh", ".ply", "not a readable PLY mesh"),
    (b"v 0 0 0\nv 1 0 0\n", ".obj", "no triangles"),
    (b"v 0 0 0\nv 1 0 nan\nv 0 1 0\nf 1 2 3\n", ".obj", "non-finite"),
])
def test_bad_files_are_refused_in_one_line(tmp_path, content, suffix, expected):
    path = tmp_path / f"bad{suffix}"
    if content is not None:
        path.write_bytes(content)
    with pytest.raises(MeshProblem) as info:
        read_mesh(path)
    assert expected in str(info.value) and "\n" not in str(info.value)
