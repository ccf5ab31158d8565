"""The water's phase function for Mitsuba: a Rayleigh + Henyey–Greenstein blend that varies with λ.

Mitsuba's ``blendphase`` takes one weight and ``hg`` one g for all wavelengths, so a
medium built from them can match the composition's backscattering ratio b_b/b at one
wavelength only (issue 19: 42 % low at 440 nm for Chl 0.03 mg m⁻³ when fitted at
550 nm). This plugin, ``oceanrender_water_phase``, reads both as spectra::

    p_λ(θ) = (1 − w(λ)) p_R(θ) + w(λ) p_HG(θ; g(λ))                                    (1)

with the Rayleigh shape p_R = 3/(16π) (1 + cos²θ) of the water's molecular
scattering and w(λ) = b_p/b, g(λ) fitted to the particles' b_bp/b_p at every
wavelength (:func:`oceanrender.optics.components.composition_optics`). Since p_R is
symmetric (B_R = ½), (1) backscatters B(λ) = (1 − w) ½ + w B_HG(g) — the composition's
b_b/b at each wavelength.

Sampling (exact, one-sample spectral MIS over the path's wavelengths; Veach 1997,
sect. 9.2.4 one-sample model, as in hero-wavelength rendering, Wilkie et al. 2014):
one of the n wavelengths is picked uniformly, then the lobe with that wavelength's
weight, then a direction from it, so the density of the sampled direction is the
mean of (1) over the wavelengths, p̄ = (1/n) Σ_λ p_λ, and the sample weight is
p_λ/p̄ per wavelength (≤ n, and 1 where (1) does not vary with λ). ``eval_pdf``
returns (p_λ, p̄). HG sampling: the inverse CDF of Henyey & Greenstein (1941), as in
Mitsuba's ``hg``; Rayleigh: the real root of μ³ + 3μ + 4 − 8u = 0 (Cardano), the
inverse of its CDF (μ³ + 3μ + 4)/8.

Angles: μ = cos θ between the new direction and the direction of propagation
(−wi in Mitsuba's convention, wi pointing back along the path) [-].
"""

from __future__ import annotations

import math

from .buffers import jit_floats

__all__ = ["PHASE_PLUGIN", "register"]

PHASE_PLUGIN = "oceanrender_water_phase"
"""Name of the plugin in scene dicts."""

_REGISTERED: set[str] = set()

_G_ISOTROPIC = 1e-3
"""|g| below which the HG lobe is sampled as isotropic (its inverse CDF divides by g) [-]."""


def _hg_value(g, mu):
    """Henyey–Greenstein p(μ; g) = (1 − g²) / (4π (1 + g² − 2gμ)^{3/2}) [sr⁻¹] (Henyey & Greenstein 1941)."""
    import drjit as dr  # noqa: PLC0415

    denom = 1.0 + g * g - 2.0 * g * mu
    return (1.0 - g * g) / (4.0 * math.pi * denom * dr.sqrt(denom))


def _rayleigh_value(mu):
    """Rayleigh p(μ) = 3 (1 + μ²) / (16π) [sr⁻¹]."""
    return (3.0 / (16.0 * math.pi)) * (1.0 + mu * mu)


def _hg_sample_mu(g, u):
    """μ of HG(g) for u ∈ [0, 1) by the inverse CDF (μ = −1 at u = 0, 1 at u → 1)."""
    import drjit as dr  # noqa: PLC0415

    safe_g = dr.select(dr.abs(g) < _G_ISOTROPIC, _G_ISOTROPIC, g)
    s = (1.0 - safe_g * safe_g) / (1.0 - safe_g + 2.0 * safe_g * u)
    mu = (1.0 + safe_g * safe_g - s * s) / (2.0 * safe_g)
    return dr.clip(dr.select(dr.abs(g) < _G_ISOTROPIC, 2.0 * u - 1.0, mu), -1.0, 1.0)


def _rayleigh_sample_mu(u):
    """μ of Rayleigh for u ∈ [0, 1): the real root of μ³ + 3μ + (4 − 8u) = 0 (Cardano; p = 3 > 0, one root)."""
    import drjit as dr  # noqa: PLC0415

    q = 4.0 - 8.0 * u
    r = dr.sqrt(0.25 * q * q + 1.0)
    return dr.clip(dr.cbrt(-0.5 * q + r) + dr.cbrt(-0.5 * q - r), -1.0, 1.0)


def _pick(spectrum, index):
    """spectrum[index] per lane (index an integer array in 0 … n − 1)."""
    import drjit as dr  # noqa: PLC0415

    value = spectrum[0]
    for k in range(1, len(spectrum)):
        value = dr.select(index == k, spectrum[k], value)
    return value


def water_phase_class():
    """The Mitsuba PhaseFunction subclass of the active variant (defined on demand: needs a variant)."""
    import drjit as dr  # noqa: PLC0415
    import mitsuba as mi  # noqa: PLC0415

    class WaterPhase(mi.PhaseFunction):
        """Eq. (1) of :mod:`oceanrender.render.phase`: properties ``weight`` (w(λ)) and ``g`` (g(λ)), textures."""

        def __init__(self, props):
            mi.PhaseFunction.__init__(self, props)
            self.weight = props.get("weight")
            self.g = props.get("g")
            self.m_flags = mi.PhaseFunctionFlags.Anisotropic

        def _spectra(self, mei, active):
            si = dr.zeros(mi.SurfaceInteraction3f)
            si.p = mei.p
            si.t = mei.t
            si.wavelengths = mei.wavelengths
            w = dr.clip(mi.Spectrum(self.weight.eval(si, active)), 0.0, 1.0)
            g = dr.clip(mi.Spectrum(self.g.eval(si, active)), -0.999, 0.999)
            return w, g

        @staticmethod
        def _values(w, g, mu):
            value = (1.0 - w) * _rayleigh_value(mu) + w * _hg_value(g, mu)  # Eq. (1), per wavelength
            return value, _mean(value)

        def sample(self, ctx, mei, sample1, sample2, active=True):
            w, g = self._spectra(mei, active)
            n = len(w)
            scaled = sample1 * n
            index = mi.UInt32(dr.minimum(dr.floor(scaled), n - 1))
            u = scaled - mi.Float(index)  # uniform in [0, 1) again, given the index
            w_k = _pick(w, index)
            g_k = _pick(g, index)
            lobe = u < w_k
            mu = dr.select(lobe, _hg_sample_mu(g_k, sample2.x), _rayleigh_sample_mu(sample2.x))
            sin_theta = dr.safe_sqrt(1.0 - mu * mu)
            s, c = dr.sincos(2.0 * math.pi * sample2.y)
            wo = mi.Frame3f(-mei.wi).to_world(mi.Vector3f(sin_theta * c, sin_theta * s, mu))
            value, pdf = self._values(w, g, mu)
            weight = dr.select(pdf > 0.0, value / dr.select(pdf > 0.0, pdf, 1.0), 0.0)
            return wo, mi.Spectrum(weight), pdf

        def eval_pdf(self, ctx, mei, wo, active=True):
            w, g = self._spectra(mei, active)
            mu = dr.dot(wo, -mei.wi)
            value, pdf = self._values(w, g, mu)
            return mi.Spectrum(value), pdf

        def traverse(self, callback):
            pass

        def to_string(self):
            return "WaterPhase[Rayleigh + HG, spectral weight and g]"

    return WaterPhase


def _mean(spectrum):
    """Mean over a spectrum's entries (the path's wavelengths), per lane."""
    total = spectrum[0]
    for k in range(1, len(spectrum)):
        total = total + spectrum[k]
    return total / len(spectrum)


def register() -> None:
    """Register :data:`PHASE_PLUGIN` with Mitsuba for the active variant (idempotent, per variant)."""
    from .plugins import register_once  # noqa: PLC0415

    register_once(_REGISTERED, "phase", PHASE_PLUGIN, water_phase_class)


# ---------------------------------------------------------------------------------------------
# Tabulated phase functions (issue 19, item 2): p(λ_i, μ_j), one row per wavelength of a 5 nm grid
# ---------------------------------------------------------------------------------------------

TABULATED_PLUGIN = "oceanrender_tabulated_phase"
"""Name of the tabulated spectral phase function in scene dicts."""

_REGISTERED_TABLE: set[str] = set()


def tabulated_phase_rows(mu, values):
    """Normalised rows and their CDFs for a phase function piecewise linear in μ.

    mu : (M,) increasing cosines from −1 to 1 [-]; values : (N, M) p ≥ 0 [sr⁻¹]. Returns
    (p, cdf), both (N, M): p scaled so that 2π ∫ p dμ = 1 exactly for the piecewise-linear
    function (trapezoids), cdf its running integral (0 at μ = −1, 1 at μ = 1).
    """
    import numpy as np  # noqa: PLC0415

    mu = np.asarray(mu, dtype=float)
    values = np.atleast_2d(np.asarray(values, dtype=float))
    if mu.ndim != 1 or mu.size < 2 or np.any(np.diff(mu) <= 0) or mu[0] != -1.0 or mu[-1] != 1.0:
        raise ValueError("tabulated phase: μ must increase from −1 to 1")
    if values.shape[1] != mu.size or np.any(~np.isfinite(values)) or np.any(values < 0):
        raise ValueError("tabulated phase: need finite p ≥ 0 with one column per μ")
    pieces = 0.5 * (values[:, 1:] + values[:, :-1]) * np.diff(mu)[None, :] * 2.0 * math.pi
    total = pieces.sum(axis=1, keepdims=True)
    if np.any(total <= 0):
        raise ValueError("tabulated phase: a row integrates to 0")
    cdf = np.concatenate([np.zeros((values.shape[0], 1)), np.cumsum(pieces, axis=1)], axis=1) / total
    cdf[:, -1] = 1.0
    return values / total, cdf


def tabulated_phase_class():
    """The Mitsuba PhaseFunction of a table p(λ_i, μ_j) (uniform λ grid, shared μ nodes), for the active variant.

    Properties: ``wavelengths`` (first, step, count) [nm], ``mu`` and ``values`` (row-major
    N × M) as comma-separated strings. Each path wavelength uses its nearest table row;
    sampling picks one of the path's wavelengths, inverts that row's CDF exactly (a
    quadratic per interval), and returns p̄ = the mean over the path's wavelengths, as
    :class:`WaterPhase` does.
    """
    import drjit as dr  # noqa: PLC0415
    import mitsuba as mi  # noqa: PLC0415
    import numpy as np  # noqa: PLC0415

    class TabulatedPhase(mi.PhaseFunction):
        def __init__(self, props):
            mi.PhaseFunction.__init__(self, props)
            first, step, count = (float(x) for x in props["wavelengths"].split(","))
            mu = np.array([float(x) for x in props["mu"].split(",")])
            values = np.array([float(x) for x in props["values"].split(",")]).reshape(int(count), mu.size)
            p, cdf = tabulated_phase_rows(mu, values)
            self.first, self.step, self.rows, self.m = first, step, int(count), mu.size
            self.mu = jit_floats(mu)
            self.p = jit_floats(p)
            self.cdf = jit_floats(cdf)
            self.m_flags = mi.PhaseFunctionFlags.Anisotropic

        def _row(self, wavelength):
            index = dr.round((wavelength - self.first) / self.step)
            return mi.UInt32(dr.clip(index, 0, self.rows - 1))

        def _value(self, row, mu):
            j = dr.binary_search(0, self.m - 2, lambda k: dr.gather(mi.Float, self.mu, k + 1) < mu)
            mu0 = dr.gather(mi.Float, self.mu, j)
            mu1 = dr.gather(mi.Float, self.mu, j + 1)
            p0 = dr.gather(mi.Float, self.p, row * self.m + j)
            p1 = dr.gather(mi.Float, self.p, row * self.m + j + 1)
            t = dr.clip((mu - mu0) / (mu1 - mu0), 0.0, 1.0)
            return dr.fma(t, p1 - p0, p0)

        def _values(self, mei, mu):
            value = mi.Spectrum(0.0)
            for k in range(len(value)):
                value[k] = self._value(self._row(mei.wavelengths[k]), mu)
            return value, _mean(value)

        def sample(self, ctx, mei, sample1, sample2, active=True):
            n = len(mei.wavelengths)
            index = mi.UInt32(dr.minimum(dr.floor(sample1 * n), n - 1))
            row = self._row(_pick(mei.wavelengths, index))
            u = sample2.x
            base = row * self.m
            j = dr.binary_search(0, self.m - 2, lambda k: dr.gather(mi.Float, self.cdf, base + k + 1) <= u)
            c0 = dr.gather(mi.Float, self.cdf, base + j)
            mu0 = dr.gather(mi.Float, self.mu, j)
            mu1 = dr.gather(mi.Float, self.mu, j + 1)
            p0 = dr.gather(mi.Float, self.p, base + j)
            p1 = dr.gather(mi.Float, self.p, base + j + 1)
            slope = (p1 - p0) / (mu1 - mu0)
            r = dr.maximum(u - c0, 0.0) / (2.0 * math.pi)  # mass left in the interval [sr⁻¹ · 1]
            # p0 t + slope t²/2 = r, the root in [0, μ1 − μ0] in the form without cancellation
            t = 2.0 * r / (p0 + dr.safe_sqrt(p0 * p0 + 2.0 * slope * r))
            t = dr.select(p0 + dr.safe_sqrt(p0 * p0 + 2.0 * slope * r) > 0.0, t, 0.0)
            mu = dr.clip(mu0 + t, -1.0, 1.0)
            sin_theta = dr.safe_sqrt(1.0 - mu * mu)
            s, c = dr.sincos(2.0 * math.pi * sample2.y)
            wo = mi.Frame3f(-mei.wi).to_world(mi.Vector3f(sin_theta * c, sin_theta * s, mu))
            value, pdf = self._values(mei, mu)
            weight = dr.select(pdf > 0.0, value / dr.select(pdf > 0.0, pdf, 1.0), 0.0)
            return wo, mi.Spectrum(weight), pdf

        def eval_pdf(self, ctx, mei, wo, active=True):
            value, pdf = self._values(mei, dr.dot(wo, -mei.wi))
            return mi.Spectrum(value), pdf

        def traverse(self, callback):
            pass

        def to_string(self):
            return f"TabulatedPhase[{self.rows} wavelengths × {self.m} cosines]"

    return TabulatedPhase


def register_tabulated() -> None:
    """Register :data:`TABULATED_PLUGIN` with Mitsuba for the active variant (idempotent, per variant)."""
    from .plugins import register_once  # noqa: PLC0415

    register_once(_REGISTERED_TABLE, "phase", TABULATED_PLUGIN, tabulated_phase_class)
