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

Sea water's extinction varies ~50-fold over the visible (0.01 m⁻¹ in the violet,
0.6 m⁻¹ at 700 nm), so the sampling of free-flight distances decides the colour
noise. :func:`trace_path` samples every flight of a path on one *hero* channel,
chosen uniformly per path, and weights every term the path adds by the one-sample
balance heuristic over all of its wavelengths' path densities (Wilkie et al.
2014 [4]; Veach 1997 [5], §9.2.4). The path tracer before it weighted each flight
by the mean of the channels' densities of that flight alone while Mitsuba
sampled every flight on channel 0 (``sample_interaction`` ignores its channel
argument in spectral variants; checked directly): for paths of more than one flight that is
biased (mean of products ≠ product of means: +5 % luminance, +20 % Z for a
deep medium whose σ_t rises from 1 to 8 m⁻¹ over the spectrum) and its weights
grow like C^k with the number k of flights: the violet fireflies of issue 15
(docs/fireflies.md).

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
.. [5] E. Veach, "Robust Monte Carlo methods for light transport simulation,"
   PhD thesis, Stanford University, 1997 — §9.2.4, the one-sample MIS model and
   its balance heuristic.
.. [3] C. Cox and W. Munk, "Measurement of the roughness of the sea surface from
   photographs of the sun's glitter," J. Opt. Soc. Am. 44(11), 838–850, 1954,
   doi:10.1364/JOSA.44.000838 — total mean-square slope 0.003 + 5.12e-3 U₁₂.₅.
"""

from __future__ import annotations

import math


#: The largest float32 below 1: uniform numbers are clamped to it where 1 would make a logarithm infinite.
ONE_MINUS_EPSILON = 0.99999994


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



class _SharedHit:
    """The BSDF of a path's hits (``bsdf``, a ``BSDFPtr``) where the lanes ``on`` hit a surface whose
    shading frame is evaluated once per hit (``prepared``: :meth:`SeaSurfaceBSDF.prepared
    <oceanrender.render.sea_shading.SeaSurfaceBSDF.prepared>`): its methods route those lanes to
    ``prepared`` and the others to ``bsdf``."""

    def __init__(self, bsdf, prepared, on):
        self.bsdf, self.prepared, self.on = bsdf, prepared, on

    def flags(self):
        return self.bsdf.flags()

    def eval_pdf(self, ctx, si, wo, active=True):
        import drjit as dr  # noqa: PLC0415

        value, pdf = self.prepared.eval_pdf(ctx, si, wo, active & self.on)
        value_b, pdf_b = self.bsdf.eval_pdf(ctx, si, wo, active & ~self.on)
        return dr.select(self.on, value, value_b), dr.select(self.on, pdf, pdf_b)

    def sample(self, ctx, si, sample1, sample2, active=True):
        import drjit as dr  # noqa: PLC0415

        bs, weight = self.prepared.sample(ctx, si, sample1, sample2, active & self.on)
        bs_b, weight_b = self.bsdf.sample(ctx, si, sample1, sample2, active & ~self.on)
        return dr.select(self.on, bs, bs_b), dr.select(self.on, weight, weight_b)

    def pdf(self, ctx, si, wo, active=True):
        import drjit as dr  # noqa: PLC0415

        return dr.select(self.on, self.prepared.pdf(ctx, si, wo, active & self.on),
                         self.bsdf.pdf(ctx, si, wo, active & ~self.on))


def _power_heuristic3(a, b, c):
    """a² / (a² + b² + c²), zero where all three vanish (Veach & Guibas 1995)."""
    import drjit as dr  # noqa: PLC0415

    a2 = dr.square(a)
    total = a2 + dr.square(b) + dr.square(c)
    return dr.select(total > 0, a2 / dr.select(total > 0, total, 1.0), 0.0)


def hero_free_flight_update(weight, pdf_ratio, value, pdf):
    """One free flight of a hero-wavelength path: the new (W, S) of :func:`trace_path`.

    One-sample MIS over the path's C wavelengths with the balance heuristic [4, 5]:
    the path's distances are all sampled on one hero channel h, chosen uniformly per
    path, so the density of the whole path under technique j is p_j(x̄) = Πₖ πⱼ(tₖ), and
    the estimator of channel i is f_i(x̄) / ((1/C) Σ_j p_j(x̄)) (Eq. 6 of [4]). It is
    carried as ``weight`` W_i = f_i / p̄ and ``pdf_ratio`` S_j = p_j / p̄ (p̄ the mean of
    the p_j, so mean S = 1 and no product over- or underflows):

        p̄' = p̄ · mean_j(S_j π_j),   W_i' = W_i g_i / mean_j(S_j π_j),   S_j' = S_j π_j / mean_j(S_j π_j).

    Parameters
    ----------
    weight, pdf_ratio : mitsuba.Spectrum   W and S before the flight [-].
    value : mitsuba.Spectrum               g_i: the flight's transmittance per channel [-].
    pdf : mitsuba.Spectrum                 π_j: the density of the flight's outcome (distance
                                           [m⁻¹], or passing probability [-]) had channel j sampled it.

    Returns
    -------
    tuple   (W', S'); zero weight where every channel's density vanishes.

    Notes
    -----
    W_i ≤ C f_i / p_i for every channel i: each channel is weighted at most C times as
    strongly as if it had been the one sampled. Per segment (a fresh channel per free
    flight, the scheme this replaced) the bound is C per flight, C^k for a path of k flights;
    sampling on one fixed channel (Mitsuba's ``volpath``: tr / pdf₀) has no bound at all,
    and infinite variance in channels with σ_t,i < σ_t,0 / 2.
    """
    import drjit as dr  # noqa: PLC0415

    mixture = dr.mean(pdf_ratio * pdf)  # mean_j(S_j π_j): Eq. 6 of [4], the balance heuristic of [5]
    ok = mixture > 0
    inverse = dr.select(ok, 1.0 / dr.select(ok, mixture, 1.0), 0.0)
    return weight * value * inverse, dr.select(ok, pdf_ratio * pdf * inverse, pdf_ratio)


def trace_path(scene, sampler, ray, medium, active, *, is_water_surface, sun, eta: float = 1.333,
               alpha: float = 0.2, max_depth: int, rr_depth: int, last=None, water_surface=None, floor=None,
               volume=None):
    """Radiance along ``ray`` [W m⁻² sr⁻¹ nm⁻¹], in air or in the water, to the end of its path.

    A path tracer for a scene of vacuum and homogeneous media inside dielectric
    surfaces (the sea under a sky), with

    * **hero-wavelength spectral MIS** (Wilkie et al. 2014 [4]): every free flight of
      a path is sampled on one hero channel chosen uniformly per path, and every
      term the path adds (emitter hits, next-event estimation, the connections B
      and D) is weighted by the one-sample balance heuristic over all of its
      wavelengths (:func:`hero_free_flight_update`), so no single wavelength can
      carry more than C = 4 times its own unidirectional weight;
    * in the water, the strategies for sunlight seen through the surface (module
      docstring): B (the refracted-sun lobe q, if ``sun`` is given), D (the exact
      transmittance along the path's own next direction) and emitter sampling
      through the underside, combined with BSDF sampling (C) by the power heuristic;
    * in air, ``volpath``'s estimator: emitter sampling at every surface with a
      non-delta lobe, BSDF sampling, emitter hits weighted by the power heuristic.
      A path that leaves the water stays in this loop (air), and one that
      re-enters it (another wave) is traced in the water again with the same
      hero channel.

    Parameters
    ----------
    scene, sampler : mitsuba.Scene, mitsuba.Sampler
    ray : mitsuba.Ray3f                   The path's first segment [m].
    medium : mitsuba.MediumPtr            Medium the ray starts in, per lane (null: air).
    active : mitsuba.Bool                 Lanes to trace.
    is_water_surface : callable           ``BSDFPtr -> Bool``: the BSDF is the air–water surface's.
    sun : mitsuba.Vector3f, 3 floats or None   Unit vector towards the sun (z up) for strategy B;
                                          None: no B. An opaque ``Vector3f`` changes between renders
                                          without recompiling.
    eta : float                           Refractive index of water relative to air [-].
    alpha : float                         Beckmann roughness α_q of the refracted-sun lobe [-].
    max_depth, rr_depth : int             Vertices allowed; Russian roulette after ``rr_depth``.
    last : tuple, optional                ``(interaction, pdf, delta)`` of the vertex the ray left:
                                          its BSDF-sampling density [sr⁻¹] and whether that was a
                                          delta lobe, for the MIS weight of an emitter the first
                                          segment meets in air (against emitter sampling there).
                                          None: the ray comes from a delta lobe (weight 1).
    water_surface : mitsuba.BSDF, optional   The air–water surface's one BSDF, if it has ``prepared(si,
                                          active, parallax)`` (the sea shaded from its fields,
                                          :class:`~oceanrender.render.sea_shading.SeaSurfaceBSDF`):
                                          its shading frame is then evaluated once per hit and
                                          shared by the hit's emitter sampling, BSDF sampling and
                                          density, instead of once per call.
    floor : FloorCaustics, optional       The sun's beam traced onto the open sea's floor
                                          (:class:`~oceanrender.render.sun_beam.FloorCaustics`): at
                                          a floor vertex inside its map the sun comes from the map,
                                          and no strategy reaches the sun's cone from there.
    volume : VolumeBeam, optional         The same in the water's volume, at scattering vertices
                                          (:class:`~oceanrender.render.sun_beam.VolumeBeam`): the shafts.

    Returns
    -------
    mitsuba.Spectrum   Radiance per wavelength [W m⁻² sr⁻¹ nm⁻¹], zero on inactive lanes.
    """
    import drjit as dr  # noqa: PLC0415
    import mitsuba as mi  # noqa: PLC0415

    sample_lobe, pdf_lobe = sun_lobe_functions()
    beam_maps = [m for m in (floor, volume) if m is not None]  # the sun's beam traced into maps

    def in_cone(direction):
        """Directions in the air inside the sun's cone (the maps' sun)."""
        return beam_maps[0].in_cone(direction)

    sun_sampling = sun is not None
    if sun_sampling:
        # NOTE: Python floats become literals in the traced kernel; an (opaque) Vector3f is used as is.
        sun_v = sun if isinstance(sun, mi.Vector3f) else mi.Vector3f(*[float(c) for c in sun])
    ctx = mi.BSDFContext()
    n_channels = dr.size_v(mi.Spectrum)
    no_medium = mi.MediumPtr(None)
    active = mi.Bool(active)
    # The hero channel, uniform per path [4]: the one-sample MIS below is then Veach's
    # one-sample model with equal selection probabilities, whatever the sensor's joint
    # distribution of the C wavelengths.
    hero = mi.UInt32(dr.minimum(sampler.next_1d(active) * n_channels, n_channels - 1))
    if last is None:
        last_it, last_pdf, last_delta = dr.zeros(mi.Interaction3f), mi.Float(0.0), mi.Bool(True)
    else:
        last_it, last_pdf, last_delta = dr.zeros(mi.Interaction3f), mi.Float(last[1]), mi.Bool(last[2])
        last_it[active] = last[0]

    def through_surface(si, bsdf, sampler, on):
        """Emitter sampling at a surface point, through its BSDF.

        Returns (f·L_e/p_e [W m⁻² sr⁻¹ nm⁻¹ per unit throughput], p_e, p_s, valid, direction): the
        emitter-sampling and BSDF-sampling densities of the sampled direction (p_s = 0 for
        a delta emitter), for the MIS weights, and that direction.
        """
        ds, em = scene.sample_emitter_direction(si, sampler.next_2d(on), True, on)
        f_y, p_s = bsdf.eval_pdf(ctx, si, si.to_local(ds.d), on)
        return f_y * em, ds.pdf, dr.select(ds.delta, 0.0, p_s), on & (ds.pdf > 0), ds.d

    def sun_strategy(vertex, f_and_pdf, weight, sigma_t, sampler, on, no_sun=False):
        """Strategy B at an in-water vertex: d ~ q, trace to the surface, emitter sampling there (``no_sun``:
        lanes whose sun comes from the floor's map: none in the sun's cone)."""
        d, q = sample_lobe(sampler.next_2d(on), sun_v, eta, alpha)
        on &= q > 0
        f_x, p_x = f_and_pdf(d, on)
        ray_b = vertex.spawn_ray(d)
        si_b = scene.ray_intersect(ray_b, on)
        bsdf_b = si_b.bsdf(ray_b)
        on &= si_b.is_valid() & is_water_surface(bsdf_b)
        # NOTE: the connection's length is evaluated, not sampled: it adds nothing to the
        # path's wavelength densities, so the weight W of the vertex applies as it is.
        transmittance = dr.exp(-sigma_t * si_b.t)
        light, p_e, p_s, valid, d_air = through_surface(si_b, bsdf_b, sampler, on)
        if beam_maps:
            valid &= ~(no_sun & in_cone(d_air))
        w = _power_heuristic3(q * p_e, p_x * p_e, p_x * p_s)
        contribution = weight * f_x * transmittance * light * (w / dr.select(q > 0, q, 1.0))
        return dr.select(valid, contribution, 0.0)

    def cond(sampler, ray, W, S, L, depth, active, *rest):
        return active

    def body(sampler, ray, W, S, L, depth, active, medium, prev_r, prev_in_water, last_it, last_pdf, last_delta,
             last_r, prev_map, from_map):
        # ---- Russian roulette on the throughput after rr_depth vertices (as volpath).
        q_rr = dr.minimum(dr.max(W), 0.99)
        roulette = active & (depth >= rr_depth)
        active &= ~roulette | (sampler.next_1d(active) < q_rr)
        W = dr.select(roulette, W / dr.select(q_rr > 0, q_rr, 1.0), W)

        in_water = active & (medium != no_medium)
        in_air = active & (medium == no_medium)
        si = scene.ray_intersect(ray, active)
        bsdf = si.bsdf(ray)
        water_bsdf = is_water_surface(bsdf)
        bsdf_ptr = bsdf
        if water_surface is not None:  # the sea's hits through its shading frame, evaluated once here
            prepared = water_surface.prepared(si, active & water_bsdf, parallax=False, branch=True)
            bsdf = _SharedHit(bsdf, prepared, water_bsdf)
        smooth = mi.has_flag(bsdf.flags(), mi.BSDFFlags.Smooth)

        # ---- In air: the emitter the segment meets (the sky where it misses), weighted by the
        # power heuristic against emitter sampling at the vertex it left (A) and, for a path
        # that left the water, against B at the in-water vertex before that (C's weight).
        emitter = si.emitter(scene, in_air)
        hit_emitter = in_air & (emitter != mi.EmitterPtr(None))
        ds = mi.DirectionSample3f(scene, si, last_it)
        p_e = scene.pdf_emitter_direction(last_it, ds, hit_emitter & ~last_delta)
        w_c = dr.select(last_delta, 1.0, _power_heuristic3(last_pdf, p_e, last_r * p_e))
        if beam_maps:  # the direct sun of a vertex in a map (its strategy C) is the map's
            hit_emitter &= ~(from_map & in_cone(ray.d))
        L += dr.select(hit_emitter, W * emitter.eval(si, hit_emitter) * w_c, 0.0)

        # ---- In the water: free flight on the hero channel.
        # NOTE: Mitsuba 3.9.1's sample_interaction ignores its channel argument in spectral
        # variants (only RGB variants pick a channel) and always samples on the first
        # wavelength: checked, the mean distance is 1/σ_t(λ₀) for channel 0 and 3 alike. The
        # medium is homogeneous, so the distance is drawn here on the hero's σ_t instead.
        # (below 1: a stratified sampler's u can round to 1.0 in float32, and ln 0 would send the flight to ∞)
        u_flight = dr.minimum(sampler.next_1d(in_water), ONE_MINUS_EPSILON)
        mei = medium.sample_interaction(ray, u_flight, 0, in_water)
        sigma_t = mei.sigma_t
        sigma_hero = sigma_t[0]
        for c in range(1, n_channels):
            sigma_hero = dr.select(hero == c, sigma_t[c], sigma_hero)
        t_hero = mei.mint - dr.log(1.0 - u_flight) / dr.select(sigma_hero > 0, sigma_hero, 1.0)
        mei.t = dr.select(in_water & (sigma_hero > 0), t_hero, dr.inf)
        mei.p = ray(mei.t)
        scattered = in_water & mei.is_valid() & (mei.t < si.t)
        mei.t = dr.select(scattered, mei.t, dr.inf)
        # Strategy D: the direction sampled at the previous in-water vertex, followed to the
        # surface with its exact transmittance, and emitter sampling there (W before this
        # flight: the connection does not sample the distance).
        on_surface = in_water & si.is_valid() & water_bsdf
        connect = on_surface & prev_in_water & smooth
        W_d = W  # (its emitter sample is drawn with A's, below)

        tr, free_pdf = medium.transmittance_eval_pdf(mei, si, in_water)
        W_f0 = W  # the throughput before the flight (for the beam along the segment)
        W_f, S_f = hero_free_flight_update(W, S, tr, free_pdf)
        W, S = dr.select(in_water, W_f, W), dr.select(in_water, S_f, S)
        depth = dr.select(active, depth + 1, depth)

        # ---- Medium scattering: strategy B, then phase-function sampling.
        scatter = scattered & (depth < max_depth)
        phase_ctx = mi.PhaseFunctionContext(sampler)
        phase = medium.phase_function()
        W_s = W * mei.sigma_s

        def phase_f_pdf(d, on):
            value, pdf = phase.eval_pdf(phase_ctx, mei, d, on)
            return mi.Spectrum(value), pdf

        in_volume = mi.Bool(False)
        if volume is not None:
            # The sun's beam once scattered from the map, along the whole segment (W before the flight),
            # not at the flight's vertex; the vertex only learns that its sun is the map's.
            # (only where the flight's vertex could scatter: the path's depth bounds its orders as before)
            L += volume.along(ray, dr.select(si.is_valid(), si.t, dr.inf), mei, phase, phase_ctx, W_f0,
                              sigma_t, sampler, in_water & (depth < max_depth), depth == 1)
            in_volume = scatter & volume.lit(mei.p, scatter)
        if sun_sampling:
            L += sun_strategy(mei, phase_f_pdf, W_s, sigma_t, sampler, scatter, in_volume)
        wo, phase_w, phase_pdf = phase.sample(phase_ctx, mei, sampler.next_1d(scatter), sampler.next_2d(scatter),
                                              scatter)
        r_phase = pdf_lobe(wo, sun_v, eta, alpha) / dr.select(phase_pdf > 0, phase_pdf, 1.0) if sun_sampling else 0.0

        # ---- Surfaces: the water surface (from either side), opaque surfaces in the water or in air.
        surface = active & ~scattered & si.is_valid() & (depth < max_depth)
        opaque_in_water = surface & in_water & ~water_bsdf
        at_floor = mi.Bool(False)
        if floor is not None:
            # The sun's beam on the floor from the map (E₀ per W m⁻² of the sun per horizontal area, its mean
            # path s̄): f_r E₀ E_n(λ) exp(−σ_t s̄), f_r the floor's BRDF (Lambertian) times the cosine of the
            # zenith there (Mitsuba's eval), n_z: the irradiance on sloping ground is E₀ n_z.
            e0, path, inside = floor.at(si.p, opaque_in_water)
            at_floor = opaque_in_water & floor.on_floor(si) & inside
            f_r = bsdf_ptr.eval(ctx, si, si.to_local(mi.Vector3f(0.0, 0.0, 1.0)), at_floor)
            beam = e0 * floor.sun_irradiance(si.wavelengths, at_floor) * dr.exp(-sigma_t * path)
            L += dr.select(at_floor, W * f_r * beam, 0.0)

        def bsdf_f_pdf(d, on):  # (``on``: opaque surfaces only)
            return bsdf_ptr.eval_pdf(ctx, si, si.to_local(d), on)

        if sun_sampling:
            L += sun_strategy(si, bsdf_f_pdf, W, sigma_t, sampler, opaque_in_water, at_floor)

        # Emitter sampling at surfaces with a non-delta lobe: in air (as volpath), and through
        # the underside of the water surface for paths that did not come from an in-water vertex
        # (from one, D did it). prev_r = 0 unless the previous vertex was in the water.
        # (D's connection and this are disjoint — D needs an in-water vertex before, this not —
        # and share one emitter sample: the same weight, D's with the flight's transmittance.)
        nee = surface & smooth & (in_air | (water_bsdf & ~prev_in_water))
        light, p_e, p_s, valid, d_air = through_surface(si, bsdf, sampler, connect | nee)
        if beam_maps:  # D from a vertex in a map: its sun is the map's
            valid &= ~(connect & prev_map & in_cone(d_air))
        w_ad = _power_heuristic3(p_e, prev_r * p_e, p_s)
        light = dr.select(connect, W_d * dr.exp(-sigma_t * si.t) * light, W * light)
        L += dr.select(valid, light * w_ad, 0.0)

        # BSDF sampling at surfaces.
        bs, bsdf_w = bsdf.sample(ctx, si, sampler.next_1d(surface), sampler.next_2d(surface), surface)
        sample_surface = surface & (bs.pdf > 0) & dr.any(bsdf_w != 0.0)
        wo_s = si.to_world(bs.wo)
        delta = mi.has_flag(bs.sampled_type, mi.BSDFFlags.Delta)
        # NOTE: the density of the whole BSDF (a ``blendbsdf``'s mixture), not bs.pdf, which
        # is the chosen component's: the MIS weights of emitter hits and of A/D must add up to one.
        pdf_s = dr.select(delta, bs.pdf, bsdf.pdf(ctx, si, bs.wo, sample_surface & ~delta))
        r_surface = pdf_lobe(wo_s, sun_v, eta, alpha) / dr.select(pdf_s > 0, pdf_s, 1.0) if sun_sampling else 0.0
        transmits = sample_surface & mi.has_flag(bs.sampled_type, mi.BSDFFlags.Transmission)

        # What an emitter hit on the next segment (in air) needs for its MIS weight.
        last_it[sample_surface] = si
        last_pdf = dr.select(sample_surface, pdf_s, last_pdf)
        last_delta = dr.select(sample_surface, delta, last_delta)
        last_r = dr.select(sample_surface, prev_r, last_r)

        # ---- Next segment.
        ray[scatter] = mei.spawn_ray(wo)
        ray[sample_surface] = si.spawn_ray(wo_s)
        medium = dr.select(transmits, si.target_medium(wo_s), medium)
        W = dr.select(scatter, W_s * phase_w, dr.select(sample_surface, W * bsdf_w, W))
        prev_r = dr.select(scatter, r_phase,
                           dr.select(sample_surface, dr.select(opaque_in_water & ~delta, r_surface, 0.0), prev_r))
        # a path that leaves the water through the surface straight from a vertex in a map (C: its sun is the map's)
        from_map = sample_surface & water_bsdf & prev_map & transmits
        prev_map = (scatter & in_volume) | (sample_surface & at_floor)
        prev_in_water = scatter | (sample_surface & opaque_in_water)
        active = (scatter & (phase_pdf > 0)) | sample_surface
        active &= dr.any(W != 0.0)
        return (sampler, ray, W, S, L, depth, active, medium, prev_r, prev_in_water, last_it, last_pdf, last_delta,
                last_r, prev_map, from_map)

    state = (sampler, mi.Ray3f(ray), mi.Spectrum(1.0), mi.Spectrum(1.0), mi.Spectrum(0.0), mi.UInt32(0), active,
             mi.MediumPtr(medium), mi.Float(0.0), mi.Bool(False), last_it, last_pdf, last_delta, mi.Float(0.0),
             mi.Bool(False), mi.Bool(False))
    state = dr.while_loop(state, cond, body, label="oceanrender_hero_path")
    return dr.select(active, state[4], 0.0)
