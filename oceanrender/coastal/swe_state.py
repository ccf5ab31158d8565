"""The shallow-water solver's settings and state: constants, :class:`SolverParams`, :class:`State`, :func:`lake_at_rest`.

Part of the solver of :mod:`.swe`, whose docstring gives the equations, the schemes and the references [1]–[15]
cited here.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .boundaries import Boundaries

G: float = 9.81
"""Default gravitational acceleration [m s⁻²]."""

CFL_BOUND: dict[int, float] = {1: 1.0, 2: 0.5}
"""Largest Courant number ν per order for which the scheme keeps depths ≥ 0 (module docstring)."""

LIMITERS: dict[str, int] = {"minmod": 0, "MC": 1, "van Leer": 2}
"""Slope limiters of the second-order reconstruction, by name (module docstring; the value is the kernel's code)."""

SCHEMES: dict[str, str] = {
    "kinetic": "kinetic flux + hydrostatic reconstruction, MUSCL on (h, u, v, η), Heun, unsplit",
    "HLL split": "HLLE flux + hydrostatic reconstruction, MUSCL on (h, u, v, η), Heun, Strang-split sweeps",
    "kinetic split": "kinetic flux + hydrostatic reconstruction, Strang-split sweeps of one stage each: "
                     "first order (order 1) or MUSCL–Hancock with a positivity fallback (order 2)",
}
"""Schemes, by name (module docstring); the first is the default. At first order "kinetic split"
selects the split first-order sweeps and every other name the unsplit kinetic scheme."""

SPLIT_CFL_BOUND: float = 1.0
"""Largest Courant number ν of each sweep of "kinetic split", at both orders (module docstring)."""

H_FLOOR: float = 1e-10
"""Depth [m] at or below which a cell is dry even when h_min = 0, so hu/h is never formed from round-off."""

PARALLEL_MIN_CELLS: int = 65536
"""Grids with fewer cells run on one thread: starting the thread pool costs more than it saves."""


def _finite_number(name: str, value) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise ValueError(f"SolverParams.{name} must be a number; got {value!r}")
    value = float(value)
    if not math.isfinite(value):
        raise ValueError(f"SolverParams.{name} must be finite; got {value}")
    return value


@dataclass(frozen=True)
class SolverParams:
    """Numerical and physical parameters of :class:`ShallowWaterSolver`, validated on creation.

    Parameters
    ----------
    dx, dy : float
        Cell sizes in x and y [m], > 0.
    order : int, optional
        1 (first-order kinetic scheme) or 2 (limited reconstruction + Heun; ``scheme``).
    cfl : float, optional
        Courant number ν [-] of the time step (module docstring), in (0, 1] at first
        order and (0, ½] at second order (:data:`CFL_BOUND`), (0, 1] at both orders for
        "kinetic split" (:data:`SPLIT_CFL_BOUND`; 0.9 recommended); for the split schemes
        ν is the Courant number of each sweep on its own direction's speed.
    h_min : float, optional
        Dry threshold and resting film [m], ≥ 0: cells with h ≤ h_min are land.
    manning : float, optional
        Manning coefficient n [s m^-1/3], ≥ 0 (0: no friction).
    g : float, optional
        Gravitational acceleration [m s⁻²], > 0.
    boundaries : Boundaries, optional
        Condition on each side (default: four walls).
    limiter : str, optional
        Slope limiter of the second-order reconstruction, a key of :data:`LIMITERS`
        ("minmod", "MC", "van Leer"); ignored at first order. Default MC: about 2–3 times
        lower L1 error than minmod on the validation cases at the same cost (docs/coastal.md).
    scheme : str, optional
        A key of :data:`SCHEMES`: "kinetic" (default; the unsplit kinetic scheme, ν on
        the sum of both directions' speeds |u| + √(3gh/2)), "HLL split" (order 2: HLLE
        flux, sweeps x y y x of Δt/2 each, two Heun stages per sweep at ν ≤ ½ on its own
        direction's speed |u| + √(gh)) or "kinetic split" (either order: the kinetic flux,
        sweeps x y y x of Δt/2 of one stage each at ν ≤ 1 on |u| + √(3gh/2) of the sweep's
        direction, first order or MUSCL–Hancock, Eqs. (10)–(12)). At first order
        "HLL split" selects the unsplit kinetic scheme. docs/coastal.md compares them.

    Raises
    ------
    ValueError
        One line naming the field, the accepted range and the value received.
    """

    dx: float
    dy: float
    order: int = 1
    cfl: float = 0.45
    h_min: float = 1e-3
    manning: float = 0.0
    g: float = G
    boundaries: Boundaries = Boundaries()
    limiter: str = "MC"
    scheme: str = "kinetic"

    def __post_init__(self) -> None:
        for name in ("dx", "dy", "g"):
            if not _finite_number(name, getattr(self, name)) > 0:
                raise ValueError(f"SolverParams.{name} must be > 0; got {getattr(self, name)}")
        if isinstance(self.order, bool) or self.order not in (1, 2):
            raise ValueError(f"SolverParams.order must be 1 or 2; got {self.order!r}")
        if not isinstance(self.scheme, str) or self.scheme not in SCHEMES:
            raise ValueError(f"SolverParams.scheme must be one of {sorted(SCHEMES)}; got {self.scheme!r}")
        bound = self.cfl_bound
        cfl = _finite_number("cfl", self.cfl)
        if not 0 < cfl <= bound:
            raise ValueError(
                f"SolverParams.cfl must be in (0, {bound}] for order {self.order} with scheme {self.scheme!r} "
                f"(the scheme's positivity bound); got {self.cfl}"
            )
        for name in ("h_min", "manning"):
            if _finite_number(name, getattr(self, name)) < 0:
                raise ValueError(f"SolverParams.{name} must be >= 0; got {getattr(self, name)}")
        if not isinstance(self.limiter, str) or self.limiter not in LIMITERS:
            raise ValueError(f"SolverParams.limiter must be one of {sorted(LIMITERS)}; got {self.limiter!r}")
        if not isinstance(self.boundaries, Boundaries):
            raise ValueError(f"SolverParams.boundaries must be a Boundaries instance; got {self.boundaries!r}")

    @property
    def split(self) -> bool:
        """True when the steps are the dimensionally split sweeps of the "HLL split" scheme (order 2)."""
        return int(self.order) == 2 and self.scheme == "HLL split"

    @property
    def kinetic_split(self) -> bool:
        """True when the steps are the one-stage kinetic sweeps of "kinetic split" (either order)."""
        return self.scheme == "kinetic split"

    @property
    def cfl_bound(self) -> float:
        """Largest accepted Courant number: :data:`CFL_BOUND` of the order, or :data:`SPLIT_CFL_BOUND` [-]."""
        return SPLIT_CFL_BOUND if self.scheme == "kinetic split" else CFL_BOUND[int(self.order)]

    @property
    def h_dry(self) -> float:
        """Depth at or below which a cell is dry, max(h_min, :data:`H_FLOOR`) [m]."""
        return max(float(self.h_min), H_FLOOR)


def _grid_array(name: str, value: ArrayLike) -> NDArray[np.float64]:
    """A float64, C-contiguous 2-D array; the input itself when it already is one (no copy)."""
    array = np.asarray(value)
    if array.ndim != 2:
        raise ValueError(f"State.{name} must be a 2-D array (ny, nx); got shape {array.shape}")
    if array.dtype != np.float64 or not array.flags.c_contiguous or not array.flags.writeable:
        array = np.array(array, dtype=np.float64, order="C")
    return array


@dataclass
class State:
    """Cell averages on the uniform grid, arrays of shape (ny, nx), float64, C-contiguous.

    Parameters
    ----------
    h : ndarray
        Water depth [m].
    hu, hv : ndarray
        Discharges per unit width along x and y [m² s⁻¹].
    t : float, optional
        Time [s].

    Notes
    -----
    Arrays that are already float64, C-contiguous and writeable are kept as given
    (the solver updates them in place); others are copied once on creation.
    """

    h: NDArray[np.float64]
    hu: NDArray[np.float64]
    hv: NDArray[np.float64]
    t: float = 0.0

    def __post_init__(self) -> None:
        self.h = _grid_array("h", self.h)
        self.hu = _grid_array("hu", self.hu)
        self.hv = _grid_array("hv", self.hv)
        if not self.h.shape == self.hu.shape == self.hv.shape:
            raise ValueError(
                f"State arrays must share one shape; got h {self.h.shape}, hu {self.hu.shape}, hv {self.hv.shape}"
            )
        self.t = float(self.t)

    def copy(self) -> State:
        """An independent copy."""
        return State(self.h.copy(), self.hu.copy(), self.hv.copy(), self.t)

    def surface(self, bed: ArrayLike) -> NDArray[np.float64]:
        """Free-surface elevation η = z_b + h [m] (on dry land: the bed plus its film)."""
        return np.asarray(bed, dtype=np.float64) + self.h

    def velocities(self, h_min: float) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """Depth-averaged velocities (u, v) [m s⁻¹], exactly 0 in dry cells (h ≤ max(h_min, H_FLOOR))."""
        wet = self.h > max(float(h_min), H_FLOOR)
        depth = np.where(wet, self.h, 1.0)
        return np.where(wet, self.hu / depth, 0.0), np.where(wet, self.hv / depth, 0.0)

    def volume(self, dx: float, dy: float) -> float:
        """Water volume Σ h Δx Δy [m³] (compensated sum)."""
        return math.fsum(self.h.ravel()) * dx * dy


def lake_at_rest(bed: ArrayLike, level: float, h_min: float) -> State:
    """A lake at rest at the surface level ``level`` over ``bed``, land covered by the film h_min.

    Parameters
    ----------
    bed : array_like, shape (ny, nx)
        Bed elevation z_b [m].
    level : float
        Still-water surface elevation [m].
    h_min : float
        Dry threshold / resting film [m], ≥ 0.

    Returns
    -------
    State
        h = max(level − z_b, h_min), hu = hv = 0, t = 0.

    Notes
    -----
    Where the cell is wet, h is nudged by a few ulps so that the computed z_b + h
    equals ``level`` exactly where a double allows it (always for level = 0); the
    kinetic scheme with hydrostatic reconstruction then keeps the lake at rest bit for
    bit. Where no double h does (h has coarser spacing than the level), z_b + h is
    off by one ulp of the level and the lake keeps velocities of order 1e-15 m/s.
    """
    bed = np.asarray(bed, dtype=np.float64)
    level, h_min = float(level), float(h_min)
    if not (math.isfinite(level) and math.isfinite(h_min) and h_min >= 0):
        raise ValueError(f"lake_at_rest needs a finite level and h_min >= 0; got level={level}, h_min={h_min}")
    depth = level - bed
    wet = depth > max(h_min, H_FLOOR)
    h = np.where(wet, depth, h_min)
    # of the doubles h − 2 ulp … h + 2 ulp keep the one whose computed z_b + h is nearest the level
    candidates = [h]
    for direction in (-np.inf, np.inf):
        step = h
        for _ in range(2):
            step = np.nextafter(step, direction)
            candidates.append(step)
    candidates = np.stack(candidates)
    best = np.argmin(np.abs((candidates + bed) - level), axis=0)
    h = np.where(wet, np.take_along_axis(candidates, best[None], axis=0)[0], h)
    zeros = np.zeros_like(h)
    return State(h, zeros, zeros.copy())
