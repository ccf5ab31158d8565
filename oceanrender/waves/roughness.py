"""Sub-grid roughness: the slopes of waves too short for the mesh.

A mesh sampled at spacing Δx resolves wavenumbers up to the Nyquist limit
k_c = π/Δx. The slopes of all shorter waves are invisible to the geometry but
not to light: they spread the reflected and refracted sun into a glitter
pattern. Treating them as microfacets (Cox & Munk 1954; the microfacet
interpretation of the sea surface is e.g. Ross, Dion & Potvin 2005) gives a
roughness for the water's BSDF that follows from the same wave spectrum as the
mesh instead of being a free parameter.
"""

from __future__ import annotations

import numpy as np


def unresolved_slope_variance(spectrum, cutoff_wavenumber: float, shortest_wavelength: float = 1e-3,
                              samples: int = 2048) -> float:
    """Mean-square slope ⟨s_x² + s_y²⟩ [-] of the waves shorter than the geometry resolves.

    .. math:: σ² = ∫_0^{2π} ∫_{k_c}^{k_max} k² Ψ(k, θ) k \\, dk \\, dθ

    (the slope spectrum is k² times the elevation spectrum, e.g. Phillips 1977,
    §4.7), with k_max = 2π / ``shortest_wavelength``.

    Parameters
    ----------
    spectrum : callable
        Directional wavenumber spectrum Ψ(kx, ky) [m⁴] (e.g. a
        :class:`~oceanrender.waves.wave_spectra.DirectionalSpectrum`).
    cutoff_wavenumber : float
        k_c, the Nyquist wavenumber π/Δx of the finest geometry [rad m⁻¹].
    shortest_wavelength : float
        Shortest gravity-capillary wave included [m]; 1 mm by default.
    samples : int
        Log-spaced radial samples of the quadrature.

    Returns
    -------
    float
        Total mean-square slope of the unresolved waves [-].
    """
    k_max = 2.0 * np.pi / shortest_wavelength
    if k_max <= cutoff_wavenumber:
        return 0.0
    return spectral_moment(spectrum, cutoff_wavenumber, k_max, 2, samples)


def spectral_moment(spectrum, k_min: float, k_max: float, order: int, samples: int = 2048) -> float:
    """∫∫ k^order Ψ(k, θ) k dk dθ over k_min ≤ k ≤ k_max [m^(2−order)]: order 0 is m₀ [m²], 2 the mss [-].

    Log-spaced radial quadrature (dk = k d ln k, trapezoid), θ by the periodic
    rectangle rule on 360 directions.
    """
    log_k = np.linspace(np.log(k_min), np.log(k_max), samples)
    theta = np.linspace(0.0, 2.0 * np.pi, 361)[:-1]
    k = np.exp(log_k)[:, None]
    psi = spectrum(k * np.cos(theta), k * np.sin(theta))
    # dk = k d(ln k): the integrand k^order Ψ · k · k over ln k.
    radial = (k[:, 0] ** (order + 2)) * psi.mean(axis=1) * 2.0 * np.pi
    return float(np.trapezoid(radial, log_k))


def elevation_variance(spectrum, k_min: float, k_max: float, samples: int = 2048) -> float:
    """Elevation variance m₀ = ⟨η²⟩ [m²] of the waves with k_min ≤ k ≤ k_max [rad m⁻¹].

    .. math:: m_0 = ∫_0^{2π} ∫_{k_min}^{k_max} Ψ(k, θ) k \\, dk \\, dθ

    (the zeroth moment of the directional wavenumber spectrum: a variance
    spectrum integrates to the variance by its definition); H_s = 4 √m₀ for
    Rayleigh-distributed wave heights (Longuet-Higgins 1952).
    """
    return spectral_moment(spectrum, k_min, k_max, 0, samples)


def beckmann_alpha(mean_square_slope: float) -> float:
    """Beckmann roughness α [-] of an isotropic Gaussian slope distribution.

    Beckmann's slope density is exp(−(s_x² + s_y²)/α²)/(π α²) (Walter et al.
    2007, Eq. 25 written in slope space), whose total mean-square slope is α².
    """
    return float(np.sqrt(max(mean_square_slope, 0.0)))
