"""Four-flux model of the light field in a homogeneous water column.

The irradiance in the water is split into fluxes that travel up or down
(Maheu et al. 1984): a collimated downward flux (the refracted sun beam) and
two diffuse fluxes, downward and upward. The fourth flux of the general
model, a collimated upward beam, is identically zero here because the bottom
is Lambertian (it returns all light diffusely) and the water column is
homogeneous. With z the depth (positive downward, z = 0 just below the
surface) and constant inherent optical properties:

    dE_s/dz   = −(a + b_b + b_f)/μ_w · E_s                                     (1)
    dE_dif/dz = −(a + b_b)/μ_d · E_dif + b_b/μ_u · E_u + b_f/μ_w · E_s         (2)
    dE_u/dz   = +(a + b_b)/μ_u · E_u − b_b/μ_d · E_dif − b_b/μ_w · E_s         (3)

E_s is the direct (collimated) downward plane irradiance, E_dif the diffuse
downward and E_u the (diffuse) upward plane irradiance [W m⁻² nm⁻¹]; the total
downward irradiance of ocean optics is E_d = E_s + E_dif. a is the absorption
and b_b the backscattering coefficient [m⁻¹]; μ_w = cos θ_w is the cosine of
the refracted solar zenith angle and μ_d, μ_u are the average cosines of the
diffuse streams (b_b E/μ is the power backscattered per unit volume from a
stream of plane irradiance E). Eqs. (2)–(3) are the two-stream (two-flow)
irradiance equations of Aas (1987) and Mobley (1994), with the direct beam as
a source term. b_f is the forward-scattering coefficient b − b_b that moves
light from the beam into the diffuse downward stream; by default it is 0, i.e.
light scattered forward is kept in the beam (a delta-scaling of the phase
function) and the beam is attenuated by a + b_b only.

Boundary conditions (z = 0⁻ just below a level surface, z = H the bottom):

    E_s(0)   = E_sun cos θ_s (1 − F(θ_s))                                      (4)
    E_dif(0) = E_sky (1 − r̄_aw)  [+ r̄_wa E_u(0) with internal reflection]     (5)
    E_u(H)   = R_b (E_s(H) + E_dif(H))     (Lambertian bottom of albedo R_b)   (6)

F is the Fresnel reflectance and r̄ the hemispherical (uniform-radiance)
Fresnel reflectance of :mod:`oceanrender.optics.fresnel` (air → water
r̄_aw = 0.066, water → air r̄_wa = 0.475). For H = ∞ Eq. (6) is replaced by
boundedness of the solution.

Adding Eqs. (1)–(3) gives Gershun's law d(E_s + E_dif − E_u)/dz =
−a (E_s/μ_w + E_dif/μ_d + E_u/μ_u): without absorption the net irradiance is
constant, and over a white bottom (R_b = 1) it is zero — all light comes back.

Solution. Eq. (1) gives E_s = E_s(0) e^{−k z}, k = (a + b_b + b_f)/μ_w. The
matrix of Eqs. (2)–(3) has real eigenvalues λ₁ ≤ 0 ≤ λ₂ (its determinant
−a(a + 2b_b)/(μ_d μ_u) is ≤ 0); the downward mode has E_u/E_dif = r₁ and the
upward mode E_dif/E_u = r₂ with 0 ≤ r₁, r₂ ≤ 1. The solution is

    E_dif = y₁ + r₂ y₂,   E_u = r₁ y₁ + y₂,
    y₁ = A e^{λ₁ z} + σ₁ (e^{λ₁ z} − e^{−k z})/(λ₁ + k),
    y₂ = B e^{λ₂ (z − H)} − σ₂ e^{−k z}/(k + λ₂),

with σ₁, σ₂ the beam source of Eqs. (2)–(3) in the mode basis. Every
exponential is bounded by 1 on 0 ≤ z ≤ H, so the evaluation is stable for any
optical depth, and (e^{λ₁ z} − e^{−k z})/(λ₁ + k) is evaluated as
e^{max(λ₁, −k) z} (1 − e^{−|λ₁ + k| z})/|λ₁ + k|, which tends to z e^{λ₁ z} at
resonance (the beam decaying at the rate of the diffuse mode). A and B follow
from Eqs. (5)–(6) (a 2 × 2 linear system solved in closed form).

For small u = b_b/(a + b_b) and deep water the reflectance R(0⁻) = E_u/E_d
tends to μ_u/(μ_u + μ_d) · u for diffuse light and μ_u/(μ_u + μ_w) · u for the
beam (0.325 u and 0.286 u with the defaults and the sun at the zenith), to be
compared with 0.33 u of Morel & Prieur (1977).

Limitations: the average cosines are fixed. Without absorption and with
μ_d ≠ μ_u, the isotropic field E_dif = E_u is not a steady state of Eqs.
(2)–(3), and over a white bottom both streams grow with depth as
e^{b_b (1/μ_u − 1/μ_d) z} at zero net flux — energy is still conserved, but the
levels are an artefact; natural waters have a > 0. Light reflected by the
bottom is attenuated by ≈ (a + b_b)/μ_u on its way up, faster than the
≈ K_d of Maritorena et al.'s (1994) Monte Carlo fit, so the bottom signal of
shallow water is weaker than theirs (see the tests for the numbers).

Units: irradiances W m⁻² nm⁻¹ (any spectral irradiance unit works; the model is
linear), coefficients m⁻¹, depths m (positive downward), angles degrees,
radiances W m⁻² sr⁻¹ nm⁻¹.

References
----------
.. [1] Maheu, B., Letoulouzan, J. N. & Gouesbet, G. (1984). Four-flux models
   to solve the scattering transfer equation in terms of Lorenz–Mie
   parameters. *Appl. Opt.* 23(19), 3353–3362. doi:10.1364/AO.23.003353
.. [2] Aas, E. (1987). Two-stream irradiance model for deep waters.
   *Appl. Opt.* 26(11), 2095–2101. doi:10.1364/AO.26.002095
.. [3] Mobley, C. D. (1994). *Light and Water: Radiative Transfer in Natural
   Waters*. Academic Press (two-flow irradiance equations; Gershun's law).
.. [4] Gordon, H. R., Brown, O. B., Evans, R. H., Brown, J. W., Smith, R. C.,
   Baker, K. S. & Clark, D. K. (1988). A semianalytic radiance model of ocean
   color. *J. Geophys. Res.* 93(D9), 10909–10924. doi:10.1029/JD093iD09p10909
.. [5] Morel, A. & Prieur, L. (1977). Analysis of variations in ocean color.
   *Limnol. Oceanogr.* 22(4), 709–722. doi:10.4319/lo.1977.22.4.0709
.. [6] Maritorena, S., Morel, A. & Gentili, B. (1994). Diffuse reflectance of
   oceanic shallow waters: influence of water depth and bottom albedo.
   *Limnol. Oceanogr.* 39(7), 1689–1703. doi:10.4319/lo.1994.39.7.1689
.. [7] Gordon, H. R. (1989). Can the Lambert–Beer law be applied to the
   diffuse attenuation coefficient of ocean water? *Limnol. Oceanogr.* 34(8),
   1389–1409. doi:10.4319/lo.1989.34.8.1389
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .fresnel import N_AIR, N_WATER, diffuse_reflectance_Fresnel, reflectance_Fresnel, refracted_cosine
from .streams import StreamCoefficients

__all__ = [
    "MU_D",
    "MU_U",
    "Q_LAMBERTIAN",
    "FourFluxResult",
    "four_flux",
]

MU_D: float = 0.83
"""Default average cosine of the diffuse downward stream μ_d [-].

(1 + cos θ_c)/2 = 0.83: the average cosine of a uniform sky refracted through a
level surface (all its light lies within the 48.6° Snell cone; 0.838 with the
Fresnel transmittance as weight), and within the 0.75–0.9 found near the
surface of clear oceanic water.
"""

MU_U: float = 0.40
"""Default average cosine of the diffuse upward stream μ_u [-].

A typical upwelling average cosine of oceanic water (0.35–0.5). With
:data:`MU_D` it gives the deep-water reflectance R ≈ μ_u/(μ_u + μ_d) ·
b_b/(a + b_b) = 0.325 u for diffuse light, Morel & Prieur's (1977) 0.33 u.
"""

Q_LAMBERTIAN: float = np.pi
"""Q = E_u/L_u of a Lambertian (isotropic) upwelling radiance field [sr]."""


@dataclass(frozen=True)
class FourFluxResult:
    """Irradiance field of :func:`four_flux`.

    Arrays marked (..., Z) have the broadcast shape of the spectral inputs
    followed by the depth axis; (...) arrays have the spectral shape only.
    Values below the bottom (z > H) are NaN.

    Attributes
    ----------
    z : ndarray (Z,)
        Depths [m], positive downward, 0 just below the surface.
    E_direct : ndarray (..., Z)
        Direct (collimated, refracted sun) downward plane irradiance E_s(z)
        [W m⁻² nm⁻¹].
    E_diffuse : ndarray (..., Z)
        Diffuse downward plane irradiance E_dif(z) [W m⁻² nm⁻¹].
    E_u : ndarray (..., Z)
        Diffuse upward plane irradiance E_u(z) [W m⁻² nm⁻¹].
    E_surface : ndarray (...)
        Total downward irradiance just below the surface, E_d(0⁻) = E_s(0) + E_dif(0)
        [W m⁻² nm⁻¹].
    E_upwell : ndarray (...)
        Upwelling irradiance just below the surface E_u(0⁻) [W m⁻² nm⁻¹].
    E_bottom : ndarray (...)
        Total downward irradiance on the bottom, E_s(H) + E_dif(H); 0 for
        H = ∞ [W m⁻² nm⁻¹].
    K_d : ndarray (...)
        Diffuse attenuation coefficient of the total downward irradiance
        averaged over the first optical depth, 1/z₁ with
        E_d(z₁) = E_d(0)/e (Gordon 1989); where the bottom (or a
        non-absorbing column) is reached first, the column average
        −ln(E_d(H)/E_d(0))/H [m⁻¹].
    R : ndarray (...)
        Irradiance reflectance just below the surface R(0⁻) = E_u(0)/E_d(0) [-].
    L_u : ndarray (...)
        Upwelling radiance just below the surface, E_u(0)/Q
        [W m⁻² sr⁻¹ nm⁻¹].
    B_refr : ndarray (...)
        Radiance refracted out of the water towards the viewer,
        L_u (1 − F(θ_v))/n_w² [W m⁻² sr⁻¹ nm⁻¹].
    Q : float or ndarray (...)
        The Q factor E_u/L_u used [sr].
    """

    z: NDArray[np.float64]
    E_direct: NDArray[np.float64]
    E_diffuse: NDArray[np.float64]
    E_u: NDArray[np.float64]
    E_surface: NDArray[np.float64]
    E_upwell: NDArray[np.float64]
    E_bottom: NDArray[np.float64]
    K_d: NDArray[np.float64]
    R: NDArray[np.float64]
    L_u: NDArray[np.float64]
    B_refr: NDArray[np.float64]
    Q: float | NDArray[np.float64]

    @property
    def E_d(self) -> NDArray[np.float64]:
        """Total downward plane irradiance E_d = E_s + E_dif (..., Z) [W m⁻² nm⁻¹]."""
        return self.E_direct + self.E_diffuse

    @property
    def E_net(self) -> NDArray[np.float64]:
        """Net downward irradiance E_d − E_u = E_s + E_dif − E_u (..., Z) [W m⁻² nm⁻¹]."""
        return self.E_direct + self.E_diffuse - self.E_u

    @property
    def r_rs(self) -> NDArray[np.float64]:
        """Subsurface remote-sensing reflectance r_rs = L_u(0⁻)/E_d(0⁻) = R/Q (...) [sr⁻¹]."""
        return _ratio(self.L_u, self.E_surface)


def _ratio(num: NDArray[np.float64], den: NDArray[np.float64]) -> NDArray[np.float64]:
    """num/den, NaN where den = 0 (no light: the ratio is undefined)."""
    return np.divide(num, den, out=np.full(np.broadcast(num, den).shape, np.nan), where=den != 0)


def _safe_div(num: NDArray[np.float64], den: NDArray[np.float64], fill: float = 0.0) -> NDArray[np.float64]:
    """num/den with ``fill`` where den = 0 (the limits used here are documented at each call)."""
    return np.divide(num, den, out=np.full(np.broadcast(num, den).shape, fill), where=den != 0)


def _rise(d: NDArray[np.float64], z: NDArray[np.float64]) -> NDArray[np.float64]:
    """(1 − e^{−d z})/d for d ≥ 0, continuous at d = 0 (where it equals z)."""
    return np.where(d > 0, -np.expm1(-d * z) / np.where(d > 0, d, 1.0), z)


@dataclass(frozen=True)
class _Solution:
    """Constants of the analytic solution, each of shape (..., 1)."""

    S0: NDArray[np.float64]  # E_s(0) [W m⁻² nm⁻¹]
    k: NDArray[np.float64]  # beam attenuation along the vertical [m⁻¹]
    lam1: NDArray[np.float64]  # downward mode eigenvalue ≤ 0 [m⁻¹]
    lam2: NDArray[np.float64]  # upward mode eigenvalue ≥ 0 [m⁻¹]
    r1: NDArray[np.float64]
    r2: NDArray[np.float64]
    A: NDArray[np.float64]
    B: NDArray[np.float64]
    sigma1: NDArray[np.float64]
    P2: NDArray[np.float64]
    H: NDArray[np.float64]  # bottom depth; 0 where infinite (B = 0 there)
    finite: NDArray[np.bool_]
    alpha_d: NDArray[np.float64]
    beta_u: NDArray[np.float64]
    source_d: NDArray[np.float64]  # b_f/μ_w

    def fields(self, z: NDArray[np.float64]) -> tuple[NDArray, NDArray, NDArray]:
        """E_s, E_dif, E_u at depths z (broadcast against the constants)."""
        beam = np.exp(-self.k * z)
        d = np.abs(self.lam1 + self.k)
        m = np.maximum(self.lam1, -self.k)
        y1 = self.A * np.exp(self.lam1 * z) + self.sigma1 * np.exp(m * z) * _rise(d, z)
        # Upward mode, anchored at the bottom; absent (exp(−∞) = 0) for H = ∞.
        up_exp = np.where(self.finite, self.lam2 * np.minimum(z - self.H, 0.0), -np.inf)
        y2 = self.B * np.exp(up_exp) + self.P2 * beam
        return self.S0 * beam, y1 + self.r2 * y2, self.r1 * y1 + y2

    def downward_slope(self, E_s, E_dif, E_u) -> NDArray[np.float64]:
        """dE_d/dz = d(E_s + E_dif)/dz from Eqs. (1)–(2) [W m⁻³ nm⁻¹]."""
        return -self.k * E_s - self.alpha_d * E_dif + self.beta_u * E_u + self.source_d * E_s


def _first_optical_depth_K(
    sol: _Solution, E0: NDArray[np.float64], E_H: NDArray[np.float64], max_iter: int = 40
) -> NDArray[np.float64]:
    """K_d averaged over the first optical depth: 1/z₁ with E_d(z₁) = E_d(0)/e.

    Newton iteration on g(z) = ln E(z) − ln E(0) + 1, which is nearly linear in
    z for a sum of decaying exponentials (4–6 steps), safeguarded by bisection
    in the bracket [0, H]. Where E(H) > E(0)/e (shallow bottom, or a column
    without absorption) the column average −ln(E(H)/E(0))/H is returned.
    """
    shape = E0.shape
    finite = sol.finite[..., 0]
    H = np.where(finite, sol.H[..., 0], np.inf)
    lit = E0 > 0
    E0s = np.where(lit, E0, 1.0)
    with np.errstate(divide="ignore", invalid="ignore"):
        K_column = -np.log(E_H / E0s) / H
    reachable = lit & ~(finite & (E_H > E0s / np.e))
    Es, Ed, Eu = sol.fields(np.zeros(shape + (1,)))
    K0 = -sol.downward_slope(Es, Ed, Eu)[..., 0] / E0s
    z = np.where(K0 > 0, 1.0 / np.where(K0 > 0, K0, 1.0), 1.0)
    lo, hi = np.zeros(shape), H.copy()
    z = np.where(z < hi, z, 0.5 * (lo + hi))
    active = reachable.copy()
    for _ in range(max_iter):
        if not np.any(active):
            break
        Es, Ed, Eu = sol.fields(z[..., None])
        E = (Es + Ed)[..., 0]
        dE = sol.downward_slope(Es, Ed, Eu)[..., 0]
        with np.errstate(divide="ignore", invalid="ignore"):
            g = np.log(E / E0s) + 1.0
            step = g * E / dE
        lo = np.where(g > 0, z, lo)
        hi = np.where(g <= 0, z, hi)
        z_new = z - step
        bad = ~np.isfinite(z_new) | (z_new < lo) | (z_new > hi) | ~(dE < 0)
        z_new = np.where(bad, np.where(np.isfinite(hi), 0.5 * (lo + hi), 2.0 * z), z_new)
        z = np.where(active, z_new, z)
        active &= ~(np.abs(step) <= 1e-12 * z)
    # NOTE: without absorption and with H = ∞ the total downward irradiance
    # can level off above E(0)/e; after max_iter doublings z ~ 2^40/K0 and
    # 1/z ≈ 0 is the right answer.
    K = np.where(reachable, 1.0 / z, K_column)
    return np.where(lit, K, np.nan)


def four_flux(
    a: ArrayLike,
    bb: ArrayLike,
    sun_irradiance: ArrayLike,
    sky_irradiance: ArrayLike,
    sun_zenith: float,
    depth: ArrayLike,
    bottom_albedo: ArrayLike,
    z: ArrayLike,
    *,
    b: ArrayLike | None = None,
    mu_d: float = MU_D,
    mu_u: float = MU_U,
    n_water: float = N_WATER,
    view_zenith: float = 0.0,
    Q: float = Q_LAMBERTIAN,
    internal_reflection: bool = False,
    coefficients: StreamCoefficients | None = None,
) -> FourFluxResult:
    """Analytic four-flux irradiance field of a homogeneous water column.

    Solves Eqs. (1)–(6) of this module exactly for constant coefficients,
    vectorised over wavelengths (any broadcastable spectral shape) and depths.

    Parameters
    ----------
    a : array_like (...)
        Absorption coefficient a(λ) ≥ 0 [m⁻¹].
    bb : array_like (...)
        Backscattering coefficient b_b(λ) ≥ 0 [m⁻¹].
    sun_irradiance : array_like (...)
        Direct solar irradiance above the surface on a plane normal to the
        beam (direct normal irradiance) [W m⁻² nm⁻¹].
    sky_irradiance : array_like (...)
        Diffuse sky irradiance above the surface on a horizontal plane, taken
        as uniform radiance [W m⁻² nm⁻¹].
    sun_zenith : float
        Solar zenith angle in air, 0–90 [deg].
    depth : array_like (...)
        Bottom depth H > 0, ``np.inf`` for optically deep water [m].
    bottom_albedo : array_like (...)
        Irradiance reflectance R_b of the Lambertian bottom, in [0, 1] [-];
        ignored where H = ∞.
    z : array_like (Z,)
        Depths at which to evaluate the field, ≥ 0 [m]. Depths below the
        bottom give NaN.
    b : array_like (...), optional
        Total scattering coefficient b ≥ b_b [m⁻¹]. When given, the beam is
        attenuated by c = a + b and its forward-scattered part b − b_b feeds
        the diffuse downward stream; when omitted (default) forward-scattered
        light stays in the beam (attenuation a + b_b).
    mu_d, mu_u : float
        Average cosines of the diffuse downward and upward streams, in (0, 1]
        [-]. Default :data:`MU_D`, :data:`MU_U`.
    n_water : float
        Refractive index of the water [-].
    view_zenith : float
        Zenith angle in air of the direction from the surface to the viewer,
        0–90, for ``B_refr`` [deg].
    Q : float
        E_u/L_u of the upwelling field just below the surface [sr]; π for a
        Lambertian field (the default), 3–5 in real oceans.
    internal_reflection : bool
        If True, the surface reflects r̄_wa ≈ 0.475 of E_u(0) back down
        (Eq. 5 with the bracketed term); default False (the plain Fresnel
        transmission of sun and sky only).
    coefficients : StreamCoefficients, optional
        Coefficients of Eqs. (1)–(3) per wavelength derived from the phase function
        and the refracted sun (:func:`oceanrender.optics.streams.stream_coefficients`,
        issue 19); they replace ``mu_d``, ``mu_u`` and the b_b/b_f of every stream,
        and, where they carry them, ``Q`` and the r̄_wa of internal reflection.
        Default None: the fixed closure above.

    Returns
    -------
    FourFluxResult
        The fields E_s, E_dif, E_u (..., Z) and the per-wavelength E_upwell,
        E_bottom, K_d, R(0⁻), L_u and B_refr (...).

    Raises
    ------
    ValueError
        For negative or non-finite coefficients or irradiances, albedo outside
        [0, 1], H ≤ 0, negative z, angles outside [0, 90]°, average cosines
        outside (0, 1], b < b_b, or the degenerate conservative case
        a = 0 < b_b with μ_d = μ_u (both diffuse modes coincide and the
        solution is linear in z; use a > 0 or μ_d ≠ μ_u).

    Notes
    -----
    * ``sun_irradiance`` is the normal-incidence value: the power crossing a
      horizontal unit area is E_sun cos θ_s, of which 1 − F(θ_s) enters the
      water (Eq. 4). The refracted beam keeps that power per horizontal area,
      so its plane irradiance below the surface carries no extra cos θ_w.
    * The model is linear in the irradiances: spectral units pass through.
    * ``B_refr`` assumes a Lambertian (or Q-scaled) upwelling radiance and the
      n² law of radiance at refraction. If the renderer mixes
      B = F_c B_refl + (1 − F_c) B_refr' itself, use ``L_u / n_water**2`` as
      B_refr' so that (1 − F) is not applied twice.
    * K_d follows Gordon's (1989) average over the first optical depth; it
      depends on the sun/sky ratio through the different vertical paths of
      the beam (μ_w) and of the diffuse light (μ_d).
    * Near the degenerate case (a ≪ b_b with μ_d ≈ μ_u) the mode basis is
      ill-conditioned: relative error ≈ 1e-16 · (b_b/a)^½.

    References
    ----------
    See the module references [1]–[7]: the fluxes of [1], the two-stream
    equations of [2], [3] with the boundary conditions (4)–(6); R(0⁻) is
    compared with [4], [5] and the bottom effect with [6] in the tests; K_d
    follows [7].

    Examples
    --------
    >>> import numpy as np
    >>> res = four_flux(a=[0.02, 0.4], bb=[0.003, 0.001], sun_irradiance=1.5,
    ...                 sky_irradiance=0.3, sun_zenith=30.0, depth=np.inf,
    ...                 bottom_albedo=0.0, z=np.linspace(0, 50, 6))
    >>> res.E_d.shape, res.R.shape
    ((2, 6), (2,))
    """
    # -- validate everything before any work ----------------------------------
    z = np.asarray(z, dtype=float)
    if z.ndim != 1:
        raise ValueError("z must be a 1-D array of depths [m]")
    if np.any(~np.isfinite(z)) or np.any(z < 0):
        raise ValueError("z must be finite depths >= 0 [m] (positive downward)")
    bf_given = b is not None
    arrays = np.broadcast_arrays(
        *(np.asarray(v, dtype=float) for v in (a, bb, sun_irradiance, sky_irradiance, depth, bottom_albedo,
                                                 b if bf_given else 0.0))
    )
    a, bb, E_sun, E_sky, H, R_b, b_tot = arrays
    for name, v in (("a", a), ("bb", bb), ("sun_irradiance", E_sun), ("sky_irradiance", E_sky)):
        if np.any(~np.isfinite(v)) or np.any(v < 0):
            raise ValueError(f"{name} must be finite and >= 0")
    if np.any(np.isnan(H)) or np.any(H <= 0):
        raise ValueError("depth must be > 0 [m] (np.inf for optically deep water)")
    if np.any(~((R_b >= 0) & (R_b <= 1))):
        raise ValueError("bottom_albedo must lie in [0, 1]")
    if bf_given and (np.any(~np.isfinite(b_tot)) or np.any(b_tot < bb)):
        raise ValueError("b must be finite and >= bb (total scattering includes backscattering)")
    for name, v in (("sun_zenith", sun_zenith), ("view_zenith", view_zenith)):
        if not 0.0 <= float(v) <= 90.0:
            raise ValueError(f"{name} must lie in [0, 90] degrees")
    for name, v in (("mu_d", mu_d), ("mu_u", mu_u)):
        if not 0.0 < float(v) <= 1.0:
            raise ValueError(f"{name} must lie in (0, 1]")
    if not (float(n_water) > 0 and np.all(np.asarray(Q) > 0)):
        raise ValueError("n_water and Q must be positive")
    if np.any((a == 0) & (bb > 0)) and mu_d == mu_u:
        raise ValueError(
            "a = 0 < bb with mu_d == mu_u is the degenerate conservative two-stream case "
            "(coincident modes, solution linear in z); use a > 0 or mu_d != mu_u"
        )

    # -- surface: Fresnel transmission of sun and sky, Eqs. (4)–(5) -----------
    mu_s = np.cos(np.radians(float(sun_zenith)))
    mu_w = float(refracted_cosine(mu_s, N_AIR, n_water))
    S0 = E_sun * mu_s * (1.0 - reflectance_Fresnel(mu_s, N_AIR, n_water))  # Eq. (4)
    D0 = E_sky * (1.0 - diffuse_reflectance_Fresnel(N_AIR, n_water))  # Eq. (5)
    rho = float(diffuse_reflectance_Fresnel(n_water, N_AIR)) if internal_reflection else 0.0
    if internal_reflection and coefficients is not None and coefficients.r_wa is not None:
        rho = np.asarray(coefficients.r_wa, dtype=float)  # Fresnel over the actual upwelling (streams)
    if coefficients is not None and coefficients.Q is not None:
        Q = np.asarray(coefficients.Q, dtype=float)

    # -- coefficients of Eqs. (1)–(3) ------------------------------------------
    if coefficients is None:  # the fixed closure: stream cosines μ_d, μ_u, b_b for every stream
        b_f = b_tot - bb if bf_given else np.zeros_like(a)
        c_beam, b_fs, b_bs = a + bb + b_f, b_f, bb
        m_d, m_u, bb_d, bb_u = mu_d, mu_u, bb, bb
    else:  # from the phase function and μ_w (oceanrender.optics.streams)
        co = coefficients
        fields = (co.c_beam, co.b_fs, co.b_bs, co.mu_d, co.mu_u, co.b_bd, co.b_bu)
        if np.broadcast_shapes(a.shape, *(np.shape(v) for v in fields)) != a.shape:
            raise ValueError("coefficients must broadcast to the shape of the spectral inputs")
        c_beam, b_fs, b_bs, m_d, m_u, bb_d, bb_u = (np.broadcast_to(np.asarray(v, dtype=float), a.shape)
                                                    for v in fields)
        b_f = b_fs
    k = c_beam / mu_w  # Eq. (1)
    alpha_d, alpha_u = (a + bb_d) / m_d, (a + bb_u) / m_u  # Eqs. (2)–(3)
    beta_d, beta_u = bb_d / m_d, bb_u / m_u  # Eqs. (2)–(3)
    s_d, s_u = S0 * b_fs / mu_w, -S0 * b_bs / mu_w  # beam source of Eqs. (2)–(3) at z = 0

    # Eigenvalues of [[−α_d, β_u], [−β_d, α_u]]: λ = t ± q, t = (α_u − α_d)/2,
    # q² = t² + a(a + b_bd + b_bu)/(μ_d μ_u); the root of smaller magnitude via the
    # product λ₁ λ₂ = −a(a + b_bd + b_bu)/(μ_d μ_u) to avoid cancellation.
    t = 0.5 * (alpha_u - alpha_d)
    neg_det = a * (a + bb_d + bb_u) / (m_d * m_u)
    q = np.sqrt(t * t + neg_det)
    lam2 = np.where(t >= 0, t + q, _safe_div(neg_det, q - t))
    lam1 = -np.where(t <= 0, q - t, _safe_div(neg_det, q + t))
    den = 0.5 * (alpha_u + alpha_d) + q
    # Mode ratios r₁ = E_u/E_dif (downward mode), r₂ = E_dif/E_u (upward mode);
    # 0 for a = b_b = 0, where any basis is an eigenbasis.
    r1, r2 = _safe_div(beta_d, den), _safe_div(beta_u, den)
    one_m_r1 = _safe_div(a / m_d + lam2, den, fill=1.0)  # 1 − r₁ without cancellation
    one_m_r2 = _safe_div(a / m_u - lam1, den, fill=1.0)  # 1 − r₂ without cancellation
    one_m_r1r2 = one_m_r1 + r1 * one_m_r2

    # Beam source in the mode basis and the particular solution of mode 2.
    sigma1 = (s_d - r2 * s_u) / one_m_r1r2
    sigma2 = (s_u - r1 * s_d) / one_m_r1r2
    P2 = -_safe_div(sigma2, k + lam2)  # k + λ₂ = 0 only without any interaction (σ₂ = 0)

    # -- boundary conditions, Eqs. (5)–(6) --------------------------------------
    # Surface, Eq. (5): E_dif(0) − ρ E_u(0) = D0  ⇒  A = D0' − r₂' y₂(0).
    D0p = D0 / (1.0 - rho * r1)
    r2p = (r2 - rho) / (1.0 - rho * r1)
    finite = np.isfinite(H)
    Hf = np.where(finite, H, 0.0)
    e1, e2, eK = np.exp(lam1 * Hf), np.exp(-lam2 * Hf), np.exp(-k * Hf)
    eD = np.exp((lam1 - lam2) * Hf)
    Y1 = sigma1 * np.exp(np.maximum(lam1, -k) * Hf) * _rise(np.abs(lam1 + k), Hf)
    one_m_Rr2 = (1.0 - R_b) + R_b * one_m_r2
    # Bottom, Eq. (6): X₂ (1 − R r₂) = R E_s(H) + (R − r₁) X₁, X₁ = y₁(H), X₂ = y₂(H).
    Dn = one_m_Rr2 + (R_b - r1) * r2p * eD
    X2 = (R_b * S0 * eK + (R_b - r1) * ((D0p - r2p * P2) * e1 + r2p * eD * P2 * eK + Y1)) / Dn
    B = np.where(finite, X2 - P2 * eK, 0.0)
    A = D0p - r2p * (B * e2 + P2)

    col = (..., None)
    sol = _Solution(
        S0=S0[col], k=k[col], lam1=lam1[col], lam2=lam2[col], r1=r1[col], r2=r2[col], A=A[col], B=B[col],
        sigma1=sigma1[col], P2=P2[col], H=Hf[col], finite=finite[col], alpha_d=alpha_d[col],
        beta_u=beta_u[col], source_d=(b_f / mu_w)[col],
    )
    E_s, E_dif, E_u = sol.fields(z)
    below = finite[col] & (z > H[col])
    E_s, E_dif, E_u = (np.where(below, np.nan, f) for f in (E_s, E_dif, E_u))

    # -- per-wavelength outputs --------------------------------------------------
    E_s0, E_dif0, E_u0 = (f[..., 0] for f in sol.fields(np.zeros(1)))
    E_surface = E_s0 + E_dif0
    E_sH, E_difH, _ = (f[..., 0] for f in sol.fields(Hf[col]))
    E_bottom = np.where(finite, E_sH + E_difH, 0.0)
    L_u = E_u0 / Q
    mu_v = np.cos(np.radians(float(view_zenith)))
    T_view = 1.0 - reflectance_Fresnel(mu_v, N_AIR, n_water)  # = 1 − F_wa(θ_w) by reciprocity
    return FourFluxResult(
        z=z,
        E_direct=E_s,
        E_diffuse=E_dif,
        E_u=E_u,
        E_surface=E_surface,
        E_upwell=E_u0,
        E_bottom=E_bottom,
        K_d=_first_optical_depth_K(sol, E_surface, E_bottom),
        R=_ratio(E_u0, E_surface),
        L_u=L_u,
        B_refr=L_u * T_view / n_water**2,
        Q=Q if np.ndim(Q) else float(Q),
    )
