"""The baked ripple maps as a shader uses them: slope moments in a mip pyramid, level of detail, perturbation.

The ripple maps of :func:`oceanrender.realtime.luts.bake_ripples` hold the
waves finer than the geometry, whose slope variance is also the Beckmann
roughness α of the surface (α² = total mean-square slope of the unresolved
waves, :func:`oceanrender.waves.roughness.beckmann_alpha`). A pixel that
resolves ripples should show them and keep only the rest as roughness; a pixel
that covers many tiles should show the mean surface with the whole α. Both
follow from one mip pyramid of the slope moments (LEAN mapping, Olano & Baker
2010, §3): level 0 holds (s_x, s_y, s_x², s_y²) per texel, each level the 2 × 2
mean of the one below; at the level λ the pixel's footprint selects,

* the mean slope ⟨s⟩_λ tilts the normal (the resolved ripples),
* σ²_λ = ⟨s_x²⟩ + ⟨s_y²⟩ − |⟨s⟩|² is the slope variance left unresolved
  inside the footprint, and the roughness becomes
  α_λ² = α² − k² (σ²_tile − σ²_λ), with σ²_tile the tile's mean-square slope
  and k the ripple strength: at level 0 the resolved ripples leave α, at the
  top level (1 texel) σ²_λ = σ²_tile and α_λ = α.

The seafloor texture-coordinate perturbation (the dissertation's refraction
by ripples) is read from the same level of the offset map: the refracted
ray's seafloor point moves by (depth below the surface) × (δx, δy).

The pyramid is built here and uploaded level by level to the GL texture, so
the shader and this model sample the same texels; sampling is OpenGL's
``LINEAR_MIPMAP_LINEAR`` with an explicit level (``textureLod``): bilinear
with wrap-around on levels ⌊λ⌋ and ⌊λ⌋ + 1, mixed by the fraction of λ
(OpenGL 4.6 core specification, §8.14.2 "Coordinate Wrapping and Texel
Selection", Eqs. 8.10–8.11, and §8.14.3 "Mipmapping").

References
----------
.. [1] M. Olano and D. Baker, "LEAN mapping," Proc. I3D 2010, 181–188.
   doi:10.1145/1730804.1730834
.. [2] The dissertation named in the project issue: normal ripples and the
   texture-coordinate perturbation of the seafloor.
.. [3] M. Segal and K. Akeley, The OpenGL Graphics System: A Specification,
   version 4.6 (Core Profile), 2019, §8.14.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["slope_moments", "mip_pyramid", "RipplePyramids", "ripple_pyramids", "ripple_lod", "ripple_texcoord",
           "sample_repeat", "sample_trilinear", "perturbed_normal", "effective_alpha", "RippleSample",
           "sample_ripples", "pixel_angle", "MIN_NORMAL_Z", "MIN_RAY_Z", "MIN_ALPHA"]

#: Facets steeper than this (normal z below it) get no ripples: a slope sum is meaningless there [-].
MIN_NORMAL_Z = 0.2

#: The footprint's stretch along the view, 1/|d_z|, is capped at 1/MIN_RAY_Z (near the horizon) [-].
MIN_RAY_Z = 0.02

#: Smallest Beckmann α left after resolved ripples are removed (a glint of a perfect mirror is a delta) [-].
MIN_ALPHA = 0.02


def slope_moments(normals: ArrayLike) -> NDArray[np.float32]:
    """Level 0 of the LEAN pyramid: (s_x, s_y, s_x², s_y²) of unit normals (N, N, 3) → (N, N, 4) float32.

    s = ∂η/∂x, ∂η/∂y = (−n_x/n_z, −n_y/n_z) for a height field η with
    n ∝ (−∂η/∂x, −∂η/∂y, 1) [-].
    """
    n = np.asarray(normals, dtype=np.float64)
    s = -n[..., :2] / n[..., 2:3]
    return np.concatenate([s, s**2], axis=-1).astype(np.float32)


def mip_pyramid(level0: ArrayLike) -> list[NDArray[np.float32]]:
    """Mip levels of a square power-of-two texture (N, N, C): each the 2 × 2 mean of the one before, to 1 × 1."""
    level = np.asarray(level0, dtype=np.float64)
    size = level.shape[0]
    if level.shape[1] != size or size & (size - 1):
        raise ValueError(f"mip_pyramid: a square power-of-two texture is needed, got {level.shape[:2]}")
    levels = [level]
    while level.shape[0] > 1:
        h = level.shape[0] // 2
        level = level.reshape(h, 2, h, 2, -1).mean(axis=(1, 3))
        levels.append(level)
    return [lv.astype(np.float32) for lv in levels]


@dataclass(frozen=True, eq=False)
class RipplePyramids:
    """The two mipmapped ripple textures and the tile they cover.

    Attributes
    ----------
    moments : list of ndarray (N_L, N_L, 4)   (s_x, s_y, s_x², s_y²) per level [-].
    offsets : list of ndarray (N_L, N_L, 2)   Seafloor drift per metre of depth (δx, δy) per level [m m⁻¹].
    patch_size : float                        Side of the tile [m].
    mean_square_slope : float                 σ²_tile = ⟨s_x² + s_y²⟩ of the tile (top level) [-].
    """

    moments: list[NDArray[np.float32]]
    offsets: list[NDArray[np.float32]]
    patch_size: float
    mean_square_slope: float

    @property
    def texels(self) -> int:
        return int(self.moments[0].shape[0])

    @property
    def levels(self) -> int:
        return len(self.moments)


def ripple_pyramids(normals: ArrayLike, offsets: ArrayLike, patch_size: float) -> RipplePyramids:
    """Both pyramids from the baked ``ripple_normals`` and ``ripple_offsets`` maps of a tile of side ``patch_size`` [m]."""
    moments = mip_pyramid(slope_moments(normals))
    top = moments[-1][0, 0].astype(np.float64)
    return RipplePyramids(moments=moments, offsets=mip_pyramid(offsets), patch_size=float(patch_size),
                          mean_square_slope=float(top[2] + top[3]))


def ripple_lod(distance: ArrayLike, ray_z: ArrayLike, pixel_angle: float, texel_size: float, levels: int
               ) -> NDArray[np.float64]:
    """Mip level λ of a pixel: log₂ of its footprint on the sea in texels, in [0, levels − 1].

    footprint = distance · pixel_angle / max(|d_z|, MIN_RAY_Z) [m]: the
    pixel's angular size at the hit, stretched by the grazing view along its
    longer axis (isotropic filtering of the longer axis; the anisotropy is
    left to the variance).

    Parameters
    ----------
    distance : array_like
        Camera to the water [m].
    ray_z : array_like
        z of the unit camera ray [-].
    pixel_angle : float
        Angle of a pixel at the image centre, 2 tan(fov_x/2)/width [rad].
    texel_size : float
        Level-0 texel spacing of the ripple map [m].
    levels : int
        Number of mip levels.
    """
    footprint = (np.asarray(distance, dtype=np.float64) * pixel_angle
                 / np.maximum(np.abs(np.asarray(ray_z, dtype=np.float64)), MIN_RAY_Z))
    with np.errstate(divide="ignore"):
        lod = np.log2(np.maximum(footprint / texel_size, 1e-30))
    return np.clip(np.nan_to_num(lod, nan=levels - 1.0, posinf=levels - 1.0), 0.0, levels - 1.0)


def ripple_texcoord(xy: ArrayLike, patch_size: float, texels: int) -> NDArray[np.float64]:
    """Texture coordinate (s, t) of world (x, y) [m]: texel (i, j) holds the ripple at (i, j)·patch/texels.

    s = x/patch + ½/N (texel i's centre is at s = (i + ½)/N); the texture repeats.
    """
    return np.asarray(xy, dtype=np.float64) / patch_size + 0.5 / texels


def sample_repeat(level: NDArray, st: ArrayLike) -> NDArray[np.float64]:
    """Bilinear sample of one level (N, N, C) at (s, t) (..., 2) with GL_REPEAT wrapping → (..., C).

    Column i is s, row j is t (the first row of the array is t near 0).
    """
    data = np.asarray(level, dtype=np.float64)
    size = data.shape[0]
    st = np.asarray(st, dtype=np.float64)
    p = st * size - 0.5  # OpenGL 4.6 §8.14.2: i0 = ⌊u − ½⌋, α = frac(u − ½)
    p0 = np.floor(p)
    f = p - p0
    i0 = np.mod(p0[..., 0].astype(np.int64), size)
    j0 = np.mod(p0[..., 1].astype(np.int64), size)
    i1, j1 = np.mod(i0 + 1, size), np.mod(j0 + 1, size)
    fx, fy = f[..., 0:1], f[..., 1:2]
    top = data[j0, i0] * (1.0 - fx) + data[j0, i1] * fx
    bottom = data[j1, i0] * (1.0 - fx) + data[j1, i1] * fx
    return top * (1.0 - fy) + bottom * fy


def sample_trilinear(pyramid: list[NDArray], st: ArrayLike, lod: ArrayLike) -> NDArray[np.float64]:
    """``textureLod`` with LINEAR_MIPMAP_LINEAR: levels ⌊λ⌋ and ⌊λ⌋ + 1 mixed by frac(λ) → (..., C)."""
    lod = np.clip(np.asarray(lod, dtype=np.float64), 0.0, len(pyramid) - 1.0)
    d1 = np.floor(lod).astype(np.int64)
    frac = (lod - d1)[..., None]
    channels = pyramid[0].shape[-1]
    out = np.zeros(lod.shape + (channels,))
    st = np.asarray(st, dtype=np.float64)
    for level in np.unique(d1):
        sel = d1 == level
        lo = sample_repeat(pyramid[level], st[sel])
        hi = sample_repeat(pyramid[min(level + 1, len(pyramid) - 1)], st[sel])
        out[sel] = lo * (1.0 - frac[sel]) + hi * frac[sel]
    return out


def perturbed_normal(normal: ArrayLike, slope: ArrayLike) -> NDArray[np.float64]:
    """The mean surface normal tilted by a ripple slope: slopes add (height fields add).

    n' ∝ (n_x/n_z − s_x, n_y/n_z − s_y, 1) for n ∝ (−∂η/∂x, −∂η/∂y, 1)
    (Olano & Baker 2010, §3, normals of summed height fields); facets with
    n_z < :data:`MIN_NORMAL_Z` keep their normal.
    """
    n = np.asarray(normal, dtype=np.float64)
    s = np.asarray(slope, dtype=np.float64)
    nz = np.maximum(n[..., 2:3], MIN_NORMAL_Z)
    tilted = np.concatenate([n[..., :2] / nz - s, np.ones_like(nz)], axis=-1)
    tilted /= np.linalg.norm(tilted, axis=-1, keepdims=True)
    return np.where(n[..., 2:3] >= MIN_NORMAL_Z, tilted, n)


def effective_alpha(alpha: ArrayLike, strength: float, tile_mss: float, unresolved: ArrayLike
                    ) -> NDArray[np.float64]:
    """Roughness left at a level: α_λ = √max(α² − k² (σ²_tile − σ²_λ), MIN_ALPHA²) [-] (module docstring)."""
    resolved = strength**2 * (tile_mss - np.asarray(unresolved, dtype=np.float64))
    return np.sqrt(np.maximum(np.asarray(alpha, dtype=np.float64) ** 2 - resolved, MIN_ALPHA**2))


@dataclass(frozen=True, eq=False)
class RippleSample:
    """The ripple terms of a set of water pixels.

    Attributes
    ----------
    normal : ndarray (..., 3)   Mean normal tilted by the resolved ripples [-].
    alpha : ndarray (...)       Beckmann roughness left unresolved [-].
    drift : ndarray (..., 2)    Seafloor drift per metre of depth, k (δx, δy) [m m⁻¹].
    lod : ndarray (...)         Mip level used [-].
    """

    normal: NDArray[np.float64]
    alpha: NDArray[np.float64]
    drift: NDArray[np.float64]
    lod: NDArray[np.float64]


def sample_ripples(pyramids: RipplePyramids, position: ArrayLike, normal: ArrayLike, distance: ArrayLike,
                   ray_z: ArrayLike, pixel_angle: float, alpha: ArrayLike, strength: float) -> RippleSample:
    """The ripple terms at water hits (position (..., 3) [m], normal, distance [m], ray z, the surface's α [-])
    for strength k ≥ 0."""
    texel = pyramids.patch_size / pyramids.texels
    lod = ripple_lod(distance, ray_z, pixel_angle, texel, pyramids.levels)
    st = ripple_texcoord(np.asarray(position)[..., :2], pyramids.patch_size, pyramids.texels)
    m = sample_trilinear(pyramids.moments, st, lod)
    mean = m[..., :2]
    unresolved = np.maximum(m[..., 2] + m[..., 3] - np.sum(mean**2, axis=-1), 0.0)
    drift = strength * sample_trilinear(pyramids.offsets, st, lod)
    return RippleSample(normal=perturbed_normal(normal, strength * mean),
                        alpha=effective_alpha(alpha, strength, pyramids.mean_square_slope, unresolved),
                        drift=drift, lod=lod)


def pixel_angle(fov_x_deg: float, width: int) -> float:
    """Angle subtended by a pixel at the image centre, 2 tan(fov_x/2)/width [rad]."""
    return 2.0 * math.tan(math.radians(fov_x_deg) / 2.0) / int(width)
