"""Environment maps as the sky (oceanrender.render.environment): units, orientation, the adapting white, bad files."""

import math
from pathlib import Path

import numpy as np
import pytest

from oceanrender.cli import main
from oceanrender.scene import load_scene
from tests.scenes import scene_from_dict

SCENES = Path(__file__).resolve().parents[2] / "scenes"


@pytest.fixture(scope="module")
def mi():
    from oceanrender.runtime.variants import activate_variant

    activate_variant("auto")
    import mitsuba

    return mitsuba


def _write(mi, path, image):
    mi.Bitmap(np.ascontiguousarray(image, dtype=np.float32)).write(str(path))
    return path


def test_a_uniform_map_lights_a_plane_with_pi_times_its_luminance(mi, tmp_path):
    # A sky of uniform radiance L lights a horizontal plane with E = π L (Lambert); its luminance: K_m ∫ L ȳ dλ of
    # Mitsuba's upsampled white times c. The white plane's reading has ~0.1 % noise (2^16 cosine-weighted samples).
    from oceanrender.render.environment import environment_scale, map_illuminance

    c = 0.2
    path = _write(mi, tmp_path / "uniform.exr", np.full((16, 32, 3), c))
    white = mi.load_dict({"type": "constant", "radiance": {"type": "rgb", "value": [1.0, 1.0, 1.0]}})
    si = mi.SurfaceInteraction3f()
    wavelengths = np.arange(360.0, 831.0, 1.0)
    import colour

    ybar = colour.MSDS_CMFS["CIE 1931 2 Degree Standard Observer"].copy().align(
        colour.SpectralShape(360, 830, 1)).values[:, 1]
    radiance = []
    for w in wavelengths:
        si.wavelengths = mi.Spectrum([float(w)] * 4)
        radiance.append(float(np.array(white.eval(si)).ravel()[0]))
    luminance = 683.0 * c * float(np.sum(np.array(radiance) * ybar))
    assert map_illuminance(str(path)) == pytest.approx(math.pi * luminance, rel=0.005)
    scene = scene_from_dict({"name": "u", "environment": {"map": str(path), "illuminance": 5000.0}})
    assert environment_scale(scene) * map_illuminance(str(path)) == pytest.approx(5000.0, rel=1e-9)


def test_map_columns_lie_at_their_azimuths(mi, tmp_path):
    # Column u at azimuth 360° u + rotation clockwise from north; the top row is the zenith.
    from oceanrender.render.environment import _envmap

    image = np.full((32, 64, 3), 0.01)
    image[8:12, 14:18] = 10.0  # u ≈ 0.25 (east), 22-45° up
    path = _write(mi, tmp_path / "east.exr", image)

    def radiance(emitter, azimuth_deg, elevation_deg=35.0):
        a, e = math.radians(azimuth_deg), math.radians(elevation_deg)
        si = mi.SurfaceInteraction3f()
        si.wi = mi.Vector3f(-math.cos(e) * math.sin(a), -math.cos(e) * math.cos(a), -math.sin(e))
        si.wavelengths = mi.Spectrum([550.0] * 4)
        return float(np.array(emitter.eval(si)).ravel()[0])

    plain = mi.load_dict(_envmap(str(path), 1.0, 0.0))
    assert radiance(plain, 90.0) > 100 * radiance(plain, 0.0)
    turned = mi.load_dict(_envmap(str(path), 1.0, 90.0))
    assert radiance(turned, 180.0) > 100 * radiance(turned, 90.0)


def test_the_shipped_map_gives_sunskys_adapting_white(mi):
    # scenes/environment.toml's map is sunsky's own sky (scripts/make_sky_map.py) plus its sun: the white a
    # Lambertian plane shows under it equals sunsky's within 2 % (RGB upsampling of the sky, noise of the meters).
    from oceanrender.render.renderer import adapting_white_XYZ

    with_map = load_scene(SCENES / "environment.toml")
    data = with_map.model_dump()
    data.pop("environment")
    plain = scene_from_dict(data)
    np.testing.assert_allclose(adapting_white_XYZ(with_map), adapting_white_XYZ(plain), rtol=0.02)


@pytest.mark.parametrize("image, suffix, expected", [
    (np.ones((16, 16, 3)), ".exr", "is not equirectangular"),
    (np.where(np.arange(32)[None, :, None] == 3, np.nan, 1.0) * np.ones((16, 32, 3)), ".exr", "non-finite"),
    (-np.ones((16, 32, 3)), ".exr", "negative"),
    (None, ".exr", "cannot open"),
    (b"not an image", ".png", "expected an EXR or Radiance .hdr"),
])
def test_bad_maps_are_one_line_errors_before_any_work(mi, tmp_path, capsys, image, suffix, expected):
    path = tmp_path / f"map{suffix}"
    if isinstance(image, bytes):
        path.write_bytes(image)
    elif image is not None:
        _write(mi, path, image)
    scene = tmp_path / "s.toml"
    scene.write_text(f'name = "s"\n[environment]\nmap = "{path.name}"\n')
    assert main(["render", str(scene), "--out", str(tmp_path / "out"), "--no-progress"]) == 2
    err = capsys.readouterr().err.strip()
    assert "[environment] map" in err and expected in err and "\n" not in err, err
    assert not (tmp_path / "out" / "s").exists() or not any((tmp_path / "out" / "s").glob("frame_*"))


def test_environment_keys_are_checked(tmp_path, capsys):
    from oceanrender.scene import SceneError

    with pytest.raises(SceneError, match="give scale or illuminance, not both"):
        scene_from_dict({"name": "e", "environment": {"map": "x.exr", "scale": 1.0, "illuminance": 1e4}})
    with pytest.raises(SceneError, match=r"a map is a still sky"):
        scene_from_dict({"name": "e", "environment": {"map": "x.exr"},
                         "sun": {"keys": [{"time": 0.0, "elevation": 30.0, "azimuth": 0.0},
                                          {"time": 1.0, "elevation": 31.0, "azimuth": 0.0}]}})
    assert main(["bake-luts", str(SCENES / "environment.toml"), "--out", str(tmp_path / "l")]) == 2
    assert "works under sunsky's sun and sky only" in capsys.readouterr().err


@pytest.mark.slow
def test_the_environment_scene_renders_with_its_passes(tmp_path):
    from oceanrender.io.frames import read_exr
    from oceanrender.pipeline import pass_channels

    out = tmp_path / "out"
    assert main(["render", str(SCENES / "environment.toml"), "--frames", "0:1", "--resolution", "32x18", "--spp", "2",
                 "--out", str(out), "--no-progress"]) == 0
    channels, meta = read_exr(out / "environment" / "frame_0000.exr")
    assert meta["sky"].startswith("environment map sunsky_e35_t3.exr") and "lx on a horizontal plane" in meta["sky"]
    scene = load_scene(SCENES / "environment.toml")
    for name in pass_channels(scene.output.passes):
        assert channels[name].shape == (18, 32) and np.all(np.isfinite(channels[name]))
    assert 0 < channels["mask.water"].mean() < 1  # sea and sky both in view
