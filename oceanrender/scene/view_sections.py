"""The light and the eye in a scene file: ``[sun]`` (keys, solar clock), ``[environment]``, ``[camera]``
(keys, views) and ``[vision]``.

Part of :mod:`.settings` (which re-exports every name here); units and conventions there.
"""

from __future__ import annotations

import math
from typing import Annotated, Literal

from pydantic import AwareDatetime, Field, ValidationError, field_validator, model_validator

from .motion import SolarClock
from .section_base import Interpolation, MIN_SUN_ELEVATION, SAFE_NAME, Vec3, _Section


def _first_key_fills(data, fields: dict[str, object], section: str) -> dict:
    """Fill the static keys of an animated section from its motion; refuse ones that contradict it.

    ``fields`` maps each static key to its value from the motion. A value
    written in the file must equal it (to 1e-9), so that a file, and the
    same settings dumped and validated again (:func:`with_overrides`), mean
    one thing.
    """
    data = dict(data)
    for name, value in fields.items():
        given = data.get(name)
        if given is None:
            data[name] = value
            continue
        try:
            same = all(abs(float(a) - float(b)) <= 1e-9 * max(1.0, abs(float(b)))
                       for a, b in zip(_as_tuple(given), _as_tuple(value), strict=True))
        except (TypeError, ValueError):
            same = False
        if not same:
            raise ValueError(f"{name} = {given!r} contradicts the motion, which gives {value!r} here; "
                             f"leave {name} out when [{section}] is animated")
    return data


def _as_tuple(value) -> tuple:
    return tuple(value) if isinstance(value, (list, tuple)) else (value,)


def _key_value(key, name: str):
    return key.get(name) if isinstance(key, dict) else getattr(key, name, None)


class SunKeySettings(_Section):
    """One sun keyframe (``[[sun.keys]]``)."""

    time: float = Field(..., ge=-1.0e6, le=1.0e6, description="key time, t = frame / fps [s]")
    elevation: float = Field(..., ge=MIN_SUN_ELEVATION, le=90,
                             description="sun elevation above the horizon at the key [deg]")
    azimuth: float = Field(..., ge=-720, le=720, description="sun azimuth clockwise from north (+y) [deg]; "
                                                             "write 350 then 370 to pass through north")


class SolarClockSettings(_Section):
    """The sun over a place as a clock runs (``[sun.clock]``): NOAA solar position at start + time_scale·t."""

    latitude: float = Field(..., ge=-90, le=90, description="geographic latitude, north positive [deg]")
    longitude: float = Field(..., ge=-180, le=180, description="longitude, east positive [deg]")
    start: AwareDatetime = Field(..., description="clock instant of scene time t = 0, ISO 8601 with a UTC offset, "
                                                  "e.g. 2024-06-21T18:30:00+02:00")
    time_scale: float = Field(1.0, ge=-1.0e6, le=1.0e6,
                              description="simulated (clock) seconds per scene second [-]; 600 = 10 min per second")
    apparent: bool = Field(True, description="use the refracted (apparent) elevation, as seen, or the geometric one")
    pressure: float = Field(1010.0, gt=0, le=1100, description="surface pressure for the refraction [hPa]")
    temperature: float = Field(10.0, ge=-90, le=60, description="air temperature for the refraction [°C]")

    def angles_at(self, t: float) -> tuple[float, float]:
        """(elevation, azimuth) of the sun at scene time t [s] [deg]."""
        clock = SolarClock(self.latitude, self.longitude, self.start, self.time_scale, self.apparent,
                           self.pressure, self.temperature)
        return tuple(clock.at(t))


class EnvironmentSettings(_Section):
    """``[environment]``: an equirectangular HDR image as the sky instead of ``sunsky``'s (docs/environment.md).

    The map's top row is the zenith, its bottom row the nadir; column u (0 at the left
    edge, 1 at the right) lies at azimuth 360° u + ``rotation``, clockwise from north (+y).
    """

    map: str = Field(..., min_length=1, max_length=4096,
                     description="equirectangular EXR or Radiance .hdr, 2:1, relative to the scene file")
    scale: float | None = Field(None, gt=0, le=1e9, description="radiance per map unit: an RGB of 1 is Mitsuba's "
                                                                 "upsampled white of about 1 W m⁻² sr⁻¹ nm⁻¹")
    illuminance: float | None = Field(None, gt=0, le=2e5, description="instead of scale: the map's illuminance on "
                                                                       "a horizontal plane [lx] (the sun not counted)")
    rotation: float = Field(0.0, ge=-360, le=360, description="azimuth of the map's left edge, clockwise from north "
                                                              "[deg]")
    sun: bool = Field(False, description="add the [sun]'s solar disk (sunsky's sun, no sky) to the map")

    @model_validator(mode="after")
    def _one_scale(self) -> "EnvironmentSettings":
        if self.scale is not None and self.illuminance is not None:
            raise ValueError("give scale or illuminance, not both")
        return self


class SunSettings(_Section):
    """Sun and sky: Mitsuba's ``sunsky`` (Hosek & Wilkie 2012/2013).

    The sun may move: ``[[sun.keys]]`` (at least two keyframes of elevation
    and azimuth, joined by ``interpolation``) or ``[sun.clock]`` (a place and
    a clock), not both. Then ``elevation`` and ``azimuth`` are those of the
    motion at its first key (keys) or at t = 0 s (clock); leave them out (if
    written they must equal those).
    """

    elevation: float = Field(22.0, ge=MIN_SUN_ELEVATION, le=90, description="sun elevation above the horizon [deg]")
    azimuth: float = Field(30.0, ge=-360, le=360, description="sun azimuth, clockwise from north (+y) [deg]")
    turbidity: float = Field(3.0, ge=1, le=10, description="atmospheric turbidity [-]")
    ground_albedo: float = Field(0.1, ge=0, le=1, description="ground albedo of the sky model [-]")
    sun_scale: float = Field(1.0, ge=0, le=1e3, description="scale of the solar radiance [-]")
    sky_scale: float = Field(1.0, ge=0, le=1e3, description="scale of the sky radiance [-]")
    keys: tuple[SunKeySettings, ...] = Field((), description="sun keyframes (time [s], elevation, azimuth [deg])")
    clock: SolarClockSettings | None = Field(None, description="a place and a clock instead of keyframes")
    interpolation: Interpolation = Field("monotone cubic", description="curve through the sun keyframes")

    @model_validator(mode="before")
    @classmethod
    def _static_from_motion(cls, data):
        if not isinstance(data, dict):
            return data
        keys, clock = data.get("keys") or (), data.get("clock")
        if keys and clock is not None:
            raise ValueError("give either [[sun.keys]] or [sun.clock], not both")
        if keys and isinstance(keys, (list, tuple)):
            first = keys[0]
            elevation, azimuth = _key_value(first, "elevation"), _key_value(first, "azimuth")
            # NOTE: a key out of range is reported with its own key path, not through the static fields.
            if (isinstance(elevation, (int, float)) and isinstance(azimuth, (int, float))
                    and MIN_SUN_ELEVATION <= elevation <= 90 and -720 <= azimuth <= 720):
                return _first_key_fills(data, {"elevation": float(elevation),
                                               "azimuth": float(azimuth) % 360.0}, "sun")
        if clock is not None:
            try:
                settings = SolarClockSettings.model_validate(clock)
            except ValidationError:
                return data  # reported with its key when the field itself is validated
            elevation, azimuth = settings.angles_at(0.0)
            if not elevation >= MIN_SUN_ELEVATION:
                raise ValueError(f"[sun.clock]: the sun is below the horizon (or within {MIN_SUN_ELEVATION}° of it) "
                                 f"at start ({settings.start.isoformat()}, t = 0 s): elevation {elevation:.2f} deg; sunsky needs it above")
            return _first_key_fills(data, {"elevation": elevation, "azimuth": azimuth}, "sun")
        return data

    @field_validator("keys")
    @classmethod
    def _key_times(cls, value: tuple[SunKeySettings, ...]) -> tuple[SunKeySettings, ...]:
        if value:
            _check_key_times([key.time for key in value], "sun")
        return value

    @property
    def animated(self) -> bool:
        """Whether the sun moves (keys or a clock)."""
        return bool(self.keys) or self.clock is not None


def _check_key_times(times: list[float], section: str) -> None:
    if len(times) < 2:
        raise ValueError(f"[[{section}.keys]] needs at least 2 keyframes, got {len(times)}")
    for i in range(1, len(times)):
        if not times[i] > times[i - 1]:
            raise ValueError(f"key times must strictly increase, but key {i + 1} at time = {times[i]:g} s "
                             f"follows time = {times[i - 1]:g} s")


class CameraKeySettings(_Section):
    """One camera keyframe (``[[camera.keys]]``)."""

    time: float = Field(..., ge=-1.0e6, le=1.0e6, description="key time, t = frame / fps [s]")
    position: Vec3 = Field(..., description="camera position [m]")
    target: Vec3 = Field(..., description="point looked at [m]")
    fov: float = Field(..., gt=0, lt=180, description="horizontal field of view [deg]")

    @model_validator(mode="after")
    def _distinct(self) -> "CameraKeySettings":
        if self.position == self.target:
            raise ValueError(f"camera key at time = {self.time:g} s: target must differ from position")
        return self


class CameraViewSettings(_Section):
    """Another viewpoint of the same scene (``[camera.views.NAME]``), rendered with ``oceanrender render --view NAME``."""

    position: Vec3 = Field(..., description="camera position [m]")
    target: Vec3 = Field(..., description="point looked at [m]")
    fov: float = Field(60.0, gt=0, lt=180, description="horizontal field of view [deg]")

    @model_validator(mode="after")
    def _distinct(self) -> "CameraViewSettings":
        if self.position == self.target:
            raise ValueError("target must differ from position")
        return self


class CameraSettings(_Section):
    """Pinhole camera (perspective).

    The camera may move: ``[[camera.keys]]``, at least two keyframes of
    position, target and fov at strictly increasing times, joined by
    ``interpolation``. Then ``position``, ``target`` and ``fov`` are the
    first key's; leave them out (if written they must equal it).
    """

    position: Vec3 = (0.0, 0.0, 8.0)
    target: Vec3 = (0.0, 40.0, 0.0)
    fov: float = Field(60.0, gt=0, lt=180, description="horizontal field of view [deg]")
    keys: tuple[CameraKeySettings, ...] = Field((), description="camera keyframes (time [s], position, target [m], "
                                                                "fov [deg])")
    interpolation: Interpolation = Field("monotone cubic", description="curve through the camera keyframes")
    views: dict[Annotated[str, Field(pattern=f"^{SAFE_NAME}$", max_length=40)], CameraViewSettings] = Field(
        default_factory=dict, description="other still viewpoints by name (render with --view NAME into the "
                                          "folder <name>_<view>)")

    @model_validator(mode="before")
    @classmethod
    def _static_from_keys(cls, data):
        if not isinstance(data, dict) or not data.get("keys") or not isinstance(data["keys"], (list, tuple)):
            return data
        first = data["keys"][0]
        values = {name: _key_value(first, name) for name in ("position", "target", "fov")}
        if any(value is None for value in values.values()):
            return data  # the key itself is reported as incomplete
        try:
            values = {"position": tuple(map(float, values["position"])),
                      "target": tuple(map(float, values["target"])), "fov": float(values["fov"])}
        except (TypeError, ValueError):
            return data
        if not 0 < values["fov"] < 180 or len(values["position"]) != 3 or len(values["target"]) != 3:
            return data  # reported with the key's own path
        return _first_key_fills(data, values, "camera")

    @field_validator("keys")
    @classmethod
    def _key_times(cls, value: tuple[CameraKeySettings, ...]) -> tuple[CameraKeySettings, ...]:
        if value:
            _check_key_times([key.time for key in value], "camera")
        return value

    @model_validator(mode="after")
    def _distinct(self) -> "CameraSettings":
        if self.position == self.target:
            raise ValueError("camera target must differ from its position")
        if self.views and self.keys:
            raise ValueError("views are still viewpoints: leave them out of a camera with keys")
        return self

    @property
    def animated(self) -> bool:
        """Whether the camera moves (keys)."""
        return bool(self.keys)


class VisionSettings(_Section):
    """The vision model Φ: brightness and chromatic adaptation, display."""

    brightness: Literal["Reinhard Devlin 2005", "Ward 1994", "Ferwerda 1996"] = Field(
        "Reinhard Devlin 2005", description="brightness adaptation: the compressive photoreceptor model "
                                            "(default) or a linear scale factor")
    chromatic_transform: Literal["Von Kries", "Bradford", "CAT02", "CAT16", "XYZ Scaling"] = "Von Kries"
    adaptation_luminance: float | Literal["frame", "daylight"] = Field(
        "frame", description="world adaptation luminance [cd m⁻²], 'frame' for the log-average of what the "
                             "camera sees (followed over time, see adaptation_time), or 'daylight' for an 18 % "
                             "grey card under the scene's sun and sky"
    )
    adaptation_time: float = Field(
        0.4, ge=0, le=60, description="time constant of the eye's light adaptation [s] for adaptation_luminance = "
                                      "'frame': a step in scene luminance is 95 % adapted to after 3x this; 0: "
                                      "every frame adapts at once to its own log-average")
    exposure: float = Field(0.0, ge=-10, le=10, description="exposure compensation [EV]: +1 doubles the light "
                                                            "before the display response")
    display_luminance: float = Field(100.0, ge=1, le=10_000, description="display white luminance [cd m⁻²]")

    @field_validator("adaptation_luminance")
    @classmethod
    def _positive(cls, value: float | str) -> float | str:
        if not isinstance(value, str) and not (value > 0 and math.isfinite(value)):
            raise ValueError(f"expected 'frame', 'daylight' or a finite luminance > 0 cd/m², got {value}")
        return value
