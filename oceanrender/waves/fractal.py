"""Fractal sea detail: fractional Brownian surfaces by midpoint random displacement.

A fractional Brownian (fBm) surface η with Hurst exponent H ∈ (0, 1) has the
structure function (twice the variogram)

    S(r) = E[(η(x + r) − η(x))²] = σ² (r / r₀)^{2H},   r₀ = 1 m,

so σ [m] is the rms height difference of points 1 m apart and H sets how it
scales: H → 1 is smooth, H → 0 is rough. :func:`estimate_fbm_parameters`
fits (H, σ) to the structure function of a base height field (the FFT or
Gerstner sea) in log–log over a range of lags; :func:`fractal_detail` draws a
periodic fBm surface with those parameters by the diamond-square algorithm
[1], [2]; :func:`blend_fractal` adds it to the base, ζ = η_base + γ η_fractal.
Because (H, σ) are measured on the base waves, the detail continues their
statistics — the power law of S(r) over the fitted lags — to the smaller
scales of a finer grid (:func:`upsample_periodic` brings the band-limited base
to that grid exactly).

Array layout: fields are indexed ``[iy, ix]`` like the FFT ocean's, with
spacing h [m] in both directions; the detail is periodic (tileable) on its
2ⁿ × 2ⁿ grid.

References
----------
.. [1] A. Fournier, D. Fussell and L. Carpenter, "Computer rendering of
   stochastic models", Commun. ACM 25(6), 371–384, 1982,
   doi:10.1145/358523.358553.
.. [2] D. Saupe, "Algorithms for random fractals", in H.-O. Peitgen and
   D. Saupe (eds.), The Science of Fractal Images, Springer, 1988, ch. 2
   (algorithm MidPointFM2D).
.. [3] B. B. Mandelbrot and J. W. Van Ness, "Fractional Brownian motions,
   fractional noises and applications", SIAM Review 10(4), 422–437, 1968,
   doi:10.1137/1010093.
"""

from __future__ import annotations

from functools import lru_cache
from typing import NamedTuple

import numpy as np
import scipy.fft
import scipy.optimize
import scipy.signal
from numpy.typing import ArrayLike, NDArray

__all__ = [
    "REFERENCE_LENGTH",
    "FBMParameters",
    "structure_function",
    "estimate_fbm_parameters",
    "fractal_detail",
    "blend_fractal",
    "upsample_periodic",
]

REFERENCE_LENGTH: float = 1.0
"""Lag r₀ at which σ is the rms height difference, S(r₀) = σ² [m]."""

#: Largest lag of the fits and of the calibration, as a fraction of the grid side.
_MAX_LAG_FRACTION = 8
#: Half-steps at the top and bottom of the recursion whose variances are calibrated freely.
_FREE_TOP, _FREE_BOTTOM = 4, 4
#: Largest grid order 2ⁿ calibrated directly; finer grids reuse its calibration.
_CALIBRATION_ORDER = 9


class FBMParameters(NamedTuple):
    """Parameters of an fBm surface, S(r) = σ² (r / 1 m)^{2H}."""

    hurst: float
    """Hurst exponent H [-]."""
    sigma: float
    """rms height difference at a lag of 1 m, σ [m]."""


def _lags(shape: tuple[int, ...], min_lag: int, max_lag: int | None) -> NDArray[np.int64]:
    """Lags 1, 2, 4, … in grid cells within [min_lag, max_lag] (default max: side/8)."""
    if max_lag is None:
        max_lag = min(shape) // _MAX_LAG_FRACTION
    if not 1 <= min_lag < max_lag:
        raise ValueError(f"expected 1 ≤ min_lag < max_lag grid cells, got {min_lag}, {max_lag} "
                         f"(fields need at least {2 * _MAX_LAG_FRACTION} points per side for the default)")
    lags = 2 ** np.arange(int(np.floor(np.log2(max_lag))) + 1)
    return lags[lags >= min_lag]


def _mean_square_difference(height: NDArray, dy: int, dx: int, periodic: bool) -> float:
    """Mean of (η(iy + dy, ix + dx) − η(iy, ix))² over the field."""
    if periodic:
        return float(np.mean(np.square(np.roll(height, (-dy, -dx), axis=(0, 1)) - height)))
    ny, nx = height.shape
    a = height[max(0, -dy):ny - max(0, dy), max(0, -dx):nx - max(0, dx)]
    b = height[max(0, dy):ny + min(0, dy) or None, max(0, dx):nx + min(0, dx) or None]
    return float(np.mean(np.square(b - a)))


def structure_function(
    height: ArrayLike, spacing: float, lags: ArrayLike, periodic: bool = True
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Direction-averaged structure function S(r) = mean (η(x + r) − η(x))² [m²].

    Parameters
    ----------
    height : array_like, shape (Ny, Nx)
        Height field on a square grid, indexed [iy, ix] [m].
    spacing : float
        Grid spacing h [m].
    lags : array_like of int
        Lags in grid cells.
    periodic : bool, optional
        True: the field wraps (FFT patches, :func:`fractal_detail`); False:
        only pairs inside the field.

    Returns
    -------
    distances : ndarray, shape (2 n,)
        r [m]: the lags along the axes (r = n h), then along the diagonals (r = n h √2).
    values : ndarray, shape (2 n,)
        S(r) [m²]: the mean of +x and +y, then of the two diagonals.

    Notes
    -----
    Averaging four directions makes the estimate of an anisotropic sea (waves
    along the wind) an isotropic one: for a plane of slope s it is s² r²/2
    exactly, the mean of s² cos²α r² over the direction α.
    """
    height = np.asarray(height, dtype=np.float64)
    if height.ndim != 2:
        raise ValueError(f"height must be a 2-D array, got shape {height.shape}")
    lags = np.asarray(lags, dtype=np.int64)
    axis = [(_mean_square_difference(height, 0, n, periodic) + _mean_square_difference(height, n, 0, periodic)) / 2
            for n in lags]
    diagonal = [(_mean_square_difference(height, n, n, periodic) + _mean_square_difference(height, n, -n, periodic))
                / 2 for n in lags]
    distances = spacing * np.concatenate([lags, lags * np.sqrt(2)])
    return distances, np.array(axis + diagonal)


def estimate_fbm_parameters(
    height: ArrayLike,
    spacing: float,
    min_lag: int = 1,
    max_lag: int | None = None,
    periodic: bool = True,
) -> FBMParameters:
    """Fit (H, σ) of S(r) = σ² (r / 1 m)^{2H} to a height field's structure function.

    Parameters
    ----------
    height : array_like, shape (Ny, Nx)
        Base height field, e.g. ``OceanFields.height`` [m].
    spacing : float
        Grid spacing h [m].
    min_lag, max_lag : int, optional
        Range of lags in grid cells; lags 1, 2, 4, … inside it are used, along
        the axes and the diagonals. Default: from 1 cell to a side/8.
    periodic : bool, optional
        Whether the field wraps (see :func:`structure_function`).

    Returns
    -------
    FBMParameters
        H [-] and σ [m], by least squares of ln S = 2 ln σ + 2H ln(r / 1 m).

    Notes
    -----
    Lags are spaced geometrically, so every octave of scales weighs the same
    in the fit. The result is returned as fitted: a sea whose spectrum falls
    off as k⁻⁴ (Phillips) or faster inside the range is smooth there and
    gives H ≥ 1, outside the range of :func:`fractal_detail`; a range that
    reaches the spectral peak (or, for a patch, the patch scale, where S
    saturates) lowers H. Choose the range inside the base's power-law range.

    References
    ----------
    .. [1] B. B. Mandelbrot and J. W. Van Ness, SIAM Review 10(4), 422–437, 1968
       (the fBm structure function).
    """
    height = np.asarray(height, dtype=np.float64)
    if not (np.isfinite(spacing) and spacing > 0):
        raise ValueError(f"spacing must be a positive length [m], got {spacing!r}")
    distances, values = structure_function(height, spacing, _lags(height.shape, min_lag, max_lag), periodic)
    if not np.all(np.isfinite(values) & (values > 0)):
        raise ValueError("the structure function must be positive and finite at every lag "
                         "(a flat field has no fBm fit)")
    slope, intercept = np.polyfit(np.log(distances / REFERENCE_LENGTH), np.log(values), 1)
    return FBMParameters(hurst=float(slope / 2), sigma=float(np.exp(intercept / 2)))  # S = σ² (r/r₀)^{2H}


def _half_steps(order: int) -> list[tuple[str, int]]:
    """The recursion on a 2ⁿ grid: (kind, step) for step = 2ⁿ, 2ⁿ⁻¹, …, 2."""
    return [(kind, 1 << s) for s in range(order, 0, -1) for kind in ("diamond", "square")]


def _stencil_distance(kind: str, step: int) -> float:
    """Side of the square of the 4 points a new point is averaged from [cells]."""
    return step if kind == "diamond" else step / np.sqrt(2)


def _half_step(z: NDArray, kind: str, step: int, noise=None) -> None:
    """One half-step of the periodic diamond-square recursion, in place.

    Diamond: each square's centre becomes the mean of its 4 corners; square:
    each edge midpoint becomes the mean of its 2 corners and the 2 adjacent
    centres. ``noise(shape)`` adds the random displacement to the new points.
    """
    half = step // 2
    corners = z[0::step, 0::step]
    # NOTE: np.roll makes every stencil wrap around: the surface is periodic
    if kind == "diamond":
        new = (corners + np.roll(corners, -1, 0) + np.roll(corners, -1, 1) + np.roll(corners, (-1, -1), (0, 1))) / 4
        z[half::step, half::step] = new if noise is None else new + noise(new.shape)
        return
    centres = z[half::step, half::step]
    row_edges = (corners + np.roll(corners, -1, 1) + np.roll(centres, 1, 0) + centres) / 4  # (i step, half + j step)
    column_edges = (corners + np.roll(corners, -1, 0) + np.roll(centres, 1, 1) + centres) / 4  # (half + i step, j step)
    z[0::step, half::step] = row_edges if noise is None else row_edges + noise(row_edges.shape)
    z[half::step, 0::step] = column_edges if noise is None else column_edges + noise(column_edges.shape)


def _structure_basis(order: int) -> NDArray[np.float64]:
    """Expected S(Δ) [cells²] of the recursion per unit displacement variance at each half-step.

    Shape (half-steps, M, M), indexed by the lag vector [Δy, Δx]. The recursion is
    linear, so S = Σ_l v_l B_l with v_l the variance of half-step l; B_l follows
    from the response h to one unit displacement, Σ_x (h(x + Δ) − h(x))² by FFT,
    times the number of new points per cell, (M/step)²/M² per class.
    """
    m = 1 << order
    steps = _half_steps(order)
    basis = np.empty((len(steps), m, m))
    for level, (kind, step) in enumerate(steps):
        half = step // 2
        starts = [(half, half)] if kind == "diamond" else [(0, half), (half, 0)]
        total = np.zeros((m, m))
        for iy, ix in starts:
            response = np.zeros((m, m))
            response[iy, ix] = 1.0
            for later_kind, later_step in steps[level + 1:]:
                _half_step(response, later_kind, later_step)
            power = np.abs(scipy.fft.fft2(response)) ** 2
            autocorrelation = scipy.fft.ifft2(power).real
            total += 2 * (autocorrelation[0, 0] - autocorrelation)
        basis[level] = total * (m // step) ** 2 / m**2
    return basis


def _calibrated_weights(order: int, hurst: float) -> NDArray[np.float64]:
    """Per-half-step displacement variances [cells^{2H}] that give S(r) ≈ r^{2H} (σ = 1, h = 1)."""
    steps = _half_steps(order)
    basis = _structure_basis(order)
    m = 1 << order
    lags = np.arange(1, m // _MAX_LAG_FRACTION + 1)
    axis = (basis[:, 0, lags] + basis[:, lags, 0]) / 2
    diagonal = (basis[:, lags, lags] + basis[:, -lags, lags]) / 2
    distance = np.concatenate([lags, lags * np.sqrt(2)])
    relative = np.concatenate([axis, diagonal], axis=1) / distance ** (2 * hurst)  # (half-steps, lags)
    scale = np.array([_stencil_distance(kind, step) for kind, step in steps]) ** (2 * hurst)
    n = len(steps)
    free = [level for level in range(n) if level < _FREE_TOP or level >= n - _FREE_BOTTOM]
    core = [level for level in range(n) if level not in free]
    columns = [relative[level] for level in free]
    if core:  # the self-similar middle: v_l = γ ρ_l^{2H}, Saupe's scaling
        columns.append(scale[core] @ relative[core])
    weight = np.sqrt(1 / distance)  # equal weight per octave
    solution, _ = scipy.optimize.nnls(np.column_stack(columns) * weight[:, None], weight)
    variances = np.empty(n)
    variances[free] = solution[: len(free)]
    if core:
        variances[core] = solution[-1] * scale[core]
    return variances


@lru_cache(maxsize=64)
def _displacement_variances(order: int, hurst: float) -> NDArray[np.float64]:
    """Calibrated variances for a 2ⁿ grid, read-only; grids above 2⁹ reuse the 2⁹ calibration."""
    if order <= _CALIBRATION_ORDER:
        variances = _calibrated_weights(order, hurst)
    else:
        reference = _calibrated_weights(_CALIBRATION_ORDER, hurst)
        ref_scale = np.array([_stencil_distance(*s) for s in _half_steps(_CALIBRATION_ORDER)]) ** (2 * hurst)
        scale = np.array([_stencil_distance(*s) for s in _half_steps(order)]) ** (2 * hurst)
        relative = reference / ref_scale  # v_l / ρ_l^{2H}: the top, core and bottom factors
        n_ref, n = len(reference), len(scale)
        factors = np.full(n, relative[_FREE_TOP])  # the core's common γ
        factors[:_FREE_TOP] = relative[:_FREE_TOP]
        factors[n - _FREE_BOTTOM:] = relative[n_ref - _FREE_BOTTOM:]
        variances = factors * scale
    variances.flags.writeable = False
    return variances


def fractal_detail(
    shape: int | tuple[int, int], spacing: float, hurst: float, sigma: float, seed: int | None
) -> NDArray[np.float64]:
    """Periodic fBm surface by midpoint random displacement (diamond-square) [m].

    Parameters
    ----------
    shape : int or (int, int)
        Grid size M × M, M = 2ⁿ ≥ 16 points per side.
    spacing : float
        Grid spacing h [m]; the surface tiles with period M h.
    hurst : float
        Hurst exponent H, 0 < H < 1 [-].
    sigma : float
        rms height difference at a lag of 1 m, σ ≥ 0 [m].
    seed : int or None
        Seed of ``np.random.default_rng``; the same seed gives the same surface.

    Returns
    -------
    ndarray, shape (M, M)
        Zero-mean height [m], indexed [iy, ix]; its expected structure
        function is σ² (r/1 m)^{2H} for lags from h to M h/8.

    Notes
    -----
    The diamond-square recursion of Fournier, Fussell & Carpenter [1] on a
    periodic grid: starting from one point, each half-step sets the centres
    of the squares (diamond) or the midpoints of their edges (square) to the
    mean of their 4 neighbours plus a Gaussian displacement, every stencil
    wrapping around the grid, so the surface is tileable.

    Displacement variances. Saupe's rule [2], v_l = σ² c(H) ρ_l^{2H} with ρ_l
    the stencil size (halved in area at every half-step) — for the 2-D stencils
    c(H) = 2^{−H} − 1/4 − 2^{H}/8, the variance of a point about the mean of its
    4 neighbours if they were exact fBm — assumes the coarser levels already
    are fBm. On a periodic patch they cannot be (there are no scales larger
    than the patch, and the grid has none below h): on a 256² grid the result
    falls short of σ² r^{2H} at the lag M/8 by 40 % for H = 0.5 and 75 % for
    H = 0.8, with a lower apparent H. Instead, the recursion being linear,
    its expected structure function is S(r) = Σ_l v_l B_l(r), with B_l
    computed exactly from the response to one unit displacement; the
    variances are chosen by non-negative least squares so that S matches
    σ² r^{2H} at every lag from h to M h/8 (axes and diagonals), keeping
    Saupe's self-similar form v_l ∝ ρ_l^{2H} in the middle of the recursion
    and freeing the top and bottom two octaves. For grids from 16² to 2048²
    the expected S then matches within 0.4 % for H ≤ 0.5, 2 % for H ≤ 0.8
    and 7 % at H = 0.95. The calibration is computed once per (grid order,
    H) and cached (under 1 s); grids above 512² reuse the 512² one (top,
    middle and bottom factors by position).

    For H near 1 most of S at small lags comes from the largest scales (in
    true fBm, from scales beyond the patch, which the top octaves stand in
    for), so one surface has few degrees of freedom there: fitted to single
    256² realisations, H scatters by ±0.02 (H = 0.2), ±0.07 (0.5) and ±0.09
    (0.8) (standard deviations), while the fit to the mean structure
    function of several realisations recovers (H, σ).

    References
    ----------
    .. [1] A. Fournier, D. Fussell and L. Carpenter, Commun. ACM 25(6), 371–384, 1982.
    .. [2] D. Saupe, "Algorithms for random fractals", The Science of Fractal
       Images, Springer, 1988, ch. 2.
    """
    m = shape if isinstance(shape, int) else shape[0]
    if (isinstance(shape, tuple) and (len(shape) != 2 or shape[0] != shape[1])) or m < 16 or m & (m - 1):
        raise ValueError(f"shape must be M × M with M = 2ⁿ ≥ 16, got {shape!r}")
    if not 0 < hurst < 1:
        raise ValueError(f"hurst must be in (0, 1), got {hurst!r}")
    if not (np.isfinite(sigma) and sigma >= 0):
        raise ValueError(f"sigma must be finite and ≥ 0 [m], got {sigma!r}")
    if not (np.isfinite(spacing) and spacing > 0):
        raise ValueError(f"spacing must be a positive length [m], got {spacing!r}")
    order = m.bit_length() - 1
    # variances in cells^{2H}, to metres: S = σ² (r/r₀)^{2H} = σ² (h/r₀)^{2H} (r/h)^{2H}
    deviations = sigma * (spacing / REFERENCE_LENGTH) ** hurst * np.sqrt(_displacement_variances(order, float(hurst)))
    rng = np.random.default_rng(seed)
    z = np.zeros((m, m))
    for deviation, (kind, step) in zip(deviations, _half_steps(order)):
        _half_step(z, kind, step, lambda size, d=deviation: d * rng.standard_normal(size))
    return z - z.mean()


def blend_fractal(base_height: ArrayLike, detail: ArrayLike, gamma: float) -> NDArray[np.float64]:
    """Base waves plus fractal detail, ζ = η_base + γ η_fractal [m].

    Parameters
    ----------
    base_height : array_like, shape (M, M)
        Base elevation [m] on the detail's grid (see :func:`upsample_periodic`).
    detail : array_like, shape (M, M)
        Fractal detail from :func:`fractal_detail` [m].
    gamma : float
        Blend weight γ ≥ 0 [-]; 0 returns the base exactly.

    Returns
    -------
    ndarray, shape (M, M)
        ζ [m].

    Notes
    -----
    The two are independent, so their structure functions add: with γ = 1
    and (H, σ) from :func:`estimate_fbm_parameters` on the base, S of the
    blend is twice the base's at the fitted lags, and the detail alone
    carries the power law on below the base's resolution. Slopes and normals
    of ζ are for the mesh to compute; the detail has no time dependence.
    """
    base = np.asarray(base_height, dtype=np.float64)
    detail = np.asarray(detail, dtype=np.float64)
    if base.shape != detail.shape:
        raise ValueError(f"base_height and detail must have the same shape, got {base.shape} and {detail.shape}")
    if not (np.isfinite(gamma) and gamma >= 0):
        raise ValueError(f"gamma must be finite and ≥ 0, got {gamma!r}")
    if gamma == 0:
        return base.copy()
    return base + gamma * detail  # ζ = H_base + γ H_fractal


def upsample_periodic(height: ArrayLike, factor: int) -> NDArray[np.float64]:
    """A periodic field on a grid ``factor`` times finer, by Fourier interpolation [m].

    Parameters
    ----------
    height : array_like, shape (N, N)
        Periodic field, e.g. the FFT ocean's height, on points −L/2 + i L/N.
    factor : int
        Refinement m ≥ 1.

    Returns
    -------
    ndarray, shape (m N, m N)
        The trigonometric interpolant on the points −L/2 + i L/(m N): exact
        for a field with no energy at or above the Nyquist wavenumber (the FFT
        ocean, whose Nyquist modes are zero); a Nyquist component is split
        evenly between ±k.
    """
    height = np.asarray(height, dtype=np.float64)
    factor = int(factor)
    if factor < 1:
        raise ValueError(f"factor must be an integer ≥ 1, got {factor}")
    finer = scipy.signal.resample(height, height.shape[0] * factor, axis=0)
    return scipy.signal.resample(finer, height.shape[1] * factor, axis=1)
