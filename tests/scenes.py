"""Small scenes for tests: a cheap sea under the keys a test leaves out.

Since issue 39 the schema's defaults are the default scene's (an empty scene file
renders ``scenes/open_ocean.toml``): four 1024² cascades of an Elfouhaily sea at
12 m s⁻¹ on a 230 000-vertex radial mesh, with whitecaps. Most tests need a sea,
not that sea: :func:`small_sea` fills the keys a test's scene leaves out with a
small one — one 256² JONSWAP patch at 7 m s⁻¹ as a closed box, no foam, a 40°
sun, a camera 5 m up, one render pass — so each test renders what it was written
for, at the cost it was written for. Keys a test gives always win.
"""

from __future__ import annotations

import copy
import tomllib

from oceanrender.scene import settings

#: The wind-form keys of the small sea (the spectrum's own; added only where a test names no other form).
SMALL_WIND = {"spectrum": "JONSWAP 1973", "wind_speed": 7.0, "wind_direction": 30.0, "fetch": 1.0e5}
#: Sizes and switches of the small sea, section by section.
SMALL = {
    "ocean": {"cascades": 1, "patch_size": 128.0, "resolution": 256},
    "mesh": {"kind": "patch"},
    "foam": {"enabled": False},
    "render": {"in_water_fraction": 1.0},
    "output": {"spp": 32},
}
#: Keys of the sea-state and file forms: a test that gives one keeps the form's own spectrum and direction.
FORM_KEYS = {"hs", "tp", "sigma_a", "sigma_b", "direction", "spreading_s", "partitions", "spectrum_file",
             "spectrum_format", "spectrum_time", "spectrum_site", "spectrum_tail"}
#: Wind keys each spectrum takes (Phillips and Pierson-Moskowitz have no fetch law).
SPECTRUM_WIND_KEYS = {"Phillips 2001": ("wind_speed", "wind_direction"),
                      "Pierson-Moskowitz 1964": ("wind_speed", "wind_direction")}


def small_sea(data: dict) -> dict:
    """``data`` (a parsed scene) with the small sea's keys wherever ``data`` leaves them out; a new dict."""
    data = copy.deepcopy(data)
    for section, values in SMALL.items():
        table = data.setdefault(section, {})
        for key, value in values.items():
            table.setdefault(key, value)
    ocean = data["ocean"]
    if not FORM_KEYS & ocean.keys():
        spectrum = ocean.setdefault("spectrum", SMALL_WIND["spectrum"])
        for key in SPECTRUM_WIND_KEYS.get(spectrum, ("wind_speed", "wind_direction", "fetch")):
            ocean.setdefault(key, SMALL_WIND[key])
    sun, camera = data.setdefault("sun", {}), data.setdefault("camera", {})
    if not ({"keys", "clock"} & sun.keys()):
        sun.setdefault("elevation", 40.0)
        sun.setdefault("azimuth", 200.0)
    if "keys" not in camera:
        camera.setdefault("position", [0.0, 0.0, 5.0])
    return data


def scene_from_dict(data: dict, source: str = "<dict>"):
    """:func:`oceanrender.scene.scene_from_dict` of :func:`small_sea` (``data``)."""
    return settings.scene_from_dict(small_sea(data), source)


def small_sea_text(text: str) -> str:
    """A scene file's text with the small sea's keys added where it leaves them out (comments are dropped)."""
    from tests.test_fuzz_scenes import toml_text  # noqa: PLC0415

    return toml_text(small_sea(tomllib.loads(text)))
