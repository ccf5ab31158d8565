"""The dissertation's second-order scheme in one dimension: Runge–Kutta discontinuous Galerkin P1 (issue 44).

The shallow-water equations (1a)–(1b) of :mod:`.swe` along x, for the depth h [m] and the
discharge q = hu [m² s⁻¹] over the bed z_b(x) [m]. On each cell [x_{i−½}, x_{i+½}] of width Δx
the state is a polynomial of degree 1 in the Legendre basis of the local coordinate
ξ = 2 (x − x_i)/Δx ∈ [−1, 1] (the dissertation's p(x, t) = Σₖ Cₖ(t) Lₖ(x), L₀ = 1, L₁ = ξ)::

    h(ξ) = h₀ + h₁ ξ,    q(ξ) = q₀ + q₁ ξ      (h₀, q₀ the cell means; h₀ ± h₁ the face values)

The weak form with the test functions L₀, L₁ (the dissertation's Eq. 13; Cockburn & Shu 1989,
2001 [1]), the mass matrix diag(Δx, Δx/3) inverted, gives for U = (h, q), F(U) = (q, q²/h + g h²/2)
and S = (0, −g h ∂x z_b)::

    Δx dU₀/dt   = −(F̂_{i+½} − F̂_{i−½}) + ∫ S dx                                              (1)
    Δx/3 dU₁/dt = ∫_{−1}^{1} F(U(ξ)) dξ − (F̂_{i+½} + F̂_{i−½}) + ∫ S ξ dx                      (2)

with the volume integral by two-point Gauss quadrature (ξ = ±1/√3, exact for the cubic
integrands of P1 h and q/h-free terms, second-order accurate for the rest).

* **Face flux**: the kinetic flux-vector splitting F̂ = F⁺(U_L) + F⁻(U_R) of :mod:`.swe` (its
  Eq. 2–4, the reading of the dissertation's Eq. 12 used by the project's finite-volume
  schemes; ``swe_kernels._kinetic_flux``), between the face values of the two neighbouring cells.
* **Well balanced**: hydrostatic reconstruction at the faces (Audusse et al. 2004 [2]) and the
  source integrated exactly for P1 h and P1 z_b (Xing & Shu 2006 [3]; Xing, Zhang & Shu 2010
  [4], Eq. 3.6–3.9): with z*_{i+½} = max(z_L, z_R), h*_{L,R} = max(0, η_{L,R} − z*), the face
  flux a cell sees is F̂(U*_L, U*_R) + (0, g/2 (h_face² − h*_face²)) of its own side, and

      ∫ S dx = −2 g z₁ h₀,    ∫ S ξ dx = −(2/3) g z₁ h₁       (z₁ the cell's bed slope coefficient)

  A lake at rest (η = h + z_b constant, q = 0) then gives dU/dt = 0 in every wet cell: in (1),
  −g/2 ((h₀ + h₁)² − (h₀ − h₁)²) − 2 g z₁ h₀ = 0 since h₁ = −z₁; in (2), g h₀² + g h₁²/3 −
  g (h₀² + h₁²) + (2/3) g h₁² = 0.
* **Wet and dry** [4, 5]: in a cell with one dry face (h ≤ h_dry there) the bed under the dry face
  is taken no higher than the water at the wet face, z*_dry = min(z_dry, η_wet) (the bed
  "redefined at the wet/dry front" of Liang 2010 [5]; Kesserwani & Liang 2010 [6] for RKDG2): a
  shoreline cell of a lake at rest then has η constant over the cell and stays at rest, while a
  dry face below the water (flooding) keeps its real slope. Velocities at points with
  h ≤ h_dry are 0; cells whose mean depth is ≤ h_dry carry no discharge.
* **Positive depths**: the scaling limiter of Zhang & Shu (2010) [7] as applied to shallow water
  in [4] (Sect. 3.2): after each stage, U₁ ← θ U₁ with θ = min(1, h₀/(h₀ − min(h₀ ± h₁))), so the
  face values (the Gauss–Lobatto points of P1) are ≥ 0; with the first-order kinetic scheme
  positive for ν ≤ 1 [2], the cell means stay ≥ 0 for ν ≤ ½ ([4], Theorem 3.1, ŵ₁ = ½).
* **Slope limiter** (the dissertation's "minmod correction", on the surface η* = h + z*_b so that
  a lake at rest is not touched, and on q): U₁ ← minmod(U₁, U₀,ᵢ₊₁ − U₀,ᵢ, U₀,ᵢ − U₀,ᵢ₋₁) (Cockburn
  & Shu's β = 1 [1]); ``limiter="TVB"`` keeps U₁ where |U₁| ≤ M Δx² (Shu 1987 [8]) so that smooth
  extrema are not clipped.
* **Time**: Heun's two-stage SSP Runge–Kutta method (Shu & Osher 1988 [9]), the limiters after
  each stage; Δt = ν Δx / max(|u| + a), a = √(3 g h/2) the kinetic speed, ν ≤ 1/3 (linear
  stability of P1–RK2, [1]; below the ½ of positivity).
* **Friction**: semi-implicit Manning as :mod:`.swe`, q ← q/(1 + Δt g n² |u₀|/h₀^{4/3}) on both
  coefficients.

Boundaries: ``"wall"`` (the mirror state: same η and bed, u → −u) or ``"open"`` (the face's own
state outside: a transmissive end).

Units: m, s; g in m s⁻².

References
----------
.. [1] Cockburn, B. & Shu, C.-W. (2001). Runge–Kutta discontinuous Galerkin methods for
   convection-dominated problems. *J. Sci. Comput.* 16(3), 173–261 (and Cockburn & Shu 1989,
   *Math. Comp.* 52, 411–435). doi:10.1023/A:1012873910884
.. [2] Audusse, E., Bouchut, F., Bristeau, M.-O., Klein, R. & Perthame, B. (2004). A fast and
   stable well-balanced scheme with hydrostatic reconstruction for shallow water flows.
   *SIAM J. Sci. Comput.* 25(6), 2050–2065. doi:10.1137/S1064827503431090
.. [3] Xing, Y. & Shu, C.-W. (2006). A new approach of high order well-balanced finite volume
   WENO schemes and discontinuous Galerkin methods for a class of hyperbolic systems with
   source terms. *Commun. Comput. Phys.* 1(1), 100–134.
.. [4] Xing, Y., Zhang, X. & Shu, C.-W. (2010). Positivity-preserving high order well-balanced
   discontinuous Galerkin methods for the shallow water equations. *Adv. Water Resour.* 33(12),
   1476–1493. doi:10.1016/j.advwatres.2010.08.005
.. [5] Liang, Q. (2010). Flood simulation using a well-balanced shallow flow model.
   *J. Hydraul. Eng.* 136(9), 669–675. doi:10.1061/(ASCE)HY.1943-7900.0000219
.. [6] Kesserwani, G. & Liang, Q. (2010). Well-balanced RKDG2 solutions to the shallow water
   equations over irregular domains with wetting and drying. *Comput. Fluids* 39(10),
   2040–2050. doi:10.1016/j.compfluid.2010.07.008
.. [7] Zhang, X. & Shu, C.-W. (2010). On maximum-principle-satisfying high order schemes for
   scalar conservation laws. *J. Comput. Phys.* 229(9), 3091–3120. doi:10.1016/j.jcp.2009.12.030
.. [8] Shu, C.-W. (1987). TVB uniformly high-order schemes for conservation laws.
   *Math. Comp.* 49(179), 105–121. doi:10.1090/S0025-5718-1987-0890256-5
.. [9] Shu, C.-W. & Osher, S. (1988). Efficient implementation of essentially non-oscillatory
   shock-capturing schemes. *J. Comput. Phys.* 77(2), 439–471. doi:10.1016/0021-9991(88)90177-5
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numba import njit
from numpy.typing import ArrayLike, NDArray

from .swe_kernels import _kinetic_flux
from .swe_state import G

__all__ = ["DG_LIMITERS", "DG_CFL_BOUND", "DGParams", "DGState", "DGSolver1D", "lake_at_rest_dg"]

DG_LIMITERS = ("minmod", "TVB")
"""Slope limiters of the DG scheme (module docstring); the first is the dissertation's."""

DG_CFL_BOUND = 1.0 / 3.0
"""Largest Courant number of P1 with two-stage Runge–Kutta (linear stability, [1]); positivity allows ½."""

BOUNDARIES = ("wall", "open")
_GAUSS = 1.0 / math.sqrt(3.0)


def check_numbers(settings, names: tuple[str, ...]) -> None:
    """Refuse a setting among ``names`` that is not a finite number, naming it (ValueError)."""
    for name in names:
        value = getattr(settings, name)
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
            raise ValueError(f"{name}: expected a finite number, got {value!r}")


def differences(mean: NDArray, axis: int = -1) -> tuple[NDArray, NDArray]:
    """(forward, backward) differences of the cell means along ``axis``; at each end the one neighbour's
    difference on both sides."""
    fwd = np.diff(mean, axis=axis, append=np.take(mean, [-1], axis=axis))
    bwd = np.diff(mean, axis=axis, prepend=np.take(mean, [0], axis=axis))
    first = [slice(None)] * mean.ndim
    last = [slice(None)] * mean.ndim
    first[axis], last[axis] = 0, -1
    bwd[tuple(first)] = fwd[tuple(first)]
    fwd[tuple(last)] = bwd[tuple(last)]
    return fwd, bwd


def minmod3(slope: NDArray, forward: NDArray, backward: NDArray, limiter: str, tvb_m: float, width: float,
            exempt: NDArray | None = None) -> NDArray:
    """minmod(a, b, c) (β = 1, [1]); for ``limiter="TVB"`` a is kept where |a| ≤ M Δ² [8] (Δ = ``width`` [m]),
    only in the cells ``exempt`` when given."""
    same = (np.sign(slope) == np.sign(forward)) & (np.sign(slope) == np.sign(backward))
    limited = np.where(same, np.sign(slope) * np.minimum(np.abs(slope), np.minimum(np.abs(forward), np.abs(backward))), 0.0)
    if limiter == "TVB":
        keep = np.abs(slope) <= tvb_m * width**2
        return np.where(keep if exempt is None else keep & exempt, slope, limited)
    return limited


@dataclass(frozen=True)
class DGParams:
    """Settings of :class:`DGSolver1D`.

    Attributes
    ----------
    dx : float            Cell width [m], > 0.
    degree : int          1: P1 with two-stage Runge–Kutta (the scheme); 0: P0 with forward Euler, i.e. the
                          first-order kinetic FVS finite-volume scheme of the same code (the dissertation's
                          first order, for its cost comparison).
    cfl : float           Courant number ν, 0 < ν ≤ :data:`DG_CFL_BOUND` (≤ 1 at degree 0).
    limiter : str         One of :data:`DG_LIMITERS`.
    tvb_m : float         TVB constant M [m⁻¹] of ``limiter="TVB"`` (U₁ kept where |U₁| ≤ M Δx²), ≥ 0.
    h_dry : float         Depth at or below which a point is dry [m], > 0.
    manning : float       Manning's n [s m^-1/3], ≥ 0.
    left, right : str     Boundary of each end, one of ``"wall"``, ``"open"``.
    g : float             Gravitational acceleration [m s⁻²].
    """

    dx: float
    degree: int = 1
    cfl: float = 0.3
    limiter: str = "minmod"
    tvb_m: float = 50.0
    h_dry: float = 1e-6
    manning: float = 0.0
    left: str = "open"
    right: str = "open"
    g: float = G

    def __post_init__(self) -> None:
        check_numbers(self, ("dx", "cfl", "tvb_m", "h_dry", "manning", "g"))
        if not (self.dx > 0 and self.h_dry > 0 and self.g > 0 and self.tvb_m >= 0 and self.manning >= 0):
            raise ValueError("dx, h_dry and g must be > 0; tvb_m and manning >= 0")
        if self.degree not in (0, 1) or isinstance(self.degree, bool):
            raise ValueError(f"degree: expected 0 or 1, got {self.degree!r}")
        bound = DG_CFL_BOUND if self.degree == 1 else 1.0
        if not 0 < self.cfl <= bound:
            raise ValueError(f"cfl: expected 0 < cfl <= {bound:.4g} at degree {self.degree}, got {self.cfl!r}")
        if self.limiter not in DG_LIMITERS:
            raise ValueError(f"limiter: expected one of {', '.join(DG_LIMITERS)}, got {self.limiter!r}")
        for name in ("left", "right"):
            if getattr(self, name) not in BOUNDARIES:
                raise ValueError(f"{name}: expected one of {', '.join(BOUNDARIES)}, got {getattr(self, name)!r}")


@dataclass
class DGState:
    """The P1 coefficients of every cell: means h₀, q₀ and slopes h₁, q₁ (face values U₀ ± U₁) [m, m² s⁻¹]."""

    h0: NDArray[np.float64]
    h1: NDArray[np.float64]
    q0: NDArray[np.float64]
    q1: NDArray[np.float64]
    t: float = 0.0

    def copy(self) -> "DGState":
        return DGState(self.h0.copy(), self.h1.copy(), self.q0.copy(), self.q1.copy(), self.t)

    @property
    def volume_per_width(self) -> float:
        """∫ h dx / Δx: the sum of the cell means [m] (times Δx: the water per metre of width)."""
        return float(self.h0.sum())


def lake_at_rest_dg(bed_faces: ArrayLike, level: float) -> DGState:
    """Still water at ``level`` [m] over a bed given at the cell faces [m] (N + 1 values): the P1 depth
    through the face depths max(0, level − z_b) of every cell, no discharge."""
    z = np.asarray(bed_faces, dtype=float)
    left, right = np.maximum(0.0, level - z[:-1]), np.maximum(0.0, level - z[1:])
    return DGState(0.5 * (left + right), 0.5 * (right - left), np.zeros(z.size - 1), np.zeros(z.size - 1))


@njit(cache=True)
def _face_fluxes(hR_prev, qR_prev, zR_prev, hL_next, qL_next, zL_next, h_dry, half_g, c_r, c_a, out):
    """Kinetic FVS fluxes at the N + 1 faces (module docstring): per face, the mass flux, the momentum flux
    the cell on the left sees and the one the cell on the right sees (each with its own g/2 h_face²), and
    the largest face speed."""
    for j in range(hR_prev.size):
        hl, hr = hR_prev[j], hL_next[j]
        ul = qR_prev[j] / hl if hl > h_dry else 0.0
        ur = qL_next[j] / hr if hr > h_dry else 0.0
        fm, fl, fr, _, speed = _kinetic_flux(hl + zR_prev[j], zR_prev[j], ul, 0.0, hr + zL_next[j], zL_next[j], ur, 0.0,
                                             half_g, c_r, c_a)
        out[0, j] = fm
        out[1, j] = fl + half_g * hl * hl
        out[2, j] = fr + half_g * hr * hr
        out[3, j] = speed


class DGSolver1D:
    """RKDG P1 for the 1D shallow-water equations with the kinetic FVS flux (module docstring).

    Parameters
    ----------
    bed_faces : array_like (N + 1,)   Bed elevation at the cell faces [m]; linear in each cell.
    params : DGParams
    """

    def __init__(self, bed_faces: ArrayLike, params: DGParams) -> None:
        z = np.asarray(bed_faces, dtype=float)
        if z.ndim != 1 or z.size < 3 or not np.all(np.isfinite(z)):
            raise ValueError("bed_faces: expected at least 3 finite face elevations [m]")
        self.params = params
        self.z_faces = z
        self.n = z.size - 1
        self.clamped_volume = 0.0
        self._flux = np.empty((4, self.n + 1))

    # -- pieces of the right-hand side ---------------------------------------------------------------

    def _effective_bed(self, hL, hR):
        """(z*_L, z*_R) per cell: the real bed, except under a dry face of a cell whose other face is wet,
        where it is min(z_dry, η_wet) (module docstring)."""
        p = self.params
        zL, zR = self.z_faces[:-1].copy(), self.z_faces[1:].copy()
        if p.degree == 0:  # a constant depth over a constant bed: the cell's mean bed (the finite-volume form)
            zL = zR = 0.5 * (zL + zR)
            return zL, zR.copy()
        wetL, wetR = hL > p.h_dry, hR > p.h_dry
        only_left = wetL & ~wetR
        only_right = wetR & ~wetL
        zR[only_left] = np.minimum(zR[only_left], hL[only_left] + zL[only_left])
        zL[only_right] = np.minimum(zL[only_right], hR[only_right] + zR[only_right])
        return zL, zR

    def _ghosts(self, hL, qL, zL, hR, qR, zR):
        """The states outside the two ends: (h, q, z) beyond the left face, beyond the right face."""
        p = self.params
        sign_l = -1.0 if p.left == "wall" else 1.0
        sign_r = -1.0 if p.right == "wall" else 1.0
        return (hL[0], sign_l * qL[0], zL[0]), (hR[-1], sign_r * qR[-1], zR[-1])

    def rhs(self, s: DGState) -> tuple[NDArray, NDArray, NDArray, NDArray, float]:
        """(dh₀/dt, dh₁/dt, dq₀/dt, dq₁/dt, largest face speed) of Eq. (1)–(2)."""
        p = self.params
        g, dx = p.g, p.dx
        hL = np.maximum(s.h0 - s.h1, 0.0)
        hR = np.maximum(s.h0 + s.h1, 0.0)
        qL, qR = s.q0 - s.q1, s.q0 + s.q1
        zL, zR = self._effective_bed(hL, hR)
        (gh_l, gq_l, gz_l), (gh_r, gq_r, gz_r) = self._ghosts(hL, qL, zL, hR, qR, zR)
        # face j: left state = right face of cell j−1 (ghost at j = 0), right state = left face of cell j
        flux = self._flux
        _face_fluxes(np.concatenate([[gh_l], hR]), np.concatenate([[gq_l], qR]), np.concatenate([[gz_l], zR]),
                     np.concatenate([hL, [gh_r]]), np.concatenate([qL, [gq_r]]), np.concatenate([zL, [gz_r]]),
                     p.h_dry, 0.5 * g, 2.0 / (3.0 * g), 1.5 * g, flux)
        mass, mom_left_cell, mom_right_cell = flux[0], flux[1], flux[2]
        FmR, FmL = mass[1:], mass[:-1]
        FpR, FpL = mom_left_cell[1:], mom_right_cell[:-1]  # cell i: its right face seen from the left, etc.
        # volume integrals, two-point Gauss
        vol_m = np.zeros(self.n)
        vol_p = np.zeros(self.n)
        for xi in (-_GAUSS, _GAUSS):
            h = np.maximum(s.h0 + s.h1 * xi, 0.0)
            q = s.q0 + s.q1 * xi
            u = np.divide(q, h, out=np.zeros_like(q), where=h > p.h_dry)
            vol_m += np.where(h > p.h_dry, q, 0.0)
            vol_p += h * u * u + 0.5 * g * h * h
        z1 = 0.5 * (zR - zL)  # the slope coefficient of the (effective) bed
        S0 = -2.0 * g * z1 * s.h0  # ∫ S dx ([3], exact for P1)
        S1 = -(2.0 / 3.0) * g * z1 * s.h1  # ∫ S ξ dx
        dh0 = -(FmR - FmL) / dx
        dq0 = (-(FpR - FpL) + S0) / dx
        dh1 = 3.0 / dx * (vol_m - FmR - FmL)
        dq1 = 3.0 / dx * (vol_p - FpR - FpL + S1)
        return dh0, dh1, dq0, dq1, float(flux[3].max())

    def _limit(self, s: DGState) -> None:
        """The slope limiter on η* and q, then the positivity limiter and the dry cells (module docstring)."""
        p = self.params
        if p.degree == 0:
            s.h1 = np.zeros_like(s.h0)
            s.q1 = np.zeros_like(s.q0)
            self._positive_and_dry(s)
            return
        hL, hR = np.maximum(s.h0 - s.h1, 0.0), np.maximum(s.h0 + s.h1, 0.0)
        zL, zR = self._effective_bed(hL, hR)
        z0, z1 = 0.5 * (zL + zR), 0.5 * (zR - zL)
        eta0, eta1 = s.h0 + z0, s.h1 + z1
        # in the characteristic fields of the cell mean (Cockburn & Shu 1989 [1]): w = R⁻¹ (η, q) with the
        # right eigenvectors (1, u ∓ c) of the flux Jacobian; a field-by-field limiter in (η, q) itself makes a
        # step at the sonic point of a transonic rarefaction (measured on Stoker: docs/coastal.md)
        wet = s.h0 > p.h_dry
        u = np.divide(s.q0, s.h0, out=np.zeros_like(s.q0), where=wet)
        c = np.sqrt(p.g * np.where(wet, s.h0, 1.0))
        lo, hi = u - c, u + c  # eigenvalues; R = [[1, 1], [lo, hi]], R⁻¹ = [[hi, −1], [−lo, 1]]/(hi − lo)

        def to_fields(e, q):
            return (hi * e - q) / (hi - lo), (q - lo * e) / (hi - lo)

        fwd_e, bwd_e = differences(eta0)
        fwd_q, bwd_q = differences(s.q0)
        w1, w2 = to_fields(eta1, s.q1)
        f1, f2 = to_fields(fwd_e, fwd_q)
        b1, b2 = to_fields(bwd_e, bwd_q)
        # TVB's exemption only where the cell and its neighbours are wet at both faces: at a shoreline the
        # thin layer's unlimited slopes oscillate (measured on Thacker's bowl)
        wet_faces = (hL > p.h_dry) & (hR > p.h_dry)
        inner = wet_faces.copy()
        inner[1:] &= wet_faces[:-1]
        inner[:-1] &= wet_faces[1:]
        limit = lambda a, f, b, exempt=None: minmod3(a, f, b, p.limiter, p.tvb_m, p.dx, exempt)  # noqa: E731
        w1, w2 = limit(w1, f1, b1, inner), limit(w2, f2, b2, inner)
        eta1_c, q1_c = w1 + w2, lo * w1 + hi * w2
        eta1_dry, q1_dry = limit(eta1, fwd_e, bwd_e), limit(s.q1, fwd_q, bwd_q)  # dry cells: field by field
        s.h1 = np.where(wet, eta1_c, eta1_dry) - z1
        s.q1 = np.where(wet, q1_c, q1_dry)
        self._positive_and_dry(s)

    def _positive_and_dry(self, s: DGState) -> None:
        """Cell means ≥ 0 (round-off clamped and counted), face values ≥ 0 by the scaling limiter, no discharge in
        dry cells."""
        p = self.params
        # positivity (Zhang & Shu 2010 as in Xing, Zhang & Shu 2010): face values ≥ 0
        negative = s.h0 < 0.0
        if negative.any():
            self.clamped_volume += float(-s.h0[negative].sum() * p.dx)
            s.h0[negative] = 0.0
        low = s.h0 - np.abs(s.h1)
        theta = np.where(low < 0.0, np.divide(s.h0, s.h0 - low, out=np.zeros_like(low), where=s.h0 - low > 0), 1.0)
        s.h1 *= theta
        s.q1 *= theta
        dry = s.h0 <= p.h_dry
        s.q0[dry] = 0.0
        s.q1[dry] = 0.0

    def _friction(self, s: DGState, dt: float) -> None:
        p = self.params
        if p.manning == 0.0:
            return
        wet = s.h0 > p.h_dry
        u = np.divide(s.q0, s.h0, out=np.zeros_like(s.q0), where=wet)
        factor = 1.0 / (1.0 + dt * p.g * p.manning**2 * np.abs(u) / np.where(wet, s.h0, 1.0) ** (4.0 / 3.0))
        s.q0 *= factor
        s.q1 *= factor

    # -- stepping --------------------------------------------------------------------------------------

    def stable_dt(self, s: DGState) -> float:
        """ν Δx / max(|u| + √(3 g h/2)) over the cells' face values and means [s]."""
        p = self.params
        speed = 0.0
        for h, q in ((s.h0, s.q0), (s.h0 - s.h1, s.q0 - s.q1), (s.h0 + s.h1, s.q0 + s.q1)):
            h = np.maximum(h, 0.0)
            wet = h > p.h_dry
            if wet.any():
                speed = max(speed, float(np.max(np.abs(q[wet] / h[wet]) + np.sqrt(1.5 * p.g * h[wet]))))
        return math.inf if speed == 0.0 else p.cfl * p.dx / speed

    def step(self, s: DGState, dt: float) -> None:
        """One Heun (SSP-RK2) step of Δt [s], the limiters after each stage (degree 0: one Euler step)."""
        if self.params.degree == 0:
            dh0, _, dq0, _, _ = self.rhs(s)
            s.h0 = s.h0 + dt * dh0
            s.q0 = s.q0 + dt * dq0
            self._limit(s)
            self._friction(s, dt)
            s.t += dt
            return
        first = s.copy()
        for k, d in enumerate(self.rhs(s)[:4]):
            name = ("h0", "h1", "q0", "q1")[k]
            setattr(first, name, getattr(s, name) + dt * d)
        self._limit(first)
        second = self.rhs(first)
        for k, name in enumerate(("h0", "h1", "q0", "q1")):
            setattr(s, name, 0.5 * getattr(s, name) + 0.5 * (getattr(first, name) + dt * second[k]))
        self._limit(s)
        self._friction(s, dt)  # split after the step, semi-implicit (as swe)
        s.t += dt

    def advance(self, s: DGState, t_end: float) -> int:
        """Step to exactly ``t_end`` [s]; returns the number of steps."""
        steps = 0
        while s.t < t_end - 1e-12:
            dt = min(self.stable_dt(s), t_end - s.t)
            self.step(s, dt)
            steps += 1
            if not (np.all(np.isfinite(s.h0)) and np.all(np.isfinite(s.q0))):
                raise FloatingPointError(f"DG state not finite at t = {s.t:.6g} s")
        return steps
