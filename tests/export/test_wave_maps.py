"""Geometry export: EXR maps in Blender's ocean-cache layout, PLY meshes, the JSON sidecar."""

import functools
import json
from dataclasses import dataclass

import numpy as np
import pytest

from oceanrender.export.wave_maps import (
    MAP_FILES,
    export_frame_maps,
    export_frame_mesh,
    export_geometry_sequence,
    frame_file,
    ocean_metadata,
    read_frame_maps,
    write_geometry_json,
)
from oceanrender.io.frames import read_exr
from oceanrender.io.ply import read_ply
from oceanrender.surface.patch_mesh import water_body_faces, water_body_vertices
from oceanrender.waves.fft_ocean import FFTOcean, OceanGrid
from oceanrender.waves.wave_spectra import spectrum_Phillips2001

N, PATCH, TIME = 16, 40.0, 1.3


@pytest.fixture(scope="module")
def sea():
    return FFTOcean(OceanGrid(N, PATCH), 7.0, 0.4, seed=2**40 + 5, choppiness=0.8, small_wave_length=0.5)


@pytest.fixture(scope="module")
def fields(sea):
    return sea.fields(TIME)


def f32(array):
    return np.asarray(array, dtype=np.float32)


def test_every_map_round_trips_in_blender_layout(tmp_path, sea, fields):
    written = export_frame_maps(tmp_path, 7, fields, ocean_metadata(sea, TIME))
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(
        ["height_0007.exr", "disp_0007.exr", "normal_0007.exr", "jacobian_0007.exr"]
    )
    assert {kind: path.name for kind, path in written.items()} == {
        "height": "height_0007.exr",
        "disp": "disp_0007.exr",
        "normal": "normal_0007.exr",
        "jacobian": "jacobian_0007.exr",
    }
    # Exact throughout: a float32 EXR round trip of the same arrays, cast to float32 once.
    north_up = lambda a: f32(a)[::-1]  # noqa: E731  (top row = north edge, as Blender bakes)
    height, _ = read_exr(written["height"])
    np.testing.assert_array_equal(height["Y"], north_up(fields.height))
    disp, _ = read_exr(written["disp"])  # Blender's y-up order: R = x, G = up, B = y
    np.testing.assert_array_equal(disp["R"], north_up(fields.displacement_x))
    np.testing.assert_array_equal(disp["G"], north_up(fields.height))
    np.testing.assert_array_equal(disp["B"], north_up(fields.displacement_y))
    normal, _ = read_exr(written["normal"])
    np.testing.assert_array_equal(normal["R"], north_up(fields.normals[..., 0]))
    np.testing.assert_array_equal(normal["G"], north_up(fields.normals[..., 2]))
    np.testing.assert_array_equal(normal["B"], north_up(fields.normals[..., 1]))
    jacobian, _ = read_exr(written["jacobian"])
    np.testing.assert_array_equal(jacobian["Y"], north_up(fields.jacobian))
    assert all(set(c) == {"Y"} or set(c) == {"R", "G", "B"} for c in (height, disp, normal, jacobian))
    assert all(a.dtype == np.float32 for c in (height, disp, normal, jacobian) for a in c.values())


def test_read_frame_maps_restores_the_fields_layout(tmp_path, sea, fields):
    coverage = np.clip(1 - fields.jacobian, 0, 1)
    export_frame_maps(tmp_path, 0, fields, ocean_metadata(sea, TIME), foam=coverage)
    maps, metadata = read_frame_maps(tmp_path, 0)
    # Exact: a file round trip of float32 casts of these very arrays.
    np.testing.assert_array_equal(maps["height"], f32(fields.height))
    np.testing.assert_array_equal(
        maps["displacement"], f32(np.stack([fields.displacement_x, fields.displacement_y, fields.height], -1))
    )
    np.testing.assert_array_equal(maps["normals"], f32(fields.normals))
    np.testing.assert_array_equal(maps["jacobian"], f32(fields.jacobian))
    np.testing.assert_array_equal(maps["foam"], f32(coverage))
    foam, _ = read_exr(tmp_path / "foam_0000.exr")
    assert set(foam) == {"R", "G", "B"} and np.array_equal(foam["R"], foam["B"])
    assert metadata["map"] == "height"


def test_metadata_is_on_every_file_and_exact(tmp_path, sea, fields):
    written = export_frame_maps(tmp_path, 12345, fields, ocean_metadata(sea, TIME))
    assert written["height"].name == "height_12345.exr"
    for kind, path in written.items():
        _, metadata = read_exr(path)
        assert metadata["map"] == kind
        assert float(metadata["patch_size_m"]) == PATCH
        assert float(metadata["time_s"]) == TIME  # exact, not float32
        assert metadata["resolution"] == N and metadata["frame"] == 12345
        assert metadata["spectrum"] == "Phillips 2001"
        assert float(metadata["spectrum_parameters.wind_speed"]) == 7.0
        assert float(metadata["spectrum_parameters.wind_direction"]) == 0.4
        assert float(metadata["choppiness"]) == 0.8
        assert float(metadata["depth_m"]) == np.inf
        assert int(metadata["seed"]) == 2**40 + 5  # a 32-bit attribute would have wrapped
        assert "north" in metadata["row_order"]
        assert metadata["channels"] == "; ".join(f"{c}={text}" for c, text in MAP_FILES[kind][1].items())


def test_invalid_inputs_are_refused(tmp_path, sea, fields):
    metadata = ocean_metadata(sea, TIME)
    with pytest.raises(ValueError, match="time_s"):
        export_frame_maps(tmp_path, 0, fields, ocean_metadata(sea))
    with pytest.raises(ValueError, match="resolution"):
        export_frame_maps(tmp_path, 0, fields, {**metadata, "resolution": 2 * N})
    with pytest.raises(ValueError, match=r"\[0, 1\]"):
        export_frame_maps(tmp_path, 0, fields, metadata, foam=np.full((N, N), 1.5))
    with pytest.raises(ValueError, match="shape"):
        export_frame_maps(tmp_path, 0, fields, metadata, foam=np.zeros((N, N + 1)))
    with pytest.raises(ValueError, match="frame"):
        export_frame_maps(tmp_path, -1, fields, metadata)
    assert list(tmp_path.iterdir()) == []
    with pytest.raises(ValueError, match="unknown map"):
        frame_file("displacement", 0)


def test_mesh_file(tmp_path, fields):
    positions, normals = water_body_vertices(fields, PATCH, depth=10.0)
    faces = water_body_faces(N)
    metadata = {"time_s": TIME, "spectrum": {"name": "x"}, "note": "Ψ ≥ 0"}
    path = export_frame_mesh(tmp_path, 3, positions, normals, faces, metadata)
    assert path.name == "mesh_0003.ply"
    mesh = read_ply(path)
    np.testing.assert_array_equal(mesh.positions, positions)  # exact: a file round trip
    np.testing.assert_array_equal(mesh.normals, normals)
    np.testing.assert_array_equal(mesh.faces, faces)
    assert {"frame: 3", "units: m", "time_s: 1.3", "spectrum.name: x", 'note: "\\u03a8 \\u2265 0"'} <= set(mesh.comments)


def test_sidecar_describes_files_units_axes_and_parameters(tmp_path, sea):
    path = write_geometry_json(tmp_path, {2: 0.1, 1: 0.05}, ocean_metadata(sea, TIME), foam=True, mesh=True)
    assert path.name == "geometry.json"
    text = path.read_text(encoding="utf-8")
    document = json.loads(text, parse_constant=lambda name: pytest.fail(f"non-standard JSON {name}"))
    assert document["frames"] == [{"frame": 1, "time_s": 0.05}, {"frame": 2, "time_s": 0.1}]
    files = document["files"]
    assert set(files) == {"height", "disp", "normal", "jacobian", "foam", "mesh"}
    assert files["disp"]["pattern"] == "disp_{frame:04d}.exr"
    assert files["disp"]["channels"]["G"].startswith("elevation z, up")
    assert files["mesh"]["pattern"] == "mesh_{frame:04d}.ply"
    assert document["units"]["length"] == "m" and document["units"]["time"] == "s"
    assert (document["axes"]["x"], document["axes"]["y"], document["axes"]["z"]) == ("east", "north", "up")
    grid = document["grid"]
    assert grid == {**grid, "resolution": N, "patch_size_m": PATCH, "spacing_m": PATCH / N, "periodic": True}
    assert grid["first_point_m"] == [-PATCH / 2, -PATCH / 2]
    parameters = document["parameters"]
    assert "time_s" not in parameters
    assert parameters["seed"] == 2**40 + 5 and parameters["depth_m"] == "inf"
    assert parameters["spectrum"] == "Phillips 2001"
    assert parameters["spectrum_parameters"]["wind_speed"] == 7.0
    assert document["blender"]["ocean_modifier"]["size_times_spatial_size_m"] == PATCH
    assert [p.name for p in tmp_path.iterdir()] == ["geometry.json"]  # no temporary left


def test_sidecar_without_optional_files(tmp_path, sea):
    write_geometry_json(tmp_path, {0: 0.0}, ocean_metadata(sea))
    files = json.loads((tmp_path / "geometry.json").read_text(encoding="utf-8"))["files"]
    assert set(files) == {"height", "disp", "normal", "jacobian"}
    with pytest.raises(ValueError, match="patch_size_m"):
        write_geometry_json(tmp_path, {0: 0.0}, {"resolution": N})



@dataclass(frozen=True)
class FlatSpectrum:
    """A stand-in spectrum object: a dataclass with a method name and parameters."""

    method: str = "flat"
    level: float = 1e-4

    def __call__(self, kx, ky):
        return np.full(np.shape(kx), self.level)


@pytest.mark.parametrize(
    "function, name, parameters",
    [
        (functools.partial(spectrum_Phillips2001, wind_speed=9.0, wind_direction=0.1), "spectrum_Phillips2001",
         {"wind_speed": 9.0, "wind_direction": 0.1}),
        (FlatSpectrum(level=2e-4), "flat", {"level": 2e-4}),
    ],
)  # fmt: skip
def test_metadata_of_a_spectrum_function(function, name, parameters):
    try:
        sea = FFTOcean(OceanGrid(8, 10.0), spectrum_function=function)
    except TypeError:
        pytest.skip("this FFTOcean takes no spectrum_function")
    metadata = ocean_metadata(sea, 0.5)
    assert metadata["spectrum"] == name and metadata["spectrum_parameters"] == parameters
    assert metadata["time_s"] == 0.5


def test_sequence_writes_sidecar_maps_and_meshes(tmp_path, sea):
    written = export_geometry_sequence(tmp_path, sea, {4: 0.2, 3: 0.1}, mesh_depth=10.0)
    assert written[0].name == "geometry.json"
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(
        ["geometry.json"]
        + [f"{kind}_{f:04d}.{ext}" for f in (3, 4) for kind, ext in
           [("height", "exr"), ("disp", "exr"), ("normal", "exr"), ("jacobian", "exr"), ("mesh", "ply")]]
    )  # fmt: skip
    maps, metadata = read_frame_maps(tmp_path, 4)
    # Exact: the export evaluates the same ocean.fields(t) with the same inputs in this process.
    np.testing.assert_array_equal(maps["height"], f32(sea.fields(0.2).height))
    assert float(metadata["time_s"]) == 0.2
    assert read_ply(tmp_path / "mesh_0003.ply").positions.min(axis=0)[2] == -10.0  # exact: the bottom is set to −depth
    document = json.loads((tmp_path / "geometry.json").read_text(encoding="utf-8"))
    assert [entry["frame"] for entry in document["frames"]] == [3, 4] and "mesh" in document["files"]


def test_sequence_checks_everything_before_writing(tmp_path, sea):
    with pytest.raises(ValueError, match="frame"):
        export_geometry_sequence(tmp_path, sea, {0: 0.0, -1: 0.1})
    with pytest.raises(ValueError, match="frame"):
        export_geometry_sequence(tmp_path, sea, {1.5: 0.0})
    with pytest.raises(ValueError, match="finite"):
        export_geometry_sequence(tmp_path, sea, {0: 0.0, 1: np.nan})
    with pytest.raises(ValueError, match="mesh_depth"):
        export_geometry_sequence(tmp_path, sea, {0: 0.0}, mesh_depth=0.0)
    assert list(tmp_path.iterdir()) == []
