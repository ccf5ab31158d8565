"""Path-traced reference views for shader validation, and the real-time model's error against them.

:class:`ReferenceRenderer` holds one loaded Mitsuba scene (a
:class:`~oceanrender.pipeline.Sequence`: the same geometry, camera, water,
sun and sky as ``oceanrender render``) and gives, per frame, the path-traced
absolute XYZ and the G-buffer of the same view (:mod:`.gbuffer`).
:func:`compare_frame` applies Φ with the LUT set's adaptation state to the
reference, shades the G-buffer with the real-time model (:mod:`.model`) and
returns the per-pixel CIEDE2000 map with its statistics (:mod:`.compare`).
"""

from __future__ import annotations

from collections.abc import Callable

from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from ..optics.scene_water import water_ior
from ..pipeline import Sequence, adaptation_luminance, vision_for_scene
from ..scene import Scene
from ..surface.open_sea import FrameGeometry
from ..vision.brightness import adaptation_luminance_log_average
from .bake import LutSet
from .compare import ErrorStats, delta_E_2000, error_stats
from .gbuffer import GBuffer, camera_for_scene, trace_gbuffer
from .luts import VisionState
from .model import RealtimeTerms, realtime_terms

__all__ = ["ReferenceRenderer", "scene_adaptation", "vision_state", "FrameComparison", "compare_frame",
           "reference_noise", "reference_report", "NOISE_SEED_OFFSET", "REPORT_FILES"]

#: Seed offset of the second, independent reference render that measures the path tracer's noise.
NOISE_SEED_OFFSET = 104729


class ReferenceRenderer:
    """Reference frames and G-buffers of a scene from one loaded Mitsuba scene (needs an active variant).

    Parameters
    ----------
    scene : Scene
        The scene.
    variant : str
        The active Mitsuba variant.
    spp, resolution : optional
        Samples per pixel and (width, height); the scene's by default.
    first_frame : int, optional
        Frame whose geometry the scene is loaded with.
    coastal_store : path, optional
        The stored simulation fields of a coastal scene.
    """

    def __init__(self, scene: Scene, variant: str, spp: int | None = None, resolution: tuple[int, int] | None = None,
                 first_frame: int | None = None, coastal_store: str | Path | None = None):
        self.scene = scene
        self.sequence = Sequence(scene, variant, spp=spp, resolution=resolution, first_frame=first_frame,
                                 coastal_store=coastal_store)
        self.camera = camera_for_scene(scene.camera, self.sequence.resolution)
        self.loaded: int | None = None
        self.geometry: FrameGeometry | None = None

    @property
    def white_XYZ(self) -> NDArray[np.float64]:
        """Adapting white of the scene [cd m⁻²] (measured once by the sequence)."""
        return np.asarray(self.sequence.white_xyz, dtype=np.float64)

    @property
    def faces(self) -> NDArray:
        return self.sequence.faces

    def load(self, frame: int) -> FrameGeometry:
        """Put the frame's water body into the loaded scene (vertex update, no reload)."""
        if self.loaded != frame:
            self.geometry = self.sequence.geometry(frame)
            self.sequence.renderer.update_water(self.geometry)
            self.loaded = frame
        return self.geometry

    def render_xyz(self, frame: int, seed_offset: int = 0, denoise: bool = False) -> tuple[NDArray[np.float64], int]:
        """Path-traced absolute XYZ (H, W, 3) [cd m⁻²] of a frame and its count of repaired pixels.

        The seed is the renderer's (scene seed + frame) plus ``seed_offset``;
        ``denoise``: Intel Open Image Denoise on the colour alone
        (:func:`oceanrender.render.denoise.denoise_XYZ`).
        """
        from ..render.denoise import denoise_XYZ  # noqa: PLC0415

        self.load(frame)
        seed = self.scene.render.seed + frame + seed_offset
        xyz, repaired = self.sequence.renderer.render_xyz(self.sequence.spp, seed=seed)
        return (denoise_XYZ(xyz) if denoise else xyz), repaired

    def gbuffer(self, frame: int) -> GBuffer:
        """The frame's G-buffer, cast into the same scene the reference was rendered from."""
        self.load(frame)
        bottom = "terrain" if self.scene.coastal is not None else None
        return trace_gbuffer(self.sequence.renderer.scene, self.camera, water_ior(self.scene), bottom_id=bottom)


def scene_adaptation(scene: Scene, reference_xyz: NDArray, white_XYZ: NDArray) -> tuple[float, str]:
    """L_wa [cd m⁻²] of Φ for the LUTs and the references, and a note of where it comes from.

    The scene's ``[vision] adaptation_luminance``; for ``"frame"`` the
    log-average of ``reference_xyz``, the reference frame.
    """
    value = adaptation_luminance(scene, reference_xyz, white_XYZ)
    setting = scene.vision.adaptation_luminance
    if setting == "frame":
        source = "log-average luminance of the path-traced reference frame (scene: adaptation_luminance = 'frame')"
    elif setting == "daylight":
        source = "0.18 x the adapting white's luminance (scene: adaptation_luminance = 'daylight')"
    else:
        source = "fixed by the scene's [vision] adaptation_luminance"
    return value, source


def vision_state(scene: Scene, luts: LutSet) -> VisionState:
    """Φ with the LUT set's adaptation state (adapting white and L_wa from its sidecar)."""
    vision = luts.constants["vision"]
    return VisionState(vision_for_scene(scene), np.asarray(vision["adapting_white_XYZ_cd_m2"], dtype=np.float64),
                       float(vision["adaptation_luminance_cd_m2"]))


@dataclass(frozen=True, eq=False)
class FrameComparison:
    """A reference view against the real-time model.

    Attributes
    ----------
    reference_rgb : ndarray (H, W, 3)   Φ's linear stage of the reference XYZ (before the display response).
    terms : RealtimeTerms               The real-time model's per-pixel terms.
    gamma : float                       γ of ``realtime_rgb`` [-].
    realtime_rgb : ndarray (H, W, 3)    The real-time image at γ.
    delta_E : ndarray (H, W)            CIEDE2000 per pixel.
    water : ErrorStats                  Over the water pixels.
    all : ErrorStats                    Over every pixel (sky and land included).
    frame_adaptation : float            The frame's own log-average luminance [cd m⁻²] (for the record).
    adaptation_luminance : float        L_wa of Φ used for the reference (the LUTs') [cd m⁻²].
    display : callable                  Φ's display response (identity for the linear operators).
    """

    reference_rgb: NDArray[np.float64]
    terms: RealtimeTerms
    gamma: float
    realtime_rgb: NDArray[np.float64]
    delta_E: NDArray[np.float64]
    water: ErrorStats
    all: ErrorStats
    frame_adaptation: float
    adaptation_luminance: float
    display: Callable[[NDArray], NDArray] = staticmethod(np.asarray)

    def at(self, gamma: float) -> "FrameComparison":
        """The same comparison for another γ (ΔE between the two images as displayed, after Φ's response)."""
        rgb = self.terms.image(gamma)
        dE = delta_E_2000(self.display(rgb), self.display(self.reference_rgb))
        return FrameComparison(self.reference_rgb, self.terms, float(gamma), rgb, dE,
                               error_stats(dE, self.terms.water), error_stats(dE), self.frame_adaptation,
                               self.adaptation_luminance, self.display)


def compare_frame(reference_xyz: NDArray, gbuffer: GBuffer, luts: LutSet, phi: VisionState,
                  gamma: float | None = None, fresnel: str = "lut") -> FrameComparison:
    """Φ of the reference, the real-time image of the same view, and their ΔE2000 map.

    Parameters
    ----------
    reference_xyz : ndarray (H, W, 3)
        Path-traced absolute XYZ [cd m⁻²].
    gbuffer : GBuffer
        The same view's G-buffer.
    luts : LutSet
        Baked textures.
    phi : VisionState
        Φ with the LUTs' adaptation state (:func:`vision_state`).
    gamma : float, optional
        γ of Eq. 20; the LUT set's by default.
    fresnel : str
        ``"lut"`` or ``"exact"`` (:func:`oceanrender.realtime.model.realtime_terms`).
    """
    reference_rgb = phi(reference_xyz)
    terms = realtime_terms(gbuffer, luts, fresnel)
    own = adaptation_luminance_log_average(np.asarray(reference_xyz)[..., 1])
    base = FrameComparison(reference_rgb, terms, 0.0, reference_rgb, np.zeros(gbuffer.shape), error_stats([]),
                           error_stats([]), own, phi.adaptation_luminance, phi.display)
    return base.at(luts.gamma if gamma is None else float(gamma))


def reference_noise(renderer: ReferenceRenderer, frame: int, comparison: FrameComparison, phi: VisionState,
                    denoise: bool = False) -> dict:
    """ΔE2000 between the frame's reference and a second render with an independent seed (the path tracer's noise).

    ``denoise``: the second render is denoised as the reference was.
    """
    second, _ = renderer.render_xyz(frame, seed_offset=NOISE_SEED_OFFSET, denoise=denoise)
    dE = delta_E_2000(phi.display(phi(second)), phi.display(comparison.reference_rgb))
    return {"frame": frame, "seed_offset": NOISE_SEED_OFFSET, "denoised": bool(denoise),
            "water": error_stats(dE, comparison.terms.water).describe(), "all": error_stats(dE).describe()}


#: What each file of a reference set holds (copied into its report).
REPORT_FILES = {
    "reference_NNNN.exr/png": "path-traced reference: XYZ (absolute) and RGB after the vision model (the LUTs' "
                              "adaptation state)",
    "realtime_NNNN.exr/png": "real-time model (Eqs. 20, 22 and the sun glint) at the LUTs' gamma",
    "realtime_fitted_NNNN.exr/png": "real-time model at the fitted gamma",
    "delta_e_NNNN.exr": "channels dE_before, dE_after (CIEDE2000) and water (mask)",
    "delta_e_NNNN.png / delta_e_fitted_NNNN.png": "dE2000 before / after the fit, magma colour map 0-20",
    "gbuffer_NNNN.exr": "per-pixel G-buffer (channel meanings in its header)",
    "camera_NNNN.json": "camera position, orientation, fov, resolution, pixel rays",
    "water_NNNN.ply": "the frame's closed water body mesh",
    "luts/": "the LUT set (when baked by this command)",
}


def reference_report(scene: Scene, frames: tuple[int, int], identity: dict, luts_folder, phi: VisionState,
                     luts: LutSet, fit, before: dict, after: dict, repaired: dict, noise: dict | None) -> dict:
    """The JSON-ready report of a reference set: settings, the γ fit, per-frame statistics, noise, files."""
    from .. import __version__  # noqa: PLC0415

    per_frame = [{"frame": frame, "time_s": frame / scene.output.fps,
                  "frame_log_average_cd_m2": before[frame].frame_adaptation, "repaired_pixels": repaired[frame],
                  "before": {"gamma": before[frame].gamma, "water": before[frame].water.describe(),
                             "all": before[frame].all.describe()},
                  "after": {"gamma": after[frame].gamma, "water": after[frame].water.describe(),
                            "all": after[frame].all.describe()}} for frame in before]
    width, height = (int(v) for v in identity["resolution"].split("x"))
    return {"scene": scene.name, "frames": list(frames), "resolution": [width, height], "spp": identity["spp"],
            "denoised": bool(identity.get("denoised", False)), "variant": identity["variant"],
            "oceanrender_version": __version__, "luts": str(luts_folder),
            "adaptation_luminance_cd_m2": phi.adaptation_luminance,
            "adaptation_source": luts.constants["vision"]["adaptation_source"], "gamma_fit": fit.describe(),
            "per_frame": per_frame, "reference_noise": noise, "files": REPORT_FILES}
