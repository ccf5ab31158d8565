"""The water's optics for a scene: IOPs, surface irradiance and the four-flux light field.

Pure computation (no files, no Mitsuba): :func:`scene_optics` returns arrays that the
``oceanrender optics`` command writes as CSV/JSON and plots; the sun and sky
irradiance it takes comes from the renderer's sky
(:func:`oceanrender.render.irradiance.sky_irradiance_spectra`).
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
