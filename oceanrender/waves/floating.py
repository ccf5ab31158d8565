"""How a floating object sits on the sea: heave, pitch and roll from the surface under it.

A hull much longer than the short waves averages them out; what moves it is the sea
surface over its waterplane. Here that is the least-squares plane through the sea's
height at a grid of points over the hull's footprint (heights found by inverting the
choppy displacement, :func:`~.query.query_height`, on the sea filtered to what a
grid of that spacing resolves):

    η(x, y) ≈ h + a (x − x_c) + b (y − y_c)

whose height h is the heave and whose slopes along the bow and to the left give
pitch = atan(∇η·f̂) (bow up) and roll = atan(∇η·l̂) (the left side up, starboard down).

The object does not follow that plane at once: its pose is the plane filtered by a
critically damped second-order system of time constant τ (``response_time``), whose
impulse response h(s) = s e^{−s/τ} / τ² has unit area — a hull's heave and pitch
respond like damped oscillators near their natural periods and not to faster
forcing (e.g. Newman 1977, *Marine Hydrodynamics*, §6.15-6.17: a stated, simple
stand-in for the hull's own dynamics, not a seakeeping computation). The filter is
evaluated as a sum over the past s_k = k Δ, k = 0 … K (Δ = τ/4, K Δ = 8τ, the
weights renormalised: the tail beyond 8τ holds 3·10⁻³ of the area), so the pose at
t depends on t alone — the same on every Dask worker and in a resumed run.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .query import query_height
from .sea import SeaSurface

__all__ = ["FloatingPose", "RESPONSE_STEPS_PER_TAU", "RESPONSE_HISTORY_TAUS", "FOOTPRINT_POINTS",
           "response_weights", "footprint", "wave_plane", "floating_pose"]

#: Steps of the response filter per time constant, and its history in time constants.
RESPONSE_STEPS_PER_TAU = 4
RESPONSE_HISTORY_TAUS = 8
#: Sample points of the footprint along and across the hull.
FOOTPRINT_POINTS = (7, 5)
#: Height-query tolerance [m].
_TOLERANCE_M = 1e-4


@dataclass(frozen=True)
class FloatingPose:
    """Heave [m] (the plane's height at the object's centre), pitch and roll [deg]."""

    heave: float
    pitch: float
    roll: float


def response_weights(tau: float) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """(lags s_k [s], weights w_k [-], Σ w = 1) of the critically damped response of time constant τ [s].

    h(s) = s e^{−s/τ} / τ² sampled at s_k = k τ / :data:`RESPONSE_STEPS_PER_TAU` up to
    :data:`RESPONSE_HISTORY_TAUS` τ, trapezoid weights, renormalised; τ = 0: no filter.
    """
    if tau < 0 or not math.isfinite(tau):
        raise ValueError(f"response_time: expected a finite time ≥ 0 [s], got {tau!r}")
    if tau == 0:
        return np.zeros(1), np.ones(1)
    lags = np.arange(RESPONSE_STEPS_PER_TAU * RESPONSE_HISTORY_TAUS + 1) * (tau / RESPONSE_STEPS_PER_TAU)
    w = lags * np.exp(-lags / tau) / tau**2
    w[0] *= 0.5
    w[-1] *= 0.5
    return lags, w / w.sum()


def footprint(extent_x: tuple[float, float], extent_y: tuple[float, float]) -> NDArray[np.float64]:
    """Sample points (P, 2) over the hull's footprint in its own frame [m] (x forward, y left)."""
    gx = np.linspace(*extent_x, FOOTPRINT_POINTS[0])
    gy = np.linspace(*extent_y, FOOTPRINT_POINTS[1])
    x, y = np.meshgrid(gx, gy, indexing="ij")
    return np.stack([x.ravel(), y.ravel()], -1)


def wave_plane(sea: SeaSurface, points: NDArray, t: float, spacing: float) -> tuple[float, float, float]:
    """Least-squares plane η ≈ h + a (x − x̄) + b (y − ȳ) through the sea's heights at world ``points`` (P, 2)
    [m] at time t [s], waves finer than ``spacing`` [m] filtered out, wakes left out: (h [m], a, b [-])."""
    q = query_height(sea.sampler(t, spacing, disturbed=False), points[:, 0], points[:, 1], tol=_TOLERANCE_M)
    centre = points.mean(axis=0)
    design = np.column_stack([np.ones(len(points)), points - centre])
    (h, a, b), *_ = np.linalg.lstsq(design, q.height, rcond=None)
    return float(h), float(a), float(b)


def floating_pose(sea: SeaSurface, local_points: NDArray, centre, heading_deg: float, t: float,
                  response_time: float, spacing: float) -> FloatingPose:
    """The pose of a floating object at time t [s].

    Parameters
    ----------
    sea : SeaSurface          The sea (no wakes: an object does not ride its own).
    local_points : (P, 2)     Footprint points in the object's frame (x forward, y left) [m].
    centre : callable         t [s] → (x, y) of the object's origin [m] (it may be moving).
    heading_deg : float       Where the bow points, clockwise from north [deg].
    t : float                 Time [s].
    response_time : float     τ of the response [s] (:func:`response_weights`).
    spacing : float           Finest wave kept, as a grid spacing [m] (a fraction of the hull).
    """
    heading = math.radians(heading_deg)
    forward = np.array([math.sin(heading), math.cos(heading)])
    left = np.array([-math.cos(heading), math.sin(heading)])
    lags, weights = response_weights(response_time)
    heave = slope_f = slope_l = 0.0
    for lag, w in zip(lags, weights):
        c = np.asarray(centre(t - lag), dtype=float)
        world = c + local_points[:, :1] * forward + local_points[:, 1:2] * left
        h, a, b = wave_plane(sea, world, t - lag, spacing)
        offset = world.mean(axis=0) - c  # the plane's height at the object's origin, not at the points' mean
        heave += w * (h - a * offset[0] - b * offset[1])
        slope_f += w * (a * forward[0] + b * forward[1])
        slope_l += w * (a * left[0] + b * left[1])
    return FloatingPose(heave, math.degrees(math.atan(slope_f)), math.degrees(math.atan(slope_l)))
