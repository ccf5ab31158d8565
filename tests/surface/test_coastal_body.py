"""The coastal water body's white water: foam where the stored flow's bores dissipate energy."""

import numpy as np
import pytest

from oceanrender.coastal.simulation import read_frame_fields, run_simulation
from oceanrender.coastal.whitewater import bore_dissipation_rate
from tests.scenes import scene_from_dict
from oceanrender.surface.coastal_body import CoastalBody

BREAKING_BEACH = {"cells": [60, 40], "size": [15.0, 10.0], "origin": [-7.5, -3.0], "slope": 0.08,
                  "offshore_depth": 0.6, "wave_height": 0.4, "wave_period": 4.0, "order": 2, "cfl": 0.45,
                  "spinup": 10.0, "checkpoint_interval": 5.0}


@pytest.fixture(scope="module")
def store(tmp_path_factory):
    path = tmp_path_factory.mktemp("whitewater")
    run_simulation(beach(True), path)
    return path


def beach(foam: bool):
    return scene_from_dict({"name": "breaking", "output": {"frames": [0, 4], "fps": 10.0},
                            "coastal": BREAKING_BEACH, "foam": {"enabled": foam, "decay_time": 0.5}})


def test_white_water_is_where_bores_dissipate(store):
    body = CoastalBody(beach(True), store)
    t = 0.3
    coverage, fresh = body.foam_state(t)
    assert np.all((0 <= fresh) & (fresh <= coverage) & (coverage <= 1))
    fields = read_frame_fields(store, 3)
    rate = bore_dissipation_rate(fields["h"], fields["hu"], fields["hv"], body.coastal.spacing, body.coastal.h_min)
    now = rate > 2 * body.scene.foam.whitewater_dissipation  # fully white this frame
    assert now.any(), "the test beach should break"
    np.testing.assert_allclose(coverage[now], 1.0)  # the current frame's bores are white
    np.testing.assert_allclose(fresh[now], 1.0)
    # foam left behind by earlier frames' bores is older: less fresh than its coverage
    older = (coverage > 0) & (rate < body.scene.foam.whitewater_dissipation)
    assert older.any() and np.all(fresh[older] < coverage[older])
    geometry = body.frame(t)
    assert geometry.foam is not None and geometry.foam.max() == pytest.approx(1.0)
    wet = fields["h"] > body.coastal.h_min
    assert np.all(geometry.foam[: wet.size][~wet.ravel()] == 0)  # no foam on dry land
    assert np.all(geometry.foam[wet.size:] == 0)  # walls and base
    # depends on the store and t only: a fresh body gives the same foam
    np.testing.assert_array_equal(geometry.foam, CoastalBody(beach(True), store).frame(t).foam)


def test_no_foam_when_disabled(store):
    assert CoastalBody(beach(False), store).frame(0.2).foam is None


def test_a_rotated_domain_turns_its_body_and_terrain_about_the_origin(store):
    """rotation = 90°: a point one cell east of the origin along the grid's x axis lies north of it."""
    straight = CoastalBody(beach(False), store)
    turned_scene = scene_from_dict({"name": "breaking", "output": {"frames": [0, 4], "fps": 10.0},
                                    "coastal": {**BREAKING_BEACH, "rotation": 90.0}})
    turned = CoastalBody(turned_scene, store)
    a, b = straight.frame(0.3), turned.frame(0.3)
    origin = np.array(BREAKING_BEACH["origin"])
    offset = a.positions[:, :2] - origin
    np.testing.assert_allclose(b.positions[:, :2] - origin, np.column_stack([-offset[:, 1], offset[:, 0]]),
                               atol=1e-4 * np.abs(offset).max())  # float32 positions
    np.testing.assert_allclose(b.positions[:, 2], a.positions[:, 2])
    np.testing.assert_allclose(b.normals[:, :2], np.column_stack([-a.normals[:, 1], a.normals[:, 0]]), atol=1e-6)
    ta, tb = straight.terrain(), turned.terrain()
    np.testing.assert_allclose(tb.positions[:, 2], ta.positions[:, 2])
