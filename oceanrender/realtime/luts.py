"""Lookup textures (LUTs) of the real-time water model, baked from the physical model.

The real-time approximation of the source dissertation mixes, per pixel,

    C = T_refl · F_c + C_water · (1 − F_c),   F_c = F^γ                       (20)
    T_refr = T0(h) + T1(h, l) ∘ (R − R0)                                        (22)
    T0(h) = Φ(E_upwell(h)/π),   T1(h, l) = Φ(α_l · E_bottom(h)/π),   α_l = e^{−c l}   (21)

with F the Fresnel reflectance, T_refl the reflected sky, C_water = T_refr the
light coming out of the water, h the depth of the water column, l the
in-water length of the refracted view ray, R the seafloor albedo where that ray
ends and R0 the albedo the LUTs were baked with. This module bakes the
textures those formulas read, as pure functions of spectra (no Mitsuba, no
files): the colour LUTs T0 and T1, a Fresnel LUT, the sky environment map, and
the ripple normal and texture-coordinate perturbation maps.

Spectral → display. Every colour LUT holds Φ(XYZ) in linear display sRGB
(1 = display white), with XYZ = K_m Σ L(λ) x̄(λ) Δλ (CIE 1931 2°, K_m =
683 lm W⁻¹) and Φ the scene's vision model with its adaptation state frozen
(:class:`VisionState`). Φ is linear in XYZ for a fixed adaptation state
(a scale factor, a von Kries matrix, the XYZ → sRGB matrix), so sums of LUT
values, such as Eq. 22, are sums of light.

Two deliberate departures from the formulas as quoted, both in the direction
of what the path tracer computes (docs/realtime.md):

* T0 and T1 include the n⁻² law of radiance at refraction: the radiance just
  above the surface is L_w (1 − F)/n², so T0 = Φ(E_upwell/(π n²)) and the
  (1 − F_c) factor of Eq. 20 supplies the transmittance.
* T1 is per unit (spectrally flat) bottom albedo: T1 ∘ (R − R0) is the
  bottom-reflected light of an albedo change, with R and R0 the albedos in
  display RGB (:func:`albedo_display_rgb`).

Texture coordinates. A LUT axis with N texels holds the quantity at N nodes
u_i = i/(N − 1), i = 0 … N − 1, with u = 0 and u = 1 at the first and last
texel centres; with hardware bilinear filtering sample at
``(u (N − 1) + 0.5)/N`` (the remapping of Bruneton & Neyret 2008). Depth and
path length are mapped by u = x/(x + s) (:class:`Axis`), so u = 1 is x = ∞ and
both the shallow and the deep limits are texels.

References
----------
.. [1] The dissertation named in the project issue, Eqs. 20–22 (its text is
   not available to us; the formulas are quoted in the issue).
.. [2] CIE 015:2018, Colorimetry, 4th ed., Eq. 7.1 (tristimulus values,
   K_m = 683 lm W⁻¹). doi:10.25039/TR.015.2018
.. [3] E. Bruneton and F. Neyret, "Precomputed atmospheric scattering,"
   Computer Graphics Forum 27(4), 1079–1086, 2008 (texel-centre remapping of
   LUT coordinates). doi:10.1111/j.1467-8659.2008.01245.x
.. [4] J. F. Blinn and M. E. Newell, "Texture and reflection in computer
   generated images," Commun. ACM 19(10), 542–547, 1976 (latitude–longitude
   environment maps). doi:10.1145/360349.360353
.. [5] J. Tessendorf, "Simulating Ocean Water," SIGGRAPH 2001 Course Notes
   (the FFT sea patch of the ripple maps).
.. [6] M. Pharr, W. Jakob and G. Humphreys, Physically Based Rendering, 4th
   ed., MIT Press, 2023, §9.3 (vector form of Snell's law).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import colour
import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..optics.fourflux import four_flux
from ..optics.fresnel import N_AIR, fresnel_correction, reflectance_Fresnel, refract, refracted_cosine
from ..optics.streams import StreamCoefficients, stream_coefficients, sunlit_coefficients
from ..vision.model import VisionModel

__all__ = [
    "K_M",
    "CIE1931",
    "MIN_DEPTH_M",
    "Axis",
    "Lut",
    "VisionState",
    "WaterColumn",
    "spectra_to_XYZ",
    "upwelling_radiance",
    "bake_T0",
    "bake_T1",
    "bake_fresnel",
    "envmap_directions",
    "direction_to_envmap_uv",
    "bake_sky",
    "RippleMaps",
    "bake_ripples",
    "albedo_display_rgb",
    "irradiance_display_rgb",
]

#: Maximum luminous efficacy of photopic vision K_m [lm W⁻¹] (CIE 015:2018; the candela's definition).
K_M = 683.0

#: colour-science's name of the CIE 1931 2° standard observer.
CIE1931 = "CIE 1931 2 Degree Standard Observer"

#: The four-flux model needs a water column H > 0; the h = 0 texel is evaluated at this depth [m].
MIN_DEPTH_M = 1e-6

#: Axis mappings from a physical value x to the texture coordinate u in [0, 1].
MAPPINGS = ("linear", "rational")


@dataclass(frozen=True)
class Axis:
    """One axis of a LUT: what it measures and how texture coordinates map to it.

    Parameters
    ----------
    name : str
        Quantity along the axis, e.g. ``"depth"``.
    symbol : str
        Its symbol in the formulas, e.g. ``"h"``.
    unit : str
        Unit of the physical value, e.g. ``"m"``; ``"1"`` for dimensionless.
    count : int
        Number of texels N ≥ 2.
    mapping : str
        ``"linear"``: u = (x − lo)/(hi − lo); ``"rational"``: u = x/(x + s),
        x ≥ 0, so that u = 1 is x = ∞.
    lo, hi : float
        Range of a linear axis (ignored for rational axes).
    scale : float
        s of a rational axis [unit] (ignored for linear axes): x = s is u = ½.

    Notes
    -----
    Texel i holds the node u_i = i/(N − 1); a shader samples at texture
    coordinate (u (N − 1) + 0.5)/N so that the hardware's bilinear filter
    interpolates between nodes (Bruneton & Neyret 2008).
    """

    name: str
    symbol: str
    unit: str
    count: int
    mapping: str = "linear"
    lo: float = 0.0
    hi: float = 1.0
    scale: float = 1.0

    def __post_init__(self) -> None:
        if self.mapping not in MAPPINGS:
            raise ValueError(f"Axis.mapping: unknown {self.mapping!r}; known: {', '.join(map(repr, MAPPINGS))}")
        if int(self.count) != self.count or self.count < 2:
            raise ValueError(f"Axis.count must be an integer ≥ 2, got {self.count!r}")
        if self.mapping == "linear" and not (math.isfinite(self.lo) and math.isfinite(self.hi) and self.hi > self.lo):
            raise ValueError(f"Axis {self.name}: a linear axis needs finite lo < hi, got {self.lo!r}, {self.hi!r}")
        if self.mapping == "rational" and not (math.isfinite(self.scale) and self.scale > 0):
            raise ValueError(f"Axis {self.name}: a rational axis needs a scale > 0, got {self.scale!r}")

    @property
    def nodes(self) -> NDArray[np.float64]:
        """Texture coordinates u_i = i/(N − 1) of the texels [-]."""
        return np.linspace(0.0, 1.0, int(self.count))

    @property
    def values(self) -> NDArray[np.float64]:
        """Physical value x_i at each texel [unit]; the last of a rational axis is ``inf``."""
        return self.value(self.nodes)

    def value(self, u: ArrayLike) -> NDArray[np.float64]:
        """Physical value x at texture coordinate u in [0, 1] [unit]."""
        u = np.asarray(u, dtype=np.float64)
        if self.mapping == "linear":
            return self.lo + (self.hi - self.lo) * u
        with np.errstate(divide="ignore"):
            return np.where(u < 1.0, self.scale * u / np.where(u < 1.0, 1.0 - u, 1.0), np.inf)

    def coordinate(self, x: ArrayLike) -> NDArray[np.float64]:
        """Texture coordinate u in [0, 1] of the physical value x [-]; clamped to the axis."""
        x = np.asarray(x, dtype=np.float64)
        if self.mapping == "linear":
            return np.clip((x - self.lo) / (self.hi - self.lo), 0.0, 1.0)
        x = np.maximum(x, 0.0)
        with np.errstate(invalid="ignore"):
            return np.where(np.isinf(x), 1.0, x / (x + self.scale))

    def texcoord(self, x: ArrayLike) -> NDArray[np.float64]:
        """Hardware texture coordinate (u (N − 1) + 0.5)/N of the value x [-]."""
        return (self.coordinate(x) * (self.count - 1) + 0.5) / self.count

    def describe(self, coordinate: str = "u") -> dict[str, object]:
        """JSON-ready description: formulas in the texture coordinate ``coordinate``, range, node convention."""
        c, x = coordinate, self.symbol
        if self.mapping == "linear":
            formula = f"{c} = ({x} - {self.lo:g}) / {self.hi - self.lo:g}"
            inverse = f"{x} = {self.lo:g} + {self.hi - self.lo:g} {c}"
            value_range = [self.lo, self.hi]
        else:
            formula, inverse = f"{c} = {x} / ({x} + s)", f"{x} = s {c} / (1 - {c})"
            value_range = [0.0, "inf"]
        return {"name": self.name, "symbol": self.symbol, "unit": self.unit, "texels": int(self.count),
                "mapping": self.mapping, "formula": formula, "inverse": inverse,
                "scale": self.scale if self.mapping == "rational" else None,
                "lo": self.lo if self.mapping == "linear" else None,
                "hi": self.hi if self.mapping == "linear" else None,
                "range": value_range,
                "nodes": f"texel i holds {c}_i = i/(N-1) ({c} = 0 and {c} = 1 are texel centres)",
                "texcoord": f"sample at ({c}*(N-1) + 0.5)/N for hardware bilinear filtering"}

    @classmethod
    def from_description(cls, description: dict) -> "Axis":
        """Inverse of :meth:`describe`."""
        d = description
        return cls(name=d["name"], symbol=d["symbol"], unit=d["unit"], count=int(d["texels"]),
                   mapping=d["mapping"], lo=0.0 if d["lo"] is None else float(d["lo"]),
                   hi=1.0 if d["hi"] is None else float(d["hi"]),
                   scale=1.0 if d["scale"] is None else float(d["scale"]))


@dataclass(frozen=True, eq=False)
class Lut:
    """A baked texture: data, what its axes and channels mean, how it is encoded.

    Attributes
    ----------
    name : str
        File stem and identifier, e.g. ``"T0"``.
    data : ndarray, float32, shape (rows, columns, channels)
        Texel values; row 0 is the first row of the file (texture v = 0).
    channels : tuple of str
        Channel names in order (``"R", "G", "B"`` for colours).
    columns : Axis or None
        Axis along a row (texture u); None for images with their own convention.
    rows : Axis or None
        Axis down the rows (texture v); None for 1-D LUTs (one row).
    quantity : str
        What the texel values are, with their unit.
    preview : str
        Encoding of the 8-bit PNG preview: ``"sRGB"`` (colours) or ``"linear"``.
    parameters : dict
        Everything the LUT was computed from (JSON-ready).
    preview_offset, preview_scale : float
        The PNG preview holds offset + scale · value, clipped to [0, 1], then
        encoded (``preview``) to 8 bits; e.g. 0.5 + 0.5 n for normals.
    """

    name: str
    data: NDArray[np.float32]
    channels: tuple[str, ...]
    columns: Axis | None
    rows: Axis | None
    quantity: str
    preview: str = "sRGB"
    parameters: dict = field(default_factory=dict)
    preview_offset: float = 0.0
    preview_scale: float = 1.0

    def __post_init__(self) -> None:
        if self.data.ndim != 3 or self.data.shape[-1] != len(self.channels):
            raise ValueError(f"Lut {self.name}: data must be (rows, columns, {len(self.channels)}), "
                             f"got {self.data.shape}")
        if self.preview not in ("sRGB", "linear"):
            raise ValueError(f"Lut {self.name}: preview encoding must be 'sRGB' or 'linear', got {self.preview!r}")
        if self.columns is not None and self.columns.count != self.data.shape[1]:
            raise ValueError(f"Lut {self.name}: {self.data.shape[1]} columns but axis {self.columns.name} has "
                             f"{self.columns.count} texels")
        if self.rows is not None and self.rows.count != self.data.shape[0]:
            raise ValueError(f"Lut {self.name}: {self.data.shape[0]} rows but axis {self.rows.name} has "
                             f"{self.rows.count} texels")


@dataclass(frozen=True)
class VisionState:
    """The vision operator Φ with its adaptation state frozen: absolute XYZ → linear display sRGB.

    Parameters
    ----------
    vision : VisionModel
        The scene's operators (brightness, chromatic transform, display).
    white_XYZ : ndarray (3,)
        Adapting white, the XYZ of a white Lambertian plane under the scene's
        sun and sky [cd m⁻²].
    adaptation_luminance : float
        World adaptation luminance L_wa [cd m⁻²].

    Notes
    -----
    For a fixed state Φ is linear in XYZ (see the module docstring), which is
    what makes Eqs. 20–22 sums of light after Φ.
    """

    vision: VisionModel
    white_XYZ: NDArray[np.float64]
    adaptation_luminance: float

    def __call__(self, XYZ: ArrayLike) -> NDArray[np.float64]:
        """Φ's linear stage: absolute XYZ (..., 3) [cd m⁻² for Y] → linear sRGB before the display response (..., 3).

        For the linear operators (Ward, Ferwerda et al.) that is the display
        image itself (1 = display white); for the compressive one
        (Reinhard & Devlin) it is light in units of the semi-saturation, and
        :meth:`display` (the response) turns a finished sum of light into
        display values. Either way sums of light stay sums (Eqs. 20–22).
        """
        return self.vision.linear(XYZ, self.white_XYZ, self.adaptation_luminance)

    def display(self, rgb_linear: ArrayLike) -> NDArray[np.float64]:
        """The response that turns a finished linear image into display sRGB [1 = display white]."""
        return self.vision.response(rgb_linear)

    def spectra(self, radiance: ArrayLike, wavelengths: ArrayLike) -> NDArray[np.float64]:
        """Φ of spectral radiance (..., W) [W m⁻² sr⁻¹ nm⁻¹] at ``wavelengths`` [nm] → (..., 3)."""
        return self(spectra_to_XYZ(radiance, wavelengths))

    def describe(self) -> dict[str, object]:
        """JSON-ready description of Φ and its state."""
        return {"brightness_operator": self.vision.brightness,
                "display_response": ("V = x / (1 + |x|) per channel (Reinhard & Devlin 2005): apply to the "
                                     "finished linear colour" if self.vision.brightness == "Reinhard Devlin 2005"
                                     else "identity: the linear colour is the display colour"),
                "exposure_EV": self.vision.exposure,
                "chromatic_transform": self.vision.chromatic_transform,
                "display_luminance_cd_m2": self.vision.display_max_luminance,
                "adapting_white_XYZ_cd_m2": [float(v) for v in self.white_XYZ],
                "adaptation_luminance_cd_m2": float(self.adaptation_luminance),
                "scale_factor": self.vision.scale_factor(self.adaptation_luminance)}


@dataclass(frozen=True)
class WaterColumn:
    """The optics a colour LUT is baked from: water IOPs and the light above the surface.

    Attributes
    ----------
    wavelengths : ndarray (W,)
        Uniformly spaced wavelengths [nm].
    absorption, scattering, backscattering : ndarray (W,)
        a, b, b_b [m⁻¹].
    sun_irradiance : ndarray (W,)
        Direct-normal solar irradiance above the surface [W m⁻² nm⁻¹].
    sky_irradiance : ndarray (W,)
        Diffuse sky irradiance on a horizontal plane [W m⁻² nm⁻¹].
    sun_zenith : float
        Solar zenith angle [deg].
    n_water : float
        Refractive index of the water [-].
    phase : (mu (M,), p (W, M)) or None
        The medium's phase function [-, sr⁻¹] (``oceanrender.optics.scene_water.water_phase_table``):
        the four-flux coefficients are derived from it and the refracted sun
        (:mod:`oceanrender.optics.streams`). None: the fixed closure (μ_d = 0.83, μ_u = 0.40).
    """

    wavelengths: NDArray[np.float64]
    absorption: NDArray[np.float64]
    scattering: NDArray[np.float64]
    backscattering: NDArray[np.float64]
    sun_irradiance: NDArray[np.float64]
    sky_irradiance: NDArray[np.float64]
    sun_zenith: float
    n_water: float
    phase: tuple[NDArray[np.float64], NDArray[np.float64]] | None = None
    _coefficients: dict = field(default_factory=dict, init=False, repr=False, compare=False)

    @property
    def attenuation(self) -> NDArray[np.float64]:
        """Beam attenuation c = a + b [m⁻¹]."""
        return self.absorption + self.scattering

    @property
    def horizontal_irradiance(self) -> NDArray[np.float64]:
        """Sun + sky irradiance on a horizontal plane above the water, E_sun cos θ_s + E_sky [W m⁻² nm⁻¹]."""
        return self.sun_irradiance * math.cos(math.radians(self.sun_zenith)) + self.sky_irradiance


def _band_width(wavelengths: NDArray) -> float:
    steps = np.diff(wavelengths)
    if wavelengths.ndim != 1 or len(wavelengths) < 2 or not np.allclose(steps, steps[0], rtol=1e-6):
        raise ValueError("wavelengths must be a 1-D, uniformly spaced grid [nm]")
    return float(steps[0])


def spectra_to_XYZ(radiance: ArrayLike, wavelengths: ArrayLike) -> NDArray[np.float64]:
    """Absolute CIE 1931 XYZ of spectral radiance sampled on a uniform grid.

    Parameters
    ----------
    radiance : array_like (..., W)
        Spectral radiance [W m⁻² sr⁻¹ nm⁻¹]; each sample stands for its band of
        width Δλ around the wavelength.
    wavelengths : array_like (W,)
        Uniformly spaced wavelengths within 360–830 nm [nm].

    Returns
    -------
    ndarray (..., 3)
        X, Y, Z with Y the luminance [cd m⁻²].

    References
    ----------
    .. [1] CIE 015:2018, Eq. 7.1.
    """
    wavelengths = np.asarray(wavelengths, dtype=np.float64)
    step = _band_width(wavelengths)
    cmfs = colour.MSDS_CMFS[CIE1931]
    xyz_bar = np.asarray(cmfs[wavelengths], dtype=np.float64)  # (W, 3), interpolated at λ
    return K_M * np.tensordot(np.asarray(radiance, dtype=np.float64), xyz_bar * step, axes=(-1, 0))  # Eq. 7.1 of [1]


def column_coefficients(column: WaterColumn) -> StreamCoefficients | None:
    """Four-flux coefficients of the column from its phase function and the refracted sun (None without a phase)."""
    if column.phase is None:
        return None
    # NOTE: the in-water coefficients, for E_upwell with a bottom and for E_bottom: the uniform-field r̄_wa
    # stays there, as over a shallow bright bottom (whose light reaches the surface nearly Lambertian) it
    # should; the water's own light gets the surface terms (_water_own_radiance). Derived once per column.
    if "in water" not in column._coefficients:
        mu_w = float(refracted_cosine(math.cos(math.radians(column.sun_zenith)), N_AIR, column.n_water))
        column._coefficients["in water"] = stream_coefficients(column.absorption, column.scattering,
                                                               column.phase[0], column.phase[1], mu_w)
    return column._coefficients["in water"]


def _column_light(column: WaterColumn, depths: NDArray, bottom_albedo: NDArray):
    """Four-flux E_upwell(0⁻) and E_bottom(H), each (D, W) [W m⁻² nm⁻¹], for depths (D,) [m]."""
    depth = np.where(np.isinf(depths), np.inf, np.maximum(depths, MIN_DEPTH_M))[:, None]
    light = four_flux(column.absorption, column.backscattering, column.sun_irradiance, column.sky_irradiance,
                      column.sun_zenith, depth, bottom_albedo, np.zeros(1), b=column.scattering,
                      n_water=column.n_water, internal_reflection=True, coefficients=column_coefficients(column))
    return light.E_upwell, light.E_bottom


def _water_own_radiance(column: WaterColumn, depths: NDArray) -> NDArray[np.float64]:
    """L_u(0⁻)/n² over a black bottom at ``depths`` (D, W) [W m⁻² sr⁻¹ nm⁻¹], with the surface terms.

    The coefficients with Q, the surface's reflection of the actual upwelling and the beam source
    refitted under the column's sky (:func:`oceanrender.optics.streams.sunlit_coefficients`): the model that agrees with the renderer's flat deep sea within 3 %.
    """
    if "surface" not in column._coefficients:
        column._coefficients["surface"] = sunlit_coefficients(
            column.absorption, column.scattering, *column.phase, column.sun_irradiance, column.sky_irradiance,
            column.sun_zenith, column.n_water)
    co = column._coefficients["surface"]
    depth = np.where(np.isinf(depths), np.inf, np.maximum(depths, MIN_DEPTH_M))[:, None]
    light = four_flux(column.absorption, column.backscattering, column.sun_irradiance, column.sky_irradiance,
                      column.sun_zenith, depth, 0.0, np.zeros(1), b=column.scattering, n_water=column.n_water,
                      internal_reflection=True, coefficients=co)
    return light.L_u / column.n_water**2


def upwelling_radiance(column: WaterColumn, depths: ArrayLike, bottom_albedo: ArrayLike = 0.0
                       ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Spectral radiances of Eqs. 21–22 before Φ, just above the surface per unit transmittance.

    Parameters
    ----------
    column : WaterColumn
        Water IOPs and the sun and sky above it.
    depths : array_like (D,)
        Depths H of the water column, ≥ 0, ``inf`` for deep water [m]; 0 is
        evaluated at :data:`MIN_DEPTH_M`.
    bottom_albedo : array_like, () or (W,)
        Lambertian albedo R0(λ) of the bottom [-].

    Returns
    -------
    upwelling : ndarray (D, W)
        E_upwell(0⁻)/(π n²) [W m⁻² sr⁻¹ nm⁻¹]: the water-leaving radiance that
        T0 holds, before the (1 − F) of Eq. 20.
    bottom : ndarray (D, W)
        E_bottom(H)/(π n²) [W m⁻² sr⁻¹ nm⁻¹]: the radiance of a white
        Lambertian bottom seen from just above the surface through a
        non-attenuating column; T1 multiplies it by e^{−c l}.

    Notes
    -----
    The four-flux model (:func:`oceanrender.optics.fourflux.four_flux`) with
    internal reflection at the surface, as in ``oceanrender optics``, and the n²
    law. Without a phase function (``column.phase`` None): the fixed closure and
    Lambertian upwelling (Q = π), Eq. 21 as the dissertation writes it. With one
    (issue 19): the coefficients from the phase function; the water's own light
    (over a black bottom) leaves with the upwelling's own Q and surface reflection
    (3.6–5.8 sr, not π), and what a bottom of albedo R0 adds stays Lambertian (π).
    """
    depths = np.atleast_1d(np.asarray(depths, dtype=np.float64))
    if np.any(np.isnan(depths)) or np.any(depths < 0):
        raise ValueError("depths must be ≥ 0 [m] (inf for deep water)")
    albedo = np.asarray(bottom_albedo, dtype=np.float64)
    E_up, E_bottom = _column_light(column, depths, albedo)
    to_radiance = 1.0 / (np.pi * column.n_water**2)
    if column.phase is None:
        return E_up * to_radiance, E_bottom * to_radiance  # Eq. 21 of [1], with the n² law
    # The water's own light (black bottom) with the upwelling's own Q and surface reflection, as checked
    # against the renderer (docs/optics.md, rendered vs model); what the bottom adds stays Lambertian (π).
    E_black, _ = _column_light(column, depths, np.zeros_like(albedo))
    water = _water_own_radiance(column, depths)
    return water + (E_up - E_black) * to_radiance, E_bottom * to_radiance


def bake_T0(column: WaterColumn, phi: VisionState, depth: Axis, bottom_albedo: ArrayLike = 0.0
            ) -> NDArray[np.float64]:
    """T0(h) = Φ(E_upwell(h)/(π n²)) at the texels of ``depth`` (Eq. 21), shape (N_h, 3) [display-relative].

    Parameters
    ----------
    column : WaterColumn
        Optics of the water and the light above it.
    phi : VisionState
        Φ with its adaptation state.
    depth : Axis
        Depth axis h [m] (a rational axis reaches h = ∞ at its last texel).
    bottom_albedo : array_like, () or (W,)
        Reference bottom albedo R0(λ) [-].
    """
    upwelling, _ = upwelling_radiance(column, depth.values, bottom_albedo)
    return phi.spectra(upwelling, column.wavelengths)  # Eq. 21 of [1]


def bake_T1(column: WaterColumn, phi: VisionState, depth: Axis, path: Axis, bottom_albedo: ArrayLike = 0.0
            ) -> NDArray[np.float64]:
    """T1(h, l) = Φ(e^{−c l} E_bottom(h)/(π n²)) per unit bottom albedo (Eq. 21), shape (N_h, N_l, 3).

    Parameters
    ----------
    column : WaterColumn
        Optics of the water and the light above it.
    phi : VisionState
        Φ with its adaptation state.
    depth : Axis
        Depth axis h (rows) [m].
    path : Axis
        In-water path length axis l (columns) [m].
    bottom_albedo : array_like, () or (W,)
        Reference albedo R0(λ) of the column whose bottom irradiance is used [-].

    Notes
    -----
    The spectral sum over λ is one tensor contraction:
    XYZ(h, l) = K_m Σ_λ E_b(h, λ) e^{−c(λ) l} x̄(λ) Δλ, then Φ once.
    """
    _, bottom = upwelling_radiance(column, depth.values, bottom_albedo)
    lengths = path.values
    with np.errstate(invalid="ignore"):
        alpha = np.exp(-np.outer(lengths, column.attenuation))  # α_l = e^{−c l}, Eq. 21 of [1]
    alpha[np.isinf(lengths)] = 0.0
    step = _band_width(column.wavelengths)
    xyz_bar = np.asarray(colour.MSDS_CMFS[CIE1931][column.wavelengths], dtype=np.float64) * (K_M * step)
    weights = alpha[:, :, None] * xyz_bar[None, :, :]  # (L, W, 3)
    XYZ = np.einsum("hw,lwk->hlk", bottom, weights, optimize=True)
    return phi(XYZ)


def bake_fresnel(axis: Axis, n_water: float, gamma: float) -> NDArray[np.float64]:
    """Fresnel LUT over cos θ_i (air → water): channels F and F^γ, shape (N, 2) [-].

    Parameters
    ----------
    axis : Axis
        Linear axis of μ = cos θ_i over [0, 1].
    n_water : float
        Refractive index of the water [-].
    gamma : float
        Exponent γ of the corrected weight F^γ (Eq. 20) [-].
    """
    mu = np.clip(axis.values, 0.0, 1.0)
    F = reflectance_Fresnel(mu, N_AIR, n_water)
    return np.stack([F, fresnel_correction(F, gamma)], axis=-1)  # Eq. 20 of [1]


def envmap_directions(width: int, height: int) -> NDArray[np.float64]:
    """World directions (height, width, 3) at the texel centres of a latitude–longitude map.

    u = φ/2π with φ the azimuth clockwise from north (+y) towards east (+x),
    v = θ/π with θ the angle from the zenith (+z); texel (i, j) is centred at
    u = (i + ½)/width, v = (j + ½)/height (Blinn & Newell 1976).
    """
    phi = 2.0 * np.pi * (np.arange(width) + 0.5) / width
    theta = np.pi * (np.arange(height) + 0.5) / height
    s = np.sin(theta)[:, None]
    return np.stack(np.broadcast_arrays(s * np.sin(phi)[None, :], s * np.cos(phi)[None, :],
                                        np.cos(theta)[:, None]), axis=-1)


def direction_to_envmap_uv(directions: ArrayLike) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """(u, v) in [0, 1] of unit world directions (..., 3) in the map of :func:`envmap_directions`."""
    d = np.asarray(directions, dtype=np.float64)
    u = np.mod(np.arctan2(d[..., 0], d[..., 1]) / (2.0 * np.pi), 1.0)
    v = np.arccos(np.clip(d[..., 2], -1.0, 1.0)) / np.pi
    return u, v


def bake_sky(radiance: ArrayLike, wavelengths: ArrayLike, phi: VisionState) -> NDArray[np.float64]:
    """Sky map Φ(L_sky), (height, width, 3), from spectral radiance (height, width, W) [W m⁻² sr⁻¹ nm⁻¹]."""
    return phi.spectra(radiance, wavelengths)


@dataclass(frozen=True, eq=False)
class RippleMaps:
    """Tileable ripple maps of one stochastic sea patch.

    Attributes
    ----------
    normals : ndarray (N, N, 3)
        Unit surface normals (x east, y north, z up) [-]; row j is y_j, column i is x_i.
    offsets : ndarray (N, N, 2)
        Texture-coordinate perturbation of the seafloor per unit depth
        (δx, δy) [m m⁻¹]: where a vertical view ray refracted by the ripple
        meets a bottom h metres down, relative to a level surface, divided by h.
    patch_size : float
        Side of the periodic tile [m].
    mean_square_slope : float
        ⟨s_x² + s_y²⟩ of the patch [-].
    expected_mean_square_slope : float
        Σ k² Ψ(k) Δk² of the band the patch carries [-].
    """

    normals: NDArray[np.float64]
    offsets: NDArray[np.float64]
    patch_size: float
    mean_square_slope: float
    expected_mean_square_slope: float


def bake_ripples(spectrum, patch_size: float, resolution: int, k_min: float, n_water: float, seed: int = 1
                 ) -> RippleMaps:
    """Ripple normal map and seafloor texture-coordinate perturbation from an FFT sea patch.

    Parameters
    ----------
    spectrum : callable
        Directional wavenumber spectrum Ψ(kx, ky) [m⁴] (the scene's [ocean] spectrum).
    patch_size : float
        Side L of the periodic (tileable) patch [m].
    resolution : int
        Texels N per side (even).
    k_min : float
        Smallest wavenumber kept [rad m⁻¹]: waves longer than 2π/k_min are in
        the geometry already (the ripples are the unresolved waves).
    n_water : float
        Refractive index of the water [-].
    seed : int
        Seed of the random amplitudes.

    Notes
    -----
    Heights only (no choppy displacement): the maps are a height field
    η(x, y) of Tessendorf's (2001) FFT sea with the spectrum band-limited to
    |k| ≥ k_min; normals n ∝ (−∂η/∂x, −∂η/∂y, 1). The perturbation refracts
    the vertical view ray (0, 0, −1) through n (Snell's law, air → water) and
    records (t_x, t_y)/|t_z|, the horizontal drift per metre of depth. For an
    oblique view the same offset is the first-order (small-slope) change of
    the drift and is added to the level-surface refraction.
    """
    from ..waves.cascades import BandLimitedSpectrum  # noqa: PLC0415
    from ..waves.fft_ocean import FFTOcean, OceanGrid  # noqa: PLC0415

    grid = OceanGrid(int(resolution), float(patch_size))
    band = BandLimitedSpectrum(spectrum, float(k_min), np.inf, grid.dk)
    # NOTE: one frame only: numpy (no numba compilation) is the faster engine here.
    ocean = FFTOcean(grid, seed=int(seed), choppiness=0.0, dtype=np.float64, spectrum_function=band, engine="numpy")
    fields = ocean.fields(0.0)
    sx, sy = np.array(fields.slope_x), np.array(fields.slope_y)
    normals = np.stack([-sx, -sy, np.ones_like(sx)], axis=-1)
    normals /= np.linalg.norm(normals, axis=-1, keepdims=True)
    down = np.broadcast_to(np.array([0.0, 0.0, -1.0]), normals.shape)
    t = refract(down, normals, N_AIR / n_water)
    offsets = t[..., :2] / np.abs(t[..., 2:3])
    psi = ocean.spectrum_values * grid.mode_mask
    expected = float(np.sum(grid.k**2 * psi) * grid.dk**2)  # slope spectrum k²Ψ (Phillips 1977, §4.7)
    return RippleMaps(normals=normals, offsets=offsets, patch_size=float(patch_size),
                      mean_square_slope=float(np.mean(sx**2 + sy**2)), expected_mean_square_slope=expected)


def irradiance_display_rgb(irradiance: ArrayLike, wavelengths: ArrayLike, phi: VisionState) -> NDArray[np.float64]:
    """Φ(E/π): display RGB of a white Lambertian surface under irradiance E(λ) [W m⁻² nm⁻¹] → (3,)."""
    return phi.spectra(np.asarray(irradiance, dtype=np.float64) / np.pi, wavelengths)


def albedo_display_rgb(reflectance: ArrayLike, irradiance: ArrayLike, wavelengths: ArrayLike, phi: VisionState
                       ) -> NDArray[np.float64]:
    """An albedo in display RGB: Φ(R E/π) ⊘ Φ(E/π) under the illuminant E [-], shape (..., 3).

    Parameters
    ----------
    reflectance : array_like (..., W)
        Spectral albedo R(λ) in [0, 1] [-].
    irradiance : array_like (W,)
        The illuminant, e.g. the horizontal sun + sky irradiance [W m⁻² nm⁻¹].
    wavelengths : array_like (W,)
        [nm].
    phi : VisionState
        Φ with its adaptation state.

    Notes
    -----
    A white albedo maps to (1, 1, 1) in every channel, so T1 ∘ R_rgb is T1's
    light coloured by the albedo as the viewer sees it under the scene's own
    light — the channel-wise product that Eq. 22 uses instead of the spectral
    product R(λ) E(λ) (exact for grey albedos).
    """
    E = np.asarray(irradiance, dtype=np.float64)
    white = irradiance_display_rgb(E, wavelengths, phi)
    return phi.spectra(np.asarray(reflectance, dtype=np.float64) * E / np.pi, wavelengths) / white
