"""Closed-form solutions of the one-dimensional shallow-water equations, for validating the solver.

Flat, frictionless bed, depth h [m] and velocity u [m s⁻¹] along x, gravity g:

* :func:`dam_break_ritter` — dam break onto a dry bed (Ritter 1892 [1]);
* :func:`dam_break_stoker` — dam break onto a wet bed, a rarefaction and a bore
  (Stoker 1957 [2]), with :func:`stoker_middle_state` for the state between them;
* :func:`bore_jump` — Rankine–Hugoniot jump relations of a bore (hydraulic jump)
  running into a given state [2, 3];
* :func:`wall_reflection` — the bore reflected when a uniform stream hits a wall;
* :func:`simple_wave` — a smooth Gaussian hump running into still water as a simple
  wave, exact until it breaks (:func:`simple_wave_breaking_time`) [2], [4]: the smooth
  test on which second order shows;
* :func:`thacker_planar` — a planar free surface oscillating in a parabolic bowl,
  with moving shorelines on both sides (Thacker 1981 [5], as in SWASHES [3],
  sect. 4.2.2): the smooth wet/dry test;
* :func:`thacker_paraboloid` — its two-dimensional form: a tilted plane of water
  circling in a paraboloid of revolution (Thacker 1981 [5]; SWASHES [3], sect. 4.2.2);
* :func:`solitary_runup` — the maximum run-up of a non-breaking solitary wave on a
  plane beach (Synolakis 1987 [6]), and :func:`solitary_wave` its initial state.

All functions are pure and vectorised over x; t in s, positions in m. The bed is
flat except for the Thacker solutions, which bring their own beds.

References
----------
.. [1] A. Ritter, "Die Fortpflanzung der Wasserwellen", Zeitschrift des Vereines
   Deutscher Ingenieure 36(33), 947–954, 1892.
.. [2] J. J. Stoker, "Water Waves: The Mathematical Theory with Applications",
   Interscience, New York, 1957, ch. 10 (dam break, bores).
.. [3] O. Delestre, C. Lucas, P.-A. Ksinant, F. Darboux, C. Laguerre, T.-N.-T. Vo,
   F. James and S. Cordier, "SWASHES: a compilation of shallow water analytic
   solutions for hydraulic and environmental studies", Int. J. Numer. Meth. Fluids
   72(3), 269–300, 2013, doi:10.1002/fld.3741 (sections 4.1.1–4.1.2: the same dam
   breaks, in the notation used here).
.. [4] G. B. Whitham, "Linear and Nonlinear Waves", Wiley, New York, 1974,
   sect. 13.10 (simple waves of the shallow-water equations).
.. [5] W. C. Thacker, "Some exact solutions to the nonlinear shallow-water wave
   equations", J. Fluid Mech. 107, 499–508, 1981, doi:10.1017/S0022112081001882.
.. [6] C. E. Synolakis, "The runup of solitary waves", J. Fluid Mech. 185, 523–545, 1987,
   doi:10.1017/S002211208700329X.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.optimize import brentq

__all__ = [
    "G",
    "dam_break_ritter",
    "stoker_middle_state",
    "dam_break_stoker",
    "BoreJump",
    "bore_jump",
    "wall_reflection",
    "simple_wave",
    "simple_wave_breaking_time",
    "thacker_planar",
    "thacker_paraboloid",
    "solitary_runup",
    "solitary_wave",
]

G: float = 9.81
"""Default gravitational acceleration [m s⁻²] (same as :data:`oceanrender.coastal.swe.G`)."""


def _check_positive(name: str, value: float) -> float:
    value = float(value)
    if not (math.isfinite(value) and value > 0):
        raise ValueError(f"{name} must be a finite number > 0; got {value}")
    return value


def dam_break_ritter(
    x: ArrayLike, t: float, h_left: float, x0: float = 0.0, g: float = G
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Ritter's dam break onto a dry bed: depth and velocity at time t.

    Parameters
    ----------
    x : array_like
        Positions [m].
    t : float
        Time since the dam vanished [s], ≥ 0.
    h_left : float
        Initial depth behind the dam (x < x0) [m]; dry ahead of it.
    x0 : float, optional
        Position of the dam [m].
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    h, u : ndarray
        Depth [m] and velocity [m s⁻¹] at x (u = 0 where h = 0).

    Notes
    -----
    With c0 = √(g h_left) and ξ = (x − x0)/t [1], [3]:
    h = h_left, u = 0 for ξ ≤ −c0; h = (2c0 − ξ)²/(9g), u = 2(c0 + ξ)/3 for
    −c0 < ξ < 2c0; h = 0 beyond the front ξ = 2c0.
    """
    x = np.asarray(x, dtype=np.float64)
    h_left = _check_positive("h_left", h_left)
    c0 = math.sqrt(g * h_left)
    if t <= 0:
        h = np.where(x < x0, h_left, 0.0)
        return h, np.zeros_like(h)
    xi = (x - x0) / t
    fan = (xi > -c0) & (xi < 2.0 * c0)
    h = np.where(xi <= -c0, h_left, 0.0)
    h = np.where(fan, (2.0 * c0 - xi) ** 2 / (9.0 * g), h)  # Ritter's parabola [1]
    u = np.where(fan, 2.0 / 3.0 * (c0 + xi), 0.0)
    return h, u


def stoker_middle_state(h_left: float, h_right: float, g: float = G) -> tuple[float, float, float]:
    """State between the rarefaction and the bore of Stoker's wet-bed dam break.

    Parameters
    ----------
    h_left, h_right : float
        Initial depths behind and ahead of the dam [m], h_left > h_right > 0.
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    h_m : float
        Depth of the middle state [m].
    u_m : float
        Its velocity [m s⁻¹].
    speed : float
        Speed of the bore [m s⁻¹].

    Notes
    -----
    h_m solves u_m = 2(√(g h_left) − √(g h_m)) (across the rarefaction) =
    (h_m − h_right) √(g (h_m + h_right)/(2 h_m h_right)) (across the bore) [2], [3];
    the bore speed follows from mass conservation, s = h_m u_m/(h_m − h_right).
    """
    h_left = _check_positive("h_left", h_left)
    h_right = _check_positive("h_right", h_right)
    if not h_right < h_left:
        raise ValueError(f"stoker_middle_state needs h_left > h_right; got {h_left} and {h_right}")

    def mismatch(hm: float) -> float:
        rarefaction = 2.0 * (math.sqrt(g * h_left) - math.sqrt(g * hm))
        bore = (hm - h_right) * math.sqrt(g * (hm + h_right) / (2.0 * hm * h_right))
        return rarefaction - bore

    h_m = brentq(mismatch, h_right, h_left, xtol=1e-15, rtol=4 * np.finfo(float).eps, maxiter=200)
    u_m = 2.0 * (math.sqrt(g * h_left) - math.sqrt(g * h_m))
    return h_m, u_m, h_m * u_m / (h_m - h_right)


def dam_break_stoker(
    x: ArrayLike, t: float, h_left: float, h_right: float, x0: float = 0.0, g: float = G
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Stoker's dam break onto a wet bed: depth and velocity at time t.

    Parameters
    ----------
    x : array_like
        Positions [m].
    t : float
        Time since the dam vanished [s], ≥ 0.
    h_left, h_right : float
        Initial depths behind (x < x0) and ahead of the dam [m], h_left > h_right ≥ 0
        (h_right = 0 is Ritter's solution).
    x0 : float, optional
        Position of the dam [m].
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    h, u : ndarray
        Depth [m] and velocity [m s⁻¹] at x.

    Notes
    -----
    Left state | rarefaction −c0 < ξ < u_m − c_m | middle state (h_m, u_m) | bore at
    ξ = s | right state, with ξ = (x − x0)/t, c = √(g h) and (h_m, u_m, s) from
    :func:`stoker_middle_state` [2], [3].
    """
    if h_right == 0:
        return dam_break_ritter(x, t, h_left, x0, g)
    x = np.asarray(x, dtype=np.float64)
    h_m, u_m, speed = stoker_middle_state(h_left, h_right, g)
    if t <= 0:
        h = np.where(x < x0, h_left, h_right)
        return h, np.zeros_like(h)
    c0 = math.sqrt(g * h_left)
    cm = math.sqrt(g * h_m)
    xi = (x - x0) / t
    h = np.full(x.shape, h_right)
    u = np.zeros(x.shape)
    fan = (xi > -c0) & (xi < u_m - cm)
    middle = (xi >= u_m - cm) & (xi < speed)
    h = np.where(xi <= -c0, h_left, h)
    h = np.where(fan, (2.0 * c0 - xi) ** 2 / (9.0 * g), h)  # centred rarefaction [2]
    u = np.where(fan, 2.0 / 3.0 * (c0 + xi), u)
    h = np.where(middle, h_m, h)
    u = np.where(middle, u_m, u)
    return h, u


@dataclass(frozen=True)
class BoreJump:
    """A bore (moving hydraulic jump) and the states on its two sides.

    Attributes
    ----------
    speed : float
        Bore speed along +x [m s⁻¹].
    h_ahead, u_ahead : float
        State the bore runs into [m], [m s⁻¹].
    h_behind, u_behind : float
        State behind the bore [m], [m s⁻¹].
    froude : float
        Froude number of the inflow relative to the bore, (s − u_ahead)/√(g h_ahead) [-].
    head_loss : float
        Energy head dissipated in the bore, (h_behind − h_ahead)³/(4 h_ahead h_behind) [m].
    """

    speed: float
    h_ahead: float
    u_ahead: float
    h_behind: float
    u_behind: float
    froude: float
    head_loss: float


def bore_jump(h_ahead: float, u_ahead: float, h_behind: float, g: float = G) -> BoreJump:
    """Rankine–Hugoniot relations of a bore running along +x into the state (h_ahead, u_ahead).

    Parameters
    ----------
    h_ahead : float
        Depth ahead of the bore [m], > 0.
    u_ahead : float
        Velocity ahead of the bore [m s⁻¹].
    h_behind : float
        Depth behind the bore [m], > h_ahead (a bore deepens the water it passes).
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    BoreJump
        Speed, both states, Froude number and head loss.

    Notes
    -----
    Mass and momentum conservation across a discontinuity moving at s [2], [3]:
    s (h_b − h_a) = h_b u_b − h_a u_a and s (h_b u_b − h_a u_a) = (h_b u_b² + g h_b²/2)
    − (h_a u_a² + g h_a²/2). For a bore moving toward +x (into the shallower state)

        s = u_a + √(g h_b (h_a + h_b) / (2 h_a)),   u_b = s − h_a (s − u_a)/h_b.

    For a bore moving toward −x, mirror x (negate the velocities and the speed).
    """
    h_ahead = _check_positive("h_ahead", h_ahead)
    h_behind = _check_positive("h_behind", h_behind)
    if not h_behind > h_ahead:
        raise ValueError(f"bore_jump needs h_behind > h_ahead; got {h_behind} and {h_ahead}")
    relative = math.sqrt(g * h_behind * (h_ahead + h_behind) / (2.0 * h_ahead))  # s − u_a
    speed = u_ahead + relative
    u_behind = speed - h_ahead * relative / h_behind  # mass conservation
    return BoreJump(
        speed=speed,
        h_ahead=h_ahead,
        u_ahead=float(u_ahead),
        h_behind=h_behind,
        u_behind=u_behind,
        froude=relative / math.sqrt(g * h_ahead),
        head_loss=(h_behind - h_ahead) ** 3 / (4.0 * h_ahead * h_behind),
    )


def wall_reflection(h_stream: float, u_stream: float, g: float = G) -> tuple[float, float]:
    """Bore reflected when a uniform stream (h, u > 0) runs into a wall at its +x end.

    Parameters
    ----------
    h_stream : float
        Depth of the incoming stream [m], > 0.
    u_stream : float
        Its velocity toward the wall [m s⁻¹], > 0.
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    h_wall : float
        Depth between the reflected bore and the wall, where the water is at rest [m].
    speed : float
        Velocity of the reflected bore [m s⁻¹] (negative: it runs away from the wall).

    Notes
    -----
    In the mirror frame the bore runs along +x into (h_stream, −u_stream) and leaves
    water at rest behind it: h_wall solves u_behind(h_wall) = 0 in :func:`bore_jump`,
    i.e. u_stream = (h_wall − h_stream) √(g (h_wall + h_stream)/(2 h_wall h_stream)) [2].
    """
    h_stream = _check_positive("h_stream", h_stream)
    u_stream = _check_positive("u_stream", u_stream)

    def mismatch(h_wall: float) -> float:
        return (h_wall - h_stream) * math.sqrt(g * (h_wall + h_stream) / (2.0 * h_wall * h_stream)) - u_stream

    upper = h_stream * 2.0
    while mismatch(upper) < 0:
        upper *= 2.0
    h_wall = brentq(mismatch, h_stream, upper, xtol=1e-15, rtol=4 * np.finfo(float).eps, maxiter=200)
    jump = bore_jump(h_stream, -u_stream, h_wall, g)
    return h_wall, -jump.speed


def _hump_celerity(xi, h0, amplitude, width, x_c, g):
    """c = √(g h) of the initial hump h0 + a exp(−((ξ − x_c)/w)²) and its derivative dc/dξ."""
    bump = amplitude * np.exp(-(((xi - x_c) / width) ** 2))
    c = np.sqrt(g * (h0 + bump))
    dc = g * bump * (-2.0 * (xi - x_c) / width**2) / (2.0 * c)
    return c, dc


def simple_wave_breaking_time(h0: float, amplitude: float, width: float, g: float = G) -> float:
    """Time at which the Gaussian simple wave of :func:`simple_wave` first breaks [s].

    Parameters
    ----------
    h0, amplitude, width : float
        Still depth [m], hump amplitude [m] (> 0) and e-folding half-width [m].
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    float
        t_b = 1 / max(−dλ/dξ) with λ = 3 c(ξ) − 2 c0 the characteristic speed [4].
    """
    xi = np.linspace(-4.0 * width, 4.0 * width, 20001)
    _, dc = _hump_celerity(xi, h0, amplitude, width, 0.0, g)
    return float(1.0 / np.max(-3.0 * dc))


def simple_wave(
    x: ArrayLike, t: float, h0: float, amplitude: float, width: float, x_c: float = 0.0, g: float = G
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """A Gaussian hump running along +x into still water as a simple wave, exact before breaking.

    Parameters
    ----------
    x : array_like
        Positions [m].
    t : float
        Time [s], 0 ≤ t < :func:`simple_wave_breaking_time`.
    h0 : float
        Still-water depth [m].
    amplitude : float
        Height a of the initial hump [m], > 0.
    width : float
        Its e-folding half-width w [m]: h(x, 0) = h0 + a exp(−((x − x_c)/w)²).
    x_c : float, optional
        Initial position of the crest [m].
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    h, u : ndarray
        Depth [m] and velocity [m s⁻¹]; at t = 0, u = 2(√(g h) − √(g h0)).

    Notes
    -----
    The Riemann invariant u − 2c (c = √(g h)) is −2c0 everywhere, so u = 2(c − c0) and
    c is constant along the characteristics dx/dt = u + c = 3c − 2c0 [2], [4]:
    c(x, t) = c(ξ, 0) with x = ξ + (3 c(ξ, 0) − 2 c0) t, solved for ξ here by bisection
    (the map is monotonic before breaking).
    """
    x = np.asarray(x, dtype=np.float64)
    h0 = _check_positive("h0", h0)
    amplitude = _check_positive("amplitude", amplitude)
    width = _check_positive("width", width)
    if t >= simple_wave_breaking_time(h0, amplitude, width, g):
        raise ValueError(f"simple_wave is exact only before breaking; t = {t} s is too late")
    c0 = math.sqrt(g * h0)
    c_top = math.sqrt(g * (h0 + amplitude))
    # foot of the characteristic ξ in [x − (3 c_top − 2 c0) t, x − c0 t]
    lo = x - (3.0 * c_top - 2.0 * c0) * t - 1e-12
    hi = x - c0 * t + 1e-12
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        c, _ = _hump_celerity(mid, h0, amplitude, width, x_c, g)
        past = mid + (3.0 * c - 2.0 * c0) * t > x
        hi = np.where(past, mid, hi)
        lo = np.where(past, lo, mid)
    c, _ = _hump_celerity(0.5 * (lo + hi), h0, amplitude, width, x_c, g)
    return c * c / g, 2.0 * (c - c0)


def thacker_planar(
    x: ArrayLike, t: float, h0: float, a: float, amplitude: float, x_c: float = 0.0, g: float = G
) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    """Thacker's planar surface oscillating in a parabolic bowl, with two moving shorelines.

    Parameters
    ----------
    x : array_like
        Positions [m].
    t : float
        Time [s].
    h0 : float
        Depth at the centre of the bowl when the surface is level [m], > 0.
    a : float
        Half-width of the wet region [m], > 0: the bed is z_b = h0 ((x − x_c)²/a² − 1).
    amplitude : float
        Velocity amplitude B [m s⁻¹], ≥ 0: the water moves as a slab, u = B sin(ωt).
    x_c : float, optional
        Centre of the bowl [m].
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    bed, h, u : ndarray
        Bed elevation [m], depth [m] (0 on dry ground) and velocity [m s⁻¹] (0 on dry ground).

    Notes
    -----
    With ξ = x − x_c and ω = √(2 g h0)/a, the surface stays a plane and the velocity
    uniform [5] (SWASHES [3], sect. 4.2.2, in its notation B, h0, a)::

        h(x, t) = h0 − (h0/a²) (ξ + (B/ω) cos ωt)²   where positive, else 0,
        u(x, t) = B sin ωt   on the wet part,   η = z_b + h = −(B ω/g) cos(ωt) ξ − (B²/2g) cos² ωt

    (the depth is the bed's parabola turned over, its centre at ξ = −(B/ω) cos ωt;
    the shorelines ξ± = −(B/ω) cos ωt ± a move with the water, ẋ± = u). Smooth
    inside the wet region, with a kink of h at each shoreline.
    """
    x = np.asarray(x, dtype=np.float64)
    h0 = _check_positive("h0", h0)
    a = _check_positive("a", a)
    if not (math.isfinite(amplitude) and amplitude >= 0):
        raise ValueError(f"amplitude must be finite and >= 0; got {amplitude}")
    omega = math.sqrt(2.0 * g * h0) / a
    xi = x - x_c
    bed = h0 * (xi * xi / (a * a) - 1.0)
    centre = -(amplitude / omega) * math.cos(omega * t)
    h = np.maximum(0.0, h0 - (h0 / (a * a)) * (xi - centre) ** 2)
    u = np.where(h > 0.0, amplitude * math.sin(omega * t), 0.0)
    return bed, h, u


def thacker_paraboloid(
    x: ArrayLike, y: ArrayLike, t: float, h0: float, a: float, eta: float,
    x_c: float = 0.0, y_c: float = 0.0, g: float = G,
) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    """Thacker's planar surface circling in a paraboloid of revolution: a moving shoreline in 2D.

    Parameters
    ----------
    x, y : array_like
        Positions [m] (broadcast together).
    t : float
        Time [s].
    h0 : float
        Depth at the centre when the water is level [m], > 0.
    a : float
        Radius of the bowl's rim at the still level [m], > 0: z_b = −h0 (1 − r²/a²).
    eta : float
        Radius of the circle the wet disc's centre runs on [m], ≥ 0 and < a.
    x_c, y_c : float, optional
        Centre of the bowl [m].
    g : float, optional
        Gravitational acceleration [m s⁻²].

    Returns
    -------
    bed, h, u, v : ndarray
        Bed [m], depth [m] (0 on dry ground), velocities [m s⁻¹] (0 on dry ground).

    Notes
    -----
    With X = x − x_c, Y = y − y_c and ω = √(2 g h0)/a (Thacker 1981 [5], Sect. 4;
    SWASHES [3], sect. 4.2.2, "planar surface in a paraboloid")::

        η_s = (eta h0/a²) (2 X cos ωt + 2 Y sin ωt − eta),   h = max(0, η_s − z_b),
        u = −eta ω sin ωt,   v = eta ω cos ωt,

    so the wet region is the disc of radius a about eta (cos ωt, sin ωt), which moves
    with the water's uniform velocity; h has a kink along the whole circle.
    """
    X = np.asarray(x, dtype=np.float64) - x_c
    Y = np.asarray(y, dtype=np.float64) - y_c
    h0 = _check_positive("h0", h0)
    a = _check_positive("a", a)
    if not (math.isfinite(eta) and 0.0 <= eta < a):
        raise ValueError(f"eta must be finite, >= 0 and < a = {a}; got {eta}")
    omega = math.sqrt(2.0 * g * h0) / a
    bed = -h0 * (1.0 - (X * X + Y * Y) / (a * a))
    surface = (eta * h0 / (a * a)) * (2.0 * X * math.cos(omega * t) + 2.0 * Y * math.sin(omega * t) - eta)
    h = np.maximum(0.0, surface - bed)
    wet = h > 0.0
    u = np.where(wet, -eta * omega * math.sin(omega * t), 0.0)
    v = np.where(wet, eta * omega * math.cos(omega * t), 0.0)
    return bed, h, u, v


def solitary_runup(height: float, depth: float, cot_beta: float) -> float:
    """Maximum run-up R [m] of a non-breaking solitary wave of height H on a plane beach of slope 1/cot β.

    Synolakis' (1987 [6]) run-up law, R/d = 2.831 √(cot β) (H/d)^{5/4}, from the linear shallow-water
    theory, whose maximum run-up the nonlinear theory shares [6]; it agrees with his laboratory waves that
    did not break (H/d up to about 0.044 on the 1:19.85 beach).
    """
    height = _check_positive("height", height)
    depth = _check_positive("depth", depth)
    cot_beta = _check_positive("cot_beta", cot_beta)
    return 2.831 * math.sqrt(cot_beta) * (height / depth) ** 1.25 * depth


def solitary_wave(x: ArrayLike, height: float, depth: float, cot_beta: float, g: float = G
                  ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Surface elevation η [m] and velocity u [m s⁻¹] of Synolakis' (1987 [6]) initial solitary wave.

    The beach's toe is at x = −X₀ = −d cot β (the still shoreline at x = 0, the beach rising towards +x);
    the crest starts at x = −X₁, X₁ = X₀ + L with L = arccosh(√20)/γ, γ = √(3H/(4d)) / d, so that the
    wave's front (where η = H/20) stands at the toe; η = H sech²(γ (x + X₁)), u = √(g/d) η (towards +x).
    """
    height = _check_positive("height", height)
    depth = _check_positive("depth", depth)
    cot_beta = _check_positive("cot_beta", cot_beta)
    gamma = math.sqrt(3.0 * height / (4.0 * depth)) / depth
    x1 = depth * cot_beta + math.acosh(math.sqrt(20.0)) / gamma
    eta = height / np.cosh(gamma * (np.asarray(x, dtype=float) + x1)) ** 2
    return eta, math.sqrt(g / depth) * eta
