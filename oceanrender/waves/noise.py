"""Counter-based Gaussian noise: one standard normal pair per wave mode.

A sequential generator (``np.random.default_rng(seed).standard_normal``)
hands out numbers in array order, so the noise of a mode depends on the grid
size: refining the grid from 128² to 256² would redraw every wave. Here the
noise of mode (nx, ny) is a pure function of (seed, cascade, nx, ny), computed
by hashing those integers with SplitMix64 [1] (a counter-based generator in
the sense of [2]), turning two hashes into two uniforms and those into two
normals by the Box–Muller transform [3]. Modes shared by two grids of the same
patch therefore get the same noise, whatever the resolution.

All arithmetic is numpy ``uint64`` (wrapping modulo 2⁶⁴, as the algorithm
requires), so the numbers are the same on every platform.

References
----------
.. [1] G. L. Steele, D. Lea and C. H. Flood, "Fast splittable pseudorandom
   number generators", Proc. OOPSLA 2014, 453–472, doi:10.1145/2660193.2660195.
.. [2] J. K. Salmon, M. A. Moraes, R. O. Dror and D. E. Shaw, "Parallel random
   numbers: as easy as 1, 2, 3", Proc. SC11, 2011, doi:10.1145/2063384.2063405.
.. [3] G. E. P. Box and M. E. Muller, "A note on the generation of random
   normal deviates", Ann. Math. Statist. 29(2), 610–611, 1958,
   doi:10.1214/aoms/1177706645.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["splitmix64", "mode_key", "mode_uniforms", "mode_gaussian"]

_MASK = (1 << 64) - 1
_GOLDEN_GAMMA = 0x9E3779B97F4A7C15  # 2⁶⁴/φ, odd: the SplitMix64 increment of [1]


def splitmix64(x: ArrayLike) -> NDArray[np.uint64]:
    """SplitMix64 finaliser of x + γ, a bijective 64-bit integer hash [1].

    Parameters
    ----------
    x : array_like of uint64 (or non-negative integers below 2⁶⁴)
        Counters.

    Returns
    -------
    ndarray, uint64
        Hashed values, same shape as ``x``.

    References
    ----------
    .. [1] G. L. Steele, D. Lea and C. H. Flood, OOPSLA 2014, Fig. 16 (``mix64``
       of the state advanced by the golden gamma).
    """
    z = np.array(x, dtype=np.uint64, ndmin=1) + np.uint64(_GOLDEN_GAMMA)
    z ^= z >> np.uint64(30)
    z *= np.uint64(0xBF58476D1CE4E5B9)
    z ^= z >> np.uint64(27)
    z *= np.uint64(0x94D049BB133111EB)
    z ^= z >> np.uint64(31)
    return z.reshape(np.shape(x))


def _as_uint64(values: ArrayLike) -> NDArray[np.uint64]:
    """Signed integers as uint64 by two's complement (−1 ↦ 2⁶⁴ − 1)."""
    return np.asarray(values, dtype=np.int64).view(np.uint64)


def mode_key(seed: int, cascade: int = 0) -> int:
    """The 64-bit key of one (seed, cascade) pair, from which every mode's noise is hashed [-].

    Parameters
    ----------
    seed : int
        Any integer; taken modulo 2⁶⁴.
    cascade : int, optional
        Index of the FFT patch in a cascade (0 for a single patch).

    Returns
    -------
    int
        Key in [0, 2⁶⁴).
    """
    first = int(splitmix64(np.uint64(int(seed) & _MASK))[()])
    return int(splitmix64(np.uint64(first ^ (int(cascade) & _MASK)))[()])


def mode_uniforms(seed: int, cascade: int, nx: ArrayLike, ny: ArrayLike) -> tuple[NDArray, NDArray]:
    """Two independent uniforms in (0, 1) per mode, a pure function of (seed, cascade, nx, ny) [-].

    Parameters
    ----------
    seed : int
        Random seed.
    cascade : int
        Index of the FFT patch in a cascade.
    nx, ny : array_like of int
        Signed integer wavenumber indices of the modes (broadcast together).

    Returns
    -------
    u1, u2 : ndarray, float64
        Uniforms on the open interval (0, 1): (m + ½) 2⁻⁵³ with m the top 53 bits
        of a hash, so neither 0 nor 1 occurs.
    """
    nx, ny = np.broadcast_arrays(_as_uint64(nx), _as_uint64(ny))
    state = splitmix64(splitmix64(nx ^ np.uint64(mode_key(seed, cascade))) ^ ny)
    bits = (splitmix64(state), splitmix64(state ^ np.uint64(_GOLDEN_GAMMA)))
    scale = 2.0**-53
    return tuple(((b >> np.uint64(11)).astype(np.float64) + 0.5) * scale for b in bits)


def mode_gaussian(seed: int, cascade: int, nx: ArrayLike, ny: ArrayLike) -> NDArray[np.complex128]:
    """Complex Gaussian noise ξ = ξ_r + i ξ_i of each mode, ξ_r, ξ_i independent N(0, 1) [-].

    Parameters
    ----------
    seed : int
        Random seed.
    cascade : int
        Index of the FFT patch in a cascade.
    nx, ny : array_like of int
        Signed integer wavenumber indices of the modes.

    Returns
    -------
    ndarray, complex128
        ξ, E|ξ|² = 2; the value of one mode does not depend on which other
        modes are drawn.

    References
    ----------
    .. [1] G. E. P. Box and M. E. Muller, Ann. Math. Statist. 29(2), 610–611, 1958.
    """
    u1, u2 = mode_uniforms(seed, cascade, nx, ny)
    radius = np.sqrt(-2.0 * np.log(u1))  # Box–Muller [1]
    angle = 2.0 * np.pi * u2
    return radius * np.cos(angle) + 1j * (radius * np.sin(angle))
