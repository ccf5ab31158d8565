"""The arrays a coastal scene names or defines: plane beach, array files checked before any work, rock cover."""

import io
import os

import numpy as np
import pytest

from oceanrender.scene import arrays, scene_from_dict
from oceanrender.scene.settings import SceneError, load_scene
from tests.tolerances import ROUNDOFF

SMALL = {"cells": [16, 12], "size": [8.0, 6.0], "origin": [-4.0, -2.0]}


def coastal(**values):
    return scene_from_dict({"name": "c", "coastal": {**SMALL, **values}}).coastal


def test_plane_beach_matches_its_formula():
    c = coastal(slope=0.1, shoreline_y=0.5, offshore_depth=0.3, still_level=0.2)
    bed = arrays.bathymetry(c)
    x, y = arrays.coastal_cell_centres(c)
    expected = np.maximum(0.2 - 0.1 * (y - 0.5), 0.2 - 0.3)[:, None] * np.ones(len(x))
    # elevations and depths cross 0 at the shoreline: relative to their largest value
    np.testing.assert_allclose(bed, expected, rtol=0, atol=ROUNDOFF * np.abs(expected).max())
    assert bed.shape == (12, 16)
    depth = arrays.initial_depth(c, bed)
    expected_depth = np.maximum(0.2 - bed, 0.0)
    np.testing.assert_allclose(depth, expected_depth, rtol=0, atol=ROUNDOFF * expected_depth.max())


def write_scene(tmp_path, body, array=None, name="bathy.npy"):
    if array is not None:
        np.save(tmp_path / name, array)
    path = tmp_path / "beach.toml"
    path.write_text("[coastal]\ncells = [16, 12]\nsize = [8.0, 6.0]\n" + body)
    return path


@pytest.mark.parametrize(
    "array, body, message",
    [
        (np.zeros((12, 15)), 'bathymetry = "bathy.npy"\n', r"\[coastal\] bathymetry: .*expected shape \(ny, nx\) = \(12, 16\)"),
        (np.where(np.eye(12, 16) > 0, np.nan, -1.0), 'bathymetry = "bathy.npy"\n', r"\[coastal\] bathymetry: .*12 NaN"),
        (None, 'bathymetry = "missing.npy"\n', r"\[coastal\] bathymetry: .*missing.npy \(No such file or directory\)"),
        (np.full((12, 16), 5.0), 'bathymetry = "bathy.npy"\n', r"no cell is below the still level"),
        (None, "cfl = 0.7\n", r"\[coastal\] cfl: must be ≤ 0.5 at order 2"),
        (None, "h_min = -0.1\n", r"\[coastal\] h_min: .*greater than or equal to 0"),
        (None, 'bathymetry = "beach.png"\n', r"\[coastal\] bathymetry: .*\.npy/\.exr file"),
    ],
)
def test_bad_inputs_are_refused_with_the_key(tmp_path, array, body, message):
    path = write_scene(tmp_path, body, array)
    with pytest.raises(SceneError, match=message) as info:
        load_scene(path)
    assert str(path) in str(info.value) and "\n" not in str(info.value)


def _npy_bytes(array):
    buffer = io.BytesIO()
    np.save(buffer, array)
    return buffer.getvalue()


GOOD = _npy_bytes(-np.ones((12, 16)))


@pytest.mark.parametrize(
    "content, message",
    [
        (b"", r"not a readable \.npy file"),
        (b"\x93NUMPY\x01\x00garbage", r"not a readable \.npy file"),
        (_npy_bytes(np.zeros((12, 16), dtype=[("a", "f8")])), r"expected an array of real numbers"),
        (_npy_bytes(np.zeros((12, 16), dtype=complex)), r"expected an array of real numbers"),
        (_npy_bytes(np.zeros((12, 16, 1))), r"expected a 2-D array"),
        (GOOD.replace(b"(12, 16)", b"(100000, 100000)"), r"expected shape \(ny, nx\) = \(12, 16\)"),
        (GOOD[:-8], r"holds 1528 bytes of data, its header claims 1536"),
        (GOOD + b"\x00" * 8, r"holds 1544 bytes of data, its header claims 1536"),
    ],
)
def test_npy_headers_are_checked_before_their_data_is_read(tmp_path, content, message):
    (tmp_path / "bathy.npy").write_bytes(content)
    with pytest.raises(SceneError, match=r"\[coastal\] bathymetry: .*" + message) as info:
        load_scene(write_scene(tmp_path, 'bathymetry = "bathy.npy"\n'))
    assert "\n" not in str(info.value)


def test_a_header_claiming_more_elements_than_accepted_is_refused_without_reading(tmp_path):
    claim = GOOD.replace(b"(12, 16)", b"(100000, 100000)")
    (tmp_path / "big.npy").write_bytes(claim)
    with pytest.raises(ValueError, match=r"at most 268435456 elements, the header claims 10000000000"):
        arrays.read_array(tmp_path / "big.npy")


@pytest.mark.parametrize("kind", ["fifo", "folder"])
def test_fifos_and_folders_are_not_read_as_arrays(tmp_path, kind):
    target = tmp_path / "odd.npy"
    os.mkfifo(target) if kind == "fifo" else target.mkdir()  # a FIFO would block a reader for ever
    with pytest.raises(SceneError, match=r"\[coastal\] bathymetry: .*(not a regular file|is a folder)"):
        load_scene(write_scene(tmp_path, 'bathymetry = "odd.npy"\n'))


def test_array_bathymetry_is_read_relative_to_the_scene(tmp_path):
    bed = -np.linspace(-0.5, 1.5, 12)[:, None] * np.ones((1, 16))
    scene = load_scene(write_scene(tmp_path, 'bathymetry = "bathy.npy"\n', bed))
    np.testing.assert_array_equal(arrays.bathymetry(scene.coastal), bed)  # .npy round-trips bit for bit


@pytest.mark.parametrize("cover", [0.0, 0.15, 0.5])
def test_rock_covers_the_requested_fraction(cover):
    mask = arrays.rock_mask(coastal(cells=[200, 150], rock_cover=cover))
    assert mask.min() >= 0 and mask.max() <= 1
    assert mask.mean() == pytest.approx(cover, abs=0.03)


def test_initial_velocity_uniform_or_from_a_file_and_none_on_land(tmp_path):
    """hu = h u on wet cells, exactly 0 where h ≤ h_min (the solver's rule for land)."""
    c = coastal(initial_u=0.5, initial_v=-0.25)
    bed = arrays.bathymetry(c)
    h = arrays.initial_depth(c, bed)
    hu, hv = arrays.initial_discharges(c, h)
    wet = h > c.h_min
    assert wet.any() and (~wet).any()
    np.testing.assert_array_equal(hu[wet], 0.5 * h[wet])
    np.testing.assert_array_equal(hv[wet], -0.25 * h[wet])
    assert np.all(hu[~wet] == 0) and np.all(hv[~wet] == 0)
    u = np.linspace(-1.0, 1.0, 16 * 12).reshape(12, 16)
    np.save(tmp_path / "u.npy", u)
    c = coastal(initial_u=str(tmp_path / "u.npy"))
    hu, hv = arrays.initial_discharges(c, h)
    np.testing.assert_array_equal(hu[wet], (u * h)[wet])
    assert np.all(hv == 0)


@pytest.mark.parametrize("value, expected", [
    (float("nan"), "finite number"), (45.0, "±30 m/s"), ("u.txt", ".npy/.exr file"),
])
def test_bad_initial_velocities_are_refused_naming_the_key(value, expected):
    with pytest.raises(SceneError) as error:
        scene_from_dict({"name": "c", "coastal": {**SMALL, "initial_v": value}}, "c.toml")
    message = str(error.value)
    assert "[coastal] initial_v" in message and expected in message and "\n" not in message


def test_initial_velocity_files_are_checked_for_shape_nan_and_speed(tmp_path):
    cases = {"shape.npy": np.zeros((3, 3)), "nan.npy": np.full((12, 16), np.nan), "fast.npy": np.full((12, 16), 99.0)}
    words = {"shape.npy": "shape", "nan.npy": "NaN", "fast.npy": "±30 m/s"}
    for name, array in cases.items():
        np.save(tmp_path / name, array)
        scene = tmp_path / "s.toml"
        scene.write_text('[coastal]\ncells = [16, 12]\nsize = [8.0, 6.0]\norigin = [-4.0, -2.0]\n'
                         f'initial_u = "{name}"\n')
        with pytest.raises(SceneError) as error:
            load_scene(scene)
        message = str(error.value)
        assert "[coastal] initial_u" in message and words[name] in message and "\n" not in message, message
