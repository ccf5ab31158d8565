"""Seas given by what people measure: Hs and Tp per partition, or a directional spectrum E(f, θ) from a file.

Both become the directional wavenumber spectrum Ψ(kx, ky) [m⁴] that the FFT
cascades sample (:class:`FrequencyDirectionSpectrum`), through the linear
dispersion relation at the scene's depth, with capillarity when a surface
tension is given (:func:`~.wave_spectra.dispersion_relation`). The variance
is conserved mode by mode: E(f, θ) df dθ = Ψ(k, θ) k dk dθ = Ψ dkx dky, so

    Ψ(k, θ) = E(f(k), θ) · (df/dk) / k = E(f(k), θ) · c_g(k) / (2π k),     (1)

f(k) = ω(k)/2π and c_g = dω/dk (e.g. Holthuijsen 2007, §3.5.6, Eq. 3.5.36).

Partitions (:class:`Partition`): S(f) of JONSWAP, TMA or Pierson–Moskowitz
with the peak at f_p = 1/Tp, scaled so that 4 √m0 = Hs exactly (the scale is
integrated numerically, rather than taken from the approximate
A_γ = 1 − 0.287 ln γ of DNV-RP-C205 §3.5.5.2), times the cos-2s spreading of
Longuet-Higgins et al. (1963) about the mean direction of travel.

    JONSWAP:  S(f) ∝ f⁻⁵ exp(−5/4 (f_p/f)⁴) γ^exp(−(f − f_p)²/(2 σ² f_p²)),
              σ = σ_a for f ≤ f_p, σ_b above                (Hasselmann et al. 1973, Eq. 2.9)
    PM:       S(f) = (5/16) Hs² f_p⁴ f⁻⁵ exp(−5/4 (f_p/f)⁴)  (Pierson & Moskowitz 1964 in Hs, Tp;
                                                            DNV-RP-C205 2019, Eq. 3.5.4)
    TMA:      JONSWAP · φ_K(ω, d), the Kitaigorodskii depth function
              (Bouws et al. 1985), then scaled to Hs (the Hs measured in that depth)

References
----------
.. [1] L. H. Holthuijsen, Waves in Oceanic and Coastal Waters, Cambridge University Press, 2007.
.. [2] K. Hasselmann et al., "Measurements of wind-wave growth and swell decay during the Joint North
   Sea Wave Project (JONSWAP)", Dtsch. Hydrogr. Z. Suppl. A8(12), 1973.
.. [3] DNV-RP-C205, Environmental conditions and environmental loads, 2019, §3.5.
.. [4] E. Bouws, H. Günther, W. Rosenthal and C. L. Vincent, "Similarity of the wind wave spectrum in
   finite depth water: 1. Spectral form", J. Geophys. Res. 90(C1), 975–986, 1985.
.. [5] M. S. Longuet-Higgins, D. E. Cartwright and N. D. Smith, "Observations of the directional
   spectrum of sea waves using the motions of a floating buoy", in Ocean Wave Spectra, 1963.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import cached_property

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .spreading import spreading_cos2s
from .wave_spectra import (
    GRAVITY,
    JONSWAP_GAMMA,
    SEAWATER_DENSITY,
    depth_function_Kitaigorodskii1975,
    dispersion_relation,
    group_velocity,
)

__all__ = ["PARTITION_SPECTRA", "shape_JONSWAP", "shape_PiersonMoskowitz", "Partition", "partition_spectrum",
           "FrequencyDirectionSpectrum", "PartitionedSpectrum", "TabulatedSpectrum"]

#: The frequency spectra a partition may have.
PARTITION_SPECTRA = ("JONSWAP 1973", "Pierson-Moskowitz 1964", "TMA 1985")

#: Relative frequency grid of the Hs scaling integral: f/f_p from 0.2 to 50, log-spaced.
_RELATIVE_F = np.geomspace(0.2, 50.0, 8001)


def shape_PiersonMoskowitz(f: ArrayLike, fp: float) -> NDArray[np.float64]:
    """Pierson–Moskowitz shape f⁻⁵ exp(−5/4 (f_p/f)⁴) [Hz⁻⁵] (0 at f ≤ 0)."""
    f = np.asarray(f, dtype=np.float64)
    with np.errstate(divide="ignore", over="ignore", invalid="ignore"):
        value = f**-5.0 * np.exp(-1.25 * (fp / f) ** 4)
    return np.where(f > 0, np.nan_to_num(value, nan=0.0, posinf=0.0), 0.0)


def shape_JONSWAP(f: ArrayLike, fp: float, gamma: float, sigma_a: float, sigma_b: float) -> NDArray[np.float64]:
    """JONSWAP shape: PM shape × γ^exp(−(f − f_p)²/(2 σ² f_p²)) [Hz⁻⁵] (Hasselmann et al. 1973, Eq. 2.9)."""
    f = np.asarray(f, dtype=np.float64)
    sigma = np.where(f <= fp, sigma_a, sigma_b)
    return shape_PiersonMoskowitz(f, fp) * gamma ** np.exp(-((f - fp) ** 2) / (2.0 * sigma**2 * fp**2))


@dataclass(frozen=True)
class Partition:
    """One partition of a sea state.

    Attributes
    ----------
    spectrum : str       One of :data:`PARTITION_SPECTRA`.
    hs : float           Significant wave height 4 √m0 [m].
    tp : float           Peak period [s].
    gamma : float        Peak enhancement γ (JONSWAP, TMA) [-].
    sigma_a, sigma_b : float  Peak widths below/above f_p (JONSWAP, TMA) [-].
    direction : float    Mean direction of travel, counter-clockwise from +x [rad].
    spreading_s : float  cos-2s parameter s [-].
    """

    spectrum: str = "JONSWAP 1973"
    hs: float = 1.0
    tp: float = 8.0
    gamma: float = JONSWAP_GAMMA
    sigma_a: float = 0.07
    sigma_b: float = 0.09
    direction: float = 0.0
    spreading_s: float = 10.0

    def __post_init__(self) -> None:
        if self.spectrum not in PARTITION_SPECTRA:
            raise ValueError(f"spectrum: {self.spectrum!r} is not one of {', '.join(map(repr, PARTITION_SPECTRA))}")
        for name, ok in (("hs", self.hs > 0), ("tp", self.tp > 0), ("gamma", 1 <= self.gamma <= 10),
                         ("sigma_a", self.sigma_a > 0), ("sigma_b", self.sigma_b > 0),
                         ("spreading_s", self.spreading_s >= 0), ("direction", math.isfinite(self.direction))):
            if not (ok and math.isfinite(getattr(self, name))):
                raise ValueError(f"{name}: out of range, got {getattr(self, name)!r}")
        if self.spectrum == "Pierson-Moskowitz 1964" and (self.gamma, self.sigma_a, self.sigma_b) != (
                JONSWAP_GAMMA, 0.07, 0.09):
            raise ValueError("gamma, sigma_a, sigma_b: 'Pierson-Moskowitz 1964' has no peak enhancement; leave "
                             "them out")


def partition_spectrum(partition: Partition, f: ArrayLike, depth: float = np.inf, g: float = GRAVITY
                       ) -> NDArray[np.float64]:
    """S(f) [m² Hz⁻¹] of a partition: its shape scaled so that ∫ S df = Hs²/16 (module docstring).

    The scale is the integral of the shape over f/f_p in [0.2, 50] (log grid,
    trapezoids; the shape holds < 1e-9 of its variance outside), so 4 √m0 = Hs
    to 1e-6.
    """
    fp = 1.0 / partition.tp

    def shape(frequency):
        if partition.spectrum == "Pierson-Moskowitz 1964":
            return shape_PiersonMoskowitz(frequency, fp)
        value = shape_JONSWAP(frequency, fp, partition.gamma, partition.sigma_a, partition.sigma_b)
        if partition.spectrum == "TMA 1985":
            value = value * depth_function_Kitaigorodskii1975(2 * np.pi * np.asarray(frequency), depth, g)
        return value

    grid = _RELATIVE_F * fp
    scale = np.trapezoid(shape(grid), grid)
    return (partition.hs**2 / 16.0) * shape(f) / scale


@dataclass(frozen=True, eq=False)
class FrequencyDirectionSpectrum:
    """Ψ(kx, ky) [m⁴] from a frequency–direction spectrum E(f, θ) [m² Hz⁻¹ rad⁻¹] by Eq. 1.

    Subclasses give :meth:`density` E(f, θ) and :attr:`frequency_band`.

    Attributes
    ----------
    depth : float             Water depth d of the dispersion relation [m]; inf: deep.
    g : float                 Gravitational acceleration [m s⁻²].
    surface_tension : float   σ of the dispersion relation [N m⁻¹]; 0: gravity waves.
    small_wave_length : float Ψ is multiplied by exp(−k² ℓ²) (Tessendorf 2001, Eq. 24) [m].
    """

    depth: float = np.inf
    g: float = GRAVITY
    surface_tension: float = 0.0
    small_wave_length: float = 0.0

    def density(self, f: NDArray, theta: NDArray) -> NDArray[np.float64]:  # pragma: no cover (abstract)
        raise NotImplementedError

    @property
    def frequency_band(self) -> tuple[float, float]:  # pragma: no cover (abstract)
        """(f_min, f_max) [Hz] outside which E = 0 (or negligible)."""
        raise NotImplementedError

    def __call__(self, kx: ArrayLike, ky: ArrayLike) -> NDArray[np.float64]:
        """Ψ(kx, ky) [m⁴]; 0 at k = 0."""
        kx, ky = np.asarray(kx, dtype=np.float64), np.asarray(ky, dtype=np.float64)
        k = np.hypot(kx, ky)
        k_safe = np.where(k == 0, 1.0, k)
        omega = dispersion_relation(k_safe, self.depth, self.g, self.surface_tension, SEAWATER_DENSITY)
        c_g = group_velocity(k_safe, self.depth, self.g, self.surface_tension, SEAWATER_DENSITY)
        E = self.density(omega / (2 * np.pi), np.mod(np.arctan2(ky, kx), 2 * np.pi))
        psi = E * c_g / (2 * np.pi * k_safe) * np.exp(-np.square(k_safe * self.small_wave_length))  # Eq. 1
        return np.where(k == 0, 0.0, psi)

    def _quadrature(self, samples: int = 4096, directions: int = 720):
        f = np.geomspace(*self.frequency_band, samples)
        theta = (np.arange(directions) + 0.5) * 2 * np.pi / directions
        E = self.density(f[:, None], theta[None, :])
        return f, theta, E

    def frequency_spectrum_hz(self, f: ArrayLike, directions: int = 720) -> NDArray[np.float64]:
        """S(f) = ∫ E(f, θ) dθ [m² Hz⁻¹]."""
        theta = (np.arange(directions) + 0.5) * 2 * np.pi / directions
        f = np.asarray(f, dtype=np.float64)
        return np.sum(self.density(f[..., None], theta), axis=-1) * (2 * np.pi / directions)

    def elevation_variance(self) -> float:
        """m0 = ∫∫ E df dθ [m²] (quadrature; before the ℓ suppression)."""
        f, theta, E = self._quadrature()
        return float(np.trapezoid(np.sum(E, axis=1) * (2 * np.pi / len(theta)), f))

    def significant_wave_height(self) -> float:
        """Hs = 4 √m0 [m]."""
        return 4.0 * math.sqrt(self.elevation_variance())

    @cached_property
    def peak_frequency(self) -> float:
        """Angular frequency ω_p of the peak of S(f) [rad s⁻¹] (the largest, for several peaks; computed once)."""
        f = np.geomspace(*self.frequency_band, 8192)
        return float(2 * np.pi * f[int(np.argmax(self.frequency_spectrum_hz(f)))])

    def mean_direction(self) -> float:
        """Energy-weighted circular mean direction of travel atan2(∫∫E sin θ, ∫∫E cos θ) [rad] in (−π, π]."""
        f, theta, E = self._quadrature()
        weights = np.trapezoid(E, f, axis=0)
        return float(np.arctan2(np.sum(weights * np.sin(theta)), np.sum(weights * np.cos(theta))))


@dataclass(frozen=True, eq=False)
class PartitionedSpectrum(FrequencyDirectionSpectrum):
    """A sea state as a sum of :class:`Partition` s: E(f, θ) = Σ S_i(f) D_i(θ − θ_i)."""

    partitions: tuple[Partition, ...] = field(default_factory=tuple)

    def __post_init__(self) -> None:
        if not self.partitions:
            raise ValueError("partitions: at least one is needed")

    def density(self, f: NDArray, theta: NDArray) -> NDArray[np.float64]:
        total = 0.0
        for p in self.partitions:
            total = total + (partition_spectrum(p, f, self.depth, self.g)
                             * spreading_cos2s(np.asarray(theta) - p.direction, p.spreading_s))
        return np.asarray(total, dtype=np.float64)

    @property
    def frequency_band(self) -> tuple[float, float]:
        fps = [1.0 / p.tp for p in self.partitions]
        return 0.2 * min(fps), 50.0 * max(fps)

    def elevation_variance(self) -> float:
        """m0 = Σ Hs_i²/16 [m²] (each partition is scaled to it)."""
        return float(sum(p.hs**2 for p in self.partitions) / 16.0)


@dataclass(frozen=True, eq=False)
class TabulatedSpectrum(FrequencyDirectionSpectrum):
    """E(f, θ) tabulated (a buoy's or a wave model's spectrum), bilinear in f and in θ (periodic), 0 outside f.

    Attributes
    ----------
    frequency : ndarray (F,)   f [Hz], increasing.
    direction : ndarray (D,)   θ of travel, counter-clockwise from +x, increasing in [0, 2π) [rad].
    table : ndarray (F, D)     E [m² Hz⁻¹ rad⁻¹].
    tail_exponent : float      n of the tail E(f_max, θ) (f/f_max)⁻ⁿ beyond the last frequency; 0: none.

    Notes
    -----
    Buoys and wave models stop at 0.5–1 Hz (waves of 1.5–6 m), but the sea
    goes on: without its shorter waves a rendered sea is a mirror (no glitter,
    no roughness). Beyond the file's last frequency the spectrum continues as
    a parametric f⁻ⁿ tail with the last frequency's directions, as WAVEWATCH III
    extends its prognostic range (n = 5, the saturation range of Phillips
    1958; WAVEWATCH III Development Group 2019, §2.4); ``tail_exponent = 0``
    keeps exactly the file's band.
    """

    frequency: NDArray[np.float64] = field(default_factory=lambda: np.zeros(0))
    direction: NDArray[np.float64] = field(default_factory=lambda: np.zeros(0))
    table: NDArray[np.float64] = field(default_factory=lambda: np.zeros((0, 0)))
    tail_exponent: float = 5.0

    def __post_init__(self) -> None:
        f, d, E = (np.asarray(a, dtype=np.float64) for a in (self.frequency, self.direction, self.table))
        if E.shape != (len(f), len(d)) or len(f) < 2 or len(d) < 2:
            raise ValueError(f"table: shape {E.shape} does not match {len(f)} frequencies x {len(d)} directions")
        if np.any(np.diff(f) <= 0) or np.any(np.diff(d) <= 0) or d[0] < 0 or d[-1] >= 2 * np.pi:
            raise ValueError("frequency and direction must increase; directions in [0, 2π)")
        if not (self.tail_exponent == 0 or self.tail_exponent > 1):
            raise ValueError(f"tail_exponent: 0 (no tail) or > 1 (a finite variance), got {self.tail_exponent!r}")

    def density(self, f: NDArray, theta: NDArray) -> NDArray[np.float64]:
        f, theta = np.broadcast_arrays(np.asarray(f, dtype=np.float64), np.asarray(theta, dtype=np.float64))
        freq, dirs, E = self.frequency, self.direction, self.table
        # Frequency: linear between the tabulated frequencies, zero outside them.
        i = np.clip(np.searchsorted(freq, f) - 1, 0, len(freq) - 2)
        wf = np.clip((f - freq[i]) / (freq[i + 1] - freq[i]), 0.0, 1.0)
        inside = (f >= freq[0]) & (f <= freq[-1])
        tail = f > freq[-1]
        # Direction: linear between neighbours, wrapping from the last to the first across 2π.
        t = np.mod(theta, 2 * np.pi)
        j = np.searchsorted(dirs, t) - 1  # −1: below the first, between the last and the first
        j0 = np.mod(j, len(dirs))
        j1 = np.mod(j + 1, len(dirs))
        span = np.mod(dirs[j1] - dirs[j0], 2 * np.pi)
        span = np.where(span == 0, 2 * np.pi, span)
        wd = np.mod(t - dirs[j0], 2 * np.pi) / span
        low = E[i, j0] * (1 - wd) + E[i, j1] * wd
        high = E[i + 1, j0] * (1 - wd) + E[i + 1, j1] * wd
        last = E[-1, j0] * (1 - wd) + E[-1, j1] * wd
        if self.tail_exponent > 0:
            with np.errstate(divide="ignore", over="ignore"):
                extended = last * np.where(tail, f / freq[-1], 1.0) ** -self.tail_exponent
            return np.where(inside, low * (1 - wf) + high * wf, np.where(tail, extended, 0.0))
        return np.where(inside, low * (1 - wf) + high * wf, 0.0)

    @property
    def frequency_band(self) -> tuple[float, float]:
        top = float(self.frequency[-1]) * (50.0 if self.tail_exponent > 0 else 1.0)
        return float(self.frequency[0]), top

    def elevation_variance(self) -> float:
        """m0 of the table (trapezoids in f, the periodic trapezoid rule in θ: exact for the bilinear E) plus
        the tail's S(f_max) f_max/(n − 1) [m²]."""
        dirs = self.direction
        widths = np.mod(np.roll(dirs, -1) - np.roll(dirs, 1), 2 * np.pi) / 2  # each node's share of 2π
        m0 = float(np.trapezoid(self.table @ widths, self.frequency))
        if self.tail_exponent > 0:
            m0 += float(self.table[-1] @ widths) * float(self.frequency[-1]) / (self.tail_exponent - 1.0)
        return m0
