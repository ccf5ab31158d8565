"""numba kernels of the unsplit kinetic scheme (first order; second order: limited reconstruction + Heun) and what
the other schemes share: slopes and limiters, the kinetic flux, row loading, friction, reductions, the thread pool.

Part of the solver of :mod:`.swe`, whose docstring gives the equations, the schemes and the references [1]–[15]
cited here.
"""

from __future__ import annotations

import math
from concurrent.futures import ThreadPoolExecutor

from numba import njit

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
