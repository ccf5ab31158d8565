"""Scene files: validation errors name the file, the key and what was expected."""

import json
from pathlib import Path

import numpy as np
import pytest

from oceanrender.scene import SceneError, load_scene, scene_from_dict, with_overrides
from tests.extras import needs_spectra
from tests.tolerances import ROUNDOFF

SCENES = Path(__file__).resolve().parents[2] / "scenes"


def write(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "bad_scene.toml"
    path.write_text(text)
    return path


@pytest.mark.parametrize("path", [pytest.param(p, marks=needs_spectra) if p.name == "measured_sea.toml" else p
                                  for p in sorted(SCENES.glob("*.toml"))], ids=lambda p: p.name)
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
        ("[vision]\nbrightness = 'Reinhard'\n",
         "[vision] brightness: Input should be 'Reinhard Devlin 2005', 'Ward 1994' or 'Ferwerda 1996' (got 'Reinhard')"),
        ("[vision]\nadaptation_luminance = -5.0\n",
         "[vision] adaptation_luminance: expected 'frame', 'daylight' or a finite luminance > 0"),
        ("[vision]\nadaptation_luminance = inf\n", "[vision] adaptation_luminance: Input should be a finite number"),
        ("[vision]\nexposure = 10.5\n", "[vision] exposure: Input should be less than or equal to 10 (got 10.5)"),
        ("[vision]\nexposure = nan\n", "[vision] exposure: Input should be a finite number (got nan)"),
        ("[vision]\nadaptation_time = -0.1\n", "[vision] adaptation_time: Input should be greater than or equal to 0"),
        ("[vision]\nadaptation_time = inf\n", "[vision] adaptation_time: Input should be a finite number"),
        ("[render]\nvariant = 'llvm_ad_rgb'\n", "[render] variant: expected 'auto' or one of cuda_ad_spectral, llvm_ad_spectral"),
        ("[water]\ndepth = -3\n", "[water] depth: Input should be greater than 0"),
        ("[camera]\nposition = [0, 0, -1060]\ntarget = [0, 10, -1060]\n", "[camera] position: the camera is at z = -1060 m, at or below the water body's bottom"),
        ("[water]\ntemperature = 45\n", "[water] temperature: Input should be less than or equal to 40"),
        # issue 43: the range of the pure-water absorption model (WOPP v3, 0-40 °C, 0-40 PSU)
        ("[water]\ntemperature = -1\n", "[water] temperature: Input should be greater than or equal to 0"),
        ("[water]\nsalinity = 41\n", "[water] salinity: Input should be less than or equal to 40"),
        ("[composition]\npreset = 'green coastal'\nphytoplankton_absorption = 'Morel 1988'\n",
         "[composition] phytoplankton_absorption: Input should be 'Bricaud 1998' or 'Hoepffner-Sathyendranath 1991'"),
        ("[water]\nsalinity = -1\n", "[water] salinity: Input should be greater than or equal to 0"),
        ("[water]\nior = 1.34\nsalinity = 30\n", "water: ior: leave it out when temperature or salinity is given"),
        ("[composition]\ntemperature_c = 10\n", "[composition] temperature_c"),
        ("[ocean\n", "not valid TOML"),
        ("[foam]\nthreshold = 0.6\n", "foam: threshold applies to criterion 'Jacobian' only"),
        ("[foam]\ncriterion = 'Jacobian'\n", "foam: criterion 'Jacobian' needs a threshold"),
        ("[foam]\ncriterion = 'folding'\n", "[foam] criterion: Input should be 'crest acceleration' or 'Jacobian'"),
        ("[foam]\nbreaking_acceleration = 0\n", "[foam] breaking_acceleration: Input should be greater than 0"),
        ("[foam]\ntime_step = 0.001\n", "[foam] time_step: Input should be greater than or equal to 0.01"),
        ("[foam]\nwhitewater_dissipation = -1\n", "[foam] whitewater_dissipation: Input should be greater than 0"),
        ("[foam]\ndecay_time = 50.0\nhistory = 10.0\ntime_step = 0.1\n", "foam: history × decay_time / time_step"),
        # Issue 23: the sea's three forms and their inputs.
        ("[ocean]\nhs = 2.0\ntp = 8.0\nwind_speed = 9.0\n", "ocean: give the sea in exactly one form, got wind"),
        ("[ocean]\nhs = 2.0\n", "ocean: the sea-state form needs both hs [m] and tp [s]"),
        ("[ocean]\nhs = 0\ntp = 8.0\n", "[ocean] hs: Input should be greater than 0"),
        ("[ocean]\nhs = 2.0\ntp = 0.5\n", "[ocean] tp: Input should be greater than or equal to 1"),
        ("[ocean]\nhs = 2.0\ntp = 45\n", "[ocean] tp: Input should be less than or equal to 30"),
        ("[ocean]\nhs = 2.0\ntp = 8.0\nspectrum = 'Phillips 2001'\n", "the sea-state form (hs, tp) takes spectrum"),
        ("[ocean]\nhs = 2.0\ntp = 8.0\nspreading = 'cos2'\n", "the sea-state form spreads with cos-2s"),
        ("[ocean]\nhs = 2.0\ntp = 8.0\n[[ocean.partitions]]\nhs = -1\ntp = 12\n",
         "[ocean.partitions[0]] hs: Input should be greater than 0"),
        ("[ocean]\nhs = 2.0\ntp = 8.0\n[[ocean.partitions]]\nhs = 1\n", "[ocean.partitions[0]] tp: required key is missing"),
        ("[ocean]\nspectrum_file = 'none.swn'\n", "[ocean] spectrum_file: "),
        ("[ocean]\nspectrum_file = 'none.swn'\nhs = 1.0\ntp = 8.0\n", "give the sea in exactly one form"),
        ("[ocean]\nspectrum_time = '2026-01-01'\n", "spectrum_format, spectrum_time, spectrum_site and spectrum_tail need spectrum_file"),
        ("[ocean]\nspectrum = 'Pierson-Moskowitz 1964'\nfetch = 1e4\n", "fetch: 'Pierson-Moskowitz 1964' has no fetch"),
        ("[ocean]\nsurface_tension = 0.5\n", "[ocean] surface_tension: Input should be less than or equal to 0.1"),
        ("[ocean]\nmodel = 'Gerstner'\nsurface_tension = 0.07\n", "surface_tension is applied by model 'FFT' only"),
        # Issue 41: the volume's beam is the open sea's alone.
        ("[render]\nshaft_cell = 0.05\n[coastal]\nsize = [10.0, 10.0]\ncells = [20, 20]\n",
         "[render] shaft_cell: the volume's beam is traced from the open sea's fields alone; a [coastal] scene "
         "cannot use it: expected 0, got 0.05"),
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


# ---- Animation: [[camera.keys]], [[sun.keys]], [sun.clock] ----

CAMERA_KEYS = """
[[camera.keys]]
time = 0.0
position = [0, 0, 5]
target = [0, 60, 0]
fov = 60
[[camera.keys]]
time = 2.0
position = [10, 5, 8]
target = [-20, 60, 0]
fov = 50
"""

SUN_KEYS = """
[[sun.keys]]
time = 0.0
elevation = 40
azimuth = 350
[[sun.keys]]
time = 2.0
elevation = 20
azimuth = 370
"""

#: A sun that dips to 0.5° at t = 1 s and climbs steeply after.
DIPPING_SUN_KEYS = """
[[sun.keys]]
time = 0.0
elevation = 10
azimuth = 350
[[sun.keys]]
time = 1.0
elevation = 0.5
azimuth = 370
[[sun.keys]]
time = 2.0
elevation = 60
azimuth = 380
"""

CLOCK = """
[sun.clock]
latitude = 43.3
longitude = 5.37
start = {start}
time_scale = {scale}
"""


def test_animated_scene_parses_and_fills_the_still_keys_from_the_motion(tmp_path):
    from oceanrender.scene.motion import camera_motion, sun_motion

    scene = load_scene(write(tmp_path, "[camera]\ninterpolation = 'Catmull-Rom'\n" + CAMERA_KEYS + SUN_KEYS))
    assert scene.camera.animated and scene.sun.animated
    assert scene.camera.position == (0, 0, 5) and scene.camera.target == (0, 60, 0) and scene.camera.fov == 60
    assert (scene.sun.elevation, scene.sun.azimuth) == (40, 350)
    path = camera_motion(scene)
    assert path.interpolation == "Catmull-Rom"
    # Coordinates can be 0: round-off relative to the largest coordinate of the keys [m].
    scale = max(abs(c) for key in scene.camera.keys for c in (*key.position, *key.target))
    for key in scene.camera.keys:  # the path of the file passes through its keys
        position, target, fov = path.at(key.time)
        assert tuple(position) == pytest.approx(key.position, abs=ROUNDOFF * scale)
        assert tuple(target) == pytest.approx(key.target, abs=ROUNDOFF * scale)
        assert fov == pytest.approx(key.fov, rel=ROUNDOFF)
    # Through north, 350 -> 370: 0 in [0, 360), compared as an angle (a value a last bit
    # below 360 wraps to 359.99…), round-off relative to a full turn.
    azimuth = sun_motion(scene).at(1.0).azimuth
    assert (azimuth + 180.0) % 360.0 - 180.0 == pytest.approx(0.0, abs=ROUNDOFF * 360.0)
    # A round trip through model_dump (command-line overrides) keeps the same motion.
    again = with_overrides(scene, output={"spp": 2})
    assert again.camera == scene.camera and again.sun == scene.sun


def test_still_scenes_are_unchanged():
    scene = scene_from_dict({"name": "x"})
    assert not scene.camera.animated and not scene.sun.animated
    from oceanrender.scene.motion import camera_motion, sun_motion

    assert camera_motion(scene) is None and sun_motion(scene) is None


def test_solar_clock_scene_takes_its_still_sun_from_the_clock(tmp_path):
    from oceanrender.scene.motion import solar_position_NOAA, sun_motion, utc

    scene = load_scene(write(tmp_path, CLOCK.format(start="2024-06-21T19:30:00+02:00", scale=900.0)))
    expected = solar_position_NOAA(utc(2024, 6, 21, 17, 30), 43.3, 5.37)
    # The same NOAA equations at the same instant [deg]: 1e-9° is round-off only.
    assert scene.sun.elevation == pytest.approx(expected.apparent_elevation, abs=1e-9)
    assert scene.sun.azimuth == pytest.approx(expected.azimuth, abs=1e-9)
    later = solar_position_NOAA(utc(2024, 6, 21, 17, 45), 43.3, 5.37)  # t = 1 s is 15 min later
    assert sun_motion(scene).at(1.0).elevation == pytest.approx(later.apparent_elevation, abs=1e-9)


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        (CAMERA_KEYS.split("[[camera.keys]]\ntime = 2.0")[0], "[camera] keys: [[camera.keys]] needs at least 2 keyframes, got 1"),
        (CAMERA_KEYS.replace("time = 2.0", "time = 0.0"), "[camera] keys: key times must strictly increase, but key 2 at time = 0 s"),
        (CAMERA_KEYS.replace("fov = 50", "fov = 180"), "[camera.keys[1]] fov: Input should be less than 180"),
        (CAMERA_KEYS.replace("target = [-20, 60, 0]", "target = [10, 5, 8]"), "[camera] keys[1]: camera key at time = 2 s: target must differ from position"),
        (CAMERA_KEYS.replace("position = [10, 5, 8]\n", ""), "[camera.keys[1]] position: required key is missing"),
        ("[camera]\nposition = [1, 2, 3]\n" + CAMERA_KEYS, "camera: position = [1, 2, 3] contradicts the motion"),
        ("[camera]\ninterpolation = 'linear'\n" + CAMERA_KEYS, "[camera] interpolation: Input should be 'monotone cubic' or 'Catmull-Rom'"),
        (SUN_KEYS.replace("elevation = 20", "elevation = -3"), "[sun.keys[1]] elevation: Input should be greater than or equal to 0.5"),
        (SUN_KEYS.replace("time = 2.0", "time = -1.0"), "[sun] keys: key times must strictly increase"),
        ("[sun]\nazimuth = 10\n" + SUN_KEYS, "sun: azimuth = 10 contradicts the motion"),
        (SUN_KEYS + CLOCK.format(start="2024-06-21T12:00:00Z", scale=1.0), "sun: give either [[sun.keys]] or [sun.clock], not both"),
        (CLOCK.format(start="2024-06-21T19:30:00", scale=1.0), "[sun.clock] start: Input should have timezone info"),
        (CLOCK.format(start="'noon'", scale=1.0), "[sun.clock] start: Input should be a valid datetime"),
        (CLOCK.format(start="2024-06-21T23:00:00+02:00", scale=1.0), "sun: [sun.clock]: the sun is below the horizon (or within 0.5° of it) at start"),
        # 21:15 local, 1 h per second: apparent elevation +0.09° at frame 2 (21:20), -0.84° at frame 3 (21:22:30).
        ("[output]\nframes = [0, 48]\n" + CLOCK.format(start="2024-06-21T21:15:00+02:00", scale=3600.0),
         "sun: [sun.clock]: the sun is below the horizon (or within 0.5° of it) at frame 1 (t = 0.0416667 s): elevation 0.41 deg"),
        # Catmull-Rom overshoots below the horizon before the low key at t = 1 s (monotone cubic does not).
        ("[output]\nframes = [0, 48]\n[sun]\ninterpolation = 'Catmull-Rom'\n" + DIPPING_SUN_KEYS,
         "sun: [[sun.keys]]: the sun is below the horizon (or within 0.5° of it) at frame 13 (t = 0.541667 s)"),
    ],
)
def test_animation_errors_are_one_line_naming_the_key(tmp_path, text, expected):
    path = write(tmp_path, text)
    with pytest.raises(SceneError) as info:
        load_scene(path)
    message = str(info.value)
    assert message.startswith(str(path)) and "\n" not in message, message
    assert expected in message, message


def test_monotone_sun_keyed_above_the_horizon_stays_above_it(tmp_path):
    # The keys that Catmull-Rom takes below the horizon (see above) are valid with the default.
    scene = load_scene(write(tmp_path, "[output]\nframes = [0, 48]\n" + DIPPING_SUN_KEYS))
    assert scene.sun.interpolation == "monotone cubic"


@pytest.mark.parametrize("key, value", [("gamma", 2.0), ("alpha", 0.01), ("spreading", "Mitsuyasu 1975")])
def test_elfouhaily_refuses_what_it_sets_itself(key, value):
    with pytest.raises(SceneError, match=key):
        scene_from_dict({"name": "e", "ocean": {"spectrum": "Elfouhaily 1997", key: value}})


def test_foam_defaults_are_the_published_values():
    foam = scene_from_dict({"name": "t"}).foam
    assert foam.criterion == "crest acceleration" and foam.threshold is None
    assert foam.albedo == 0.55  # fresh foam, Whitlock et al. (1982)
    assert scene_from_dict({"name": "t", "foam": {"criterion": "Jacobian", "threshold": 0.3}}).foam.threshold == 0.3


def test_a_view_replaces_the_camera_and_names_its_own_folder():
    from oceanrender.scene import with_view

    scene = scene_from_dict({"name": "bay", "camera": {"position": [0.0, 0.0, 5.0], "target": [0.0, 9.0, 0.0],
                                                       "views": {"cliff": {"position": [1.0, 2.0, 30.0],
                                                                           "target": [5.0, 50.0, 0.0], "fov": 40.0}}}})
    cliff = with_view(scene, "cliff")
    assert cliff.name == "bay_cliff"
    assert (cliff.camera.position, cliff.camera.target, cliff.camera.fov) == ((1.0, 2.0, 30.0), (5.0, 50.0, 0.0), 40.0)
    assert scene.camera.position == (0.0, 0.0, 5.0)  # the scene itself is unchanged (frozen)


@pytest.mark.parametrize("views, key", [
    ({"bad name": {"position": [0, 0, 5], "target": [0, 9, 0]}}, "views"),
    ({"low": {"position": [0, 0, -1001], "target": [0, 9, 0]}}, "[camera] position"),  # below the 1000 m bottom
    ({"same": {"position": [0, 0, 5], "target": [0, 0, 5]}}, "views"),
])
def test_bad_views_are_refused_naming_the_key(views, key):
    with pytest.raises(SceneError) as error:
        scene_from_dict({"name": "bay", "camera": {"views": views}}, "bay.toml")
    assert key in str(error.value) and "\n" not in str(error.value)


@pytest.mark.parametrize("scheme, cfl, accepted", [
    ("kinetic", 0.5, True), ("kinetic", 0.6, False), ("HLL split", 0.6, False),
    ("kinetic split", 0.9, True), ("kinetic split", 1.0, True),
])
def test_the_second_order_courant_bound_follows_the_scheme(scheme, cfl, accepted):
    # The unsplit Heun schemes keep h >= 0 only for cfl <= 1/2; the split MUSCL-Hancock
    # sweeps of "kinetic split" for cfl <= 1 (oceanrender.coastal.swe, CFL_BOUND / SPLIT_CFL_BOUND).
    data = {"name": "t", "coastal": {"order": 2, "scheme": scheme, "cfl": cfl}}
    if accepted:
        assert scene_from_dict(data).coastal.cfl == cfl
    else:
        with pytest.raises(SceneError) as error:
            scene_from_dict(data, "t.toml")
        assert "cfl" in str(error.value) and "\n" not in str(error.value)


@pytest.mark.parametrize("coastal, key", [
    ({"scheme": "dg", "order": 1, "limiter": "minmod", "cfl": 0.3}, "[coastal] scheme"),  # P1 is second order
    ({"scheme": "dg", "limiter": "MC", "cfl": 0.3}, "[coastal] limiter"),  # DG takes minmod or TVB
    ({"scheme": "kinetic", "limiter": "TVB"}, "[coastal] limiter"),  # TVB is DG's
    ({"scheme": "dg", "limiter": "minmod", "cfl": 0.4}, "[coastal] cfl"),  # ν ≤ 1/3 for P1 with RK2
    ({"scheme": "dg", "limiter": "minmod", "tvb_m": 20.0, "cfl": 0.3}, "[coastal] tvb_m"),  # unused without TVB
    ({"scheme": "dg", "limiter": "TVB", "tvb_m": -1.0, "cfl": 0.3}, "[coastal] tvb_m"),
    ({"scheme": "dgx", "limiter": "minmod"}, "[coastal] scheme"),
])
def test_a_dg_scheme_with_settings_it_cannot_use_is_refused_naming_the_key(coastal, key):
    with pytest.raises(SceneError) as error:
        scene_from_dict({"name": "t", "coastal": {"order": 2, **coastal}}, "t.toml")
    message = str(error.value)
    assert message.startswith("t.toml: ") and key in message and "\n" not in message


def test_a_dg_scheme_is_accepted_with_its_limiters():
    for limiter, extra in (("minmod", {}), ("TVB", {}), ("TVB", {"tvb_m": 10.0})):
        coastal = scene_from_dict({"name": "t", "coastal": {"scheme": "dg", "limiter": limiter, "cfl": 1 / 3,
                                                            **extra}}).coastal
        assert coastal.scheme == "dg" and coastal.limiter == limiter and coastal.tvb_m == extra.get("tvb_m")


def _object_scene(tmp_path, entry: str, extra: str = "") -> Path:
    import trimesh

    trimesh.creation.box(extents=(4.0, 2.0, 2.0)).export(tmp_path / "box.ply")
    open_box = trimesh.creation.box(extents=(4.0, 2.0, 2.0))
    open_box.update_faces(np.arange(len(open_box.faces)) != 0)  # one triangle removed: not watertight
    open_box.export(tmp_path / "open.ply")
    path = tmp_path / "objects.toml"
    path.write_text(f'name = "objects"\n{extra}[[objects]]\nname = "box"\n{entry}')
    return path


@pytest.mark.parametrize("entry, extra, expected", [
    ('mesh = "nothing.ply"\n', "", "[[objects]] box mesh: cannot open"),
    ('mesh = "box.ply"\nmaterial = "wood"\n', "", "[objects[0]] material: Input should be 'diffuse'"),
    ('mesh = "box.ply"\nposition = [0, 0, nan]\n', "", "[objects[0]] position[2]: Input should be a finite number"),
    ('mesh = "box.ply"\nposition = [0, 0, -9.5]\n', "[water]\ndepth = 10.0\n",
     "[[objects]] box position: the object can reach down to z = -10.5 m"),
    ('mesh = "open.ply"\nfloating = true\n', "", "[[objects]] box mesh: a floating object needs a closed"),
    ('mesh = "box.ply"\nfloating = true\npitch = 5.0\n', "", "pitch and roll come from the sea"),
    ('mesh = "box.ply"\nposition = [0, 0, 2.0]\nfloating = true\n', "", "must reach below its waterline"),
    ('mesh = "box.ply"\n[[objects]]\nname = "box"\nmesh = "box.ply"\n', "", "box appear(s) more than once"),
])
def test_object_errors_are_one_line_naming_the_key(tmp_path, entry, extra, expected):
    path = _object_scene(tmp_path, entry, extra)
    with pytest.raises(SceneError) as info:
        load_scene(path)
    message = str(info.value)
    assert message.startswith(str(path)) and expected in message and "\n" not in message, message


def test_object_paths_are_relative_to_the_scene_file(tmp_path):
    path = _object_scene(tmp_path, 'mesh = "box.ply"\n')
    assert load_scene(path).objects[0].mesh == str(tmp_path / "box.ply")


EXAMPLE = SCENES / "sea_states" / "bimodal.swn"


@needs_spectra
@pytest.mark.parametrize(("extra", "key", "expected"), [
    ("spectrum_time = '2026-03-14T09:00:00'\n", "spectrum_time", "is not in the file (it has 3 times"),
    ("spectrum_time = 'noon'\n", "spectrum_time", "is not an ISO 8601 time"),
    ("spectrum_site = 2\n", "spectrum_site", "spectrum_site 2 is not in the file (it has 2 site(s)"),
    ("spectrum_format = 'json'\n", "spectrum_file", "wavespectra.read_json cannot read it"),
])
def test_spectrum_file_errors_name_the_key_before_any_work(tmp_path, extra, key, expected):
    path = write(tmp_path, f"[ocean]\nspectrum_file = '{EXAMPLE}'\n" + extra)
    with pytest.raises(SceneError) as info:
        load_scene(path)
    message = str(info.value)
    assert message.startswith(f"{path}: [ocean] {key}: {EXAMPLE}: ") and expected in message and "\n" not in message


@needs_spectra
def test_unreadable_spectrum_file(tmp_path):
    (tmp_path / "garbage.swn").write_text("not a spectrum\n")
    with pytest.raises(SceneError, match=r"\[ocean\] spectrum_file: .*garbage.swn: wavespectra.read_swan cannot read"):
        load_scene(write(tmp_path, "[ocean]\nspectrum_file = 'garbage.swn'\n"))


@needs_spectra
def test_sea_forms_are_read():
    wind = load_scene(SCENES / "open_ocean.toml").ocean
    state = load_scene(SCENES / "swell_crossing.toml").ocean
    measured = load_scene(SCENES / "measured_sea.toml").ocean
    assert (wind.form, state.form, measured.form) == ("wind", "sea state", "file")
    assert state.hs == 1.4 and state.partitions[0].tp == 12.5 and state.surface_tension == 0.074
    assert measured.spectrum_file == str(EXAMPLE.resolve())  # relative to the scene file


def test_an_empty_scene_is_the_default_scene(tmp_path):
    """The schema's defaults are scenes/open_ocean.toml's (issue 39: an empty file rendered a patch and a void)."""
    shipped = load_scene(Path(__file__).resolve().parents[2] / "scenes" / "open_ocean.toml").model_dump()
    empty = load_scene(write(tmp_path, "")).model_dump()
    shipped.pop("name"), empty.pop("name")
    # The file names ior = 1.333; left out, the water's index is the same 1.333 (optics.water.water_ior).
    assert shipped["water"].pop("ior") == 1.333 and empty["water"].pop("ior") is None
    assert empty == shipped


def test_the_sea_state_form_defaults_to_jonswap():
    assert scene_from_dict({"name": "s", "ocean": {"hs": 2.0, "tp": 8.0}}).ocean.spectrum == "JONSWAP 1973"
    assert scene_from_dict({"name": "s"}).ocean.spectrum == "Elfouhaily 1997"


@pytest.mark.parametrize("directory, message", [("a\x00b", "NUL byte"), ("x" * 300, "longer than 255 bytes")])
def test_output_directories_the_file_system_cannot_hold_are_refused_at_load(tmp_path, directory, message):
    with pytest.raises(SceneError, match=rf"\[output\] directory: .*{message}"):
        load_scene(write(tmp_path, f"[output]\ndirectory = {json.dumps(directory)}\n"))  # TOML reads \\u0000


def test_long_values_and_keys_are_quoted_short(tmp_path):
    """A 5000-character name or key is shown as ~80 characters and its length (issue 39)."""
    with pytest.raises(SceneError) as error:
        load_scene(write(tmp_path, 'name = "' + "x" * 5000 + '"\n'))
    assert len(str(error.value)) < 400 and "(5002 characters)" in str(error.value)
    with pytest.raises(SceneError) as error:
        load_scene(write(tmp_path, "[output]\n" + "k" * 3000 + " = 1\n"))
    assert len(str(error.value)) < 300 and "unknown key" in str(error.value)
