"""Camera paths and sun motion: interpolation through keys, C¹ continuity, validation, solar position."""

import math
from datetime import datetime

import numpy as np
import pytest

from oceanrender.scene.motion import (
    INTERPOLATIONS,
    CameraKey,
    CameraPath,
    SolarClock,
    SunKey,
    SunPath,
    check_key_times,
    frame_times,
    julian_day,
    refraction_Saemundsson1986,
    solar_position_NOAA,
    tangents_CatmullRom,
    utc,
)
from tests.tolerances import EPS64, ROUNDOFF

METHODS = sorted(INTERPOLATIONS)


def orbit_keys(n=5, radius=20.0):
    """Keys on an orbit around the origin at uneven times, with a dip in height and a zoom."""
    times = np.cumsum([0.0, 1.0, 2.5, 0.7, 3.0, 1.2])[:n]
    keys = []
    for i, t in enumerate(times):
        angle = 0.9 * i
        keys.append(CameraKey(float(t), (radius * math.cos(angle), radius * math.sin(angle), 5.0 + 3.0 * (i % 2)),
                              (0.0, 0.0, 0.5 * i), 60.0 - 5.0 * i))
    return tuple(keys)


@pytest.mark.parametrize("method", METHODS)
def test_camera_path_passes_exactly_through_its_keys(method):
    keys = orbit_keys()
    path = CameraPath(keys, interpolation=method)
    # Exactly up to round-off on the keys' coordinate scale (20 m; some coordinates are 0).
    scale = max(abs(c) for key in keys for c in (*key.position, *key.target))
    for key in keys:
        position, target, fov = path.at(key.time)
        np.testing.assert_allclose(position, key.position, rtol=0, atol=ROUNDOFF * scale)
        np.testing.assert_allclose(target, key.target, rtol=0, atol=ROUNDOFF * scale)
        assert fov == pytest.approx(key.fov, rel=ROUNDOFF)


@pytest.mark.parametrize("method", METHODS)
def test_camera_path_is_C1_at_the_keys(method):
    # One-sided finite differences of the first derivative left and right of each interior key
    # agree to O(h) (a C⁰-only join, e.g. piecewise linear, would differ by O(1)).
    keys = orbit_keys()
    path = CameraPath(keys, interpolation=method)
    h = 1e-5
    for key in keys[1:-1]:
        t = key.time
        left = (path.sample(t) - path.sample(t - h)) / h
        right = (path.sample(t + h) - path.sample(t)) / h
        scale = np.abs(left).max() + 1.0
        assert np.abs(left - right).max() < 1e-3 * scale
        # and the position itself is continuous (the path moves ≲ 50 m/s × 2e-9 s ≈ 1e-7 m)
        np.testing.assert_allclose(path.sample(t - 1e-9), path.sample(t + 1e-9), atol=1e-6)


def test_a_piecewise_linear_join_would_fail_the_C1_check():
    # The check above can fail: the same finite differences on linear interpolation see the kink.
    keys = orbit_keys()
    times = np.array([k.time for k in keys])
    values = np.array([k.position for k in keys])
    linear = lambda t: np.array([np.interp(t, times, values[:, i]) for i in range(3)])  # noqa: E731
    t, h = keys[2].time, 1e-5
    left = (linear(t) - linear(t - h)) / h
    right = (linear(t + h) - linear(t)) / h
    assert np.abs(left - right).max() > 1e-3 * (np.abs(left).max() + 1.0)


def test_monotone_path_never_leaves_the_range_of_neighbouring_keys():
    # A camera swooping down to 0.5 m and staying there must not dip below 0.5 m (into the sea).
    keys = (CameraKey(0, (0, 0, 10), (0, 50, 0), 60), CameraKey(2, (0, 10, 0.5), (0, 50, 0), 30),
            CameraKey(3, (0, 20, 0.5), (0, 50, 0), 30), CameraKey(5, (0, 30, 6), (0, 50, 0), 90))
    t = np.linspace(0, 5, 2001)
    monotone = CameraPath(keys).sample(t)
    # Up to round-off on the keys' scales: heights up to 10 m, fields of view up to 90°.
    assert monotone[:, 2].min() >= 0.5 - ROUNDOFF * 10.0
    assert monotone[:, 6].min() >= 30 - ROUNDOFF * 90.0 and monotone[:, 6].max() <= 90 + ROUNDOFF * 90.0
    # Catmull-Rom overshoots here (why it is not the default).
    assert CameraPath(keys, interpolation="Catmull-Rom").sample(t)[:, 2].min() < 0.5 - 1e-3


def test_catmull_rom_tangents_reproduce_a_parabola():
    # The three-point tangent is exact for quadratics, on uneven key times.
    times = np.array([0.0, 0.4, 1.5, 2.0, 3.7])
    values = (2.0 * times**2 - times + 1.0)[:, None]
    tangents = tangents_CatmullRom(times, values)
    np.testing.assert_allclose(tangents[1:-1, 0], 4.0 * times[1:-1] - 1.0, rtol=ROUNDOFF)  # 0.6 to 7


def test_camera_holds_still_outside_the_keys():
    keys = orbit_keys()
    path = CameraPath(keys)
    np.testing.assert_allclose(path.at(-3.0).position, keys[0].position)
    np.testing.assert_allclose(path.at(1e3).position, keys[-1].position)


@pytest.mark.parametrize("times, message", [
    ((0.0, 2.0, 1.0), "strictly increase"),
    ((0.0, 1.0, 1.0), "strictly increase"),
    ((0.0,), "at least 2"),
    ((0.0, float("nan")), "finite"),
])
def test_bad_key_times_are_refused(times, message):
    keys = tuple(CameraKey(0.0, (0, 0, 5), (0, 50, 0), 60) for _ in times)
    with pytest.raises(ValueError, match=message):
        check_key_times(times)
    if all(math.isfinite(t) for t in times):
        with pytest.raises(ValueError, match=message):
            CameraPath(tuple(CameraKey(t, k.position, k.target, k.fov) for t, k in zip(times, keys)))


@pytest.mark.parametrize("kwargs, message", [
    ({"time": float("nan")}, "time must be finite"),
    ({"position": (0.0, float("nan"), 5.0)}, "position must be 3 finite"),
    ({"target": (0.0, 1.0)}, "target must be 3 finite"),
    ({"fov": 0.0}, "fov must be in"),
    ({"fov": 180.0}, "fov must be in"),
    ({"fov": float("nan")}, "fov must be in"),
    ({"target": (0.0, 0.0, 5.0)}, "target equals position"),
])
def test_bad_camera_keys_are_refused(kwargs, message):
    values = {"time": 0.0, "position": (0.0, 0.0, 5.0), "target": (0.0, 50.0, 0.0), "fov": 60.0, **kwargs}
    with pytest.raises(ValueError, match=message):
        CameraKey(**values)


def test_unknown_interpolation_names_the_known_ones():
    with pytest.raises(ValueError, match="monotone cubic"):
        CameraPath(orbit_keys(), interpolation="bezier")


def test_camera_path_rejects_nan_time_queries():
    with pytest.raises(ValueError, match="finite"):
        CameraPath(orbit_keys()).at(float("nan"))


def test_sun_path_through_keys_and_wraps_azimuth():
    # Through north: 350° → 370° (= 10°) is interpolated the short way and reported modulo 360°.
    path = SunPath((SunKey(0, 20, 350), SunKey(10, 30, 370), SunKey(20, 25, 400)))
    assert path.at(0) == pytest.approx((20, 350))
    assert path.at(10) == pytest.approx((30, 10))
    assert path.at(20) == pytest.approx((25, 40))
    elevation, azimuth = path.at(5)
    assert 0 <= azimuth < 360 and (azimuth > 350 or azimuth < 10)
    assert 20 <= elevation <= 30


def test_sun_path_keyed_above_the_horizon_stays_above_it():
    path = SunPath((SunKey(0, 1, 90), SunKey(4, 60, 180), SunKey(8, 2, 270), SunKey(9, 1, 280)))
    assert min(path.at(t).elevation for t in np.linspace(0, 9, 901)) >= 1 - ROUNDOFF * 60.0  # keys up to 60°


def test_bad_sun_keys_are_refused():
    with pytest.raises(ValueError, match="elevation must be in"):
        SunKey(0, 95, 0)
    with pytest.raises(ValueError, match="finite"):
        SunKey(0, float("nan"), 0)
    with pytest.raises(ValueError, match="strictly increase"):
        SunPath((SunKey(1, 10, 0), SunKey(0, 20, 0)))
    with pytest.raises(ValueError, match="at least 2"):
        SunPath((SunKey(0, 10, 0),))


# --- solar position -------------------------------------------------------------------------

def test_julian_day_of_J2000_and_naive_times_refused():
    # A few ulp of a day count of 2.45e6 (one ulp is 4.7e-10 d = 40 µs).
    assert julian_day(utc(2000, 1, 1, 12)) == pytest.approx(2451545.0, rel=64 * EPS64)
    with pytest.raises(ValueError, match="timezone-aware"):
        julian_day(datetime(2000, 1, 1, 12))


def test_solar_position_matches_the_SPA_reference_case():
    # Reda & Andreas (2004), NREL/TP-560-34302, Table A5.1: 2003-10-17 12:30:30 at UTC-7,
    # 39.742476° N, 105.1786° W, 820 hPa, 11 °C: geometric elevation 39.872046°,
    # refracted (topocentric) zenith 50.111622°, azimuth 194.340241°, equation of time 14.641503 min.
    p = solar_position_NOAA(utc(2003, 10, 17, 12, 30, 30, offset_hours=-7), 39.742476, -105.1786,
                            pressure=820.0, temperature=11.0)
    assert p.elevation == pytest.approx(39.872046, abs=0.01)
    assert 90.0 - p.apparent_elevation == pytest.approx(50.111622, abs=0.01)
    assert p.azimuth == pytest.approx(194.340241, abs=0.01)
    assert p.equation_of_time == pytest.approx(14.641503, abs=0.05)
    assert p.declination == pytest.approx(-9.31434, abs=0.01)  # SPA's geocentric δ


def test_solar_noon_elevation_at_the_june_solstice():
    # June solstice 2024: 2024-06-20 20:51 UTC (Astronomical Almanac), δ = +23.44°.
    # At 40° N the local solar-noon elevation is then 90 − 40 + 23.44 = 73.44°.
    when = utc(2024, 6, 20, 20, 51)
    assert solar_position_NOAA(when, 0.0, 0.0).declination == pytest.approx(23.44, abs=0.01)
    # Solar noon at longitude λ: 12:00 − 4 min/° · λ − equation of time (UTC); evaluate there.
    longitude = -(20 + 51 / 60 - 12) * 15  # where it is noon at the solstice instant
    p = solar_position_NOAA(when, 40.0, longitude)
    clock = SolarClock(40.0, longitude, when, time_scale=60.0)
    # the maximum over ±20 min (animation seconds of a minute each) is the noon elevation
    noon = max(clock.elevations(np.arange(-20, 21)))
    assert noon == pytest.approx(73.44 + float(refraction_Saemundsson1986(73.44)), abs=0.05)
    assert p.azimuth == pytest.approx(180.0, abs=5.0)  # the sun is due south at noon


def test_southern_hemisphere_noon_sun_is_north():
    # At 33.9° S on the December solstice the noon sun is due north, elevation ≈ 90 − 33.9 + 23.44.
    when = utc(2024, 12, 21, 9, 21)  # solstice 09:21 UTC
    longitude = -(9 + 21 / 60 - 12) * 15
    p = solar_position_NOAA(when, -33.9, longitude)
    assert p.declination == pytest.approx(-23.44, abs=0.01)
    assert p.elevation == pytest.approx(90 - 33.9 + 23.44, abs=0.5)
    assert min(p.azimuth, 360 - p.azimuth) < 5.0


def test_solar_clock_is_a_time_lapse_of_the_sun():
    clock = SolarClock(48.0, -4.5, utc(2024, 6, 1, 6, 0), time_scale=3600.0)  # one hour per second
    morning, noon = clock.at(0.0), clock.at(6.0)  # 06:00 and 12:00 UTC off Brittany
    assert noon.elevation > morning.elevation
    assert 60 < noon.elevation < 66
    assert 45 < morning.azimuth < 100 and 150 < noon.azimuth < 210
    with pytest.raises(ValueError, match="timezone-aware"):
        SolarClock(48.0, -4.5, datetime(2024, 6, 1, 6))


def test_refraction_agrees_with_Bennetts_inverse_formula():
    # Sæmundsson (1986) gives R from the true elevation h; Bennett (1982) gives R from the apparent one,
    # h + R (Meeus 1998, Eqs. 16.3 and 16.4). At standard conditions the two must agree to ~0.1'.
    for h in (0.0, 2.0, 10.0, 30.0, 60.0):
        r = float(refraction_Saemundsson1986(h, 1010.0, 10.0))
        apparent = h + r
        bennett = 1.0 / math.tan(math.radians(apparent + 7.31 / (apparent + 4.4))) / 60.0
        assert r == pytest.approx(bennett, abs=0.1 / 60)
    assert float(refraction_Saemundsson1986(90.0)) == pytest.approx(0.0, abs=1e-4)
    assert float(refraction_Saemundsson1986(-5.0)) == 0.0  # the sun is set: no correction (exact: np.where)


def test_frame_times():
    np.testing.assert_allclose(frame_times((2, 5), 24.0), [2 / 24, 3 / 24, 4 / 24])
