"""Probing the sea at fixed world points over time: height, water velocity and normal.

What ``oceanrender probe`` prints and what floating objects stand on. The sea
surface of a choppy model is the displaced sheet P(x₀, t) = (x₀ + D(x₀, t), η(x₀, t));
at a world point x the rest point x₀ under it is found by inverting the
displacement (:func:`~.query.query_height`). There:

* height η [m] above the still level and the unit normal of the displaced sheet;
* velocity [m s⁻¹] of the water at the surface: the time derivative of the sheet's
  point at that rest point, ∂P/∂t at fixed x₀ (the orbital velocity of the surface
  particle: exact for Gerstner waves, the linear theory's for the FFT sea, whose
  displacement is the particle displacement of Tessendorf 2001, Eq. 29), by a central
  difference over ±:data:`VELOCITY_STEP_S`.

Everything is a pure function of the scene's sea and the times: the same numbers on
every machine, worker and resumed run.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .query import query_height
from .sea import SeaSurface

__all__ = ["VELOCITY_STEP_S", "SeaProbe", "probe_sea"]

#: Half-width of the central difference of the surface velocity [s]: 1 ms; the truncation error
#: (δt² ω² / 6 ≈ 2e-6 relative for a 1 s wave) is far below what the velocity is used for.
VELOCITY_STEP_S = 1.0e-3

#: Convergence tolerance of the height query [m]: 1 µm.
PROBE_TOLERANCE_M = 1.0e-6


@dataclass(frozen=True)
class SeaProbe:
    """The sea at P world points over T times.

    Attributes
    ----------
    times : (T,) ndarray          Times [s].
    x, y : (P,) ndarray           World points [m].
    height : (T, P) ndarray       Elevation η above the still level [m].
    velocity : (T, P, 3) ndarray  Velocity (u, v, w) of the water at the surface [m s⁻¹].
    normal : (T, P, 3) ndarray    Unit normal of the surface, z up [-].
    converged : (T, P) ndarray    The displacement inversion met :data:`PROBE_TOLERANCE_M`.
    folded : (T, P) ndarray       The surface overturns there (J ≤ 0): the height is one of several.
    """

    times: NDArray[np.float64]
    x: NDArray[np.float64]
    y: NDArray[np.float64]
    height: NDArray[np.float64]
    velocity: NDArray[np.float64]
    normal: NDArray[np.float64]
    converged: NDArray[np.bool_]
    folded: NDArray[np.bool_]


def _sheet_point(sea: SeaSurface, x0: NDArray, y0: NDArray, t: float) -> NDArray:
    """P(x₀, t) = (x₀ + Dx, y₀ + Dy, η) [m], shape (P, 3)."""
    s = sea.surface_sample(x0, y0, t)
    return np.stack([x0 + s.displacement[..., 0], y0 + s.displacement[..., 1], s.height], -1)


def probe_sea(sea: SeaSurface, x: ArrayLike, y: ArrayLike, times: ArrayLike) -> SeaProbe:
    """Height, surface velocity and normal of ``sea`` at world points (x, y) [m] at ``times`` [s].

    Parameters
    ----------
    sea : SeaSurface    The scene's sea (:func:`~.sea.SeaSurface`).
    x, y : array_like   World coordinates of the points, 1-D, same length [m].
    times : array_like  Times [s], 1-D.

    Returns
    -------
    SeaProbe
    """
    x = np.atleast_1d(np.asarray(x, dtype=float))
    y = np.atleast_1d(np.asarray(y, dtype=float))
    times = np.atleast_1d(np.asarray(times, dtype=float))
    if x.ndim != 1 or x.shape != y.shape or x.size == 0:
        raise ValueError(f"x, y: expected two 1-D arrays of the same length ≥ 1, got shapes {x.shape}, {y.shape}")
    if not (np.all(np.isfinite(x)) and np.all(np.isfinite(y)) and np.all(np.isfinite(times))):
        raise ValueError("x, y, times: expected finite numbers [m, s]")
    shape = (times.size, x.size)
    height, converged, folded = np.empty(shape), np.empty(shape, bool), np.empty(shape, bool)
    velocity, normal = np.empty(shape + (3,)), np.empty(shape + (3,))
    for i, t in enumerate(times):
        q = query_height(sea.sampler(float(t)), x, y, tol=PROBE_TOLERANCE_M)
        height[i], normal[i], converged[i], folded[i] = q.height, q.normal, q.converged, q.folded
        x0, y0 = q.undisplaced[..., 0], q.undisplaced[..., 1]
        ahead = _sheet_point(sea, x0, y0, float(t) + VELOCITY_STEP_S)
        behind = _sheet_point(sea, x0, y0, float(t) - VELOCITY_STEP_S)
        velocity[i] = (ahead - behind) / (2.0 * VELOCITY_STEP_S)  # ∂P/∂t at fixed x₀
    return SeaProbe(times, x, y, height, velocity, normal, converged, folded)
