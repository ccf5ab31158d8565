"""Render passes read back from the frame EXR and checked on a calm, nearly flat sea (oceanrender.render.passes)."""

import math

import numpy as np
import pytest
import trimesh

from oceanrender.cli import main
from oceanrender.io.frames import read_exr
from tests.scenes import small_sea_text

DEPTH, HEIGHT, N_WATER = 20.0, 5.0, 1.333
ALL = '["Z", "N", "P", "water", "foam", "objects", "water_path"]'


def _render(tmp_path, name, camera, extra=""):
    trimesh.creation.box(extents=(2.0, 2.0, 2.0)).export(tmp_path / "box.ply")
    path = tmp_path / f"{name}.toml"
    path.write_text(small_sea_text(f'name = "{name}"\n[output]\nframes = [0, 1]\nresolution = [64, 36]\nspp = 1\npasses = {ALL}\n'
                    f'directory = "{tmp_path / "out"}"\n[ocean]\nwind_speed = 0.5\nresolution = 64\n'
                    f'[water]\ndepth = {DEPTH}\nsurface_roughness = 0.0\n[sun]\nelevation = 45.0\n{camera}\n{extra}'))
    assert main(["render", str(path), "--no-progress"]) == 0
    return read_exr(tmp_path / "out" / name / "frame_0000.exr")[0]


def test_passes_on_a_calm_sea(tmp_path):
    # The camera 5 m up looks 10° down the +y axis (the horizon in the upper part of the frame); the centre
    # ray meets the (nearly flat) sea 28.8 m away.
    down = math.radians(10)
    c = _render(tmp_path, "calm", f"[camera]\nposition = [0.0, 0.0, {HEIGHT}]\n"
                f"target = [0.0, {HEIGHT / math.tan(down)}, 0.0]\nfov = 60.0")
    h, w = c["depth.Z"].shape
    # The centre ray is between the middle four pixels; their mean is the centre's to first order.
    centre = (slice(h // 2 - 1, h // 2 + 1), slice(w // 2 - 1, w // 2 + 1))
    # A 0.5 m/s sea: ripples of millimetres; 2 % of the distance bounds them and the half-pixel offsets.
    assert c["depth.Z"][centre].mean() == pytest.approx(HEIGHT / math.sin(down), rel=0.02)
    water = c["mask.water"] > 0.5
    assert water[-1].all() and not water[0].any()  # sea below the horizon, sky above
    assert np.all(c["depth.Z"][~water] >= 1e9)  # the sky is "far", not 0
    assert c["Z"].max() < 1e5  # the CIE Z of the frame is still there, not overwritten by depth
    assert np.abs(c["P.Z"][water]).max() < 0.05  # the points lie on the still level (ripples ≪ 5 cm)
    normal_z = c["N.Z"][water]
    assert normal_z.min() > math.cos(math.radians(3))  # normals up within 3°
    # P = camera + Z · direction: the centre point lies on the centre ray.
    np.testing.assert_allclose(c["P.Y"][centre].mean(), HEIGHT / math.tan(down), rtol=0.02)
    # The refracted ray: incidence 80°, refraction asin(sin 80°/n), then down to the 20 m bottom.
    refracted = math.asin(math.sin(math.radians(80)) / N_WATER)
    assert c["water_path"][centre].mean() == pytest.approx(DEPTH / math.cos(refracted), rel=0.02)
    assert np.all(c["water_path"][~water] == 0)
    assert np.all((c["mask.foam"] >= 0) & (c["mask.foam"] <= 1)) and np.all(c["mask.objects"] == 0)


def test_the_object_mask_covers_the_object(tmp_path):
    box = '[[objects]]\nname = "box"\nmesh = "box.ply"\nposition = [0.0, 8.66, 0.0]\n'
    c = _render(tmp_path, "box", f"[camera]\nposition = [0.0, 0.0, {HEIGHT}]\ntarget = [0.0, 8.66, 0.0]\nfov = 60.0",
                box)
    objects = c["mask.objects"] > 0.5
    h, w = objects.shape
    assert objects[h // 2, w // 2]  # the box is in the middle of the view
    assert 0.01 < objects.mean() < 0.5
    assert not np.any(objects & (c["mask.water"] > 0.5))  # one first surface per pixel
