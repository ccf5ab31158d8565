"""Monte Carlo light field of a homogeneous, optically deep water slab lit by a collimated beam.

The reference the four-flux model (:mod:`oceanrender.optics.fourflux`) is checked
against (issue 19, item 3): Mitsuba's ``volpath`` solves the full radiative transfer
of a slab with absorption a, scattering b [m⁻¹] and a tabulated phase function p(μ)
[sr⁻¹] (:data:`oceanrender.render.phase.TABULATED_PLUGIN`, sampled exactly), lit from
above by a collimated beam travelling at θ_w from the vertical *inside the water* (the
refracted sun) with irradiance 1 on a plane normal to it, so that the direct plane
irradiance just below the surface is E_s(0) = cos θ_w.

Estimator: the reciprocity theorem of plane-parallel transport (Chandrasekhar 1950,
§ 53; Case 1957). The downward plane irradiance E_d(z) that a beam of normal
irradiance F from direction ω_s makes at depth z equals

    E_d(z) = F cos θ_w · L_top(−ω_s) / L_e                                          (1)

where L_top(−ω_s) is the radiance leaving the top of the same slab towards the beam's
source when, instead of the beam, a transparent plane at depth z emits the uniform
radiance L_e *upwards* (into the hemisphere the downward flux came from); the medium
is unchanged, below the plane too. Likewise E_u(0⁻) with a plane just below the
surface emitting downwards. Each E(z) is then one ``radiancemeter`` render whose paths
follow the beam into the water: phase-function sampling carries them along the
forward peak onto the emitting plane, so the estimate is smooth even for the sharp
Fournier–Forand peaks, where a meter in the water (cosine-sampled rays that must find a
narrow cone around the beam) had errors of 30–90 % at 4000 paths.

Set-up, and why:

* The upper boundary is index-matched (``null`` interface): light leaving the water is
  not reflected back. The Fresnel transmission of the sun and the internal reflection
  at a level surface are separate, exactly known factors; the comparison isolates the
  in-water transport, which is what the four-flux closure approximates. Compare with
  :func:`~oceanrender.optics.fourflux.four_flux` at ``n_water = 1``.
* The slab is 10 km wide and deep enough that e^{−a H} < 10⁻⁶ (H ≥ 14/a); the emitting
  planes have a radius of 30/a (no path to beyond it is more likely than e^{−30}).
* One 20 nm band at 540–560 nm with spectrally flat IOPs: a single monochromatic
  light field (the band only sets Mitsuba's spectral sampling).

Units: coefficients m⁻¹, depths m (positive downward), irradiances per unit normal
irradiance of the beam [-].

References
----------
.. [1] Chandrasekhar, S. (1950). *Radiative Transfer*. Oxford, Clarendon Press (§ 53,
   the principle of reciprocity for plane-parallel atmospheres).
.. [2] Case, K. M. (1957). Transfer problems and the reciprocity principle.
   *Rev. Mod. Phys.* 29(4), 651–663. doi:10.1103/RevModPhys.29.651
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

__all__ = ["SlabKd", "SlabLight", "first_optical_depth_K", "slab_kd", "slab_light_field"]

_BAND_NM = (540.0, 560.0)
_HALF_WIDTH_M = 5000.0


@dataclass(frozen=True)
class SlabLight:
    """Monte Carlo light field of :func:`slab_light_field`.

    Attributes
    ----------
    z : ndarray (Z,)          Depths of E_d [m].
    E_d : ndarray (Z,)        Downward plane irradiance (direct + scattered) [-].
    E_d_error : ndarray (Z,)  One standard error of E_d (spread of independent passes) [-].
    E_u0 : float              Upward plane irradiance just below the surface [-].
    E_u0_error : float        Its standard error [-].
    E_d0 : float              E_d(0⁻) = cos θ_w (nothing is scattered above z = 0) [-].
    """

    z: np.ndarray
    E_d: np.ndarray
    E_d_error: np.ndarray
    E_u0: float
    E_u0_error: float
    E_d0: float

    @property
    def R(self) -> float:
        """Irradiance reflectance R(0⁻) = E_u(0⁻)/E_d(0⁻) [-]."""
        return self.E_u0 / self.E_d0


def slab_scene(a: float, b: float, phase: tuple[np.ndarray, np.ndarray], zenith_deg: float,
               plane_depth: float, emits_up: bool, spp: int, water: bool = True,
               n_water: float | None = None) -> dict:
    """Mitsuba scene of the reciprocal problem (1): the slab, a plane emitting L_e = 1 at
    ``plane_depth`` [m] upwards (or downwards), and a radiance meter looking down along the beam;
    without the slab for ``water=False``. With ``n_water`` the slab's faces are a smooth dielectric
    (water of that index under vacuum, Mitsuba's ``dielectric``) and ``zenith_deg`` is the beam's
    angle in the air (Eq. 2)."""
    import mitsuba as mi  # noqa: PLC0415

    from .phase import TABULATED_PLUGIN, register_tabulated  # noqa: PLC0415

    register_tabulated()
    mu, p = phase
    c = a + b
    thickness = max(14.0 / a, 2.0 * plane_depth + 1.0)
    theta = math.radians(zenith_deg)
    down = [math.sin(theta), 0.0, -math.cos(theta)]  # the beam's direction of travel
    T = mi.ScalarTransform4f
    plane = T().translate([0.0, 0.0, -plane_depth]).scale([30.0 / a, 30.0 / a, 1.0])
    if not emits_up:
        plane = plane @ T().rotate([1.0, 0.0, 0.0], 180.0)
    band = {"type": "specfilm", "width": 1, "height": 1, "component_format": "float32", "rfilter": {"type": "box"},
            "band": {"type": "spectrum", "value": [(_BAND_NM[0], 1.0), (_BAND_NM[1], 1.0)]}}
    scene = {
        "type": "scene",
        "integrator": {"type": "volpath", "max_depth": -1, "rr_depth": 500},
        "slab": {"type": "cube",
                 "bsdf": {"type": "null"} if n_water is None else {"type": "dielectric", "int_ior": float(n_water),
                                                                   "ext_ior": 1.0},
                 "interior": {"type": "homogeneous", "sigma_t": c, "albedo": b / c,
                              "phase": {"type": TABULATED_PLUGIN, "wavelengths": "550,5,1",
                                        "mu": ",".join(f"{x:.17g}" for x in mu),
                                        "values": ",".join(f"{x:.9g}" for x in np.ravel(p))}},
                 "to_world": T().translate([0.0, 0.0, -thickness / 2]).scale([_HALF_WIDTH_M, _HALF_WIDTH_M, thickness / 2])},
        "plane": {"type": "disk", "to_world": plane, "bsdf": {"type": "null"},
                  "emitter": {"type": "area", "radiance": 1.0}},
        # NOTE: the meter's ray enters at (0.3, 0.1, 0), off the diagonal edge of the cube's top triangles
        # (a ray through the shared edge at the origin can miss both in float32 and skip the medium).
        "meter": {"type": "radiancemeter", "origin": [0.3 - down[0], 0.1, -down[2]], "direction": down, "film": band,
                  "sampler": {"type": "independent", "sample_count": spp}},
    }
    if not water:  # the plane seen through vacuum: what L_e = 1 reads on this film
        del scene["slab"]
    return scene


def slab_light_field(a: float, b: float, phase: tuple[np.ndarray, np.ndarray], zenith_deg: float,
                     depths, spp: int = 65536, passes: int = 4, seed: int = 0, spp_up: int | None = None) -> SlabLight:
    """Monte Carlo E_d(z) and E_u(0⁻) of a deep slab under a collimated beam, Eq. (1).

    Parameters
    ----------
    a, b : float             Absorption and scattering coefficients, a > 0, b ≥ 0 [m⁻¹].
    phase : (mu, p)          Phase function table: cosines from −1 to 1 [-], p (M,) or (1, M) [sr⁻¹].
    zenith_deg : float       Beam angle from the vertical in the water, 0–85 [deg].
    depths : array_like (Z,) Depths of E_d, > 0 [m].
    spp : int                Paths per depth and pass.
    passes : int             Independent passes (seeds) whose spread gives the standard error, ≥ 2.
    seed : int               First seed.
    spp_up : int, optional   Paths per pass for E_u(0⁻) (backscattering is rarer); default ``spp``.

    Needs an active Mitsuba variant (the project's spectral LLVM variant).
    """
    import mitsuba as mi  # noqa: PLC0415

    depths = np.asarray(depths, dtype=float)
    if not (a > 0 and b >= 0 and 0 <= zenith_deg <= 85 and np.all(depths > 0) and passes >= 2):
        raise ValueError("slab_light_field: need a > 0, b >= 0, 0 <= zenith <= 85 deg, depths > 0, passes >= 2")
    mu_w = math.cos(math.radians(zenith_deg))
    width = _BAND_NM[1] - _BAND_NM[0]
    # NOTE: E_u(0⁻) from a plane 2 cm *above* the water (vacuum, index-matched: the same upward
    # irradiance); one just below the surface lies within Mitsuba's ray offset of the top face
    # (~1e-4 (1 + |p|) m), so paths skipped the face and went on in "water" above it (R 55 % high).
    planes = [(float(z), True) for z in depths] + [(-0.02, False)]
    bare = mi.load_dict(slab_scene(a, b, phase, zenith_deg, 1.0, True, spp, water=False))
    # NOTE: a "radiance": 1.0 emitter reads 4 % above 1 on this band (Mitsuba's spectral conversion of a
    # float); the plane seen through vacuum calibrates L_e exactly.
    L_e = float(np.array(mi.render(bare, seed=seed, spp=spp)).ravel()[0]) / width
    values = np.empty((passes, len(planes)))
    for i, (z, up) in enumerate(planes):
        scene = mi.load_dict(slab_scene(a, b, phase, zenith_deg, z, up, spp))
        n = spp if up or spp_up is None else spp_up
        for k in range(passes):
            image = mi.render(scene, seed=seed + 7919 * k + i, spp=n)
            values[k, i] = mu_w * float(np.array(image).ravel()[0]) / width / L_e  # Eq. (1), F = 1
    mean = values.mean(axis=0)
    error = values.std(axis=0, ddof=1) / math.sqrt(passes)
    return SlabLight(z=depths, E_d=mean[:-1], E_d_error=error[:-1], E_u0=float(mean[-1]),
                     E_u0_error=float(error[-1]), E_d0=mu_w)


def first_optical_depth_K(z, E_d, E_d0: float) -> float:
    """K_d over the first optical depth, 1/z₁ with ln E_d(z₁) = ln E_d(0) − 1 [m⁻¹] (Gordon 1989).

    From metered depths z (three around z₁) [m] and their E_d: a quadratic of ln E_d in z, its root
    nearest the middle depth.
    """
    z = np.asarray(z, dtype=float)
    coeffs = np.polyfit(z, np.log(np.asarray(E_d, dtype=float)), 2)
    roots = np.roots(coeffs - np.array([0.0, 0.0, math.log(E_d0) - 1.0]))
    real = roots[np.isreal(roots)].real
    return float(1.0 / real[np.argmin(np.abs(real - z[1]))])


@dataclass(frozen=True)
class SlabKd:
    """K̄_d of :func:`slab_kd`: ln(E_d(z₀)/E_d(H))/(H − z₀) [m⁻¹] and one standard error [m⁻¹];
    E_d at both depths [-, per unit horizontal irradiance above the water]."""

    K: float
    K_error: float
    E_d: tuple[float, float]
    depths: tuple[float, float]


#: Depth of the "just below the surface" meter of :func:`slab_kd` [m]: 20 ray offsets below the top face,
#: where E_d differs from E_d(0⁻) by K z₀ ≤ 0.4 % even at K = 2 m⁻¹.
NEAR_SURFACE_M = 0.002


def slab_kd(a: float, b: float, phase: tuple[np.ndarray, np.ndarray], air_zeniths_deg, weights, depth: float,
            n_water: float, spp: int = 16384, passes: int = 4, seed: int = 0) -> SlabKd:
    """Monte Carlo K̄_d over [z₀, H] of a deep slab under a level water surface, lit by several beams.

    The surface is a smooth dielectric of index ``n_water`` (Fresnel reflection and refraction of the
    light coming in and internal reflection of the light going out, as a level sea). Beam k comes from
    ``air_zeniths_deg[k]`` with horizontal irradiance ``weights[k]`` above the water (the sun and the
    rings of a uniform sky, :func:`oceanrender.optics.jerlov_kd.surface_beams`). Per beam, Eq. (1) with
    the basic radiance L/n² reciprocal across the interface (Case 1957) reads

        E_d(z) = F cos θ_air · n² · L_air(−ω_s) / L_e                                      (2)

    (for a clear slab: L_air = L_e (1 − F) e^{−c z/μ_w}/n², so E_d = F μ_air (1 − F) e^{−c z/μ_w}, the
    refracted beam; tested). E_d is metered at z₀ = :data:`NEAR_SURFACE_M` and at H = ``depth`` [m].
    """
    import mitsuba as mi  # noqa: PLC0415

    zeniths = np.atleast_1d(np.asarray(air_zeniths_deg, dtype=float))
    weights = np.atleast_1d(np.asarray(weights, dtype=float))
    if not (a > 0 and b >= 0 and depth > 10 * NEAR_SURFACE_M and passes >= 2 and zeniths.shape == weights.shape
            and np.all((zeniths >= 0) & (zeniths <= 85)) and np.all(weights >= 0) and 1.0 < n_water < 2.0):
        raise ValueError("slab_kd: need a > 0, b >= 0, depth > 0.02 m, passes >= 2, one weight >= 0 per zenith "
                         "0-85 deg, 1 < n_water < 2")
    width = _BAND_NM[1] - _BAND_NM[0]
    bare = mi.load_dict(slab_scene(a, b, phase, 0.0, 1.0, True, spp, water=False))
    L_e = float(np.array(mi.render(bare, seed=seed, spp=spp)).ravel()[0]) / width
    depths = (NEAR_SURFACE_M, float(depth))
    values = np.zeros((passes, 2))
    for j, (zenith, weight) in enumerate(zip(zeniths, weights)):
        for i, z in enumerate(depths):
            scene = mi.load_dict(slab_scene(a, b, phase, float(zenith), z, True, spp, n_water=n_water))
            for k in range(passes):
                image = mi.render(scene, seed=seed + 7919 * k + 104729 * j + i, spp=spp)
                values[k, i] += weight * n_water**2 * float(np.array(image).ravel()[0]) / width / L_e  # Eq. (2)
    mean = values.mean(axis=0)
    error = values.std(axis=0, ddof=1) / math.sqrt(passes)
    thickness = depths[1] - depths[0]
    K = math.log(mean[0] / mean[1]) / thickness
    K_error = math.hypot(error[0] / mean[0], error[1] / mean[1]) / thickness
    return SlabKd(K=K, K_error=K_error, E_d=(float(mean[0]), float(mean[1])), depths=depths)
