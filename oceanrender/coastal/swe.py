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

import numba
import numpy as np
from numpy.typing import ArrayLike

from .boundaries import BoundaryPlan
from .swe_hll import _block_sweep_x, _block_sweep_y, _scan_split
from .swe_kernels import _block_order1, _block_order2, _run_blocks, _save_halos, _scan
from .swe_ksplit import _block_ksweep_x, _block_ksweep_y, _ghost_speeds
from .swe_state import (
    CFL_BOUND,
    G,
    H_FLOOR,
    LIMITERS,
    PARALLEL_MIN_CELLS,
    SCHEMES,
    SPLIT_CFL_BOUND,
    SolverParams,
    State,
    lake_at_rest,
)

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
