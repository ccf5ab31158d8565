"""Two-dimensional shallow-water equations over bathymetry: state, kinetic flux-vector splitting, stepping.

The model (the issue's "dissertation eq. 1") for the depth h [m] and the discharges
hu, hv [m² s⁻¹] over the bed z_b(x, y) [m], with Manning friction of coefficient n
[s m^-1/3]::

    ∂t h  + ∂x(hu)             + ∂y(hv)             = 0                                   (1a)
    ∂t hu + ∂x(hu² + g h²/2)   + ∂y(huv)            = −g h ∂x z_b − g n² u|u| / h^(1/3)   (1b)
    ∂t hv + ∂x(huv)            + ∂y(hv² + g h²/2)   = −g h ∂y z_b − g n² v|u| / h^(1/3)   (1c)

Scheme (details, the reasons for each choice and the measured validation are in
docs/coastal.md, section "Solver"):

* **Flux: kinetic flux-vector splitting** [1]. Equations (1) without sources are the
  isentropic Euler equations of a γ = 2 gas (ρ = h, p = g h²/2) closed by the energy
  equation; kinetic flux-vector splitting, the gas-dynamics splitting of [3] written
  for shallow water in [1], is our reading of the dissertation's "flux-vector
  splitting of the system extended by the energy equation" (its eqs. 5–12 are not
  available to us). (h, hu) and the momentum flux hu² + g h²/2 are moments of a
  particle density M(ξ), and the interface flux is split by the sign of the particle
  velocity ξ, F = F⁺(U_L) + F⁻(U_R). With the compactly supported ("uniform")
  Maxwellian of [1]

      M(ξ) = h/(2a) for |ξ − u| ≤ a,  a = √(3 g h / 2),                               (2)

  ∫M = h, ∫ξM = hu, ∫ξ²M = hu² + g h²/2, and the half-fluxes are closed forms with
  α = min(0, u − a), β = min(0, u + a)::

      F⁻_h  = h (β² − α²) / (4a),    F⁻_hu = h (β³ − α³) / (6a),                       (3)
      F⁺ = F(U) − F⁻(U),    F_h,hv = F⁺_h(U_L) v_L + F⁻_h(U_R) v_R   (transverse, upwind).  (4)

* **Well balanced and depth positive: hydrostatic reconstruction** [2]. At each
  interface z* = max(z_L, z_R) and h*_L,R = max(0, η_L,R − z*) with η = h + z_b;
  the flux is evaluated between the reconstructed states U* = (h*, h* u, h* v), and
  the cell on each side adds the pressure difference g/2 (h² − h*²) of its side::

      U_i^{n+1} = U_i − Δt/Δx (F_{i+½}^{(i)} − F_{i−½}^{(i)}) − (same in y),
      F_{i+½}^{(i)} = F(U*_L, U*_R) + (0, g/2 (h_i² − h*_L²), 0).                      (5)

  A lake at rest (η constant, u = v = 0) makes h*_L = h*_R at every interface, so
  every flux and pressure difference is zero: it stays at rest exactly (bit for bit
  when η = h + z_b is the same double in every wet cell, as :func:`lake_at_rest`
  arranges).
* **Wet/dry "through computation"**: cells with h ≤ h_min are dry (land). Their water
  is a resting film held by bottom friction: for the fluxes it is part of the bed
  (effective bed z_b + h, mobile depth 0, u = v = 0), so it never flows out; dry
  cells can be flooded, and their discharges are set to exactly 0 after every
  update, so no dry cell ever carries a velocity.
* **Second order** (``order=2``): piecewise-linear reconstruction of (h, u, v, η)
  with limited slopes (MC [7] by default; van Leer [8] or minmod [5]), face beds
  z_f = η_f − h_f, the centred source −g h_i Δη_i/Δx that keeps (5) well balanced
  [2], and Heun's two-stage strong-stability-preserving Runge–Kutta method [4]: the
  finite-volume form of the dissertation's P1 + RK2 + minmod, with minmod an option
  (docs/coastal.md explains the choice over DG-P1 and MUSCL–Hancock).
* **Friction**: semi-implicit Manning [6], q^{n+1} = q* / (1 + Δt g n² |u*| / h^{4/3}),
  unconditionally stable and zero-preserving in thin layers.
* **Time step**: Δt = ν / max_i[(|u_i| + a_i)/Δx + (|v_i| + a_i)/Δy] with the kinetic
  speed a = √(3gh/2) of (2). The outflow of a cell through its four faces is then at
  most ν times its water, so depths stay ≥ 0 for ν ≤ 1 at first order [1, 2] and for
  ν ≤ ½ at second order (the cell average is the mean of its two face values in
  each direction, every face value is ≥ 0, and two Heun stages are convex
  combinations of Euler steps; the step is checked against the reconstructed face
  speeds): :data:`CFL_BOUND`. Positivity alone would allow the mean particle speed
  E|ξ| ≥ a/2 instead of |u| + a, but linear stability needs the largest one (the
  kinetic flux diffuses the normal momentum with coefficient a), and the unsplit
  update needs the sum over the two directions (docs/coastal.md).
* **Limiters** (second order, :data:`LIMITERS`): minmod [5] (default, the
  dissertation's), monotonized central (MC) [7] and van Leer's harmonic one [8].
  All three vanish at extrema and are at most twice the smaller one-sided
  difference, so face depths stay ≥ 0 and the positivity bound ν ≤ ½ is unchanged;
  MC and van Leer clip smooth crests and sharpen fronts less than minmod.

Equation numbers in the comments refer to the list above.

References
----------
.. [1] B. Perthame and C. Simeoni, "A kinetic scheme for the Saint-Venant system
   with a source term", Calcolo 38(4), 201–231, 2001, doi:10.1007/s10092-001-8181-3.
.. [2] E. Audusse, F. Bouchut, M.-O. Bristeau, R. Klein and B. Perthame, "A fast and
   stable well-balanced scheme with hydrostatic reconstruction for shallow water
   flows", SIAM J. Sci. Comput. 25(6), 2050–2065, 2004, doi:10.1137/S1064827503431090.
.. [3] J. C. Mandal and S. M. Deshpande, "Kinetic flux vector splitting for Euler
   equations", Computers & Fluids 23(2), 447–478, 1994,
   doi:10.1016/0045-7930(94)90050-7.
.. [4] C.-W. Shu and S. Osher, "Efficient implementation of essentially
   non-oscillatory shock-capturing schemes", J. Comput. Phys. 77(2), 439–471, 1988,
   doi:10.1016/0021-9991(88)90177-5.
.. [5] B. van Leer, "Towards the ultimate conservative difference scheme. V. A
   second-order sequel to Godunov's method", J. Comput. Phys. 32(1), 101–136, 1979,
   doi:10.1016/0021-9991(79)90145-1.
.. [6] A. Chertock, S. Cui, A. Kurganov and T. Wu, "Well-balanced positivity
   preserving central-upwind scheme for the shallow water system with friction
   terms", Int. J. Numer. Meth. Fluids 78, 355–383, 2015, doi:10.1002/fld.4023.
.. [7] B. van Leer, "Towards the ultimate conservative difference scheme. IV. A new
   approach to numerical convection", J. Comput. Phys. 23(3), 276–299, 1977,
   doi:10.1016/0021-9991(77)90095-X.
.. [8] B. van Leer, "Towards the ultimate conservative difference scheme. II.
   Monotonicity and conservation combined in a second-order scheme", J. Comput.
   Phys. 14(4), 361–370, 1974, doi:10.1016/0021-9991(74)90019-9.
"""

from __future__ import annotations

import math
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass

import numba
import numpy as np
from numba import njit
from numpy.typing import ArrayLike, NDArray

from .boundaries import Boundaries, BoundaryPlan

__all__ = [
    "G",
    "CFL_BOUND",
    "LIMITERS",
    "H_FLOOR",
    "SolverParams",
    "State",
    "lake_at_rest",
    "ShallowWaterSolver",
]

G: float = 9.81
"""Default gravitational acceleration [m s⁻²]."""

CFL_BOUND: dict[int, float] = {1: 1.0, 2: 0.5}
"""Largest Courant number ν per order for which the scheme keeps depths ≥ 0 (module docstring)."""

LIMITERS: dict[str, int] = {"minmod": 0, "MC": 1, "van Leer": 2}
"""Slope limiters of the second-order reconstruction, by name (module docstring; the value is the kernel's code)."""

H_FLOOR: float = 1e-10
"""Depth [m] at or below which a cell is dry even when h_min = 0, so hu/h is never formed from round-off."""

PARALLEL_MIN_CELLS: int = 65536
"""Grids with fewer cells run on one thread: starting the thread pool costs more than it saves."""

# kernels may contract a·b + c into an FMA; small helpers are inlined by LLVM
_JIT = dict(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"})
_INLINE = dict(cache=True, error_model="numpy", fastmath={"contract", "nsz", "arcp"})
# NOTE: F⁻(R) − F⁻(L) must be exactly 0 for equal states (lake at rest), so that difference is
# never contracted into an FMA with the products before it; fastmath=False must be explicit,
# numba callees otherwise inherit their caller's flags.
_EXACT = dict(cache=True, error_model="numpy", fastmath=False)
# row reductions: sums may be reordered (NaN still propagates); the max runs on finite speeds only
_SUMS = dict(cache=True, error_model="numpy", fastmath={"reassoc", "nsz", "contract"})
_MAX = dict(cache=True, error_model="numpy", fastmath={"nnan", "ninf", "nsz", "reassoc"})

_POOLS: dict[int, ThreadPoolExecutor] = {}


def _run_blocks(kernel, nb: int, args: tuple) -> None:
    """Run kernel(b, *args) for the row blocks b = 0 … nb − 1 on nb threads (the kernels release the GIL).

    NOTE: threads of a shared pool instead of a numba ``prange``: compiling a parallel
    region around the kernels took ~15 s per order on the 2-core CI machine, ten
    times the cost of this dispatch; the work and the thread count are the same.
    """
    if nb == 1:
        kernel(0, *args)
        return
    pool = _POOLS.get(nb)
    if pool is None:
        pool = _POOLS[nb] = ThreadPoolExecutor(max_workers=nb, thread_name_prefix="swe")
    futures = [pool.submit(kernel, b, *args) for b in range(1, nb)]
    kernel(0, *args)  # the calling thread takes block 0
    for future in futures:
        future.result()


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
        1 (first-order kinetic scheme) or 2 (minmod reconstruction + Heun).
    cfl : float, optional
        Courant number ν [-] of the time step (module docstring), in (0, 1] at first
        order and (0, ½] at second order (:data:`CFL_BOUND`).
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

    def __post_init__(self) -> None:
        for name in ("dx", "dy", "g"):
            if not _finite_number(name, getattr(self, name)) > 0:
                raise ValueError(f"SolverParams.{name} must be > 0; got {getattr(self, name)}")
        if isinstance(self.order, bool) or self.order not in (1, 2):
            raise ValueError(f"SolverParams.order must be 1 or 2; got {self.order!r}")
        bound = CFL_BOUND[int(self.order)]
        cfl = _finite_number("cfl", self.cfl)
        if not 0 < cfl <= bound:
            raise ValueError(
                f"SolverParams.cfl must be in (0, {bound}] for order {self.order} "
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


# ---------------------------------------------------------------------------------------------
# numba kernels
# ---------------------------------------------------------------------------------------------


@njit(**_INLINE)
def _minmod(a, b):
    """minmod(a, b): the smaller slope when both have one sign, else 0 (branch-free)."""
    return max(0.0, min(a, b)) + min(0.0, max(a, b))


@njit(**_INLINE)
def _limited_slope(a, b, lim):
    """Limited slope from the backward and forward differences a, b: minmod (0), MC (1), van Leer (2) [5, 7].

    All three are 0 at extrema and at most 2 min(|a|, |b|) in size, so a face value
    stays between the cell's value and the average with its neighbour's (positive
    depths stay positive; :data:`LIMITERS`).
    """
    if lim == 0:
        return _minmod(a, b)
    if lim == 1:  # MC: minmod(2a, 2b, (a + b)/2) [7]
        return _minmod(2.0 * _minmod(a, b), 0.5 * (a + b))
    ab = a * b  # van Leer: 2ab/(a + b) where ab > 0 [5]
    return 2.0 * ab / (a + b) if ab > 0.0 else 0.0  # van Leer's harmonic limiter [8]


@njit(**_EXACT)
def _exact_difference(a, b):
    """a − b, never fused with the products that made a and b: exactly 0 when a and b are equal."""
    return a - b


@njit(**_INLINE)
def _kinetic_flux(eL, zL, uL, vL, eR, zR, uR, vR, half_g, c_r, c_a):
    """Kinetic FVS flux between two interface states after hydrostatic reconstruction.

    Returns (mass flux, normal-momentum flux seen by the left cell, seen by the right
    cell, transverse-momentum flux, largest face speed |u| + a of a wet side). The
    normal-momentum fluxes exclude the g/2 h_i² term of (5), which cancels in the
    cell's own balance at first order and is restored by the centred source at
    second order.
    """
    zs = max(zL, zR)  # Eq. (5): z* = max(z_L, z_R) [2]
    hL = max(0.0, eL - zs)  # Eq. (5): h*_L = max(0, η_L − z*) [2]
    hR = max(0.0, eR - zs)
    rL = math.sqrt(c_r * hL)  # h*/a = √(2h*/(3g)); a = (3g/2) (h*/a)
    rR = math.sqrt(c_r * hR)
    aL = c_a * rL  # Eq. (2): a = √(3 g h / 2)
    aR = c_a * rR
    loL = min(0.0, uL - aL)  # Eq. (3): α, β of the left state
    hiL = min(0.0, uL + aL)
    loR = min(0.0, uR - aR)
    hiR = min(0.0, uR + aR)
    mL = 0.25 * rL * (hiL * hiL - loL * loL)  # Eq. (3): F⁻_h(U*_L)
    mR = 0.25 * rR * (hiR * hiR - loR * loR)  # Eq. (3): F⁻_h(U*_R)
    pL = (1.0 / 6.0) * rL * (hiL * hiL * hiL - loL * loL * loL)  # Eq. (3): F⁻_hu(U*_L)
    pR = (1.0 / 6.0) * rR * (hiR * hiR * hiR - loR * loR * loR)
    qL = hL * uL
    # NOTE: F⁺(L) + F⁻(R) is written F(L) + (F⁻(R) − F⁻(L)) (Eq. 4) so that equal states give
    # exactly F(L); with the pressure g/2 h*² left out of F(L) and of the correction of (5)
    # alike, a lake at rest gives fluxes that are exactly zero.
    fm = qL + _exact_difference(mR, mL)  # Eq. (4): mass
    fl = qL * uL + _exact_difference(pR, pL)  # Eq. (4)–(5): F_hu − g/2 h*_L²
    fr = fl + half_g * (hL - hR) * (hL + hR)  # Eq. (5): F_hu − g/2 h*_R²
    ft = (qL - mL) * vL + mR * vR  # Eq. (4): transverse momentum, upwind
    sL = abs(uL) + aL if hL > 0.0 else 0.0
    sR = abs(uR) + aR if hR > 0.0 else 0.0
    return fm, fl, fr, ft, max(sL, sR)


@njit(**_INLINE)
def _load_row(r, row, h, hu, hv, zpad, gcol, grow, halo_b, j0, j1, inplace, K, h_dry):
    """Fill a padded row buffer (mobile depth, u, v, η, effective bed) with grid row r and its ghosts.

    r runs over −K … ny + K − 1 (ghost rows outside). A dry cell (h ≤ h_dry) is stored
    with mobile depth 0, u = v = 0 and effective bed z_b + h: its film rests.
    """
    ny, nx = h.shape
    zr = zpad[r + K]
    if r < 0:
        sh = grow[0, 0, -r - 1]
        sq = grow[0, 1, -r - 1]
        sr = grow[0, 2, -r - 1]
    elif r >= ny:
        sh = grow[1, 0, r - ny]
        sq = grow[1, 1, r - ny]
        sr = grow[1, 2, r - ny]
    elif inplace and r < j0:  # another block may already have overwritten it: saved copy
        sh = halo_b[0, 0]
        sq = halo_b[0, 1]
        sr = halo_b[0, 2]
    elif inplace and r >= j1:
        sh = halo_b[1, 0]
        sq = halo_b[1, 1]
        sr = halo_b[1, 2]
    else:
        sh = h[r]
        sq = hu[r]
        sr = hv[r]
    m = row[0]
    u = row[1]
    v = row[2]
    e = row[3]
    ze = row[4]
    for i in range(nx):
        p = i + K
        hh = sh[i]
        z = zr[p]
        eta = z + hh
        wet = hh > h_dry
        inv = 1.0 / max(hh, h_dry)
        m[p] = hh if wet else 0.0
        u[p] = sq[i] * inv if wet else 0.0
        v[p] = sr[i] * inv if wet else 0.0
        e[p] = eta
        ze[p] = z if wet else eta  # dry: the resting film is bed for the fluxes
    if 0 <= r < ny:
        for k in range(K):
            for side in range(2):
                p = K - 1 - k if side == 0 else nx + K + k
                hh = gcol[side, 0, k, r]
                z = zr[p]
                eta = z + hh
                wet = hh > h_dry
                inv = 1.0 / max(hh, h_dry)
                m[p] = hh if wet else 0.0
                u[p] = gcol[side, 1, k, r] * inv if wet else 0.0
                v[p] = gcol[side, 2, k, r] * inv if wet else 0.0
                e[p] = eta
                ze[p] = z if wet else eta
    else:  # corners of ghost rows: never used by a flux, kept finite
        for k in range(K):
            for f in range(5):
                row[f, K - 1 - k] = row[f, K]
                row[f, nx + K + k] = row[f, nx + K - 1]


@njit(**_INLINE)
def _euler_row(sh, sq, sr, xf, south, north, tb, nx, dtdx, dtdy):
    """Flux balance of one row into tb[0:3]: U − Δt/Δx (F_E − F_W) − Δt/Δy (G_N − G_S), Eq. (5)."""
    th = tb[0]
    tq = tb[1]
    tr = tb[2]
    for i in range(nx):
        th[i] = sh[i] - dtdx * (xf[0, i + 1] - xf[0, i]) - dtdy * (north[0, i] - south[0, i])
        tq[i] = sq[i] - dtdx * (xf[1, i + 1] - xf[2, i]) - dtdy * (north[3, i] - south[3, i])
        tr[i] = sr[i] - dtdx * (xf[3, i + 1] - xf[3, i]) - dtdy * (north[1, i] - south[2, i])


@njit(**_SUMS)
def _row_sums(th, tq, tr, nx):
    """(Σ (h + hu + hv), Σ min(h, 0)) of an updated row: non-finite if any value is, < 0 if any depth is."""
    total = 0.0
    negative = 0.0
    for i in range(nx):
        total += th[i] + tq[i] + tr[i]
        negative += min(th[i], 0.0)
    return total, negative


@njit(**_MAX)
def _row_max(values, nx):
    """Largest of n finite values (vectorised: the values are known to be finite)."""
    largest = 0.0
    for i in range(nx):
        largest = max(largest, values[i])
    return largest


@njit(**_INLINE)
def _finish_row(tb, bh, bq, br, oh, oq, orr, alpha, nx, dt, cf, h_dry, g15, rdx, rdy):
    """Checks, friction, Heun blend, dry cells and CFL speeds of one updated row tb[0:3].

    Writes out = α·base + (1 − α)·tb into (oh, oq, orr) and returns (max CFL speed sum
    of the row [s⁻¹], non-finite cells, clamped negative depth [m]). ``out`` may be
    ``tb`` itself; it must not be ``base`` (the loop would not be vectorised).
    """
    th = tb[0]
    tq = tb[1]
    tr = tb[2]
    sb = tb[3]
    bad = 0.0
    neg = 0.0
    total, negative = _row_sums(th, tq, tr, nx)
    if not (math.isfinite(total) and negative == 0.0):  # rare: find and count the culprits
        for i in range(nx):
            hn = th[i]
            check = hn + tq[i] + tr[i]
            if check - check != 0.0:
                bad += 1.0
            elif hn < 0.0:  # NOTE: not reached within the CFL bound; a last guard, counted
                neg -= hn
                th[i] = 0.0
        if bad:
            return 0.0, bad, neg
    if cf > 0.0:  # semi-implicit Manning [6]: q / (1 + Δt g n² |u| / h^{4/3})
        for i in range(nx):
            hn = th[i]
            if hn > h_dry:
                speed = math.sqrt(tq[i] * tq[i] + tr[i] * tr[i]) / hn
                damp = 1.0 / (1.0 + dt * cf * speed / (hn * hn ** (1.0 / 3.0)))
                tq[i] *= damp
                tr[i] *= damp
    beta = 1.0 - alpha
    for i in range(nx):  # Heun blend [4] (α = 0: plain Euler, exact), dry cells, CFL speed: vectorised
        hn = alpha * bh[i] + beta * th[i]
        qn = alpha * bq[i] + beta * tq[i]
        rn = alpha * br[i] + beta * tr[i]
        wet = hn > h_dry
        inv = 1.0 / max(hn, h_dry)
        a = math.sqrt(g15 * max(hn, 0.0))
        qn = qn if wet else 0.0  # dry: no velocity, ever
        rn = rn if wet else 0.0
        oh[i] = hn
        oq[i] = qn
        orr[i] = rn
        sb[i] = (abs(qn) * inv + a) * rdx + (abs(rn) * inv + a) * rdy if wet else 0.0
    return _row_max(sb, nx), bad, neg


@njit(nogil=True, **_JIT)
def _block_order1(b, h, hu, hv, zpad, gcol, grow, halo, bounds, rows, fx, fy, tmp, walls,
                  dt, dx, dy, g, h_dry, cf, red):
    """One first-order step, in place, of the rows bounds[b]:bounds[b + 1] (one block, one thread)."""
    ny, nx = h.shape
    K = 1  # ghost layers
    inplace = K == 1  # True: this step overwrites its source
    half_g = 0.5 * g
    c_r = 2.0 / (3.0 * g)
    c_a = 1.5 * g
    dtdx = dt / dx
    dtdy = dt / dy
    rdx = 1.0 / dx
    rdy = 1.0 / dy
    j0 = bounds[b]
    j1 = bounds[b + 1]
    rb = rows[b]
    xf = fx[b]
    tb = tmp[b]
    halo_b = halo[b]
    _load_row(j0 - 1, rb[0], h, hu, hv, zpad, gcol, grow, halo_b, j0, j1, inplace, K, h_dry)
    _load_row(j0, rb[1], h, hu, hv, zpad, gcol, grow, halo_b, j0, j1, inplace, K, h_dry)
    south = fy[b, 0]
    north = fy[b, 1]
    _flux_y_row1(rb[0], rb[1], south, nx, K, half_g, c_r, c_a)
    if j0 == 0 and walls[2] != 0:
        _wall_row(south, nx)
    cur = 1
    nxt = 0
    smax = 0.0
    bad = 0.0
    neg = 0.0
    for j in range(j0, j1):
        _load_row(j + 1, rb[nxt], h, hu, hv, zpad, gcol, grow, halo_b, j0, j1, inplace, K, h_dry)
        _flux_x_row1(rb[cur], xf, nx, K, half_g, c_r, c_a)
        _wall_ends(xf, nx, walls)
        _flux_y_row1(rb[cur], rb[nxt], north, nx, K, half_g, c_r, c_a)
        if j == ny - 1 and walls[3] != 0:
            _wall_row(north, nx)
        hj = h[j]
        qj = hu[j]
        rj = hv[j]
        _euler_row(hj, qj, rj, xf, south, north, tb, nx, dtdx, dtdy)
        s, bd, ng = _finish_row(tb, tb[0], tb[1], tb[2], hj, qj, rj, 0.0, nx, dt, cf, h_dry, c_a, rdx, rdy)
        smax = max(smax, s)
        bad += bd
        neg += ng
        south, north = north, south
        cur, nxt = nxt, cur
    red[b, 0] = smax
    red[b, 3] = bad
    red[b, 4] = neg


@njit(**_INLINE)
def _copy_row(tb, oh, oq, orr, nx):
    """Copy tb[0:3] into a row of the state."""
    for i in range(nx):
        oh[i] = tb[0, i]
        oq[i] = tb[1, i]
        orr[i] = tb[2, i]


@njit(**_INLINE)
def _wall_row(yf, nx):
    """No mass (and no transverse momentum) through a wall: zero those fluxes of a face row."""
    for i in range(nx):
        yf[0, i] = 0.0
        yf[3, i] = 0.0


@njit(**_INLINE)
def _wall_ends(xf, nx, walls):
    """Zero the mass and transverse fluxes of the west/east faces of a row where they are walls."""
    if walls[0] != 0:
        xf[0, 0] = 0.0
        xf[3, 0] = 0.0
    if walls[1] != 0:
        xf[0, nx] = 0.0
        xf[3, nx] = 0.0


@njit(**_INLINE)
def _flux_x_row1(row, xf, nx, K, half_g, c_r, c_a):
    """First-order fluxes through the nx + 1 x-faces of one row."""
    u = row[1]
    v = row[2]
    e = row[3]
    z = row[4]
    for i in range(nx + 1):
        L = i + K - 1
        R = i + K
        fm, fl, fr, ft, s = _kinetic_flux(e[L], z[L], u[L], v[L], e[R], z[R], u[R], v[R], half_g, c_r, c_a)
        xf[0, i] = fm
        xf[1, i] = fl
        xf[2, i] = fr
        xf[3, i] = ft


@njit(**_INLINE)
def _flux_y_row1(south_row, north_row, yf, nx, K, half_g, c_r, c_a):
    """First-order fluxes through the y-faces between two rows (normal = v, transverse = u)."""
    uS = south_row[1]
    vS = south_row[2]
    eS = south_row[3]
    zS = south_row[4]
    uN = north_row[1]
    vN = north_row[2]
    eN = north_row[3]
    zN = north_row[4]
    for i in range(nx):
        p = i + K
        fm, fl, fr, ft, s = _kinetic_flux(eS[p], zS[p], vS[p], uS[p], eN[p], zN[p], vN[p], uN[p], half_g, c_r, c_a)
        yf[0, i] = fm
        yf[1, i] = fl
        yf[2, i] = fr
        yf[3, i] = ft


@njit(**_INLINE)
def _slopes_x(row, sx, nx, K, lim):
    """Limited slopes (undivided) of (h, u, v, η) along a padded row, ghost cells included."""
    for f in range(4):
        a = row[f]
        s = sx[f]
        for p in range(1, nx + 2 * K - 1):
            s[p] = _limited_slope(a[p] - a[p - 1], a[p + 1] - a[p], lim)


@njit(**_INLINE)
def _slopes_y(below, row, above, sy, nx, K, lim):
    """Limited slopes (undivided) of (h, u, v, η) across three padded rows, interior columns."""
    for f in range(4):
        a = below[f]
        b = row[f]
        c = above[f]
        s = sy[f]
        for i in range(nx):
            p = i + K
            s[i] = _limited_slope(b[p] - a[p], c[p] - b[p], lim)


@njit(**_INLINE)
def _flux_x_row2(row, sx, xf, nx, K, half_g, c_r, c_a):
    """Second-order x-face fluxes of one row from the limited face values; returns the max face speed."""
    m = row[0]
    u = row[1]
    v = row[2]
    e = row[3]
    sm = sx[0]
    su = sx[1]
    sv = sx[2]
    se = sx[3]
    for i in range(nx + 1):
        L = i + K - 1
        R = i + K
        mL = m[L] + 0.5 * sm[L]
        eL = e[L] + 0.5 * se[L]
        mR = m[R] - 0.5 * sm[R]
        eR = e[R] - 0.5 * se[R]
        fm, fl, fr, ft, s = _kinetic_flux(
            eL, eL - mL, u[L] + 0.5 * su[L], v[L] + 0.5 * sv[L],  # face bed z_f = η_f − h_f [2]
            eR, eR - mR, u[R] - 0.5 * su[R], v[R] - 0.5 * sv[R],
            half_g, c_r, c_a,
        )
        xf[0, i] = fm
        xf[1, i] = fl
        xf[2, i] = fr
        xf[3, i] = ft
        xf[4, i] = s
    smax = 0.0
    for i in range(nx + 1):
        smax = max(smax, xf[4, i])
    return smax


@njit(**_INLINE)
def _flux_y_row2(south_row, sys, north_row, syn, yf, nx, K, half_g, c_r, c_a):
    """Second-order y-face fluxes between two rows; returns the max face speed."""
    mS = south_row[0]
    uS = south_row[1]
    vS = south_row[2]
    eS = south_row[3]
    mN = north_row[0]
    uN = north_row[1]
    vN = north_row[2]
    eN = north_row[3]
    for i in range(nx):
        p = i + K
        mL = mS[p] + 0.5 * sys[0, i]
        eL = eS[p] + 0.5 * sys[3, i]
        mR = mN[p] - 0.5 * syn[0, i]
        eR = eN[p] - 0.5 * syn[3, i]
        fm, fl, fr, ft, s = _kinetic_flux(
            eL, eL - mL, vS[p] + 0.5 * sys[2, i], uS[p] + 0.5 * sys[1, i],
            eR, eR - mR, vN[p] - 0.5 * syn[2, i], uN[p] - 0.5 * syn[1, i],
            half_g, c_r, c_a,
        )
        yf[0, i] = fm
        yf[1, i] = fl
        yf[2, i] = fr
        yf[3, i] = ft
        yf[4, i] = s
    smax = 0.0
    for i in range(nx):
        smax = max(smax, yf[4, i])
    return smax


@njit(nogil=True, **_JIT)
def _block_order2(b, sh, shu, shv, bh, bhu, bhv, oh, ohu, ohv, alpha, zpad, gcol, grow, halo, bounds,
                  rows, sx, sy, fx, fy, tmp, walls, dt, dx, dy, g, h_dry, cf, lim, red):
    """One Euler stage of the second-order scheme on the rows of block b:
    out = α base + (1 − α)(src + Δt L(src)).

    ``src`` must not alias ``out``; ``base`` may (it is read cell by cell before the write).
    """
    ny, nx = sh.shape
    K = 2  # ghost layers
    inplace = K == 1  # False: a stage never writes its source
    half_g = 0.5 * g
    c_r = 2.0 / (3.0 * g)
    c_a = 1.5 * g
    dtdx = dt / dx
    dtdy = dt / dy
    rdx = 1.0 / dx
    rdy = 1.0 / dy
    gdtdx = g * dtdx
    gdtdy = g * dtdy
    j0 = bounds[b]
    j1 = bounds[b + 1]
    rb = rows[b]
    xf = fx[b]
    xs = sx[b]
    tb = tmp[b]
    halo_b = halo[b]  # never read: the source is not written during a stage
    s_m1 = 0
    s_0 = 1
    s_p1 = 2
    s_p2 = 3
    _load_row(j0 - 2, rb[s_m1], sh, shu, shv, zpad, gcol, grow, halo_b, j0, j1, inplace, K, h_dry)
    _load_row(j0 - 1, rb[s_0], sh, shu, shv, zpad, gcol, grow, halo_b, j0, j1, inplace, K, h_dry)
    _load_row(j0, rb[s_p1], sh, shu, shv, zpad, gcol, grow, halo_b, j0, j1, inplace, K, h_dry)
    _load_row(j0 + 1, rb[s_p2], sh, shu, shv, zpad, gcol, grow, halo_b, j0, j1, inplace, K, h_dry)
    y_prev = 0
    y_cur = 1
    _slopes_y(rb[s_m1], rb[s_0], rb[s_p1], sy[b, y_prev], nx, K, lim)  # row j0 − 1
    _slopes_y(rb[s_0], rb[s_p1], rb[s_p2], sy[b, y_cur], nx, K, lim)  # row j0
    south = fy[b, 0]
    north = fy[b, 1]
    fmax_y = _flux_y_row2(rb[s_0], sy[b, y_prev], rb[s_p1], sy[b, y_cur], south, nx, K, half_g, c_r, c_a)
    if j0 == 0 and walls[2] != 0:
        _wall_row(south, nx)
    s_m1, s_0, s_p1, s_p2 = s_0, s_p1, s_p2, s_m1  # now s_0 holds row j0
    fmax_x = 0.0
    smax = 0.0
    bad = 0.0
    neg = 0.0
    for j in range(j0, j1):
        _load_row(j + 2, rb[s_p2], sh, shu, shv, zpad, gcol, grow, halo_b, j0, j1, inplace, K, h_dry)
        _slopes_y(rb[s_0], rb[s_p1], rb[s_p2], sy[b, y_prev], nx, K, lim)  # row j + 1, into the free slot
        fmax_y = max(fmax_y, _flux_y_row2(rb[s_0], sy[b, y_cur], rb[s_p1], sy[b, y_prev], north,
                                          nx, K, half_g, c_r, c_a))
        if j == ny - 1 and walls[3] != 0:
            _wall_row(north, nx)
        row = rb[s_0]
        _slopes_x(row, xs, nx, K, lim)
        fmax_x = max(fmax_x, _flux_x_row2(row, xs, xf, nx, K, half_g, c_r, c_a))
        _wall_ends(xf, nx, walls)
        _euler_row(sh[j], shu[j], shv[j], xf, south, north, tb, nx, dtdx, dtdy)
        # Eq. (5) at second order: g/2 (h_E² − h_W²) + g h̄ (z_E − z_W) = g h_i Δη [2]
        _well_balanced_source(tb, row[0], xs[3], sy[b, y_cur, 3], nx, K, gdtdx, gdtdy)
        if alpha == 0.0:
            s, bd, ng = _finish_row(tb, bh[j], bhu[j], bhv[j], oh[j], ohu[j], ohv[j], alpha, nx, dt, cf,
                                    h_dry, c_a, rdx, rdy)
        else:  # out is base (Heun's second stage, in place): finish in tb, then copy
            s, bd, ng = _finish_row(tb, bh[j], bhu[j], bhv[j], tb[0], tb[1], tb[2], alpha, nx, dt, cf,
                                    h_dry, c_a, rdx, rdy)
            _copy_row(tb, oh[j], ohu[j], ohv[j], nx)
        smax = max(smax, s)
        bad += bd
        neg += ng
        south, north = north, south
        y_prev, y_cur = y_cur, y_prev
        s_m1, s_0, s_p1, s_p2 = s_0, s_p1, s_p2, s_m1
    red[b, 0] = smax
    red[b, 1] = fmax_x
    red[b, 2] = fmax_y
    red[b, 3] = bad
    red[b, 4] = neg


@njit(**_INLINE)
def _well_balanced_source(tb, m, slope_x, slope_y, nx, K, gdtdx, gdtdy):
    """Centred bed source of the second-order hydrostatic reconstruction: −Δt g h_i Δη / Δ [2]."""
    tq = tb[1]
    tr = tb[2]
    for i in range(nx):
        p = i + K
        tq[i] -= gdtdx * m[p] * slope_x[p]
        tr[i] -= gdtdy * m[p] * slope_y[i]


@njit(**_JIT)
def _save_halos(h, hu, hv, bounds, halo):
    """Copy the rows next to each block (read by that block, written by its neighbour) before a step."""
    ny, nx = h.shape
    nb = bounds.shape[0] - 1
    for b in range(nb):
        for side in range(2):
            r = bounds[b] - 1 if side == 0 else bounds[b + 1]
            if 0 <= r < ny:
                for i in range(nx):
                    halo[b, side, 0, i] = h[r, i]
                    halo[b, side, 1, i] = hu[r, i]
                    halo[b, side, 2, i] = hv[r, i]


@njit(**_JIT)
def _scan(h, hu, hv, h_dry, g15, rdx, rdy, out):
    """Per row: max CFL speed sum, count of non-finite values, count of negative depths."""
    ny, nx = h.shape
    for j in range(ny):
        smax = 0.0
        bad = 0.0
        neg = 0.0
        for i in range(nx):
            hh = h[j, i]
            q = hu[j, i]
            r = hv[j, i]
            check = hh + q + r
            if check - check != 0.0:
                bad += 1.0
            if hh < 0.0:
                neg += 1.0
            if hh > h_dry:
                inv = 1.0 / hh
                a = math.sqrt(g15 * hh)
                smax = max(smax, (abs(q) * inv + a) * rdx + (abs(r) * inv + a) * rdy)
        out[j, 0] = smax
        out[j, 1] = bad
        out[j, 2] = neg


# ---------------------------------------------------------------------------------------------
# solver
# ---------------------------------------------------------------------------------------------


class ShallowWaterSolver:
    """Finite-volume solver of (1) on a uniform grid: kinetic FVS, hydrostatic reconstruction.

    Parameters
    ----------
    bed : array_like, shape (ny, nx)
        Bed elevation z_b at the cell centres [m]; ny, nx ≥ 2, all finite. Cell
        (j, i) has its centre at x = (i + ½) dx, y = (j + ½) dy.
    params : SolverParams
        Grid spacing, order, Courant number, dry threshold, friction, gravity, sides.

    Attributes
    ----------
    cell_updates : int
        Running count of cells × steps (a second-order step counts once), for benchmarks.
    clamped_volume : float
        Water volume [m³] removed by the last-resort clamp of negative depths
        (zero within the CFL bound; reported so that tests can check it).
    retries : int
        Second-order steps repeated with a smaller Δt because the reconstructed face
        speeds exceeded the bound.

    Raises
    ------
    ValueError
        Bed of the wrong shape or with non-finite values, or params not a SolverParams.
    """

    def __init__(self, bed: ArrayLike, params: SolverParams):
        if not isinstance(params, SolverParams):
            raise ValueError(f"params must be a SolverParams; got {type(params).__name__}")
        array = np.asarray(bed)
        if array.ndim != 2 or array.shape[0] < 2 or array.shape[1] < 2:
            raise ValueError(f"bed must be a 2-D array (ny, nx) with ny >= 2 and nx >= 2; got shape {array.shape}")
        if not (np.issubdtype(array.dtype, np.floating) or np.issubdtype(array.dtype, np.integer)):
            raise ValueError(f"bed must hold real numbers; got dtype {array.dtype}")
        array = np.array(array, dtype=np.float64, order="C")
        bad = ~np.isfinite(array)
        if bad.any():
            first = tuple(int(k) for k in np.argwhere(bad)[0])
            raise ValueError(f"bed must be finite; got {int(bad.sum())} NaN/inf values, the first at (j, i) = {first}")
        self.bed = array
        self.params = params
        self.shape = array.shape
        self._K = 1 if params.order == 1 else 2
        self._h_dry = params.h_dry
        self._plan = BoundaryPlan(params.boundaries, array, params.dx, params.dy, params.g, self._h_dry, self._K)
        self._gcol, self._grow = self._plan.new_ghosts()
        self._buffers: dict[int, dict[str, np.ndarray]] = {}
        self._stage = None  # second-order intermediate state U¹
        self.cell_updates = 0
        self.clamped_volume = 0.0
        self.retries = 0

    # -- helpers -------------------------------------------------------------------------------

    def _work(self) -> dict[str, np.ndarray]:
        ny, nx = self.shape
        nb = 1 if ny * nx < PARALLEL_MIN_CELLS else max(1, min(numba.get_num_threads(), ny))
        work = self._buffers.get(nb)
        if work is None:
            K = self._K
            slots = 2 if K == 1 else 4
            work = {
                "bounds": (np.arange(nb + 1, dtype=np.int64) * ny) // nb,
                "rows": np.zeros((nb, slots, 5, nx + 2 * K)),
                "fx": np.zeros((nb, 5, nx + 1)),
                "fy": np.zeros((nb, 2, 5, nx)),
                "tmp": np.zeros((nb, 4, nx)),
                "red": np.zeros((nb, 5)),
                "halo": np.zeros((nb, 2, 3, nx)),  # rows next to each block, saved before an in-place step
            }
            if K == 2:
                work["sx"] = np.zeros((nb, 4, nx + 2 * K))
                work["sy"] = np.zeros((nb, 2, 4, nx))
            self._buffers[nb] = work
        return work

    def _check_state(self, state: State) -> None:
        if not isinstance(state, State):
            raise ValueError(f"state must be a State; got {type(state).__name__}")
        for name in ("h", "hu", "hv"):
            array = getattr(state, name)
            if array.shape != self.shape:
                raise ValueError(f"state.{name} has shape {array.shape}; the bed has shape {self.shape}")
            if array.dtype != np.float64 or not array.flags.c_contiguous:
                raise ValueError(f"state.{name} must be float64 and C-contiguous; got {array.dtype}")

    def _cell_speed(self, state: State) -> tuple[float, int, int]:
        p = self.params
        out = np.zeros((self.shape[0], 3))
        _scan(state.h, state.hu, state.hv, self._h_dry, 1.5 * p.g, 1.0 / p.dx, 1.0 / p.dy, out)
        return float(out[:, 0].max()), int(out[:, 1].sum()), int(out[:, 2].sum())

    def _stage_kernel(self, work, src, base, out, alpha, t, dt):
        """One Euler stage of the second-order scheme; returns (cell speed, face speed, ghost speed, bad, neg)."""
        p = self.params
        ghost = self._plan.fill(t, src[0], src[1], src[2], self._gcol, self._grow)
        red = work["red"]
        args = (*src, *base, *out, alpha, self._plan.zpad, self._gcol, self._grow, work["halo"], work["bounds"],
                work["rows"], work["sx"], work["sy"], work["fx"], work["fy"], work["tmp"], self._plan.walls,
                dt, p.dx, p.dy, p.g, self._h_dry, p.g * p.manning**2, LIMITERS[p.limiter], red)
        _run_blocks(_block_order2, work["bounds"].shape[0] - 1, args)
        faces = float(red[:, 1].max()) / p.dx + float(red[:, 2].max()) / p.dy
        return float(red[:, 0].max()), faces, ghost, float(red[:, 3].sum()), float(red[:, 4].sum())

    def _one_step(self, state: State, dt: float, adaptive: bool) -> tuple[float, float]:
        """Advance by one step (Δt may shrink at second order when adaptive); return (Δt, next speed)."""
        p = self.params
        work = self._work()
        U = (state.h, state.hu, state.hv)
        if p.order == 1:
            ghost = self._plan.fill(state.t, *U, self._gcol, self._grow)
            red = work["red"]
            args = (*U, self._plan.zpad, self._gcol, self._grow, work["halo"], work["bounds"], work["rows"],
                    work["fx"], work["fy"], work["tmp"], self._plan.walls, dt, p.dx, p.dy, p.g, self._h_dry,
                    p.g * p.manning**2, red)
            nb = work["bounds"].shape[0] - 1
            if nb > 1:
                _save_halos(*U, work["bounds"], work["halo"])
            _run_blocks(_block_order1, nb, args)
            speed, bad, neg = float(red[:, 0].max()), float(red[:, 3].sum()), float(red[:, 4].sum())
            speed = max(speed, ghost)
        else:
            if self._stage is None:
                self._stage = tuple(np.zeros(self.shape) for _ in range(3))
            U1 = self._stage
            while True:
                s1, faces, ghost, bad, neg = self._stage_kernel(work, U, U, U1, 0.0, state.t, dt)
                if adaptive and bad == 0 and dt * faces > CFL_BOUND[2] * (1.0 + 1e-12):
                    self.retries += 1
                    dt = p.cfl / faces  # U is untouched by stage 1: repeat with the face speeds
                    continue
                break
            if bad == 0:
                speed, faces2, ghost2, bad, neg2 = self._stage_kernel(work, U1, U, U, 0.5, state.t + dt, dt)
                neg += neg2
                # NOTE: the next Δt also honours this step's reconstructed face speeds (stage 2)
                speed = max(speed, faces2, ghost, ghost2)
            else:
                speed = math.nan
        if bad:
            raise FloatingPointError(
                f"shallow-water step at t = {state.t:.6g} s produced {int(bad)} non-finite cells (Δt = {dt:.3g} s)"
            )
        self.clamped_volume += neg * p.dx * p.dy
        state.t += dt
        self.cell_updates += self.shape[0] * self.shape[1]
        return dt, speed

    # -- public API ----------------------------------------------------------------------------

    def stable_dt(self, state: State) -> float:
        """Largest time step allowed by the Courant number for this state [s] (inf if nothing moves).

        Parameters
        ----------
        state : State
            The current state (its ghost cells, e.g. incident waves at state.t, count too).

        Returns
        -------
        float
            Δt = ν / max[(|u| + a)/Δx + (|v| + a)/Δy] [s].
        """
        self._check_state(state)
        speed, _, _ = self._cell_speed(state)
        speed = max(speed, self._plan.fill(state.t, state.h, state.hu, state.hv, self._gcol, self._grow))
        return self.params.cfl / speed if speed > 0 else math.inf

    def step(self, state: State, dt: float) -> None:
        """One step of length dt, in place (state.t += dt).

        Parameters
        ----------
        state : State
            Updated in place (its arrays keep their identity).
        dt : float
            Time step [s], > 0. Not checked against :meth:`stable_dt`, for speed: a
            larger step can lose positivity (then caught by the clamp and counted in
            :attr:`clamped_volume`) or accuracy.

        Raises
        ------
        FloatingPointError
            If the step produced non-finite values.
        """
        self._check_state(state)
        dt = float(dt)
        if not (math.isfinite(dt) and dt > 0):
            raise ValueError(f"dt must be a finite number > 0 s; got {dt}")
        self._one_step(state, dt, adaptive=False)

    def advance(self, state: State, t_end: float, max_steps: int | None = None) -> State:
        """Advance with the adaptive time step until t_end exactly (or max_steps steps).

        Parameters
        ----------
        state : State
            Updated in place; must have finite values and h ≥ 0.
        t_end : float
            Final time [s], ≥ state.t.
        max_steps : int or None, optional
            Stop after this many steps even if t_end is not reached.

        Returns
        -------
        State
            ``state`` itself, with state.t == t_end unless max_steps stopped it.

        Raises
        ------
        ValueError
            Before any work: a state of the wrong shape, with NaN/inf or negative depth,
            or t_end before state.t.
        """
        self._check_state(state)
        t_end = float(t_end)
        if not math.isfinite(t_end) or t_end < state.t:
            raise ValueError(f"t_end must be finite and >= state.t = {state.t}; got {t_end}")
        if max_steps is not None and (isinstance(max_steps, bool) or int(max_steps) < 0):
            raise ValueError(f"max_steps must be None or an integer >= 0; got {max_steps!r}")
        speed, bad, neg = self._cell_speed(state)
        if bad:
            raise ValueError(f"state holds {bad} non-finite cells; refusing to advance")
        if neg:
            raise ValueError(f"state.h holds {neg} negative depths; refusing to advance")
        speed = max(speed, self._plan.fill(state.t, state.h, state.hu, state.hv, self._gcol, self._grow))
        cfl = self.params.cfl
        steps = 0
        while state.t < t_end and (max_steps is None or steps < max_steps):
            remaining = t_end - state.t
            dt = cfl / speed if speed > 0 else math.inf
            final = dt >= remaining
            if final:
                dt = remaining
            used, speed = self._one_step(state, dt, adaptive=True)
            steps += 1
            if final and used == dt:
                state.t = t_end
        return state
