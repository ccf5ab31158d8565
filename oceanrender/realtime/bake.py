"""A scene's LUT set: the same optics, sun and sky, and vision model Φ as its offline render.

Three layers (as the rest of the project):

* :func:`scene_iops` and :func:`measure_scene_light` gather the inputs — the
  water's a, b, b_b exactly as ``oceanrender optics`` computes them, and the
  sun and sky irradiance, adapting white and sky radiance from the renderer's
  own ``sunsky`` (these need an active Mitsuba variant);
* :func:`bake_lut_set` turns them into the textures (pure, no Mitsuba, no files);
* :mod:`oceanrender.realtime.files` writes and reads them.

The adaptation state of Φ (the world adaptation luminance L_wa) is an input:
the scene's fixed value, 0.18 · Y_white for ``"daylight"``, or — for
``"frame"`` — the log-average of a path-traced reference frame, which the
caller renders (:func:`oceanrender.realtime.reference.ReferenceRenderer`).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

from ..optics.foam import foam_spectral_factor_Frouin1996
from ..optics.report import REPORT_WAVELENGTHS
from ..optics.scene_water import scene_iops, water_ior  # scene_iops: the water as `oceanrender optics` has it
from ..optics.seafloor import linear_reflectance
from ..render.scene import sun_direction
from ..scene import Scene
from .luts import (
    Axis,
    Lut,
    VisionState,
    WaterColumn,
    albedo_display_rgb,
    bake_fresnel,
    bake_ripples,
    bake_sky,
    bake_T0,
    bake_T1,
    envmap_directions,
    irradiance_display_rgb,
)

__all__ = ["BakeSettings", "SceneLight", "LutSet", "scene_iops", "measure_scene_light", "water_column",
           "reference_albedo", "floor_albedo", "lut_axes", "bake_lut_set", "finest_cell", "surface_roughness_alpha",
           "LUT_NAMES", "OPTIONAL_LUT_NAMES", "COLOUR_UNIT", "seafloor_lut"]

#: The textures of a LUT set, in the order they are written.
LUT_NAMES = ("T0", "T1", "fresnel", "sky", "ripple_normals", "ripple_offsets")

#: LUTs a set holds only for some scenes: ``seafloor`` (rock coverage of a coastal floor).
OPTIONAL_LUT_NAMES = ("seafloor",)

#: Unit of every colour LUT.
COLOUR_UNIT = "linear display sRGB after the vision model Φ (1 = display white, D65)"


@dataclass(frozen=True)
class BakeSettings:
    """Sizes and parameters of the baked textures.

    Attributes
    ----------
    depth_texels, path_texels : int
        Texels of T0/T1 along the depth h and of T1 along the path length l.
    depth_scale, path_scale : float
        s of the rational axes u = x/(x + s) [m]: half the texels lie below s.
    fresnel_texels : int
        Texels of the Fresnel LUT over cos θ_i ∈ [0, 1].
    sky_size : (int, int)
        Width, height of the latitude–longitude sky map [px].
    ripple_texels : int
        Texels per side of the ripple maps (even).
    ripple_patch : float
        Side of the tileable ripple patch [m].
    ripple_seed : int
        Seed of the ripple patch.
    gamma : float
        γ of the corrected Fresnel weight F^γ baked into the Fresnel LUT [-].
    reference_albedo : (float, float)
        R0 of Eq. 22 at 400 and 700 nm (linear in λ, as the scene's seafloor
        albedos) [-]: the bottom albedo of T0's water column. Default black:
        T0 is the water's own light and T1 ∘ R the bottom's, so that the
        bottom follows the view ray's path length l (docs/realtime.md).
    floor_albedo : (float, float) or None
        Area-mean albedo of the seafloor at 400 and 700 nm [-], which sets the
        light on the bottom (E_bottom of T1) through the interreflection
        between floor and surface; None: the scene's sand and rock mixed by
        ``rock_cover`` (coastal), else black.
    wavelengths : ndarray
        Uniform wavelength grid of the spectral computation [nm].
    """

    depth_texels: int = 256
    path_texels: int = 256
    depth_scale: float = 2.0
    path_scale: float = 4.0
    fresnel_texels: int = 256
    sky_size: tuple[int, int] = (512, 256)
    ripple_texels: int = 256
    ripple_patch: float = 2.0
    ripple_seed: int = 1
    gamma: float = 1.0
    reference_albedo: tuple[float, float] = (0.0, 0.0)
    floor_albedo: tuple[float, float] | None = None
    wavelengths: NDArray[np.float64] = field(default_factory=lambda: REPORT_WAVELENGTHS.copy())

    def __post_init__(self) -> None:
        for name in ("depth_texels", "path_texels", "fresnel_texels", "ripple_texels"):
            if getattr(self, name) < 2:
                raise ValueError(f"BakeSettings.{name} must be ≥ 2, got {getattr(self, name)}")
        if self.ripple_texels % 2:
            raise ValueError(f"BakeSettings.ripple_texels must be even, got {self.ripple_texels}")
        if not (self.depth_scale > 0 and self.path_scale > 0 and self.ripple_patch > 0):
            raise ValueError("BakeSettings: depth_scale, path_scale and ripple_patch must be > 0 [m]")
        if not self.gamma > 0:
            raise ValueError(f"BakeSettings.gamma must be > 0, got {self.gamma}")
        if min(self.sky_size) < 2:
            raise ValueError(f"BakeSettings.sky_size must be at least 2 x 2, got {self.sky_size}")
        for name in ("reference_albedo", "floor_albedo"):
            pair = getattr(self, name)
            if pair is not None and not (len(pair) == 2 and all(0 <= r <= 1 for r in pair)):
                raise ValueError(f"BakeSettings.{name} must be two albedos in [0, 1], got {pair}")

    def describe(self) -> dict[str, object]:
        """JSON-ready copy."""
        return {"depth_texels": self.depth_texels, "path_texels": self.path_texels,
                "depth_scale_m": self.depth_scale, "path_scale_m": self.path_scale,
                "fresnel_texels": self.fresnel_texels, "sky_size": list(self.sky_size),
                "ripple_texels": self.ripple_texels, "ripple_patch_m": self.ripple_patch,
                "ripple_seed": self.ripple_seed, "gamma": self.gamma,
                "reference_albedo_400_700": list(self.reference_albedo),
                "floor_albedo_400_700": None if self.floor_albedo is None else list(self.floor_albedo),
                "wavelengths_nm": [float(self.wavelengths[0]), float(self.wavelengths[-1]),
                                   float(self.wavelengths[1] - self.wavelengths[0])]}


@dataclass(frozen=True, eq=False)
class SceneLight:
    """What the renderer's sun and sky deliver, measured once with Mitsuba.

    Attributes
    ----------
    wavelengths : ndarray (W,)          [nm]
    sun_irradiance : ndarray (W,)       Direct-normal solar irradiance [W m⁻² nm⁻¹].
    sky_irradiance : ndarray (W,)       Diffuse horizontal sky irradiance [W m⁻² nm⁻¹].
    white_XYZ : ndarray (3,)            Adapting white (white Lambertian plane) [cd m⁻²].
    sky_radiance : ndarray (H, W_map, W)  Sky radiance at the env-map texel centres [W m⁻² sr⁻¹ nm⁻¹].
    """

    wavelengths: NDArray[np.float64]
    sun_irradiance: NDArray[np.float64]
    sky_irradiance: NDArray[np.float64]
    white_XYZ: NDArray[np.float64]
    sky_radiance: NDArray[np.float64]


@dataclass(frozen=True, eq=False)
class LutSet:
    """The textures of the real-time model and the constants that go with them.

    Attributes
    ----------
    luts : dict of str to Lut
        ``T0``, ``T1``, ``fresnel``, ``sky``, ``ripple_normals``, ``ripple_offsets``.
    constants : dict
        JSON-ready values the shader needs besides the textures: ``n_water``,
        ``gamma``, ``reference_albedo_rgb`` (R0), ``sand_albedo_rgb``,
        ``rock_albedo_rgb``, ``sun_direction``, ``sun_irradiance_rgb``,
        ``sky_irradiance_rgb``, the vision state and the scene's parameters.
    """

    luts: dict
    constants: dict

    def __getitem__(self, name: str) -> Lut:
        return self.luts[name]

    @property
    def n_water(self) -> float:
        return float(self.constants["n_water"])

    @property
    def gamma(self) -> float:
        return float(self.constants["gamma"])

    def rgb(self, key: str) -> NDArray[np.float64]:
        """A colour constant as an array (3,)."""
        return np.asarray(self.constants[key], dtype=np.float64)


def measure_scene_light(scene: Scene, settings: BakeSettings, white_XYZ: NDArray | None = None) -> SceneLight:
    """Sun and sky irradiance, adapting white and sky map radiance of the scene (needs Mitsuba).

    ``white_XYZ`` (e.g. a :class:`~oceanrender.pipeline.Sequence`'s) is measured
    with :func:`~oceanrender.render.renderer.adapting_white_XYZ` when not given.
    """
    from ..render.irradiance import sky_irradiance_spectra  # noqa: PLC0415
    from ..render.renderer import adapting_white_XYZ  # noqa: PLC0415
    from .sky import sky_radiance_spectra  # noqa: PLC0415

    wavelengths = settings.wavelengths
    direct, diffuse = sky_irradiance_spectra(scene.sun, wavelengths, spp=scene.render.white_spp)
    if white_XYZ is None:
        white_XYZ = adapting_white_XYZ(scene, seed=scene.render.seed)
    directions = envmap_directions(*settings.sky_size)
    radiance = sky_radiance_spectra(scene.sun, directions, wavelengths)
    return SceneLight(wavelengths=wavelengths, sun_irradiance=direct, sky_irradiance=diffuse,
                      white_XYZ=np.asarray(white_XYZ, dtype=np.float64), sky_radiance=radiance)


def water_column(scene: Scene, light: SceneLight) -> WaterColumn:
    """The :class:`~oceanrender.realtime.luts.WaterColumn` of the scene under its measured light."""
    from ..optics.scene_water import water_phase_table  # noqa: PLC0415

    a, b, bb = scene_iops(scene, light.wavelengths)
    return WaterColumn(wavelengths=light.wavelengths, absorption=np.asarray(a, float), scattering=np.asarray(b, float),
                       backscattering=np.asarray(bb, float), sun_irradiance=light.sun_irradiance,
                       sky_irradiance=light.sky_irradiance, sun_zenith=90.0 - scene.sun.elevation,
                       n_water=water_ior(scene), phase=water_phase_table(scene, light.wavelengths))


def reference_albedo(scene: Scene, settings: BakeSettings) -> tuple[float, float]:
    """R0 of Eq. 22 at 400 and 700 nm [-] (the settings'; black by default)."""
    return tuple(float(r) for r in settings.reference_albedo)


def floor_albedo(scene: Scene, settings: BakeSettings) -> tuple[float, float]:
    """Area-mean seafloor albedo at 400 and 700 nm [-] that lights the bottom.

    The settings', else (1 − c) R_sand + c R_rock with c the scene's
    ``rock_cover`` (both albedos are linear in λ, so the mix of the end values
    is the mix of the spectra), else black (no seafloor).
    """
    if settings.floor_albedo is not None:
        return tuple(float(r) for r in settings.floor_albedo)
    if scene.coastal is None:
        return (0.0, 0.0)
    c = scene.coastal
    return tuple(float((1 - c.rock_cover) * s + c.rock_cover * r) for s, r in zip(c.sand_albedo, c.rock_albedo))


def lut_axes(settings: BakeSettings) -> tuple[Axis, Axis, Axis]:
    """The depth h, path length l and cos θ_i axes of T0, T1 and the Fresnel LUT."""
    depth = Axis("depth", "h", "m", settings.depth_texels, "rational", scale=settings.depth_scale)
    path = Axis("in-water path length", "l", "m", settings.path_texels, "rational", scale=settings.path_scale)
    cosine = Axis("cosine of the incidence angle (air side)", "mu", "1", settings.fresnel_texels, "linear", 0.0, 1.0)
    return depth, path, cosine


def bake_lut_set(scene: Scene, light: SceneLight, adaptation_luminance: float, adaptation_source: str,
                 settings: BakeSettings = BakeSettings()) -> LutSet:
    """Bake every texture of the real-time model for a scene (pure: no Mitsuba, no files).

    Parameters
    ----------
    scene : Scene
        The scene (water, sun, vision, coastal seafloor, [ocean] spectrum).
    light : SceneLight
        Its measured sun and sky (:func:`measure_scene_light`).
    adaptation_luminance : float
        L_wa of Φ [cd m⁻²].
    adaptation_source : str
        How L_wa was obtained (recorded in the sidecars).
    settings : BakeSettings
        Sizes and parameters.

    Returns
    -------
    LutSet
    """
    from ..pipeline import vision_for_scene  # noqa: PLC0415
    from ..waves.sea import directional_spectrum  # noqa: PLC0415

    if list(light.wavelengths) != list(settings.wavelengths):
        raise ValueError("light was measured on another wavelength grid than the settings'")
    phi = VisionState(vision_for_scene(scene), light.white_XYZ, float(adaptation_luminance))
    column = water_column(scene, light)
    wl = light.wavelengths
    depth, path, cosine = lut_axes(settings)
    R0_pair = reference_albedo(scene, settings)
    R0 = linear_reflectance(wl, R0_pair)
    floor_pair = floor_albedo(scene, settings)
    E_white = column.horizontal_irradiance

    common = {"scene": scene.name, "wavelengths_nm": [float(wl[0]), float(wl[-1]), float(wl[1] - wl[0])],
              "vision": {**phi.describe(), "adaptation_source": adaptation_source},
              "sun": scene.sun.model_dump(), "n_water": water_ior(scene), "settings": settings.describe()}
    optics = {"iops": "oceanrender.realtime.bake.scene_iops (as `oceanrender optics`)",
              "four_flux": {"coefficients": "oceanrender.optics.streams: from the medium's phase function and the "
                                            "refracted sun (delta-M discrete ordinates; asymptotic diffuse block, "
                                            "beam sources matching R(0-) and E_d at the first optical depth)",
                            "Q_sr": float(np.pi), "internal_reflection": True},
              "water": scene.water.model_dump(),
              "composition": None if scene.composition is None else scene.composition.model_dump(),
              "reference_albedo_400_700": list(R0_pair), "floor_albedo_400_700": list(floor_pair)}

    T0 = bake_T0(column, phi, depth, R0)
    T1 = bake_T1(column, phi, depth, path, linear_reflectance(wl, floor_pair))
    fresnel = bake_fresnel(cosine, water_ior(scene), settings.gamma)
    sky = bake_sky(light.sky_radiance, wl, phi)
    luts = {
        "T0": Lut("T0", T0[None].astype(np.float32), ("R", "G", "B"), depth, None,
                  f"T0(h) = Phi(E_upwell(h) / (pi n^2)): water-leaving radiance per unit transmittance over a "
                  f"bottom of albedo R0 at depth h (Eq. 21); {COLOUR_UNIT}", "sRGB", {**common, "optics": optics}),
        "T1": Lut("T1", T1.astype(np.float32), ("R", "G", "B"), path, depth,
                  f"T1(h, l) = Phi(exp(-c l) E_bottom(h) / (pi n^2)) per unit bottom albedo (Eq. 21), E_bottom "
                  f"over a floor of the area-mean albedo (floor_albedo); "
                  f"T_refr = T0(h) + T1(h, l) * (R - R0) with R, R0 albedos in display RGB (Eq. 22); {COLOUR_UNIT}",
                  "sRGB", {**common, "optics": optics}),
        "fresnel": Lut("fresnel", fresnel[None].astype(np.float32), ("R", "G"), cosine, None,
                       f"R: exact unpolarised Fresnel reflectance F(mu) air -> water (n = {water_ior(scene):g}); "
                       f"G: F^gamma with gamma = {settings.gamma:g} (Eq. 20) [-]", "linear",
                       {**common, "gamma": settings.gamma}),
        "sky": Lut("sky", sky.astype(np.float32), ("R", "G", "B"), None, None,
                   "Phi(L_sky): sky radiance arriving from each direction, sun disc excluded (the sun is in "
                   f"luts.json: sun_direction, sun_irradiance_rgb); latitude-longitude map; {COLOUR_UNIT}", "sRGB",
                   {**common, "mapping": {
                       "u": "u = azimuth / (2 pi), azimuth clockwise from north (+y) towards east (+x)",
                       "v": "v = zenith angle / pi (v = 0 straight up, +z; v = 1 straight down)",
                       "texels": "texel (i, j) is centred at u = (i + 0.5)/width, v = (j + 0.5)/height; "
                                 "row 0 is the first row of the file",
                       "direction": "d = (sin(pi v) sin(2 pi u), sin(pi v) cos(2 pi u), cos(pi v))",
                       "below_horizon": "0 (sunsky is black below the horizon)"}}),
    }
    spectrum = directional_spectrum(scene.ocean)
    luts.update(_ripple_luts(scene, settings, spectrum, common))

    sand = rock = None
    if scene.coastal is not None:
        luts["seafloor"] = seafloor_lut(scene.coastal, common)
        sand = albedo_display_rgb(linear_reflectance(wl, scene.coastal.sand_albedo), E_white, wl, phi)
        rock = albedo_display_rgb(linear_reflectance(wl, scene.coastal.rock_albedo), E_white, wl, phi)
    for lut in luts.values():
        if not np.all(np.isfinite(lut.data)):
            raise ValueError(f"LUT {lut.name}: {int(np.count_nonzero(~np.isfinite(lut.data)))} non-finite texels")
    constants = {
        **common,
        "gamma": settings.gamma,
        "reference_albedo_400_700": list(R0_pair),
        "floor_albedo_400_700": list(floor_pair),
        "reference_albedo_rgb": albedo_display_rgb(R0, E_white, wl, phi).tolist(),
        "sand_albedo_rgb": None if sand is None else sand.tolist(),
        "rock_albedo_rgb": None if rock is None else rock.tolist(),
        "foam_albedo_rgb": albedo_display_rgb(scene.foam.albedo * foam_spectral_factor_Frouin1996(wl), E_white,
                                              wl, phi).tolist(),
        "foam_definition": "fresh foam on the fraction B of the surface (the G-buffer's foam): Lambertian of "
                           "foam_albedo_rgb (the renderer's foam reflectance: [foam] albedo times Frouin et al. "
                           "1996's fall towards the near infrared) under sun and sky; water on the rest: "
                           "C = (1 - B) (Eq. 20 + glint) + B foam_albedo_rgb (sun max(0, n.s) + sky (1 + n_z)/2)",
        "albedo_rgb_definition": "Phi(R E / pi) / Phi(E / pi) per channel under the horizontal sun + sky "
                                 "irradiance E: a white albedo is (1, 1, 1)",
        "sun_direction": sun_direction(scene.sun.elevation, scene.sun.azimuth).tolist(),
        "surface_roughness_alpha": surface_roughness_alpha(scene, spectrum),
        "surface_roughness_definition": "Beckmann alpha of the waves finer than the geometry (the renderer's "
                                        "roughdielectric); the sun glint uses it",
        "sun_irradiance_rgb": irradiance_display_rgb(light.sun_irradiance, wl, phi).tolist(),
        "sky_irradiance_rgb": irradiance_display_rgb(light.sky_irradiance, wl, phi).tolist(),
        "irradiance_rgb_definition": "Phi(E / pi): a white Lambertian plane facing the sun (sun) or horizontal "
                                     "under the sky alone (sky); diffuse shading = albedo * (sun * max(0, n.s) "
                                     "+ sky * (1 + n_z) / 2); sun glint = pi * sun * F(v.h) D(h) G1(v) G1(s) / "
                                     "(4 n.v) with Beckmann D of alpha = surface_roughness_alpha",
        "coastal": None if scene.coastal is None else {
            "sand_albedo_400_700": list(scene.coastal.sand_albedo),
            "rock_albedo_400_700": list(scene.coastal.rock_albedo),
            "albedo_mixing": "R = (1 - rock) R_sand + rock R_rock, rock coverage in [0, 1]"},
        "equations": {
            "20": "C = T_refl F_c + C_water (1 - F_c), F_c = F^gamma",
            "21": "T0(h) = Phi(E_upwell / (pi n^2)); T1(h, l) = Phi(exp(-c l) E_bottom / (pi n^2))",
            "22": "C_water = T_refr = T0(h) + T1(h, l) * (R - R0)",
            "glint": "the sun's specular highlight, added to Eq. 20 (not part of T_refl, which is the sky map)"},
    }
    return LutSet(luts=luts, constants=constants)


def seafloor_lut(coastal, common: dict) -> Lut:
    """Rock coverage of a coastal floor on its grid (R, [0, 1]) over world x (columns) and y (rows) [m].

    The values the terrain mesh carries per vertex
    (:func:`oceanrender.scene.arrays.rock_mask`), so that a shader can look
    the seafloor up at a displaced point (the ripples' texture-coordinate
    perturbation); bilinear between the cell centres, clamped at the edges.
    """
    from ..scene.arrays import coastal_cell_centres, rock_mask  # noqa: PLC0415

    x, y = coastal_cell_centres(coastal)
    rock = rock_mask(coastal)
    columns = Axis("x", "x", "m", len(x), "linear", float(x[0]), float(x[-1]))
    rows = Axis("y", "y", "m", len(y), "linear", float(y[0]), float(y[-1]))
    return Lut("seafloor", rock[..., None].astype(np.float32), ("R",), columns, rows,
               "rock coverage c in [0, 1] of the seafloor at world (x, y) [-]; the albedo is "
               "(1 - c) sand_albedo_rgb + c rock_albedo_rgb (luts.json)", "linear",
               {**common, "rock_cover": coastal.rock_cover, "seed": coastal.seed,
                "source": "oceanrender.scene.arrays.rock_mask (the terrain mesh's per-vertex rock)"})


def finest_cell(scene: Scene) -> float:
    """Finest resolved cell of the scene's water geometry [m] (as the renderer's water body reports it)."""
    if scene.coastal is not None:
        return float(min(scene.coastal.spacing))
    from ..waves.sea import SeaSurface  # noqa: PLC0415

    return float(SeaSurface(scene.ocean).finest_cell)


def surface_roughness_alpha(scene: Scene, spectrum) -> float:
    """Beckmann α of the water surface [-], as :func:`oceanrender.pipeline.surface_roughness` sets it."""
    from ..waves.roughness import beckmann_alpha, unresolved_slope_variance  # noqa: PLC0415

    if scene.water.surface_roughness != "auto":
        return float(scene.water.surface_roughness)
    return beckmann_alpha(unresolved_slope_variance(spectrum, np.pi / finest_cell(scene)))


def _ripple_luts(scene: Scene, settings: BakeSettings, spectrum, common: dict) -> dict[str, Lut]:
    """The ripple normal map and perturbation map of the waves finer than the scene's geometry."""
    finest = finest_cell(scene)
    k_min = np.pi / finest  # the Nyquist wavenumber of the geometry (as the surface roughness)
    maps = bake_ripples(spectrum, settings.ripple_patch, settings.ripple_texels, k_min, water_ior(scene),
                        settings.ripple_seed)
    limit = float(np.max(np.abs(maps.offsets))) or 1.0
    tile = {"patch_size_m": maps.patch_size, "texels": settings.ripple_texels,
            "texel_spacing_m": maps.patch_size / settings.ripple_texels,
            "placement": "texel (i, j) holds the ripple at (x, y) = (i, j) * patch_size / texels; the tile repeats "
                         "every patch_size metres (periodic, seamless); column i -> +x (east), row j -> +y (north)",
            "band_rad_per_m": [float(k_min), float(np.pi * settings.ripple_texels / maps.patch_size)],
            "band_wavelengths_m": [2 * maps.patch_size / settings.ripple_texels, 2 * finest],
            "spectrum": scene.ocean.spectrum, "wind_speed_m_s": scene.ocean.wind_speed,
            "wind_direction_deg": scene.ocean.wind_direction, "fetch_m": scene.ocean.fetch,
            "seed": settings.ripple_seed, "mean_square_slope": maps.mean_square_slope,
            "expected_mean_square_slope": maps.expected_mean_square_slope,
            "source": "Tessendorf FFT height field of the [ocean] spectrum, band-limited to the waves shorter than "
                      "twice the geometry's finest cell (they are not in the mesh)"}
    return {
        "ripple_normals": Lut("ripple_normals", maps.normals.astype(np.float32), ("R", "G", "B"), None, None,
                              "unit ripple normal (R: x east, G: y north, B: z up) of a level surface [-]; "
                              "PNG: 0.5 + 0.5 n", "linear", {**common, "tile": tile},
                              preview_offset=0.5, preview_scale=0.5),
        "ripple_offsets": Lut("ripple_offsets", maps.offsets.astype(np.float32), ("R", "G"), None, None,
                              "seafloor texture-coordinate perturbation per unit depth (R: dx, G: dy) [m per m of "
                              "depth]: a vertical view ray refracted by the ripple meets a bottom h below at "
                              "(x, y) + h (dx, dy); for oblique rays add it to the level-surface refraction "
                              f"(first order in the slope). PNG: 0.5 + 0.5 d / {limit:.6g}", "linear",
                              {**common, "tile": tile}, preview_offset=0.5, preview_scale=0.5 / limit),
    }
