"""The sequence runner: scene → geometry → Mitsuba → vision model → files.

Stages are pure functions in their sub-packages; this module strings them
together for a frame range, does the file I/O and reports timings. The
Mitsuba variant must already be active (the CLI activates it).
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

import numpy as np

from . import __version__
from .io.frames import frame_is_complete, write_exr, write_png
from .io.paths import remove_stale_temporaries
from .optics.scene_water import water_optics
from .render.renderer import WaterRenderer, adapting_white_XYZ
from .scene import Scene
from .surface.bodies import scene_water_body, sun_lobe_alpha, surface_roughness
from .surface.frame import FIELD_KEYS, FrameError, FrameGeometry
from .vision.brightness import adaptation_luminance_log_average
from .vision.display import encode_sRGB_8bit
from .vision.model import VisionModel
from .vision.temporal import adaptation_window, adapted_luminance

#: Stages timed per frame, in order.
STAGES = ("meter", "geometry", "update", "render", "denoise", "vision", "write")
#: Largest share of a frame's pixels that may come out of the renderer non-finite and be repaired from their
#: neighbours [-]: Mitsuba's volpath gives NaN in a handful of pixels now and then (../shared/NOTES.md); more
#: than this is a broken frame, not noise, and is not written.
REPAIR_SHARE = 1e-3


def check_geometry(geometry: FrameGeometry, frame: int, t: float) -> FrameGeometry:
    """``geometry`` if every field is finite; else :class:`FrameError` naming the field and the keys behind it."""
    bad = geometry.non_finite()
    if bad:
        name, count = next(iter(bad.items()))
        raise FrameError(f"frame {frame} (t = {t:g} s): stage geometry: {count} non-finite value(s) in the water's "
                         f"{name}, from {FIELD_KEYS[name]}; nothing of this frame is written")
    return geometry


def check_repaired(repaired: int, pixels: int, frame: int) -> None:
    """:class:`FrameError` when more than :data:`REPAIR_SHARE` of a frame's ``pixels`` were non-finite."""
    if repaired > REPAIR_SHARE * pixels:
        raise FrameError(f"frame {frame}: stage render: {repaired} of {pixels} pixels came out non-finite "
                         f"({repaired / pixels:.2%}, more than the {REPAIR_SHARE:.1%} repaired from their "
                         f"neighbours); the frame is not written: check the scene's [water], [composition] and "
                         f"[render] settings")


@dataclass(frozen=True)
class FramePaths:
    """Where one frame's files go."""

    exr: Path
    png: Path


def frame_paths(out_dir: str | Path, frame: int) -> FramePaths:
    """``<out_dir>/frame_NNNN.exr`` and ``.png``."""
    out_dir = Path(out_dir)
    return FramePaths(exr=out_dir / f"frame_{frame:04d}.exr", png=out_dir / f"frame_{frame:04d}.png")


#: ∫ȳ(λ) dλ of the CIE 1931 2° observer over 360–830 nm [nm].
INTEGRAL_YBAR_NM = 106.857


def white_mean_radiance(white_XYZ) -> float:
    """ȳ-weighted mean spectral radiance [W m⁻² sr⁻¹ nm⁻¹] of the adapting white: Y / (683 ∫ȳ dλ)."""
    return float(white_XYZ[1]) / (683.0 * INTEGRAL_YBAR_NM)


def vision_for_scene(scene: Scene) -> VisionModel:
    """The vision model Φ configured by the scene's ``[vision]`` section."""
    v = scene.vision
    return VisionModel(brightness=v.brightness, chromatic_transform=v.chromatic_transform,
                       display_max_luminance=v.display_luminance, exposure=v.exposure)


#: Blocks across the view of the adaptation meter [-] (rows in the frame's aspect: 80 × 45 at 16:9), see
#: :meth:`Sequence.meter`. A block is a fixed fraction of the view, so a preview and a final frame adapt alike.
METER_COLUMNS = 80

#: Samples per block and pass of the meter [-]: 32, so the log of a noisy block (Jensen) is within ~1 % of the
#: log of its mean; the eye's adaptation pools over a region, not a single receptor, anyway.
METER_SAMPLES = 32

#: Added to a frame's seed for its meter render, so meter and frame use independent samples [-].
METER_SEED_OFFSET = 1 << 30


def meter_samples(width: int, height: int) -> int:
    """Samples per pass of one meter reading of a ``width`` × ``height`` frame [-]."""
    from .render.pixels import grid_shape  # noqa: PLC0415

    rows, columns = grid_shape(width, height, METER_COLUMNS)
    return rows * columns * METER_SAMPLES


#: Reflectance of the grey card of ``adaptation_luminance = "daylight"`` [-]: the mid-grey to which
#: reflected-light meters are calibrated (ISO 2720:1974, K = 12.5 cd s m⁻² ISO⁻¹ ⇔ ≈ 18 %).
GREY_CARD_REFLECTANCE = 0.18


def adaptation_luminance(scene: Scene, xyz: np.ndarray, white_XYZ: np.ndarray | None = None) -> float:
    """World adaptation luminance [cd m⁻²].

    Fixed by the scene; ``"frame"``: the frame's log-average (Ward 1994);
    ``"daylight"``: an 18 % grey card under the scene's sun and sky,
    0.18 · Y_white (``white_XYZ``: the adapting white, a white Lambertian
    plane's XYZ [cd m⁻²]) — the state of a viewer outdoors, whose field of
    view holds sky and sunlit surroundings, not just the water in the frame.
    """
    value = scene.vision.adaptation_luminance
    if value == "frame":
        return adaptation_luminance_log_average(xyz[..., 1])
    if value == "daylight":
        if white_XYZ is None:
            raise ValueError("adaptation_luminance = 'daylight' needs the adapting white's XYZ")
        return GREY_CARD_REFLECTANCE * float(white_XYZ[1])
    return float(value)


@dataclass
class SequenceReport:
    """What a run did: frames rendered and skipped, seconds per stage."""

    variant: str
    rendered: list[int] = field(default_factory=list)
    skipped: list[int] = field(default_factory=list)
    repaired_pixels: int = 0
    setup_seconds: float = 0.0
    simulation: object = None  # coastal scenes: the SimulationReport of the run
    failed: list = field(default_factory=list)  # distributed runs: frames whose task failed on every try
    stage_seconds: dict[str, float] = field(default_factory=lambda: {s: 0.0 for s in STAGES})

    @property
    def frame_seconds(self) -> float:
        return sum(self.stage_seconds.values())


class Sequence:
    """A scene prepared for rendering frames: ocean, renderer, adapting white.

    Building it loads the Mitsuba scene once; :meth:`render_frame` then only
    updates the water mesh, and, in an animated scene (``[[camera.keys]]``,
    ``[[sun.keys]]`` or ``[sun.clock]``), points the camera and the sun for
    the frame's time (:meth:`point`): the sky's and the ``split``
    integrator's sun, the adapting white (re-measured in a white-plane scene
    kept loaded) and the in-water clamp, which is a multiple of that white.
    Nothing is reloaded or recompiled (the integrator's sun is opaque).
    """

    def __init__(self, scene: Scene, variant: str, spp: int | None = None, resolution: tuple[int, int] | None = None,
                 first_frame: int | None = None, coastal_store: str | Path | None = None):
        self.scene = scene
        self.variant = variant
        self.spp = int(spp or scene.output.spp)
        self.resolution = tuple(resolution or scene.output.resolution)
        self.body = scene_water_body(scene, coastal_store)
        self.faces = self.body.faces
        self.iops = water_optics(scene)
        first_frame = scene.output.frames[0] if first_frame is None else first_frame
        # A calm stand-in of the first frame's water loads the scene when the kernels can compile while the real
        # water is computed (_first_geometry); else the real one, computed now.
        stand_in = self._stand_in(first_frame)
        first = self.geometry(first_frame) if stand_in is None else stand_in
        self.roughness = surface_roughness(scene, self.body)
        self.sun_lobe_alpha = sun_lobe_alpha(scene, self.body, self.roughness)
        from .scene.motion import SunAngles, camera_motion, static_camera_pose, sun_motion  # noqa: PLC0415

        self.camera_path = camera_motion(scene)
        self.sun_path = sun_motion(scene)
        #: The camera pose and sun angles of the frame last pointed at (:meth:`point`).
        self.pose = static_camera_pose(scene)
        self.sun_angles = SunAngles(scene.sun.elevation, scene.sun.azimuth % 360.0)
        self.white_meter = None
        self._white_frame: int | None = None
        if self.sun_path is not None:
            from .render.renderer import WhiteMeter  # noqa: PLC0415

            self.white_meter = WhiteMeter(scene)
            self.sun_angles = self.sun_path.at(self.time_of(first_frame))
            self._measure_white(first_frame)
        else:
            self.white_xyz = adapting_white_XYZ(scene, seed=scene.render.seed)
        self.in_water_clamp = scene.render.in_water_clamp * white_mean_radiance(self.white_xyz)
        from .surface.objects import SceneObjects  # noqa: PLC0415

        self.objects = SceneObjects(scene, getattr(self.body, "sea", None))
        self.renderer = WaterRenderer.build(scene, self.iops, self.faces, first, roughness=self.roughness,
                                            in_water_clamp=self.in_water_clamp,
                                            sun_lobe_alpha=self.sun_lobe_alpha, terrain=self.body.terrain(),
                                            spp=self.spp, resolution=self.resolution,
                                            objects=self.objects.frame(self.time_of(first_frame)))
        self.vision = vision_for_scene(scene)
        if self.follows_adaptation:
            # NOTE: the meter's samplers made now, before any render: making Mitsuba objects adds instances to the
            # registries the kernels dispatch over, so a frame rendered before them would run another kernel than
            # one rendered after (other float round-off): a resumed run would then differ from a whole one.
            self.renderer.prepare_blocks()
        if stand_in is not None:
            first = self._first_geometry(first_frame)
            self.renderer.update_water(first)  # the scene holds the first frame, as when loaded with it
        # NOTE: the scene is loaded with this frame's geometry; compute_frame reuses it once.
        self._loaded: tuple[int, FrameGeometry] | None = (first_frame, first)
        self._meters: dict[int, float] = {}  # frame → its meter (log-average) [cd m⁻²]
        self._frame_geometry = None  # (frame, geometry) of the frame compute_frame is metering
        self._map_illuminance: float | None = None  # [lx], of an [environment] map, measured once

    def _stand_in(self, frame: int) -> FrameGeometry | None:
        """The body's calm stand-in for ``frame`` (``frame_layout``: the same arrays, the sea at rest), to load the
        scene with while the real water is computed beside the kernels' compilation (JIT variants); else None."""
        layout = getattr(self.body, "frame_layout", None)
        if layout is None or not self.variant.startswith(("llvm", "cuda")):
            return None
        return layout(self.time_of(frame))

    def _first_geometry(self, frame: int) -> FrameGeometry:
        """``frame``'s water, computed (numpy) while another thread compiles the frame's kernels and the meter's
        (:meth:`~oceanrender.render.renderer.WaterRenderer.compile_kernels_beside`; measured on the default
        scene with a cold kernel cache: ~18 s of compilation beside ~10 s of sea, BENCHMARKS.md)."""
        return self.renderer.compile_kernels_beside(lambda: self.geometry(frame), self.spp, self.follows_adaptation)

    def _measure_white(self, frame: int) -> None:
        """The adapting white [cd m⁻²] under the sun of ``frame`` (:attr:`sun_angles`), measured once per frame."""
        if self._white_frame != frame:
            self.white_meter.point_sun(*self.sun_angles)
            # Same seed every frame, as for a still sun: a frame's white depends on its time alone.
            self.white_xyz = self.white_meter.measure(seed=self.scene.render.seed)
            self._white_frame = frame

    def point(self, frame: int) -> None:
        """Pose the objects, point the camera and the sun at ``frame``'s time (animated scenes; else nothing).

        Moves the sensor (``apply_camera``), the ``sunsky`` sun and the
        ``split`` integrator's sun, re-measures the adapting white and sets
        the in-water clamp to ``render.in_water_clamp`` × that white's mean
        radiance. The water mesh follows the camera in :meth:`geometry`.
        """
        t = self.time_of(frame)
        if self.objects.items:
            self.renderer.update_objects(self.objects.frame(t))
        if self.camera_path is not None:
            self.pose = self.camera_path.at(t)
            self.renderer.point_camera(*self.pose)
        if self.sun_path is not None:
            self.sun_angles = self.sun_path.at(t)
            self._measure_white(frame)
            self.in_water_clamp = self.scene.render.in_water_clamp * white_mean_radiance(self.white_xyz)
            self.renderer.point_sun(*self.sun_angles)
            if self.in_water_clamp > 0:
                self.renderer.set_in_water_clamp(self.in_water_clamp)

    @property
    def follows_adaptation(self) -> bool:
        """Whether the adaptation luminance follows the view over time (``'frame'`` with ``adaptation_time`` > 0)."""
        vision = self.scene.vision
        return vision.adaptation_luminance == "frame" and vision.adaptation_time > 0

    def meter(self, frame: int) -> float:
        """Log-average luminance of ``frame``'s view [cd m⁻²], from a quick render of its own (cached).

        The mean luminance of each block of a :data:`METER_COLUMNS`-wide grid over the view, from
        :data:`METER_SAMPLES` samples per block at uniform positions in it (own seed;
        :meth:`~oceanrender.render.renderer.WaterRenderer.block_xyz`: one compiled kernel per pass,
        whatever the frame), then log-averaged. It depends on the frame number alone, so every
        process computes the same value.
        """
        if frame not in self._meters:
            known = [g for g in (self._frame_geometry, self._loaded) if g is not None and g[0] == frame]
            geometry = known[0][1] if known else self.geometry(frame)
            self.point(frame)
            # (the floor's map left out: the quick render's mean is the path tracer's alone, and a frame of the
            # window is not traced for a map it would use once; the frame's own render traces it)
            self.renderer.update_water(geometry, floor_map=False)
            xyz = self.renderer.block_xyz(METER_COLUMNS, METER_SAMPLES,
                                          seed=self.scene.render.seed + frame + METER_SEED_OFFSET)
            self._meters[frame] = adaptation_luminance_log_average(xyz[..., 1])
            self._loaded = (frame, geometry)
        return self._meters[frame]

    def followed_adaptation(self, frame: int) -> tuple[float, float]:
        """(adaptation luminance, its target) of ``frame`` [cd m⁻²] as the eye follows the view over time.

        The target is :meth:`meter` of the frame; the state is the
        exponential filter of :mod:`oceanrender.vision.temporal` run over the
        frames of :func:`~oceanrender.vision.temporal.adaptation_window` (at
        most 4 τ back, starting adapted), so it is a function of the frame
        number alone: frames stay independent, resumed runs identical.
        """
        vision, fps = self.scene.vision, self.scene.output.fps
        window = adaptation_window(frame, vision.adaptation_time, fps)
        # NOTE: the frame itself last, so its geometry is the one left loaded for its render.
        targets = {m: self.meter(m) for m in [*window[:-1], frame]}
        return adapted_luminance([targets[m] for m in window], 1.0 / fps, vision.adaptation_time), targets[frame]

    def time_of(self, frame: int) -> float:
        """Frame time t = frame / fps [s]."""
        return frame / self.scene.output.fps

    def geometry(self, frame: int) -> FrameGeometry:
        """The water body of a frame: vertex positions [m], normals, foam; :class:`FrameError` if not finite."""
        t = self.time_of(frame)
        return check_geometry(self.body.frame(t), frame, t)

    def metadata(self, frame: int, repaired: int, adaptation: float,
                 adaptation_target: float | None = None) -> dict[str, object]:
        import colour  # noqa: PLC0415
        import mitsuba  # noqa: PLC0415

        return {
            "scene": self.scene.name,
            "frame": frame,
            "time_s": self.time_of(frame),
            "spp": self.spp,
            "in_water_spp": (self.renderer.in_water_spp(self.spp)
                             if self.renderer.in_water is not None and not self.renderer.last_camera_in_water
                             else self.spp),
            "camera_in_water": bool(self.renderer.last_camera_in_water),
            "roulette_depth": self.scene.render.roulette_depth,
            "variant": self.variant,
            "oceanrender_version": __version__,
            "mitsuba_version": mitsuba.__version__,
            "colour_version": colour.__version__,
            "white_XYZ_cd_m2": " ".join(f"{v:.6g}" for v in self.white_xyz),
            "adaptation_luminance_cd_m2": adaptation,
            "adaptation": self._adaptation_label(adaptation_target),
            "brightness_operator": self.vision.brightness,
            "exposure_EV": self.vision.exposure,
            "chromatic_transform": self.vision.chromatic_transform,
            "display_luminance_cd_m2": self.vision.display_max_luminance,
            "surface_roughness_beckmann_alpha": self.roughness,
            "surface_roughness_per_vertex": self._roughness_label(),
            "sun_lobe_beckmann_alpha": self.sun_lobe_alpha if self.scene.render.sun_sampling else 0.0,
            "in_water_clamp_W_m2_sr_nm": self.in_water_clamp,
            "camera_position_m": " ".join(f"{v:.6g}" for v in self.pose.position),
            "camera_target_m": " ".join(f"{v:.6g}" for v in self.pose.target),
            "camera_fov_deg": f"{self.pose.fov:.6g}",
            "camera_motion": f"keys ({self.camera_path.interpolation})" if self.camera_path is not None else "still",
            "sun_elevation_deg": f"{self.sun_angles.elevation:.6g}",
            "sun_azimuth_deg": f"{self.sun_angles.azimuth:.6g}",
            "sun_motion": self._sun_motion_label(),
            "sky": self._sky_label(),
            "denoiser": self._denoiser_label(),
            "repaired_pixels": repaired,
            "channels": "XYZ absolute [cd/m2 for Y]; RGB linear sRGB after vision model [1 = display white]",
        }

    def _denoiser_label(self) -> str:
        render = self.scene.render
        if not render.denoise:
            return "none"
        label = "Intel Open Image Denoise (pyoidn), colour only, HDR"
        if render.chroma_radius > 0:
            label += f"; chromaticity averaged over {render.chroma_radius} px by denoised luminance"
        return label

    def _sky_label(self) -> str:
        """What lights the frame: sunsky, or the environment map with its scale and horizontal illuminance."""
        env = self.scene.environment
        if env is None:
            return "sunsky (Hosek-Wilkie)"
        from .render.environment import environment_scale, map_illuminance  # noqa: PLC0415

        if self._map_illuminance is None:  # the given illuminance is what the scale was set to give
            self._map_illuminance = env.illuminance or map_illuminance(env.map, environment_scale(self.scene))
        sun = " + sunsky's sun" if env.sun else ""
        return (f"environment map {Path(env.map).name} (scale {environment_scale(self.scene):.6g}, rotation "
                f"{env.rotation:g} deg; {self._map_illuminance:.6g} lx on a horizontal plane){sun}")

    def _adaptation_label(self, target: float | None) -> str:
        """How the adaptation luminance was set."""
        value = self.scene.vision.adaptation_luminance
        if target is not None:
            return (f"followed over time (tau = {self.scene.vision.adaptation_time:g} s) towards the meter's "
                    f"log-average {target:.6g} cd/m2 ({METER_SAMPLES} samples in each of {METER_COLUMNS} blocks across)")
        if value == "frame":
            return "this frame's log-average luminance"
        if value == "daylight":
            return "18 % grey card under the sun and sky"
        return "fixed by the scene"

    def _roughness_label(self) -> str:
        """How the surface BSDF's α is set: one value, or per vertex with its range."""
        if not getattr(self.body, "per_vertex_roughness", False):
            return "no: one alpha for the whole surface"
        alpha = self.body.vertex_roughness
        return (f"yes: alpha = sqrt(unresolved slope variance), {float(alpha.min()):.4g} (finest vertices) to "
                f"{float(alpha.max()):.4g} (all slopes unresolved)")

    def _sun_motion_label(self) -> str:
        if self.scene.sun.clock is not None:
            c = self.scene.sun.clock
            return (f"clock (NOAA) at {c.latitude:g} N {c.longitude:g} E from {c.start.isoformat()}, "
                    f"time_scale {c.time_scale:g}")
        return f"keys ({self.scene.sun.interpolation})" if self.scene.sun.keys else "still"

    def compute_frame(self, frame: int, seconds: dict[str, float] | None = None) -> RenderedFrame:
        """Geometry, render, denoise and vision model of one frame, in memory (nothing written).

        ``seconds`` (stage → s) is added to when given; the frame's own stage
        times are also in :attr:`RenderedFrame.seconds`.
        """
        own = {stage: 0.0 for stage in STAGES}
        tic = time.perf_counter()
        if self._loaded is not None and self._loaded[0] == frame:
            geometry = self._loaded[1]
        else:
            geometry = self.geometry(frame)
        tac = time.perf_counter()
        own["geometry"] += tac - tic
        self._loaded = None
        self.point(frame)
        self.renderer.update_water(geometry)
        tic = time.perf_counter()
        own["update"] += tic - tac
        xyz, repaired = self.renderer.render_xyz(self.spp, seed=self.scene.render.seed + frame)
        check_repaired(repaired, xyz.shape[0] * xyz.shape[1], frame)
        tac = time.perf_counter()
        own["render"] += tac - tic
        if self.scene.render.denoise:
            from .render.denoise import denoise_frame  # noqa: PLC0415

            xyz = denoise_frame(xyz, self.scene.render.chroma_radius)
            tic, tac = tac, time.perf_counter()
            own["denoise"] += tac - tic
        # the passes of the frame's own scene, before the meter loads other frames' water
        passes = self.renderer.passes(self.scene.output.passes) if self.scene.output.passes else {}
        target = None
        if self.follows_adaptation:
            # NOTE: after the frame's render, so the meter reads the water just loaded (no upload); an open sea's
            # kernels, the meter's included, were compiled beside its first frame's sea (_first_geometry).
            self._frame_geometry = (frame, geometry)  # the meter's reading of this frame uses it too
            adaptation, target = self.followed_adaptation(frame)
            self._frame_geometry = None
            tic, tac = tac, time.perf_counter()
            own["meter"] += tac - tic
        if target is None:
            adaptation = adaptation_luminance(self.scene, xyz, self.white_xyz)
        rgb = self.vision.apply(xyz, self.white_xyz, adaptation)
        metadata = self.metadata(frame, repaired, adaptation, target)
        spectral = None
        if self.renderer.bands and self.renderer.last_bands is not None:
            spectral = spectral_frame(self.renderer.last_bands, metadata)
        channels = {name: np.asarray(xyz[..., i], np.float32) for i, name in enumerate("XYZ")}
        channels.update({name: np.asarray(rgb[..., i], np.float32) for i, name in enumerate("RGB")})
        channels.update(passes)
        rendered = RenderedFrame(frame=frame, channels=channels, metadata=metadata, rgb8=encode_sRGB_8bit(rgb),
                                 spectral=spectral, repaired=repaired, seconds=own)
        own["vision"] += time.perf_counter() - tac
        if seconds is not None:
            for stage, value in own.items():
                seconds[stage] += value
        return rendered

    def render_frame(self, frame: int, paths: FramePaths, seconds: dict[str, float]) -> int:
        """Render, adapt and write one frame; returns the count of repaired pixels."""
        rendered = self.compute_frame(frame, seconds)
        seconds["write"] += write_frame(paths, rendered)
        return rendered.repaired


@dataclass(frozen=True)
class RenderedFrame:
    """One finished frame in memory, ready to be written (or sent from a worker to the writer).

    Attributes
    ----------
    frame : int
    channels : dict of (H, W) float32   X, Y, Z absolute [cd m⁻² for Y]; R, G, B linear display sRGB.
    metadata : dict                      The EXR header attributes.
    rgb8 : (H, W, 3) uint8               The display frame (PNG).
    spectral : (channels, metadata) or None   The optional spectral EXR (:func:`spectral_frame`).
    repaired : int                       Non-finite pixels repaired from their neighbours.
    seconds : dict                       This frame's time per stage [s] (``"write"`` excluded).
    """

    frame: int
    channels: dict
    metadata: dict
    rgb8: np.ndarray
    spectral: tuple | None
    repaired: int
    seconds: dict


def write_frame(paths: FramePaths, rendered: RenderedFrame) -> float:
    """Write a frame's EXR (and spectral EXR) and PNG, each atomically; returns the seconds taken.

    The PNG is written last: :func:`~oceanrender.io.frames.frame_is_complete`
    needs both, so a frame interrupted between the two is rendered again.
    """
    tic = time.perf_counter()
    if rendered.spectral is not None:
        write_exr(paths.exr.with_name(paths.exr.stem + "_spectral.exr"), *rendered.spectral)
    write_exr(paths.exr, rendered.channels, rendered.metadata)
    write_png(paths.png, rendered.rgb8)
    return time.perf_counter() - tic


def spectral_frame(band_integrals: np.ndarray, metadata: dict) -> tuple[dict[str, np.ndarray], dict]:
    """Channels and metadata of a frame's spectral EXR: mean radiance per band [W m⁻² sr⁻¹ nm⁻¹].

    ``band_integrals`` (H, W, N) are the film's ∫L dλ over N equal bands of the
    film's range [W m⁻² sr⁻¹]; each becomes a channel named ``"<lo>-<hi>nm"``
    holding the band's mean spectral radiance (the integral over its width).
    Not adapted: absolute radiance, for re-lighting or another vision model.
    """
    from .render.scene import spectral_band_edges  # noqa: PLC0415

    bands = band_integrals.shape[-1]
    edges = spectral_band_edges(bands)
    widths = np.diff(edges)
    channels = {f"{lo:.1f}-{hi:.1f}nm": (band_integrals[..., i] / widths[i]).astype(np.float32)
                for i, (lo, hi) in enumerate(zip(edges[:-1], edges[1:]))}
    meta = {**metadata, "channels": "mean spectral radiance per band [W m-2 sr-1 nm-1], absolute, not adapted",
            "band_edges_nm": " ".join(f"{e:.3f}" for e in edges)}
    return channels, meta


def pass_channels(passes: tuple[str, ...]) -> tuple[str, ...]:
    """The EXR channels of the render passes ``passes`` (:mod:`oceanrender.render.passes`)."""
    from .render.passes import PASS_CHANNELS  # noqa: PLC0415

    return tuple(channel for name in passes for channel in PASS_CHANNELS[name])


def coastal_store(out_dir: str | Path) -> Path:
    """Where a coastal scene's simulation keeps its per-frame fields: ``<out_dir>/coastal``."""
    return Path(out_dir) / "coastal"


def frames_to_render(out_dir: str | Path, frames: tuple[int, int], size: tuple[int, int], report: SequenceReport,
                     on_frame: Callable[[int, float, bool], None] | None = None,
                     passes: tuple[str, ...] = ()) -> list[int]:
    """The frames of [start, end) not yet intact in ``out_dir`` (the others go to ``report.skipped``).

    Deletes the temporaries a killed run left first; ``on_frame(frame, 0, True)``
    is called for each frame skipped.
    """
    remove_stale_temporaries(out_dir)
    todo = []
    for frame in range(*frames):
        paths = frame_paths(out_dir, frame)
        if frame_is_complete(paths.exr, paths.png, size, pass_channels(passes)):
            report.skipped.append(frame)
            if on_frame:
                on_frame(frame, 0.0, True)
        else:
            todo.append(frame)
    return todo


def simulate_coastal(scene: Scene, out_dir: str | Path, todo: list[int], report: SequenceReport) -> Path | None:
    """Run (or resume) a coastal scene's simulation up to its last frame to render; its store, or None (open sea)."""
    if scene.coastal is None:
        return None
    from .coastal.simulation import run_simulation  # noqa: PLC0415

    store = coastal_store(out_dir).resolve()
    report.simulation = run_simulation(scene, store, (first_needed_frame(scene, todo[0]), todo[-1] + 1))
    return store


def first_needed_frame(scene: Scene, first: int) -> int:
    """The earliest frame whose state a render of frames from ``first`` on needs [-].

    With the eye's adaptation followed over time a frame meters the frames of its
    adaptation window (:func:`~oceanrender.vision.temporal.adaptation_window`), so a
    coastal simulation must store those too.
    """
    vision = scene.vision
    if vision.adaptation_luminance == "frame" and vision.adaptation_time > 0:
        return adaptation_window(first, vision.adaptation_time, scene.output.fps).start
    return first


def render_sequence(scene: Scene, out_dir: str | Path, variant: str, frames: tuple[int, int] | None = None,
                    spp: int | None = None, resolution: tuple[int, int] | None = None,
                    on_frame: Callable[[int, float, bool], None] | None = None) -> SequenceReport:
    """Render frames [start, end) of ``scene`` into ``out_dir``; resume where files exist.

    A frame whose EXR and PNG both read back intact is skipped, so a killed
    run loses at most the frame in flight. ``on_frame(frame, seconds, skipped)``
    is called after each frame (for progress display).
    """
    size = tuple(resolution or scene.output.resolution)
    report = SequenceReport(variant=variant)
    todo = frames_to_render(out_dir, frames or scene.output.frames, size, report, on_frame, scene.output.passes)
    if not todo:
        return report
    tic = time.perf_counter()
    store = simulate_coastal(scene, out_dir, todo, report)
    sequence = Sequence(scene, variant, spp=spp, resolution=size, first_frame=todo[0], coastal_store=store)
    report.setup_seconds = time.perf_counter() - tic
    for frame in todo:
        tic = time.perf_counter()
        report.repaired_pixels += sequence.render_frame(frame, frame_paths(out_dir, frame), report.stage_seconds)
        report.rendered.append(frame)
        if on_frame:
            on_frame(frame, time.perf_counter() - tic, False)
    return report
