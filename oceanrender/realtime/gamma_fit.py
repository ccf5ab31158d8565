"""Fit γ of the corrected Fresnel weight F^γ (Eq. 20) to path-traced reference views.

Only the mix of Eq. 20 depends on γ, so each view is reduced once to its
water pixels' F, T_refl, C_water and the reference's CIELAB values; the mean
CIEDE2000 difference over all views is then a cheap function of γ, minimised
in log γ by a grid search followed by Brent's bounded method.

References
----------
.. [1] The dissertation named in the project issue, Eq. 20.
.. [2] G. Sharma, W. Wu and E. N. Dalal, "The CIEDE2000 color-difference
   formula: implementation notes, supplementary test data, and mathematical
   observations," Color Res. Appl. 30(1), 21–30, 2005. doi:10.1002/col.20070
.. [3] R. P. Brent, Algorithms for Minimization without Derivatives,
   Prentice-Hall, 1973, ch. 5.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import colour
import numpy as np
from numpy.typing import ArrayLike, NDArray

from .compare import ErrorStats, display_to_Lab, error_stats
from .model import RealtimeTerms, fresnel_mix, with_foam

__all__ = ["FitView", "fit_view", "mean_delta_E", "GammaFit", "fit_gamma", "minimise_log_gamma"]


@dataclass(frozen=True, eq=False)
class FitView:
    """One view reduced to what γ changes: its water pixels (N of them).

    Attributes
    ----------
    F : ndarray (N,)                 Fresnel reflectance [-].
    T_refl, C_water : ndarray (N, 3)  The two terms of Eq. 20 (display RGB).
    reference_Lab : ndarray (N, 3)   CIELAB of the reference at those pixels, as displayed.
    glint : ndarray (N, 3) or None   The sun's glint added after Eq. 20 (display RGB).
    foam, foam_colour : (N,), (N, 3) or None  Fresh-foam coverage and the foam's light (display RGB).
    display : callable               Φ's display response applied to the model before CIELAB (identity
                                     for the linear operators; the reference's is in ``reference_Lab``).
    """

    F: NDArray[np.float64]
    T_refl: NDArray[np.float64]
    C_water: NDArray[np.float64]
    reference_Lab: NDArray[np.float64]
    glint: NDArray[np.float64] | None = None
    display: Callable[[NDArray], NDArray] = np.asarray
    foam: NDArray[np.float64] | None = None
    foam_colour: NDArray[np.float64] | None = None

    def delta_E(self, gamma: float) -> NDArray[np.float64]:
        """ΔE2000 (N,) of the model at γ against the reference, both as displayed."""
        rgb = fresnel_mix(self.F, self.T_refl, self.C_water, gamma)
        rgb = with_foam(rgb if self.glint is None else rgb + self.glint, self.foam, self.foam_colour)
        model = display_to_Lab(self.display(rgb))
        return np.asarray(colour.delta_E(model, self.reference_Lab, method="CIE 2000"))


def fit_view(terms: RealtimeTerms, reference_rgb: ArrayLike,
             display: Callable[[NDArray], NDArray] = np.asarray) -> FitView:
    """The :class:`FitView` of a view from its real-time terms and its reference image (H, W, 3).

    ``display``: Φ's display response (``VisionState.display``), applied to
    both images before they are compared, as :func:`.reference.compare_frame` does.
    """
    w = terms.water
    return FitView(F=terms.F[w], T_refl=terms.T_refl[w], C_water=terms.C_water[w],
                   reference_Lab=display_to_Lab(display(np.asarray(reference_rgb)[w])), glint=terms.glint[w],
                   display=display, foam=None if terms.foam is None else terms.foam[w],
                   foam_colour=None if terms.foam_colour is None else terms.foam_colour[w])


def mean_delta_E(views: list[FitView], gamma: float) -> float:
    """Mean ΔE2000 over the water pixels of all views (each pixel weighs the same)."""
    values = np.concatenate([view.delta_E(gamma) for view in views])
    return float(np.mean(values))


@dataclass(frozen=True)
class GammaFit:
    """Result of :func:`fit_gamma`.

    Attributes
    ----------
    gamma : float            The fitted γ [-].
    gamma_start : float      γ of the "before" figures (1: exact Fresnel) [-].
    before, after : ErrorStats  ΔE2000 over all water pixels of all views at γ_start and at γ.
    curve : tuple of (γ, mean ΔE)  The grid search.
    """

    gamma: float
    gamma_start: float
    before: ErrorStats
    after: ErrorStats
    curve: tuple[tuple[float, float], ...]

    def describe(self) -> dict[str, object]:
        return {"gamma": self.gamma, "gamma_start": self.gamma_start, "before": self.before.describe(),
                "after": self.after.describe(), "grid": [list(point) for point in self.curve]}


def fit_gamma(views: list[FitView], gamma_start: float = 1.0, bounds: tuple[float, float] = (0.1, 10.0),
              grid: int = 41, tolerance: float = 1e-4) -> GammaFit:
    """γ minimising the mean ΔE2000 between the real-time model and the references.

    Parameters
    ----------
    views : list of FitView
        The views (:func:`fit_view`).
    gamma_start : float
        γ of the "before" figures [-].
    bounds : (float, float)
        Search interval of γ [-].
    grid : int
        Points of the initial log-spaced grid (guards against a local minimum).
    tolerance : float
        Tolerance on ln γ of the bounded Brent search [3].

    Returns
    -------
    GammaFit
    """
    if not views or sum(len(v.F) for v in views) == 0:
        raise ValueError("fit_gamma: no water pixels to fit")
    gamma, curve = minimise_log_gamma(lambda g: mean_delta_E(views, g), bounds, grid, tolerance)

    def stats(g: float) -> ErrorStats:
        return error_stats(np.concatenate([view.delta_E(g) for view in views]))

    return GammaFit(gamma=gamma, gamma_start=float(gamma_start), before=stats(gamma_start), after=stats(gamma),
                    curve=curve)


def minimise_log_gamma(cost: Callable[[float], float], bounds: tuple[float, float] = (0.1, 10.0), grid: int = 41,
                       tolerance: float = 1e-4) -> tuple[float, tuple[tuple[float, float], ...]]:
    """γ minimising ``cost(γ)``: a log-spaced grid over ``bounds``, then Brent's bounded method [3] in ln γ.

    Returns γ and the grid's (γ, cost) pairs. The grid guards against a
    local minimum; Brent refines between the best grid point's neighbours.
    """
    from scipy.optimize import minimize_scalar  # noqa: PLC0415

    log_grid = np.linspace(np.log(bounds[0]), np.log(bounds[1]), grid)
    values = np.array([cost(float(np.exp(g))) for g in log_grid])
    best = int(np.argmin(values))
    bracket = (log_grid[max(best - 1, 0)], log_grid[min(best + 1, grid - 1)])
    result = minimize_scalar(lambda g: cost(float(np.exp(g))), bounds=bracket, method="bounded",
                             options={"xatol": tolerance})
    log_gamma = float(result.x) if result.fun <= values[best] else float(log_grid[best])
    return float(np.exp(log_gamma)), tuple((float(np.exp(g)), float(v)) for g, v in zip(log_grid, values))
