"""The real-time water model on the CPU: Eqs. 20 and 22 per pixel, from baked LUTs and a G-buffer.

What a fragment shader would do, in numpy, texel conventions included (so
that a shader can be checked against it pixel by pixel):

* water (open sea and coastal):
  C = G₁ [T_refl F_c + C_water (1 − F_c)], F_c = F^γ                 (Eq. 20)
  with F from the Fresnel LUT at μ = n·v (or exact, for tests), T_refl the
  sky map in the mirror direction, and C_water = T_refr of Eq. 22
  T_refr = T0(h) + T1(h, l) ∘ (R − R0)                                (Eq. 22)
  with G₁ Smith's masking of the unresolved roughness at the view (1 but
  at grazing views; ``masking=False`` drops it), and
  where h is the depth of the water column, l the in-water path of the
  refracted view ray, R the seafloor albedo where it ends (display RGB) and R0
  the LUTs' reference albedo; without a seafloor (open sea, h = l = ∞) this is
  T0(∞);
* land (beach or seafloor seen directly): Lambertian, R ∘ (E_sun max(0, n·s)
  + E_sky (1 + n_z)/2) with the sun and sky irradiance colours of the LUT set;
* sky: the sky map in the view direction (no sun disc); a mirror direction
  below the horizon is lifted onto it (the map is black below);
* the sun's glint on the water, added to Eq. 20 as shaders add a specular
  highlight: π E_sun F(v·h) D(h) G₁(v) G₁(s)/(4 n·v), with the Beckmann
  distribution D of the unresolved waves' roughness α (the renderer's
  ``roughdielectric``) and Smith's G₁ (Walter et al. 2007). It is a separate
  term because its Fresnel factor is F(v·h), not the F(n·v) of Eq. 20.

* ripples (optional, :class:`RippleView`; what the shipped GLSL shader does):
  the baked ripple maps' resolved slopes tilt the normal, the unresolved rest
  stays roughness of the glint, and the seafloor is looked up where the
  ripple-refracted ray meets it (:mod:`.ripples`). Without them the normal is
  the mesh's and α the whole roughness of the unresolved waves.

Not modelled (stated in docs/realtime.md): the blur of the sky's reflection by
the roughness, shadows.

References
----------
.. [1] The dissertation named in the project issue, Eqs. 20–22.
.. [2] B. Walter, S. R. Marschner, H. Li and K. E. Torrance, "Microfacet
   models for refraction through rough surfaces," Proc. EGSR 2007, 195–206
   (Eqs. 20, 25, 27). doi:10.2312/EGWR/EGSR07/195-206
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..optics.fresnel import N_AIR, fresnel_correction, reflectance_Fresnel
from .bake import LutSet
from .gbuffer import KIND_LAND, KIND_SKY, KIND_WATER, GBuffer
from .luts import Axis, Lut, direction_to_envmap_uv
from .ripples import RipplePyramids, sample_ripples

__all__ = ["sample_lut_1d", "sample_lut_2d", "sample_envmap", "fresnel_mix", "transmitted_colour",
           "distribution_Beckmann", "masking_Smith_Beckmann", "sun_glint", "RealtimeTerms", "realtime_terms",
           "render_realtime", "FRESNEL_SOURCES", "RippleView", "surface_alpha", "with_foam", "diffuse_light"]

#: Lowest z of a reflected direction looked up in the sky map [-] (just above the horizon).
HORIZON_Z = 1e-3

#: Where F comes from: the baked LUT (what a shader does) or the exact formula.
FRESNEL_SOURCES = ("lut", "exact")


def _stencil(axis: Axis, x: ArrayLike) -> tuple[NDArray[np.intp], NDArray[np.float64]]:
    """Lower texel index and weight of linear interpolation between nodes at the value x."""
    p = axis.coordinate(x) * (axis.count - 1)
    i0 = np.clip(np.floor(p), 0, axis.count - 2).astype(np.intp)
    return i0, (p - i0)


def sample_lut_1d(lut: Lut, x: ArrayLike) -> NDArray[np.float64]:
    """Linear interpolation of a one-row LUT at values x of its column axis → (..., channels)."""
    row = lut.data[0].astype(np.float64)
    i0, f = _stencil(lut.columns, x)
    return row[i0] * (1.0 - f[..., None]) + row[i0 + 1] * f[..., None]


def sample_lut_2d(lut: Lut, x_columns: ArrayLike, x_rows: ArrayLike) -> NDArray[np.float64]:
    """Bilinear interpolation of a 2-D LUT at values of its column (u) and row (v) axes → (..., channels)."""
    data = lut.data.astype(np.float64)
    i0, fu = _stencil(lut.columns, x_columns)
    j0, fv = _stencil(lut.rows, x_rows)
    fu, fv = fu[..., None], fv[..., None]
    top = data[j0, i0] * (1.0 - fu) + data[j0, i0 + 1] * fu
    bottom = data[j0 + 1, i0] * (1.0 - fu) + data[j0 + 1, i0 + 1] * fu
    return top * (1.0 - fv) + bottom * fv


def sample_envmap(lut: Lut, directions: ArrayLike) -> NDArray[np.float64]:
    """Bilinear lookup of a latitude–longitude map (texel centres at (i + ½)/width), wrapping in azimuth."""
    data = lut.data.astype(np.float64)
    height, width = data.shape[:2]
    u, v = direction_to_envmap_uv(directions)
    px = u * width - 0.5
    py = np.clip(v * height - 0.5, 0.0, height - 1.0)
    x0 = np.floor(px)
    fx = (px - x0)[..., None]
    i0 = np.mod(x0.astype(np.intp), width)
    i1 = np.mod(i0 + 1, width)
    j0 = np.minimum(np.floor(py).astype(np.intp), height - 2)
    fy = (py - j0)[..., None]
    top = data[j0, i0] * (1.0 - fx) + data[j0, i1] * fx
    bottom = data[j0 + 1, i0] * (1.0 - fx) + data[j0 + 1, i1] * fx
    return top * (1.0 - fy) + bottom * fy


def fresnel_mix(F: ArrayLike, T_refl: ArrayLike, C_water: ArrayLike, gamma: float) -> NDArray[np.float64]:
    """Eq. 20: C = T_refl F^γ + C_water (1 − F^γ).

    Parameters
    ----------
    F : array_like (...)
        Fresnel reflectance in [0, 1] [-].
    T_refl, C_water : array_like (..., 3)
        Reflected sky and light from the water, display RGB.
    gamma : float
        Correction exponent γ > 0 [-].
    """
    Fc = fresnel_correction(F, gamma)[..., None]
    return np.asarray(T_refl) * Fc + np.asarray(C_water) * (1.0 - Fc)  # Eq. 20 of [1]


def transmitted_colour(T0: ArrayLike, T1: ArrayLike, R: ArrayLike, R0: ArrayLike) -> NDArray[np.float64]:
    """Eq. 22: T_refr = T0(h) + T1(h, l) ∘ (R − R0), all (..., 3) display RGB (R, R0 albedos)."""
    return np.asarray(T0) + np.asarray(T1) * (np.asarray(R) - np.asarray(R0))  # Eq. 22 of [1]


def distribution_Beckmann(cos_h: ArrayLike, alpha: ArrayLike) -> NDArray[np.float64]:
    """Beckmann microfacet distribution D(h) = exp(−tan²θ_h/α²)/(π α² cos⁴θ_h) [sr⁻¹].

    Normalised so that ∫ D cos θ_h dω = 1.

    References: Eq. 25 of Walter et al. (2007).
    """
    alpha = np.asarray(alpha, dtype=np.float64)
    c2 = np.clip(np.asarray(cos_h, dtype=np.float64), 1e-12, 1.0) ** 2
    return np.where(np.asarray(cos_h) > 0, np.exp(-(1.0 - c2) / (c2 * alpha**2)) / (np.pi * alpha**2 * c2**2),
                    0.0)  # Eq. 25 of [2]


def masking_Smith_Beckmann(cos_v: ArrayLike, alpha: ArrayLike) -> NDArray[np.float64]:
    """Smith's masking G₁ for Beckmann facets, the rational approximation of Walter et al. (2007), Eq. 27 [-]."""
    alpha = np.asarray(alpha, dtype=np.float64)
    c = np.clip(np.asarray(cos_v, dtype=np.float64), 1e-12, 1.0)
    a = np.minimum(c / (alpha * np.maximum(np.sqrt(1.0 - c**2), 1e-12)), 1.6)
    g = (3.535 * a + 2.181 * a**2) / (1.0 + 2.276 * a + 2.577 * a**2)  # Eq. 27 of [2]
    return np.where(a < 1.6, g, 1.0)


def sun_glint(normal: ArrayLike, to_viewer: ArrayLike, sun: ArrayLike, alpha: ArrayLike, n_water: float,
              sun_rgb: ArrayLike) -> NDArray[np.float64]:
    """Radiance of the sun reflected by rough water, π E_sun F(v·h) D(h) G₁(v) G₁(s)/(4 n·v), display RGB.

    Parameters
    ----------
    normal, to_viewer : array_like (..., 3)
        Unit mean surface normal and unit direction to the camera.
    sun : array_like (3,)
        Unit direction to the sun.
    alpha : float or array_like (...)
        Beckmann roughness α of the unresolved waves [-].
    n_water : float
        Refractive index [-].
    sun_rgb : array_like (3,)
        Φ(E_sun/π) of the direct-normal sun irradiance (the LUT set's ``sun_irradiance_rgb``).

    Notes
    -----
    The microfacet BRDF F D G/(4 cos θ_s cos θ_v) of Walter et al. (2007,
    Eq. 20) times the sun's irradiance E_sun cos θ_s; zero where the sun or the
    viewer is below the mean surface.
    """
    n = np.asarray(normal, dtype=np.float64)
    v = np.asarray(to_viewer, dtype=np.float64)
    s = np.asarray(sun, dtype=np.float64)
    h = v + s
    h /= np.maximum(np.linalg.norm(h, axis=-1, keepdims=True), 1e-12)
    cos_v, cos_s, cos_h = (np.sum(n * x, axis=-1) for x in (v, np.broadcast_to(s, n.shape), h))
    F = reflectance_Fresnel(np.clip(np.sum(v * h, axis=-1), 0.0, 1.0), N_AIR, n_water)
    value = (F * distribution_Beckmann(cos_h, alpha) * masking_Smith_Beckmann(cos_v, alpha)
             * masking_Smith_Beckmann(cos_s, alpha) / (4.0 * np.maximum(cos_v, 1e-6)))  # Eq. 20 of [2]
    value = np.where((cos_v > 0) & (cos_s > 0), value, 0.0)
    return np.pi * value[..., None] * np.asarray(sun_rgb, dtype=np.float64)


@dataclass(frozen=True, eq=False)
class RealtimeTerms:
    """The per-pixel terms of Eq. 20 of one view, so that any γ gives the image at once.

    Attributes
    ----------
    water : ndarray (H, W) bool     Pixels shaded by Eq. 20.
    F : ndarray (H, W)              Fresnel reflectance F (before the γ correction) [-].
    T_refl : ndarray (H, W, 3)      Reflected sky (display RGB).
    C_water : ndarray (H, W, 3)     Light from the water, T_refr (display RGB).
    glint : ndarray (H, W, 3)       The sun's glint on the water (display RGB), added after Eq. 20.
    other : ndarray (H, W, 3)       Colour of the pixels that are not water (sky, land).
    foam : ndarray (H, W)           Fresh-foam coverage B of the water pixels [-].
    foam_colour : ndarray (H, W, 3) Light from that foam, Lambertian under sun and sky (display RGB).
    """

    water: NDArray[np.bool_]
    F: NDArray[np.float64]
    T_refl: NDArray[np.float64]
    C_water: NDArray[np.float64]
    glint: NDArray[np.float64]
    other: NDArray[np.float64]
    foam: NDArray[np.float64] | None = None
    foam_colour: NDArray[np.float64] | None = None

    def image(self, gamma: float) -> NDArray[np.float64]:
        """The real-time image (H, W, 3) in linear display sRGB for the exponent γ."""
        mixed = with_foam(fresnel_mix(self.F, self.T_refl, self.C_water, gamma) + self.glint, self.foam,
                          self.foam_colour)
        return np.where(self.water[..., None], mixed, self.other)


def with_foam(water: NDArray, foam: NDArray | None, foam_colour: NDArray | None) -> NDArray[np.float64]:
    """(1 − B) water + B foam: the renderer's blend of the water BSDF and Lambertian foam (``foamy_surface_bsdf``)."""
    if foam is None:
        return water
    B = np.asarray(foam, dtype=np.float64)[..., None]
    return (1.0 - B) * water + B * np.asarray(foam_colour, dtype=np.float64)


@dataclass(frozen=True, eq=False)
class RippleView:
    """The ripple maps as one view samples them.

    Attributes
    ----------
    pyramids : RipplePyramids   The mipmapped slope moments and offsets (:func:`.ripples.ripple_pyramids`).
    strength : float            k ≥ 0: scale of the ripple slopes (1: as baked; 0: none, the seafloor map still used).
    pixel_angle : float         Angle of a pixel at the image centre [rad] (:func:`.ripples.pixel_angle`).
    """

    pyramids: RipplePyramids
    strength: float
    pixel_angle: float


def _albedo(luts: LutSet, rock: NDArray) -> NDArray[np.float64]:
    """Seafloor albedo in display RGB: (1 − rock) R_sand + rock R_rock; R0 without a coastal seafloor."""
    sand, stone = luts.constants.get("sand_albedo_rgb"), luts.constants.get("rock_albedo_rgb")
    if sand is None or stone is None:
        return np.broadcast_to(luts.rgb("reference_albedo_rgb"), rock.shape + (3,))
    return (1.0 - rock[..., None]) * np.asarray(sand) + rock[..., None] * np.asarray(stone)


def realtime_terms(gbuffer: GBuffer, luts: LutSet, fresnel: str = "lut", glint: bool = True,
                   ripples: RippleView | None = None, masking: bool = True) -> RealtimeTerms:
    """Shade a G-buffer with the LUTs: the terms of Eq. 20 for water, final colours elsewhere.

    Parameters
    ----------
    gbuffer : GBuffer
        The view (:func:`oceanrender.realtime.gbuffer.trace_gbuffer`).
    luts : LutSet
        Baked textures and constants (:func:`oceanrender.realtime.bake.bake_lut_set`).
    fresnel : str
        ``"lut"`` (linear interpolation in the Fresnel LUT, as a shader) or
        ``"exact"`` (the Fresnel formula).
    glint : bool
        Add the sun's glint (:func:`sun_glint`).
    ripples : RippleView, optional
        Tilt the water's normals by the resolved ripples, keep the rest as the
        glint's roughness and look the seafloor up in the LUT set's
        ``seafloor`` map at the ripple-displaced point (when it has one).
    masking : bool
        Weight Eq. 20 by Smith's G₁(n·v) of the unresolved roughness α (Walter
        et al. 2007, Eq. 27): the share of the rough surface the viewer sees.
        The path tracer's microfacet BSDF (single scattering) drops the light
        of the masked share, which matters at grazing views of a rough sea
        (G₁ = 0.38 at 88° for α = 0.26) and not elsewhere (> 0.99 below 70°).
    """
    if fresnel not in FRESNEL_SOURCES:
        raise ValueError(f"fresnel: unknown source {fresnel!r}; known: {', '.join(map(repr, FRESNEL_SOURCES))}")
    kind = gbuffer.kind
    water = kind == KIND_WATER
    alpha = surface_alpha(gbuffer, float(luts.constants["surface_roughness_alpha"]))
    normal, rock, mu = gbuffer.normal, gbuffer.rock, np.clip(gbuffer.cos_view, 0.0, 1.0)
    if ripples is not None:
        sample = sample_ripples(ripples.pyramids, gbuffer.position[water], gbuffer.normal[water],
                                gbuffer.distance[water], gbuffer.ray[water][:, 2], ripples.pixel_angle,
                                alpha[water], ripples.strength)
        normal = gbuffer.normal.copy()
        normal[water] = sample.normal
        alpha[water] = sample.alpha
        rock = _seafloor_rock(luts, gbuffer, water, sample.drift, rock)
        mu = np.where(water, np.clip(np.sum(normal * -gbuffer.ray, axis=-1), 0.0, 1.0), mu)
    if fresnel == "lut":
        F = sample_lut_1d(luts["fresnel"], mu)[..., 0]
    else:
        F = reflectance_Fresnel(mu, N_AIR, luts.n_water)
    F = np.where(water, np.clip(F, 0.0, 1.0), 0.0)
    # Mirror direction of the camera ray about the shading normal. NOTE: where it points below the horizon
    # (grazing views of tilted facets) it is lifted onto the horizon: the sky map is black down there, while
    # the path tracer's ray meets the sea again; the horizon sky is the usual stand-in.
    reflected = gbuffer.ray + 2.0 * mu[..., None] * normal
    reflected[..., 2] = np.maximum(reflected[..., 2], HORIZON_Z)
    reflected /= np.linalg.norm(reflected, axis=-1, keepdims=True)
    T_refl = sample_envmap(luts["sky"], reflected)
    visible = np.where(water, masking_Smith_Beckmann(mu, alpha), 1.0) if masking else np.ones(kind.shape)
    h = np.where(water, gbuffer.depth, np.inf)
    l = np.where(water, gbuffer.path_length, np.inf)
    T0 = sample_lut_1d(luts["T0"], h)
    T1 = sample_lut_2d(luts["T1"], l, h)
    R = _albedo(luts, rock)
    C_water = transmitted_colour(T0, np.where(np.isfinite(l)[..., None], T1, 0.0), R,
                                 luts.rgb("reference_albedo_rgb"))
    sun = np.asarray(luts.constants["sun_direction"], dtype=np.float64)
    glints = np.zeros(kind.shape + (3,))
    if glint and np.any(water):
        glints[water] = sun_glint(normal[water], -gbuffer.ray[water], sun, alpha[water], luts.n_water,
                                  luts.rgb("sun_irradiance_rgb"))
    other = np.zeros(kind.shape + (3,))
    sky = kind == KIND_SKY
    other[sky] = sample_envmap(luts["sky"], gbuffer.ray[sky])
    land = kind == KIND_LAND
    if np.any(land):
        other[land] = _albedo(luts, gbuffer.rock[land]) * diffuse_light(gbuffer.normal[land], luts)
    foam = np.where(water, np.clip(gbuffer.foam, 0.0, 1.0), 0.0)
    foam_colour = np.zeros(kind.shape + (3,))
    if np.any(foam > 0) and luts.constants.get("foam_albedo_rgb") is not None:
        foamy = foam > 0
        foam_colour[foamy] = luts.rgb("foam_albedo_rgb") * diffuse_light(normal[foamy], luts)
    else:
        foam = np.zeros(kind.shape)
    return RealtimeTerms(water=water, F=F, T_refl=np.where(water[..., None], visible[..., None] * T_refl, 0.0),
                         C_water=np.where(water[..., None], visible[..., None] * C_water, 0.0), glint=glints,
                         other=other, foam=foam, foam_colour=foam_colour)


def diffuse_light(normal: NDArray, luts: LutSet) -> NDArray[np.float64]:
    """Light on a white Lambertian surface of unit normals (N, 3): sun_rgb max(0, n·s) + sky_rgb (1 + n_z)/2.

    The sky term is a uniform sky's irradiance on a tilted plane, (1 + n_z)/2 of
    the horizontal one (the view factor of the upper hemisphere).
    """
    sun = np.asarray(luts.constants["sun_direction"], dtype=np.float64)
    n = np.asarray(normal, dtype=np.float64)
    return (np.maximum(n @ sun, 0.0)[:, None] * luts.rgb("sun_irradiance_rgb")
            + ((1.0 + n[:, 2]) / 2.0)[:, None] * luts.rgb("sky_irradiance_rgb"))


def surface_alpha(gbuffer: GBuffer, alpha_surface: float) -> NDArray[np.float64]:
    """Beckmann α per pixel [-]: the G-buffer's (a mesh with α per vertex), else the LUT set's ``alpha_surface``."""
    given = np.asarray(gbuffer.roughness, dtype=np.float64)
    return np.where(given > 0, given, alpha_surface)


def _seafloor_rock(luts: LutSet, gbuffer: GBuffer, water: NDArray, drift: NDArray, rock: NDArray) -> NDArray:
    """Rock coverage where the ripple-refracted rays meet the floor: the ``seafloor`` map at P_b + z_drop (δx, δy).

    z_drop = l |t_z| is how far below the surface the refracted ray meets the
    floor; pixels without a floor, and sets without the map, keep ``rock``.
    """
    if "seafloor" not in luts.luts:
        return rock
    l = gbuffer.path_length[water]
    floor = np.isfinite(l)
    drop = np.where(floor, l, 0.0) * np.abs(gbuffer.refracted[water][:, 2])
    xy = gbuffer.bottom_position[water][:, :2] + drop[:, None] * drift
    looked_up = sample_lut_2d(luts["seafloor"], xy[:, 0], xy[:, 1])[:, 0]
    out = rock.copy()
    out[water] = np.where(floor, looked_up, rock[water])
    return out


def render_realtime(gbuffer: GBuffer, luts: LutSet, gamma: float | None = None, fresnel: str = "lut",
                    glint: bool = True, ripples: RippleView | None = None, masking: bool = True
                    ) -> NDArray[np.float64]:
    """The real-time model's image (H, W, 3), linear display sRGB; γ defaults to the LUT set's."""
    terms = realtime_terms(gbuffer, luts, fresnel, glint, ripples, masking)
    return terms.image(luts.gamma if gamma is None else float(gamma))
