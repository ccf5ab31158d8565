"""Grade a fragment shader against a reference set: its images, ΔE2000 maps, statistics, worst regions, γ fit.

A reference set (``oceanrender reference``) holds, per frame, the
path-traced reference after the vision model Φ (``reference_NNNN.exr``, RGB
= Φ's linear stage), the G-buffer of the same view and its camera, and the
LUT set. :func:`validate_shader` runs the shader on every frame's G-buffer
(:mod:`.glsl`), compares its image with the reference as displayed
(Φ's display response, clipped, CIELAB, CIEDE2000: :mod:`.compare`), and also
with the numpy model of :mod:`.model` on the same inputs (ripples included),
which checks the shader's arithmetic separately from the model's physics.

The γ of Eq. 20 is fitted for the shader itself: the shader is run again
with ``u_gamma`` set to each γ of the search of
:func:`.gamma_fit.minimise_log_gamma` (a shader that ignores the uniform
gets a flat curve, reported as such).
"""

from __future__ import annotations

import hashlib
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from ..vision.model import VisionModel
from .bake import LutSet
from .compare import ErrorStats, delta_E_2000, error_stats
from .gamma_fit import minimise_log_gamma
from .gbuffer import KIND_WATER, GBuffer
from .glsl import GLContext, Texture, gbuffer_textures
from .luts import VisionState
from .model import RippleView, render_realtime
from .ripples import RipplePyramids, pixel_angle, ripple_pyramids

__all__ = ["vision_from_constants", "lut_pyramids", "lut_textures", "source_digest", "shader_uniforms", "ReferenceView", "ReferenceSet",
           "read_reference_set", "ShaderRunner", "worst_regions", "FrameGrade", "grade_frame", "ShaderGrade",
           "validate_shader", "GAMMA_BOUNDS"]

#: Search interval of the shader's γ fit [-] (as ``oceanrender reference``'s).
GAMMA_BOUNDS = (0.1, 10.0)


def vision_from_constants(constants: dict) -> VisionState:
    """Φ with the adaptation state a LUT set was baked for (``luts.json`` → ``constants["vision"]``)."""
    v = constants["vision"]
    model = VisionModel(brightness=v["brightness_operator"], chromatic_transform=v["chromatic_transform"],
                        display_max_luminance=float(v["display_luminance_cd_m2"]), exposure=float(v["exposure_EV"]))
    return VisionState(model, np.asarray(v["adapting_white_XYZ_cd_m2"], dtype=np.float64),
                       float(v["adaptation_luminance_cd_m2"]))


def lut_pyramids(luts: LutSet) -> RipplePyramids:
    """The ripple maps of a LUT set as mip pyramids (:func:`.ripples.ripple_pyramids`)."""
    tile = luts["ripple_normals"].parameters["tile"]
    return ripple_pyramids(luts["ripple_normals"].data, luts["ripple_offsets"].data, float(tile["patch_size_m"]))


def lut_textures(luts: LutSet, pyramids: RipplePyramids) -> dict[str, Texture]:
    """The LUTs as the shader's textures: bilinear, clamped (the sky wraps in u), ripples mipmapped and repeating."""
    textures = {"lut_T0": Texture(luts["T0"].data), "lut_T1": Texture(luts["T1"].data),
                "lut_fresnel": Texture(luts["fresnel"].data), "lut_sky": Texture(luts["sky"].data, repeat=(True, False)),
                "ripple_moments": Texture(pyramids.moments[0], repeat=(True, True), levels=tuple(pyramids.moments[1:])),
                "ripple_offsets": Texture(pyramids.offsets[0], repeat=(True, True), levels=tuple(pyramids.offsets[1:]))}
    if "seafloor" in luts.luts:
        textures["lut_seafloor"] = Texture(luts["seafloor"].data)
    return textures


def shader_uniforms(luts: LutSet, pyramids: RipplePyramids, angle: float, gamma: float, strength: float,
                    glint: bool = True) -> dict:
    """The uniforms of the shader interface (shaders/water.frag) for one view."""
    c = luts.constants
    has_sand_rock = c.get("sand_albedo_rgb") is not None and c.get("rock_albedo_rgb") is not None
    seafloor = luts.luts.get("seafloor")
    extent = (0.0, 1.0, 0.0, 1.0) if seafloor is None else (seafloor.columns.lo, seafloor.columns.hi,
                                                            seafloor.rows.lo, seafloor.rows.hi)

    def rgb(key: str) -> tuple[float, float, float]:
        value = c.get(key)
        return (0.0, 0.0, 0.0) if value is None else tuple(float(v) for v in value)

    return {"u_depth_scale": float(luts["T0"].columns.scale), "u_path_scale": float(luts["T1"].columns.scale),
            "u_has_seafloor": int(seafloor is not None), "u_seafloor_extent": tuple(float(v) for v in extent),
            "u_has_sand_rock": int(has_sand_rock), "u_reference_albedo": rgb("reference_albedo_rgb"),
            "u_sand_albedo": rgb("sand_albedo_rgb"), "u_rock_albedo": rgb("rock_albedo_rgb"),
            "u_gamma": float(gamma), "u_n_water": float(luts.n_water),
            "u_alpha": float(c["surface_roughness_alpha"]), "u_sun_direction": rgb("sun_direction"),
            "u_sun_rgb": rgb("sun_irradiance_rgb"), "u_sky_rgb": rgb("sky_irradiance_rgb"), "u_glint": int(glint),
            "u_masking": 1, "u_has_foam": int(c.get("foam_albedo_rgb") is not None), "u_foam_albedo": rgb("foam_albedo_rgb"),
            "u_ripple_patch": float(pyramids.patch_size), "u_ripple_strength": float(strength),
            "u_ripple_mss": float(pyramids.mean_square_slope), "u_pixel_angle": float(angle)}


@dataclass(frozen=True, eq=False)
class ReferenceView:
    """One frame of a reference set: Φ's linear stage of the reference, its G-buffer, its pixel angle [rad]."""

    frame: int
    reference_rgb: NDArray[np.float64]
    gbuffer: GBuffer
    pixel_angle: float


@dataclass(frozen=True, eq=False)
class ReferenceSet:
    """A reference set read back: its frames, LUTs, report (for the noise floor) and Φ."""

    folder: Path
    views: list[ReferenceView]
    luts: LutSet
    luts_folder: Path
    report: dict
    phi: VisionState


def read_reference_set(folder: str | Path, luts_folder: str | Path | None = None) -> ReferenceSet:
    """Read every frame of a reference set written by ``oceanrender reference``.

    Raises ValueError ("<path>: <problem>") for a folder that is not a
    reference set or misses a frame's file.
    """
    from .files import read_exr, read_gbuffer, read_json, read_lut_set  # noqa: PLC0415

    folder = Path(folder)
    report_path = folder / "report.json"
    if not report_path.is_file():
        raise ValueError(f"{folder}: no report.json (not a reference set: run `oceanrender reference` first)")
    report = read_json(report_path)
    luts_folder = Path(luts_folder) if luts_folder is not None else (
        folder / "luts" if (folder / "luts" / "luts.json").is_file() else Path(report["luts"]))
    if not (luts_folder / "luts.json").is_file():
        raise ValueError(f"{luts_folder}: no luts.json (give the LUT folder with --luts)")
    luts = read_lut_set(luts_folder)
    views = []
    for frame in range(*report["frames"]):
        paths = {key: folder / f"{key}_{frame:04d}.{ext}"
                 for key, ext in (("reference", "exr"), ("gbuffer", "exr"), ("camera", "json"))}
        for path in paths.values():
            if not path.is_file():
                raise ValueError(f"{path}: missing (frame {frame} of the reference set)")
        channels, _ = read_exr(paths["reference"])
        rgb = np.stack([channels[c] for c in "RGB"], axis=-1).astype(np.float64)
        camera = read_json(paths["camera"])
        width = int(camera["resolution"][0])
        views.append(ReferenceView(frame, rgb, read_gbuffer(paths["gbuffer"]),
                                   pixel_angle(float(camera["fov_x_deg"]), width)))
    if not views:
        raise ValueError(f"{folder}: the reference set has no frames")
    return ReferenceSet(folder, views, luts, luts_folder, report, vision_from_constants(luts.constants))


class ShaderRunner:
    """A compiled shader with the LUT textures of a reference set: images of its views at any γ."""

    def __init__(self, context: GLContext, source: str, source_name: str, luts: LutSet, strength: float,
                 glint: bool = True):
        self.context = context
        self.program = context.program(source, source_name)
        self.luts = luts
        self.pyramids = lut_pyramids(luts)
        # Uploaded once: the γ fit draws every view some 35 times with the same textures.
        self.textures = {name: context.upload(t) for name, t in lut_textures(luts, self.pyramids).items()}
        self._views: dict[ReferenceView, dict] = {}
        self.strength = float(strength)
        self.glint = glint

    def _gbuffer(self, view: ReferenceView) -> dict:
        """The view's G-buffer textures, uploaded on its first draw."""
        if view not in self._views:
            self._views[view] = {name: self.context.upload(t) for name, t in gbuffer_textures(view.gbuffer).items()}
        return self._views[view]

    def release(self) -> None:
        """Free the uploaded textures (the context stays)."""
        for texture in [*self.textures.values(), *(t for v in self._views.values() for t in v.values())]:
            texture.release()
        self.textures, self._views = {}, {}

    def image(self, view: ReferenceView, gamma: float) -> NDArray[np.float64]:
        """The shader's output rgb (H, W, 3) for a view, float64."""
        height, width = view.gbuffer.shape
        textures = {**self.textures, **self._gbuffer(view)}
        uniforms = shader_uniforms(self.luts, self.pyramids, view.pixel_angle, gamma, self.strength, self.glint)
        return self.context.render(self.program, (width, height), textures, uniforms)[..., :3].astype(np.float64)

    def model(self, view: ReferenceView, gamma: float) -> NDArray[np.float64]:
        """The numpy model of the same inputs (:func:`.model.render_realtime`, ripples at the same strength)."""
        ripples = RippleView(self.pyramids, self.strength, view.pixel_angle)
        return render_realtime(view.gbuffer, self.luts, gamma, "lut", self.glint, ripples)


def worst_regions(delta_E: NDArray, water: NDArray, gbuffer: GBuffer, count: int = 5, tile: int | None = None
                  ) -> list[dict]:
    """The ``count`` square tiles of highest mean ΔE, with where they are and what they show.

    ``tile``: side in pixels (default: the image's shorter side / 9, at
    least 4). Each entry: the pixel rectangle [x0, y0, x1, y1) (x right, y
    down), mean and max ΔE, the share of water pixels, the mean view angle
    [deg] and median distance [m] of its hits.
    """
    height, width = delta_E.shape
    side = tile or max(4, min(height, width) // 9)
    entries = []
    for y0 in range(0, height, side):
        for x0 in range(0, width, side):
            block = (slice(y0, min(y0 + side, height)), slice(x0, min(x0 + side, width)))
            values = delta_E[block]
            hits = np.isfinite(gbuffer.distance[block])
            entries.append({"rect_px": [x0, y0, min(x0 + side, width), min(y0 + side, height)],
                            "mean": float(np.mean(values)), "max": float(np.max(values)),
                            "water_share": float(np.mean(water[block])),
                            "view_angle_deg": float(np.mean(gbuffer.view_angle[block][hits])) if hits.any() else None,
                            "distance_m": float(np.median(gbuffer.distance[block][hits])) if hits.any() else None})
    entries.sort(key=lambda e: -e["mean"])
    return entries[:count]


@dataclass(frozen=True, eq=False)
class FrameGrade:
    """One frame graded: images (linear display sRGB), ΔE maps and their statistics."""

    frame: int
    shader_rgb: NDArray[np.float64]
    model_rgb: NDArray[np.float64]
    delta_E_reference: NDArray[np.float64]
    delta_E_model: NDArray[np.float64]
    water: NDArray[np.bool_]
    regions: list[dict]

    def stats(self) -> dict:
        """Mean/p95/max over the water and over all pixels, against the reference and against the numpy model."""
        return {"shader_vs_reference": {"water": error_stats(self.delta_E_reference, self.water).describe(),
                                        "all": error_stats(self.delta_E_reference).describe()},
                "shader_vs_model": {"water": error_stats(self.delta_E_model, self.water).describe(),
                                    "all": error_stats(self.delta_E_model).describe()}}


def grade_frame(runner: ShaderRunner, view: ReferenceView, phi: VisionState, gamma: float) -> FrameGrade:
    """Run the shader and the numpy model on a view at γ and compare both as displayed."""
    shader = runner.image(view, gamma)
    model = runner.model(view, gamma)
    reference = phi.display(view.reference_rgb)
    dE_ref = delta_E_2000(phi.display(shader), reference)
    dE_model = delta_E_2000(phi.display(shader), phi.display(model))
    water = view.gbuffer.kind == KIND_WATER
    return FrameGrade(view.frame, shader, model, dE_ref, dE_model, water,
                      worst_regions(dE_ref, water, view.gbuffer))


@dataclass(frozen=True, eq=False)
class ShaderGrade:
    """A shader graded on a reference set.

    Attributes
    ----------
    frames : list of FrameGrade          At the LUT set's γ.
    gamma : float                        γ of ``frames`` [-].
    fitted_gamma : float                 γ minimising the shader's mean water ΔE against the references [-].
    before, after : ErrorStats           Water pixels of all frames at γ and at the fitted γ.
    model_vs_reference : ErrorStats      The numpy model's own water ΔE at γ (the baseline).
    shader_vs_model : ErrorStats         Water pixels of all frames, shader against the numpy model.
    all_vs_reference : ErrorStats        Every pixel of all frames (sky and land included), at γ.
    curve : tuple of (γ, mean ΔE)        The fit's grid.
    gamma_sensitive : bool               Whether the shader's image changes with ``u_gamma``.
    """

    frames: list[FrameGrade]
    gamma: float
    fitted_gamma: float
    before: ErrorStats
    after: ErrorStats
    model_vs_reference: ErrorStats
    shader_vs_model: ErrorStats
    all_vs_reference: ErrorStats
    curve: tuple[tuple[float, float], ...]
    gamma_sensitive: bool


def validate_shader(runner: ShaderRunner, references: ReferenceSet, gamma: float | None = None,
                    fit_grid: int = 21, progress: Callable[[str], None] | None = None) -> ShaderGrade:
    """Grade ``runner``'s shader on every frame of ``references`` and fit its γ (module docstring)."""
    phi = references.phi
    gamma = references.luts.gamma if gamma is None else float(gamma)
    frames = []
    for view in references.views:
        frames.append(grade_frame(runner, view, phi, gamma))
        if progress:
            progress(f"frame {view.frame}: shader vs reference dE2000 water mean "
                     f"{error_stats(frames[-1].delta_E_reference, frames[-1].water).mean:.2f}, "
                     f"shader vs numpy model {error_stats(frames[-1].delta_E_model, frames[-1].water).mean:.3f}")
    displayed = [phi.display(view.reference_rgb) for view in references.views]

    def water_dE(g: float) -> NDArray:
        return np.concatenate([delta_E_2000(phi.display(runner.image(view, g)), ref)[view.gbuffer.kind == KIND_WATER]
                               for view, ref in zip(references.views, displayed)])

    def cost(g: float) -> float:
        values = water_dE(g)
        return float(np.mean(values)) if values.size else 0.0

    fitted, curve = minimise_log_gamma(cost, GAMMA_BOUNDS, fit_grid, 1e-3)
    costs = [value for _, value in curve]
    sensitive = bool(np.ptp(costs) > 1e-6)
    if not sensitive:
        fitted = gamma
    model_dE = np.concatenate([delta_E_2000(phi.display(f.model_rgb), ref)[f.water] for f, ref in zip(frames, displayed)])
    return ShaderGrade(frames=frames, gamma=gamma, fitted_gamma=fitted,
                       before=error_stats(np.concatenate([f.delta_E_reference[f.water] for f in frames])),
                       after=error_stats(water_dE(fitted)), model_vs_reference=error_stats(model_dE),
                       shader_vs_model=error_stats(np.concatenate([f.delta_E_model[f.water] for f in frames])),
                       all_vs_reference=error_stats(np.concatenate([f.delta_E_reference.ravel() for f in frames])),
                       curve=curve, gamma_sensitive=sensitive)


def source_digest(source: str) -> str:
    """SHA-256 of a shader's source text (recorded in the report)."""
    return hashlib.sha256(source.encode("utf-8")).hexdigest()
