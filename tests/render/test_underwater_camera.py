"""A camera under the water: Snell's window, no NaN, and the side of the surface decided per frame."""

import math

import numpy as np
import pytest

from oceanrender.cli import main
from oceanrender.io.frames import read_exr
from tests.scenes import small_sea_text

#: Refractive index of the scenes below ([water] ior default) [-].
N_WATER = 1.333


def _render(tmp_path, name, camera, extra="", resolution=(192, 192), spp=16):
    path = tmp_path / f"{name}.toml"
    path.write_text(small_sea_text(f'name = "{name}"\n[output]\nframes = [0, 1]\nresolution = [{resolution[0]}, {resolution[1]}]\n'
                    f'spp = {spp}\ndirectory = "{tmp_path / "out"}"\n{camera}\n[sun]\nelevation = 50.0\n'
                    f'azimuth = 180.0\n{extra}'))
    assert main(["render", str(path), "--no-progress"]) == 0
    return read_exr(tmp_path / "out" / name / "frame_0000.exr")


@pytest.mark.slow
def test_snells_window_from_under_a_calm_sea(tmp_path):
    # Looking straight up from 3 m under a calm sea (0.5 m/s wind, smooth surface): the sky is seen inside a
    # cone of half-angle asin(1/n) = 48.6°, total internal reflection of the deep water outside it.
    fov = 110.0
    channels, meta = _render(tmp_path, "window", '[camera]\nposition = [0.0, 0.0, -3.0]\n'
                             f'target = [0.0, 0.001, 10.0]\nfov = {fov}',
                             "[ocean]\nwind_speed = 0.5\n[water]\nsurface_roughness = 0.0\n")
    assert meta["camera_in_water"] in (True, "true")
    assert int(meta["repaired_pixels"]) == 0  # no non-finite pixel came out of the renderer
    Y = channels["Y"]
    assert np.all(np.isfinite(Y))
    h, w = Y.shape
    f = (w / 2) / math.tan(math.radians(fov / 2))
    yy, xx = np.mgrid[0:h, 0:w]
    theta = np.degrees(np.arctan(np.hypot(xx + 0.5 - w / 2, yy + 0.5 - h / 2) / f))
    edges = np.arange(40.0, 58.0, 0.5)
    ring = np.array([np.median(Y[(theta >= a) & (theta < a + 0.5)]) for a in edges])
    inside, outside = np.median(ring[edges < 46]), np.median(ring[edges >= 52])
    assert inside > 10 * outside  # the window is bright, its surround dark
    level = math.sqrt(inside * outside)  # halfway in log between the two
    crossing = edges[np.argmax(ring < level)]  # first 0.5° ring below it
    expected = math.degrees(math.asin(1.0 / N_WATER))  # 48.61°
    # ±1°: two rings of 0.5° (the crossing is located to a ring), pixels ~0.4° wide at 48°, ripples of a
    # 0.5 m/s sea tilt the surface by a few tenths of a degree.
    assert abs(crossing + 0.25 - expected) <= 1.0, (crossing, expected)


@pytest.mark.slow
def test_a_level_view_under_the_waves_has_no_nan_and_is_under_water(tmp_path):
    channels, meta = _render(tmp_path, "level", "[camera]\nposition = [0.0, 0.0, -4.0]\n"
                             "target = [0.0, 10.0, -1.0]\nfov = 90.0", resolution=(64, 36), spp=8)
    assert meta["camera_in_water"] in (True, "true")
    assert int(meta["repaired_pixels"]) == 0
    rgb = np.stack([channels[c] for c in "RGB"], -1)
    assert np.all(np.isfinite(rgb))
    # Under clear sea water everything is blue-green: blue exceeds red in the mean of the frame.
    assert rgb[..., 2].mean() > 2 * rgb[..., 0].mean()


@pytest.mark.slow
def test_a_camera_above_the_water_renders_from_the_air(tmp_path):
    _, meta = _render(tmp_path, "above", "[camera]\nposition = [0.0, 0.0, 6.0]\ntarget = [0.0, 10.0, 0.0]\nfov = 60.0",
                      resolution=(32, 18), spp=4)
    assert meta["camera_in_water"] in (False, "false")


@pytest.mark.slow
def test_a_camera_path_through_the_surface_renders_each_frame_from_its_side(tmp_path):
    # Keys from 2 m above to 2 m under the still level over 4 frames at 2 fps: the first two frames are in
    # the air, the last two in the water (a calm 1 m/s sea is ±0.05 m high), none refused, none non-finite.
    keys = "".join(f'[[camera.keys]]\ntime = {t}\nposition = [0.0, 0.0, {z}]\ntarget = [0.0, 10.0, {z - 1.0}]\n'
                   f'fov = 70.0\n' for t, z in ((0.0, 2.0), (1.5, -2.0)))
    path = tmp_path / "dive.toml"
    path.write_text(small_sea_text(f'name = "dive"\n[output]\nframes = [0, 4]\nfps = 2.0\nresolution = [24, 16]\nspp = 4\n'
                    f'directory = "{tmp_path / "out"}"\n[ocean]\nwind_speed = 1.0\nresolution = 64\n'
                    f'[sun]\nelevation = 50.0\nazimuth = 180.0\n{keys}'))
    assert main(["render", str(path), "--no-progress"]) == 0
    sides = []
    for frame in range(4):
        channels, meta = read_exr(tmp_path / "out" / "dive" / f"frame_{frame:04d}.exr")
        assert int(meta["repaired_pixels"]) == 0 and np.all(np.isfinite(channels["Y"]))
        sides.append(meta["camera_in_water"] in (True, "true"))
    assert sides == [False, False, True, True]


@pytest.mark.slow
def test_an_open_sea_seafloor_is_seen_from_under_the_water(tmp_path):
    # 3 m under a 6 m deep sea, looking 45° down at an opaque Lambertian bottom: a bright floor (albedo 0.5)
    # returns far more light than a black one (albedo 0); 16 spp noise is a few % of the mean of 200 pixels.
    lower = []
    for albedo in (0.0, 0.5):
        channels, meta = _render(tmp_path, f"floor_{int(albedo * 10)}",
                                 "[camera]\nposition = [0.0, 0.0, -3.0]\ntarget = [0.0, 5.0, -8.0]\nfov = 60.0",
                                 f"[ocean]\nwind_speed = 3.0\nresolution = 64\n[water]\ndepth = 6.0\n"
                                 f"bottom_albedo = {albedo}\n", resolution=(32, 24), spp=16)
        assert meta["camera_in_water"] in (True, "true") and int(meta["repaired_pixels"]) == 0
        lower.append(float(channels["Y"][12:, :].mean()))
    assert lower[1] > 2.0 * lower[0], lower


def test_a_deep_sea_without_a_floor_returns_no_light_from_its_bottom(tmp_path):
    # 3 m under the sea, looking 60° from the vertical down (beyond the critical angle of 48.6°, where a
    # water-vacuum face reflects totally). Without bottom_albedo the sea is deep: its body's bottom must
    # absorb, so a 6 m deep body shows no more light than a 1000 m deep one (the water below 6 m only adds
    # light: it scatters some back). The bottom face as it was (water against vacuum) mirrored the whole
    # downwelling light field there: several times brighter. 16 spp noise is a few % of the mean of 200 pixels.
    lower = {}
    for depth in (6.0, 1000.0):
        channels, meta = _render(tmp_path, f"deep_{int(depth)}",
                                 "[camera]\nposition = [0.0, 0.0, -3.0]\ntarget = [0.0, 8.66, -8.0]\nfov = 60.0",
                                 f"[ocean]\nwind_speed = 3.0\nresolution = 64\n[water]\ndepth = {depth}\n",
                                 resolution=(32, 24), spp=16)
        assert meta["camera_in_water"] in (True, "true") and int(meta["repaired_pixels"]) == 0
        lower[depth] = float(channels["Y"][12:, :].mean())
    assert lower[6.0] <= 1.1 * lower[1000.0], lower
