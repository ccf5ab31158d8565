"""Four-flux coefficients from the phase function and the refracted sun: discrete ordinates, δ-M.

The four-flux model (:mod:`oceanrender.optics.fourflux`) closes the radiative transfer
equation with constant stream coefficients. Fixed constants (μ_d = 0.83, μ_u = 0.40,
b_b for every stream) put its K_d up to 2× off in scattering water (issue 19). Here
the coefficients are derived, per wavelength, from the exact transport of a deep
homogeneous layer with the given a, b, phase function and beam angle:

1. **Legendre moments** χ_l = 2π ∫ p(μ) P_l(μ) dμ of the tabulated phase function
   (piecewise linear in μ, integrated with 8 Gauss points per interval), and the
   **δ-M truncation** of Wiscombe (1977): f = χ_{2N}, χ'_l = (χ_l − f)/(1 − f),
   b' = (1 − f) b, c' = a + b' (Eqs. 7–9 of [1]). The truncated forward peak (the light
   scattered by less than a few degrees) stays in the beam.
2. **Discrete ordinates** (Chandrasekhar 1960; Stamnes et al. 1988) for the azimuthal
   mean of the radiance, which is all that plane irradiances need: N double-Gauss
   directions per hemisphere (Sykes 1951), p₀(μ, μ') = (1/4π) Σ_{l<2N} (2l+1) χ'_l
   P_l(μ) P_l(μ'), the beam as a source b' F p₀(μ, μ_w) e^{−c' z/μ_w}. The eigenvalues of
   the homogeneous system come in pairs ±κ_j; the smallest decaying one is the
   asymptotic K_∞ and its eigenvector gives R_∞ = E_u/E_d of the asymptotic regime
   (Preisendorfer 1959; Mobley 1994, § 9.5). A deep layer with no downward diffuse light
   at the top is solved exactly (an N × N system for the mode amplitudes).
3. **Coefficients.** The diffuse block of Eqs. (2)–(3) of the four-flux model is taken
   so that both of its modes are the exact asymptotic ones: decaying downwards with
   K_∞ and E_u/E_dif = R_∞, and (its mirror image, the mode a bottom excites) decaying
   upwards with K_∞ and E_dif/E_u = R_∞. This fixes it completely (``stream_block``):
   equal stream cosines μ̄ = a (1 + R_∞)/(K_∞ (1 − R_∞)) and stream backscattering
   b_b,s = 2 R_∞ K_∞ μ̄ /(1 − R_∞²). The beam is attenuated by c' (Eq. 1 with δ-M), and
   its two source coefficients (forward into E_dif, backward into E_u) are solved for
   so that the four-flux solution of the deep layer has the exact E_u(0⁻) and the exact
   E_d at the first optical depth z₁ (``_beam_sources``).

So R(0⁻) and K_d over the first optical depth of a sunlit deep layer are those of the
transport equation, and so is K_d far down (K_∞); between z₁ and the asymptotic regime
the two exponentials of the closure stand in for the N of the exact solution (K_d over
0–10 m within 3.8 % of the discrete ordinates on the grid of docs/optics.md).

Notes
-----
The two beam sources are *effective* coefficients: they absorb the closure's error near
the surface (where the scattered light is still near the beam's direction, not in the
asymptotic distribution), so b_fs + b_bs need not equal b' and b_bs can be slightly
negative in very forward-scattering water (down to −5 % of b' B(μ_w) on the grid).
Gershun's law holds for the diffuse block, not exactly for the beam's sources.
The fit is for a sunlit deep layer under an index-matched top; sky light, internal
reflection and a bottom use the same coefficients (the asymptotic block makes a bottom's
upward mode exact too).

Units: coefficients m⁻¹, depths m, cosines and fractions [-], irradiances per unit
normal irradiance of the beam [-].

References
----------
.. [1] Wiscombe, W. J. (1977). The delta-M method: rapid yet accurate radiative flux
   calculations for strongly asymmetric phase functions. *J. Atmos. Sci.* 34(9),
   1408–1422. doi:10.1175/1520-0469(1977)034<1408:TDMRYA>2.0.CO;2
.. [2] Stamnes, K., Tsay, S.-C., Wiscombe, W. & Jayaweera, K. (1988). Numerically stable
   algorithm for discrete-ordinate-method radiative transfer in multiple scattering and
   emitting layered media. *Appl. Opt.* 27(12), 2502–2509. doi:10.1364/AO.27.002502
.. [3] Chandrasekhar, S. (1960). *Radiative Transfer*. Dover (discrete ordinates, ch. II–III).
.. [4] Sykes, J. B. (1951). Approximate integration of the equation of transfer.
   *Mon. Not. R. Astron. Soc.* 111, 377–386 (double-Gauss quadrature).
.. [5] Preisendorfer, R. W. (1959). Theoretical proof of the existence of characteristic
   diffuse light in natural waters. *J. Mar. Res.* 18, 1–9.
.. [6] Mobley, C. D. (1994). *Light and Water*. Academic Press (§ 9.5, asymptotic radiance).
.. [7] Nakajima, T. & Tanaka, M. (1988). Algorithms for radiative intensity calculations in
   moderately thick atmospheres using a truncation approximation. *J. Quant. Spectrosc.
   Radiat. Transfer* 40(1), 51–69. doi:10.1016/0022-4073(88)90031-3
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = [
    "N_STREAMS",
    "DeepLayer",
    "StreamCoefficients",
    "deep_layer",
    "first_optical_depth",
    "legendre_moments",
    "stream_block",
    "stream_coefficients",
    "sunlit_coefficients",
    "surface_light",
]

N_STREAMS: int = 32
"""Discrete-ordinate directions per hemisphere (2N = 64 Legendre moments kept, χ_64 truncated)."""


def _legendre(x: NDArray, count: int) -> NDArray:
    """P_0..P_{count−1} at x, shape (count, x.size), by Bonnet's recurrence."""
    x = np.asarray(x, dtype=float).ravel()
    out = np.empty((count, x.size))
    out[0] = 1.0
    if count > 1:
        out[1] = x
    for n in range(1, count - 1):
        out[n + 1] = ((2 * n + 1) * x * out[n] - n * out[n - 1]) / (n + 1)
    return out


def legendre_moments(mu: ArrayLike, p: ArrayLike, count: int) -> NDArray[np.float64]:
    """χ_l = 2π ∫ p(μ) P_l(μ) dμ, l = 0..count−1, of a phase function piecewise linear in μ [-].

    Parameters
    ----------
    mu : array_like (M,)       Increasing cosines from −1 to 1 [-].
    p : array_like (..., M)    Phase function values [sr⁻¹].
    count : int                Number of moments.

    Returns
    -------
    ndarray (..., count)   The moments divided by χ_0 (so χ_0 = 1: the table's own normalisation).
    """
    mu = np.asarray(mu, dtype=float)
    p = np.asarray(p, dtype=float)
    nodes, weights = np.polynomial.legendre.leggauss(8)
    lo, hi = mu[:-1], mu[1:]
    t = 0.5 * (nodes[None, :] + 1.0)  # (1, 8) in [0, 1]
    x = lo[:, None] + (hi - lo)[:, None] * t  # (M−1, 8)
    w = (0.5 * weights[None, :] * (hi - lo)[:, None]).ravel()
    # linear interpolation weights of the two end values at the Gauss points
    p_x = p[..., :-1, None] * (1.0 - t) + p[..., 1:, None] * t  # (..., M−1, 8)
    p_x = p_x.reshape(p.shape[:-1] + (-1,))
    P = _legendre(x.ravel(), count)  # (count, (M−1)·8)
    moments = 2.0 * np.pi * (p_x * w) @ P.T
    return moments / moments[..., :1]


def _double_gauss(n: int) -> tuple[NDArray, NDArray]:
    """Nodes and weights of n-point Gauss–Legendre on (0, 1) (Sykes 1951)."""
    x, w = np.polynomial.legendre.leggauss(n)
    return 0.5 * (x + 1.0), 0.5 * w


@dataclass(frozen=True)
class DeepLayer:
    """Exact (discrete-ordinate) light field of a deep homogeneous layer under a beam.

    The beam has normal irradiance 1 in the water and travels at cos θ = ``mu_w`` [-]; the
    top is index-matched or a level surface with a uniform sky (:func:`deep_layer`).

    Attributes
    ----------
    K_inf : float        Asymptotic diffuse attenuation K_∞ [m⁻¹].
    R_inf : float        Asymptotic E_u/E_d [-].
    f : float            δ-M truncated forward fraction [-].
    c_scaled : float     c' = a + (1 − f) b [m⁻¹].
    mu_w : float         Beam cosine [-].
    nadir_radiance : float
        Upwelling radiance just below the surface along the vertical [sr⁻¹ per unit normal
        irradiance]: exact from the azimuthal mean, whose other Fourier terms vanish at μ = ±1.
    reflected : float
        Upwelling irradiance the surface reflects back down at z = 0 [-] (0 when index-matched).
    """

    K_inf: float
    R_inf: float
    f: float
    c_scaled: float
    mu_w: float
    nadir_radiance: float
    reflected: float
    _rates: NDArray  # decaying eigenvalues (N,) [m⁻¹], negative
    _down: NDArray  # E_dif of each mode per unit amplitude (N,)
    _up: NDArray  # E_u of each mode per unit amplitude (N,)
    _amp: NDArray  # mode amplitudes (N,)
    _particular: tuple[float, float]  # (E_dif, E_u) of the beam's particular solution per e^{−c' z/μ_w}
    _slowest: int

    def irradiances(self, z: ArrayLike) -> tuple[NDArray, NDArray, NDArray]:
        """(E_s, E_dif, E_u) at depths z [m] (E_s: the δ-M beam, with its truncated peak) [-]."""
        z = np.asarray(z, dtype=float)[..., None]
        beam = np.exp(-self.c_scaled * z[..., 0] / self.mu_w)
        modes = np.exp(self._rates * z) * self._amp
        E_dif = modes @ self._down + self._particular[0] * beam
        E_u = modes @ self._up + self._particular[1] * beam
        return self.mu_w * beam, E_dif, E_u

    @property
    def E_u0(self) -> float:
        """E_u(0⁻) per unit normal irradiance of the beam [-]."""
        return float(self._amp @ self._up + self._particular[1])


def deep_layer(a: float, b: float, moments: ArrayLike, mu_w: float, n: int = N_STREAMS, *,
               n_water: float | None = None, sky: float = 0.0, back_phase: float | None = None) -> DeepLayer:
    """Discrete-ordinate solution of a deep layer (a, b [m⁻¹], phase moments χ_l, beam cosine μ_w).

    ``moments`` needs at least 2n + 1 entries (χ_{2n} is the δ-M truncation, [1] Eq. 7).
    Irradiances are per unit normal irradiance of the beam *in the water*.

    Top boundary: index-matched (no downward diffuse light) by default. With ``n_water`` a
    level water surface: the upwelling is reflected back by Fresnel's F(θ) water → air
    (1 beyond the critical angle), and a sky of uniform radiance whose horizontal
    irradiance above the surface is ``sky`` (per unit in-water beam normal irradiance)
    enters inside the Snell cone as (1 − F) n² L_sky (the n² law of radiance).

    ``back_phase``: the exact phase function p(Θ) [sr⁻¹] at cos Θ = −μ_w (the beam scattered
    straight up). With it the nadir radiance gets the TMS correction of Nakajima & Tanaka
    (1988, Eq. 17): the beam's single scattering of the truncated series, b' p'(Θ) μ_w F /
    (c' (1 + μ_w)), is replaced by the exact b p(Θ) μ_w F/(c (1 + μ_w)). The δ-M series
    misses p at backward angles by up to 15 % for g ≈ 0.95 (irradiances are unaffected).
    """
    from .fresnel import N_AIR, reflectance_Fresnel, refracted_cosine  # noqa: PLC0415

    chi = np.asarray(moments, dtype=float)
    if chi.size < 2 * n + 1:
        raise ValueError(f"deep_layer: need {2 * n + 1} Legendre moments, got {chi.size}")
    if not (a > 0 and b >= 0 and 0 < mu_w <= 1 and sky >= 0):
        raise ValueError("deep_layer: need a > 0, b >= 0, 0 < mu_w <= 1, sky >= 0")
    f = float(chi[2 * n])  # Eq. 7 of [1]
    scaled = (chi[: 2 * n] - f) / (1.0 - f)  # Eq. 8 of [1]
    b_s = (1.0 - f) * b  # Eq. 9 of [1]
    c_s = a + b_s
    x, w = _double_gauss(n)
    mus = np.concatenate([x, -x])  # downward (μ > 0, z down) then upward
    ws = np.concatenate([w, w])
    ell = np.arange(2 * n)
    P = _legendre(mus, 2 * n)  # (2n, 2n): P_l(μ_i)
    kernel = (P.T * ((2 * ell + 1) * scaled)) @ P / (4.0 * np.pi)  # p₀(μ_i, μ_j) [sr⁻¹], addition theorem
    # μ dL/dz = −c' L + b' 2π Σ_j w_j p₀(μ, μ_j) L_j + b' p₀(μ, μ_w) e^{−c' z/μ_w}   (F = 1)
    A = (-c_s * np.eye(2 * n) + b_s * 2.0 * np.pi * kernel * ws[None, :]) / mus[:, None]
    P_w = _legendre(np.array([mu_w]), 2 * n)[:, 0]
    source = b_s * ((P.T * ((2 * ell + 1) * scaled)) @ P_w / (4.0 * np.pi)) / mus
    values, vectors = np.linalg.eig(A)
    values, vectors = values.real, vectors.real
    decaying = np.argsort(values)[:n]  # the n negative eigenvalues
    rates, modes = values[decaying], vectors[:, decaying]
    k_beam = c_s / mu_w
    particular = np.linalg.solve(A + k_beam * np.eye(2 * n), -source)
    # top: L⁺ = ρ L⁻ + L_sky at z = 0, i.e. Σ_k C_k (v_k⁺ − ρ v_k⁻) = L_sky − (Z⁺ − ρ Z⁻)
    rho, sky_in = np.zeros(n), np.zeros(n)
    if n_water is not None:
        rho = reflectance_Fresnel(x, n_water, N_AIR)  # 1 under total internal reflection
        mu_air = refracted_cosine(x, n_water, N_AIR)  # NaN beyond the critical angle
        inside = np.isfinite(mu_air)
        sky_in[inside] = (1.0 - rho[inside]) * n_water**2 * sky / np.pi
    amp = np.linalg.solve(modes[:n] - rho[:, None] * modes[n:], sky_in - (particular[:n] - rho * particular[n:]))
    weight_down = 2.0 * np.pi * w * x  # plane irradiance of the downward streams
    down = weight_down @ modes[:n]
    up = weight_down @ modes[n:]
    slowest = int(np.argmax(rates))
    # nadir radiance (μ = −1) by the natural interpolation of each solution: L(μ) = b' J(μ)/(c' + λ μ)
    row = ((2 * ell + 1) * scaled * (-1.0) ** ell) @ P / (4.0 * np.pi)  # p₀(−1, μ_j)
    J_modes = 2.0 * np.pi * (row * ws) @ modes
    J_part = 2.0 * np.pi * (row * ws) @ particular + ((2 * ell + 1) * scaled * (-1.0) ** ell) @ P_w / (4.0 * np.pi)
    nadir = float(amp @ (b_s * J_modes / (c_s - rates)) + b_s * J_part / (c_s + k_beam))
    if back_phase is not None:  # Eq. 17 of Nakajima & Tanaka (1988): exact single scattering of the beam
        truncated = float(((2 * ell + 1) * scaled * (-1.0) ** ell) @ P_w / (4.0 * np.pi))
        nadir += mu_w / (1.0 + mu_w) * (b * back_phase / (a + b) - b_s * truncated / c_s)
    upwelling = modes[n:] @ amp + particular[n:]  # L⁻ at the nodes, z = 0
    reflected = float(weight_down @ (rho * upwelling))
    return DeepLayer(K_inf=float(-rates[slowest]), R_inf=float(up[slowest] / down[slowest]), f=f, c_scaled=c_s,
                     mu_w=float(mu_w), nadir_radiance=nadir, reflected=reflected, _rates=rates, _down=down, _up=up, _amp=amp,
                     _particular=(float(weight_down @ particular[:n]), float(weight_down @ particular[n:])),
                     _slowest=slowest)


@dataclass(frozen=True)
class StreamCoefficients:
    """Coefficients of the four-flux equations (:mod:`oceanrender.optics.fourflux`, Eqs. 1–3) per wavelength.

    dE_s/dz   = −c_beam/μ_w E_s
    dE_dif/dz = −(a + b_bd)/μ_d E_dif + b_bu/μ_u E_u + b_fs/μ_w E_s
    dE_u/dz   = +(a + b_bu)/μ_u E_u − b_bd/μ_d E_dif − b_bs/μ_w E_s

    Attributes (arrays of the spectral shape)
    ----------
    c_beam : beam attenuation [m⁻¹];  b_fs, b_bs : beam → diffuse down / up [m⁻¹];
    mu_d, mu_u : stream cosines [-];  b_bd, b_bu : stream backscattering [m⁻¹];
    Q : E_u(0⁻)/L_u(0⁻, nadir) [sr], or None (then π, Lambertian);
    r_wa : share of E_u(0⁻) the level surface reflects back down [-], or None (then the
        uniform-radiance r̄_wa of :func:`~oceanrender.optics.fresnel.diffuse_reflectance_Fresnel`).
    """

    c_beam: NDArray[np.float64]
    b_fs: NDArray[np.float64]
    b_bs: NDArray[np.float64]
    mu_d: NDArray[np.float64]
    mu_u: NDArray[np.float64]
    b_bd: NDArray[np.float64]
    b_bu: NDArray[np.float64]
    Q: NDArray[np.float64] | None = None
    r_wa: NDArray[np.float64] | None = None


def stream_block(a: float, K: float, R: float) -> tuple[float, float]:
    """(μ̄, b_b,s) of the symmetric diffuse block whose modes are the asymptotic ones (module docstring).

    With α = (a + b_b,s)/μ̄ and β = b_b,s/μ̄ the block [[−α, β], [−β, α]] has eigenvalues ∓K with
    eigenvectors (1, R) and (R, 1) iff α = K (1 + R²)/(1 − R²) and β = 2 R K/(1 − R²).
    """
    alpha = K * (1.0 + R * R) / (1.0 - R * R)
    beta = 2.0 * R * K / (1.0 - R * R)
    mu = a / (alpha - beta)
    return mu, beta * mu


def first_optical_depth(layer: DeepLayer) -> float:
    """Depth z₁ [m] where E_d = E_s + E_dif of ``layer`` falls to E_d(0)/e (Gordon 1989), by bisection."""
    target = layer.mu_w / np.e
    lo, hi = 0.0, 1.0 / layer.c_scaled
    while float(np.sum(layer.irradiances(hi)[:2])) > target:
        lo, hi = hi, 2.0 * hi
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if float(np.sum(layer.irradiances(mid)[:2])) > target:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def _beam_sources(layer: DeepLayer, z1: float) -> tuple[float, float, float]:
    """(c_beam, b_fs, b_bs) [m⁻¹]: the four-flux deep solution gets the layer's E_u(0⁻) and E_d(z₁).

    With the block of :func:`stream_block` and E_dif(0) = 0, in the mode basis
    y₁ (1, R) + y₂ (R, 1) with s = (s_d, s_u) the beam source at z = 0 and
    σ = (s_d − R s_u, s_u − R s_d)/(1 − R²):

        E_u(0) = −(1 − R²) σ₂/(K + k),     E_d(z) = S₀ e^{−k z} + A (e^{−K z} − e^{−k z}),
        A = −σ₁/(K − k) + R σ₂/(K + k),    k = c'/μ_w,

    both linear in s: a 2 × 2 system. Where K = k (the beam decays like the asymptotic
    mode) k is moved by 1e-6 relative, far below any measurable change.
    """
    K, R, mu_w = layer.K_inf, layer.R_inf, layer.mu_w
    c_beam = layer.c_scaled
    if abs(K - c_beam / mu_w) < 1e-6 * c_beam / mu_w:
        c_beam *= 1.0 + 1e-6
    k, S0, d = c_beam / mu_w, mu_w, 1.0 - R * R
    E_s, E_dif, _ = layer.irradiances(z1)
    spread = np.exp(-K * z1) - np.exp(-k * z1)
    A = (float(E_s + E_dif) - S0 * np.exp(-k * z1)) / spread
    gap = K - k
    # rows: E_u(0), A; columns: s_d, s_u
    M = np.array([[R / (k + K), -1.0 / (k + K)],
                  [-1.0 / (d * gap) - R * R / (d * (k + K)), R / (d * gap) + R / (d * (k + K))]])
    s_d, s_u = np.linalg.solve(M, [layer.E_u0, A])
    return c_beam, s_d * mu_w / S0, -s_u * mu_w / S0


def _surface_beam_backscatter(layer: DeepLayer, c_beam: float, b_fs: float, surface: DeepLayer, sky_in: float) -> float:
    """b_bs [m⁻¹] giving the four-flux model the E_u(0⁻) of the layer under its level surface and sky.

    With the surface's reflection ρ = r_wa of the upwelling and the transmitted sky D (per unit
    in-water beam normal irradiance) as the four-flux model's Eq. (5) has them, the deep solution
    has y₁(0) (1 − ρR) = D + y₂(0)(ρ − R), so E_u(0) = R D/(1 − ρR) + y₂(0)(1 − R²)/(1 − ρR) with
    y₂(0) = −(s_u − R s_d)/((1 − R²)(K + k)): linear in s_u = −S₀ b_bs/μ_w. This replaces the
    index-matched fit of b_bs (``_beam_sources``) where a surface is given, so that R(0⁻) is the
    transport's under the sky/sun ratio of the scene (a uniform sky).
    """
    K, R, mu_w = layer.K_inf, layer.R_inf, layer.mu_w
    k, S0 = c_beam / mu_w, mu_w
    rho = surface.reflected / surface.E_u0
    y2 = (surface.E_u0 - R * sky_in / (1.0 - rho * R)) * (1.0 - rho * R) / (1.0 - R * R)
    s_d = S0 * b_fs / mu_w
    s_u = R * s_d - (1.0 - R * R) * (K + k) * y2
    return -s_u * mu_w / S0


def surface_light(sun_irradiance: ArrayLike, sky_irradiance: ArrayLike, sun_zenith: float, n_water: float
                  ) -> tuple[float, NDArray[np.float64]]:
    """(μ_w, sky per unit in-water beam normal irradiance) for :func:`stream_coefficients` [-].

    The refracted beam keeps the power per horizontal area that enters, E_sun cos θ_s (1 − F(θ_s)),
    so its normal irradiance in the water is that over cos θ_w. Where the sun gives no light
    (sunsky above 720 nm) the ratio is 0 (those wavelengths carry no light either way).
    """
    from .fresnel import N_AIR, reflectance_Fresnel, refracted_cosine  # noqa: PLC0415

    mu_s = math.cos(math.radians(float(sun_zenith)))
    mu_w = float(refracted_cosine(mu_s, N_AIR, n_water))
    beam = np.asarray(sun_irradiance, dtype=float) * mu_s * (1.0 - reflectance_Fresnel(mu_s, N_AIR, n_water)) / mu_w
    sky = np.asarray(sky_irradiance, dtype=float)
    return mu_w, np.divide(sky, beam, out=np.zeros(np.broadcast(sky, beam).shape), where=beam > 0)


def sunlit_coefficients(a: ArrayLike, b: ArrayLike, mu: ArrayLike, p: ArrayLike, sun_irradiance: ArrayLike,
                        sky_irradiance: ArrayLike, sun_zenith: float, n_water: float) -> StreamCoefficients:
    """:func:`stream_coefficients` with the surface terms, for a sun [direct-normal, W m⁻² nm⁻¹] at
    ``sun_zenith`` [deg] and a sky [horizontal, W m⁻² nm⁻¹] above water of index ``n_water``."""
    mu_w, sky = surface_light(sun_irradiance, sky_irradiance, sun_zenith, n_water)
    return stream_coefficients(a, b, mu, p, mu_w, n_water=n_water, sky=sky)


def stream_coefficients(a: ArrayLike, b: ArrayLike, mu: ArrayLike, p: ArrayLike, mu_w: float,
                        n: int = N_STREAMS, *, n_water: float | None = None, sky: ArrayLike = 0.0
                        ) -> StreamCoefficients:
    """Four-flux coefficients per wavelength from a, b [m⁻¹], the phase table (μ (M,), p (W, M) [sr⁻¹]) and μ_w [-].

    See the module docstring; a and b have shape (W,) (the rows of p). With ``n_water`` [-]
    also the surface terms, from the deep layer under a level surface with a uniform sky
    whose horizontal irradiance above the water is ``sky`` (W,) per unit normal irradiance
    of the refracted beam in the water [-]: Q = E_u(0⁻)/L_u(nadir) [sr] and the share r_wa
    of E_u(0⁻) reflected back down [-] (Fresnel at every angle of the actual upwelling,
    instead of a uniform field's 0.475), and b_bs then gives the four-flux model that layer's
    E_u(0⁻) under the sky (:func:`_surface_beam_backscatter`).
    """
    a = np.atleast_1d(np.asarray(a, dtype=float))
    b = np.atleast_1d(np.asarray(b, dtype=float))
    mu = np.asarray(mu, dtype=float)
    p = np.atleast_2d(np.asarray(p, dtype=float))
    sky = np.broadcast_to(np.asarray(sky, dtype=float), a.shape)
    chi = legendre_moments(mu, p, 2 * n + 1)
    keys = ("c_beam", "b_fs", "b_bs", "mu_d", "mu_u", "b_bd", "b_bu", "Q", "r_wa")
    if n_water is not None:
        from .fresnel import N_AIR, diffuse_reflectance_Fresnel  # noqa: PLC0415

        sky_transmitted = 1.0 - float(diffuse_reflectance_Fresnel(N_AIR, n_water))  # as four_flux's Eq. (5)
    out = {key: np.full(a.shape, np.nan) for key in keys}
    for i in range(a.size):
        row = chi[i if chi.shape[0] > 1 else 0]
        if b[i] <= 0:  # no scattering: the beam alone; the streams carry no light
            for key, value in zip(keys[:7], (a[i], 0.0, 0.0, 1.0, 1.0, 0.0, 0.0)):
                out[key][i] = value
            continue
        layer = deep_layer(float(a[i]), float(b[i]), row, mu_w, n)
        mu_bar, bb_s = stream_block(float(a[i]), layer.K_inf, layer.R_inf)
        c_beam, b_fs, b_bs = _beam_sources(layer, first_optical_depth(layer))
        for key, value in zip(keys[:7], (c_beam, b_fs, b_bs, mu_bar, mu_bar, bb_s, bb_s)):
            out[key][i] = value
        if n_water is not None:
            back = float(np.interp(-mu_w, mu, p[i if p.shape[0] > 1 else 0]))
            surface = deep_layer(float(a[i]), float(b[i]), row, mu_w, n, n_water=n_water, sky=float(sky[i]),
                                 back_phase=back)
            out["Q"][i] = surface.E_u0 / surface.nadir_radiance
            out["r_wa"][i] = surface.reflected / surface.E_u0
            out["b_bs"][i] = _surface_beam_backscatter(layer, c_beam, b_fs, surface, sky_transmitted * float(sky[i]))
    if n_water is None:
        out["Q"] = out["r_wa"] = None
    else:  # no scattering: nothing upwells; keep the Lambertian and uniform-field values there
        out["Q"] = np.where(np.isfinite(out["Q"]), out["Q"], np.pi)
        out["r_wa"] = np.where(np.isfinite(out["r_wa"]), out["r_wa"], float(diffuse_reflectance_Fresnel(n_water, N_AIR)))
    return StreamCoefficients(**out)
