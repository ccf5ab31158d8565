"""Ship wakes on the sea: the Kelvin wake of a moving object as a disturbance of the sea surface.

Linear theory lets wakes and waves add: the surface is the sea plus each moving
object's steady wake (:mod:`.kelvin_wake`), carried along with the object. The wake
is computed once per object in its own frame (x along the track, the object at the
origin moving towards +x) on an FFT grid, with its slopes by central differences,
and sampled bilinearly at the rest points of the water mesh each frame (outside the
grid: no wake). Limits: a steady wake of a straight course at constant speed (no
start-up transient, no turning); it does not reach the coastal solver; a wave that
passes through a hull is not reflected by it.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .kelvin_wake import WakeSource, kelvin_wake_grid, kelvin_wake_spacing

__all__ = ["ShipWake", "ship_wake", "submerged_source", "WAKE_LENGTHS", "MAX_WAKE_POINTS"]

#: Extent of the wake grid in hull lengths (it keeps ~85 % of it behind the hull), bounded to [200, 4000] m.
WAKE_LENGTHS = 60.0
#: Most grid points per side (cost: 0.12 s at 1500², 1.2 s at 4096²: docs/wake.md).
MAX_WAKE_POINTS = 2048


@dataclass(frozen=True)
class ShipWake:
    """A steady wake carried by a moving object.

    Attributes
    ----------
    x, y : (Nx,), (Ny,) ndarray   Grid coordinates along and across the track [m].
    height, slope_x, slope_y : (Ny, Nx) ndarray   η [m] and its gradient in the object's frame [-].
    heading : float               Course, clockwise from north [deg].
    centre : callable             t [s] → (x, y) of the object [m].
    """

    x: NDArray[np.float64]
    y: NDArray[np.float64]
    height: NDArray[np.float64]
    slope_x: NDArray[np.float64]
    slope_y: NDArray[np.float64]
    heading: float
    centre: Callable[[float], NDArray]

    def sample(self, x: NDArray, y: NDArray, t: float) -> tuple[NDArray, NDArray, NDArray]:
        """(η [m], ∂η/∂x, ∂η/∂y [-]) of the wake at world points (x, y) [m] at time t [s]."""
        h = math.radians(self.heading)
        forward, left = (math.sin(h), math.cos(h)), (-math.cos(h), math.sin(h))
        cx, cy = self.centre(t)
        dx, dy = np.asarray(x, float) - cx, np.asarray(y, float) - cy
        u = dx * forward[0] + dy * forward[1]  # along the track
        v = dx * left[0] + dy * left[1]  # across it
        fields = [_bilinear(self.x, self.y, f, u, v) for f in (self.height, self.slope_x, self.slope_y)]
        eta, su, sv = fields
        return eta, su * forward[0] + sv * left[0], su * forward[1] + sv * left[1]


def _bilinear(gx: NDArray, gy: NDArray, field: NDArray, u: NDArray, v: NDArray) -> NDArray:
    """``field`` [iy, ix] on the regular grid (gx, gy) at (u, v); zero outside the grid."""
    fx = (u - gx[0]) / (gx[1] - gx[0])
    fy = (v - gy[0]) / (gy[1] - gy[0])
    inside = (fx >= 0) & (fx <= len(gx) - 1) & (fy >= 0) & (fy <= len(gy) - 1)
    i = np.clip(np.floor(fx).astype(np.int64), 0, len(gx) - 2)
    j = np.clip(np.floor(fy).astype(np.int64), 0, len(gy) - 2)
    a, b = np.clip(fx - i, 0, 1), np.clip(fy - j, 0, 1)
    value = ((1 - a) * (1 - b) * field[j, i] + a * (1 - b) * field[j, i + 1]
             + (1 - a) * b * field[j + 1, i] + a * b * field[j + 1, i + 1])
    return np.where(inside, value, 0.0)


def submerged_source(vertices: NDArray, waterline_z: float = 0.0) -> WakeSource | None:
    """The hull below ``waterline_z`` as a pressure patch: its length, beam and draft [m]; None if it is dry.

    ``vertices`` (V, 3) [m] in the object's frame (x forward, y left, z up) at rest.
    """
    below = vertices[vertices[:, 2] < waterline_z]
    if len(below) < 2:
        return None
    length = float(np.ptp(below[:, 0]))
    beam = float(np.ptp(below[:, 1]))
    draft = float(waterline_z - below[:, 2].min())
    if min(length, beam, draft) <= 0:
        return None
    return WakeSource(length=length, beam=beam, draft=draft)


def ship_wake(source: WakeSource, speed: float, depth: float, heading: float,
              centre: Callable[[float], NDArray]) -> ShipWake:
    """The steady Kelvin wake of ``source`` moving at ``speed`` [m s⁻¹] over water of ``depth`` [m] (inf: deep).

    The grid spans :data:`WAKE_LENGTHS` hull lengths (200-4000 m) at the spacing that
    resolves every wave the hull excites (:func:`~.kelvin_wake.kelvin_wake_spacing`),
    at most :data:`MAX_WAKE_POINTS` per side.
    """
    size = float(np.clip(WAKE_LENGTHS * source.length, 200.0, 4000.0))
    spacing = kelvin_wake_spacing(source, speed, depth)
    points = int(min(MAX_WAKE_POINTS, 2 * math.ceil(size / spacing / 2)))
    x, y, eta = kelvin_wake_grid(source, speed, depth, size, points)
    slope_y, slope_x = np.gradient(eta, y, x)
    return ShipWake(x, y, eta, slope_x, slope_y, float(heading), centre)
