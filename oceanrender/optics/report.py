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
from .streams import sunlit_coefficients

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
                 n_water: float = 1.333, wavelengths: np.ndarray = REPORT_WAVELENGTHS,
                 phase: tuple[np.ndarray, np.ndarray] | None = None) -> SceneOptics:
    """Four-flux light field of the scene's water under its sun and sky.

    Parameters
    ----------
    a, b, bb : ndarray   Absorption, scattering, backscattering [m⁻¹] at ``wavelengths``.
    direct_normal, diffuse : ndarray   Irradiance above the surface [W m⁻² nm⁻¹].
    sun_zenith : float   [deg].
    depth : float        Water depth H [m] (np.inf for deep water).
    z : ndarray          Depths of the profiles [m].
    bottom_albedo : float   Lambertian bottom reflectance [-].
    phase : (mu (M,), p (W, M)) or None
        The medium's phase function [-, sr⁻¹]: the four-flux coefficients then come from it
        and the refracted sun (:mod:`oceanrender.optics.streams`); None: the fixed closure.
    """
    coefficients = None
    if phase is not None:
        coefficients = sunlit_coefficients(a, b, *phase, direct_normal, diffuse, sun_zenith, n_water)
    light = four_flux(a, bb, direct_normal, diffuse, sun_zenith, depth, bottom_albedo, z, b=b,
                      n_water=n_water, internal_reflection=True, coefficients=coefficients)
    return SceneOptics(wavelengths, a, b, bb, direct_normal, diffuse, float(sun_zenith), float(depth), light)


def nadir_water_leaving(optics, wavelengths: np.ndarray, direct_normal: np.ndarray, diffuse: np.ndarray,
                        sun_zenith: float, n_water: float):
    """Water-leaving radiance at nadir of a deep sea by the four-flux model [W m⁻² sr⁻¹ nm⁻¹] (issue 19, item 4).

    L_w = L_u(0⁻)(1 − F(0))/n² under the sun (direct-normal irradiance) and a uniform sky
    (horizontal irradiance) [W m⁻² nm⁻¹], for the water ``optics``
    (:func:`oceanrender.optics.scene_water.water_optics`) at ``wavelengths`` [nm].
    Returns (before, after, coefficients): the fixed closure (Q = π, r̄_wa = 0.475), and the
    coefficients, Q and surface reflection from the medium's phase function and the refracted
    sun (:func:`oceanrender.optics.streams.stream_coefficients`).
    """
    from .components import medium_phase_table  # noqa: PLC0415

    iops = optics.iops if hasattr(optics, "iops") else optics
    wl = np.asarray(wavelengths, dtype=float)
    a = np.interp(wl, iops.wavelengths, iops.absorption)
    b = np.interp(wl, iops.wavelengths, iops.scattering)
    mu, p = medium_phase_table(optics, wl)
    # b_b of the table itself (trapezoids; the half-node at μ = 0 matters < 1 % here)
    bb = b * np.array([np.trapezoid(row[mu <= 0], mu[mu <= 0]) / np.trapezoid(row, mu) for row in p])
    coefficients = sunlit_coefficients(a, b, mu, p, direct_normal, diffuse, sun_zenith, n_water)
    common = dict(b=b, n_water=n_water, internal_reflection=True, view_zenith=0.0)
    before = four_flux(a, bb, direct_normal, diffuse, sun_zenith, np.inf, 0.0, [0.0], **common)
    after = four_flux(a, bb, direct_normal, diffuse, sun_zenith, np.inf, 0.0, [0.0], coefficients=coefficients,
                      **common)
    return before.B_refr, after.B_refr, coefficients
