"""Fresnel reflection and transmission at a flat air–water interface.

Exact reflectance of unpolarised light at a smooth dielectric interface
(average of the s- and p-polarised reflectances), its hemispherical
(cosine-weighted) average for diffuse light, and the dissertation's empirical
correction F_c = F^γ.

Conventions: angles are given by their cosines, measured from the interface
normal on the side of incidence; refractive indices are real and
dimensionless; ``n1`` is the medium the light comes from, ``n2`` the medium it
enters. Reflectances and transmittances are energy (power) fractions in
[0, 1]. Total internal reflection (n1 > n2 beyond the critical angle) gives a
reflectance of exactly 1.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = [
    "N_AIR",
    "N_WATER",
    "refract",
    "refracted_cosine",
    "critical_cosine",
    "reflectance_components_Fresnel",
    "reflectance_Fresnel",
    "transmittance_Fresnel",
    "diffuse_reflectance_Fresnel",
    "diffuse_transmittance_Fresnel",
    "fresnel_correction",
]

N_AIR: float = 1.0
"""Refractive index of air used throughout [-] (1.0003 in reality; the 0.03 % is ignored)."""

N_WATER: float = 1.333
"""Refractive index of sea water in the visible used as default [-] (the scene's ``ior``)."""

#: Gauss–Legendre order of the hemispherical integrals (the integrand is smooth
#: on the transmitting part, so 64 nodes are exact to ~1e-15).
_QUADRATURE_ORDER = 64


@lru_cache(maxsize=1)
def _gauss_legendre_unit() -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Gauss–Legendre nodes on [0, 1] and weights on [−1, 1] (computed once)."""
    nodes, weights = np.polynomial.legendre.leggauss(_QUADRATURE_ORDER)
    return 0.5 * (nodes + 1.0), weights


def _check_cosine(cos_theta_i: ArrayLike) -> NDArray[np.float64]:
    mu = np.asarray(cos_theta_i, dtype=float)
    finite = mu[np.isfinite(mu)]
    if np.any((finite < 0.0) | (finite > 1.0)):
        raise ValueError("cos_theta_i must lie in [0, 1] (angle of incidence 0–90° from the normal)")
    return mu


def _check_indices(n1: ArrayLike, n2: ArrayLike) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    n1, n2 = np.asarray(n1, dtype=float), np.asarray(n2, dtype=float)
    if np.any(~(n1 > 0.0)) or np.any(~(n2 > 0.0)):
        raise ValueError("refractive indices n1, n2 must be positive")
    return n1, n2


def refracted_cosine(cos_theta_i: ArrayLike, n1: ArrayLike, n2: ArrayLike) -> NDArray[np.float64]:
    """Cosine of the refraction angle, cos θ_t, from Snell's law [-].

    Parameters
    ----------
    cos_theta_i : array_like
        Cosine of the angle of incidence, in [0, 1] [-].
    n1, n2 : array_like
        Refractive index of the incident and of the transmitting medium [-].

    Returns
    -------
    ndarray
        cos θ_t = √(1 − (n1/n2)² sin²θ_i) [-]; NaN where the light is totally
        internally reflected (no refracted ray).

    References
    ----------
    .. [1] Born, M. & Wolf, E. (1999). *Principles of Optics*, 7th ed.,
       Cambridge University Press, §1.5.1. doi:10.1017/CBO9781139644181
    """
    mu = _check_cosine(cos_theta_i)
    n1, n2 = _check_indices(n1, n2)
    sin2_t = (n1 / n2) ** 2 * (1.0 - mu * mu)  # Snell's law n1 sin θi = n2 sin θt, §1.5.1 of [1]
    with np.errstate(invalid="ignore"):
        return np.where(sin2_t <= 1.0, np.sqrt(np.abs(1.0 - sin2_t)), np.nan)


def critical_cosine(n1: ArrayLike, n2: ArrayLike) -> NDArray[np.float64]:
    """Cosine of the critical angle, cos θ_c = √(1 − (n2/n1)²) [-].

    Zero (no total internal reflection) where n1 ≤ n2. For water → air with
    n = 1.333, θ_c = asin(1/1.333) = 48.6°.

    Parameters
    ----------
    n1, n2 : array_like
        Refractive index of the incident and of the transmitting medium [-].

    References
    ----------
    .. [1] Born & Wolf (1999), *Principles of Optics*, §1.5.4.
    """
    n1, n2 = _check_indices(n1, n2)
    ratio = np.minimum(n2 / n1, 1.0)
    return np.sqrt(1.0 - ratio * ratio)  # sin θc = n2/n1, §1.5.4 of [1]


def reflectance_components_Fresnel(
    cos_theta_i: ArrayLike, n1: ArrayLike, n2: ArrayLike
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Fresnel reflectances R_s and R_p of s- and p-polarised light [-].

    Parameters
    ----------
    cos_theta_i : array_like
        Cosine of the angle of incidence, in [0, 1] [-].
    n1, n2 : array_like
        Refractive index of the incident and of the transmitting medium [-].

    Returns
    -------
    R_s, R_p : ndarray
        Reflectance for the electric field perpendicular (s, TE) and parallel
        (p, TM) to the plane of incidence [-]; both 1 under total internal
        reflection. R_p vanishes at Brewster's angle, tan θ_B = n2/n1.

    References
    ----------
    .. [1] Born, M. & Wolf, E. (1999). *Principles of Optics*, 7th ed.,
       Cambridge University Press, §1.5.2–1.5.3. doi:10.1017/CBO9781139644181
    """
    mu_i = _check_cosine(cos_theta_i)
    n1, n2 = _check_indices(n1, n2)
    mu_t = refracted_cosine(mu_i, n1, n2)
    tir = np.isnan(mu_t) & ~np.isnan(mu_i)
    mu_t = np.where(tir, 0.0, mu_t)
    with np.errstate(invalid="ignore", divide="ignore"):
        r_s = (n1 * mu_i - n2 * mu_t) / (n1 * mu_i + n2 * mu_t)  # Fresnel formula (s), §1.5.2 of [1]
        r_p = (n2 * mu_i - n1 * mu_t) / (n2 * mu_i + n1 * mu_t)  # Fresnel formula (p), §1.5.2 of [1]
    # NOTE: at grazing incidence from the denser side both denominators can be
    # 0 only when mu_i = mu_t = 0, which is total internal reflection anyway.
    R_s = np.where(tir, 1.0, r_s * r_s)
    R_p = np.where(tir, 1.0, r_p * r_p)
    return R_s, R_p


def reflectance_Fresnel(cos_theta_i: ArrayLike, n1: ArrayLike, n2: ArrayLike) -> NDArray[np.float64]:
    """Fresnel reflectance of unpolarised light at a flat dielectric interface [-].

    F = (R_s + R_p) / 2, exact for a smooth interface between two lossless
    media; 1 under total internal reflection; 1 at grazing incidence.

    Parameters
    ----------
    cos_theta_i : array_like
        Cosine of the angle of incidence, in [0, 1] [-].
    n1, n2 : array_like
        Refractive index of the incident and of the transmitting medium [-]
        (air → water: ``n1=1, n2=1.333``; water → air: ``n1=1.333, n2=1``).

    Returns
    -------
    ndarray
        Reflectance F(θ_i) in [0, 1] [-], broadcast over the inputs.

    Examples
    --------
    >>> round(float(reflectance_Fresnel(1.0, 1.0, 1.333)), 5)  # normal incidence
    0.02037

    References
    ----------
    .. [1] Born & Wolf (1999), *Principles of Optics*, 7th ed., §1.5.3.
    .. [2] Mobley, C. D. (1994). *Light and Water: Radiative Transfer in
       Natural Waters*, Academic Press, Ch. 4.
    """
    R_s, R_p = reflectance_components_Fresnel(cos_theta_i, n1, n2)
    return 0.5 * (R_s + R_p)  # unpolarised: mean of s and p, §1.5.3 of [1], Ch. 4 of [2]


def transmittance_Fresnel(cos_theta_i: ArrayLike, n1: ArrayLike, n2: ArrayLike) -> NDArray[np.float64]:
    """Fresnel transmittance of unpolarised light, T = 1 − F [-].

    The fraction of the incident power that crosses the interface (energy
    conservation for lossless media). The radiance of the transmitted beam is
    T (n2/n1)² times the incident radiance (the n² law, Mobley 1994, Ch. 4).

    Parameters
    ----------
    cos_theta_i : array_like
        Cosine of the angle of incidence, in [0, 1] [-].
    n1, n2 : array_like
        Refractive index of the incident and of the transmitting medium [-].
    """
    return 1.0 - reflectance_Fresnel(cos_theta_i, n1, n2)


def diffuse_reflectance_Fresnel(n1: ArrayLike, n2: ArrayLike) -> NDArray[np.float64]:
    """Hemispherical reflectance of a flat interface for uniform radiance [-].

    The cosine-weighted average of F over the incident hemisphere,

        r̄ = 2 ∫₀¹ F(μ) μ dμ,

    i.e. the reflected fraction of the irradiance of an isotropic radiance
    distribution (a uniform overcast sky seen from the water, or a uniform
    upwelling field seen from the air). Computed by Gauss–Legendre quadrature
    on the transmitting side (n1 < n2); for incidence from the denser medium
    the exact reciprocity relation

        1 − r̄(n1 → n2) = (1 − r̄(n2 → n1)) · (n2/n1)²,

    which holds because the cosine-weighted solid angle μ dμ scales by
    (n2/n1)² through Snell's law, is used, so that the total-internal-
    reflection part (μ < cos θ_c, weight cos²θ_c) is exact.

    Parameters
    ----------
    n1, n2 : array_like
        Refractive index of the incident and of the transmitting medium [-].

    Returns
    -------
    ndarray
        r̄ [-]: 0.0664 for air → water and 0.4746 for water → air at n = 1.333.
        Published: 0.066 for a uniform sky over a level sea (Preisendorfer
        1976; Mobley 1994, Ch. 4) and 0.47–0.49 for uniform radiance from
        below (the value depends on n: 0.4746 at 1.333, 0.4807 at 1.34;
        ocean-colour models commonly use 0.48).

    References
    ----------
    .. [1] Mobley, C. D. (1994). *Light and Water: Radiative Transfer in
       Natural Waters*, Academic Press, Ch. 4.
    .. [2] Preisendorfer, R. W. (1976). *Hydrologic Optics*, Vol. VI, NOAA,
       Honolulu.
    """
    n1, n2 = _check_indices(n1, n2)
    lo, hi = np.minimum(n1, n2), np.maximum(n1, n2)
    mu, weights = _gauss_legendre_unit()  # nodes mapped from [−1, 1] to [0, 1]
    F = reflectance_Fresnel(mu, lo[..., None], hi[..., None])
    r_rare = np.sum(weights * F * mu, axis=-1)  # r̄ = 2 ∫ F μ dμ with dμ = dx/2, Ch. 4 of [1]
    r_dense = 1.0 - (1.0 - r_rare) * (lo / hi) ** 2  # reciprocity, 1 − r̄ scales with (n2/n1)²
    return np.where(n1 <= n2, r_rare, r_dense)


def diffuse_transmittance_Fresnel(n1: ArrayLike, n2: ArrayLike) -> NDArray[np.float64]:
    """Hemispherical transmittance for uniform radiance, 1 − r̄ [-].

    See :func:`diffuse_reflectance_Fresnel`.

    Parameters
    ----------
    n1, n2 : array_like
        Refractive index of the incident and of the transmitting medium [-].
    """
    return 1.0 - diffuse_reflectance_Fresnel(n1, n2)


def fresnel_correction(F: ArrayLike, gamma: ArrayLike) -> NDArray[np.float64]:
    """The dissertation's corrected Fresnel weight F_c = F^γ [-].

    An empirical exponent applied to the Fresnel reflectance before it mixes
    the reflected and refracted radiance, B = F_c B_refl + (1 − F_c) B_refr,
    so the mix stays a convex combination (energy is only redistributed).
    γ < 1 raises the reflected share (F^γ ≥ F for F ≤ 1), γ > 1 lowers it;
    γ = 1 is the exact Fresnel weight. F = 0 and F = 1 are fixed points.

    Parameters
    ----------
    F : array_like
        Fresnel reflectance in [0, 1] [-].
    gamma : array_like
        Correction exponent γ > 0 [-].

    Returns
    -------
    ndarray
        F_c in [0, 1] [-].

    References
    ----------
    .. [1] The dissertation named in the project issue, Eq. 20 (the
       correction; its text is not available to us, the form F^γ is quoted in
       the issue).
    """
    F = np.asarray(F, dtype=float)
    gamma = np.asarray(gamma, dtype=float)
    finite = F[np.isfinite(F)]
    if np.any((finite < 0.0) | (finite > 1.0)):
        raise ValueError("F must lie in [0, 1]")
    if np.any(~(gamma > 0.0)):
        raise ValueError("gamma must be positive")
    return F**gamma  # Eq. 20 of [1]


def refract(directions: ArrayLike, normals: ArrayLike, eta: float) -> NDArray[np.float64]:
    """Refracted unit directions (vector Snell's law); NaN under total internal reflection.

    Parameters
    ----------
    directions : array_like (..., 3)
        Unit propagation directions of the incident rays.
    normals : array_like (..., 3)
        Unit normals on the side the rays come from (d·n ≤ 0).
    eta : float
        Ratio n₁/n₂ of the incident to the transmitting refractive index [-].

    References
    ----------
    .. [1] Pharr, Jakob & Humphreys (2023), §9.3.2.
    """
    d = np.asarray(directions, dtype=np.float64)
    n = np.asarray(normals, dtype=np.float64)
    cos_i = -np.sum(d * n, axis=-1, keepdims=True)
    sin2_t = eta**2 * np.maximum(0.0, 1.0 - cos_i**2)
    cos_t = np.sqrt(np.maximum(0.0, 1.0 - sin2_t))
    t = eta * d + (eta * cos_i - cos_t) * n  # Snell's law in vector form, §9.3.2 of [1]
    return np.where(sin2_t <= 1.0, t, np.nan)
