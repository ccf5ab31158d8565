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
  unconditionally stable and zero-preserving in thin layers; h^{1/3} by Halley's
  iteration (:func:`_cbrt`), so that the friction loop vectorises.
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
* **Second order, scheme "HLL split"** (``scheme="HLL split"``, :data:`SCHEMES`; the
  default stays "kinetic", see docs/coastal.md for the measured comparison). The same
  reconstruction, face beds, hydrostatic reconstruction (5) and centred source, but the
  HLLE flux [9, 10] between the reconstructed states and one direction at a time::

      F = (S_R⁺ F(U*_L) − S_L⁻ F(U*_R) + S_L⁻ S_R⁺ (U*_R − U*_L)) / (S_R⁺ − S_L⁻),
          S_L⁻ = min(S_L, 0), S_R⁺ = max(S_R, 0)                                            (6)
      S_L = min(u_L − c_L, û − ĉ),  S_R = max(u_R + c_R, û + ĉ),  c = √(g h*),
          û = (√h*_L u_L + √h*_R u_R)/(√h*_L + √h*_R),  ĉ = √(g (h*_L + h*_R)/2);
          next to a dry side (h*_R = 0): S_R = u_L + 2 c_L (and mirrored)                  (7)
      F_hv = F_h · (v_L if F_h > 0 else v_R)   (transverse momentum upwinded with the mass) (8)

  Einfeldt's bounds contain the exact Riemann fan, which makes the HLL flux positive
  (Einfeldt et al. 1991 [10]) — the condition for (5) to keep h ≥ 0 and the lake at
  rest [2]. A step of Δt is the symmetric sequence of sweeps [12]::

      U^{n+1} = X(Δt/2) Y(Δt/2) Y(Δt/2) X(Δt/2) U^n,                                       (9)

  each sweep a Heun step [4] of the one-dimensional scheme along its direction, with
  Manning friction at half strength in each. A sweep of Δt/2 needs Δt/2 · max(|u| + c)/Δ
  ≤ ν ≤ ½ for its own direction only, so Δt = 2ν / max((|u| + c)/Δx, (|v| + c)/Δy):
  4–5 times the unsplit kinetic step, for 2.7–3 times its cost. Within one call, so a
  step is a function of (state, Δt, params) alone.
* **Scheme "kinetic split"** (``scheme="kinetic split"``, either order): the kinetic
  flux (2)–(5), unchanged, one direction at a time in the sweeps (9), each sweep a
  *single* stage with its own Courant number ν ≤ 1 on (|u| + a)/Δx (x sweeps) or
  (|v| + a)/Δy (y sweeps), so Δt = 2ν / max((|u| + a)/Δx, (|v| + a)/Δy): 4 times the
  unsplit step in 2-D still water for 4 sweeps of ~0.75 of its cost each (first order,
  measured at 1000 × 600; docs/coastal.md). Manning friction
  acts once per step, with the whole Δt, after the first y sweep (the middle of (9)).
  First order: each sweep is the 1-D first-order scheme (positive for ν ≤ 1 [1, 2]).
  Second order: MUSCL–Hancock [13, 14], the limited face values of (h, u_n, u_t, η)
  advanced by Δt/2 with the primitive equations before the flux::

      δh = −Δt/(2Δ) (u_n Δh + h Δu_n),  δu_n = −Δt/(2Δ) (u_n Δu_n + g Δη),
      δu_t = −Δt/(2Δ) u_n Δu_t,  W^± = W_i ± ΔW/2 + δW,  η^± = η_i ± Δη/2 + δh,           (10)

  (Δ· the limited undivided slopes; δ· = 0 in a cell beside a dry one whose bed stands
  above its water level, where the slopes are not samples of a smooth flow), and the centred bed source of (5) at the half step,
  −Δt/Δ g h_i^{n+½} Δη with h_i^{n+½} = h_i + δh (11), which makes (10)–(11) vanish bit for
  bit at rest (u = 0, Δη = 0). Positivity: with a flux-vector splitting a cell's loss is
  its own outflow F⁺_h(W*⁺) − F⁻_h(W*⁻), a function of its own face states only, and
  its inflow from the neighbours is ≥ 0 whatever they are [1, 2]. Each cell therefore
  keeps (10) only where::

      h^± ≥ 0  and  Δt/Δ (F⁺_h(h⁺, u_n⁺) − F⁻_h(h⁻, u_n⁻)) ≤ (1 − 10⁻⁹) h_i,                 (12)

  evaluated at the face depths h^± ≥ h*^± (F^±_h grow with h at fixed u, so (12) bounds
  the reconstructed outflow, whatever the neighbour's face bed); elsewhere it falls back
  to its cell values (first order, outflow ≤ ν h_i) — an a-priori, cell-local form of
  the order decrement of MOOD [15]. So h ≥ 0 for ν ≤ 1 per sweep, without a second stage.
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
.. [9] A. Harten, P. D. Lax and B. van Leer, "On upstream differencing and Godunov-type
   schemes for hyperbolic conservation laws", SIAM Review 25(1), 35–61, 1983,
   doi:10.1137/1025002.
.. [10] B. Einfeldt, "On Godunov-type methods for gas dynamics", SIAM J. Numer. Anal.
   25(2), 294–318, 1988, doi:10.1137/0725021; B. Einfeldt, C.-D. Munz, P. L. Roe and
   B. Sjögreen, "On Godunov-type methods near low densities", J. Comput. Phys. 92(2),
   273–295, 1991, doi:10.1016/0021-9991(91)90211-3 (positivity of the HLLE flux).
.. [11] E. F. Toro, "Shock-Capturing Methods for Free-Surface Shallow Flows", Wiley,
   2001, ch. 10 (HLL and HLLC for shallow water, wave-speed estimates, dry fronts).
.. [12] G. Strang, "On the construction and comparison of difference schemes", SIAM J.
   Numer. Anal. 5(3), 506–517, 1968, doi:10.1137/0705041.
.. [13] B. van Leer, "On the relation between the upwind-differencing schemes of Godunov,
   Engquist–Osher and Roe", SIAM J. Sci. Stat. Comput. 5(1), 1–20, 1984,
   doi:10.1137/0905001 (the MUSCL–Hancock predictor).
.. [14] E. F. Toro, "Riemann Solvers and Numerical Methods for Fluid Dynamics", 3rd ed.,
   Springer, 2009, sect. 14.4 (MUSCL–Hancock in primitive variables; linearly stable for
   ν ≤ 1), doi:10.1007/b79761.
.. [15] S. Clain, S. Diot and R. Loubère, "A high-order finite volume method for systems
   of conservation laws — Multi-dimensional Optimal Order Detection (MOOD)", J. Comput.
   Phys. 230(10), 4028–4050, 2011, doi:10.1016/j.jcp.2011.02.026.
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
    "SCHEMES",
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


# ---------------------------------------------------------------------------------------------
# numba kernels
# ---------------------------------------------------------------------------------------------


@njit(**_INLINE)
def _minmod(a, b):
    """minmod(a, b): the smaller slope when both have one sign, else 0 (branch-free)."""
    return max(0.0, min(a, b)) + min(0.0, max(a, b))


@njit(**_INLINE)
def _slope_minmod(a, b):
    """minmod limited slope from the backward and forward differences a, b [5]."""
    return _minmod(a, b)


@njit(**_INLINE)
def _slope_mc(a, b):
    """Monotonised-central limited slope minmod(2a, 2b, (a + b)/2) [7]."""
    return _minmod(2.0 * _minmod(a, b), 0.5 * (a + b))


@njit(**_INLINE)
def _slope_van_leer(a, b):
    """van Leer's harmonic limited slope 2ab/(a + b) where ab > 0, else 0 [8]."""
    ab = a * b
    return 2.0 * ab / (a + b) if ab > 0.0 else 0.0


@njit(**_INLINE)
def _limited_slope(a, b, lim):
    """Limited slope from the backward and forward differences a, b: minmod (0), MC (1), van Leer (2) [5, 7].

    All three are 0 at extrema and at most 2 min(|a|, |b|) in size, so a face value
    stays between the cell's value and the average with its neighbour's (positive
    depths stay positive; :data:`LIMITERS`).
    """
    if lim == 0:
        return _slope_minmod(a, b)
    if lim == 1:
        return _slope_mc(a, b)
    return _slope_van_leer(a, b)


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
def _cbrt(h):
    """h^(1/3) for h > 0 with square roots and divisions only, so that LLVM vectorises it.

    NOTE: without Intel SVML (absent here) ``h ** (1/3)`` is a scalar libm call that cost
    more than the whole flux balance of a first-order step (13.8 of 24 ms per step at
    1000 × 600 with friction; 37 ns per cell, against ~9 ns for this). Start h^(3/8)
    (relative error h^(1/24) − 1) and four Halley iterations y ← y (y³ + 2h)/(2y³ + h)
    (cubic convergence; Traub 1964, *Iterative Methods for the Solution of Equations*,
    Prentice-Hall, sect. 8.1): ≤ 2.1 ulp from ``np.cbrt`` for h in [1e-9, 1e7] [m],
    ≤ 1e-11 relative down to 1e-12 (measured).
    """
    r = math.sqrt(math.sqrt(h))
    y = r * math.sqrt(r)  # h^(3/8)
    for _ in range(4):
        y3 = y * y * y
        y = y * (y3 + 2.0 * h) / (2.0 * y3 + h)
    return y


@njit(**_INLINE)
def _culprits(th, tq, tr, nx):
    """(non-finite cells, clamped negative depth [m]) of an updated row; negative depths are set to 0."""
    bad = 0.0
    neg = 0.0
    for i in range(nx):
        hn = th[i]
        check = hn + tq[i] + tr[i]
        if check - check != 0.0:
            bad += 1.0
        elif hn < 0.0:  # NOTE: not reached within the CFL bound; a last guard, counted
            neg -= hn
            th[i] = 0.0
    return bad, neg


@njit(**_INLINE)
def _manning_row(th, tq, tr, nx, dtcf, h_dry):
    """Semi-implicit Manning friction [6] on a row, in place, wet cells only (branch-free, vectorised).

    q ← q / (1 + Δt g n² |u| / h^{4/3}) written q ← q h^{7/3} / (h^{7/3} + Δt g n² |q|), one division;
    ``dtcf`` = Δt g n² [s · m s⁻² · s² m⁻²ᐟ³ = s m^(1/3)], depths [m], discharges [m² s⁻¹].
    """
    for i in range(nx):
        hn = th[i]
        hs = max(hn, h_dry)
        h73 = hs * hs * _cbrt(hs)  # h^{7/3}
        damp = h73 / (h73 + dtcf * math.sqrt(tq[i] * tq[i] + tr[i] * tr[i]))  # Eq. of [6]
        damp = damp if hn > h_dry else 1.0
        tq[i] *= damp
        tr[i] *= damp

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
        bad, neg = _culprits(th, tq, tr, nx)
        if bad:
            return 0.0, bad, neg
    if cf > 0.0:  # semi-implicit Manning [6], vectorised (no libm call: _cbrt)
        _manning_row(th, tq, tr, nx, dt * cf, h_dry)
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
# second order, scheme "HLL split": HLLE flux + hydrostatic reconstruction, one direction per sweep
# ---------------------------------------------------------------------------------------------


@njit(**_INLINE)
def _hll_flux(eL, zL, uL, vL, eR, zR, uR, vR, half_g, sqrt_g):
    """HLLE flux between two interface states after hydrostatic reconstruction, Eqs. (6)–(8).

    Same outputs as :func:`_kinetic_flux`: (mass flux [m² s⁻¹], normal-momentum flux
    seen by the left cell and by the right cell, both without the g/2 h*² of their
    own side [m³ s⁻²], transverse-momentum flux [m³ s⁻²], largest signal speed
    max(−S_L, S_R) of the face [m s⁻¹], 0 between two dry sides).
    """
    zs = max(zL, zR)  # Eq. (5): z* = max(z_L, z_R) [2]
    hL = max(0.0, eL - zs)  # Eq. (5): h*_L = max(0, η_L − z*) [2]
    hR = max(0.0, eR - zs)
    rL = math.sqrt(hL)
    rR = math.sqrt(hR)
    cL = sqrt_g * rL  # c = √(g h*)
    cR = sqrt_g * rR
    # Eq. (7): Roe averages û = (√h_L u_L + √h_R u_R)/(√h_L + √h_R), ĉ = √(g (h_L + h_R)/2) [9, 11]
    uh = (rL * uL + rR * uR) / max(rL + rR, 1e-300)  # 0 between two dry sides (numerator 0)
    ch = math.sqrt(half_g * (hL + hR))
    # Eq. (7): Einfeldt's bounds S_L = min(u_L − c_L, û − ĉ), S_R = max(u_R + c_R, û + ĉ) [10];
    # next to a dry side the dry-front speed u ± 2c of the wet side (Toro 2001, ch. 10: the
    # exact speed of a front running onto a dry bed) [11]
    # NOTE: written as min/max with offsets of 1e300 (0 or 1e300 chosen by selects of constants), not
    # as `a if hL > 0 else b`, which kept LLVM from vectorising the face loop (4× slower)
    offL = 0.0 if hL > 0.0 else 1e300
    offR = 0.0 if hR > 0.0 else 1e300
    sL = min(uL - cL + offL, uh - ch, uR - 2.0 * cR + (1e300 - offL))
    sR = max(uR + cR - offR, uh + ch, uL + 2.0 * cL - (1e300 - offR))
    # Eq. (6) with S_L⁻ = min(S_L, 0), S_R⁺ = max(S_R, 0): the upwind F_L (F_R) where all waves
    # go right (left), without a branch [9]
    sL = min(sL, 0.0)
    sR = max(sR, 0.0)
    inv = 1.0 / max(sR - sL, 1e-300)  # sR − sL ≥ c_L + c_R > 0 unless both sides are dry
    qL = hL * uL
    qR = hR * uR
    fm = (sR * qL - sL * qR + sL * sR * (hR - hL)) * inv  # Eq. (6): mass
    # Eq. (6) for hu minus g/2 h*_L², written so that a lake at rest (h*_L = h*_R, q = 0) gives
    # exactly 0: [S_R q_L u_L − S_L q_R u_R − S_L g/2 (h_R² − h_L²) + S_L S_R (q_R − q_L)]/(S_R − S_L)
    fl = (sR * qL * uL - sL * qR * uR - sL * half_g * (hR - hL) * (hR + hL) + sL * sR * (qR - qL)) * inv
    fr = fl + half_g * (hL - hR) * (hL + hR)  # Eq. (5): F_hu − g/2 h*_R²
    ft = fm * (vL if fm > 0.0 else vR)  # Eq. (8): transverse momentum upwinded with the mass flux [11]
    s = max(-sL, sR) if hL + hR > 0.0 else 0.0
    return fm, fl, fr, ft, s


@njit(**_INLINE)
def _hll_x_row(row, sx, xf, nx, K, half_g, sqrt_g):
    """HLLE x-face fluxes of one row from the limited face values; returns the max face speed [m s⁻¹]."""
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
        fm, fl, fr, ft, s = _hll_flux(
            eL, eL - mL, u[L] + 0.5 * su[L], v[L] + 0.5 * sv[L],  # face bed z_f = η_f − h_f [2]
            eR, eR - mR, u[R] - 0.5 * su[R], v[R] - 0.5 * sv[R],
            half_g, sqrt_g,
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
def _hll_y_row(south_row, sys, north_row, syn, yf, nx, K, half_g, sqrt_g):
    """HLLE y-face fluxes between two rows (normal = v, transverse = u); returns the max face speed."""
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
        fm, fl, fr, ft, s = _hll_flux(
            eL, eL - mL, vS[p] + 0.5 * sys[2, i], uS[p] + 0.5 * sys[1, i],
            eR, eR - mR, vN[p] - 0.5 * syn[2, i], uN[p] - 0.5 * syn[1, i],
            half_g, sqrt_g,
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


@njit(**_INLINE)
def _balance_x(sh, sq, sr, xf, m, slope_eta, tb, nx, K, dtdx, gdtdx):
    """x sweep of Eq. (5) into tb[0:3]: U − Δt/Δx (F_E − F_W), with the centred source −Δt g h_i Δη/Δx [2]."""
    th = tb[0]
    tq = tb[1]
    tr = tb[2]
    for i in range(nx):
        p = i + K
        th[i] = sh[i] - dtdx * (xf[0, i + 1] - xf[0, i])
        tq[i] = sq[i] - dtdx * (xf[1, i + 1] - xf[2, i]) - gdtdx * m[p] * slope_eta[p]
        tr[i] = sr[i] - dtdx * (xf[3, i + 1] - xf[3, i])


@njit(**_INLINE)
def _balance_y(sh, sq, sr, south, north, m, slope_eta, tb, nx, K, dtdy, gdtdy):
    """y sweep of Eq. (5) into tb[0:3]: U − Δt/Δy (G_N − G_S), with the centred source −Δt g h_i Δη/Δy [2]."""
    th = tb[0]
    tq = tb[1]
    tr = tb[2]
    for i in range(nx):
        th[i] = sh[i] - dtdy * (north[0, i] - south[0, i])
        tq[i] = sq[i] - dtdy * (north[3, i] - south[3, i])
        tr[i] = sr[i] - dtdy * (north[1, i] - south[2, i]) - gdtdy * m[i + K] * slope_eta[i]


@njit(**_INLINE)
def _finish_row_split(tb, bh, bq, br, oh, oq, orr, alpha, nx, dt, cf, h_dry, g, rdx, rdy):
    """:func:`_finish_row` for the split scheme: the cell speed is max((|u| + c)/Δx, (|v| + c)/Δy), c = √(g h).

    Returns (max cell speed of the row [s⁻¹], non-finite cells, clamped negative depth [m]).
    """
    th = tb[0]
    tq = tb[1]
    tr = tb[2]
    sb = tb[3]
    bad = 0.0
    neg = 0.0
    total, negative = _row_sums(th, tq, tr, nx)
    if not (math.isfinite(total) and negative == 0.0):  # rare: find and count the culprits
        bad, neg = _culprits(th, tq, tr, nx)
        if bad:
            return 0.0, bad, neg
    if cf > 0.0:  # semi-implicit Manning [6], vectorised (no libm call: _cbrt)
        _manning_row(th, tq, tr, nx, dt * cf, h_dry)
    beta = 1.0 - alpha
    for i in range(nx):  # Heun blend [4], dry cells, CFL speed: vectorised
        hn = alpha * bh[i] + beta * th[i]
        qn = alpha * bq[i] + beta * tq[i]
        rn = alpha * br[i] + beta * tr[i]
        wet = hn > h_dry
        inv = 1.0 / max(hn, h_dry)
        c = math.sqrt(g * max(hn, 0.0))
        qn = qn if wet else 0.0  # dry: no velocity, ever
        rn = rn if wet else 0.0
        oh[i] = hn
        oq[i] = qn
        orr[i] = rn
        sb[i] = max((abs(qn) * inv + c) * rdx, (abs(rn) * inv + c) * rdy) if wet else 0.0
    return _row_max(sb, nx), bad, neg


@njit(nogil=True, **_JIT)
def _block_sweep_x(b, sh, shu, shv, bh, bhu, bhv, oh, ohu, ohv, alpha, zpad, gcol, grow, halo, bounds,
                   rows, sx, fx, tmp, walls, dt, dx, dy, g, h_dry, cf, lim, red):
    """One Euler stage of an x sweep (HLLE, second order) on the rows of block b:
    out = α base + (1 − α)(src + Δt L_x(src)).

    ``src`` must not alias ``out``; ``base`` may. Rows are independent: no halo.
    """
    ny, nx = sh.shape
    K = 2
    half_g = 0.5 * g
    sqrt_g = math.sqrt(g)
    dtdx = dt / dx
    gdtdx = g * dtdx
    rdx = 1.0 / dx
    rdy = 1.0 / dy
    j0 = bounds[b]
    j1 = bounds[b + 1]
    row = rows[b, 0]
    xf = fx[b]
    xs = sx[b]
    tb = tmp[b]
    halo_b = halo[b]  # never read: the source is not written during a stage
    smax = 0.0
    fmax = 0.0
    bad = 0.0
    neg = 0.0
    for j in range(j0, j1):
        _load_row(j, row, sh, shu, shv, zpad, gcol, grow, halo_b, j0, j1, False, K, h_dry)
        _slopes_x(row, xs, nx, K, lim)
        fmax = max(fmax, _hll_x_row(row, xs, xf, nx, K, half_g, sqrt_g))
        _wall_ends(xf, nx, walls)
        _balance_x(sh[j], shu[j], shv[j], xf, row[0], xs[3], tb, nx, K, dtdx, gdtdx)
        if alpha == 0.0:
            s, bd, ng = _finish_row_split(tb, bh[j], bhu[j], bhv[j], oh[j], ohu[j], ohv[j], alpha, nx, dt, cf,
                                          h_dry, g, rdx, rdy)
        else:  # out is base (Heun's second stage, in place): finish in tb, then copy
            s, bd, ng = _finish_row_split(tb, bh[j], bhu[j], bhv[j], tb[0], tb[1], tb[2], alpha, nx, dt, cf,
                                          h_dry, g, rdx, rdy)
            _copy_row(tb, oh[j], ohu[j], ohv[j], nx)
        smax = max(smax, s)
        bad += bd
        neg += ng
    red[b, 0] = smax
    red[b, 1] = fmax
    red[b, 3] = bad
    red[b, 4] = neg


@njit(nogil=True, **_JIT)
def _block_sweep_y(b, sh, shu, shv, bh, bhu, bhv, oh, ohu, ohv, alpha, zpad, gcol, grow, halo, bounds,
                   rows, sy, fy, tmp, walls, dt, dx, dy, g, h_dry, cf, lim, red):
    """One Euler stage of a y sweep (HLLE, second order) on the rows of block b (rolling 4-row window)."""
    ny, nx = sh.shape
    K = 2
    half_g = 0.5 * g
    sqrt_g = math.sqrt(g)
    dtdy = dt / dy
    gdtdy = g * dtdy
    rdx = 1.0 / dx
    rdy = 1.0 / dy
    j0 = bounds[b]
    j1 = bounds[b + 1]
    rb = rows[b]
    tb = tmp[b]
    halo_b = halo[b]
    s_m1 = 0
    s_0 = 1
    s_p1 = 2
    s_p2 = 3
    _load_row(j0 - 2, rb[s_m1], sh, shu, shv, zpad, gcol, grow, halo_b, j0, j1, False, K, h_dry)
    _load_row(j0 - 1, rb[s_0], sh, shu, shv, zpad, gcol, grow, halo_b, j0, j1, False, K, h_dry)
    _load_row(j0, rb[s_p1], sh, shu, shv, zpad, gcol, grow, halo_b, j0, j1, False, K, h_dry)
    _load_row(j0 + 1, rb[s_p2], sh, shu, shv, zpad, gcol, grow, halo_b, j0, j1, False, K, h_dry)
    y_prev = 0
    y_cur = 1
    _slopes_y(rb[s_m1], rb[s_0], rb[s_p1], sy[b, y_prev], nx, K, lim)  # row j0 − 1
    _slopes_y(rb[s_0], rb[s_p1], rb[s_p2], sy[b, y_cur], nx, K, lim)  # row j0
    south = fy[b, 0]
    north = fy[b, 1]
    fmax = _hll_y_row(rb[s_0], sy[b, y_prev], rb[s_p1], sy[b, y_cur], south, nx, K, half_g, sqrt_g)
    if j0 == 0 and walls[2] != 0:
        _wall_row(south, nx)
    s_m1, s_0, s_p1, s_p2 = s_0, s_p1, s_p2, s_m1  # now s_0 holds row j0
    smax = 0.0
    bad = 0.0
    neg = 0.0
    for j in range(j0, j1):
        _load_row(j + 2, rb[s_p2], sh, shu, shv, zpad, gcol, grow, halo_b, j0, j1, False, K, h_dry)
        _slopes_y(rb[s_0], rb[s_p1], rb[s_p2], sy[b, y_prev], nx, K, lim)  # row j + 1, into the free slot
        fmax = max(fmax, _hll_y_row(rb[s_0], sy[b, y_cur], rb[s_p1], sy[b, y_prev], north, nx, K, half_g,
                                    sqrt_g))
        if j == ny - 1 and walls[3] != 0:
            _wall_row(north, nx)
        _balance_y(sh[j], shu[j], shv[j], south, north, rb[s_0][0], sy[b, y_cur, 3], tb, nx, K, dtdy, gdtdy)
        if alpha == 0.0:
            s, bd, ng = _finish_row_split(tb, bh[j], bhu[j], bhv[j], oh[j], ohu[j], ohv[j], alpha, nx, dt, cf,
                                          h_dry, g, rdx, rdy)
        else:
            s, bd, ng = _finish_row_split(tb, bh[j], bhu[j], bhv[j], tb[0], tb[1], tb[2], alpha, nx, dt, cf,
                                          h_dry, g, rdx, rdy)
            _copy_row(tb, oh[j], ohu[j], ohv[j], nx)
        smax = max(smax, s)
        bad += bd
        neg += ng
        south, north = north, south
        y_prev, y_cur = y_cur, y_prev
        s_m1, s_0, s_p1, s_p2 = s_0, s_p1, s_p2, s_m1
    red[b, 0] = smax
    red[b, 2] = fmax
    red[b, 3] = bad
    red[b, 4] = neg


@njit(**_JIT)
def _scan_split(h, hu, hv, h_dry, g, rdx, rdy, out):
    """:func:`_scan` with the split scheme's speed max((|u| + c)/Δx, (|v| + c)/Δy), c = √(g h)."""
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
                c = math.sqrt(g * hh)
                smax = max(smax, (abs(q) * inv + c) * rdx, (abs(r) * inv + c) * rdy)
        out[j, 0] = smax
        out[j, 1] = bad
        out[j, 2] = neg


# ---------------------------------------------------------------------------------------------
# scheme "kinetic split": the kinetic flux, one direction per sweep; first order or MUSCL–Hancock
# ---------------------------------------------------------------------------------------------


@njit(**_INLINE)
def _kinetic_out(h, u, c_r, c_a):
    """Mass a state (h [m], u [m s⁻¹]) sends through its right and its left face: (F⁺_h, −F⁻_h) [m² s⁻¹], Eq. (3).

    Both are ≥ 0 and increase with h at fixed u (the Maxwellian (2) widens with a = √(3gh/2)),
    so the values at a face depth bound those at the hydrostatically reconstructed h* ≤ h [1, 2].
    """
    r = math.sqrt(c_r * h)  # h/a
    a = c_a * r
    lo = min(0.0, u - a)
    hi = min(0.0, u + a)
    fminus = 0.25 * r * (hi * hi - lo * lo)  # Eq. (3): F⁻_h ≤ 0
    return h * u - fminus, -fminus


@njit(**_INLINE)
def _hancock_faces(mB, nB, tB, eB, m, un, ut, e, mA, nA, tA, eA, n, fv, keep, lam, g, c_r, c_a, lim):
    """Face values at t + Δt/2 of n cells along a sweep, MUSCL–Hancock with a positivity fallback, Eqs. (10)–(12).

    Inputs: (mobile depth [m], normal velocity, transverse velocity [m s⁻¹], η [m]) of the cells
    before (B), at and after (A) each cell along the sweep; lam = Δt/Δ [s m⁻¹]. Writes
    fv[0:8, k] = (h⁻, h⁺, u_n⁻, u_n⁺, u_t⁻, u_t⁺, η⁻, η⁺) and fv[8, k] = h^{n+½} Δη, the
    weight of the centred bed source [m²]. A cell whose predicted face depth is negative, or
    whose own outflow λ (F⁺_h(W⁺) − F⁻_h(W⁻)) would exceed its depth, keeps its cell values
    (first order) and no source. keep[0:n] is scratch (the predictor's weight per cell).

    NOTE: three loops, each with a limiter fixed at compile time, writing to 1-D rows: one
    loop with nine output rows and a run-time limiter is not vectorised by LLVM (22 → 9 ns
    per cell measured on 800 cells, bit for bit the same values).
    """
    if lim == 0:
        _HANCOCK_MINMOD(mB, nB, tB, eB, m, un, ut, e, mA, nA, tA, eA, n, fv, keep, lam, g, c_r, c_a)
    elif lim == 1:
        _HANCOCK_MC(mB, nB, tB, eB, m, un, ut, e, mA, nA, tA, eA, n, fv, keep, lam, g, c_r, c_a)
    else:
        _HANCOCK_VAN_LEER(mB, nB, tB, eB, m, un, ut, e, mA, nA, tA, eA, n, fv, keep, lam, g, c_r, c_a)


def _hancock_loops(slope):
    """:func:`_hancock_faces` for the limited slope ``slope(a, b)`` (a jitted function, fixed when compiled).

    NOTE: closures over ``slope``, not a function argument: a dispatcher passed as an
    argument made the callers uncacheable ("dynamic globals", numba 0.68).
    """

    @njit(**_INLINE)
    def _hancock_normal(mB, nB, eB, m, un, e, mA, nA, eA, n, hm_, hp_, nm_, np__, keep, lam, g, c_r, c_a):
        """Depth and normal-velocity face values (h⁻, h⁺, u_n⁻, u_n⁺) and keep = Δt/(2Δ), 0 (no predictor) or −1 (fallback)."""
        half = 0.5 * lam
        for k in range(n):
            hk = m[k]
            uk = un[k]
            sm = slope(hk - mB[k], mA[k] - hk)  # undivided limited slopes [5, 7, 8]
            sn = slope(uk - nB[k], nA[k] - uk)
            se = slope(e[k] - eB[k], eA[k] - e[k])
            # Beside a dry cell (m = 0) whose bed stands above this cell's water level (a shoreline on a
            # slope) the slopes are not samples of a smooth flow (that η is the bed, its velocity 0): the
            # predictor is dropped there (the cell stays MUSCL in space). A dry bed below the level (a
            # front flooding it, Ritter's) keeps it. Measured on Thacker's bowl, L1 of h: order 1.64 →
            # 1.84 at nx = 1600 → 3200 (docs/coastal.md).
            shore = ((mB[k] <= 0.0) & (eB[k] >= e[k])) | ((mA[k] <= 0.0) & (eA[k] >= e[k]))
            w = 0.0 if shore else half
            # Eq. (10): primitive predictor over Δt/2, h_t + u h_x + h u_x = 0, u_t + u u_x + g η_x = 0
            # (Toro 2009, sect. 14.4); zero at rest (u = 0, Δη = 0), bit for bit
            dh = -w * (uk * sm + hk * sn)
            dn = -w * (uk * sn + g * se)
            hm = hk - 0.5 * sm + dh
            hp = hk + 0.5 * sm + dh
            nm = uk - 0.5 * sn + dn
            np_ = uk + 0.5 * sn + dn
            out_p, _ = _kinetic_out(max(hp, 0.0), np_, c_r, c_a)
            _, out_m = _kinetic_out(max(hm, 0.0), nm, c_r, c_a)
            # Eq. (12): the cell's own outflow bounds its loss; inflow is ≥ 0 whatever the neighbours do
            # NOTE: the margin 1e-9 keeps the rounding of h − λ ΔF (~1e-16 of the flux) from crossing 0 in a draining cell
            ok = (min(hm, hp) >= 0.0) & (lam * (out_p + out_m) <= (1.0 - 1e-9) * hk)
            hm_[k] = hm if ok else hk
            hp_[k] = hp if ok else hk
            nm_[k] = nm if ok else uk
            np__[k] = np_ if ok else uk
            keep[k] = w if ok else -1.0

    @njit(**_INLINE)
    def _hancock_transverse(tB, un, ut, tA, n, tm_, tp_, keep):
        """Transverse-velocity face values (u_t⁻, u_t⁺) of :func:`_hancock_faces`: v_t + u v_x = 0 over Δt/2 (10)."""
        for k in range(n):
            w = keep[k]
            ok = w >= 0.0
            st = slope(ut[k] - tB[k], tA[k] - ut[k])
            dt_ = -w * un[k] * st
            tm_[k] = ut[k] - 0.5 * st + dt_ if ok else ut[k]
            tp_[k] = ut[k] + 0.5 * st + dt_ if ok else ut[k]

    @njit(**_INLINE)
    def _hancock_surface(mB, nB, eB, m, un, e, mA, nA, eA, n, em_, ep_, src, keep):
        """Surface face values (η⁻, η⁺) and the source weight h^{n+½} Δη [m²] of :func:`_hancock_faces` (10)–(11)."""
        for k in range(n):
            w = keep[k]
            ok = w >= 0.0
            hk = m[k]
            uk = un[k]
            sm = slope(hk - mB[k], mA[k] - hk)  # the same slopes and predictor as _hancock_normal
            sn = slope(uk - nB[k], nA[k] - uk)
            se = slope(e[k] - eB[k], eA[k] - e[k])
            dh = -w * (uk * sm + hk * sn)
            em_[k] = e[k] - 0.5 * se + dh if ok else e[k]  # the face bed η − h is not moved by the predictor
            ep_[k] = e[k] + 0.5 * se + dh if ok else e[k]
            src[k] = (hk + dh) * se if ok else 0.0  # Eq. (11): h^{n+½} Δη

    @njit(**_INLINE)
    def loops(mB, nB, tB, eB, m, un, ut, e, mA, nA, tA, eA, n, fv, keep, lam, g, c_r, c_a):
        _hancock_normal(mB, nB, eB, m, un, e, mA, nA, eA, n, fv[0], fv[1], fv[2], fv[3], keep, lam, g, c_r, c_a)
        _hancock_transverse(tB, un, ut, tA, n, fv[4], fv[5], keep)
        _hancock_surface(mB, nB, eB, m, un, e, mA, nA, eA, n, fv[6], fv[7], fv[8], keep)
    return loops


_HANCOCK_MINMOD = _hancock_loops(_slope_minmod)
_HANCOCK_MC = _hancock_loops(_slope_mc)
_HANCOCK_VAN_LEER = _hancock_loops(_slope_van_leer)


@njit(**_INLINE)
def _hancock_fluxes(fvL, offL, fvR, offR, n, out, half_g, c_r, c_a):
    """Kinetic fluxes (4)–(5) through n faces between the plus face of fvL[:, i + offL] and the minus face of fvR[:, i + offR].

    NOTE: the rows are taken as 1-D arrays before the loop; indexed as fv[j, i] inside it the
    loop was not vectorised (as in :func:`_hancock_faces`).
    """
    hL_, uL_, vL_, eL_ = fvL[1, offL:offL + n], fvL[3, offL:offL + n], fvL[5, offL:offL + n], fvL[7, offL:offL + n]
    hR_, uR_, vR_, eR_ = fvR[0, offR:offR + n], fvR[2, offR:offR + n], fvR[4, offR:offR + n], fvR[6, offR:offR + n]
    o0, o1, o2, o3 = out[0], out[1], out[2], out[3]
    for i in range(n):
        eL = eL_[i]
        eR = eR_[i]
        zL = eL - hL_[i]  # face bed z_f = η_f − h_f [2]
        zR = eR - hR_[i]
        fm, fl, fr, ft, s = _kinetic_flux(eL, zL, uL_[i], vL_[i], eR, zR, uR_[i], vR_[i], half_g, c_r, c_a)
        # NOTE: a dry side sends nothing (F^∓ of h* = 0 is exactly 0), but F⁺_L = q_L − F⁻_L is a
        # difference that can round to −1e-20 when u_L ≤ −a_L: keep the sign exact
        zs = max(zL, zR)
        fm = fm if eR > zs else max(fm, 0.0)
        fm = fm if eL > zs else min(fm, 0.0)
        o0[i] = fm
        o1[i] = fl
        o2[i] = fr
        o3[i] = ft


@njit(**_INLINE)
def _finish_sweep(tb, sy, oh, oq, orr, nx, dtcf, h_dry, g15, rdx, rdy):
    """Checks, friction (if dtcf > 0), dry cells and the speeds of one row after a sweep of "kinetic split".

    Writes the row to (oh, oq, orr); returns (max (|u| + a)/Δx, max (|v| + a)/Δy [s⁻¹],
    non-finite cells, clamped negative depth [m]).
    """
    th = tb[0]
    tq = tb[1]
    tr = tb[2]
    sx = tb[3]
    bad = 0.0
    neg = 0.0
    total, negative = _row_sums(th, tq, tr, nx)
    if not (math.isfinite(total) and negative == 0.0):  # rare: find and count the culprits
        bad, neg = _culprits(th, tq, tr, nx)
        if bad:
            return 0.0, 0.0, bad, neg
    if dtcf > 0.0:  # semi-implicit Manning [6]
        _manning_row(th, tq, tr, nx, dtcf, h_dry)
    for i in range(nx):
        hn = th[i]
        wet = hn > h_dry
        inv = 1.0 / max(hn, h_dry)
        a = math.sqrt(g15 * max(hn, 0.0))
        qn = tq[i] if wet else 0.0  # dry: no velocity, ever
        rn = tr[i] if wet else 0.0
        oh[i] = hn
        oq[i] = qn
        orr[i] = rn
        sx[i] = (abs(qn) * inv + a) * rdx if wet else 0.0
        sy[i] = (abs(rn) * inv + a) * rdy if wet else 0.0
    return _row_max(sx, nx), _row_max(sy, nx), bad, neg


@njit(nogil=True, **_JIT)
def _block_ksweep_x(b, sh, shu, shv, oh, ohu, ohv, zpad, gcol, grow, halo, bounds, rows, fv, keep, fx, tmp, sy, walls,
                    dt, dx, dy, g, h_dry, dtcf, lim, hancock, red):
    """One x sweep of "kinetic split" (Δt = dt) on the rows of block b, src → out (distinct arrays).

    hancock = 0: first order (the fluxes (3)–(5) of the cell values); 1: MUSCL–Hancock (10)–(12).
    """
    ny, nx = sh.shape
    K = (zpad.shape[1] - nx) // 2
    half_g = 0.5 * g
    c_r = 2.0 / (3.0 * g)
    c_a = 1.5 * g
    lam = dt / dx
    glam = g * lam
    rdx = 1.0 / dx
    rdy = 1.0 / dy
    j0 = bounds[b]
    j1 = bounds[b + 1]
    row = rows[b, 0]
    xf = fx[b]
    f = fv[b, 0]
    tb = tmp[b]
    halo_b = halo[b]  # never read: out-of-place
    npad = nx + 2 * K
    smx = 0.0
    smy = 0.0
    bad = 0.0
    neg = 0.0
    for j in range(j0, j1):
        _load_row(j, row, sh, shu, shv, zpad, gcol, grow, halo_b, j0, j1, False, K, h_dry)
        if hancock:
            m = row[0]
            u = row[1]
            v = row[2]
            e = row[3]
            _hancock_faces(m[0:npad - 2], u[0:npad - 2], v[0:npad - 2], e[0:npad - 2],
                           m[1:npad - 1], u[1:npad - 1], v[1:npad - 1], e[1:npad - 1],
                           m[2:npad], u[2:npad], v[2:npad], e[2:npad], npad - 2, f, keep[b], lam, g, c_r, c_a, lim)
            _hancock_fluxes(f, K - 2, f, K - 1, nx + 1, xf, half_g, c_r, c_a)  # f[:, k] is cell p = k + 1
        else:
            _flux_x_row1(row, xf, nx, K, half_g, c_r, c_a)
        _wall_ends(xf, nx, walls)
        hj = sh[j]
        qj = shu[j]
        rj = shv[j]
        th = tb[0]
        tq = tb[1]
        tr = tb[2]
        if hancock:
            w = f[8]
            for i in range(nx):  # Eq. (5) with the centred source −Δt g h^{n+½} Δη/Δx (11) [2]
                th[i] = hj[i] - lam * (xf[0, i + 1] - xf[0, i])
                tq[i] = qj[i] - lam * (xf[1, i + 1] - xf[2, i]) - glam * w[i + K - 1]
                tr[i] = rj[i] - lam * (xf[3, i + 1] - xf[3, i])
        else:
            for i in range(nx):  # Eq. (5), x faces only
                th[i] = hj[i] - lam * (xf[0, i + 1] - xf[0, i])
                tq[i] = qj[i] - lam * (xf[1, i + 1] - xf[2, i])
                tr[i] = rj[i] - lam * (xf[3, i + 1] - xf[3, i])
        s1, s2, bd, ng = _finish_sweep(tb, sy[b], oh[j], ohu[j], ohv[j], nx, dtcf, h_dry, c_a, rdx, rdy)
        smx = max(smx, s1)
        smy = max(smy, s2)
        bad += bd
        neg += ng
    red[b, 0] = smx
    red[b, 1] = smy
    red[b, 3] = bad
    red[b, 4] = neg


@njit(nogil=True, **_JIT)
def _block_ksweep_y(b, sh, shu, shv, oh, ohu, ohv, zpad, gcol, grow, halo, bounds, rows, fv, keep, fy, tmp, sy, walls,
                    dt, dx, dy, g, h_dry, dtcf, lim, hancock, red):
    """One y sweep of "kinetic split" on the rows of block b, src → out (rolling window of rows).

    Iteration r computes the fluxes through the face between rows r and r + 1 (from the
    face values of row r + 1, MUSCL–Hancock, or the cell values, first order) and then
    updates row r. NOTE: one call site per helper keeps the compile time down.
    """
    ny, nx = sh.shape
    K = (zpad.shape[1] - nx) // 2
    half_g = 0.5 * g
    c_r = 2.0 / (3.0 * g)
    c_a = 1.5 * g
    lam = dt / dy
    glam = g * lam
    rdx = 1.0 / dx
    rdy = 1.0 / dy
    j0 = bounds[b]
    j1 = bounds[b + 1]
    rb = rows[b]
    tb = tmp[b]
    halo_b = halo[b]
    th = tb[0]
    tq = tb[1]
    tr = tb[2]
    nslot = 4 if hancock else 2
    reach = 1 + hancock  # rows loaded ahead of the face row
    r0 = j0 - 1 - hancock  # Hancock: the first iteration only fills the face values of row j0 − 1
    for r in range(r0, r0 + reach):  # rows r0 … r0 + reach − 1
        _load_row(r, rb[(r + 8) % nslot], sh, shu, shv, zpad, gcol, grow, halo_b, j0, j1, False, K, h_dry)
    smx = 0.0
    smy = 0.0
    bad = 0.0
    neg = 0.0
    for r in range(r0, j1):
        ahead = r + reach
        _load_row(ahead, rb[(ahead + 8) % nslot], sh, shu, shv, zpad, gcol, grow, halo_b, j0, j1, False, K, h_dry)
        north = fy[b, (r + 8) % 2]
        south = fy[b, (r + 7) % 2]
        if hancock:
            A = rb[(r + 8) % 4]
            B = rb[(r + 9) % 4]
            C = rb[(r + 10) % 4]
            _hancock_faces(A[0, K:K + nx], A[2, K:K + nx], A[1, K:K + nx], A[3, K:K + nx],
                           B[0, K:K + nx], B[2, K:K + nx], B[1, K:K + nx], B[3, K:K + nx],
                           C[0, K:K + nx], C[2, K:K + nx], C[1, K:K + nx], C[3, K:K + nx],
                           nx, fv[b, (r + 9) % 2], keep[b], lam, g, c_r, c_a, lim)  # row r + 1 (normal v, transverse u)
            _hancock_fluxes(fv[b, (r + 8) % 2], 0, fv[b, (r + 9) % 2], 0, nx, north, half_g, c_r, c_a)
        else:
            _flux_y_row1(rb[(r + 8) % 2], rb[(r + 9) % 2], north, nx, K, half_g, c_r, c_a)
        if (r == -1 and walls[2] != 0) or (r == ny - 1 and walls[3] != 0):
            _wall_row(north, nx)
        if r < j0:
            continue
        hj = sh[r]
        qj = shu[r]
        rj = shv[r]
        if hancock:
            w = fv[b, (r + 8) % 2, 8]
            for i in range(nx):  # Eq. (5) in y with the centred source (11) [2]
                th[i] = hj[i] - lam * (north[0, i] - south[0, i])
                tq[i] = qj[i] - lam * (north[3, i] - south[3, i])
                tr[i] = rj[i] - lam * (north[1, i] - south[2, i]) - glam * w[i]
        else:
            for i in range(nx):  # Eq. (5), y faces only
                th[i] = hj[i] - lam * (north[0, i] - south[0, i])
                tq[i] = qj[i] - lam * (north[3, i] - south[3, i])
                tr[i] = rj[i] - lam * (north[1, i] - south[2, i])
        s1, s2, bd, ng = _finish_sweep(tb, sy[b], oh[r], ohu[r], ohv[r], nx, dtcf, h_dry, c_a, rdx, rdy)
        smx = max(smx, s1)
        smy = max(smy, s2)
        bad += bd
        neg += ng
    red[b, 0] = smx
    red[b, 1] = smy
    red[b, 3] = bad
    red[b, 4] = neg


@njit(**_JIT)
def _ghost_speeds(gcol, grow, h_dry, g15, rdx, rdy):
    """(max (|u| + a)/Δx of the west/east ghosts, max (|v| + a)/Δy of the south/north ghosts) [s⁻¹], a = √(3gh/2)."""
    sx = 0.0
    for side in range(2):
        for k in range(gcol.shape[2]):
            for r in range(gcol.shape[3]):
                hh = gcol[side, 0, k, r]
                if hh > h_dry:
                    sx = max(sx, (abs(gcol[side, 1, k, r]) / hh + math.sqrt(g15 * hh)) * rdx)
    sy = 0.0
    for side in range(2):
        for k in range(grow.shape[2]):
            for c in range(grow.shape[3]):
                hh = grow[side, 0, k, c]
                if hh > h_dry:
                    sy = max(sy, (abs(grow[side, 2, k, c]) / hh + math.sqrt(g15 * hh)) * rdy)
    return sx, sy


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
        self._stage = None  # second-order intermediate state U¹ (split schemes: A)
        self._stage2 = None  # "kinetic split": the second intermediate state B
        self._start = None  # split scheme: the state at the start of a step, for a restart
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
            if self.params.kinetic_split:
                work["fv"] = np.zeros((nb, 2, 9, nx + 2 * K))  # face values of two rows (Eqs. 10–12)
                work["keep"] = np.zeros((nb, nx + 2 * K))  # the predictor's weight per cell (_hancock_faces)
                work["speed_y"] = np.zeros((nb, nx))
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
        """(CFL speed [s⁻¹]: Δt = ν / speed, non-finite cells, negative depths) of the state's cells."""
        p = self.params
        out = np.zeros((self.shape[0], 3))
        if p.split:  # each sweep lasts Δt/2: Δt = 2ν / max((|u| + c)/Δx, (|v| + c)/Δy)
            _scan_split(state.h, state.hu, state.hv, self._h_dry, p.g, 1.0 / p.dx, 1.0 / p.dy, out)
            out[:, 0] *= 0.5
        elif p.kinetic_split:  # the same with the kinetic speed a = √(3gh/2)
            _scan_split(state.h, state.hu, state.hv, self._h_dry, 1.5 * p.g, 1.0 / p.dx, 1.0 / p.dy, out)
            out[:, 0] *= 0.5
        else:
            _scan(state.h, state.hu, state.hv, self._h_dry, 1.5 * p.g, 1.0 / p.dx, 1.0 / p.dy, out)
        return float(out[:, 0].max()), int(out[:, 1].sum()), int(out[:, 2].sum())

    def _ghost_speed(self, state: State) -> float:
        """Fill the ghosts at state.t; their CFL speed (0 for the split scheme, whose stages check every face)."""
        speed = self._plan.fill(state.t, state.h, state.hu, state.hv, self._gcol, self._grow)
        if self.params.kinetic_split:
            p = self.params
            return 0.5 * max(_ghost_speeds(self._gcol, self._grow, self._h_dry, 1.5 * p.g, 1.0 / p.dx, 1.0 / p.dy))
        return 0.0 if self.params.split else speed

    def _sweep(self, work, direction, src, base, out, alpha, t, dt, cf):
        """One Euler stage of a sweep of the split scheme along x (0) or y (1).

        Returns (cell speed max((|u| + c)/Δx, (|v| + c)/Δy) of ``out`` [s⁻¹], face speed
        of the sweep's direction / Δ [s⁻¹], non-finite cells, clamped negative depth [m]).
        """
        p = self.params
        self._plan.fill(t, src[0], src[1], src[2], self._gcol, self._grow)
        red = work["red"]
        if direction == 0:
            kernel, slopes, fluxes, d = _block_sweep_x, work["sx"], work["fx"], p.dx
        else:
            kernel, slopes, fluxes, d = _block_sweep_y, work["sy"], work["fy"], p.dy
        args = (*src, *base, *out, alpha, self._plan.zpad, self._gcol, self._grow, work["halo"], work["bounds"],
                work["rows"], slopes, fluxes, work["tmp"], self._plan.walls, dt, p.dx, p.dy, p.g, self._h_dry,
                cf, LIMITERS[p.limiter], red)
        _run_blocks(kernel, work["bounds"].shape[0] - 1, args)
        return (float(red[:, 0].max()), float(red[:, 1 + direction].max()) / d, float(red[:, 3].sum()),
                float(red[:, 4].sum()))

    def _split_step(self, state: State, dt: float, adaptive: bool) -> tuple[float, float, float, float]:
        """One step of the split scheme, sweeps x y y x of Δt/2 each (Eq. 9); returns (Δt, speed, bad, neg).

        Each sweep is a Heun step [4] of the one-dimensional scheme (6)–(8) along its
        direction. When adaptive, a sweep stage whose face speeds exceed the bound
        ν ≤ ½ restarts the whole step from its saved start with a shorter Δt.
        """
        p = self.params
        work = self._work()
        U = (state.h, state.hu, state.hv)
        if self._stage is None:
            self._stage = tuple(np.zeros(self.shape) for _ in range(3))
        U1 = self._stage
        if adaptive:
            if self._start is None:
                self._start = tuple(np.empty(self.shape) for _ in range(3))
            for a, b in zip(self._start, U):
                np.copyto(a, b)
        cf = 0.5 * p.g * p.manning**2  # Manning at half strength in each of the 4 sweeps of Δt/2: Δt in all (Eq. 9)
        bound = CFL_BOUND[2] * (1.0 + 1e-12)
        while True:
            h = 0.5 * dt
            faces = 0.0
            bad = neg = 0.0
            restart = False
            for direction, t0 in ((0, state.t), (1, state.t), (1, state.t + h), (0, state.t + h)):
                for src, alpha, ts in ((U, 0.0, t0), (U1, 0.5, t0 + h)):
                    dst = U1 if alpha == 0.0 else U
                    speed, face, bd, ng = self._sweep(work, direction, src, U, dst, alpha, ts, h, cf)
                    faces = max(faces, face)
                    bad += bd
                    neg += ng
                    if bad:
                        break
                    if adaptive and h * face > bound:
                        restart = True
                        break
                if bad or restart:
                    break
            if restart:
                self.retries += 1
                for a, b in zip(U, self._start):
                    np.copyto(a, b)
                dt = 2.0 * p.cfl / faces
                continue
            break
        # NOTE: the next Δt also honours the face speeds met during this step
        return dt, (math.nan if bad else 0.5 * max(speed, faces)), bad, neg

    def _kinetic_split_step(self, state: State, dt: float, adaptive: bool) -> tuple[float, float, float, float]:
        """One step of "kinetic split": sweeps x y y x of Δt/2 (Eq. 9), one stage each; returns (Δt, speed, bad, neg).

        The sweeps run U → A → B → A → U, so U is intact until the last one. Each sweep's
        Courant number is known before it runs (its source's speeds along its direction,
        from the previous sweep's output, and its ghosts'); when adaptive, a sweep above
        ν ≤ 1 restarts the step from U with a shorter Δt. Manning friction acts once, with
        the whole Δt, after the first y sweep (the middle of the symmetric sequence).
        """
        p = self.params
        work = self._work()
        U = (state.h, state.hu, state.hv)
        if self._stage is None:
            self._stage = tuple(np.zeros(self.shape) for _ in range(3))
            self._stage2 = tuple(np.zeros(self.shape) for _ in range(3))
        A, B = self._stage, self._stage2
        hancock = 1 if p.order == 2 else 0
        lim = LIMITERS[p.limiter]
        g15, rdx, rdy = 1.5 * p.g, 1.0 / p.dx, 1.0 / p.dy
        bound = SPLIT_CFL_BOUND * (1.0 + 1e-12)
        red = work["red"]
        nb = work["bounds"].shape[0] - 1
        while True:
            h = 0.5 * dt
            speeds = [math.inf, math.inf]  # the source's speeds; the first sweep's came with Δt
            bad = neg = 0.0
            restart = 0.0
            sweeps = ((0, U, A, state.t, 0.0), (1, A, B, state.t, dt * p.g * p.manning**2),
                      (1, B, A, state.t + h, 0.0), (0, A, U, state.t + h, 0.0))
            for k, (direction, src, out, t, dtcf) in enumerate(sweeps):
                self._plan.fill(t, src[0], src[1], src[2], self._gcol, self._grow)
                ghost = _ghost_speeds(self._gcol, self._grow, self._h_dry, g15, rdx, rdy)[direction]
                need = ghost if k == 0 else max(ghost, speeds[direction])
                if adaptive and h * need > bound:
                    restart = need
                    break
                if direction == 0:
                    kernel, fluxes = _block_ksweep_x, work["fx"]
                else:
                    kernel, fluxes = _block_ksweep_y, work["fy"]
                args = (*src, *out, self._plan.zpad, self._gcol, self._grow, work["halo"], work["bounds"],
                        work["rows"], work["fv"], work["keep"], fluxes, work["tmp"], work["speed_y"], self._plan.walls,
                        h, p.dx, p.dy, p.g, self._h_dry, dtcf, lim, hancock, red)
                _run_blocks(kernel, nb, args)
                speeds = [float(red[:, 0].max()), float(red[:, 1].max())]
                bad += float(red[:, 3].sum())
                neg += float(red[:, 4].sum())
                if bad:
                    break
            if restart:
                self.retries += 1
                dt = 2.0 * p.cfl / restart
                continue
            break
        return dt, (math.nan if bad else 0.5 * max(speeds)), bad, neg

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
        if p.split:
            dt, speed, bad, neg = self._split_step(state, dt, adaptive)
        elif p.kinetic_split:
            dt, speed, bad, neg = self._kinetic_split_step(state, dt, adaptive)
        elif p.order == 1:
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
            Δt = ν / max[(|u| + a)/Δx + (|v| + a)/Δy] [s]; for the "HLL split" scheme
            Δt = 2ν / max[max((|u| + c)/Δx, (|v| + c)/Δy)], c = √(g h) (Eq. 9); for
            "kinetic split" the same with a = √(3gh/2) instead of c.
        """
        self._check_state(state)
        speed, _, _ = self._cell_speed(state)
        speed = max(speed, self._ghost_speed(state))
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
        speed = max(speed, self._ghost_speed(state))
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
