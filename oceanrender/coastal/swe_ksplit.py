"""numba kernels of the scheme "kinetic split": the kinetic flux, one direction per sweep; first order or
MUSCL–Hancock.

Part of the solver of :mod:`.swe`, whose docstring gives the equations, the schemes and the references [1]–[15]
cited here.
"""

from __future__ import annotations

import math

from numba import njit

from .swe_kernels import (
    _INLINE,
    _JIT,
    _culprits,
    _flux_x_row1,
    _flux_y_row1,
    _kinetic_flux,
    _load_row,
    _manning_row,
    _row_max,
    _row_sums,
    _slope_mc,
    _slope_minmod,
    _slope_van_leer,
    _wall_ends,
    _wall_row,
)

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
