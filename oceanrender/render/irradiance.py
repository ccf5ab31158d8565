"""Irradiance spectra of the renderer's sun and sky, measured with Mitsuba.

The four-flux light field (:mod:`oceanrender.optics.fourflux`) and the real-time
LUTs take the direct-normal and diffuse irradiance above the sea; they are
measured here from the very ``sunsky`` emitter the frames are rendered under.
"""

from __future__ import annotations

import numpy as np

from .scene import meter_reading, sun_direction, sunsky_emitter, white_plane_meter


def sky_irradiance_spectra(sun, wavelengths: np.ndarray, spp: int = 4096, seed: int = 0) -> tuple[np.ndarray, np.ndarray]:
    """Direct-normal and diffuse horizontal irradiance of Mitsuba's ``sunsky`` [W m⁻² nm⁻¹].

    Measured as π × the radiance of a white Lambertian plane (Lambert's law;
    :func:`~oceanrender.render.scene.white_plane_meter`, the same readings in
    every process) through a ``specfilm`` with one 5-nm box band per wavelength, once with the
    sky alone and once with the sun alone (its horizontal irradiance divided
    by cos θ_s gives the direct-normal value). Needs an active Mitsuba variant.
    """
    import mitsuba as mi  # noqa: PLC0415

    half = 0.5 * float(np.median(np.diff(wavelengths)))
    film = {"type": "specfilm", "width": 1, "height": 1, "component_format": "float32", "rfilter": {"type": "box"}}
    for i, w in enumerate(wavelengths):
        film[f"band_{i:03d}"] = {"type": "spectrum", "value": [(w - half, 1.0), (w + half - 1e-3, 1.0)]}

    def horizontal(sky_scale: float, sun_scale: float) -> np.ndarray:
        emitter = {**sunsky_emitter(sun), "sky_scale": sky_scale * sun.sky_scale, "sun_scale": sun_scale * sun.sun_scale}
        scene = mi.load_dict(white_plane_meter(emitter, film, spp))
        band_integrals = meter_reading(mi.render(scene, seed=seed))
        return np.pi * band_integrals / (2 * half)  # E = π L, per nm

    cos_sun = float(sun_direction(sun.elevation, sun.azimuth)[2])
    return horizontal(0.0, 1.0) / cos_sun, horizontal(1.0, 0.0)
