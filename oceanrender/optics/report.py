"""The water's optics for a scene: IOPs, surface irradiance and the four-flux light field.

Pure computation (no files): :func:`scene_optics` returns arrays that the
``oceanrender optics`` command writes as CSV/JSON and plots.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .fourflux import FourFluxResult, four_flux

#: Wavelength grid of the report [nm] (95 wavelengths).
REPORT_WAVELENGTHS = np.arange(360.0, 831.0, 5.0)


@dataclass(frozen=True)
class SceneOptics:
    """IOPs [m⁻¹], sun and sky irradiance above the surface [W m⁻² nm⁻¹], four-flux field."""

    wavelengths: np.ndarray
    absorption: np.ndarray
    scattering: np.ndarray
    backscattering: np.ndarray
    direct_normal_irradiance: np.ndarray
    diffuse_irradiance: np.ndarray
    sun_zenith: float
    depth: float
    light: FourFluxResult

    @property
    def attenuation(self) -> np.ndarray:
        """c = a + b [m⁻¹]."""
        return self.absorption + self.scattering


def sky_irradiance_spectra(sun, wavelengths: np.ndarray, spp: int = 4096, seed: int = 0) -> tuple[np.ndarray, np.ndarray]:
    """Direct-normal and diffuse horizontal irradiance of Mitsuba's ``sunsky`` [W m⁻² nm⁻¹].

    Measured as π × the radiance of a white Lambertian plane (Lambert's law)
    through a ``specfilm`` with one 5-nm box band per wavelength, once with the
    sky alone and once with the sun alone (its horizontal irradiance divided
    by cos θ_s gives the direct-normal value). Needs an active Mitsuba variant.
    """
    import mitsuba as mi  # noqa: PLC0415

    from ..render.scene import sun_direction, sunsky_emitter  # noqa: PLC0415

    half = 0.5 * float(np.median(np.diff(wavelengths)))
    film = {"type": "specfilm", "width": 1, "height": 1, "component_format": "float32", "rfilter": {"type": "box"}}
    for i, w in enumerate(wavelengths):
        film[f"band_{i:03d}"] = {"type": "spectrum", "value": [(w - half, 1.0), (w + half - 1e-3, 1.0)]}

    def horizontal(sky_scale: float, sun_scale: float) -> np.ndarray:
        emitter = {**sunsky_emitter(sun), "sky_scale": sky_scale * sun.sky_scale, "sun_scale": sun_scale * sun.sun_scale}
        scene = mi.load_dict({
            "type": "scene",
            "integrator": {"type": "path", "max_depth": 2},
            "sensor": {"type": "radiancemeter", "origin": [0, 0, 1], "direction": [0, 0, -1], "film": film,
                       "sampler": {"type": "independent", "sample_count": int(spp)}},
            "sky": emitter,
            "ground": {"type": "disk", "to_world": mi.ScalarTransform4f().scale([1e4, 1e4, 1]),
                       "bsdf": {"type": "diffuse", "reflectance": {"type": "spectrum", "value": 1.0}}},
        })
        band_integrals = np.array(mi.render(scene, seed=seed)).ravel()
        return np.pi * band_integrals / (2 * half)  # E = π L, per nm

    cos_sun = float(sun_direction(sun.elevation, sun.azimuth)[2])
    return horizontal(0.0, 1.0) / cos_sun, horizontal(1.0, 0.0)


def scene_optics(a: np.ndarray, b: np.ndarray, bb: np.ndarray, direct_normal: np.ndarray, diffuse: np.ndarray,
                 sun_zenith: float, depth: float, z: np.ndarray, bottom_albedo: float = 0.0,
                 n_water: float = 1.333, wavelengths: np.ndarray = REPORT_WAVELENGTHS) -> SceneOptics:
    """Four-flux light field of the scene's water under its sun and sky.

    Parameters
    ----------
    a, b, bb : ndarray   Absorption, scattering, backscattering [m⁻¹] at ``wavelengths``.
    direct_normal, diffuse : ndarray   Irradiance above the surface [W m⁻² nm⁻¹].
    sun_zenith : float   [deg].
    depth : float        Water depth H [m] (np.inf for deep water).
    z : ndarray          Depths of the profiles [m].
    bottom_albedo : float   Lambertian bottom reflectance [-].
    """
    light = four_flux(a, bb, direct_normal, diffuse, sun_zenith, depth, bottom_albedo, z, b=b,
                      n_water=n_water, internal_reflection=True)
    return SceneOptics(wavelengths, a, b, bb, direct_normal, diffuse, float(sun_zenith), float(depth), light)
