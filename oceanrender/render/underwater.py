"""Sunlight under a wavy surface: the refracted-sun lobe and its next-event estimator.

Light scattered inside the water (by the medium or a seafloor) reaches a viewer
mostly as *sunlight* that crossed the surface on its way in. Mitsuba's
``volpath`` can only find that light by chance: a shadow ray from inside the
water towards the sun is blocked by the dielectric surface, so the sun is
found only when a path, sampled from the phase function, happens to leave the
water within the narrow lobe of directions that refract towards the sun. At
preview sample counts that is a speckle of rare bright samples whose mean is
right but whose median is far too dark (in turbid water the mean was 3× the
median-clipped mean).

This module adds a third strategy at every vertex *inside* the water (medium
scattering events and opaque surfaces such as the seafloor): sample the
direction d towards the surface from the distribution q(d) of directions in
which the sun's light travels after refraction through a rough surface whose
mean normal is +z (Beckmann facets of roughness α_q; α_q² = the total
mean-square slope of the sea, resolved plus unresolved), trace d to the
surface, and there do ordinary next-event estimation of the emitters through
the surface's actual BSDF. The three ways of generating a path segment
x → y (surface) → z (emitter) are combined with the power heuristic
(Veach & Guibas 1995):

    A: d from the phase function/BSDF at x (pdf p_x), z by emitter sampling at y (p_e)
    B: d from q (pdf q),                          z by emitter sampling at y (p_e)
    C: d from p_x,                                z by BSDF sampling at y (p_s)

    w_k = P_k² / (P_A² + P_B² + P_C²),  P_A = p_x p_e,  P_B = q p_e,  P_C = p_x p_s.

The weights add up to one for every path, so the estimator is unbiased
whatever q is; q only decides how much variance is left. The distance x → y
enters B as the exact transmittance exp(−σ_t |xy|) (homogeneous medium).

References
----------
.. [1] B. Walter, S. R. Marschner, H. Li and K. E. Torrance, "Microfacet models
   for refraction through rough surfaces," Proc. EGSR 2007, pp. 195–206,
   doi:10.2312/EGWR/EGSR07/195-206 — Eq. 16 (generalised half vector),
   Eq. 17 (its Jacobian), Eq. 25 (Beckmann distribution) and Eqs. 28 (sampling it).
.. [2] E. Veach and L. J. Guibas, "Optimally combining sampling techniques for
   Monte Carlo rendering," Proc. SIGGRAPH '95, pp. 419–428,
   doi:10.1145/218380.218498 — the power heuristic (β = 2).
.. [4] A. Wilkie, S. Nawaz, M. Droske, A. Weidlich and J. Hanika, "Hero wavelength
   spectral sampling," Computer Graphics Forum 33(4), 123–131, 2014,
   doi:10.1111/cgf.12419 — one-sample MIS over the wavelengths of a path.
.. [3] C. Cox and W. Munk, "Measurement of the roughness of the sea surface from
   photographs of the sun's glitter," J. Opt. Soc. Am. 44(11), 838–850, 1954,
   doi:10.1364/JOSA.44.000838 — total mean-square slope 0.003 + 5.12e-3 U₁₂.₅.
"""

from __future__ import annotations

import math


def cox_munk_mean_square_slope(wind_speed: float) -> float:
    """Total mean-square slope of a clean sea surface [-] (Cox & Munk 1954).

    Parameters
    ----------
    wind_speed : float   Wind speed 12.5 m above the sea [m s⁻¹] (≈ U₁₀ within a few %).

    Returns
    -------
    float   ⟨s_x² + s_y²⟩ = 0.003 + 5.12·10⁻³ U [-].
    """
    if not (math.isfinite(wind_speed) and wind_speed >= 0):
        raise ValueError(f"wind_speed must be finite and ≥ 0 [m/s], got {wind_speed!r}")
    return 0.003 + 5.12e-3 * float(wind_speed)  # Eq. for the clean surface in [3]


def sun_lobe_functions():
    """(sample, pdf) of the refracted-sun lobe q(d) for the active Mitsuba variant.

    ``sample(u, sun, eta, alpha) -> (d, pdf)`` and ``pdf(d, sun, eta, alpha) -> pdf``
    work on Mitsuba/Dr.Jit vectors: ``u`` a Point2f of uniform numbers, ``sun``
    the unit vector towards the sun (z up), ``eta`` the refractive index of the
    water relative to air [-], ``alpha`` the Beckmann roughness α_q [-].
    ``d`` is the unit direction *from a point in the water towards the surface*
    along which the refracted sunlight arrives (upward; −d is the direction the
    light travels), and ``pdf`` its density per unit solid angle [sr⁻¹].
    """
    import drjit as dr  # noqa: PLC0415
    import mitsuba as mi  # noqa: PLC0415

    def beckmann_d(m, alpha):
        # D(m) = exp(−tan²θ_m/α²) / (π α² cos⁴θ_m): Eq. 25 of [1].
        cos2 = dr.square(m.z)
        tan2 = (1.0 - cos2) / dr.maximum(cos2, 1e-12)
        value = dr.exp(-tan2 / dr.square(alpha)) / (dr.pi * dr.square(alpha) * dr.square(cos2))
        return dr.select(m.z > 0, value, 0.0)

    def refraction_jacobian(sun, t, m, eta):
        # |∂ω_h/∂ω_o| = η_o² |ω_o·h| / (η_i (ω_i·h) + η_o (ω_o·h))², ω_i = sun (η_i = 1),
        # ω_o = t (η_o = η): Eq. 17 of [1].
        i_dot = dr.dot(sun, m)
        o_dot = dr.dot(t, m)
        denominator = dr.square(i_dot + eta * o_dot)
        return dr.square(eta) * dr.abs(o_dot) / dr.maximum(denominator, 1e-20)

    def sample(u, sun, eta, alpha):
        # Facet normal from D(m) cosθ_m: tan²θ_m = −α² ln(1 − u₁), φ = 2π u₂ (Eqs. 28 of [1]).
        tan2 = -dr.square(alpha) * dr.log(dr.maximum(1.0 - u.x, 1e-12))
        cos_m = dr.rsqrt(1.0 + tan2)
        sin_m = dr.safe_sqrt(1.0 - dr.square(cos_m))
        phi = 2.0 * dr.pi * u.y
        m = mi.Vector3f(sin_m * dr.cos(phi), sin_m * dr.sin(phi), cos_m)
        # The sunlight, travelling along −sun, refracts through the facet into the water.
        cos_i = dr.dot(sun, m)
        ratio = 1.0 / eta
        cos_t2 = 1.0 - dr.square(ratio) * (1.0 - dr.square(cos_i))
        t = -ratio * sun + (ratio * cos_i - dr.safe_sqrt(cos_t2)) * m
        valid = (cos_i > 0) & (cos_t2 > 0) & (t.z < 0)
        pdf_m = beckmann_d(m, alpha) * m.z
        pdf = dr.select(valid, pdf_m * refraction_jacobian(sun, t, m, eta), 0.0)
        return -t, pdf

    def pdf(d, sun, eta, alpha):
        t = -d
        # Generalised half vector h = −(ω_i + η ω_o)/|…| (Eq. 16 of [1]), pointing up.
        h = -(sun + eta * t)
        m = dr.normalize(h)
        valid = (t.z < 0) & (m.z > 0) & (dr.dot(sun, m) > 0) & (dr.dot(t, m) < 0) & (dr.norm(h) > 1e-9)
        value = beckmann_d(m, alpha) * m.z * refraction_jacobian(sun, t, m, eta)
        return dr.select(valid, value, 0.0)

    return sample, pdf



def _power_heuristic3(a, b, c):
    """a² / (a² + b² + c²), zero where all three vanish (Veach & Guibas 1995)."""
    import drjit as dr  # noqa: PLC0415

    a2 = dr.square(a)
    total = a2 + dr.square(b) + dr.square(c)
    return dr.select(total > 0, a2 / dr.select(total > 0, total, 1.0), 0.0)


def trace_in_water(scene, sampler, ray, medium, active, *, is_water_surface, sun, eta: float, alpha: float,
                   max_depth: int, rr_depth: int):
    """Radiance along ``ray``, which starts inside the water ``medium``, until it leaves the water.

    A path tracer for the inside of the water body with the three strategies
    for emitters seen through the surface (see the module docstring). It
    follows the path through the medium (free-flight sampling with spectral
    MIS over the path's wavelengths [4]), off opaque surfaces
    in the water (the seafloor) and off the underside of the water surface;
    where the path refracts out into the air it stops, and
    :func:`escaped_radiance` adds the rest.

    Parameters
    ----------
    scene, sampler : mitsuba.Scene, mitsuba.Sampler
    ray : mitsuba.Ray3f                   Starting inside the water [m].
    medium : mitsuba.Medium               The homogeneous water medium (σ in m⁻¹).
    active : mitsuba.Bool                 Lanes to trace.
    is_water_surface : callable           ``BSDFPtr -> Bool``: the BSDF is the air–water surface's.
    sun : mitsuba.Vector3f or 3 floats    Unit vector towards the sun (z up); pass an opaque
                                          ``Vector3f`` to change it between renders without recompiling.
    eta : float                           Refractive index of water relative to air [-].
    alpha : float                         Beckmann roughness α_q of the refracted-sun lobe [-].
    max_depth, rr_depth : int             Vertices allowed in the water; Russian roulette after ``rr_depth``.

    Returns
    -------
    tuple
        ``(L, escape)``: the radiance gathered in the water [W m⁻² sr⁻¹ nm⁻¹]
        and the escaping rays, a tuple for :func:`escaped_radiance`.
    """
    import drjit as dr  # noqa: PLC0415
    import mitsuba as mi  # noqa: PLC0415

    sample_lobe, pdf_lobe = sun_lobe_functions()
    # NOTE: Python floats become literals in the traced kernel; an (opaque) Vector3f is used as is.
    sun_v = sun if isinstance(sun, mi.Vector3f) else mi.Vector3f(*[float(c) for c in sun])
    ctx = mi.BSDFContext()
    phase = medium.phase_function()
    n_channels = dr.size_v(mi.Spectrum)

    def through_surface(si, bsdf, sampler, on):
        """Emitter sampling at a point of the water surface, through its BSDF.

        Returns (f·L_e/p_e [W m⁻² sr⁻¹ nm⁻¹ per unit throughput], p_e, p_s, valid): the
        emitter-sampling and BSDF-sampling densities of the sampled direction (p_s = 0 for
        a delta emitter), for the MIS weights of strategies A, B and D.
        """
        ds, em = scene.sample_emitter_direction(si, sampler.next_2d(on), True, on)
        f_y, p_s = bsdf.eval_pdf(ctx, si, si.to_local(ds.d), on)
        return f_y * em, ds.pdf, dr.select(ds.delta, 0.0, p_s), on & (ds.pdf > 0)

    def sun_strategy(vertex, f_and_pdf, beta, sigma_t, sampler, on):
        """Strategy B at an in-water vertex: d ~ q, trace to the surface, emitter sampling there."""
        d, q = sample_lobe(sampler.next_2d(on), sun_v, eta, alpha)
        on &= q > 0
        f_x, p_x = f_and_pdf(d, on)
        ray_b = vertex.spawn_ray(d)
        si_b = scene.ray_intersect(ray_b, on)
        bsdf_b = si_b.bsdf(ray_b)
        on &= si_b.is_valid() & is_water_surface(bsdf_b)
        transmittance = dr.exp(-sigma_t * si_b.t)
        light, p_e, p_s, valid = through_surface(si_b, bsdf_b, sampler, on)
        w = _power_heuristic3(q * p_e, p_x * p_e, p_x * p_s)
        contribution = beta * f_x * transmittance * light * (w / dr.select(q > 0, q, 1.0))
        return dr.select(valid, contribution, 0.0)

    def cond(sampler, ray, beta, L, depth, active, prev_r, prev_in_water, *escape):
        return active

    def body(sampler, ray, beta, L, depth, active, prev_r, prev_in_water, esc, esc_ray, esc_beta, esc_p, esc_r,
             esc_delta, esc_it):
        # ---- Russian roulette on the throughput after rr_depth vertices (as volpath).
        q_rr = dr.minimum(dr.max(beta), 0.99)
        roulette = active & (depth >= rr_depth)
        active &= ~roulette | (sampler.next_1d(active) < q_rr)
        beta = dr.select(roulette, beta / dr.select(q_rr > 0, q_rr, 1.0), beta)

        # ---- Free flight to the next scattering event or surface.
        # NOTE: the distance is sampled on one of the path's wavelengths chosen at random per
        # segment, and weighted by the mean of the densities of all of them (the one-sample
        # balance heuristic over wavelengths, "hero wavelength" spectral MIS, Wilkie et al.
        # 2014). volpath samples on the first wavelength only: where σ_t(λ) varies several-fold
        # (turbid water) its weights tr/pdf₀ explode into coloured speckle.
        si = scene.ray_intersect(ray, active)
        channel = mi.UInt32(dr.minimum(sampler.next_1d(active) * n_channels, n_channels - 1))
        mei = medium.sample_interaction(ray, sampler.next_1d(active), channel, active)
        sigma_t = mei.sigma_t
        scattered = active & mei.is_valid() & (mei.t < si.t)
        mei.t = dr.select(scattered, mei.t, dr.inf)
        # Strategy D: the direction sampled at the previous in-water vertex, followed to the
        # surface with its exact transmittance, and emitter sampling there.
        bsdf = si.bsdf(ray)
        on_surface = active & si.is_valid() & is_water_surface(bsdf)
        connect = on_surface & prev_in_water & mi.has_flag(bsdf.flags(), mi.BSDFFlags.Smooth)
        light, p_e, p_s, valid = through_surface(si, bsdf, sampler, connect)
        w_d = _power_heuristic3(p_e, prev_r * p_e, p_s)
        L += dr.select(valid, beta * dr.exp(-sigma_t * si.t) * light * w_d, 0.0)

        tr, free_pdf = medium.transmittance_eval_pdf(mei, si, active)
        pdf_mean = dr.mean(free_pdf)
        beta = dr.select(active, beta * dr.select(pdf_mean > 0, tr / dr.select(pdf_mean > 0, pdf_mean, 1.0), 0.0),
                         beta)
        depth = dr.select(active, depth + 1, depth)

        # ---- Medium scattering: strategy B, then phase-function sampling.
        scatter = scattered & (depth < max_depth)
        phase_ctx = mi.PhaseFunctionContext(sampler)
        beta_s = beta * mei.sigma_s

        def phase_f_pdf(d, on):
            value, pdf = phase.eval_pdf(phase_ctx, mei, d, on)
            return mi.Spectrum(value), pdf

        L += sun_strategy(mei, phase_f_pdf, beta_s, sigma_t, sampler, scatter)
        wo, phase_w, phase_pdf = phase.sample(phase_ctx, mei, sampler.next_1d(scatter), sampler.next_2d(scatter),
                                              scatter)
        r_phase = pdf_lobe(wo, sun_v, eta, alpha) / dr.select(phase_pdf > 0, phase_pdf, 1.0)

        # ---- Surfaces: the water surface from below, or an opaque surface in the water.
        surface = active & ~scattered & si.is_valid() & (depth < max_depth)
        water = surface & is_water_surface(bsdf)
        opaque = surface & ~water

        def bsdf_f_pdf(d, on):
            return bsdf.eval_pdf(ctx, si, si.to_local(d), on)

        L += sun_strategy(si, bsdf_f_pdf, beta, sigma_t, sampler, opaque)

        # Emitter sampling through the underside of the water surface: only for paths that
        # come from outside the water or off its underside (from an in-water vertex, D did it).
        nee = water & mi.has_flag(bsdf.flags(), mi.BSDFFlags.Smooth) & ~prev_in_water
        light, p_e, p_s, valid = through_surface(si, bsdf, sampler, nee)
        w_a = _power_heuristic3(p_e, prev_r * p_e, p_s)
        L += dr.select(valid, beta * light * w_a, 0.0)

        # BSDF sampling at surfaces.
        sample_surface = water | opaque
        bs, bsdf_w = bsdf.sample(ctx, si, sampler.next_1d(sample_surface), sampler.next_2d(sample_surface),
                                 sample_surface)
        sample_surface &= (bs.pdf > 0) & dr.any(bsdf_w != 0.0)
        wo_s = si.to_world(bs.wo)
        delta = mi.has_flag(bs.sampled_type, mi.BSDFFlags.Delta)
        leaves = sample_surface & water & (si.target_medium(wo_s) != mi.MediumPtr(medium))
        r_surface = dr.select(opaque & ~delta,
                              pdf_lobe(wo_s, sun_v, eta, alpha) / dr.select(bs.pdf > 0, bs.pdf, 1.0), 0.0)

        # ---- Escapes: keep the ray and what the MIS weight of its emitter hit needs.
        esc |= leaves
        esc_ray[leaves] = si.spawn_ray(wo_s)
        esc_beta[leaves] = beta * bsdf_w
        esc_p[leaves] = bs.pdf
        esc_r[leaves] = prev_r
        esc_delta[leaves] = delta
        esc_it[leaves] = si

        # ---- Next segment.
        ray[scatter] = mei.spawn_ray(wo)
        ray[sample_surface & ~leaves] = si.spawn_ray(wo_s)
        beta = dr.select(scatter, beta_s * phase_w, dr.select(sample_surface, beta * bsdf_w, beta))
        prev_r = dr.select(scatter, r_phase, dr.select(sample_surface, r_surface, prev_r))
        prev_in_water = scatter | (sample_surface & opaque)
        active = (scatter & (phase_pdf > 0)) | (sample_surface & ~leaves)
        active &= dr.any(beta != 0.0)
        return (sampler, ray, beta, L, depth, active, prev_r, prev_in_water, esc, esc_ray, esc_beta, esc_p, esc_r,
                esc_delta, esc_it)

    state = (sampler, mi.Ray3f(ray), mi.Spectrum(1.0), mi.Spectrum(0.0), mi.UInt32(0), mi.Bool(active),
             mi.Float(0.0), mi.Bool(False), mi.Bool(False), dr.zeros(mi.Ray3f), mi.Spectrum(0.0), mi.Float(0.0), mi.Float(0.0),
             mi.Bool(False), dr.zeros(mi.Interaction3f))
    state = dr.while_loop(state, cond, body, label="oceanrender_in_water")
    return state[3], state[8:]


def escaped_radiance(scene, sampler, continuation, escape):
    """Radiance brought back by the rays that left the water (see :func:`trace_in_water`).

    Adds the first emitter a ray meets, weighted by the power heuristic of
    strategy C against A and B, and continues it with ``continuation`` (a
    ``volpath`` with ``hide_emitters``, so that emission is not counted twice)
    [W m⁻² sr⁻¹ nm⁻¹].
    """
    import drjit as dr  # noqa: PLC0415
    import mitsuba as mi  # noqa: PLC0415

    esc, ray, beta, p_s, r, delta, it = escape
    si = scene.ray_intersect(ray, esc)
    ds = mi.DirectionSample3f(scene, si, it)
    glossy = esc & ~delta
    p_e = scene.pdf_emitter_direction(it, ds, glossy)
    w = dr.select(delta, 1.0, _power_heuristic3(p_s, p_e, r * p_e))
    L = si.emitter(scene, esc).eval(si, esc) * w
    L += continuation.sample(scene, sampler, mi.RayDifferential3f(ray), None, esc & si.is_valid())[0]
    return dr.select(esc, beta * L, 0.0)
