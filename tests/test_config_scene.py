"""Scene files: validation errors name the file, the key and what was expected."""

from pathlib import Path

import pytest

from oceanrender.config import SceneError, load_scene, scene_from_dict, with_overrides

SCENES = Path(__file__).resolve().parents[1] / "scenes"


def write(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "bad_scene.toml"
    path.write_text(text)
    return path


@pytest.mark.parametrize("path", sorted(SCENES.glob("*.toml")), ids=lambda p: p.name)
def test_shipped_scenes_load(path):
    scene = load_scene(path)
    assert scene.name == path.stem


def test_defaults_fill_missing_sections(tmp_path):
    scene = load_scene(write(tmp_path, "[ocean]\nwind_speed = 9.0\n"))
    assert scene.ocean.wind_speed == 9.0
    assert scene.output.frames == (0, 3)
    assert scene.name == "bad_scene"


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("[ocean]\nwind_speed = -1.0\n", "[ocean] wind_speed: Input should be greater than 0"),
        ("[ocean]\nwind_speed = 0\n", "[ocean] wind_speed"),
        ("[ocean]\nwindspeed = 5.0\n", "[ocean] windspeed: unknown key"),
        ("[oceans]\n", "oceans: unknown key"),
        ("[ocean]\nresolution = 255\n", "[ocean] resolution: expected an even number"),
        ("[ocean]\nspectrum = 'Foo 1999'\n", "[ocean] spectrum: Input should be 'Phillips 2001'"),
        ("[output]\nframes = [5, 2]\n", "[output] frames: expected [start, end) with end > start"),
        ("[output]\nresolution = [320]\n", "[output] resolution[1]: expected more values"),
        ("[sun]\nelevation = 120\n", "[sun] elevation: Input should be less than or equal to 90"),
        ("[camera]\nposition = [0, 0, 1]\ntarget = [0, 0, 1]\n", "camera target must differ"),
        ("[vision]\nbrightness = 'Reinhard'\n", "[vision] brightness: Input should be 'Ward 1994' or 'Ferwerda 1996'"),
        ("[vision]\nadaptation_luminance = -5.0\n", "[vision] adaptation_luminance: expected 'frame', 'daylight' or a luminance > 0"),
        ("[render]\nvariant = 'llvm_ad_rgb'\n", "[render] variant: expected 'auto' or a spectral variant"),
        ("[water]\ndepth = -3\n", "[water] depth: Input should be greater than 0"),
        ("[ocean\n", "not valid TOML"),
    ],
)
def test_errors_are_one_line_with_file_and_key(tmp_path, text, expected):
    path = write(tmp_path, text)
    with pytest.raises(SceneError) as info:
        load_scene(path)
    message = str(info.value)
    assert message.startswith(str(path)), message
    assert expected in message
    assert "\n" not in message


def test_error_includes_unit(tmp_path):
    with pytest.raises(SceneError, match=r"m s⁻¹"):
        load_scene(write(tmp_path, "[ocean]\nwind_speed = -1.0\n"))


def test_missing_file():
    with pytest.raises(SceneError, match="cannot read scene file"):
        load_scene("no/such/scene.toml")


def test_settings_are_immutable():
    scene = scene_from_dict({"name": "x"})
    with pytest.raises(Exception, match="frozen"):
        scene.output.spp = 3


def test_overrides_are_validated_like_the_file():
    scene = scene_from_dict({"name": "x"})
    assert with_overrides(scene, output={"spp": 4}).output.spp == 4
    with pytest.raises(SceneError, match=r"^command line: \[output\] spp"):
        with_overrides(scene, output={"spp": 0})


def test_toml_cannot_execute_anything(tmp_path):
    # A string that would be code in a Python-based config stays an invalid value here.
    with pytest.raises(SceneError, match=r"\[ocean\] wind_speed"):
        load_scene(write(tmp_path, "[ocean]\nwind_speed = \"__import__('os').getcwd()\"\n"))
