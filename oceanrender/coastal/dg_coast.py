"""The DG scheme behind a scene's coast: ``[coastal] scheme = "dg"`` (issue 44).

:class:`DGCoastSolver` gives :class:`.dg2d.DGSolver2D` the interface of
:class:`.swe.ShallowWaterSolver` that :mod:`.simulation` drives — ``advance(state, t_end)``
landing exactly on t_end, ``cell_updates`` — with the same sides (walls, transmissive,
incident waves, the open sea's long waves through :func:`.inputs.boundaries`) and Manning
friction. Its state is a :class:`P1State`: the cell means h, hu, hv of :class:`.swe.State`
(what frames store and the renderer reads) plus the P1 slopes, which checkpoints keep so
that a resumed run continues bit for bit.

The scene gives the bed at cell centres; the DG bed is bilinear through the cell corners
(:func:`corners_from_centres`: each interior corner the mean of its four centres, the
centres first extended by one linear layer so that a plane bed stays exact), projected on
P1. Frames store that P1 bed's cell means, so h + bed is the scheme's own surface.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .dg2d import DG2DParams, DGSolver2D, DGState2D, lake_at_rest_dg2d, p1_bed
from .swe import State

__all__ = ["P1State", "DGCoastSolver", "corners_from_centres", "p1_initial_state"]


@dataclass
class P1State(State):
    """A :class:`.swe.State` (cell means) with the P1 slopes of the DG scheme.

    slopes : ndarray (3, 2, ny, nx)
        The ξ and η coefficients of h [m], hu and hv [m² s⁻¹] per cell (values at the cell's faces: mean ± slope).
    """

    slopes: NDArray[np.float64] | None = None

    def __post_init__(self) -> None:
        super().__post_init__()
        expected = (3, 2) + self.h.shape
        if self.slopes is None:
            self.slopes = np.zeros(expected)
        self.slopes = np.ascontiguousarray(self.slopes, dtype=np.float64)
        if self.slopes.shape != expected:
            raise ValueError(f"P1State.slopes must have shape {expected}; got {self.slopes.shape}")

    def copy(self) -> "P1State":
        return P1State(self.h.copy(), self.hu.copy(), self.hv.copy(), self.t, self.slopes.copy())

    def coefficients(self) -> NDArray[np.float64]:
        """(3, 3, ny, nx): per variable (h, hu, hv) the mean, ξ and η coefficients."""
        return np.concatenate([np.stack([self.h, self.hu, self.hv])[:, None], self.slopes], axis=1)

    def assign(self, c: NDArray[np.float64], t: float) -> None:
        """Take the coefficients c (3, 3, ny, nx) and time t [s], in place (the arrays keep their identity)."""
        np.copyto(self.h, c[0, 0])
        np.copyto(self.hu, c[1, 0])
        np.copyto(self.hv, c[2, 0])
        np.copyto(self.slopes, c[:, 1:])
        self.t = float(t)


def corners_from_centres(bed: ArrayLike) -> NDArray[np.float64]:
    """Bed elevation at the cell corners (ny + 1, nx + 1) [m] from its values at the centres (ny, nx) [m].

    The centres are extended by one layer on each side linearly (2 z₀ − z₁), then every corner is the mean
    of the four centres around it: exact for a bed linear in x and y, second order for a smooth one.
    """
    z = np.asarray(bed, dtype=np.float64)
    pad = np.pad(z, 1, mode="reflect", reflect_type="odd")  # 2 z_edge − z_inner: the linear extension
    return 0.25 * (pad[:-1, :-1] + pad[:-1, 1:] + pad[1:, :-1] + pad[1:, 1:])


def p1_initial_state(corners: NDArray, surface: NDArray | float, u: NDArray, v: NDArray, h_dry: float) -> P1State:
    """The P1 state of water at rest at a level, or at a given surface, moving with (u, v) [m s⁻¹].

    ``surface``: a float [m] is a still level — the exact lake at rest over the P1 bed
    (:func:`.dg2d.lake_at_rest_dg2d`); an array (ny, nx) [m] is a surface per cell, taken as
    the cell mean depth max(0, η − z̄_b) with flat slopes. Discharges are u h and v h on
    every coefficient (cells with a mean depth ≤ h_dry [m] get none).
    """
    if np.ndim(surface) == 0:
        c = lake_at_rest_dg2d(corners, float(surface)).c
    else:
        bed = p1_bed(np.asarray(corners, dtype=np.float64))
        c = np.zeros((3, 3) + bed.shape[1:])
        c[0, 0] = np.maximum(0.0, np.asarray(surface, dtype=np.float64) - bed[0])
    wet = c[0, 0] > h_dry
    for var, velocity in ((1, u), (2, v)):
        c[var] = np.where(wet, np.asarray(velocity, dtype=np.float64) * c[0], 0.0)
    return P1State(c[0, 0].copy(), c[1, 0].copy(), c[2, 0].copy(), 0.0, np.ascontiguousarray(c[:, 1:]))


class DGCoastSolver:
    """RKDG P1 (:mod:`.dg2d`) with the interface :mod:`.simulation` drives (module docstring).

    Parameters
    ----------
    corners : array_like (ny + 1, nx + 1)
        Bed elevation at the cell corners [m].
    params : DG2DParams
        Grid, Courant number ν ≤ 1/3, limiter, dry depth, Manning's n, the sides (``boundaries``).

    Attributes
    ----------
    bed : ndarray (ny, nx)
        The P1 bed's cell means [m] (what frames store).
    cell_updates : int
        Cells × steps so far.
    """

    def __init__(self, corners: ArrayLike, params: DG2DParams) -> None:
        self.core = DGSolver2D(corners, params)
        self.bed = np.ascontiguousarray(self.core.bed[0])
        self.shape = self.bed.shape
        self.params = params

    @property
    def cell_updates(self) -> int:
        return self.core.cell_updates

    @property
    def clamped_volume(self) -> float:
        """Water [m³] the positivity limiter's last resort removed (zero within ν ≤ 1/3)."""
        return self.core.clamped_volume

    def advance(self, state: P1State, t_end: float) -> P1State:
        """Advance to t_end [s] exactly, in place; returns ``state``.

        Raises
        ------
        ValueError
            Before any work: not a P1State of the grid's shape, non-finite or negative depths, t_end < state.t.
        FloatingPointError
            The state stopped being finite.
        """
        if not isinstance(state, P1State) or state.h.shape != self.shape:
            raise ValueError(f"state must be a P1State of shape {self.shape}; got {type(state).__name__}")
        c = state.coefficients()
        if not np.all(np.isfinite(c)):
            raise ValueError("state holds non-finite values; refusing to advance")
        if np.any(state.h < 0.0):
            raise ValueError("state.h holds negative depths; refusing to advance")
        if not (np.isfinite(t_end) and t_end >= state.t):
            raise ValueError(f"t_end must be finite and >= state.t = {state.t}; got {t_end}")
        s = DGState2D(c, state.t)
        self.core.advance(s, float(t_end))
        state.assign(s.c, s.t)
        return state
