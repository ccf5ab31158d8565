"""RKDG P1 on the coast's 2D grid (issue 44, second part): the scheme of :mod:`.dg` on Cartesian cells.

On each cell of Δx × Δy, with local coordinates ξ, η ∈ [−1, 1], every variable U ∈ {h, hu, hv} is the
complete P1 polynomial U₀ + U_ξ ξ + U_η η (three coefficients; orthogonal on the cell, mass matrix
Δx Δy diag(1, ⅓, ⅓)). The weak form with the test functions 1, ξ, η (Cockburn & Shu 2001 [1])::

    Δx Δy dU₀/dt   = −∮ F̂·n ds + ∫ S dA
    Δx Δy/3 dU_ξ/dt = (2/Δx) ∫ F_x dA − ∮ F̂·n ξ ds + ∫ S ξ dA                          (1)
    Δx Δy/3 dU_η/dt = (2/Δy) ∫ F_y dA − ∮ F̂·n η ds + ∫ S η dA

with the area integrals by 2 × 2 Gauss points and the face integrals by two Gauss points per face (exact
for the quadratic g h²/2 of P1 h). F̂·n is the kinetic FVS flux of :mod:`.swe` (``_kinetic_flux``: the
normal velocity, and the transverse momentum upwinded with the mass) between the two cells' values at
each face point, after hydrostatic reconstruction (Audusse et al. 2004 [2]), each side adding its own
g/2 (h² − h*²) (Xing, Zhang & Shu 2010 [3]). The bed is P1 too (the projection of the bilinear bed given
at the cell corners), and S = (0, −g h ∂x z_b, −g h ∂y z_b) is integrated exactly: with ∂x z_b = 2 z_ξ/Δx,
∫ S_x dA = −2 g z_ξ h₀ Δy, ∫ S_x ξ dA = −(2/3) g z_ξ h_ξ Δy, ∫ S_x η dA = −(2/3) g z_ξ h_η Δy, and
the same in y. A lake at rest (h + z_b constant, no discharge) then gives dU/dt = 0 in every wet cell
(the 1D argument of :mod:`.dg` in each direction; tested).

Limiters after each Heun stage (as :mod:`.dg`): minmod (or TVB) of U_ξ against the x-differences of the
means and of U_η against the y-differences, in the characteristic fields of the flux Jacobian in that
direction at the cell mean (right eigenvectors (1, u − c, v), (0, 0, 1), (1, u + c, v) in x), on
(η = h + z_b, hu, hv); then Zhang & Shu's positivity scaling (Xing, Zhang & Shu 2010 [3], Sect. 4) so
that h ≥ 0 at the eight face points; cells with a dry mean carry no discharge.

Wet/dry (three rules on top of the hydrostatic reconstruction and the positivity limiter):

* in a shoreline cell — wet mean, some face points dry, and every dry point's bed at or above the cell's
  mean surface η̄ = h₀ + z₀ — the bed's slopes are replaced by those of a flat surface, z*_ξ = −h_ξ,
  z*_η = −h_η (z*₀ = z₀): the 2D form of the 1D scheme's capped bed (Liang 2010; Kesserwani & Liang 2010,
  [5], [6] of :mod:`.dg`), which holds h + z* = η̄ over the cell, so that a lake's shoreline cells stay at
  rest; where a dry point lies below the water (flooding) the real slope stays;
* a dry cell (mean depth ≤ h_dry) shows its mean bed z₀ at every face point: a P1 plane through a steep
  cell (a cliff) dips below the still water at some corner while its mean lies above it, so the real
  plane would draw water out of a lake at rest into a cell that cannot hold it (P1 depth ≥ 0 with a zero
  mean is zero); with the mean bed it floods only when the water rises above z₀, as a finite volume does;
* velocity-based limiting (Vater, Beisiegel & Behrens 2015 [4]): each velocity component at the eight face
  points is kept within the range of the cell's and its four neighbours' mean velocities by pulling the
  momentum slopes towards ū × the depth slopes (θ ∈ [0, 1], the largest that does it), and q = ū h in
  cells with a dry face point. Without it, thin layers at a moving shoreline took velocities of 10 m s⁻¹ at
  their face points and the step fell to 1e-9 s (Thacker's bowl, docs/coastal.md).

Boundaries: those of the finite-volume schemes, through :class:`.boundaries.BoundaryPlan` (one ghost
layer): a wall mirrors each face point's state; transmissive and absorbing-generating sides (incident
waves, the open sea's long waves) build their ghost from the boundary cell's value at that face point
(as a surface over the cell's mean bed). Manning friction semi-implicit on every momentum coefficient
after each stage. :mod:`.dg_coast` puts this behind a scene's ``[coastal] scheme = "dg"``.

[4] S. Vater, N. Beisiegel and J. Behrens, "A limiter-based well-balanced discontinuous Galerkin method for
shallow-water flows with wetting and drying: one-dimensional case", Adv. Water Resour. 85, 1–13, 2015,
doi:10.1016/j.advwatres.2015.08.008.

References: [1]–[3] of :mod:`.dg` ([1] Cockburn & Shu 2001; [2] Audusse et al. 2004; [3] Xing, Zhang &
Shu 2010).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numba import njit
from numpy.typing import ArrayLike, NDArray

from .boundaries import Boundaries, BoundaryPlan, Transmissive, Wall
from .dg import BOUNDARIES, DG_LIMITERS, check_numbers, differences, minmod3
from .swe_kernels import _kinetic_flux
from .swe_state import G

__all__ = ["DG2DParams", "DGState2D", "DGSolver2D", "lake_at_rest_dg2d", "p1_bed"]

_GP = 1.0 / math.sqrt(3.0)
_SIDES = ("west", "east", "south", "north")


@dataclass(frozen=True)
class DG2DParams:
    """Settings of :class:`DGSolver2D` (units and meanings as :class:`.dg.DGParams`); ``cfl`` is the Courant
    number of Δt = ν / max((|u| + a)/Δx + (|v| + a)/Δy), ν ≤ 1/3. The sides: ``boundaries`` (a
    :class:`.boundaries.Boundaries`: walls, transmissive, incident waves) when given, else the strings
    ``west`` … ``north``, ``"wall"`` or ``"open"`` (transmissive). ``manning``: Manning's n [s m^-1/3]."""

    dx: float
    dy: float
    cfl: float = 0.25
    limiter: str = "minmod"
    tvb_m: float = 50.0
    h_dry: float = 1e-6
    west: str = "open"
    east: str = "open"
    south: str = "wall"
    north: str = "wall"
    g: float = G
    manning: float = 0.0
    boundaries: Boundaries | None = None

    def __post_init__(self) -> None:
        check_numbers(self, ("dx", "dy", "cfl", "tvb_m", "h_dry", "g", "manning"))
        if not (self.dx > 0 and self.dy > 0 and self.h_dry > 0 and self.g > 0 and self.tvb_m >= 0
                and self.manning >= 0):
            raise ValueError("dx, dy, h_dry and g must be > 0, tvb_m and manning >= 0")
        if self.boundaries is not None and not isinstance(self.boundaries, Boundaries):
            raise ValueError(f"boundaries: expected a coastal.boundaries.Boundaries, got {self.boundaries!r}")
        if not 0 < self.cfl <= 1.0 / 3.0:
            raise ValueError(f"cfl: expected 0 < cfl <= 1/3 (P1 with two-stage Runge-Kutta), got {self.cfl!r}")
        if self.limiter not in DG_LIMITERS:
            raise ValueError(f"limiter: expected one of {', '.join(DG_LIMITERS)}, got {self.limiter!r}")
        for side in _SIDES:
            if getattr(self, side) not in BOUNDARIES:
                raise ValueError(f"{side}: expected one of {', '.join(BOUNDARIES)}, got {getattr(self, side)!r}")

    def sides(self) -> Boundaries:
        """The four sides' conditions: ``boundaries`` when given, else the strings ("open" = transmissive)."""
        if self.boundaries is not None:
            return self.boundaries
        return Boundaries(**{side: Wall() if getattr(self, side) == "wall" else Transmissive() for side in _SIDES})


@dataclass
class DGState2D:
    """P1 coefficients: ``c[v, k]`` for v ∈ (h, hu, hv) and k ∈ (mean, ξ, η), each (ny, nx) [m, m² s⁻¹]."""

    c: NDArray[np.float64]
    t: float = 0.0

    def copy(self) -> "DGState2D":
        return DGState2D(self.c.copy(), self.t)

    @property
    def means(self) -> NDArray[np.float64]:
        """(3, ny, nx): the cell means of h, hu, hv."""
        return self.c[:, 0]


def p1_bed(corners: NDArray) -> NDArray:
    """(3, ny, nx): mean, ξ and η coefficients of the bilinear bed through the cell corners (ny+1, nx+1)."""
    sw, se, nw, ne = corners[:-1, :-1], corners[:-1, 1:], corners[1:, :-1], corners[1:, 1:]
    return np.stack([0.25 * (sw + se + nw + ne), 0.25 * (se + ne - sw - nw), 0.25 * (nw + ne - sw - se)])


def lake_at_rest_dg2d(bed_corners: ArrayLike, level: float) -> DGState2D:
    """Still water at ``level`` [m] over the P1 bed of the corners (ny + 1, nx + 1) [m]: h = level − z_b where
    that is ≥ 0 at all eight face points of a cell, 0 in cells dry at every point, no discharge. Shoreline cells
    (wet at some points only) get the P1 depth through their wet points' mean, positivity-limited."""
    b = p1_bed(np.asarray(bed_corners, dtype=float))
    c = np.zeros((3, 3) + b.shape[1:])
    c[0, 0] = level - b[0]
    c[0, 1] = -b[1]
    c[0, 2] = -b[2]
    low = c[0, 0] - np.abs(c[0, 1]) - _GP * np.abs(c[0, 2])
    low = np.minimum(low, c[0, 0] - _GP * np.abs(c[0, 1]) - np.abs(c[0, 2]))
    shore = low < 0.0
    c[0, 0][shore] = np.maximum(c[0, 0][shore], 0.0)
    theta = np.where(shore, np.divide(c[0, 0], c[0, 0] - low, out=np.zeros_like(low), where=c[0, 0] - low > 0), 1.0)
    c[0, 1] *= theta
    c[0, 2] *= theta
    return DGState2D(c)


@njit(cache=True)
def _face_fluxes(hl, ql, tl, zl, hr, qr, tr, zr, h_dry, half_g, c_r, c_a, out):
    """Kinetic FVS normal fluxes at face points: (mass, normal momentum seen from the left, from the right,
    transverse momentum, face speed), the normal-momentum ones with each side's own g/2 h² ([3] of dg)."""
    n = hl.size
    for j in range(n):
        a, b = hl[j], hr[j]
        ul = ql[j] / a if a > h_dry else 0.0
        ur = qr[j] / b if b > h_dry else 0.0
        vl = tl[j] / a if a > h_dry else 0.0
        vr = tr[j] / b if b > h_dry else 0.0
        fm, fl, fr, ft, speed = _kinetic_flux(a + zl[j], zl[j], ul, vl, b + zr[j], zr[j], ur, vr, half_g, c_r, c_a)
        out[0, j] = fm
        out[1, j] = fl + half_g * a * a
        out[2, j] = fr + half_g * b * b
        out[3, j] = ft
        out[4, j] = speed


class DGSolver2D:
    """RKDG P1 on a Cartesian grid (module docstring).

    Parameters
    ----------
    bed_corners : array_like (ny + 1, nx + 1)   Bed elevation at the cell corners [m].
    params : DG2DParams
    """

    def __init__(self, bed_corners: ArrayLike, params: DG2DParams) -> None:
        z = np.asarray(bed_corners, dtype=float)
        if z.ndim != 2 or min(z.shape) < 2 or not np.all(np.isfinite(z)):
            raise ValueError("bed_corners: expected a (ny + 1, nx + 1) array of finite elevations [m], ny, nx >= 1")
        self.params = params
        self.bed = p1_bed(z)
        self.ny, self.nx = z.shape[0] - 1, z.shape[1] - 1
        self.clamped_volume = 0.0
        self.cell_updates = 0
        self._plan = BoundaryPlan(params.sides(), np.ascontiguousarray(self.bed[0]), params.dx, params.dy, params.g,
                                  params.h_dry, 1)
        self._columns, self._rows = self._plan.new_ghosts()
        self._scratch = np.zeros((3, self.ny, self.nx))
        self._ghost_speed = 0.0

    # -- the effective bed -------------------------------------------------------------------------------

    _POINTS = ((1.0, _GP), (1.0, -_GP), (-1.0, _GP), (-1.0, -_GP), (_GP, 1.0), (-_GP, 1.0), (_GP, -1.0), (-_GP, -1.0))

    def _effective_bed(self, c: NDArray) -> NDArray:
        """(3, ny, nx): the bed's P1 coefficients, with a flat surface's slopes in shoreline cells (module
        docstring)."""
        p = self.params
        zb = self.bed.copy()
        h0 = c[0, 0]
        level = h0 + zb[0]
        partial = np.zeros(h0.shape, dtype=bool)
        shoreline = h0 > p.h_dry
        for gx, gy in self._POINTS:
            h_pt = h0 + gx * c[0, 1] + gy * c[0, 2]
            dry_pt = h_pt <= p.h_dry
            z_pt = zb[0] + gx * zb[1] + gy * zb[2]
            partial |= dry_pt
            shoreline &= ~dry_pt | (z_pt >= level)
        flat = shoreline & partial
        dry = h0 <= p.h_dry  # a dry cell shows its mean bed at every face point
        zb[1] = np.where(flat, -c[0, 1], np.where(dry, 0.0, zb[1]))
        zb[2] = np.where(flat, -c[0, 2], np.where(dry, 0.0, zb[2]))
        return zb

    # -- face values -----------------------------------------------------------------------------------

    @staticmethod
    def _x_face(c: NDArray, side: float, g: float) -> NDArray:
        """Values at the x-face ξ = side, η = g (…, ny, nx)."""
        return c[..., 0, :, :] + side * c[..., 1, :, :] + g * c[..., 2, :, :]

    @staticmethod
    def _y_face(c: NDArray, side: float, g: float) -> NDArray:
        return c[..., 0, :, :] + g * c[..., 1, :, :] + side * c[..., 2, :, :]

    def _outside(self, side: int, h: NDArray, qn: NDArray, qt: NDArray, z: NDArray) -> tuple[NDArray, ...]:
        """(h, q_normal, q_transverse) outside the domain at a boundary face point, from the inside values there
        (each (n, 1)) and the face's bed z [m]: a wall mirrors them (q_normal → −q_normal); the other sides take
        the ghost cell of :class:`.boundaries.BoundaryPlan` built from this face point (:meth:`_fill_face_ghosts`;
        transmissive: its copy; incident waves: the characteristic state) as a level η_g = h_g + z_g, i.e. depth
        max(0, η_g − z) at the face (0 if the ghost is dry), with the ghost's velocity. Side index in the order of
        :data:`.boundaries.SIDES`."""
        if self._plan.kinds[side] == 0:
            return h, -qn, qt
        ghosts = self._columns if side < 2 else self._rows
        ghost = ghosts[side % 2, :, 0, :]  # (h, hu, hv) of the ghost layer along the side
        zpad, K = self._plan.zpad, 1
        z_g = (zpad[K:-K, 0], zpad[K:-K, -1], zpad[0, K:-K], zpad[-1, K:-K])[side]
        n_i, t_i = (1, 2) if side < 2 else (2, 1)
        h_g = ghost[0]
        wet = h_g > self.params.h_dry
        safe = np.where(wet, h_g, 1.0)
        depth = np.where(wet, np.maximum(0.0, h_g + z_g - z[:, 0]), 0.0)  # a dry ghost lends no water
        un = np.where(wet, ghost[n_i] / safe, 0.0)
        ut = np.where(wet, ghost[t_i] / safe, 0.0)
        return depth[:, None], (depth * un)[:, None], (depth * ut)[:, None]

    def _fill_ghosts(self, c: NDArray, t: float) -> None:
        """The boundary plan's ghost cells from the cell means at time t [s] (incident waves move with t)."""
        means = [np.ascontiguousarray(c[v, 0]) for v in range(3)]
        self._ghost_speed = self._plan.fill(t, *means, self._columns, self._rows)

    def _fill_face_ghosts(self, c: NDArray, t: float, axis: str, low: NDArray, z_low: NDArray, high: NDArray,
                          z_high: NDArray) -> None:
        """The ghosts of the two sides normal to ``axis`` from the boundary cells' values at one Gauss point of
        their outer faces (``low``, ``high``: (3, n) of h, q_normal, q_transverse; ``z_low``, ``z_high``: the
        face beds [m]), not from their means: an absorbing side then sees the wave at the face, where the
        flux is taken. Each face value enters as the depth h + z_face − z̄ over the cell's mean bed z̄ (the
        same surface; 0 where the face point is dry) with the face's velocity."""
        scratch = self._scratch  # the plan reads only its edge rows and columns: the other axis's keep the means
        for edge in (np.s_[:, :, 0], np.s_[:, :, -1], np.s_[:, 0, :], np.s_[:, -1, :]):
            scratch[edge] = c[:, 0][edge]
        bed = self.bed[0]
        normal, transverse = (1, 2) if axis == "x" else (2, 1)
        edges = ((np.s_[:, 0], np.s_[:, -1]) if axis == "x" else (np.s_[0, :], np.s_[-1, :]))
        for values, z_face, edge in ((low, z_low, edges[0]), (high, z_high, edges[1])):
            h = values[0]
            wet = h > self.params.h_dry
            safe = np.where(wet, h, 1.0)
            depth = np.where(wet, np.maximum(0.0, h + z_face - bed[edge]), 0.0)
            scratch[0][edge] = depth
            scratch[normal][edge] = np.where(wet, values[1] / safe, 0.0) * depth
            scratch[transverse][edge] = np.where(wet, values[2] / safe, 0.0) * depth
        self._plan.fill(t, scratch[0], scratch[1], scratch[2], self._columns, self._rows)

    def _direction_flux(self, c: NDArray, axis: str, zb: NDArray, t: float) -> tuple[NDArray, NDArray, float]:
        """Fluxes through the faces normal to ``axis`` at both Gauss points: (per point, per face) arrays of
        (mass, normal momentum into the low cell, into the high cell, transverse momentum), and the speed."""
        p = self.params
        face = self._x_face if axis == "x" else self._y_face
        normal, transverse = (1, 2) if axis == "x" else (2, 1)
        results = []
        speed = 0.0
        for gp in (-_GP, _GP):
            lo = face(c, 1.0, gp)  # each cell's value at its high face (3, ny, nx)
            hi = face(c, -1.0, gp)  # at its low face
            zlo = face(zb[None], 1.0, gp)[0]
            zhi = face(zb[None], -1.0, gp)[0]
            if axis == "y":  # work with faces along the last axis
                lo, hi, zlo, zhi = (np.swapaxes(a, -1, -2) for a in (lo, hi, zlo, zhi))
            h_lo, h_hi = np.maximum(lo[0], 0.0), np.maximum(hi[0], 0.0)
            inner_low = np.stack([h_hi[..., 0], hi[normal][..., 0], hi[transverse][..., 0]])
            inner_high = np.stack([h_lo[..., -1], lo[normal][..., -1], lo[transverse][..., -1]])
            self._fill_face_ghosts(c, t, axis, inner_low, zhi[..., 0], inner_high, zlo[..., -1])
            # faces: left state = high face of cell i−1 (outside at 0), right state = low face of cell i (at n)
            west = self._outside(0 if axis == "x" else 2, h_hi[..., :1], hi[normal][..., :1],
                                 hi[transverse][..., :1], zhi[..., :1])
            east = self._outside(1 if axis == "x" else 3, h_lo[..., -1:], lo[normal][..., -1:],
                                 lo[transverse][..., -1:], zlo[..., -1:])
            L_h = np.concatenate([west[0], h_lo], axis=-1)
            L_q = np.concatenate([west[1], lo[normal]], axis=-1)
            L_t = np.concatenate([west[2], lo[transverse]], axis=-1)
            L_z = np.concatenate([zhi[..., :1], zlo], axis=-1)
            R_h = np.concatenate([h_hi, east[0]], axis=-1)
            R_q = np.concatenate([hi[normal], east[1]], axis=-1)
            R_t = np.concatenate([hi[transverse], east[2]], axis=-1)
            R_z = np.concatenate([zhi, zlo[..., -1:]], axis=-1)
            out = np.empty((5, L_h.size))
            _face_fluxes(L_h.ravel(), L_q.ravel(), L_t.ravel(), L_z.ravel(), R_h.ravel(), R_q.ravel(), R_t.ravel(),
                         R_z.ravel(), p.h_dry, 0.5 * p.g, 2.0 / (3.0 * p.g), 1.5 * p.g, out)
            out = out.reshape((5,) + L_h.shape)
            speed = max(speed, float(out[4].max()))
            if axis == "y":
                out = np.swapaxes(out, -1, -2)
            results.append(out)
        return results, speed

    def rhs(self, s: DGState2D) -> tuple[NDArray, float]:
        """dc/dt (3, 3, ny, nx) of Eq. (1), and the largest face speed."""
        p = self.params
        g, dx, dy = p.g, p.dx, p.dy
        c = s.c
        d = np.zeros_like(c)
        # volume integrals: 2 × 2 Gauss points, F_x and F_y of (h, hu, hv)
        for gx in (-_GP, _GP):
            for gy in (-_GP, _GP):
                U = c[:, 0] + gx * c[:, 1] + gy * c[:, 2]
                h = np.maximum(U[0], 0.0)
                wet = h > p.h_dry
                u = np.divide(U[1], h, out=np.zeros_like(h), where=wet)
                v = np.divide(U[2], h, out=np.zeros_like(h), where=wet)
                hu, hv = h * u, h * v
                Fx = (hu, hu * u + 0.5 * g * h * h, hu * v)
                Fy = (hv, hv * u, hv * v + 0.5 * g * h * h)
                for k in range(3):  # (2/Δx) ∫ F_x dA = (Δy/2) Σ F_x; (2/Δy) ∫ F_y dA = (Δx/2) Σ F_y
                    d[k, 1] += 0.5 * dy * Fx[k]
                    d[k, 2] += 0.5 * dx * Fy[k]
        # face integrals
        zb = self._effective_bed(c)
        x_res, sx = self._direction_flux(c, "x", zb, s.t)
        y_res, sy = self._direction_flux(c, "y", zb, s.t)
        for gp, out in zip((-_GP, _GP), x_res):  # out: (5, ny, nx + 1)
            mass, mom_low, mom_high, trans = out[0], out[1], out[2], out[3]
            fluxes_high = (mass[:, 1:], mom_low[:, 1:], trans[:, 1:])  # through each cell's east face
            fluxes_low = (mass[:, :-1], mom_high[:, :-1], trans[:, :-1])  # through its west face
            for k, var in enumerate((0, 1, 2)):
                fe, fw = fluxes_high[k], fluxes_low[k]
                d[var, 0] -= 0.5 * dy * (fe - fw)
                d[var, 1] -= 0.5 * dy * (fe + fw)
                d[var, 2] -= 0.5 * dy * gp * (fe - fw)
        for gp, out in zip((-_GP, _GP), y_res):  # out: (5, ny + 1, nx); normal = v, transverse = u
            mass, mom_low, mom_high, trans = out[0], out[1], out[2], out[3]
            high = {0: mass[1:], 2: mom_low[1:], 1: trans[1:]}
            low = {0: mass[:-1], 2: mom_high[:-1], 1: trans[:-1]}
            for var in (0, 1, 2):
                fn, fs = high[var], low[var]
                d[var, 0] -= 0.5 * dx * (fn - fs)
                d[var, 2] -= 0.5 * dx * (fn + fs)
                d[var, 1] -= 0.5 * dx * gp * (fn - fs)
        # sources, exact for P1 h and bed
        zx, zy = zb[1], zb[2]
        h0, hx, hy = c[0, 0], c[0, 1], c[0, 2]
        d[1, 0] += -2.0 * g * zx * h0 * dy
        d[1, 1] += -(2.0 / 3.0) * g * zx * hx * dy
        d[1, 2] += -(2.0 / 3.0) * g * zx * hy * dy
        d[2, 0] += -2.0 * g * zy * h0 * dx
        d[2, 1] += -(2.0 / 3.0) * g * zy * hx * dx
        d[2, 2] += -(2.0 / 3.0) * g * zy * hy * dx
        area = dx * dy
        d[:, 0] /= area
        d[:, 1:] *= 3.0 / area
        return d, max(sx / dx, 0.0) + max(sy / dy, 0.0)

    # -- limiters ---------------------------------------------------------------------------------------

    def _limit(self, s: DGState2D) -> None:
        p = self.params
        c = s.c
        h0 = c[0, 0]
        wet = h0 > p.h_dry
        safe = np.where(wet, h0, 1.0)
        u = np.where(wet, c[1, 0] / safe, 0.0)
        v = np.where(wet, c[2, 0] / safe, 0.0)
        cel = np.sqrt(p.g * safe)
        zb = self._effective_bed(c)
        eta = c[0] + zb  # (mean, ξ, η) of the surface
        for k, axis, normal, dxy in ((1, 1, (u, v), p.dx), (2, 0, (v, u), p.dy)):
            un, ut = normal
            # characteristic variables of the direction: w = L (η, q_normal, q_transverse)
            qn_i, qt_i = (1, 2) if k == 1 else (2, 1)
            # the differences of the means along this direction, once
            diffs = [differences(v, axis) for v in (eta[0], c[qn_i, 0], c[qt_i, 0])]
            fields = []
            for e, qn, qt in ((eta[k], c[qn_i, k], c[qt_i, k]), tuple(d[0] for d in diffs), tuple(d[1] for d in diffs)):
                w1 = ((un + cel) * e - qn) / (2.0 * cel)
                w2 = qt - ut * e
                w3 = (qn - (un - cel) * e) / (2.0 * cel)
                fields.append((w1, w2, w3))
            limit = lambda a, f, b: minmod3(a, f, b, p.limiter, p.tvb_m, dxy)  # noqa: E731
            lim = [limit(fields[0][i], fields[1][i], fields[2][i]) for i in range(3)]
            e_new = lim[0] + lim[2]
            qn_new = (un - cel) * lim[0] + (un + cel) * lim[2]
            qt_new = ut * lim[0] + lim[1] + ut * lim[2]
            # dry cells: field by field
            c[0, k] = np.where(wet, e_new, limit(eta[k], *diffs[0])) - zb[k]
            c[qn_i, k] = np.where(wet, qn_new, limit(c[qn_i, k], *diffs[1]))
            c[qt_i, k] = np.where(wet, qt_new, limit(c[qt_i, k], *diffs[2]))
        # positivity at the eight face points (Zhang & Shu, as Xing, Zhang & Shu 2010)
        negative = c[0, 0] < 0.0
        if negative.any():
            self.clamped_volume += float(-c[0, 0][negative].sum() * p.dx * p.dy)
            c[0, 0][negative] = 0.0
        hx, hy = np.abs(c[0, 1]), np.abs(c[0, 2])
        low = np.minimum(c[0, 0] - hx - _GP * hy, c[0, 0] - _GP * hx - hy)
        theta = np.where(low < 0.0, np.divide(c[0, 0], c[0, 0] - low, out=np.zeros_like(low), where=c[0, 0] - low > 0), 1.0)
        c[:, 1:] *= theta
        dry = c[0, 0] <= p.h_dry
        c[1:, :, dry] = 0.0
        self._limit_velocity(c, dry)

    def _limit_velocity(self, c: NDArray, dry: NDArray) -> None:
        """Keep each velocity component at the eight face points within the range of the cell's and its four
        neighbours' mean velocities (Vater, Beisiegel & Behrens 2015, velocity-based limiting): the momentum
        slope is pulled towards ū × the depth slope (which has velocity ū at every point) by the largest θ ∈
        [0, 1] that does so; θ = 0 (q = ū h) in cells with a dry face point."""
        p = self.params
        h0 = c[0, 0]
        safe = np.where(dry, 1.0, h0)
        points = [(gx, gy) for gx, gy in self._POINTS]
        h_pts = [h0 + gx * c[0, 1] + gy * c[0, 2] for gx, gy in points]
        semi = np.zeros(h0.shape, dtype=bool)
        for h_pt in h_pts:
            semi |= h_pt <= p.h_dry
        for var in (1, 2):
            ubar = np.where(dry, 0.0, c[var, 0] / safe)
            hi_b = np.where(dry, -np.inf, ubar)
            lo_b = np.where(dry, np.inf, ubar)
            pad_hi = np.pad(hi_b, 1, mode="edge")
            pad_lo = np.pad(lo_b, 1, mode="edge")
            upper, lower = ubar.copy(), ubar.copy()
            for sl in ((slice(1, -1), slice(2, None)), (slice(1, -1), slice(None, -2)),
                       (slice(2, None), slice(1, -1)), (slice(None, -2), slice(1, -1))):
                upper = np.maximum(upper, pad_hi[sl])
                lower = np.minimum(lower, pad_lo[sl])
            dq_x = c[var, 1] - ubar * c[0, 1]
            dq_y = c[var, 2] - ubar * c[0, 2]
            theta = np.where(semi | dry, 0.0, 1.0)
            for (gx, gy), h_pt in zip(points, h_pts):
                du = np.divide(gx * dq_x + gy * dq_y, h_pt, out=np.zeros_like(h0), where=h_pt > p.h_dry)
                room = np.where(du > 0.0, upper - ubar, lower - ubar)
                ratio = np.divide(room, du, out=np.ones_like(h0), where=np.abs(du) > 0.0)
                theta = np.minimum(theta, np.clip(ratio, 0.0, 1.0))
            c[var, 1] = ubar * c[0, 1] + theta * dq_x
            c[var, 2] = ubar * c[0, 2] + theta * dq_y

    # -- stepping --------------------------------------------------------------------------------------

    def stable_dt(self, s: DGState2D) -> float:
        p = self.params
        c = s.c
        rate = 0.0
        for gx, gy in ((0.0, 0.0), (1.0, _GP), (-1.0, _GP), (_GP, 1.0), (_GP, -1.0)):
            U = c[:, 0] + gx * c[:, 1] + gy * c[:, 2]
            h = np.maximum(U[0], 0.0)
            wet = h > p.h_dry
            if not wet.any():
                continue
            a = np.sqrt(1.5 * p.g * h[wet])
            r = (np.abs(U[1][wet] / h[wet]) + a) / p.dx + (np.abs(U[2][wet] / h[wet]) + a) / p.dy
            rate = max(rate, float(r.max()))
        self._fill_ghosts(c, s.t)
        rate = max(rate, self._ghost_speed)
        return math.inf if rate == 0.0 else p.cfl / rate

    def _friction(self, c: NDArray, dt: float) -> None:
        """Manning friction, semi-implicit on every momentum coefficient: q ← q / (1 + Δt g n² |ū| / h₀^{4/3})
        with ū the cell mean's velocity (Chertock et al. 2015, as the finite-volume schemes of :mod:`.swe`)."""
        p = self.params
        if p.manning == 0.0:
            return
        h0 = c[0, 0]
        wet = h0 > p.h_dry
        safe = np.where(wet, h0, 1.0)
        speed = np.hypot(c[1, 0], c[2, 0]) / safe
        factor = np.where(wet, 1.0 / (1.0 + dt * p.g * p.manning**2 * speed / (safe * np.cbrt(safe))), 1.0)
        c[1:] *= factor

    def step(self, s: DGState2D, dt: float) -> None:
        """One Heun step of Δt [s]: two Euler stages, each followed by friction and the limiters."""
        d, _ = self.rhs(s)
        first = DGState2D(s.c + dt * d, s.t + dt)
        self._friction(first.c, dt)
        self._limit(first)
        d2, _ = self.rhs(first)
        second = first.c + dt * d2
        self._friction(second, dt)
        s.c = 0.5 * s.c + 0.5 * second
        self._limit(s)
        s.t += dt
        self.cell_updates += self.ny * self.nx

    def advance(self, s: DGState2D, t_end: float) -> int:
        """Step with the adaptive Δt until t_end [s] exactly (the last step shortened); returns the steps taken.

        Raises FloatingPointError if the state stops being finite."""
        steps = 0
        while s.t < t_end:
            dt = self.stable_dt(s)
            final = dt >= t_end - s.t
            self.step(s, t_end - s.t if final else dt)
            if final:
                s.t = float(t_end)
            steps += 1
            if not np.all(np.isfinite(s.c)):
                raise FloatingPointError(f"DG state not finite at t = {s.t:.6g} s")
        return steps
