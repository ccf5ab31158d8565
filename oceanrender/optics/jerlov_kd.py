"""K_d of the Jerlov water types from their IOPs, under the conditions of HydroLight's table (issue 43).

Solonenko & Mobley (2015) retrieved a(λ) and b(λ) for all ten Jerlov types and checked
them by running HydroLight with those a, b: the resulting K_d^H (their Tables 4-8, the
``jerlov`` package's ``kd_hydrolight``) is the reference here. What their runs state, as the
``jerlov`` package quotes them: the Petzold average-particle phase function, a clear sky,
infinitely deep water, no inelastic scattering, "to an optical depth of 10 scattering
lengths, or 6 for Jerlov III". The sun's zenith angle, the sky's share of the light, the
phase function of the water molecules and the depth range of the tabulated K_d are not
stated; :class:`KdConditions` makes each explicit, and docs/optics.md ("K_d against
HydroLight") shows what each does.

This module computes, per wavelength:

* :func:`kd_transport` — the exact transport (discrete ordinates, :mod:`.streams`, δ-M,
  32 streams per hemisphere; within 0.5 % of Mitsuba's Monte Carlo in K_d, docs/optics.md)
  of a deep layer under a level surface, the refracted sun and a uniform sky;
* :func:`kd_four_flux` — the four-flux model with coefficients derived from the same phase
  function (:func:`.streams.sunlit_coefficients`), and :func:`kd_four_flux_fixed` with the
  fixed closure it had before issue 19 (μ_d = 0.83, μ_u = 0.40, b_b from the phase function);
* :func:`surface_beams` — the sun and the sky as a few collimated beams in the water (the sky's
  rings of equal zenith angle by Gauss–Legendre quadrature), so that a Monte Carlo slab lit by
  one beam at a time (:func:`oceanrender.render.slab.slab_kd`) adds up to the same light.

K_d over a layer is K̄ = ln(E_d(0⁻)/E_d(H))/H, the depth average of K_d(z) = −d ln E_d/dz
over 0 ≤ z ≤ H (Mobley 1994, Eq. 5.61 integrated).

Units: coefficients m⁻¹, depths m, angles degrees, irradiances relative [-].

References
----------
.. [1] Solonenko, M. G. & Mobley, C. D. (2015). Inherent optical properties of Jerlov water
   types. *Appl. Opt.* 54(17), 5392–5401. doi:10.1364/AO.54.005392
.. [2] Petzold, T. J. (1972). Volume scattering functions for selected ocean waters. SIO
   Ref. 72-78; Mobley, C. D. (1994), *Light and Water*, Table 3.10 (the "average particle").
.. [3] Morel, A. (1974). Optical properties of pure water and pure sea water. In *Optical
   Aspects of Oceanography*, Academic Press, pp. 1–24 (β_w ∝ 1 + 0.835 cos²θ, b_sw).
.. [4] Jerlov, N. G. (1976). *Marine Optics*. Elsevier (K_d of the upper layer defines the types).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["HYDROLIGHT_TYPES", "KdConditions", "hydrolight_phase", "kd_four_flux", "kd_four_flux_fixed",
           "kd_transport", "layer_depth", "solonenko2015_water", "surface_beams"]

#: The Jerlov types of Solonenko & Mobley (2015) compared in issue 43.
HYDROLIGHT_TYPES = ("I", "II", "III", "1C", "5C", "9C")

#: Salinity of the pure sea water whose molecular scattering is split off b [PSU] (Morel 1974's sea water).
SEAWATER_SALINITY_PSU = 35.0

#: Deepest optical depth c z a layer may reach [-]: beyond it E_d ≲ e⁻⁶⁰ of the surface's, nothing to average.
MAX_OPTICAL_DEPTH = 60.0


@dataclass(frozen=True)
class KdConditions:
    """The light and the K_d definition of a comparison with HydroLight's K_d^H.

    Attributes
    ----------
    sun_zenith_deg : float      Sun's zenith angle in air [deg], 0–85.
    sky_fraction : float        Share of the horizontal irradiance above the water that comes from
                                the sky, taken as uniform radiance [-], 0 ≤ f < 1.
    n_water : float             Refractive index of the water [-] (a level surface).
    layer_m : float or None     K_d is averaged over 0 ≤ z ≤ ``layer_m`` [m]; None: over the first
                                optical depth z₁, E_d(z₁) = E_d(0⁻)/e (Gordon 1989) ...
    scattering_lengths : float or None
        ... unless given: then over 0 ≤ z ≤ N/b (N scattering lengths), at most
        :data:`MAX_OPTICAL_DEPTH`/c.
    water_rayleigh : bool       The water molecules' share b_w of b scatters with Morel's (1974)
                                phase function, the rest with Petzold's; False: all of b Petzold's.
    level_surface : bool        A level water surface (Fresnel, Snell, the upwelling reflected back
                                down); False: an index-matched top (the sun's refracted beam enters
                                without loss and nothing is reflected: the slab of issue 19).
    """

    sun_zenith_deg: float = 30.0
    sky_fraction: float = 0.15
    n_water: float = 1.34
    layer_m: float | None = 10.0
    scattering_lengths: float | None = None
    water_rayleigh: bool = True
    level_surface: bool = True

    def __post_init__(self) -> None:
        if not (0.0 <= self.sun_zenith_deg <= 85.0 and 0.0 <= self.sky_fraction < 1.0 and 1.0 < self.n_water < 2.0
                and (self.layer_m is None or self.layer_m > 0)
                and (self.scattering_lengths is None or self.scattering_lengths > 0)):
            raise ValueError(f"KdConditions: out of range: {self}")


def solonenko2015_water(water_type: str, wavelengths_nm: ArrayLike) -> tuple[NDArray, NDArray, NDArray, NDArray]:
    """(a, b, b_w, K_d^H) [m⁻¹] of a Jerlov type from Solonenko & Mobley (2015), via the ``jerlov`` package.

    b_w is Morel's (1974) pure sea water at :data:`SEAWATER_SALINITY_PSU` (``jerlov.pure_water_scattering``),
    capped at b (type I's b at 400–450 nm is below it: the package flags that b as suspect).
    NaN where the paper has no value (5C beyond 575 nm).
    """
    import warnings  # noqa: PLC0415

    import jerlov  # noqa: PLC0415

    wl = np.atleast_1d(np.asarray(wavelengths_nm, dtype=float))
    with warnings.catch_warnings():  # the package warns on its flagged rows; the flags are in its caveats
        warnings.simplefilter("ignore")
        water = jerlov.water(water_type, source="solonenko2015")
        a, b, kd = (np.asarray(f(wl), dtype=float) for f in (water.a, water.b, water.kd_hydrolight))
    b_w = np.minimum(np.asarray(jerlov.pure_water_scattering(wl, salinity_psu=SEAWATER_SALINITY_PSU), float), b)
    return a, b, b_w, kd


def hydrolight_phase(b: ArrayLike, b_w: ArrayLike, water_rayleigh: bool = True) -> tuple[NDArray, NDArray]:
    """(μ (M,) from −1 to 1 [-], p (W, M) [sr⁻¹]): (b_w p_w + (b − b_w) p_Petzold)/b per wavelength.

    p_w is pure water's phase function (Morel 1974), p_Petzold the average-particle function of [2]
    (:func:`~oceanrender.optics.components.petzold_particle_phase`); both on the project's 1201-angle table.
    """
    from .components import _tabulate, petzold_particle_phase, pure_water_phase_function  # noqa: PLC0415

    b = np.atleast_1d(np.asarray(b, dtype=float))
    share = np.atleast_1d(np.asarray(b_w, dtype=float)) / b if water_rayleigh else np.zeros_like(b)
    mu, p_particles = _tabulate(petzold_particle_phase)
    _, p_water = _tabulate(pure_water_phase_function)
    return mu, (1.0 - share)[:, None] * p_particles[None, :] + share[:, None] * p_water[None, :]


def layer_depth(a: float, b: float, conditions: KdConditions) -> float | None:
    """The depth H [m] K_d is averaged down to (:class:`KdConditions`); None for the first optical depth."""
    if conditions.scattering_lengths is None:
        return conditions.layer_m
    return min(conditions.scattering_lengths / b, MAX_OPTICAL_DEPTH / (a + b))


def _layer_mean(E_d_of_z, H: float | None, K_guess: float) -> float:
    """ln(E_d(0⁻)/E_d(H))/H [m⁻¹]; for H None the first optical depth z₁ (E_d(z₁) = E_d(0⁻)/e, found by
    bisection on ln E_d from a bracket around 1/K_guess), K = 1/z₁."""
    if H is not None:
        E0, EH = E_d_of_z(np.array([0.0, H]))
        return math.log(E0 / EH) / H
    E0 = float(E_d_of_z(np.array([0.0]))[0])
    lo, hi = 0.0, 1.0 / K_guess
    while math.log(E0 / float(E_d_of_z(np.array([hi]))[0])) < 1.0:
        hi *= 2.0
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if math.log(E0 / float(E_d_of_z(np.array([mid]))[0])) < 1.0 else (lo, mid)
    return 1.0 / (0.5 * (lo + hi))


def _surface(conditions: KdConditions) -> tuple[float, float, float]:
    """(μ_w, sun's direct-normal irradiance, sky's horizontal irradiance) above the water, for 1 horizontal in all."""
    mu_s = math.cos(math.radians(conditions.sun_zenith_deg))
    return mu_s, (1.0 - conditions.sky_fraction) / mu_s, conditions.sky_fraction


def kd_transport(a: ArrayLike, b: ArrayLike, b_w: ArrayLike, conditions: KdConditions = KdConditions()) -> NDArray:
    """K̄_d [m⁻¹] of the exact transport (discrete ordinates) of a deep layer, per wavelength."""
    from .streams import N_STREAMS, deep_layer, legendre_moments, surface_light  # noqa: PLC0415

    a, b, b_w = (np.atleast_1d(np.asarray(v, dtype=float)) for v in (a, b, b_w))
    mu, p = hydrolight_phase(b, b_w, conditions.water_rayleigh)
    chi = legendre_moments(mu, p, 2 * N_STREAMS + 1)
    _, sun, sky = _surface(conditions)
    mu_w, sky_in = surface_light(sun, sky, conditions.sun_zenith_deg, conditions.n_water)
    if not conditions.level_surface:
        if conditions.sky_fraction > 0:
            raise ValueError("kd_transport: an index-matched top takes the sun alone (sky_fraction = 0)")
        sky_in = 0.0
    out = np.empty(a.size)
    for i in range(a.size):
        layer = deep_layer(float(a[i]), float(b[i]), chi[i], mu_w, sky=float(sky_in),
                           n_water=conditions.n_water if conditions.level_surface else None)
        out[i] = _layer_mean(lambda z: sum(layer.irradiances(z)[:2]), layer_depth(float(a[i]), float(b[i]), conditions),
                             float(a[i] + b[i]))
    return out


def kd_four_flux(a: ArrayLike, b: ArrayLike, b_w: ArrayLike, conditions: KdConditions = KdConditions()) -> NDArray:
    """K̄_d [m⁻¹] of the four-flux model with coefficients from the phase function and the sky (issue 19)."""
    from .fourflux import four_flux  # noqa: PLC0415
    from .streams import sunlit_coefficients  # noqa: PLC0415

    a, b, b_w = (np.atleast_1d(np.asarray(v, dtype=float)) for v in (a, b, b_w))
    mu, p = hydrolight_phase(b, b_w, conditions.water_rayleigh)
    _, sun, sky = _surface(conditions)
    out = np.empty(a.size)
    for i in range(a.size):
        coefficients = sunlit_coefficients(a[i:i + 1], b[i:i + 1], mu, p[i:i + 1], sun, sky,
                                           conditions.sun_zenith_deg, conditions.n_water)
        out[i] = _layer_mean(
            lambda z, i=i, coefficients=coefficients: four_flux(
                a[i:i + 1], coefficients.b_bd, sun, sky, conditions.sun_zenith_deg, np.inf, 0.0, z, b=b[i:i + 1],
                n_water=conditions.n_water, coefficients=coefficients, internal_reflection=True).E_d[0],
            layer_depth(float(a[i]), float(b[i]), conditions), float(a[i] + b[i]))
    return out


def kd_four_flux_fixed(a: ArrayLike, b: ArrayLike, b_w: ArrayLike, conditions: KdConditions = KdConditions()) -> NDArray:
    """K̄_d [m⁻¹] of the four-flux model's fixed closure (μ_d = 0.83, μ_u = 0.40; before issue 19), with the
    phase function's b_b = b_w/2 + 0.0183 (b − b_w) (Petzold's average particle, Mobley 1994)."""
    from .fourflux import four_flux  # noqa: PLC0415
    from .jerlov_types import PETZOLD_PARTICLE_BB_RATIO  # noqa: PLC0415

    a, b, b_w = (np.atleast_1d(np.asarray(v, dtype=float)) for v in (a, b, b_w))
    share = b_w if conditions.water_rayleigh else np.zeros_like(b)
    bb = 0.5 * share + PETZOLD_PARTICLE_BB_RATIO * (b - share)
    _, sun, sky = _surface(conditions)
    out = np.empty(a.size)
    for i in range(a.size):
        out[i] = _layer_mean(
            lambda z, i=i: four_flux(a[i], bb[i], sun, sky, conditions.sun_zenith_deg, np.inf, 0.0, z,
                                     n_water=conditions.n_water).E_d,
            layer_depth(float(a[i]), float(b[i]), conditions), float(a[i] + b[i]))
    return out



def surface_beams(conditions: KdConditions = KdConditions(), sky_nodes: int = 4) -> tuple[NDArray, NDArray]:
    """The sun and the sky as collimated beams above a level sea: (zenith angles in air [deg], weights [-]).

    Each weight is the beam's horizontal irradiance above the water, for 1 in all: the sun's 1 − f; the
    sky's uniform radiance L = f/π over the hemisphere split in rings of equal zenith angle by
    Gauss–Legendre nodes μ_k, weights w_k on [0, 1]: 2π L w_k μ_k = 2 f w_k μ_k. For plane irradiances
    a ring acts as one beam at its zenith angle (azimuth does not matter), so E_d(z) = Σ_k weight_k
    E_d(z; k), E_d(z; k) that of a beam of unit horizontal irradiance from θ_k (Fresnel and refraction
    at the surface included; :func:`oceanrender.render.slab.slab_kd`).
    """
    zeniths = [float(conditions.sun_zenith_deg)]
    weights = [1.0 - conditions.sky_fraction]
    if conditions.sky_fraction > 0:
        x, w = np.polynomial.legendre.leggauss(sky_nodes)
        for m, wk in zip(0.5 * (x + 1.0), 0.5 * w):
            zeniths.append(math.degrees(math.acos(m)))
            weights.append(2.0 * conditions.sky_fraction * wk * m)
    return np.array(zeniths), np.array(weights)
