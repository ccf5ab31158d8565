"""The camera-following mesh export: fixed triangulation, upward faces, per-ring LOD weights."""

import json

import numpy as np
import plyfile

from oceanrender.cli import main
from oceanrender.export.camera_mesh import camera_mesh_table, export_camera_mesh
from tests.scenes import scene_from_dict, small_sea_text
from tests.tolerances import ROUNDOFF

SCENE = {"name": "cm", "mesh": {"kind": "radial", "inner_radius": 0.5, "outer_radius": 2000.0, "segments": 48},
         "ocean": {"resolution": 64, "patch_size": 200.0, "cascades": 3}}


def test_export_writes_an_upward_mesh_and_its_lod_table(tmp_path):
    scene = scene_from_dict(SCENE)
    ply_path, json_path = export_camera_mesh(scene, tmp_path)
    table = json.loads(json_path.read_text())
    ply = plyfile.PlyData.read(str(ply_path))
    v = np.stack([ply["vertex"][c] for c in "xyz"], axis=1).astype(float)
    f = np.stack(ply["face"]["vertex_indices"]).astype(int)
    assert len(v) == table["vertex_count"] == 1 + table["rings"] * table["segments"]
    assert len(f) == table["face_count"] == table["segments"] * (2 * table["rings"] - 1)
    # Counter-clockwise from above: every face's normal points up; the mesh is flat at rest.
    n = np.cross(v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 0]])
    assert np.all(n[:, 2] > 0) and np.all(v[:, 2] == 0)
    # Ring radii as documented; the last ring reaches the outer radius.
    r = np.hypot(v[1:, 0], v[1:, 1]).reshape(table["rings"], table["segments"])
    # Vertex k = 0 lies on +x (cos 0 = 1, sin 0 = 0 exactly), so r is the float32-stored radius:
    # within half a float32 ulp (6e-8), 1e-6 relative.
    np.testing.assert_allclose(r[:, 0], table["ring_radius_m"], rtol=1e-6)
    assert r[-1, 0] == np.float32(2000.0)  # exact: float32 storage absorbs float64 last bits of r_out


def test_lod_weights_filter_by_wavenumber_with_distance():
    table = camera_mesh_table(scene_from_dict(SCENE))
    spacing = np.array(table["ring_spacing_m"])
    for i, cutoffs in enumerate(table["cascade_level_cutoffs_rad_m"]):
        w = np.array([ring[i] for ring in table["lod_weight_per_ring"]])  # (rings, levels)
        assert w.shape == (table["rings"], len(cutoffs))
        np.testing.assert_allclose(w.sum(axis=1), 1.0, rtol=ROUNDOFF)  # the weights of a ring add up to 1
        # effective weight of a mode at each level cutoff: Σ_j w_j 1[k < K_j]; a wave ≥ 8 vertices long is
        # whole, ≤ 2 vertices long gone (the documented rule)
        for k in cutoffs[1:]:
            weight = w @ (k < np.array(cutoffs)).astype(float)
            vertices = 2 * np.pi / k / spacing
            assert np.all(weight[vertices >= 8] == 1.0) and np.all(weight[vertices <= 2] == 0.0)
    alpha = np.array(table["ring_beckmann_alpha"])
    assert np.all(np.diff(alpha) >= -ROUNDOFF)  # roughness grows outwards as the mesh carries less
    assert alpha[-1] ** 2 <= table["total_slope_variance"] * (1 + ROUNDOFF)


def test_cli_geometry_camera_mesh(tmp_path, capsys):
    scene = tmp_path / "s.toml"
    scene.write_text(small_sea_text("[output]\nframes = [0, 1]\n[ocean]\nresolution = 16\npatch_size = 40.0\ncascades = 1\n"
                     "[mesh]\nkind = 'radial'\nouter_radius = 500.0\nsegments = 24\n"))
    assert main(["geometry", str(scene), "--out", str(tmp_path / "g"), "--camera-mesh"]) == 0
    assert (tmp_path / "g" / "camera_mesh.ply").is_file() and (tmp_path / "g" / "camera_mesh.json").is_file()
    assert "camera-following mesh" in capsys.readouterr().out
