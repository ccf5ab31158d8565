"""The sky of a frame: Mitsuba's ``sunsky``, or an equirectangular HDR map (``[environment]``).

An environment map is Mitsuba's ``envmap`` emitter: its RGB pixels become smooth
spectra by Mitsuba's spectral upsampling (Jakob & Hanika 2019), over the whole film
range, so the map has no gap above 720 nm (``sunsky``'s spectral data end there). Its
frame: the top row is the zenith, column u lies at azimuth 360° u + ``rotation``
clockwise from north (Mitsuba's ``envmap`` is y-up: turned by 90° about x, then by
−``rotation`` about z). Absolute units: ``scale`` multiplies the pixels (an RGB of 1 is
Mitsuba's upsampled white, 1.05 W m⁻² sr⁻¹ nm⁻¹ at 550 nm), or ``illuminance`` sets
the scale so that the map lights a horizontal plane with that many lux, measured like
the adapting white: a white Lambertian plane under the map, E_v = π L_v (Lambert).
``sun = true`` adds ``sunsky``'s sun for the ``[sun]`` as a ``directional`` emitter of the same
irradiance spectrum (Mitsuba takes one environment emitter per scene: the map), which ends
at 720 nm as ``sunsky``'s does.
"""

from __future__ import annotations

import functools
import math
from pathlib import Path

import numpy as np

from ..io.paths import PathProblem, check_input_file
from ..scene import Scene
from .irradiance import sky_irradiance_spectra
from .scene import K_M, irregular_spectrum, meter_reading, sun_direction, sunsky_emitter, white_plane_meter, xyz_film

__all__ = ["ENVIRONMENT_SUFFIXES", "EnvironmentMapProblem", "read_environment_map", "sky_emitters",
           "environment_scale", "map_illuminance", "sun_normal_irradiance"]

#: Files an environment map may be.
ENVIRONMENT_SUFFIXES = (".exr", ".hdr")
#: Largest map accepted [bytes].
MAX_MAP_BYTES = 1 << 30
#: Samples of the meter that calibrates ``illuminance`` (one per pixel; ±0.3 % noise on a smooth sky).
CALIBRATION_SPP = 1 << 16


class EnvironmentMapProblem(ValueError):
    """A map that cannot be a sky; one line, without the key."""


def read_environment_map(path: str | Path) -> np.ndarray:
    """The map as (H, W, 3) float32 linear RGB; :class:`EnvironmentMapProblem` if it cannot be a sky.

    An equirectangular map is twice as wide as high; every value finite and ≥ 0;
    one channel (grey) or at least three (RGB, others ignored).
    """
    import mitsuba as mi  # noqa: PLC0415

    try:
        path = check_input_file(path, MAX_MAP_BYTES)
    except PathProblem as exc:
        raise EnvironmentMapProblem(str(exc)) from None
    if path.suffix.lower() not in ENVIRONMENT_SUFFIXES:
        raise EnvironmentMapProblem(f"{path}: expected an EXR or Radiance .hdr file, got {path.suffix or 'none'!r}")
    try:
        image = np.array(mi.Bitmap(str(path)), dtype=np.float32)
    except Exception as exc:  # noqa: BLE001 - Mitsuba raises RuntimeError of several kinds
        raise EnvironmentMapProblem(f"{path}: not a readable image ({str(exc).splitlines()[0][:200]})") from None
    if image.ndim == 2:
        image = image[..., None]
    if image.shape[2] == 2:
        raise EnvironmentMapProblem(f"{path}: expected 1 (grey) or 3+ (RGB) channels, got {image.shape[2]}")
    image = np.repeat(image, 3, axis=2) if image.shape[2] == 1 else image[..., :3]
    height, width = image.shape[:2]
    if width != 2 * height:
        raise EnvironmentMapProblem(f"{path}: {width} × {height} pixels is not equirectangular (width = 2 × height)")
    if not np.all(np.isfinite(image)):
        raise EnvironmentMapProblem(f"{path}: has non-finite pixels ({int(np.sum(~np.isfinite(image)))} values)")
    if np.any(image < 0):
        raise EnvironmentMapProblem(f"{path}: has negative pixels (min {float(image.min()):g}); radiance is ≥ 0")
    return np.ascontiguousarray(image)


def _envmap(path: str, scale: float, rotation: float) -> dict:
    import mitsuba as mi  # noqa: PLC0415

    to_world = mi.ScalarTransform4f().rotate([0.0, 0.0, 1.0], -rotation) @ mi.ScalarTransform4f().rotate(
        [1.0, 0.0, 0.0], 90.0)
    return {"type": "envmap", "bitmap": mi.Bitmap(read_environment_map(path)), "scale": float(scale),
            "to_world": to_world}


def map_illuminance(path: str, scale: float = 1.0, spp: int = CALIBRATION_SPP) -> float:
    """Illuminance of the map on a horizontal plane [lx]: π × the luminance of a white Lambertian plane under it."""
    import mitsuba as mi  # noqa: PLC0415

    meter = mi.load_dict(white_plane_meter(_envmap(path, scale, 0.0), xyz_film(1, 1), spp))
    luminance = K_M * float(np.asarray(meter_reading(mi.render(meter, seed=0))).reshape(-1)[1])  # Y = K_m ∫ L ȳ dλ
    return math.pi * luminance  # E_v = π L_v (Lambert)


@functools.lru_cache(maxsize=8)
def _calibrated_scale(path: str, illuminance: float) -> float:
    return float(illuminance) / map_illuminance(path)


def environment_scale(scene: Scene) -> float:
    """The envmap's ``scale`` [-]: the scene's, or the one that gives its ``illuminance`` [lx] (measured once)."""
    env = scene.environment
    if env.illuminance is not None:
        return _calibrated_scale(env.map, env.illuminance)
    return float(env.scale if env.scale is not None else 1.0)


def sky_emitters(scene: Scene) -> dict[str, dict]:
    """The scene-dict entries of the sky: ``{"sky": sunsky}``, or the map (``"sky"``) and its optional ``"sun"``."""
    if scene.environment is None:
        return {"sky": sunsky_emitter(scene.sun)}
    env = scene.environment
    out = {"sky": _envmap(env.map, environment_scale(scene), env.rotation)}
    if env.sun:
        out["sun"] = sun_emitter(scene.sun)
    return out


#: Wavelengths of the added sun's irradiance spectrum [nm] (5 nm; sunsky's sun is zero above 720 nm).
SUN_WAVELENGTHS_NM = tuple(float(w) for w in np.arange(360.0, 831.0, 5.0))
#: Samples of the measurement of the sun's irradiance (noise ≪ 1 %: the sun alone, by emitter sampling).
SUN_SPP = 1 << 12


def sun_emitter(sun) -> dict:
    """``sunsky``'s sun as a ``directional`` emitter (Mitsuba holds one environment emitter per scene, the map).

    Its spectral irradiance [W m⁻² nm⁻¹] normal to the sunlight is ``sunsky``'s, measured
    (:func:`~oceanrender.render.irradiance.sky_irradiance_spectra`); a delta light: the solar
    disk itself is not seen, its reflections only through the water's roughness.
    """
    towards = -sun_direction(sun.elevation, sun.azimuth)
    return {"type": "directional", "direction": [float(v) for v in towards],
            "irradiance": irregular_spectrum(np.array(SUN_WAVELENGTHS_NM), np.maximum(sun_normal_irradiance(sun), 0.0))}


@functools.lru_cache(maxsize=8)
def sun_normal_irradiance(sun) -> np.ndarray:
    """Direct-normal irradiance of ``sunsky``'s sun at :data:`SUN_WAVELENGTHS_NM` [W m⁻² nm⁻¹], measured once per sun."""
    return sky_irradiance_spectra(sun, np.array(SUN_WAVELENGTHS_NM), spp=SUN_SPP)[0]
