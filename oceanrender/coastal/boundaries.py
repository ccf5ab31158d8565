"""Sides of the shallow-water grid: reflective walls, transmissive sides and incident waves.

A side is one of three frozen dataclasses, chosen per side in :class:`Boundaries`:

* :class:`Wall` — impermeable and reflective: mirror ghost cells (depth and bed
  mirrored, normal discharge negated); the solver also sets the mass flux through
  a wall to exactly zero, so walls conserve mass to round-off.
* :class:`Transmissive` — zero-order extrapolation (ghost = first interior cell):
  what leaves the grid along the normal leaves without the side imposing anything.
* :class:`IncidentWave` — the open sea: a prescribed incident surface elevation
  η_in(t, x, y) (a monochromatic wave train or a sum of linear components drawn
  from the FFT sea's directional spectrum) enters, while waves leaving the grid go
  out through the same side. The ghost state comes from the two linear Riemann
  invariants normal to the side (an absorbing-generating boundary, [1]):

      w⁺ = u_n + √(g/d) η′   (runs into the grid: taken from the incident wave)
      w⁻ = u_n − √(g/d) η′   (runs out of the grid: taken from the first interior cell)

  with u_n the inward normal velocity, η′ = η − (still level) and d the still-water
  depth of the boundary cell. An IncidentWave without components is a pure
  absorbing (radiating) side that holds the mean level at its still level.

Geometry: cell (j, i) has its centre at x = (i + ½) dx, y = (j + ½) dy; the west
side is the line x = 0, east x = nx dx, south y = 0, north y = ny dy. Directions are
the directions the waves travel *toward*, counter-clockwise from +x (east), as for
the wind in :mod:`oceanrender.waves.wave_spectra`; a wave train travelling east
(direction 0) enters through the west side. The phase convention is that of the
open-sea modules, η = Σ a cos(k·x − ω t + φ).

:class:`BoundaryPlan` turns a :class:`Boundaries` into ghost values for the
solver's grid (bed ghosts once, water ghosts once per stage, O(nx + ny) work).

References
----------
.. [1] A. R. Van Dongeren and I. A. Svendsen, "Absorbing-generating boundary
   condition for shallow water models", J. Waterway, Port, Coastal, Ocean Eng.
   123(6), 303–313, 1997, doi:10.1061/(ASCE)0733-950X(1997)123:6(303).
.. [2] R. A. Flather, "A tidal model of the north-west European continental
   shelf", Mémoires de la Société Royale des Sciences de Liège 6(10), 141–164,
   1976 (the linear radiation condition u_n = u_ext − √(g/d)(η − η_ext) that the
   invariants above reduce to).
.. [3] E. F. Toro, "Shock-Capturing Methods for Free-Surface Shallow Flows",
   Wiley, 2001, ch. 14 (reflective and transmissive boundary conditions by ghost
   cells).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numba import njit
from numpy.typing import ArrayLike, NDArray

__all__ = [
    "SIDES",
    "Wall",
    "Transmissive",
    "IncidentWave",
    "Boundaries",
    "BoundaryPlan",
]

SIDES: tuple[str, ...] = ("west", "east", "south", "north")
"""Names of the four sides, in the order the solver indexes them."""

_GRAVITY = 9.81  # the solver's default g [m s⁻²]; kept here to avoid importing swe (which imports us)


@dataclass(frozen=True)
class Wall:
    """Impermeable, reflective side (free slip): mirror ghost cells, zero mass flux [3]."""


@dataclass(frozen=True)
class Transmissive:
    """Open side by zero-order extrapolation: the ghost cells copy the first interior cell [3].

    Notes
    -----
    A long wave leaving along the normal carries no incoming Riemann invariant,
    so copying the interior state lets it out with little reflection; waves
    leaving obliquely, and a mean level that drifts, are not controlled. Use an
    :class:`IncidentWave` without components (:meth:`IncidentWave.absorbing`) to
    hold the mean level.
    """


def _as_float_tuple(name: str, values: ArrayLike) -> tuple[float, ...]:
    array = np.atleast_1d(np.asarray(values, dtype=np.float64))
    if array.ndim != 1:
        raise ValueError(f"IncidentWave.{name} must be a 1-D sequence of numbers; got shape {array.shape}")
    if not np.all(np.isfinite(array)):
        raise ValueError(f"IncidentWave.{name} must be finite; got {array.tolist()}")
    return tuple(float(value) for value in array)


@dataclass(frozen=True)
class IncidentWave:
    """Waves entering through a side from the open sea; outgoing waves leave through it.

    The incident field is a sum of linear progressive waves

        η_in(x, y, t) = r(t) Σ_n a_n cos(k_n (x cos θ_n + y sin θ_n) − ω_n t + φ_n),

    evaluated on the side, and the side is an absorbing-generating boundary built
    on the linear Riemann invariants normal to it [1] (module docstring).

    Parameters
    ----------
    amplitudes : sequence of float
        Amplitudes a_n [m], ≥ 0.
    omegas : sequence of float
        Angular frequencies ω_n [rad s⁻¹], > 0.
    directions : sequence of float
        Directions θ_n the components travel toward, counter-clockwise from +x [rad].
    phases : sequence of float
        Phases φ_n [rad].
    still_level : float, optional
        Still-water level of the sea outside the side [m] (same datum as the bed).
    wavenumbers : sequence of float or None, optional
        Wavenumbers k_n [rad m⁻¹]. None uses the shallow-water wavenumber
        k_n = ω_n/√(g d̄) of the mean still depth d̄ of the side, so that each
        component enters in the direction θ_n; pass the open sea's own wavenumbers
        to match its phases along the side.
    ramp_time : float, optional
        Duration of the smooth start r(t) = ½(1 − cos(π t/T)) for t < T [s]; 0 for none.

    Notes
    -----
    The shallow-water equations carry long waves at √(g d) whatever their period:
    components shorter than a few depths enter with the right elevation on the side
    but then travel without dispersion. The depth-averaged velocity of each incident
    component is a_n ω_n/(k_n d) cos(…) along θ_n (linear theory, mass flux (ω/k) η).
    Outgoing waves are absorbed exactly only along the normal; oblique ones are
    partly reflected, as for every first-order characteristic boundary [1].
    """

    amplitudes: tuple[float, ...] = ()
    omegas: tuple[float, ...] = ()
    directions: tuple[float, ...] = ()
    phases: tuple[float, ...] = ()
    still_level: float = 0.0
    wavenumbers: tuple[float, ...] | None = None
    ramp_time: float = 0.0

    def __post_init__(self) -> None:
        names = ("amplitudes", "omegas", "directions", "phases")
        values = {name: _as_float_tuple(name, getattr(self, name)) for name in names}
        if self.wavenumbers is not None:
            values["wavenumbers"] = _as_float_tuple("wavenumbers", self.wavenumbers)
        counts = {name: len(value) for name, value in values.items()}
        if len(set(counts.values())) > 1:
            raise ValueError(f"IncidentWave component sequences must have equal lengths; got {counts}")
        if any(a < 0 for a in values["amplitudes"]):
            raise ValueError(f"IncidentWave.amplitudes must be >= 0 m; got {list(values['amplitudes'])}")
        if any(w <= 0 for w in values["omegas"]):
            raise ValueError(f"IncidentWave.omegas must be > 0 rad/s; got {list(values['omegas'])}")
        if "wavenumbers" in values and any(k <= 0 for k in values["wavenumbers"]):
            raise ValueError(f"IncidentWave.wavenumbers must be > 0 rad/m; got {list(values['wavenumbers'])}")
        for name in ("still_level", "ramp_time"):
            value = getattr(self, name)
            if not (isinstance(value, (int, float, np.floating)) and math.isfinite(value)):
                raise ValueError(f"IncidentWave.{name} must be a finite number; got {value!r}")
        if self.ramp_time < 0:
            raise ValueError(f"IncidentWave.ramp_time must be >= 0 s; got {self.ramp_time}")
        for name, value in values.items():
            object.__setattr__(self, name, value)
        object.__setattr__(self, "still_level", float(self.still_level))
        object.__setattr__(self, "ramp_time", float(self.ramp_time))

    @classmethod
    def wave_train(
        cls,
        amplitude: float,
        period: float,
        direction_deg: float = 0.0,
        still_level: float = 0.0,
        phase: float = 0.0,
        wavenumber: float | None = None,
        ramp_time: float = 0.0,
    ) -> IncidentWave:
        """A monochromatic linear wave train η = a cos(k·x − ω t + φ), ω = 2π/T.

        Parameters
        ----------
        amplitude : float
            Amplitude a [m].
        period : float
            Period T [s], > 0.
        direction_deg : float, optional
            Direction of travel, counter-clockwise from +x [°]; 0 enters through the west side.
        still_level : float, optional
            Still-water level [m].
        phase : float, optional
            Phase φ [rad].
        wavenumber : float or None, optional
            Wavenumber k [rad m⁻¹]; None for the shallow-water k = ω/√(g d̄).
        ramp_time : float, optional
            Smooth start duration [s].

        Returns
        -------
        IncidentWave
        """
        if not (math.isfinite(period) and period > 0):
            raise ValueError(f"IncidentWave.wave_train period must be > 0 s; got {period}")
        return cls(
            amplitudes=(amplitude,),
            omegas=(2.0 * math.pi / period,),
            directions=(math.radians(direction_deg),),
            phases=(phase,),
            still_level=still_level,
            wavenumbers=None if wavenumber is None else (wavenumber,),
            ramp_time=ramp_time,
        )

    @classmethod
    def from_components(
        cls,
        amplitudes: ArrayLike,
        omegas: ArrayLike,
        directions_rad: ArrayLike,
        phases: ArrayLike,
        still_level: float = 0.0,
        wavenumbers: ArrayLike | None = None,
        ramp_time: float = 0.0,
    ) -> IncidentWave:
        """A sum of linear waves, e.g. components drawn from the FFT sea's directional spectrum.

        Parameters
        ----------
        amplitudes : array_like
            Amplitudes a_n [m].
        omegas : array_like
            Angular frequencies ω_n [rad s⁻¹].
        directions_rad : array_like
            Directions of travel θ_n, counter-clockwise from +x [rad].
        phases : array_like
            Phases φ_n [rad], relative to the solver's origin (the SW corner of the grid).
        still_level : float, optional
            Still-water level [m].
        wavenumbers : array_like or None, optional
            Wavenumbers k_n [rad m⁻¹] (e.g. the open sea's); None for shallow-water ones.
        ramp_time : float, optional
            Smooth start duration [s].

        Returns
        -------
        IncidentWave
        """
        return cls(
            amplitudes=amplitudes,
            omegas=omegas,
            directions=directions_rad,
            phases=phases,
            still_level=still_level,
            wavenumbers=wavenumbers,
            ramp_time=ramp_time,
        )

    @classmethod
    def absorbing(cls, still_level: float = 0.0) -> IncidentWave:
        """An open side that lets waves out and holds the mean level (no incident wave) [2]."""
        return cls(still_level=still_level)

    def ramp(self, t: float) -> float:
        """Smooth-start factor r(t) ∈ [0, 1] [-]."""
        if self.ramp_time <= 0 or t >= self.ramp_time:
            return 1.0
        if t <= 0:
            return 0.0
        return 0.5 * (1.0 - math.cos(math.pi * t / self.ramp_time))

    def wavenumbers_for(self, depth: float, g: float = _GRAVITY) -> NDArray[np.float64]:
        """Wavenumbers k_n [rad m⁻¹] used at still depth ``depth`` [m] (explicit, or ω/√(g d))."""
        if self.wavenumbers is not None:
            return np.asarray(self.wavenumbers, dtype=np.float64)
        return np.asarray(self.omegas, dtype=np.float64) / math.sqrt(g * depth)

    def elevation(self, t: float, x: ArrayLike, y: ArrayLike, depth: float, g: float = _GRAVITY) -> NDArray[np.float64]:
        """Incident elevation η_in(x, y, t) − still level [m].

        Parameters
        ----------
        t : float
            Time [s].
        x, y : array_like
            Positions in the solver's frame [m] (broadcast together).
        depth : float
            Still depth d̄ that sets the shallow-water wavenumbers [m].
        g : float, optional
            Gravitational acceleration [m s⁻²].

        Returns
        -------
        ndarray
            η_in [m], the shape of x and y broadcast.
        """
        x, y = np.broadcast_arrays(np.asarray(x, dtype=np.float64), np.asarray(y, dtype=np.float64))
        if not self.amplitudes:
            return np.zeros(x.shape)
        k = self.wavenumbers_for(depth, g)
        theta = np.asarray(self.directions)
        phase = (
            k * (x[..., None] * np.cos(theta) + y[..., None] * np.sin(theta))
            - np.asarray(self.omegas) * t
            + np.asarray(self.phases)
        )
        return self.ramp(t) * np.sum(np.asarray(self.amplitudes) * np.cos(phase), axis=-1)


_SIDE_TYPES = (Wall, Transmissive, IncidentWave)


@dataclass(frozen=True)
class Boundaries:
    """The condition on each side of the grid (default: four walls).

    Parameters
    ----------
    west, east, south, north : Wall, Transmissive or IncidentWave
        Condition on the side x = 0, x = nx dx, y = 0 and y = ny dy respectively.
    """

    west: Wall | Transmissive | IncidentWave = Wall()
    east: Wall | Transmissive | IncidentWave = Wall()
    south: Wall | Transmissive | IncidentWave = Wall()
    north: Wall | Transmissive | IncidentWave = Wall()

    def __post_init__(self) -> None:
        for side in SIDES:
            value = getattr(self, side)
            if not isinstance(value, _SIDE_TYPES):
                raise ValueError(
                    f"Boundaries.{side} must be Wall(), Transmissive() or IncidentWave(...); got {value!r}"
                )

    def sides(self) -> tuple[Wall | Transmissive | IncidentWave, ...]:
        """The four conditions in the order of :data:`SIDES`."""
        return tuple(getattr(self, side) for side in SIDES)


class _IncidentSide:
    """Precomputed incident forcing on one side: η_in(t) and u_n,in(t) as complex sums."""

    def __init__(self, wave: IncidentWave, x, y, z0, inward_angle, h_dry, g):
        self.wave = wave
        self.still = wave.still_level
        self.depth = wave.still_level - z0  # still depth of the boundary cells [m]
        self.wet = self.depth > h_dry
        depth = np.where(self.wet, self.depth, 1.0)
        self.root = np.where(self.wet, np.sqrt(g / depth), 0.0)  # √(g/d) [s⁻¹]
        n = len(wave.amplitudes)
        if n and np.any(self.wet):
            mean_depth = float(np.mean(self.depth[self.wet]))
            k = wave.wavenumbers_for(mean_depth, g)
            theta = np.asarray(wave.directions)
            omega = np.asarray(wave.omegas)
            amplitude = np.asarray(wave.amplitudes)
            phase = k[:, None] * (np.cos(theta)[:, None] * x[None, :] + np.sin(theta)[:, None] * y[None, :])
            phase += np.asarray(wave.phases)[:, None]
            carrier = amplitude[:, None] * np.exp(1j * phase)  # a e^{i(k·x + φ)}
            self.eta_coefficients = carrier
            # linear theory: depth-averaged velocity (ω/(k d)) η along θ; its inward normal part
            normal = np.cos(theta - inward_angle)
            self.u_coefficients = carrier * ((omega / k) * normal)[:, None] / depth[None, :]
            self.omega = omega
        else:
            self.eta_coefficients = None

    def forcing(self, t: float) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """(η_in, u_n,in) on the side's cells at time t [m], [m s⁻¹]."""
        if self.eta_coefficients is None:
            zeros = np.zeros(self.depth.shape)
            return zeros, zeros
        clock = np.exp(-1j * self.omega * t) * self.wave.ramp(t)
        # NOTE: einsum's own loop, not BLAS: a threaded BLAS call between the solver's stages competes
        # with the solver's threads (measured 16 ms instead of 0.2 ms per call for 442 × 400 terms).
        return (np.einsum("n,ns->s", clock, self.eta_coefficients).real,
                np.einsum("n,ns->s", clock, self.u_coefficients).real)


class BoundaryPlan:
    """Ghost cells for one grid: bed ghosts (fixed) and water ghosts (filled per stage).

    Parameters
    ----------
    boundaries : Boundaries
        Condition on each side.
    bed : ndarray, shape (ny, nx)
        Bed elevation z_b at the cell centres [m].
    dx, dy : float
        Cell sizes [m].
    g : float
        Gravitational acceleration [m s⁻²].
    h_dry : float
        Depth at or below which a cell is dry [m].
    layers : int
        Number K of ghost layers (1 for first order, 2 for second order).

    Attributes
    ----------
    zpad : ndarray, shape (ny + 2K, nx + 2K)
        Bed with its ghost cells [m].
    walls : ndarray of int64, shape (4,)
        1 where the side (order of :data:`SIDES`) is a wall: the solver zeroes the
        mass flux there.

    Notes
    -----
    Ghost arrays: ``columns`` (2, 3, K, ny) for west/east and ``rows`` (2, 3, K, nx)
    for south/north; axis 1 is (h, hu, hv), layer 0 touches the grid. Walls mirror
    layer k to interior cell k; transmissive and incident sides give every layer the
    same state.
    """

    def __init__(self, boundaries: Boundaries, bed: NDArray[np.float64], dx: float, dy: float, g: float,
                 h_dry: float, layers: int):
        ny, nx = bed.shape
        self.shape = (ny, nx)
        self.layers = K = int(layers)
        self.sides = boundaries.sides()
        self.kinds = np.array([_SIDE_TYPES.index(type(side)) for side in self.sides], dtype=np.int64)
        self.walls = (self.kinds == 0).astype(np.int64)
        self.h_dry = float(h_dry)
        self._constants = (self.h_dry, 1.5 * g, 1.0 / dx, 1.0 / dy)
        xc = (np.arange(nx) + 0.5) * dx
        yc = (np.arange(ny) + 0.5) * dy
        geometry = {  # side: (x, y of the face points, bed of the first interior cells, inward normal angle)
            "west": (np.zeros(ny), yc, bed[:, 0], 0.0),
            "east": (np.full(ny, nx * dx), yc, bed[:, nx - 1], math.pi),
            "south": (xc, np.zeros(nx), bed[0, :], 0.5 * math.pi),
            "north": (xc, np.full(nx, ny * dy), bed[ny - 1, :], -0.5 * math.pi),
        }
        # per side: still depth d, √(g/d), η_in, u_n,in of the boundary cells (incident sides only)
        self.incident_columns = np.zeros((2, 4, ny))
        self.incident_rows = np.zeros((2, 4, nx))
        self._incident = {}
        for index, (name, side) in enumerate(zip(SIDES, self.sides)):
            if isinstance(side, IncidentWave):
                x, y, z0, angle = geometry[name]
                forcing = _IncidentSide(side, x, y, z0.copy(), angle, self.h_dry, g)
                target = self.incident_columns[index] if index < 2 else self.incident_rows[index - 2]
                target[0] = forcing.depth
                target[1] = forcing.root
                self._incident[index] = (forcing, target)
        # bed with ghosts: mirrored at walls, copied from the first cell elsewhere
        zpad = np.empty((ny + 2 * K, nx + 2 * K))
        zpad[K:K + ny, K:K + nx] = bed
        for k in range(K):
            west, east, south, north = (k if isinstance(s, Wall) else 0 for s in self.sides)
            zpad[K:K + ny, K - 1 - k] = bed[:, west]
            zpad[K:K + ny, K + nx + k] = bed[:, nx - 1 - east]
            zpad[K - 1 - k, K:K + nx] = bed[south, :]
            zpad[K + ny + k, K:K + nx] = bed[ny - 1 - north, :]
        # corners are never used by a flux; keep them finite
        zpad[:K, :K] = zpad[K, K]
        zpad[:K, K + nx:] = zpad[K, K + nx - 1]
        zpad[K + ny:, :K] = zpad[K + ny - 1, K]
        zpad[K + ny:, K + nx:] = zpad[K + ny - 1, K + nx - 1]
        self.zpad = np.ascontiguousarray(zpad)

    def new_ghosts(self) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """Zeroed ghost arrays (columns (2, 3, K, ny), rows (2, 3, K, nx)) for :meth:`fill`."""
        ny, nx = self.shape
        return np.zeros((2, 3, self.layers, ny)), np.zeros((2, 3, self.layers, nx))

    def fill(self, t: float, h: NDArray[np.float64], hu: NDArray[np.float64], hv: NDArray[np.float64],
             columns: NDArray[np.float64], rows: NDArray[np.float64]) -> float:
        """Fill the water ghosts of the state (h, hu, hv) at time t in place.

        Parameters
        ----------
        t : float
            Time of the state [s] (drives incident waves).
        h, hu, hv : ndarray, shape (ny, nx)
            Depth [m] and discharges [m² s⁻¹] of the interior cells.
        columns, rows : ndarray
            Ghost arrays from :meth:`new_ghosts`, overwritten.

        Returns
        -------
        float
            Largest CFL speed sum (|u| + a)/Δx + (|v| + a)/Δy of the ghost cells [s⁻¹].
        """
        for forcing, target in self._incident.values():
            target[2], target[3] = forcing.forcing(t)
        return _fill_ghosts(self.kinds, self.incident_columns, self.incident_rows, h, hu, hv,
                            columns, rows, *self._constants)


@njit(cache=True, error_model="numpy")
def _fill_ghosts(kinds, incident_columns, incident_rows, h, hu, hv, columns, rows, h_dry, g15, rdx, rdy):
    """Ghost states of the four sides (module docstring); returns the ghosts' largest CFL speed sum."""
    ny, nx = h.shape
    K = columns.shape[2]
    smax = 0.0
    for side in range(4):
        kind = kinds[side]
        if side < 2:
            n = ny
            dest = columns[side]
            incident = incident_columns[side]
            n_index, t_index = 1, 2  # normal discharge hu, tangential hv
            rn, rt = rdx, rdy
        else:
            n = nx
            dest = rows[side - 2]
            incident = incident_rows[side - 2]
            n_index, t_index = 2, 1
            rn, rt = rdy, rdx
        sign = 1.0 if side % 2 == 0 else -1.0  # inward normal along +axis (west, south) or −axis
        for s in range(n):
            for k in range(K):
                layer = k if kind == 0 else 0
                if side == 0:
                    j, i = s, layer
                elif side == 1:
                    j, i = s, nx - 1 - layer
                elif side == 2:
                    j, i = layer, s
                else:
                    j, i = ny - 1 - layer, s
                hh = h[j, i]
                qn = hu[j, i] if side < 2 else hv[j, i]
                qt = hv[j, i] if side < 2 else hu[j, i]
                gh, gn, gt = hh, qn, qt
                if kind == 0:  # wall: mirror
                    gn = -qn
                elif kind == 2 and incident[0, s] > h_dry:
                    # absorbing-generating side: linear Riemann invariants normal to the side [1]
                    depth = incident[0, s]
                    root = incident[1, s]  # √(g/d)
                    wet = hh > h_dry
                    un = sign * qn / hh if wet else 0.0
                    ut = qt / hh if wet else 0.0
                    w_out = un - root * (hh - depth)  # w⁻ = u_n − √(g/d) η′, from the interior
                    w_in = incident[3, s] + root * incident[2, s]  # w⁺ = u_n,in + √(g/d) η_in
                    gh = max(0.0, depth + 0.5 * (w_in - w_out) / root)  # η′_g = (w⁺ − w⁻)/(2√(g/d))
                    gn = sign * gh * 0.5 * (w_in + w_out)  # u_n,g = (w⁺ + w⁻)/2
                    gt = gh * ut
                elif kind == 2:  # NOTE: a side that is dry at still level cannot let waves in: a wall
                    gn = -qn
                dest[0, k, s] = gh
                dest[n_index, k, s] = gn
                dest[t_index, k, s] = gt
            gh = dest[0, 0, s]
            if gh > h_dry:
                a = math.sqrt(g15 * gh)
                speed = (abs(dest[n_index, 0, s]) / gh + a) * rn + (abs(dest[t_index, 0, s]) / gh + a) * rt
                smax = max(smax, speed)
    return smax
