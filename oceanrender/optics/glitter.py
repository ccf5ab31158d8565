"""Sun glitter: the sun reflected by a sea of random facet slopes (Cox & Munk 1954).

A camera sees the sun in the sea wherever a facet is tilted to mirror the
sun into it: its normal is the half vector h of the sun direction s and the
direction o back to the camera, tilted β from the vertical, of slope tan β.
With facet slopes (z_x, z_y) of density p, the sea's mean radiance in
direction o is (Cox & Munk 1954, Eq. 4; the same as a microfacet BRDF with
the sun as a delta light, Walter et al. 2007, Eq. 20 with G = 1)

    L(o) = E_sun ρ(s·h) p(tan β) / (4 cos θ_o cos⁴ β),

E_sun the sun's irradiance on a plane normal to it [W m⁻²], ρ the Fresnel
reflectance at incidence angle arccos(s·h), θ_o the angle of o from the
zenith. For an isotropic Gaussian sea of total mean-square slope σ² =
⟨z_x² + z_y²⟩, p(tan β) = exp(−tan²β / σ²) / (π σ²): the glitter's
angular extent is set by σ² alone. :func:`fit_slope_variance` inverts it:
it recovers σ² from a rendered glitter pattern, which is how the renders
are tested against the sea's total slope variance.

References
----------
.. [1] C. Cox and W. Munk, "Measurement of the roughness of the sea surface
   from photographs of the sun's glitter", J. Opt. Soc. Am. 44(11), 838–850,
   1954, doi:10.1364/JOSA.44.000838.
.. [2] B. Walter, S. R. Marschner, H. Li and K. E. Torrance, "Microfacet models
   for refraction through rough surfaces", EGSR 2007, doi:10.2312/EGWR/EGSR07/195-206.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .fresnel import reflectance_Fresnel

__all__ = ["glitter_geometry", "glitter_radiance_CoxMunk1954", "fit_slope_variance"]


def glitter_geometry(to_camera: ArrayLike, to_sun: ArrayLike) -> tuple[NDArray, NDArray, NDArray]:
    """(tan²β [-], cos θ_o [-], cos of the incidence angle s·h [-]) of the facet mirroring the sun.

    Parameters
    ----------
    to_camera : array_like, (..., 3)   Unit directions o from the sea towards the camera (z up).
    to_sun : array_like, (3,)          Unit direction s towards the sun.
    """
    o = np.asarray(to_camera, dtype=np.float64)
    h = o + np.asarray(to_sun, dtype=np.float64)
    h /= np.linalg.norm(h, axis=-1, keepdims=True)  # the mirroring facet's normal
    tan2 = (h[..., 0] ** 2 + h[..., 1] ** 2) / h[..., 2] ** 2
    return tan2, o[..., 2], np.sum(h * np.asarray(to_sun, dtype=np.float64), axis=-1)


def glitter_radiance_CoxMunk1954(to_camera: ArrayLike, to_sun: ArrayLike, mean_square_slope: float,
                                 water_ior: float = 1.333, sun_irradiance: float = 1.0) -> NDArray:
    """Mean radiance of the sun's glitter in direction o [units of E_sun per sr].

    Parameters
    ----------
    to_camera : array_like, (..., 3)   Unit directions o from the sea towards the camera (z up).
    to_sun : array_like, (3,)          Unit direction s towards the sun.
    mean_square_slope : float          σ² = ⟨z_x² + z_y²⟩ of an isotropic Gaussian sea [-].
    water_ior : float                  Refractive index of water [-].
    sun_irradiance : float             E_sun normal to the sun [W m⁻²] (or any unit).
    """
    tan2, cos_o, cos_i = glitter_geometry(to_camera, to_sun)
    density = np.exp(-tan2 / mean_square_slope) / (np.pi * mean_square_slope)  # Gaussian slopes, [1] Eq. 1
    cos4_beta = 1.0 / (1.0 + tan2) ** 2
    reflectance = reflectance_Fresnel(np.clip(cos_i, 0.0, 1.0), 1.0, water_ior)
    return sun_irradiance * reflectance * density / (4.0 * cos_o * cos4_beta)  # Eq. 4 of [1]


def fit_slope_variance(radiance: ArrayLike, to_camera: ArrayLike, to_sun: ArrayLike, water_ior: float = 1.333,
                       bins: int = 12, reach: float = 2.5) -> float:
    """σ² [-] of the Gaussian slope density that best explains a glitter pattern.

    Parameters
    ----------
    radiance : array_like, (...)       Glitter radiance of each pixel (sun only, any unit).
    to_camera : array_like, (..., 3)   Direction from the pixel's sea point to the camera.
    to_sun : array_like, (3,)          Unit direction towards the sun.
    water_ior : float                  Refractive index of water [-].
    bins : int                         Bins in tan²β whose mean density is fitted [-].
    reach : float                      Bins run from the smallest tan²β seen to ``reach`` times
                                       the first estimate of σ² (the core of the pattern) [-].

    Notes
    -----
    Undoes Eq. 4 of Cox & Munk (1954): p ∝ L cos θ_o cos⁴β / ρ, averages p
    in bins of tan²β, and fits ln p = c − tan²β/σ² by least squares weighted
    by the pixel count of each bin; the first estimate of σ² is the
    p-weighted mean of tan²β (σ² for a Gaussian).
    """
    tan2, cos_o, cos_i = glitter_geometry(to_camera, to_sun)
    reflectance = reflectance_Fresnel(np.clip(cos_i, 0.0, 1.0), 1.0, water_ior)
    density = np.asarray(radiance, dtype=np.float64) * cos_o / ((1.0 + tan2) ** 2 * reflectance)
    tan2, density = tan2.ravel(), density.ravel()
    first = float(np.sum(density * tan2) / np.sum(density))
    edges = np.linspace(tan2.min(), tan2.min() + reach * first, bins + 1)
    which = np.digitize(tan2, edges) - 1
    centres, means, counts = [], [], []
    for b in range(bins):
        inside = which == b
        if inside.sum() >= 3 and density[inside].mean() > 0:
            centres.append(tan2[inside].mean())
            means.append(density[inside].mean())
            counts.append(inside.sum())
    slope, _ = np.polyfit(np.array(centres), np.log(means), 1, w=np.sqrt(np.array(counts)))
    return float(-1.0 / slope)
