"""A Mitsuba integrator that takes both Fresnel lobes at the camera's first water hit.

Mitsuba's ``volpath`` picks, at a dielectric interface, reflection with
probability F (the Fresnel reflectance, 2–8 % at the view angles of a sea
seen from a few metres) and transmission otherwise. The reflected sky, which
dominates what a viewer sees, is then estimated from a few percent of the
samples. :class:`SplitSurfaceIntegrator` rewrites that estimator exactly:
where a camera ray first meets a ``dielectric`` or ``roughdielectric`` surface
(or a ``blendbsdf`` of one, e.g. water with foam) it follows *both* lobes
every sample,

    L = L_e + L_nee + w_r L_r + w_t L_t,

with (w_r, ω_r) sampled from the reflection lobe alone and (w_t, ω_t) from
the transmission lobe alone (Mitsuba returns w_r = F, w_t = (1 − F) η_ti²
for a smooth interface, with pdf 1: ``src/bsdfs/dielectric.cpp``), and each
continued with a ``volpath`` one bounce shorter. The expectation is
F L_r + (1 − F) L_t, the same as ``volpath``'s lobe-selected estimate, so the
image converges to the same value with less noise per sample.

In JIT variants both lobes are continued by
:func:`oceanrender.render.underwater.trace_path` (hero-wavelength spectral MIS in
the water, Wilkie et al. 2014; in-water sun sampling when a sun is given), also
where a reflected ray re-enters the water; scalar variants continue them with
``volpath``.

Call :func:`register` once a variant is active, then use
:func:`split_integrator` as the scene's ``"integrator"`` entry.

References
----------
.. [1] E. Veach and L. J. Guibas, "Optimally combining sampling techniques for
   Monte Carlo rendering," in Proc. SIGGRAPH '95, pp. 419–428, 1995,
   doi:10.1145/218380.218498 (the power heuristic, multi-sample MIS).
.. [2] B. Walter, S. R. Marschner, H. Li and K. E. Torrance, "Microfacet models
   for refraction through rough surfaces," in Proc. EGSR 2007, pp. 195–206,
   doi:10.2312/EGWR/EGSR07/195-206 (``roughdielectric``; its η² radiance scaling).
.. [3] Mitsuba 3.9.1 sources: ``src/integrators/volpath.cpp``,
   ``src/bsdfs/dielectric.cpp``, ``roughdielectric.cpp``, ``blendbsdf.cpp``.
"""

from __future__ import annotations

#: Name of the plugin in Mitsuba's registry.
SPLIT_INTEGRATOR = "oceanrender_split"

#: Mitsuba class names of the BSDFs whose lobes are split: ``dielectric``, ``roughdielectric``
#: and ``blendbsdf`` (e.g. water blended with foam), when they have a transmission lobe.
SPLIT_BSDF_CLASSES = ("SmoothDielectric", "RoughDielectric", "BlendBSDF")

#: Variants in which the plugin is registered (registration is per variant).
_REGISTERED: set[str] = set()

#: The integrator class per variant (it subclasses that variant's ``mi.SamplingIntegrator``).
_CLASSES: dict[str, type] = {}


#: What a split sample returns: both lobes (the default), or one lobe alone (a pass of a two-pass frame).
LOBES = ("both", "reflection", "transmission")


def split_integrator(max_depth: int, rr_depth: int = 5, sun=None, water_ior: float = 1.333,
                     sun_lobe_alpha: float = 0.2, in_water_clamp: float = 0.0, lobes: str = "both") -> dict:
    """Scene-dict entry of the split-surface integrator.

    Parameters
    ----------
    max_depth : int          Longest path, as in ``volpath`` (−1: unbounded) [-].
    rr_depth : int           Depth after which Russian roulette starts, as in ``volpath`` [-].
    sun : sequence, optional Unit vector towards the sun (z up). Given, the paths in the water
                             sample the sunlight refracted into it explicitly
                             (:func:`oceanrender.render.underwater.trace_path`).
    water_ior : float        Refractive index of the water relative to air [-].
    sun_lobe_alpha : float   Beckmann roughness of the refracted-sun lobe: the total rms slope
                             of the sea surface [-].
    in_water_clamp : float   Largest radiance one sample of the transmitted lobe may bring back,
                             per wavelength [W m⁻² sr⁻¹ nm⁻¹]; 0: no clamp (unbiased).
    lobes : str              ``"both"``: every sample follows both lobes of the split vertex.
                             ``"reflection"``: every sample *except* the transmitted lobe (camera rays
                             that are not split included); ``"transmission"``: the transmitted lobe
                             alone (0 elsewhere). The two passes add up to ``"both"`` in expectation,
                             so each can be given its own sample count
                             (:meth:`oceanrender.render.renderer.WaterRenderer.render_xyz`).

    Call :func:`register` (after the variant is set) before loading the scene.
    """
    if max_depth < -1:
        raise ValueError(f"max_depth must be -1 (unbounded) or ≥ 0, got {max_depth}")
    if rr_depth < 1:
        raise ValueError(f"rr_depth must be ≥ 1, got {rr_depth}")
    entry = {"type": SPLIT_INTEGRATOR, "max_depth": int(max_depth), "rr_depth": int(rr_depth)}
    if sun is not None:
        if not (water_ior > 1.0 and 0.0 < sun_lobe_alpha <= 1.0):
            raise ValueError(f"need water_ior > 1 and 0 < sun_lobe_alpha ≤ 1, got {water_ior}, {sun_lobe_alpha}")
        entry.update({"sun_x": float(sun[0]), "sun_y": float(sun[1]), "sun_z": float(sun[2]),
                      "water_ior": float(water_ior), "sun_lobe_alpha": float(sun_lobe_alpha)})
    if in_water_clamp < 0:
        raise ValueError(f"in_water_clamp must be ≥ 0 [W m⁻² sr⁻¹ nm⁻¹], got {in_water_clamp}")
    if in_water_clamp > 0:
        entry["in_water_clamp"] = float(in_water_clamp)
    if lobes not in LOBES:
        raise ValueError(f"lobes must be one of {LOBES}, got {lobes!r}")
    if lobes != "both":
        entry["lobes"] = lobes
    return entry


def register() -> None:
    """Register ``oceanrender_split`` with Mitsuba for the active variant.

    Idempotent. Mitsuba keeps Python plugins per variant, so call it again
    after switching variants.
    """
    from .plugins import register_once  # noqa: PLC0415

    register_once(_REGISTERED, "integrator", SPLIT_INTEGRATOR, split_surface_integrator_class)


def split_surface_integrator_class() -> type:
    """The :class:`SplitSurfaceIntegrator` class of the active variant."""
    import mitsuba as mi  # noqa: PLC0415

    variant = mi.variant()
    if variant not in _CLASSES:
        if "polarized" in variant:
            raise NotImplementedError("the split-surface integrator does not handle polarized variants")
        _CLASSES[variant] = _define_class()
    return _CLASSES[variant]


def _define_class() -> type:
    import math  # noqa: PLC0415

    import drjit as dr  # noqa: PLC0415
    import mitsuba as mi  # noqa: PLC0415

    jit = dr.is_jit_v(mi.Float)

    def logical_not(mask):
        # NOTE: in scalar variants masks are Python bools, for which ~True == -2.
        return ~mask if jit else not mask

    def same_object(ptr, obj, ptr_type):
        """Per-lane ``ptr == obj`` for a Mitsuba pointer array (or a scalar pointer)."""
        if jit:
            return ptr == ptr_type(obj)
        return ptr is obj

    def power_heuristic(pdf_a, pdf_b):
        """Veach's power heuristic (β = 2), as ``volpath`` uses it."""
        a2, b2 = dr.square(pdf_a), dr.square(pdf_b)
        denominator = a2 + b2
        # NOTE: scalar variants compute with Python floats, which raise on 0 / 0.
        w = a2 / dr.select(denominator > 0, denominator, 1.0)
        return dr.select(dr.isfinite(w), w, 0.0)

    def eval_emitter(emitter, si, active):
        if not jit and emitter is None:
            return mi.Spectrum(0.0)
        return emitter.eval(si, active)

    class SplitSurfaceIntegrator(mi.SamplingIntegrator):
        """``volpath`` with both lobes of the camera's first water hit sampled every time.

        Properties: ``max_depth`` (default −1), ``rr_depth`` (default 5),
        ``hide_emitters`` (default false), as in ``volpath``; ``lobes``
        (``"both"``, ``"reflection"`` or ``"transmission"``, see :func:`split_integrator`).

        Notes
        -----
        Path depths match ``volpath``: the continuations have ``max_depth − 1``
        and ``rr_depth − 1`` (JIT variants: :func:`~oceanrender.render.underwater.trace_path`;
        scalar variants: ``volpath`` instances). At the split
        vertex, next-event estimation uses the reflection lobe only and is
        combined by the power heuristic with sampling of that lobe (densities of
        the whole reflection strategy, which for a ``blendbsdf`` is the mixture
        of its components); the
        emission the reflected ray reaches first is weighted against it (in
        ``trace_path``; in scalar variants here, the ``volpath`` continuation then
        runs with ``hide_emitters``). Emitters
        are unreachable straight through the transmission lobe by NEE (a
        dielectric blocks shadow rays in ``volpath`` too), so the transmitted
        continuation counts what it meets first with full weight.

        The split is only used where this bookkeeping is exact: the camera
        is in vacuum, the split shapes have no exterior medium and a homogeneous
        interior medium (or none), and no shape has a ``null`` BSDF. Otherwise, and on camera rays that miss or hit
        other surfaces, the whole sample is ``volpath``'s.
        """

        def __init__(self, props):
            super().__init__(props)
            self.max_depth = int(props.get("max_depth", -1))
            self.rr_depth = int(props.get("rr_depth", 5))
            if self.max_depth < -1:
                raise ValueError(f"max_depth must be -1 (unbounded) or ≥ 0, got {self.max_depth}")
            if self.rr_depth < 1:
                raise ValueError(f"rr_depth must be ≥ 1, got {self.rr_depth}")
            self.lobes = str(props.get("lobes", "both"))
            if self.lobes not in LOBES:
                raise ValueError(f"lobes must be one of {LOBES}, got {self.lobes!r}")
            if self.lobes != "both" and not jit:
                raise NotImplementedError("single-lobe passes are implemented for JIT variants only")
            # A split needs a bounce after the first vertex: max_depth ≥ 2 (or unbounded).
            self.splits = self.max_depth < 0 or self.max_depth >= 2
            # NOTE: the sun and the clamp are opaque Dr.Jit values (kernel parameters), not Python
            # floats, which a traced kernel would bake in as literals: a sun that moves between
            # frames (set_sun) would then recompile the render kernel every frame.
            self.sun = None
            #: the sun's beam on the open sea's floor (:class:`~.sun_beam.FloorCaustics`), set before the first render
            self.floor_caustics = None
            #: the sun's beam in the water's volume (:class:`~.sun_beam.VolumeBeam`), set before the first render
            self.volume_beam = None
            clamp = float(props.get("in_water_clamp", 0.0))
            self.clamps = clamp > 0  # whether to clamp at all is part of the kernel's structure
            self.in_water_clamp = None
            if self.clamps:
                self.set_in_water_clamp(clamp)
            if "sun_z" in props:
                self.set_sun((float(props["sun_x"]), float(props["sun_y"]), float(props["sun_z"])))
                self.water_ior = float(props.get("water_ior", 1.333))
                self.sun_lobe_alpha = float(props.get("sun_lobe_alpha", 0.2))
            hide = bool(self.hide_emitters)  # NOTE: a bool attribute in Python, not a method
            self.full = self._volpath(self.max_depth, self.rr_depth, hide)
            self.reflected = self.transmitted = None
            if self.splits:
                inner_depth = -1 if self.max_depth < 0 else self.max_depth - 1
                # NOTE: volpath refuses rr_depth < 1; rr_depth only changes the variance.
                inner_rr = max(self.rr_depth - 1, 1)
                self.reflected = self._volpath(inner_depth, inner_rr, hide_emitters=True)
                self.transmitted = self._volpath(inner_depth, inner_rr, hide_emitters=False)

        def set_sun(self, direction) -> None:
            """Point the in-water sun sampling at ``direction`` (unit vector towards the sun, z up), no recompile.

            Only for an integrator built with a sun (``sun_x/y/z``): turning sun sampling on
            or off changes the kernel.
            """
            d = [float(c) for c in direction]
            if len(d) != 3 or not abs(math.hypot(*d) - 1.0) < 1e-4:
                raise ValueError(f"the sun direction must be a unit 3-vector, got {direction!r}")
            if self.sun is None and hasattr(self, "full"):
                raise ValueError("this integrator was built without in-water sun sampling; cannot set a sun")
            sun = mi.Vector3f(*d)
            dr.make_opaque(sun)
            self.sun = sun

        def set_in_water_clamp(self, value: float) -> None:
            """Set the in-water firefly clamp [W m⁻² sr⁻¹ nm⁻¹] (> 0; built with a clamp), no recompile."""
            if not (math.isfinite(value) and value > 0):
                raise ValueError(f"in_water_clamp must be finite and > 0 [W m⁻² sr⁻¹ nm⁻¹], got {value!r}")
            if not self.clamps:
                raise ValueError("this integrator was built without an in-water clamp (0 = off); cannot set one")
            clamp = mi.Float(float(value))
            dr.make_opaque(clamp)
            self.in_water_clamp = clamp

        @staticmethod
        def _volpath(max_depth, rr_depth, hide_emitters):
            # NOTE: not mi.load_dict: a nested scene parser inside this constructor (which
            # Mitsuba 3.9.1's parallel loader runs on a worker thread) intermittently broke
            # the concurrent loading of ``sunsky`` ("basic_string::_M_create",
            # std::bad_alloc). Nor lazily in sample(): creating a plugin there evaluates the
            # half-traced camera rays and splits the render kernel in two.
            props = mi.Properties("volpath")
            props["max_depth"] = int(max_depth)
            props["rr_depth"] = int(rr_depth)
            props["hide_emitters"] = bool(hide_emitters)
            return mi.PluginManager.instance().create_object(props)

        def _continue(self, scene, sampler, ray, medium, active, bsdfs, last=None):
            """Radiance of a ray leaving the split vertex into ``medium`` (null: air), to its path's end.

            Traced by :func:`oceanrender.render.underwater.trace_path` (hero-wavelength spectral
            MIS in the water, in-water sun sampling when the integrator has a sun), not by volpath.
            """
            depth = 1 << 20 if self.max_depth < 0 else self.max_depth - 1
            return self._trace(scene, sampler, ray, medium, active, bsdfs, depth, max(self.rr_depth - 1, 1), last)

        def _trace(self, scene, sampler, ray, medium, active, bsdfs, depth, rr_depth, last=None):
            """:func:`~oceanrender.render.underwater.trace_path` of ``ray`` from ``medium`` with this
            integrator's sun sampling; the split BSDFs ``bsdfs`` are the air-water surface."""
            from .underwater import trace_path  # noqa: PLC0415

            def is_water_surface(ptr):
                on = mi.Bool(False)
                for b in bsdfs:
                    on |= same_object(ptr, b, mi.BSDFPtr)
                return on

            sun = {} if self.sun is None else {"eta": self.water_ior, "alpha": self.sun_lobe_alpha}
            # the sea shaded from its fields (:mod:`.sea_shading`): one shading frame per hit
            surface = bsdfs[0] if len(bsdfs) == 1 and hasattr(bsdfs[0], "prepared") else None
            return trace_path(scene, sampler, mi.Ray3f(ray), medium, active, is_water_surface=is_water_surface,
                              sun=self.sun, max_depth=depth, rr_depth=rr_depth, last=last, water_surface=surface,
                              floor=self.floor_caustics, volume=self.volume_beam, **sun)

        def _from_camera_in_water(self, scene, sampler, ray, medium, active):
            """A camera inside the water body (its sensor's ``medium``): the whole path by ``trace_path``.

            No vertex is split (the camera ray starts in the water), so the ``"reflection"`` (or
            ``"both"``) pass takes the whole sample and the ``"transmission"`` pass none, as for
            rays that meet no water. In JIT variants the path is traced like the light behind a
            split vertex (hero-wavelength MIS, in-water sun sampling: the light shafts); scalar
            variants, and scenes whose water is not one homogeneous medium inside a dielectric,
            use ``volpath``.
            """
            if self.lobes == "transmission":
                return mi.Spectrum(0.0), mi.Bool(active), []
            setup = self.split_setup(scene, None) if self.splits else None
            if not jit or setup is None or not any(medium is m for m in setup[1]):
                return self.full.sample(scene, sampler, ray, medium, active)
            depth = 1 << 20 if self.max_depth < 0 else self.max_depth
            L = self._trace(scene, sampler, ray, mi.MediumPtr(medium), mi.Bool(active), setup[0], depth, self.rr_depth)
            return L, mi.Bool(active), []

        def _reflected_scalar(self, scene, sampler, si, bsdf, ctx_r, bs_r, ray_r):
            """Scalar variants: the reflected ray's first emitter hit (MIS against the NEE) + volpath after it."""
            si_r = scene.ray_intersect(ray_r)
            delta_r = mi.has_flag(bs_r.sampled_type, mi.BSDFFlags.Delta)
            ds_r = mi.DirectionSample3f(scene, si_r, si)
            # NOTE: scalar variants ignore masks and would dereference a null emitter.
            pdf_em = scene.pdf_emitter_direction(si, ds_r) if not delta_r and ds_r.emitter is not None else 0.0
            pdf_r_strategy = 0.0 if delta_r else bsdf.pdf(ctx_r, si, bs_r.wo)
            w_r_hit = 1.0 if delta_r else power_heuristic(pdf_r_strategy, pdf_em)
            L_r = eval_emitter(si_r.emitter(scene), si_r, True) * w_r_hit
            if si_r.is_valid():
                L_r += self.reflected.sample(scene, sampler, mi.RayDifferential3f(ray_r), None, True)[0]
            return L_r

        def _transmitted(self, scene, sampler, si, bsdf, split, bsdfs):
            """w_t L_t: the transmitted lobe of the split vertex ``si``, continued in the medium behind it."""
            ctx_t = mi.BSDFContext(mi.TransportMode.Radiance, mi.BSDFFlags.Transmission)
            bs_t, weight_t = bsdf.sample(ctx_t, si, sampler.next_1d(split), sampler.next_2d(split), split)
            act_t = split & (bs_t.pdf > 0) & dr.any(weight_t != 0.0)
            ray_t = mi.RayDifferential3f(si.spawn_ray(si.to_world(bs_t.wo)))
            target = si.target_medium(ray_t.d)
            if jit:
                L_t = self._continue(scene, sampler, ray_t, target, act_t, bsdfs)
            else:
                L_t = self.transmitted.sample(scene, sampler, ray_t, target, act_t)[0] if act_t else mi.Spectrum(0.0)
            if self.clamps:
                # NOTE: a stated, biased firefly clamp (scene setting render.in_water_clamp).
                L_t = dr.minimum(L_t, self.in_water_clamp)
            return dr.select(act_t, weight_t * L_t, 0.0)

        def to_string(self):
            return (f"SplitSurfaceIntegrator[max_depth={self.max_depth}, rr_depth={self.rr_depth}, "
                    f"lobes={self.lobes}]")

        @staticmethod
        def split_setup(scene, medium):
            """(split BSDFs, media behind them) of ``scene``, or None where splitting is not exact."""
            if medium is not None or not scene.shapes():
                return None
            bsdfs, media = [], [None]
            for shape in scene.shapes():
                bsdf = shape.bsdf()
                if bsdf is None:
                    continue
                if mi.has_flag(bsdf.flags(), mi.BSDFFlags.Null):
                    return None
                # (the sea's field-shaded surface, :mod:`.sea_shading`, wraps one of those BSDFs)
                split_class = bsdf.class_name() in SPLIT_BSDF_CLASSES or getattr(bsdf, "wraps_dielectric", False)
                if not split_class or not (
                        mi.has_flag(bsdf.flags(), mi.BSDFFlags.Reflection)
                        and mi.has_flag(bsdf.flags(), mi.BSDFFlags.Transmission)):
                    continue
                if shape.exterior_medium() is not None:
                    return None
                if not any(bsdf is b for b in bsdfs):
                    bsdfs.append(bsdf)
                interior = shape.interior_medium()
                if interior is not None and not interior.is_homogeneous():
                    return None  # trace_path samples free flights and connections in closed form
                if not any(interior is m for m in media):
                    media.append(interior)
            return (bsdfs, media) if bsdfs else None

        def sample(self, scene, sampler, ray, medium=None, active=True):
            full = self.full
            if medium is not None:  # a camera in the water (the sensor's medium): no split vertex
                return self._from_camera_in_water(scene, sampler, ray, medium, active)
            setup = self.split_setup(scene, medium) if self.splits else None
            if setup is None:
                if self.lobes == "transmission":  # nothing is split: the whole sample is the other pass's
                    return mi.Spectrum(0.0), mi.Bool(active), []
                return full.sample(scene, sampler, ray, medium, active)
            bsdfs, _ = setup

            # ---- The camera ray's first hit: split only on the dielectric BSDFs.
            si = scene.ray_intersect(mi.Ray3f(ray), active)
            split = active & si.is_valid()
            # NOTE: in scalar variants si.bsdf() of a ray that missed dereferences a null shape.
            bsdf = si.bsdf(ray) if jit or split else None
            if jit:
                on_split_bsdf = mi.Bool(False)
                for b in bsdfs:
                    on_split_bsdf |= same_object(bsdf, b, mi.BSDFPtr)
                split &= on_split_bsdf
            else:
                split = bool(split) and any(bsdf is b for b in bsdfs)

            if jit and len(bsdfs) == 1 and hasattr(bsdfs[0], "prepared"):
                # The sea shaded from its fields (:mod:`.sea_shading`): every split lane is on it, so its
                # methods are called directly, with the hit's shading frame evaluated once, not per call.
                bsdf = bsdfs[0].prepared(si, split)

            if self.lobes == "transmission":
                L_t = self._transmitted(scene, sampler, si, bsdf, split, bsdfs)
                return dr.select(split, L_t, 0.0), mi.Bool(active), []

            # NOTE: volpath first, before any random number is drawn here, so a
            # camera ray that is not split gets exactly volpath's sample.
            full_L, full_valid, _ = full.sample(scene, sampler, ray, medium, active & logical_not(split))
            if not jit and not split:
                return full_L, full_valid, []

            # ---- Emission of the split surface itself (depth 0: counted in full).
            result = mi.Spectrum(0.0)
            if not self.hide_emitters:
                result += eval_emitter(si.emitter(scene, split), si, split)

            # ---- Reflection lobe: next-event estimation (glossy only) + lobe sampling.
            ctx_r = mi.BSDFContext(mi.TransportMode.Radiance, mi.BSDFFlags.Reflection)
            nee = split & mi.has_flag(bsdf.flags(), mi.BSDFFlags.Smooth)
            ds, em_weight = scene.sample_emitter_direction(si, sampler.next_2d(nee), True, nee)
            f_r, pdf_r = bsdf.eval_pdf(ctx_r, si, si.to_local(ds.d), nee)
            w_nee = power_heuristic(ds.pdf, dr.select(ds.delta, 0.0, pdf_r))
            result += dr.select(nee & (ds.pdf > 0), f_r * em_weight * w_nee, 0.0)

            bs_r, weight_r = bsdf.sample(ctx_r, si, sampler.next_1d(split), sampler.next_2d(split), split)
            act_r = split & (bs_r.pdf > 0) & dr.any(weight_r != 0.0)
            ray_r = si.spawn_ray(si.to_world(bs_r.wo))
            if jit:
                # The reflected path (its first emitter hit, the sky mostly, MIS-weighted against
                # the NEE above) is traced in this package, so that the water it may re-enter
                # (another wave) is sampled with hero-wavelength MIS, not on volpath's first
                # wavelength alone.
                delta_r = mi.has_flag(bs_r.sampled_type, mi.BSDFFlags.Delta)
                # NOTE: the density of the whole reflection strategy, not bs_r.pdf: for a
                # ``blendbsdf`` that is the chosen component's alone, and the two MIS weights
                # would then not add up to one (volpath has that bias on blends).
                pdf_r_strategy = dr.select(delta_r, bs_r.pdf, bsdf.pdf(ctx_r, si, bs_r.wo, act_r & ~delta_r))
                L_r = self._continue(scene, sampler, ray_r, mi.MediumPtr(None), act_r, bsdfs,
                                     last=(si, pdf_r_strategy, delta_r))
            else:
                L_r = self._reflected_scalar(scene, sampler, si, bsdf, ctx_r, bs_r, ray_r) if act_r else 0.0
            result += dr.select(act_r, weight_r * L_r, 0.0)

            # ---- Transmission lobe: continue in the medium behind the surface.
            if self.lobes == "both":
                result += self._transmitted(scene, sampler, si, bsdf, split, bsdfs)

            return dr.select(split, result, full_L), split | full_valid, []

    return SplitSurfaceIntegrator
