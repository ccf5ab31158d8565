"""Denoising frames with Intel Open Image Denoise (OIDN), guided by albedo and normal AOVs.

Two halves:

* **Mitsuba side** — a small second scene that renders, for the same camera
  and the same water mesh, the two feature images OIDN is trained with:
  the albedo and the shading normal at the first surface each pixel sees
  (Mitsuba's ``aov`` integrator, ``"albedo:albedo,nn:sh_normal"``, on an
  ``hdrfilm``). The main film is a ``specfilm`` of CIE x̄ȳz̄ channels, to
  which the ``aov`` integrator cannot add channels, hence the second scene
  (:class:`FeatureRenderer`, built and updated like
  :class:`oceanrender.render.renderer.WaterRenderer`).
* **OIDN side** — :func:`denoise` (linear RGB in, linear RGB out) through
  PyPI ``pyoidn`` on the CPU device, and :func:`denoise_XYZ` for the
  pipeline's absolute XYZ frames (converted to linear Rec. 709 and back).

Decisions (see docs/production.md)
----------------------------------
* The water surface's feature albedo is a constant (1 by default), not
  what Mitsuba's ``aov`` reports for a dielectric (0 for a smooth
  ``dielectric``, a view-dependent value for ``roughdielectric``). OIDN's
  documentation asks for the albedo of the first *diffuse-like* hit and
  allows a constant for perfectly specular (dielectric) surfaces. Foam is
  blended in by coverage with its own albedo; the sky (no hit) has albedo 0
  and normal 0.
* In spectral variants ``hdrfilm`` develops a spectrum to linear Rec. 709
  through XYZ without white balance, so a perfectly white (flat) reflectance
  comes out as the RGB of illuminant E, (1.205, 0.948, 0.909). Albedos are
  divided by it, so a white surface has albedo (1, 1, 1).
* HDR mode: OIDN requires non-negative colour. Linear Rec. 709 from XYZ can
  be slightly negative outside the gamut; the negative part is not denoised
  and is added back unchanged.
* OIDN treats isolated very bright pixels as fireflies and flattens them.
  On the sea that includes single-pixel sun glints: the denoised error
  levels off (relMSE ≈ 0.0015 at 64–128 spp on the default scene) instead
  of falling with the sample count.
* Measured on the default open-sea scene (benchmarks/bench_denoise.py,
  docs/production.md): denoising cuts the spp needed for a given error by
  7–17×, and the albedo/normal features do *not* help there (slightly
  worse at every spp): use colour only, ``denoise_XYZ(xyz)``, unless a
  scene has textured surfaces.

References
----------
.. [1] Intel Open Image Denoise, https://www.openimagedenoise.org/ (v2.5,
       through pyoidn 2.5.1); the ``RT`` filter: A. Áfra (2024), "Intel Open
       Image Denoise" (library documentation and technical overview).
.. [2] C. R. A. Chaitanya et al. (2017), "Interactive reconstruction of Monte
       Carlo image sequences using a recurrent denoising autoencoder", ACM
       Trans. Graph. 36(4), 98. doi:10.1145/3072959.3073601 (the albedo and
       normal feature inputs of learned denoisers).
.. [3] IEC 61966-2-1:1999, sRGB: the XYZ → linear RGB matrix (Mitsuba's
       ``xyz_to_srgb``).
.. [4] SMPTE ST 2065-1:2012, Academy Color Encoding Specification (ACES):
       the AP0 primaries and the XYZ → ACES2065-1 matrix (as in colour-science's
       ``RGB_COLOURSPACES["ACES2065-1"]``, checked equal in the tests).
.. [5] F. Durand and J. Dorsey (2002), "Fast bilateral filtering for the display of
       high-dynamic-range images", ACM Trans. Graph. 21(3), 257–266,
       doi:10.1145/566654.566574 — §5, the piecewise-linear bilateral filter (the
       range axis sampled at levels, a linear filter per level, interpolation between them).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..scene import CameraSettings, Scene
from ..surface.frame import FrameGeometry, Terrain
from .renderer import FOAM_ATTRIBUTE, WATER_ID, terrain_shapes, update_water_parameters, water_mesh
from .scene import perspective_sensor

#: XYZ → linear Rec. 709 (sRGB primaries, D65), as in Mitsuba's ``xyz_to_srgb`` [3].
XYZ_TO_LINEAR_SRGB = np.array([
    [3.240479, -1.537150, -0.498535],
    [-0.969256, 1.875991, 0.041556],
    [0.055648, -0.204043, 1.057311],
])

#: Linear Rec. 709 → XYZ, the inverse of :data:`XYZ_TO_LINEAR_SRGB`.
LINEAR_SRGB_TO_XYZ = np.linalg.inv(XYZ_TO_LINEAR_SRGB)

#: XYZ → linear ACES2065-1 (AP0 primaries, white ≈ D60) [4]. AP0's triangle encloses the spectral
#: locus, so every physical colour (XYZ of a non-negative spectrum) has AP0 components ≥ 0.
XYZ_TO_AP0 = np.array([
    [1.0498110175, 0.0000000000, -0.0000974845],
    [-0.4959030231, 1.3733130458, 0.0982400361],
    [0.0000000000, 0.0000000000, 0.9912520182],
])

#: Linear ACES2065-1 → XYZ, the inverse of :data:`XYZ_TO_AP0`.
AP0_TO_XYZ = np.linalg.inv(XYZ_TO_AP0)

#: AOV specification of Mitsuba's ``aov`` integrator: ``name:kind`` pairs.
FEATURE_AOVS = "albedo:albedo,nn:sh_normal"

#: Samples per pixel of the feature images: edges anti-aliased like the colour; OIDN prefilters the rest.
FEATURE_SPP = 16

#: Quality presets of OIDN's ``RT`` filter, by name.
QUALITIES = ("high", "balanced", "fast")


# ---------------------------------------------------------------------------
# Colour conversions
# ---------------------------------------------------------------------------


def XYZ_to_linear_sRGB(xyz: np.ndarray) -> np.ndarray:
    """Linear Rec. 709 RGB of CIE XYZ (..., 3), same scale [3]."""
    return np.asarray(xyz, dtype=np.float64) @ XYZ_TO_LINEAR_SRGB.T


def linear_sRGB_to_XYZ(rgb: np.ndarray) -> np.ndarray:
    """CIE XYZ of linear Rec. 709 RGB (..., 3), same scale [3]."""
    return np.asarray(rgb, dtype=np.float64) @ LINEAR_SRGB_TO_XYZ.T


def equal_energy_white_rgb() -> np.ndarray:
    """Linear Rec. 709 RGB of a flat spectrum of 1 as Mitsuba's spectral ``hdrfilm`` develops it [-].

    XYZ = (∫x̄, ∫ȳ, ∫z̄)/∫ȳ over the film's 360–830 nm (CIE 1931 2°), then
    :data:`XYZ_TO_LINEAR_SRGB`: about (1.205, 0.948, 0.909).
    """
    import colour  # noqa: PLC0415

    from .scene import CIE1931, FILM_RANGE_NM  # noqa: PLC0415

    cmfs = colour.MSDS_CMFS[CIE1931].copy().trim(colour.SpectralShape(*FILM_RANGE_NM, 1))
    integrals = cmfs.values.sum(axis=0)
    return XYZ_TO_LINEAR_SRGB @ (integrals / integrals[1])


# ---------------------------------------------------------------------------
# OIDN
# ---------------------------------------------------------------------------


def _image(array, name: str, shape=None) -> np.ndarray:
    image = np.asarray(array, dtype=np.float32)
    if image.ndim != 3 or image.shape[2] != 3 or min(image.shape[:2]) == 0:
        raise ValueError(f"{name} must have shape (height, width, 3), got {image.shape}")
    if shape is not None and image.shape != shape:
        raise ValueError(f"{name} has shape {image.shape}, but the colour image has {shape}")
    if not np.all(np.isfinite(image)):
        raise ValueError(f"{name} has {int((~np.isfinite(image)).any(axis=-1).sum())} non-finite pixels")
    return np.ascontiguousarray(image)


def denoise(rgb_linear: np.ndarray, albedo: np.ndarray | None = None, normal: np.ndarray | None = None,
            hdr: bool = True, quality: str = "high", clean_aux: bool = False) -> np.ndarray:
    """Denoise a linear RGB image with OIDN's ``RT`` filter on the CPU [1].

    Parameters
    ----------
    rgb_linear : array_like (H, W, 3)
        Linear RGB, any positive scale (HDR: OIDN picks the exposure itself).
        Negative values (out-of-gamut colours) are passed through undenoised.
    albedo : array_like (H, W, 3), optional
        Albedo of the first surface seen [-], clipped to [0, 1].
    normal : array_like (H, W, 3), optional
        Shading normal there (world or camera space), in [-1, 1]; requires ``albedo``
        (OIDN's trained filters take colour, colour + albedo, or colour + albedo + normal).
    hdr : bool
        The colour is high dynamic range (True for rendered radiance/luminance).
    quality : str
        "high" (default), "balanced" or "fast".
    clean_aux : bool
        The albedo and normal are noise-free (then OIDN does not prefilter them).

    Returns
    -------
    ndarray (H, W, 3) float32
        The denoised image, in the units of ``rgb_linear``.

    Raises
    ------
    ValueError
        Wrong shapes, non-finite values, a normal without an albedo, an unknown quality.
    """
    import pyoidn  # noqa: PLC0415

    if quality not in QUALITIES:
        raise ValueError(f"unknown quality {quality!r}; known: {', '.join(map(repr, QUALITIES))}")
    if normal is not None and albedo is None:
        raise ValueError("OIDN takes a normal image only together with an albedo image")
    colour_image = _image(rgb_linear, "colour")
    shape = colour_image.shape
    features = {}
    if albedo is not None:
        features["albedo"] = np.clip(_image(albedo, "albedo", shape), 0.0, 1.0)
    if normal is not None:
        features["normal"] = np.clip(_image(normal, "normal", shape), -1.0, 1.0)
    negative = np.minimum(colour_image, 0.0) if hdr else 0.0
    positive = np.maximum(colour_image, 0.0) if hdr else np.clip(colour_image, 0.0, 1.0)
    out = pyoidn.denoise(np.ascontiguousarray(positive), features.get("albedo"), features.get("normal"),
                         hdr=bool(hdr), clean_aux=bool(clean_aux), quality=quality)
    return np.asarray(out, dtype=np.float32) + negative


def denoise_XYZ(xyz: np.ndarray, albedo: np.ndarray | None = None, normal: np.ndarray | None = None,
                quality: str = "high") -> np.ndarray:
    """Denoise an absolute XYZ frame [cd m⁻² for Y]: via linear ACES2065-1 (AP0), back to XYZ (float64).

    OIDN's filters take non-negative linear RGB. In Rec. 709 a saturated
    spectral firefly (a violet sample at x, y ≈ 0.15, 0.03: one wavelength
    carrying a path's energy) has components of −10⁴ and more, which
    :func:`denoise` can only pass through undenoised: they left dark blue
    dots in the denoised default scene (93 in one 320×180 frame). In AP0
    [4], whose primaries enclose the spectral locus, every physical colour
    is non-negative, so the whole frame is denoised (0 such dots; mean
    luminance of the water within 0.6 % of the noisy frame's). ``albedo``
    and ``normal`` as in :func:`denoise` (e.g. from :class:`FeatureRenderer`).
    """
    ap0 = np.asarray(xyz, dtype=np.float64) @ XYZ_TO_AP0.T
    return np.asarray(denoise(ap0, albedo, normal, hdr=True, quality=quality), dtype=np.float64) @ AP0_TO_XYZ.T


def denoise_frame(xyz: np.ndarray, chroma_radius: int = 0) -> np.ndarray:
    """A frame's denoising [XYZ's unit]: OIDN colour only (:func:`denoise_XYZ`), then, with ``chroma_radius``
    > 0 [px], its chromaticity from the *noisy* frame's sums over neighbours of similar denoised luminance
    (:func:`smooth_chroma`), its luminance OIDN's. The default view at 320×180, 64 spp against a 4096-spp
    reference (own error 0.24): mean ΔE00 1.81 noisy, 1.15 OIDN, 0.71 with the chroma filter at r = 4
    (p95 5.18, 3.13, 1.99); mean Z +0.11 % (docs/time_to_quality.md)."""
    clean = denoise_XYZ(xyz)
    if chroma_radius <= 0:
        return clean
    return smooth_chroma(np.maximum(np.asarray(xyz, dtype=np.float64), 0.0), np.maximum(clean[..., 1], 0.0),
                         radius=int(chroma_radius))


#: Range of the chroma filter [-]: std of the Gaussian in natural-log luminance (±10 % is one σ).
CHROMA_SIGMA_LOG_Y = 0.1
#: Spatial radius of the chroma filter [px]: a (2r + 1)² box.
CHROMA_RADIUS_PX = 4


def smooth_chroma(xyz: np.ndarray, guide_Y: np.ndarray, radius: int = CHROMA_RADIUS_PX,
                  sigma: float = CHROMA_SIGMA_LOG_Y) -> np.ndarray:
    """An XYZ frame with its chromaticity averaged over neighbours of similar luminance, luminance kept.

    Colour noise of a spectral path tracer is chroma noise: each sample carries four wavelengths, so
    neighbouring pixels of the same water differ in colour far more than in lightness (issue 42), while
    the water's true colour changes slowly across the view. Per pixel p the ratios X/Y and Z/Y become the
    ratios of weighted sums over its (2r + 1)² box,

        X'/Y' = Σ_q w_pq X_q / Σ_q w_pq Y_q,   w_pq = exp(−(ln G_p − ln G_q)² / 2σ²),

    with G the guide (a denoised luminance): a cross-bilateral filter in log luminance, computed as
    Durand & Dorsey's piecewise-linear bilateral filter [5] (levels of ln G every σ, a box filter of
    X, Y, Z weighted by each level's Gaussian, linear interpolation between the two levels around
    ln G_p). Sums of X and Y, not means of X/Y: a dark, noisy pixel counts by its luminance. The
    result is Y = ``guide_Y`` with the averaged chromaticity (x/y, z/y of the sums).

    Parameters
    ----------
    xyz : ndarray (H, W, 3)       The frame's XYZ (any common unit, e.g. cd m⁻²), non-negative Y.
    guide_Y : ndarray (H, W)      The luminance to keep and to guide by [XYZ's unit] (e.g. OIDN's output).
    radius : int                  Box radius r [px], ≥ 0 (0: the frame as it is, luminance replaced).
    sigma : float                 σ of the range Gaussian in ln luminance [-], > 0.

    Returns
    -------
    ndarray (H, W, 3) float64     XYZ with Y = ``guide_Y``.
    """
    from scipy.ndimage import uniform_filter  # noqa: PLC0415

    xyz = np.asarray(xyz, dtype=np.float64)
    guide = np.asarray(guide_Y, dtype=np.float64)
    if xyz.ndim != 3 or xyz.shape[2] != 3 or guide.shape != xyz.shape[:2]:
        raise ValueError(f"need xyz (H, W, 3) and guide_Y (H, W), got {xyz.shape} and {guide.shape}")
    if not (int(radius) >= 0 and sigma > 0):
        raise ValueError(f"need radius ≥ 0 and sigma > 0, got {radius}, {sigma}")
    tiny = 1e-12 * max(float(np.max(guide)), 1e-30)
    log_g = np.log(np.maximum(guide, tiny))
    lo, hi = float(log_g.min()), float(log_g.max())
    levels = lo + sigma * np.arange(int(np.ceil((hi - lo) / sigma)) + 2)
    size = 2 * int(radius) + 1
    position = (log_g - lo) / sigma  # ln G in units of the level spacing
    below = np.clip(np.floor(position).astype(int), 0, levels.size - 2)
    t = position - below
    out = np.zeros_like(xyz)
    used = np.zeros(levels.size, dtype=bool)
    used[np.unique(below)] = True
    used[np.unique(below) + 1] = True
    for k, level in enumerate(levels):
        if not used[k]:  # no pixel interpolates from this level
            continue
        weight = np.exp(-0.5 * ((log_g - level) / sigma) ** 2)
        sums = np.stack([uniform_filter(weight * xyz[..., c], size=size, mode="nearest") for c in range(3)], axis=-1)
        share = np.where(below == k, 1.0 - t, 0.0) + np.where(below + 1 == k, t, 0.0)
        out += share[..., None] * sums
    y = out[..., 1]
    ok = y > 0
    ratio = np.where(ok[..., None], out / np.where(ok, y, 1.0)[..., None], xyz / np.maximum(xyz[..., 1:2], tiny))
    return ratio * guide[..., None]


# ---------------------------------------------------------------------------
# Mitsuba: the feature (albedo, normal) images
# ---------------------------------------------------------------------------


def aov_integrator(aovs: str = FEATURE_AOVS) -> dict:
    """Mitsuba's ``aov`` integrator: albedo and shading normal of the first hit (no inner integrator).

    Its output has the channels ``albedo.R, albedo.G, albedo.B, nn.X, nn.Y, nn.Z``
    (``integrator.aov_names()``); a pixel that hits nothing is 0 in all of them.
    """
    return {"type": "aov", "aovs": aovs}


def feature_film(width: int, height: int) -> dict:
    """``hdrfilm`` for the feature images: float32, box filter like :func:`~oceanrender.render.scene.xyz_film`."""
    return {"type": "hdrfilm", "width": int(width), "height": int(height), "pixel_format": "rgb",
            "component_format": "float32", "rfilter": {"type": "box"}}


def feature_water_bsdf(water_albedo: float = 1.0, foam_albedo: float | None = None) -> dict:
    """Stand-in BSDF of the water surface for the feature images.

    A ``diffuse`` of reflectance ``water_albedo`` [-] (the constant albedo
    OIDN allows for dielectrics), blended per vertex with a ``diffuse`` of
    ``foam_albedo`` [-] by the mesh's foam coverage when the sea has foam.
    """
    water = {"type": "diffuse", "reflectance": {"type": "spectrum", "value": float(water_albedo)}}
    if foam_albedo is None:
        return water
    return {"type": "blendbsdf", "weight": {"type": "mesh_attribute", "name": FOAM_ATTRIBUTE},
            "bsdf_0": water,
            "bsdf_1": {"type": "diffuse", "reflectance": {"type": "spectrum", "value": float(foam_albedo)}}}


@dataclass(frozen=True)
class Features:
    """OIDN's feature images of a frame: albedo (H, W, 3) in [0, 1] [-], shading normal (H, W, 3), world frame."""

    albedo: np.ndarray
    normal: np.ndarray


def split_features(image: np.ndarray, names: list[str], white_rgb: np.ndarray) -> Features:
    """Pick albedo and normal out of an ``aov`` render (H, W, C) by channel name.

    ``names`` is ``integrator.aov_names()``; the albedo is divided by
    ``white_rgb`` (:func:`equal_energy_white_rgb`) so a white surface is (1, 1, 1).
    """
    index = {name: i for i, name in enumerate(names)}
    try:
        albedo = image[..., [index[f"albedo.{c}"] for c in "RGB"]]
        normal = image[..., [index[f"nn.{c}"] for c in "XYZ"]]
    except KeyError as exc:
        raise ValueError(f"aov render lacks channel {exc}; it has {names}") from None
    return Features(albedo=np.asarray(albedo / white_rgb, dtype=np.float32), normal=np.asarray(normal, dtype=np.float32))


@dataclass
class FeatureRenderer:
    """A second Mitsuba scene, same camera and water mesh, rendering the albedo and normal AOVs.

    Build it next to the frame renderer with :meth:`build`; per frame call
    :meth:`update_water` with the same geometry and :meth:`render`. Its
    sensor is the scene's camera (``perspective_sensor``), so the feature
    images line up with the colour pixel for pixel (tested).
    """

    scene: object
    params: object
    resolution: tuple[int, int]
    spp: int
    white_rgb: np.ndarray

    @classmethod
    def build(cls, settings: Scene, faces: np.ndarray, geometry: FrameGeometry,
              resolution: tuple[int, int] | None = None, spp: int = FEATURE_SPP, terrain: Terrain | None = None,
              camera: CameraSettings | None = None, water_albedo: float = 1.0) -> "FeatureRenderer":
        """Load the feature scene once.

        Parameters
        ----------
        settings : Scene               The scene (camera, foam albedo).
        faces : ndarray (F, 3)         Water mesh triangles (``Sequence.faces``).
        geometry : FrameGeometry       Water mesh of the first frame.
        resolution : (int, int)        (width, height) [px]; the scene's by default.
        spp : int                      Samples per pixel of the feature images.
        terrain : Terrain or None      The coastal seafloor and beach, as for the frame renderer.
        camera : CameraSettings        Override of ``settings.camera``.
        water_albedo : float           Feature albedo of the water surface [-] (:func:`feature_water_bsdf`).
        """
        import mitsuba as mi  # noqa: PLC0415

        width, height = resolution or settings.output.resolution
        foam = settings.foam.albedo if geometry.foam is not None else None
        mesh = water_mesh(faces, geometry, feature_water_bsdf(water_albedo, foam))  # no medium
        scene = mi.load_dict({
            "type": "scene",
            "integrator": aov_integrator(),
            "sensor": perspective_sensor(camera or settings.camera, feature_film(width, height), spp),
            WATER_ID: mesh,
            **terrain_shapes(terrain),
        })
        return cls(scene=scene, params=mi.traverse(scene), resolution=(width, height), spp=int(spp),
                   white_rgb=equal_energy_white_rgb())

    def update_water(self, geometry: FrameGeometry) -> None:
        """Replace the water mesh's vertex positions [m], normals and foam in place."""
        update_water_parameters(self.params, geometry)

    def render(self, seed: int = 0) -> Features:
        """Render the albedo and normal images of the current geometry and camera."""
        import mitsuba as mi  # noqa: PLC0415

        image = np.array(mi.render(self.scene, seed=int(seed), spp=self.spp))
        return split_features(image, list(self.scene.integrator().aov_names()), self.white_rgb)
