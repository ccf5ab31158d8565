"""The sea reaches the horizon: level views from 1 m, 30 m and 1 km show no dark line between sea and sky
(the far ring of oceanrender.surface.radial_mesh and the sensor's far clip of oceanrender.render.scene)."""

import numpy as np
import pytest

from oceanrender.pipeline import Sequence
from tests.scenes import scene_from_dict

pytestmark = pytest.mark.render


@pytest.mark.parametrize("height", [1.0, 30.0, 1000.0])
def test_no_gap_line_at_the_horizon(variant, height):
    scene = scene_from_dict({
        "name": "horizon",
        "output": {"resolution": [48, 28], "spp": 8, "frames": [0, 1]},
        "ocean": {"resolution": 64, "patch_size": 200.0, "cascades": 2, "wind_speed": 8.0},
        "mesh": {"kind": "radial", "outer_radius": 4000.0, "segments": 64},
        "render": {"white_spp": 64, "max_depth": 6},
        "camera": {"position": [0.0, 0.0, height], "target": [0.0, 1000.0, height], "fov": 60.0},
    })
    sequence = Sequence(scene, variant)
    sequence.renderer.update_water(sequence.geometry(0))
    xyz, _ = sequence.renderer.render_xyz(spp=8, seed=3)
    rows = xyz[..., 1].mean(axis=1)  # luminance per row [cd/m²]; the horizon lies between rows 13 and 14
    sky, sea = rows[10:13].mean(), rows[15:18].mean()
    assert sky > sea > 0
    # A gap between the far edge of the water and the horizon shows the black sky below the horizon:
    # the row just above or below would fall far under both neighbours (it was 0 from 1 km up, 0.9 of
    # the sea from 30 m). Without a gap each is within the range its sky and sea rows span, give or take
    # the rough surface's darkening at grazing incidence (0.95 of the sea measured at 320×180).
    assert rows[13] > 0.75 * sea and rows[14] > 0.75 * sea
