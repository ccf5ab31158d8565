"""Mass-specific IOPs of a population of homogeneous spheres from Mie theory.

The Mie coefficients aₙ, bₙ come from ``miepython`` (Prahl); this module sums
them into efficiencies, integrates the backward hemisphere of the phase
function and averages over a particle size distribution (PSD) to give the
mass-specific absorption a*, scattering b* and backscattering b_b* [m² g⁻¹] of
a suspension and its phase function p(θ) [sr⁻¹].

Conventions
-----------
* Wavelengths in vacuum [nm]; diameters [m]; density [kg m⁻³].
* The particle's refractive index is given *relative to water*,
  m = (n_p + i k_p) / n_w, with a **non-negative** imaginary part (the ocean
  optics sign, e.g. Stramski et al. 2004). ``miepython`` uses m = n − ik; the
  sign is flipped here, once.
* The size parameter is x = π D n_w / λ (wavelength inside water).
* Mass-specific coefficients are per gram of dry particle mass:
  c*(λ) = ∫ Q(D, λ) (π D²/4) n(D) dD / (ρ ∫ (π D³/6) n(D) dD)   [m² g⁻¹].

References
----------
.. [1] Bohren, C. F. & Huffman, D. R. (1983), Absorption and Scattering of
   Light by Small Particles, Wiley: Eqs. 4.61-4.62 (Qext, Qsca), 4.74 (S1, S2),
   4.47 (πₙ, τₙ), 5.8 (Rayleigh limit).
.. [2] van de Hulst, H. C. (1957), Light Scattering by Small Particles, Wiley
   (extinction paradox: Q_ext → 2 as x → ∞).
.. [3] Prahl, S. (2024), miepython, https://github.com/scottprahl/miepython.
.. [4] Junge, C. E. (1963), Air Chemistry and Radioactivity, Academic Press
   (power-law size distribution); Bader, H. (1970), J. Geophys. Res. 75,
   2822-2830 (its use for marine particles).
"""

from __future__ import annotations

import functools
from dataclasses import dataclass, field
from typing import Callable, Union

import numpy as np
from scipy.special import roots_legendre

#: Real refractive index of sea water used when none is given [-] (Mobley 1994, Light and Water, §3.6).
N_WATER_DEFAULT = 1.34

#: Scattering angles of the returned phase function [deg]: log-spaced in the
#: forward peak (0.01-10°), then every 2.5° to 180°.
DEFAULT_ANGLES_DEG = np.unique(np.concatenate([np.geomspace(0.01, 10.0, 41), np.arange(10.0, 180.0 + 1e-9, 2.5)]))

IndexLike = Union[complex, np.ndarray, Callable[[np.ndarray], np.ndarray]]


@dataclass(frozen=True)
class JungePSD:
    """Power-law (Junge) number size distribution n(D) ∝ D^−ξ on [D_min, D_max].

    Parameters
    ----------
    slope : float        Junge slope ξ [-] (marine particles: 3.5-4.5, typical 4; Bader 1970).
    d_min_m : float      Smallest diameter [m].
    d_max_m : float      Largest diameter [m].
    """

    slope: float = 4.0
    d_min_m: float = 0.2e-6
    d_max_m: float = 100e-6

    def __post_init__(self) -> None:
        _check_range("JungePSD", self.d_min_m, self.d_max_m)
        if not np.isfinite(self.slope):
            raise ValueError(f"JungePSD: slope must be finite, got {self.slope!r}")

    @property
    def bounds_m(self) -> tuple[float, float]:
        return self.d_min_m, self.d_max_m

    def number_density(self, diameters_m: np.ndarray) -> np.ndarray:
        """Relative number per unit diameter n(D) [arbitrary m⁻¹]."""
        d = np.asarray(diameters_m, dtype=float)
        return (d / self.d_min_m) ** (-self.slope)

    def describe(self) -> str:
        return f"Junge n(D) ~ D^-{self.slope:g}, D = {self.d_min_m * 1e6:g}-{self.d_max_m * 1e6:g} um"


@dataclass(frozen=True)
class LogNormalPSD:
    """Log-normal number size distribution, truncated to [D_min, D_max].

    n(D) ∝ (1/D) exp(−(ln D − ln D_g)² / (2 ln² σ_g)).

    Parameters
    ----------
    median_diameter_m : float   Number-median diameter D_g [m].
    geometric_sd : float        Geometric standard deviation σ_g > 1 [-].
    d_min_m, d_max_m : float    Truncation [m]; default D_g σ_g^∓4.
    """

    median_diameter_m: float
    geometric_sd: float
    d_min_m: float | None = None
    d_max_m: float | None = None

    def __post_init__(self) -> None:
        if not (self.median_diameter_m > 0 and self.geometric_sd > 1):
            raise ValueError("LogNormalPSD: median_diameter_m must be > 0 and geometric_sd > 1")
        _check_range("LogNormalPSD", *self.bounds_m)

    @property
    def bounds_m(self) -> tuple[float, float]:
        lo = self.d_min_m if self.d_min_m is not None else self.median_diameter_m / self.geometric_sd**4
        hi = self.d_max_m if self.d_max_m is not None else self.median_diameter_m * self.geometric_sd**4
        return lo, hi

    def number_density(self, diameters_m: np.ndarray) -> np.ndarray:
        d = np.asarray(diameters_m, dtype=float)
        s = np.log(self.geometric_sd)
        return np.exp(-0.5 * (np.log(d / self.median_diameter_m) / s) ** 2) / d

    def describe(self) -> str:
        lo, hi = self.bounds_m
        return (f"log-normal D_g = {self.median_diameter_m * 1e6:g} um, sigma_g = {self.geometric_sd:g}, "
                f"D = {lo * 1e6:g}-{hi * 1e6:g} um")


PSD = Union[JungePSD, LogNormalPSD]


def _check_range(name: str, lo: float, hi: float) -> None:
    if not (np.isfinite(lo) and np.isfinite(hi) and 0 < lo < hi):
        raise ValueError(f"{name}: need 0 < d_min_m < d_max_m, got {lo!r}, {hi!r}")


@dataclass(frozen=True)
class SphereEfficiencies:
    """Mie efficiencies of single spheres [-] (arrays over the size parameters)."""

    x: np.ndarray
    q_ext: np.ndarray
    q_sca: np.ndarray
    q_bsca: np.ndarray  # hemispherical backscattering efficiency (θ > 90°)
    g: np.ndarray

    @property
    def q_abs(self) -> np.ndarray:
        return self.q_ext - self.q_sca


@dataclass(frozen=True)
class MassSpecificIOPs:
    """Mass-specific IOPs of a particle population.

    Attributes
    ----------
    wavelengths : ndarray      Wavelengths in vacuum [nm].
    absorption : ndarray       a*(λ) [m² g⁻¹].
    scattering : ndarray       b*(λ) [m² g⁻¹].
    backscattering : ndarray   b_b*(λ) [m² g⁻¹].
    asymmetry : ndarray        g(λ) = <cos θ> [-].
    angles_deg : ndarray       Scattering angles of ``phase_function`` [deg].
    phase_function : ndarray   p(λ, θ) [sr⁻¹], 2π ∫ p dcosθ = 1, shape (n_λ, n_θ).
    """

    wavelengths: np.ndarray
    absorption: np.ndarray
    scattering: np.ndarray
    backscattering: np.ndarray
    asymmetry: np.ndarray
    angles_deg: np.ndarray
    phase_function: np.ndarray = field(repr=False)

    @property
    def backscattering_ratio(self) -> np.ndarray:
        """b̃_b = b_b / b [-]."""
        return self.backscattering / self.scattering


def _legendre_pi_tau(n_max: int, mu: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Angular functions πₙ(μ), τₙ(μ), n = 1..n_max, shape (n_max, len(μ)) (Eq. 4.47 of [1])."""
    pi = np.zeros((n_max + 1, mu.size))
    tau = np.zeros_like(pi)
    pi[1] = 1.0
    tau[1] = mu
    for n in range(2, n_max + 1):
        pi[n] = ((2 * n - 1) * mu * pi[n - 1] - n * pi[n - 2]) / (n - 1)
        tau[n] = n * mu * pi[n] - (n + 1) * pi[n - 1]
    return pi[1:], tau[1:]


def _coefficients(m: complex, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """aₙ, bₙ of spheres of size parameters ``x`` padded to one array (n_x, n_max)."""
    m_mie = complex(m.real, -abs(m.imag))  # miepython's sign: m = n − ik
    coeffs = [_an_bn(m_mie, float(xi)) for xi in x]
    n_max = max(len(a) for a, _ in coeffs)
    a = np.zeros((x.size, n_max), dtype=complex)
    b = np.zeros_like(a)
    for i, (ai, bi) in enumerate(coeffs):
        a[i, : len(ai)] = ai
        b[i, : len(bi)] = bi
    return a, b


def _an_bn(m: complex, x: float) -> tuple[np.ndarray, np.ndarray]:
    # Imported on first use so that a caller's MIEPYTHON_USE_JIT (numba backend) takes effect.
    import miepython

    return miepython.an_bn(m, x)


def sphere_efficiencies(m: complex, x) -> SphereEfficiencies:
    """Extinction, scattering and backscattering efficiencies of spheres [-].

    Parameters
    ----------
    m : complex        Relative refractive index n + ik (k ≥ 0) [-].
    x : array_like     Size parameters π D n_w / λ [-].

    Notes
    -----
    Q_bsca = (2/x²) ∫₋₁⁰ (|S₁|² + |S₂|²)/2 dμ, evaluated by Gauss-Legendre
    quadrature with more than N nodes for a series of N terms: |S|² is a
    polynomial of degree 2N in μ, so the quadrature is exact (to round-off).
    """
    eff, _ = _spheres(m, np.atleast_1d(np.asarray(x, dtype=float)), np.empty(0))
    return eff


def _spheres(m: complex, x: np.ndarray, mu_out: np.ndarray) -> tuple[SphereEfficiencies, np.ndarray]:
    """Efficiencies and i(μ)/(π x²) [sr⁻¹ per unit geometric cross-section] at ``mu_out``."""
    q_ext, q_sca, q_bsca, g = (np.empty_like(x) for _ in range(4))
    intensity_out = np.empty((x.size, mu_out.size))
    # Chunks of similar x share one quadrature grid sized for the chunk's largest sphere.
    for chunk in np.array_split(np.argsort(x), max(1, x.size // 8)):
        xs = x[chunk]
        a, b = _coefficients(m, xs)
        n = np.arange(1, a.shape[1] + 1)
        q_ext[chunk] = 2.0 / xs**2 * np.sum((2 * n + 1) * (a + b).real, axis=1)  # Eq. 4.62 of [1]
        q_sca[chunk] = 2.0 / xs**2 * np.sum((2 * n + 1) * (np.abs(a) ** 2 + np.abs(b) ** 2), axis=1)  # Eq. 4.61 of [1]
        # Asymmetry parameter: g Q_sca (Bohren & Huffman 1983, p. 120).
        nn = n[:-1]
        gq = np.sum(nn * (nn + 2) / (nn + 1) * (a[:, :-1] * a[:, 1:].conj() + b[:, :-1] * b[:, 1:].conj()).real, axis=1)
        gq += np.sum((2 * n + 1) / (n * (n + 1)) * (a * b.conj()).real, axis=1)
        g[chunk] = 4.0 / (xs**2 * q_sca[chunk]) * gq
        mu, weights = _back_hemisphere_nodes(a.shape[1] + 1)
        s1, s2 = _amplitudes(a, b, np.concatenate([mu, mu_out]))
        intensity = 0.5 * (np.abs(s1) ** 2 + np.abs(s2) ** 2)
        q_bsca[chunk] = 2.0 / xs**2 * (intensity[:, : mu.size] @ weights)
        intensity_out[chunk] = intensity[:, mu.size :] / (np.pi * xs[:, None] ** 2)
    return SphereEfficiencies(x=x, q_ext=q_ext, q_sca=q_sca, q_bsca=q_bsca, g=g), intensity_out


@functools.lru_cache(maxsize=64)
def _back_hemisphere_nodes_cached(n_nodes: int) -> tuple[np.ndarray, np.ndarray]:
    nodes, weights = roots_legendre(n_nodes)
    return 0.5 * (nodes - 1.0), 0.5 * weights  # mapped from [-1, 1] to μ in [-1, 0]


def _back_hemisphere_nodes(n_min: int) -> tuple[np.ndarray, np.ndarray]:
    """Gauss-Legendre nodes and weights on μ ∈ [−1, 0], at least ``n_min`` nodes."""
    # NOTE: rounded up to a multiple of 32 so that nodes are computed once and reused across wavelengths.
    return _back_hemisphere_nodes_cached(int(32 * np.ceil(n_min / 32)))


def _amplitudes(a: np.ndarray, b: np.ndarray, mu: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """S₁(μ), S₂(μ) for each sphere (rows of a, b), Eq. 4.74 of [1]."""
    pi, tau = _legendre_pi_tau(a.shape[1], mu)
    n = np.arange(1, a.shape[1] + 1)
    c = (2 * n + 1) / (n * (n + 1))
    rows = a.shape[0]
    # Real matrix products (πₙ, τₙ are real): rows [Re a, Im a, Re b, Im b].
    coef = np.concatenate([(c * a).real, (c * a).imag, (c * b).real, (c * b).imag])
    p_, t_ = coef @ pi, coef @ tau
    ar, ai, br, bi = (slice(k * rows, (k + 1) * rows) for k in range(4))
    s1 = (p_[ar] + t_[br]) + 1j * (p_[ai] + t_[bi])
    s2 = (t_[ar] + p_[br]) + 1j * (t_[ai] + p_[bi])
    return s1, s2


def _relative_index(m_particle: IndexLike, wavelengths_nm: np.ndarray) -> np.ndarray:
    if callable(m_particle):
        m = np.asarray(m_particle(wavelengths_nm), dtype=complex)
    else:
        m = np.asarray(m_particle, dtype=complex)
    m = np.broadcast_to(m, wavelengths_nm.shape).astype(complex)
    if np.any(~np.isfinite(m)) or np.any(m.real <= 0) or np.any(m.imag < 0):
        raise ValueError("m_particle: need finite n > 0 and k >= 0 (m = n + ik relative to water)")
    return m


def mass_specific_iops(
    wavelengths_nm,
    m_particle: IndexLike,
    psd: PSD,
    density_kg_m3: float,
    n_water: float | np.ndarray = N_WATER_DEFAULT,
    angles_deg: np.ndarray = DEFAULT_ANGLES_DEG,
    n_diameters: int = 120,
) -> MassSpecificIOPs:
    """Mass-specific a*, b*, b_b* [m² g⁻¹] and phase function of a particle population.

    Parameters
    ----------
    wavelengths_nm : array_like   Wavelengths in vacuum [nm].
    m_particle : complex, array or callable
        Refractive index relative to water m = (n_p + i k_p)/n_w, k ≥ 0 [-]:
        one value, one per wavelength, or a function of wavelength [nm].
    psd : JungePSD or LogNormalPSD
        Number size distribution (shape only; its normalisation cancels).
    density_kg_m3 : float          Particle density ρ [kg m⁻³].
    n_water : float or array       Real index of the surrounding water [-].
    angles_deg : array             Angles of the returned phase function [deg].
    n_diameters : int              Log-spaced diameters for the PSD integral [-].

    Returns
    -------
    MassSpecificIOPs

    Notes
    -----
    The PSD integrals are trapezoids in ln D over ``n_diameters`` diameters
    from D_min to D_max; with the default 120 nodes the result changes by
    < 0.3 % at 443-700 nm on doubling them. Single spheres oscillate in D (ripple
    structure); the PSD average smooths them, so no finer grid is needed.
    """
    wl = np.atleast_1d(np.asarray(wavelengths_nm, dtype=float))
    if not np.all(np.isfinite(wl)) or np.any(wl <= 0):
        raise ValueError("wavelengths_nm: need finite, positive wavelengths [nm]")
    if not (np.isfinite(density_kg_m3) and density_kg_m3 > 0):
        raise ValueError(f"density_kg_m3: need a positive density, got {density_kg_m3!r}")
    m = _relative_index(m_particle, wl)
    n_w = np.broadcast_to(np.asarray(n_water, dtype=float), wl.shape)
    angles = np.asarray(angles_deg, dtype=float)
    mu_out = np.cos(np.radians(angles))

    d = np.geomspace(*psd.bounds_m, n_diameters)
    w = psd.number_density(d) * d  # n(D) dD = n(D) D d(ln D)
    ln_d = np.log(d)
    volume = np.trapezoid(w * np.pi * d**3 / 6.0, ln_d)  # [m³ per unit number]
    mass_g = density_kg_m3 * 1e3 * volume  # [g] (ρ in g m⁻³ times volume)
    area = np.pi * d**2 / 4.0

    a_s, b_s, bb_s, g_s = (np.empty(wl.size) for _ in range(4))
    phase = np.empty((wl.size, angles.size))
    for j, lam in enumerate(wl):
        x = np.pi * d * n_w[j] / (lam * 1e-9)
        eff, intensity = _spheres(m[j], x, mu_out)
        a_s[j] = np.trapezoid(w * area * eff.q_abs, ln_d) / mass_g
        b_s[j] = np.trapezoid(w * area * eff.q_sca, ln_d) / mass_g
        bb_s[j] = np.trapezoid(w * area * eff.q_bsca, ln_d) / mass_g
        g_s[j] = np.trapezoid(w * area * eff.q_sca * eff.g, ln_d) / mass_g / b_s[j]
        # p(θ) = ∫ σ_sca(D) p_D(θ) n(D) dD / ∫ σ_sca n dD, with σ_sca p_D = area · i / (π x²).
        phase[j] = np.trapezoid((w * area)[:, None] * intensity, ln_d, axis=0) / (b_s[j] * mass_g)
    return MassSpecificIOPs(wl, a_s, b_s, bb_s, g_s, angles, phase)


def rayleigh_scattering_efficiency(m: complex, x) -> np.ndarray:
    """Small-sphere limit Q_sca = (8/3) x⁴ |(m²−1)/(m²+2)|² [-] (Eq. 5.8 of [1])."""
    x = np.asarray(x, dtype=float)
    return 8.0 / 3.0 * x**4 * np.abs((m**2 - 1) / (m**2 + 2)) ** 2
