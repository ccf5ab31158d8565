"""The arrays a coastal scene names or defines: plane beach, array files checked before any work, rock cover."""

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
        (None, 'bathymetry = "missing.npy"\n', r"\[coastal\] bathymetry: file not found"),
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


def test_array_bathymetry_is_read_relative_to_the_scene(tmp_path):
    bed = -np.linspace(-0.5, 1.5, 12)[:, None] * np.ones((1, 16))
    scene = load_scene(write_scene(tmp_path, 'bathymetry = "bathy.npy"\n', bed))
    np.testing.assert_array_equal(arrays.bathymetry(scene.coastal), bed)  # .npy round-trips bit for bit


@pytest.mark.parametrize("cover", [0.0, 0.15, 0.5])
def test_rock_covers_the_requested_fraction(cover):
    mask = arrays.rock_mask(coastal(cells=[200, 150], rock_cover=cover))
    assert mask.min() >= 0 and mask.max() <= 1
    assert mask.mean() == pytest.approx(cover, abs=0.03)
