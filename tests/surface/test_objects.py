"""Objects posed per frame and their wakes (oceanrender.surface.objects)."""

from pathlib import Path

import numpy as np
import pytest

from oceanrender.scene import load_scene
from oceanrender.surface.objects import SceneObjects, attitude_matrix, object_centre, scene_wakes
from oceanrender.waves.sea import SeaSurface

from ..tolerances import ROUNDOFF

SCENES = Path(__file__).resolve().parents[2] / "scenes"


def test_attitude_matrix_turns_the_bow_by_heading_pitch_and_roll():
    r = attitude_matrix(0.0, 0.0, 0.0)
    np.testing.assert_allclose(r @ [1, 0, 0], [0, 1, 0], atol=ROUNDOFF)  # heading 0: bow north
    np.testing.assert_allclose(attitude_matrix(90.0, 0, 0) @ [1, 0, 0], [1, 0, 0], atol=ROUNDOFF)  # 90: east
    np.testing.assert_allclose(attitude_matrix(90.0, 0, 0) @ [0, 1, 0], [0, 1, 0], atol=ROUNDOFF)  # left: north
    assert (attitude_matrix(30.0, 10.0, 0) @ [1, 0, 0])[2] == pytest.approx(np.sin(np.radians(10)))  # bow up
    assert (attitude_matrix(30.0, 0, 10.0) @ [0, 1, 0])[2] == pytest.approx(np.sin(np.radians(10)))  # left up
    m = attitude_matrix(123.0, -7.0, 21.0)
    np.testing.assert_allclose(m @ m.T, np.eye(3), atol=ROUNDOFF)
    assert np.linalg.det(m) == pytest.approx(1.0)


def test_the_boat_scene_moves_floats_and_leaves_one_wake():
    scene = load_scene(SCENES / "boat.toml")
    boat = next(o for o in scene.objects if o.name == "boat")
    np.testing.assert_allclose(object_centre(boat)(2.0), [0.0, 20.0 + 2.0 * boat.speed], atol=ROUNDOFF)
    wakes = scene_wakes(scene)
    assert len(wakes) == 1  # the buoy does not move
    wake = wakes[0]
    # Behind the boat the wake is there; far ahead of it, and beside it beyond the cusp lines, it is not.
    centre = object_centre(boat)(0.0)
    behind = wake.sample(np.array([centre[0]]), np.array([centre[1] - 40.0]), 0.0)[0]
    ahead = wake.sample(np.array([centre[0]]), np.array([centre[1] + 60.0]), 0.0)[0]
    assert abs(behind[0]) > 20 * abs(ahead[0])
    sea = SeaSurface(scene.ocean, wakes)
    objects = SceneObjects(scene, sea)
    first = objects.frame(0.0)
    assert [g.name for g in first] == ["boat", "buoy"]
    again = SceneObjects(scene, SeaSurface(scene.ocean, wakes)).frame(0.0)
    np.testing.assert_array_equal(first[0].positions, again[0].positions)  # a function of t alone
    # The floating boat rides the sea: its waterline origin's height is the sea's plane, within the sea's range.
    rotation, translation = objects.pose(objects.items[0][0], objects.items[0][1], 0.5)
    assert abs(translation[2]) < 4 * 0.36 and np.allclose(rotation @ rotation.T, np.eye(3), atol=ROUNDOFF)


def test_the_water_mesh_carries_the_wake():
    scene = load_scene(SCENES / "boat.toml")
    wakes = scene_wakes(scene)
    plain, waked = SeaSurface(scene.ocean), SeaSurface(scene.ocean, wakes)
    x, y = np.array([0.0, 3.0]), np.array([-10.0, -30.0])
    difference = waked.sample(x, y, 0.0).displacement[..., 2] - plain.sample(x, y, 0.0).displacement[..., 2]
    np.testing.assert_allclose(difference, wakes[0].sample(x, y, 0.0)[0], atol=ROUNDOFF)
