"""How much a sea surface repeats: its height autocorrelation over lags of up to kilometres.

A sum of periodic patches repeats at each patch's period: the height field
correlates with itself at that lag by the share of the variance the patch
carries. :func:`repetition` measures the largest |ρ(τ)| over lags from two
peak wavelengths (where the sea's own correlation has died out) to a
distance, on a window of the sampled surface.

ρ(τ) = Σ η(x) η(x + τ) / (n(τ) σ²) over the n(τ) points where the window and
its shift overlap (the unbiased estimator, Bendat & Piersol 2010, Eq. 8.95),
computed by zero-padded FFTs.

References
----------
.. [1] J. S. Bendat and A. G. Piersol, Random Data: Analysis and Measurement
   Procedures, 4th ed., Wiley, 2010, §8.5, doi:10.1002/9781118032428.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..scene import OceanSettings
from .sea import SeaSurface


def autocorrelation(height: NDArray) -> NDArray:
    """ρ over all lags of a 2D field (its mean removed), shape (2n, 2m), lag (0, 0) at index (n, m) [-]."""
    eta = height - height.mean()
    n, m = eta.shape
    padded = np.zeros((2 * n, 2 * m))
    padded[:n, :m] = eta
    spectrum = np.fft.rfft2(padded)
    products = np.fft.irfft2(spectrum * np.conj(spectrum), s=padded.shape)
    ones = np.zeros_like(padded)
    ones[:n, :m] = 1.0
    ones_spectrum = np.fft.rfft2(ones)
    overlap = np.rint(np.fft.irfft2(ones_spectrum * np.conj(ones_spectrum), s=padded.shape))
    rho = np.where(overlap > 0, products / np.maximum(overlap, 1) / eta.var(), 0.0)
    return np.fft.fftshift(rho)


@dataclass(frozen=True)
class Repetition:
    """The result of :func:`repetition`.

    Attributes
    ----------
    peak_wavelength : float         2π g/ω_p² [m].
    max_abs_rho : float             Largest |ρ| over the lags 2 λ_p ≤ |τ| ≤ max_lag [-].
    at_lag : (float, float)         The lag (τx, τy) where it occurs [m].
    at_periods : dict               ρ at the lag (L, 0) of each cascade of side L below the window's size [-].
    """

    peak_wavelength: float
    max_abs_rho: float
    at_lag: tuple[float, float]
    at_periods: dict


def repetition(ocean: OceanSettings, step: float = 4.0, max_lag: float = 2000.0, t: float = 0.0) -> Repetition:
    """Largest |ρ| over lags 2 λ_p ≤ |τ| ≤ ``max_lag`` [m] of the sea's height at time t [s].

    The height is sampled every ``step`` [m] on a square of side 2 ``max_lag``
    + 32 steps, with the waves filtered as on a mesh of that spacing
    (:mod:`.lod`), so waves shorter than 2 steps do not alias into it.
    """
    sea = SeaSurface(ocean)
    peak_wavelength = 2 * np.pi * sea.spectrum.g / sea.spectrum.peak_frequency**2
    side = 2 * max_lag + 2 * step * 16
    count = int(np.ceil(side / step))
    axis = (np.arange(count) - count / 2) * step
    x, y = np.meshgrid(axis, axis)
    height = sea.sample(x, y, t, np.full(x.shape, step)).displacement[..., 2]
    rho = autocorrelation(height)
    lags = (np.arange(rho.shape[0]) - rho.shape[0] // 2) * step
    lag_x, lag_y = np.meshgrid(lags, lags)
    distance = np.hypot(lag_x, lag_y)
    window = (distance >= 2 * peak_wavelength) & (distance <= max_lag)
    worst = np.argmax(np.where(window, np.abs(rho), -1.0))
    at_period = {}
    if sea.cascades is not None:
        centre = rho.shape[0] // 2
        for size in sea.cascades.patch_sizes:
            shift = int(round(size / step))
            if shift < centre:
                at_period[round(size, 1)] = float(rho[centre, centre + shift])
    return Repetition(float(peak_wavelength), float(np.abs(rho.flat[worst])),
                      (float(lag_x.flat[worst]), float(lag_y.flat[worst])), at_period)
