"""Keyframed camera paths and sun motion.

Camera: keyframes of position [m], target [m] and horizontal field of view
[deg] at times [s], joined by a C¹ piecewise cubic through every keyframe.
Sun: either keyframes of elevation and azimuth [deg] joined the same way,
or a place on Earth and a clock, turned into the sun's elevation and azimuth
by the NOAA solar-position algorithm (after Meeus 1998).

Everything here is pure (frozen dataclasses, arrays in, arrays out); writing a
pose into a loaded Mitsuba scene is the renderer's
(:func:`oceanrender.render.scene.apply_camera`, :func:`~oceanrender.render.scene.apply_sun`).

Conventions as everywhere in oceanrender: world frame z up, +x east, +y
north; azimuth clockwise from north (+y) [deg]; time t = frame / fps [s].

Interpolation
-------------
Two C¹ cubic Hermite interpolants are offered by name (:data:`INTERPOLATIONS`):

``"monotone cubic"`` (default)
    Fritsch & Carlson (1980) piecewise cubic Hermite with the tangents of
    Fritsch & Butland (1984) (scipy's ``PchipInterpolator``), per coordinate.
    Between two keyframes each coordinate stays within their values: a
    camera keyed at 0.5 m over the sea never dips below 0.5 m between its
    keys, a field of view never leaves the keyed range (so never reaches 0°
    or 180°), and a sun keyed above the horizon stays above it (Mitsuba's
    ``sunsky`` needs elevation > 0). The price: where a coordinate has a
    local extremum at a keyframe its velocity there is zero (the camera
    eases through such keys).
``"Catmull-Rom"``
    Non-uniform Catmull–Rom (1974): Hermite tangents of the parabola through
    each key and its neighbours, at the keyframe *times* (the three-point
    "Bessel" tangent, de Boor 1978), one-sided secants at the ends. Smoother
    speed through keys, but it can overshoot between keys.

The keyframes carry explicit times, so the curve parameter is time. This
is why the centripetal Catmull–Rom of Yuksel et al. (2011), whose knots are
chord lengths, is not used: it would pass through the keys at times other
than those keyed.

References
----------
.. [1] F. N. Fritsch & R. E. Carlson (1980), "Monotone piecewise cubic
       interpolation", SIAM J. Numer. Anal. 17(2), 238–246. doi:10.1137/0717021
.. [2] F. N. Fritsch & J. Butland (1984), "A method for constructing local
       monotone piecewise cubic interpolants", SIAM J. Sci. Stat. Comput.
       5(2), 300–304. doi:10.1137/0905021
.. [3] E. Catmull & R. Rom (1974), "A class of local interpolating splines",
       in Computer Aided Geometric Design, Academic Press, 317–326.
       doi:10.1016/B978-0-12-079050-0.50020-5
.. [4] C. de Boor (1978), A Practical Guide to Splines, Springer, ch. IV.
.. [5] C. Yuksel, S. Schaefer & J. Keyser (2011), "Parameterization and
       applications of Catmull–Rom curves", Computer-Aided Design 43(7),
       747–755. doi:10.1016/j.cad.2010.08.008
.. [6] J. Meeus (1998), Astronomical Algorithms, 2nd ed., Willmann-Bell,
       ch. 13, 22, 25, 28; as used by NOAA Global Monitoring Laboratory,
       "NOAA Solar Calculator" (spreadsheet equations),
       https://gml.noaa.gov/grad/solcalc/
.. [7] I. Reda & A. Andreas (2004), "Solar position algorithm for solar
       radiation applications", Solar Energy 76(5), 577–589.
       doi:10.1016/j.solener.2003.12.003 (NREL/TP-560-34302, Table A5.1:
       the reference case used in the tests)
.. [8] Þ. Sæmundsson (1986), "Astronomical refraction", Sky and Telescope
       72, 70 (the refraction formula of [7], Eq. 42).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from datetime import datetime, timezone
from typing import Any, Callable, NamedTuple, Protocol, Sequence

import numpy as np
from scipy.interpolate import CubicHermiteSpline, PchipInterpolator

# ---------------------------------------------------------------------------
# Interpolation: C¹ piecewise cubic Hermite curves through keyframes.
# ---------------------------------------------------------------------------


def check_key_times(times: Sequence[float], what: str = "keyframes") -> np.ndarray:
    """Key times [s] as an array, refused unless ≥ 2, finite and strictly increasing.

    Raises
    ------
    ValueError
        One line saying which rule is broken, with the offending times.
    """
    times = np.asarray(times, dtype=float)
    if times.ndim != 1 or times.size < 2:
        raise ValueError(f"{what}: need at least 2 keyframes, got {times.size}")
    if not np.all(np.isfinite(times)):
        raise ValueError(f"{what}: key times must be finite numbers [s], got {times.tolist()}")
    steps = np.diff(times)
    if np.any(steps <= 0):
        i = int(np.argmax(steps <= 0))
        raise ValueError(f"{what}: key times must strictly increase, but key {i + 1} at t = {times[i + 1]:g} s "
                         f"follows t = {times[i]:g} s")
    return times


def tangents_CatmullRom(times: np.ndarray, values: np.ndarray) -> np.ndarray:
    """Tangents dv/dt at the keys of a non-uniform Catmull–Rom curve [value s⁻¹].

    At an interior key the derivative of the parabola through it and its two
    neighbours (the Bessel tangent of [4]); at the ends the secant to the
    neighbour.

    Parameters
    ----------
    times : ndarray (n,)        Strictly increasing key times [s].
    values : ndarray (n, ...)   Values at the keys.
    """
    h = np.diff(times).reshape(-1, *([1] * (values.ndim - 1)))
    secants = np.diff(values, axis=0) / h
    tangents = np.empty_like(values, dtype=float)
    tangents[0], tangents[-1] = secants[0], secants[-1]
    # [4] ch. IV: (h_k δ_{k-1} + h_{k-1} δ_k) / (h_{k-1} + h_k), δ the secants.
    tangents[1:-1] = (h[1:] * secants[:-1] + h[:-1] * secants[1:]) / (h[:-1] + h[1:])
    return tangents


def interpolant_monotone(times: np.ndarray, values: np.ndarray) -> Callable[[np.ndarray], np.ndarray]:
    """Fritsch–Carlson monotone cubic through (times, values), per column [1, 2]."""
    return PchipInterpolator(times, values, axis=0, extrapolate=False)


def interpolant_CatmullRom(times: np.ndarray, values: np.ndarray) -> Callable[[np.ndarray], np.ndarray]:
    """Non-uniform Catmull–Rom cubic through (times, values), per column [3, 4]."""
    return CubicHermiteSpline(times, values, tangents_CatmullRom(times, values), axis=0, extrapolate=False)


#: Interpolants by name: ``name -> f(times, values) -> callable(t)``.
INTERPOLATIONS: dict[str, Callable[[np.ndarray, np.ndarray], Callable[[np.ndarray], np.ndarray]]] = {
    "monotone cubic": interpolant_monotone,
    "Catmull-Rom": interpolant_CatmullRom,
}


def interpolant(times: np.ndarray, values: np.ndarray, method: str) -> Callable[[np.ndarray], np.ndarray]:
    """The interpolant of ``method`` (a key of :data:`INTERPOLATIONS`); unknown names refused with the list."""
    if method not in INTERPOLATIONS:
        raise ValueError(f"unknown interpolation {method!r}; known: {', '.join(map(repr, INTERPOLATIONS))}")
    return INTERPOLATIONS[method](times, values)


def _clamped(t, times: np.ndarray) -> np.ndarray:
    t = np.asarray(t, dtype=float)
    if not np.all(np.isfinite(t)):
        raise ValueError(f"time must be finite [s], got {t.tolist()}")
    return np.clip(t, times[0], times[-1])


# ---------------------------------------------------------------------------
# Camera
# ---------------------------------------------------------------------------


def _vec3(value, name: str) -> tuple[float, float, float]:
    array = np.asarray(value, dtype=float)
    if array.shape != (3,) or not np.all(np.isfinite(array)):
        raise ValueError(f"{name} must be 3 finite numbers [m], got {value!r}")
    return tuple(float(v) for v in array)


@dataclass(frozen=True)
class CameraKey:
    """A camera keyframe.

    Attributes
    ----------
    time : float                       Key time [s].
    position : (float, float, float)   Camera position, world frame [m].
    target : (float, float, float)     Point looked at [m]; differs from ``position``.
    fov : float                        Horizontal field of view [deg], in (0, 180).
    """

    time: float
    position: tuple[float, float, float]
    target: tuple[float, float, float]
    fov: float

    def __post_init__(self):
        if not math.isfinite(self.time):
            raise ValueError(f"camera key time must be finite [s], got {self.time}")
        object.__setattr__(self, "time", float(self.time))
        object.__setattr__(self, "position", _vec3(self.position, "camera key position"))
        object.__setattr__(self, "target", _vec3(self.target, "camera key target"))
        if not (math.isfinite(self.fov) and 0 < self.fov < 180):
            raise ValueError(f"camera key fov must be in (0, 180) deg, got {self.fov}")
        object.__setattr__(self, "fov", float(self.fov))
        if self.position == self.target:
            raise ValueError(f"camera key at t = {self.time:g} s: target equals position {self.position}")


class CameraPose(NamedTuple):
    """Where the camera is at one time: position [m], target [m], horizontal fov [deg]."""

    position: np.ndarray
    target: np.ndarray
    fov: float


@dataclass(frozen=True)
class CameraPath:
    """A camera moving through keyframes on a C¹ cubic (see the module's Interpolation notes).

    Position, target and field of view are interpolated independently over
    time. Before the first key and after the last the camera holds still.

    Parameters
    ----------
    keys : sequence of CameraKey
        At least two, with strictly increasing times.
    interpolation : str
        A name in :data:`INTERPOLATIONS` (default ``"monotone cubic"``).

    Examples
    --------
    >>> path = CameraPath((CameraKey(0, (0, 0, 5), (0, 60, 0), 60), CameraKey(4, (10, 0, 8), (0, 60, 0), 50)))
    >>> position, target, fov = path.at(2.0)
    """

    keys: tuple[CameraKey, ...]
    interpolation: str = "monotone cubic"
    _curve: Callable = field(init=False, repr=False, compare=False)

    def __post_init__(self):
        keys = tuple(self.keys)
        if not all(isinstance(key, CameraKey) for key in keys):
            raise ValueError("camera path keys must be CameraKey objects")
        times = check_key_times([key.time for key in keys], "camera path")
        values = np.array([[*key.position, *key.target, key.fov] for key in keys])
        object.__setattr__(self, "keys", keys)
        object.__setattr__(self, "_curve", interpolant(times, values, self.interpolation))

    @property
    def times(self) -> np.ndarray:
        """Key times [s]."""
        return np.array([key.time for key in self.keys])

    @property
    def duration(self) -> float:
        """Time from the first to the last key [s]."""
        return self.keys[-1].time - self.keys[0].time

    def sample(self, t) -> np.ndarray:
        """Poses at times ``t`` [s] as an array (..., 7): position (3) [m], target (3) [m], fov [deg]."""
        return self._curve(_clamped(t, self.times))

    def at(self, t: float) -> CameraPose:
        """The pose at time ``t`` [s]; unpacks as ``(position, target, fov)``.

        Raises
        ------
        ValueError
            The interpolated target coincides with the position (the keys
            allow it only if two keys swap position and target).
        """
        row = self.sample(float(t))
        position, target = row[:3], row[3:6]
        if np.allclose(position, target, rtol=0, atol=1e-9):
            raise ValueError(f"camera path at t = {t:g} s: target coincides with position {position.tolist()}")
        return CameraPose(position=position, target=target, fov=float(row[6]))


# ---------------------------------------------------------------------------
# Sun: keyframes
# ---------------------------------------------------------------------------


class SunAngles(NamedTuple):
    """The sun's elevation above the horizon and azimuth clockwise from north [deg]."""

    elevation: float
    azimuth: float


class SunMotion(Protocol):
    """Anything that gives the sun's angles at a time t [s]."""

    def at(self, t: float) -> SunAngles: ...


@dataclass(frozen=True)
class SunKey:
    """A sun keyframe: time [s], elevation in [-90, 90] [deg], azimuth clockwise from north [deg].

    Azimuths are interpolated as given, not modulo 360°: to move from 350°
    to 10° through north write 350 then 370 (the result is reported modulo 360°).
    """

    time: float
    elevation: float
    azimuth: float

    def __post_init__(self):
        for name in ("time", "elevation", "azimuth"):
            value = getattr(self, name)
            if not math.isfinite(value):
                raise ValueError(f"sun key {name} must be finite, got {value}")
            object.__setattr__(self, name, float(value))
        if not -90 <= self.elevation <= 90:
            raise ValueError(f"sun key elevation must be in [-90, 90] deg, got {self.elevation}")


@dataclass(frozen=True)
class SunPath:
    """The sun moving through keyframes of (elevation, azimuth) on a C¹ cubic.

    Elevation and azimuth are interpolated as spherical coordinates with the
    method of :class:`CameraPath`; with the default monotone cubic the
    elevation never leaves the range of its neighbouring keys, so a sun
    keyed above the horizon stays there. Before the first key and after the
    last the sun holds still.
    """

    keys: tuple[SunKey, ...]
    interpolation: str = "monotone cubic"
    _curve: Callable = field(init=False, repr=False, compare=False)

    def __post_init__(self):
        keys = tuple(self.keys)
        if not all(isinstance(key, SunKey) for key in keys):
            raise ValueError("sun path keys must be SunKey objects")
        times = check_key_times([key.time for key in keys], "sun path")
        values = np.array([[key.elevation, key.azimuth] for key in keys])
        object.__setattr__(self, "keys", keys)
        object.__setattr__(self, "_curve", interpolant(times, values, self.interpolation))

    @property
    def times(self) -> np.ndarray:
        """Key times [s]."""
        return np.array([key.time for key in self.keys])

    def at(self, t: float) -> SunAngles:
        """Elevation and azimuth (in [0, 360)) of the sun at time ``t`` [s] [deg]."""
        elevation, azimuth = self._curve(_clamped(float(t), self.times))
        return SunAngles(float(elevation), float(azimuth % 360.0))


# ---------------------------------------------------------------------------
# Sun: place and clock (NOAA / Meeus)
# ---------------------------------------------------------------------------

#: Julian day of the Unix epoch, 1970-01-01T00:00 UTC [d].
JULIAN_DAY_UNIX_EPOCH = 2440587.5

#: Julian day of the J2000.0 epoch, 2000-01-01T12:00 TT [d].
JULIAN_DAY_J2000 = 2451545.0


def julian_day(when: datetime) -> float:
    """Julian day [d] of a timezone-aware instant (UTC; leap seconds ignored).

    Raises
    ------
    ValueError
        ``when`` has no time zone (local times are ambiguous).
    """
    if when.tzinfo is None or when.utcoffset() is None:
        raise ValueError(f"give a timezone-aware time (e.g. datetime(..., tzinfo=timezone.utc)), got {when!r}")
    return JULIAN_DAY_UNIX_EPOCH + when.timestamp() / 86400.0


class SolarPosition(NamedTuple):
    """The sun seen from a place at an instant (NOAA algorithm).

    Attributes
    ----------
    elevation : float          Geometric (true) elevation above the horizon [deg].
    azimuth : float            Clockwise from north, in [0, 360) [deg].
    apparent_elevation : float Elevation with atmospheric refraction [deg].
    declination : float        Solar declination [deg].
    equation_of_time : float   Apparent minus mean solar time [min].
    """

    elevation: float
    azimuth: float
    apparent_elevation: float
    declination: float
    equation_of_time: float


def refraction_Saemundsson1986(elevation, pressure: float = 1010.0, temperature: float = 10.0):
    """Atmospheric refraction Δe to add to a true elevation [deg].

    Parameters
    ----------
    elevation : array_like   True (geometric) elevation [deg].
    pressure : float         Surface pressure [hPa].
    temperature : float      Air temperature [°C].

    Notes
    -----
    Zero below −(0.26667° + 0.5667°) (the sun entirely below the horizon
    with standard refraction), as in [7].

    References
    ----------
    Eq. 42 of [7], the formula of [8] (also Eq. 16.4 of [6]).
    """
    e0 = np.asarray(elevation, dtype=float)
    # Eq. 42 of [7]: Δe = (P/1010)(283/(273+T)) · 1.02 / (60 tan(e0 + 10.3/(e0 + 5.11))).
    delta = (pressure / 1010.0) * (283.0 / (273.0 + temperature)) * 1.02 / (
        60.0 * np.tan(np.radians(e0 + 10.3 / (e0 + 5.11))))
    return np.where(e0 >= -(0.26667 + 0.5667), delta, 0.0)


def solar_position_NOAA(when: datetime, latitude: float, longitude: float, pressure: float = 1010.0,
                        temperature: float = 10.0) -> SolarPosition:
    """Solar elevation and azimuth at a place and instant: the NOAA Solar Calculator's equations.

    Parameters
    ----------
    when : datetime       Timezone-aware instant.
    latitude : float      Geographic latitude, north positive [deg].
    longitude : float     Longitude, east positive [deg].
    pressure : float      Surface pressure for the refraction [hPa].
    temperature : float   Air temperature for the refraction [°C].

    Returns
    -------
    SolarPosition

    Notes
    -----
    The low-precision solar theory of Meeus [6]; NOAA quotes about
    0.01° for 1800–2100 (checked against SPA [7] in the tests). UT is used
    for dynamical time (ΔT ≈ 1 min moves the sun by < 0.001°), and parallax
    (< 0.003°) is ignored.

    References
    ----------
    [6] for the ephemeris; [7, 8] for refraction.
    """
    if not (-90 <= latitude <= 90 and math.isfinite(longitude)):
        raise ValueError(f"latitude must be in [-90, 90] and longitude finite [deg], got {latitude}, {longitude}")
    jd = julian_day(when)
    T = (jd - JULIAN_DAY_J2000) / 36525.0  # Julian centuries since J2000.0
    L0 = (280.46646 + T * (36000.76983 + T * 0.0003032)) % 360.0  # Eq. 25.2 of [6]: geometric mean longitude
    M = 357.52911 + T * (35999.05029 - 0.0001537 * T)  # Eq. 25.3: mean anomaly
    e = 0.016708634 - T * (0.000042037 + 0.0000001267 * T)  # Eq. 25.4: eccentricity of Earth's orbit
    Mr = math.radians(M)
    C = (math.sin(Mr) * (1.914602 - T * (0.004817 + 0.000014 * T))  # equation of the centre ([6] ch. 25)
         + math.sin(2 * Mr) * (0.019993 - 0.000101 * T) + math.sin(3 * Mr) * 0.000289)
    omega = math.radians(125.04 - 1934.136 * T)  # longitude of the Moon's ascending node
    apparent_longitude = math.radians(L0 + C - 0.00569 - 0.00478 * math.sin(omega))  # λ ([6] ch. 25)
    eps0 = 23.0 + (26.0 + (21.448 - T * (46.815 + T * (0.00059 - T * 0.001813))) / 60.0) / 60.0  # Eq. 22.2
    eps = math.radians(eps0 + 0.00256 * math.cos(omega))  # obliquity corrected for nutation ([6] ch. 25)
    declination = math.asin(math.sin(eps) * math.sin(apparent_longitude))  # Eq. 25.7
    y = math.tan(eps / 2) ** 2
    L0r = math.radians(L0)
    # Equation of time, Eq. 28.3 of [6] (Smart's series) [min]:
    eot = 4.0 * math.degrees(y * math.sin(2 * L0r) - 2 * e * math.sin(Mr) + 4 * e * y * math.sin(Mr) * math.cos(2 * L0r)
                             - 0.5 * y * y * math.sin(4 * L0r) - 1.25 * e * e * math.sin(2 * Mr))
    minutes_utc = ((jd + 0.5) % 1.0) * 1440.0
    true_solar_time = (minutes_utc + eot + 4.0 * longitude) % 1440.0  # [min]
    H = math.radians(true_solar_time / 4.0 - 180.0)  # hour angle, zero at local solar noon
    phi = math.radians(latitude)
    cos_zenith = math.sin(phi) * math.sin(declination) + math.cos(phi) * math.cos(declination) * math.cos(H)
    elevation = 90.0 - math.degrees(math.acos(min(1.0, max(-1.0, cos_zenith))))
    # Eq. 13.5 of [6] (azimuth from south, westward), turned to clockwise from north:
    azimuth = (math.degrees(math.atan2(math.sin(H), math.cos(H) * math.sin(phi) - math.tan(declination) * math.cos(phi)))
               + 180.0) % 360.0
    apparent = elevation + float(refraction_Saemundsson1986(elevation, pressure, temperature))
    return SolarPosition(elevation=elevation, azimuth=azimuth, apparent_elevation=apparent,
                         declination=math.degrees(declination), equation_of_time=eot)


#: Solar-position methods by name: ``name -> f(when, latitude, longitude, pressure, temperature)``.
SOLAR_POSITION_METHODS = {"NOAA": solar_position_NOAA}


@dataclass(frozen=True)
class SolarClock:
    """The sun over a place as a clock runs: frame time t ↦ ``start + time_scale · t``.

    Parameters
    ----------
    latitude : float       North positive [deg].
    longitude : float      East positive [deg].
    start : datetime       Timezone-aware instant of t = 0.
    time_scale : float     Clock seconds per animation second [-] (e.g. 600
                           for a time-lapse of 10 min per second); may be 0.
    apparent : bool        Report the refracted (apparent) elevation, as the
                           eye sees it (default) or the geometric one.
    pressure, temperature : float   For the refraction [hPa], [°C].

    Notes
    -----
    Mitsuba's ``sunsky`` needs the sun above the horizon: check the
    elevation over the frame range (:meth:`elevations`) before rendering.
    """

    latitude: float
    longitude: float
    start: datetime
    time_scale: float = 1.0
    apparent: bool = True
    pressure: float = 1010.0
    temperature: float = 10.0

    def __post_init__(self):
        julian_day(self.start)  # refuses a naive datetime
        if not (-90 <= self.latitude <= 90) or not math.isfinite(self.longitude):
            raise ValueError(f"latitude must be in [-90, 90] and longitude finite [deg], "
                             f"got {self.latitude}, {self.longitude}")
        if not math.isfinite(self.time_scale):
            raise ValueError(f"time_scale must be finite [-], got {self.time_scale}")

    def when(self, t: float) -> datetime:
        """The clock instant of animation time ``t`` [s]."""
        from datetime import timedelta  # noqa: PLC0415

        return self.start + timedelta(seconds=self.time_scale * float(t))

    def position(self, t: float) -> SolarPosition:
        """The full :class:`SolarPosition` at animation time ``t`` [s]."""
        return solar_position_NOAA(self.when(t), self.latitude, self.longitude, self.pressure, self.temperature)

    def at(self, t: float) -> SunAngles:
        """Elevation and azimuth of the sun at animation time ``t`` [s] [deg]."""
        p = self.position(t)
        return SunAngles(p.apparent_elevation if self.apparent else p.elevation, p.azimuth)

    def elevations(self, times) -> np.ndarray:
        """Elevations at several animation times [deg] (to check the sun stays up)."""
        return np.array([self.at(t).elevation for t in np.atleast_1d(times)])


# ---------------------------------------------------------------------------
# Writing a pose into a loaded Mitsuba scene.
# ---------------------------------------------------------------------------


def frame_times(frames: tuple[int, int], fps: float) -> np.ndarray:
    """Times t = frame / fps [s] of the half-open frame range [start, end)."""
    return np.arange(*frames) / float(fps)


def utc(year: int, month: int, day: int, hour: int = 0, minute: int = 0, second: float = 0.0,
        offset_hours: float = 0.0) -> datetime:
    """A timezone-aware instant from civil date and time at a fixed UTC offset [h] (convenience)."""
    from datetime import timedelta  # noqa: PLC0415

    whole = int(second)
    return datetime(year, month, day, hour, minute, whole, int(round((second - whole) * 1e6)),
                    tzinfo=timezone(timedelta(hours=offset_hours)))


# ---------------------------------------------------------------------------
# The motion a scene file describes ([[camera.keys]], [[sun.keys]], [sun.clock]).
# The sections are described by what is read from them (structural types), so that this module knows
# nothing of scene.settings, which sits above it and validates animated sections with it.
# ---------------------------------------------------------------------------


class CameraSection(Protocol):
    """What is read from a ``[camera]`` section: its pose [m, m, deg], ``keys`` (each with time [s],
    position [m], target [m], fov [deg]) and their ``interpolation``."""

    position: Sequence[float]
    target: Sequence[float]
    fov: float
    keys: Sequence[Any]
    interpolation: str


class SunSection(Protocol):
    """What is read from a ``[sun]`` section: ``keys`` (time [s], elevation, azimuth [deg]), their
    ``interpolation``, and ``clock`` (latitude, longitude [deg], start, time_scale, apparent, pressure [hPa],
    temperature [°C]) or None."""

    keys: Sequence[Any]
    interpolation: str
    clock: Any


class SceneSections(Protocol):
    """A scene as far as its motion goes: its ``camera`` and ``sun`` sections."""

    camera: CameraSection
    sun: SunSection


def scene_camera_path(camera: CameraSection) -> CameraPath | None:
    """The :class:`CameraPath` of a ``[camera]`` section with ``[[camera.keys]]``, else None."""
    if not camera.keys:
        return None
    keys = tuple(CameraKey(key.time, key.position, key.target, key.fov) for key in camera.keys)
    return CameraPath(keys, interpolation=camera.interpolation)


def scene_sun_motion(sun: SunSection) -> SunMotion | None:
    """The sun motion of a ``[sun]`` section: a :class:`SunPath` (keys), a :class:`SolarClock` (clock) or None."""
    if sun.keys:
        return SunPath(tuple(SunKey(key.time, key.elevation, key.azimuth) for key in sun.keys),
                       interpolation=sun.interpolation)
    if sun.clock is not None:
        c = sun.clock
        return SolarClock(c.latitude, c.longitude, c.start, c.time_scale, c.apparent, c.pressure, c.temperature)
    return None


def camera_motion(scene: SceneSections) -> CameraPath | None:
    """The scene's camera path, or None for a still camera."""
    return scene_camera_path(scene.camera)


def sun_motion(scene: SceneSections) -> SunMotion | None:
    """The scene's sun motion, or None for a still sun."""
    return scene_sun_motion(scene.sun)


def static_camera_pose(scene: SceneSections) -> CameraPose:
    """The still camera of a scene without keys: ``[camera]`` position [m], target [m], fov [deg]."""
    c = scene.camera
    return CameraPose(np.array(c.position, dtype=float), np.array(c.target, dtype=float), float(c.fov))
