"""numba kernels of the second-order scheme "HLL split": HLLE flux + hydrostatic reconstruction, one direction
per sweep.

Part of the solver of :mod:`.swe`, whose docstring gives the equations, the schemes and the references [1]–[15]
cited here.
"""

from __future__ import annotations

import math

from numba import njit

from .swe_kernels import (
    _INLINE,
    _JIT,
    _copy_row,
    _culprits,
    _load_row,
    _manning_row,
    _row_max,
    _row_sums,
    _slopes_x,
    _slopes_y,
    _wall_ends,
    _wall_row,
)

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
