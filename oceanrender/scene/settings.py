"""Scene files: TOML parsed into typed, immutable, validated settings.

A scene file is data only (``tomllib``: nothing in it is executed). Every
section is a frozen pydantic model that forbids unknown keys and checks
ranges, so a bad file is refused before any work starts, with one line
naming the file, the key and what was expected. Defaults live here and only
here.

Conventions: z up, +x east, +y north; lengths in m, angles in degrees in the
file (converted where used), wind in m s⁻¹, luminance in cd m⁻².
"""

from __future__ import annotations

import math
import os
import re
import tomllib
from pathlib import Path
from typing import Annotated, Literal

from pydantic import BaseModel, Field, ValidationError, field_validator, model_validator

from ..io.messages import QUOTE_LIMIT, quoted
from ..runtime.names import SPECTRAL_VARIANTS
from .coastal_section import ARRAY_SUFFIXES, CoastalSettings, OPEN_SEA_DEPTH_MATCH
from .motion import frame_times, scene_camera_path, scene_sun_motion
from .object_sections import CONDUCTORS, OBJECT_MATERIALS, ObjectSettings
from .ocean_sections import (
    CompositionSettings,
    FoamSettings,
    MeshSettings,
    OceanSettings,
    PartitionSettings,
    SEA_STATE_SPECTRA,
    TP_RANGE,
    WaterSettings,
)
from .section_base import (
    Interpolation,
    MAX_FRAME,
    MAX_FRAME_COUNT,
    MAX_SCENE_BYTES,
    MAX_SPECTRAL_BANDS,
    MIN_SUN_ELEVATION,
    SAFE_NAME,
    SEED_MAX,
    SceneError,
    Vec3,
    _Section,
)
from .view_sections import (
    CameraKeySettings,
    CameraSettings,
    CameraViewSettings,
    EnvironmentSettings,
    SolarClockSettings,
    SunKeySettings,
    SunSettings,
    VisionSettings,
)


class OutputSettings(_Section):
    """What to render and where [frames, pixels, samples]."""

    frames: tuple[Annotated[int, Field(ge=0)], Annotated[int, Field(ge=1)]] = Field(
        (0, 3), description="half-open frame range [start, end)"
    )
    fps: float = Field(24.0, gt=0, le=1000, description="frames per second [s⁻¹]")
    resolution: tuple[Annotated[int, Field(ge=1, le=16384)], Annotated[int, Field(ge=1, le=16384)]] = (320, 180)
    spp: int = Field(24, ge=1, le=1 << 20, description="samples per pixel")
    directory: str = Field("outputs", min_length=1, description="output root; frames go to <directory>/<scene name>/")
    spectral_bands: int = Field(0, ge=0, le=MAX_SPECTRAL_BANDS,
                                description="> 0: also write frame_NNNN_spectral.exr with this many equal bands of "
                                            f"mean radiance over 360-830 nm (at most {MAX_SPECTRAL_BANDS}: 5 nm bands)")
    passes: tuple[Literal["Z", "N", "P", "water", "foam", "objects", "water_path"], ...] = Field(
        (), description="render passes written into the frame EXR (docs/passes.md): Z, N, P, water, foam, objects, "
                        "water_path")

    @field_validator("directory")
    @classmethod
    def _usable_folder(cls, value: str) -> str:
        from ..io.paths import name_problem  # noqa: PLC0415

        problem = name_problem(value)
        if problem:
            raise ValueError(f"{problem}; expected a folder name the file system can hold (taken literally: "
                             f"no '~' or '$VAR' expansion)")
        return value

    @field_validator("passes")
    @classmethod
    def _passes_once(cls, value: tuple[str, ...]) -> tuple[str, ...]:
        twice = sorted({p for p in value if value.count(p) > 1})
        if twice:
            raise ValueError(f"each pass once; {', '.join(twice)} given more than once")
        return value

    @field_validator("frames")
    @classmethod
    def _ordered(cls, value: tuple[int, int]) -> tuple[int, int]:
        if value[1] <= value[0]:
            raise ValueError(f"expected [start, end) with end > start, got {list(value)}")
        if value[1] > MAX_FRAME or value[1] - value[0] > MAX_FRAME_COUNT:
            raise ValueError(f"expected at most {MAX_FRAME_COUNT} frames per run and end ≤ {MAX_FRAME}, "
                             f"got {list(value)}")
        return value


class RenderSettings(_Section):
    """Light transport settings."""

    variant: str = Field("auto", description="'auto' or a Mitsuba spectral variant")
    integrator: Literal["volpath", "volpathmis", "split"] = Field(
        "split", description="'split' follows both Fresnel lobes at the first water hit (less noise, 1.3x time)"
    )
    max_depth: int = Field(12, ge=2, le=1024, description="maximum path length [vertices]")
    sun_sampling: bool = Field(
        True, description="('split' only) sample the sunlight refracted into the water at every in-water vertex"
    )
    in_water_clamp: float = Field(
        0.0, ge=0, le=1e6,
        description="('split') firefly clamp: largest in-water radiance of one sample, in multiples of the "
                    "mean radiance of a white Lambertian surface under the scene's sun and sky; 0: off (unbiased)")
    roulette_depth: int = Field(
        5, ge=1, le=1024,
        description="path vertices before Russian roulette starts (as volpath's rr_depth; 'split' continues "
                    "its lobes with one less)")
    in_water_fraction: float = Field(
        0.25, gt=0, le=1,
        description="('split') samples per pixel of the transmitted (in-water) lobe, as a fraction of spp: "
                    "below 1 a frame is two passes, the rest at spp and the in-water lobe at "
                    "max(1, round(fraction x spp)); the sum is unbiased")
    caustic_cell: float = Field(
        0.02, ge=0, le=1.0,
        description="('split', open sea with [water] bottom_albedo, fields shading) side of the cells of the map "
                    "of the sun's beam traced through the sea onto the floor [m]: the caustics' resolution "
                    "(docs/sunlight.md); 0: off, the floor's sunlight from the path tracer's connections")
    caustic_window: float = Field(
        24.0, gt=0, le=400,
        description="side of the floor's caustic map, centred under the camera [m]; beyond it the path tracer's "
                    "connections")
    shaft_cell: float = Field(
        0.0, ge=0, le=2.0,
        description="('split', fields shading) side of the cells of the planes of the sun's beam traced through "
                    "the sea into the water's volume (the shafts) [m], planes every 0.5 m down to shaft_depth over "
                    "caustic_window, sheared along the beam, their mean beyond it, read along every in-water "
                    "segment (docs/sunlight.md); 0: off, the volume's sunlight from the path tracer's connections")
    shaft_depth: float = Field(12.0, gt=0, le=200, description="depth the shafts' planes reach below the mean level [m]")
    denoise: bool = Field(False, description="denoise each frame with Intel Open Image Denoise (colour only), then "
                                             "its chromaticity (chroma_radius)")
    chroma_radius: int = Field(
        4, ge=0, le=64, description="(with denoise) radius [px] over which the chromaticity is averaged among "
        "pixels of similar denoised luminance, the luminance kept (the colour noise of four wavelengths per "
        "sample; docs/time_to_quality.md); 0: OIDN alone")
    surface_shading: Literal["fields", "vertex"] = Field(
        "fields", description="'fields': every water hit shaded from the sea's fields at its footprint (FFT sea, "
        "surface_roughness 'auto'; docs/pixel_detail.md); 'vertex': normals, α and foam interpolated from the mesh")
    sampler: Literal["independent", "multijitter", "orthogonal"] = Field(
        "multijitter", description="Mitsuba's sampler of the frame's samples: 'multijitter' stratifies each of a "
        "pixel's dimensions (its wavelengths among them: less colour noise, docs/time_to_quality.md); "
        "'independent' draws each number on its own; 'orthogonal' rounds spp up to a prime's square")
    white_spp: int = Field(1024, ge=16, le=1 << 20, description="samples to measure the adapting white")
    seed: int = Field(0, ge=0, le=SEED_MAX, description="sampler seed (per frame: seed + frame, below 2³²)")

    @field_validator("variant")
    @classmethod
    def _spectral(cls, value: str) -> str:
        if value != "auto" and value not in SPECTRAL_VARIANTS:
            raise ValueError(f"expected 'auto' or one of {', '.join(SPECTRAL_VARIANTS)} (the scalar variants are "
                             f"not supported: the renderer needs a JIT backend), got {quoted(value)}")
        return value


class Scene(_Section):
    """A whole scene; ``name`` defaults to the file's stem."""

    name: str = Field(..., min_length=1, max_length=100, pattern=f"^{SAFE_NAME}$",
                      description="the scene's folder name under the output directory: letters, digits, '_', "
                                  "'.', '-', not starting with '.' or '-'")
    output: OutputSettings = OutputSettings()
    render: RenderSettings = RenderSettings()
    ocean: OceanSettings = OceanSettings()
    mesh: MeshSettings = MeshSettings()
    foam: FoamSettings = FoamSettings()
    water: WaterSettings = WaterSettings()
    composition: CompositionSettings | None = None
    coastal: CoastalSettings | None = None
    sun: SunSettings = SunSettings()
    environment: EnvironmentSettings | None = None
    camera: CameraSettings = CameraSettings()
    vision: VisionSettings = VisionSettings()
    objects: tuple[ObjectSettings, ...] = Field((), max_length=64, description="[[objects]]: meshes in the scene")

    @model_validator(mode="after")
    def _environment_with_a_still_sun(self) -> "Scene":
        if self.environment is not None and self.sun.animated:
            raise ValueError("[environment]: a map is a still sky; its [sun] cannot move ([[sun.keys]], [sun.clock])")
        return self

    @field_validator("objects")
    @classmethod
    def _unique_object_names(cls, value: tuple[ObjectSettings, ...]) -> tuple[ObjectSettings, ...]:
        names = [o.name for o in value]
        twice = sorted({n for n in names if names.count(n) > 1})
        if twice:
            raise ValueError(f"names must differ; {', '.join(twice)} appear(s) more than once")
        return value

    @field_validator("camera")
    @classmethod
    def _camera_over_frames(cls, value: CameraSettings, info) -> CameraSettings:
        output = info.data.get("output")
        if value.animated and output is not None:
            path = scene_camera_path(value)
            for frame, t in zip(range(*output.frames), frame_times(output.frames, output.fps)):
                try:
                    path.at(t)
                except ValueError as exc:
                    raise ValueError(f"[[camera.keys]] at frame {frame}: {exc}") from None
        return value

    @field_validator("sun")
    @classmethod
    def _sun_over_frames(cls, value: SunSettings, info) -> SunSettings:
        output = info.data.get("output")
        if value.animated and output is not None:
            motion = scene_sun_motion(value)
            where = "[sun.clock]" if value.clock is not None else "[[sun.keys]]"
            for frame, t in zip(range(*output.frames), frame_times(output.frames, output.fps)):
                elevation = motion.at(t).elevation
                if not elevation >= MIN_SUN_ELEVATION:
                    raise ValueError(f"{where}: the sun is below the horizon (or within {MIN_SUN_ELEVATION}° of "
                                     f"it) at frame {frame} (t = {t:g} s): elevation {elevation:.2f} deg; sunsky needs it above over the frame range")
        return value

    @model_validator(mode="after")
    def _seeds_fit(self) -> "Scene":
        last = self.render.seed + self.output.frames[1] - 1
        if last > SEED_MAX:
            raise ValueError(f"[render] seed: seed + last frame = {last} must stay below 2³² "
                             f"(Mitsuba's 32-bit sampler seed); lower the seed")
        return self

    @model_validator(mode="after")
    def _camera_in_the_water_body(self) -> "Scene":
        positions = ([self.camera.position] + [key.position for key in self.camera.keys]
                     + [view.position for view in self.camera.views.values()])
        low = min(position[2] for position in positions)
        if self.coastal is not None:
            level = self.coastal.still_level
            if low <= level:
                raise ValueError(f"[camera] position: the camera is at z = {low:g} m, at or below the still water "
                                 f"level {level:g} m; under-water views of a [coastal] scene are not supported "
                                 f"(open-sea scenes only)")
        elif low <= -self.water.depth:
            raise ValueError(f"[camera] position: the camera is at z = {low:g} m, at or below the water body's "
                             f"bottom (−[water] depth = {-self.water.depth:g} m); expected z > {-self.water.depth:g}")
        return self

    @model_validator(mode="after")
    def _shafts_in_the_open_sea(self) -> "Scene":
        if self.coastal is not None and self.render.shaft_cell > 0:
            raise ValueError(f"[render] shaft_cell: the volume's beam is traced from the open sea's fields alone; "
                             f"a [coastal] scene cannot use it: expected 0, got {self.render.shaft_cell:g}")
        return self

    @model_validator(mode="after")
    def _coast_in_open_sea(self) -> "Scene":
        coastal = self.coastal
        if coastal is None or coastal.waves != "open sea":
            return self
        needs = [
            (self.ocean.model == "FFT", "[ocean] model: must be 'FFT': the coast inside the open sea takes the FFT "
                                        "sea's own modes"),
            (self.mesh.kind == "radial", "[mesh] kind: must be 'radial': the open sea around the coast reaches the "
                                         "horizon on the camera's radial mesh"),
            (coastal.still_level == 0.0, "[coastal] still_level: must be 0 m with waves = 'open sea' (the FFT sea's "
                                         "mean level)"),
            (not self.camera.animated, "[camera] keys: the coast inside the open sea needs a still camera (its "
                                       "terrain is built once, on the camera's radial mesh)"),
            (math.isfinite(self.ocean.wave_depth),
             "[ocean] wave_depth: must be finite with waves = 'open sea': the sea's dispersion relation at the "
             "offshore depth is what the solver's side takes"),
            (self.water.depth > coastal.outer_depth + 1.0,
             f"[water] depth: must exceed [coastal] outer_depth + 1 m = {coastal.outer_depth + 1.0:g} m (the body's "
             f"bottom lies below the sea floor), got {self.water.depth:g}"),
        ]
        for ok, message in needs:
            if not ok:
                raise ValueError(message)
        return self

    @field_validator("composition")
    @classmethod
    def _one_water(cls, value, info):
        water = info.data.get("water")
        if value is not None and water is not None and water.jerlov_type is not None:
            raise ValueError("give either [composition] or [water] jerlov_type, not both")
        return value


def _field_location(location: tuple) -> tuple:
    """``location`` without pydantic's union-member tags (``'float'``, ``"literal['frame']"``).

    A name that is no field of its section is kept only as the last item (an unknown key).
    """
    kept, model = [], Scene
    for index, item in enumerate(location):
        if isinstance(item, int):
            kept.append(item)
        elif model is None:
            continue  # a tag inside a plain field
        elif item in model.model_fields:
            kept.append(item)
            model = _section_model(model.model_fields[item].annotation)
        elif index == len(location) - 1:
            kept.append(item)  # an unknown key
    return tuple(kept)


def _key_path(location: tuple) -> str:
    location = _field_location(location)
    parts: list[str] = []
    for item in location:
        if isinstance(item, int) and parts:
            parts[-1] += f"[{item}]"
        else:  # an unknown key is the file's text: quoted like any value when it is long
            parts.append(str(item) if len(str(item)) <= QUOTE_LIMIT else quoted(item))
    if not parts:
        return "(top level)"
    if len(parts) == 1:
        return parts[0]
    return f"[{'.'.join(parts[:-1])}] {parts[-1]}"


def _field_help(location: tuple) -> str | None:
    """The description (meaning and unit) of the field at ``location``."""
    model: type[BaseModel] = Scene
    info = None
    for item in location:
        if isinstance(item, int):
            continue
        fields = getattr(model, "model_fields", None)
        if not fields or item not in fields:
            return None
        info = fields[item]
        model = _section_model(info.annotation)
    return info.description if info is not None else None


def _section_model(annotation) -> type[BaseModel] | None:
    """The section model of a field's annotation: ``Model``, ``Model | None`` or ``tuple[Model, ...]``."""
    from typing import get_args  # noqa: PLC0415

    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return annotation
    for arg in get_args(annotation):
        if isinstance(arg, type) and issubclass(arg, BaseModel):
            return arg
    return None


def _describe(error: dict) -> str:
    kind = error["type"]
    location = error["loc"]
    if kind == "extra_forbidden":
        return "unknown key"
    if kind == "missing":
        return "expected more values" if location and isinstance(location[-1], int) else "required key is missing"
    message = error["msg"].removeprefix("Value error, ")
    shown = error.get("input")
    if "got" not in message and not (isinstance(shown, (dict, list)) and len(repr(shown)) > 60):
        message = f"{message} (got {quoted(shown)})"
    meaning = _field_help(location)
    return f"{message}; {meaning}" if meaning else message


def scene_from_dict(data: dict, source: str = "<dict>") -> Scene:
    """Validate a parsed scene mapping; raise :class:`SceneError` on the first problem."""
    try:
        return Scene.model_validate(data)
    except ValidationError as exc:
        first = exc.errors()[0]
        message = first["msg"].removeprefix("Value error, ")
        if not first["loc"] and message.startswith("["):  # a whole-scene check names its own key
            raise SceneError(f"{source}: {message}") from None
        raise SceneError(f"{source}: {_key_path(first['loc'])}: {_describe(first)}") from None
    except RecursionError:
        raise SceneError(f"{source}: tables nested too deeply") from None


def load_scene(path: str | Path) -> Scene:
    """Read and validate a TOML scene file.

    Parameters
    ----------
    path : str or Path
        The scene file.

    Raises
    ------
    SceneError
        One line naming the file, the key and what was expected.
    """
    from ..io.paths import PathProblem, check_input_file  # noqa: PLC0415

    try:
        path = check_input_file(path, MAX_SCENE_BYTES)
        text = path.read_bytes().decode("utf-8")
    except PathProblem as exc:
        raise SceneError(f"{path}: cannot read scene file: {exc}") from None
    except OSError as exc:
        raise SceneError(f"{path}: cannot read scene file ({exc.strerror or exc})") from None
    except UnicodeDecodeError as exc:
        raise SceneError(f"{path}: not UTF-8 text (byte {exc.start}); a scene file is TOML") from None
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise SceneError(f"{path}: not valid TOML: {exc}") from None
    except RecursionError:
        raise SceneError(f"{path}: not usable TOML: tables or arrays nested too deeply") from None
    if "name" not in data:
        if not re.fullmatch(SAFE_NAME, path.stem):
            raise SceneError(f"{path}: name: the file's name {quoted(path.stem)} is not a safe folder name (letters, "
                             f"digits, '_', '.', '-', not starting with '.' or '-'); give name = \"...\" in the file")
        data["name"] = path.stem
    resolve_scene_paths(data, path.parent)
    scene = scene_from_dict(data, str(path))
    check_scene_inputs(scene, str(path))
    return scene


def resolve_scene_paths(data: dict, folder: Path) -> None:
    """Make the file paths of a parsed scene absolute, in place, the one documented way.

    Array files ([coastal] bathymetry, initial_surface, initial_u, initial_v) and an ``iop_table``
    that is a path (holds a ``/``) are relative to the scene file's folder; a
    bare table name is a table in ``spectra/`` and is left as it is.
    """
    coastal = data.get("coastal")
    if isinstance(coastal, dict):
        for key in ("bathymetry", "initial_surface", "initial_u", "initial_v"):
            value = coastal.get(key)
            if isinstance(value, str) and value.lower().endswith(ARRAY_SUFFIXES) and "\x00" not in value:
                coastal[key] = os.path.abspath(folder / value)
    water = data.get("water")
    if isinstance(water, dict):
        value = water.get("iop_table")
        if isinstance(value, str) and "/" in value and "\x00" not in value:
            water["iop_table"] = os.path.abspath(folder / value)
    ocean = data.get("ocean")
    if isinstance(ocean, dict):
        value = ocean.get("spectrum_file")
        if isinstance(value, str) and value and "\x00" not in value:
            ocean["spectrum_file"] = os.path.abspath(folder / value)
    environment = data.get("environment")
    if isinstance(environment, dict):
        value = environment.get("map")
        if isinstance(value, str) and value and "\x00" not in value:
            environment["map"] = os.path.abspath(folder / value)
    objects = data.get("objects")
    if isinstance(objects, list):
        for entry in objects:
            for key in ("mesh", "albedo_texture", "albedo_spectrum"):
                value = entry.get(key) if isinstance(entry, dict) else None
                if isinstance(value, str) and value and "\x00" not in value:
                    entry[key] = os.path.abspath(folder / value)


def check_scene_inputs(scene: Scene, source: str = "<dict>") -> None:
    """Read and check the data files a scene names (coastal arrays, object meshes); SceneError naming the key."""
    check_object_inputs(scene, source)
    check_spectrum_file(scene, source)
    if scene.coastal is None:
        return
    from .arrays import check_coastal_inputs  # noqa: PLC0415

    try:
        check_coastal_inputs(scene.coastal)
    except ValueError as exc:
        raise SceneError(f"{source}: [coastal] {exc}") from None
    if scene.coastal.waves == "open sea":
        from .arrays import bathymetry, offshore_depth  # noqa: PLC0415

        try:
            depth = offshore_depth(scene.coastal, bathymetry(scene.coastal))
        except ValueError as exc:
            raise SceneError(f"{source}: [coastal] {exc}") from None
        if abs(scene.ocean.wave_depth - depth) > OPEN_SEA_DEPTH_MATCH * depth:
            raise SceneError(f"{source}: [ocean] wave_depth: must equal the mean still depth along the "
                             f"[coastal] offshore side, {depth:.3g} m, within {OPEN_SEA_DEPTH_MATCH:.0%} with waves = "
                             f"'open sea' (one dispersion relation on both sides of the join), got "
                             f"{scene.ocean.wave_depth:g}")


def check_spectrum_file(scene: Scene, source: str = "<dict>") -> None:
    """Read the ``[ocean] spectrum_file`` at its time and site now; SceneError naming the key and the problem."""
    ocean = scene.ocean
    if ocean.spectrum_file is None:
        return
    from ..io.spectrum_files import read_spectrum_file  # noqa: PLC0415

    try:
        read_spectrum_file(ocean.spectrum_file, ocean.spectrum_format, ocean.spectrum_time, ocean.spectrum_site)
    except (ValueError, OSError) as exc:
        message = str(exc).splitlines()[0]
        key = next((k for k in ("spectrum_time", "spectrum_site", "spectrum_format") if message.startswith(k)),
                   "spectrum_file")
        raise SceneError(f"{source}: [ocean] {key}: {ocean.spectrum_file}: {message}") from None


def check_object_inputs(scene: Scene, source: str = "<dict>") -> None:
    """Each ``[[objects]]`` mesh read and checked, and fitted in the water body; SceneError naming the key.

    An object must stay above the bottom (its lowest point above −[water] depth at its
    pose), a floating one needs a closed hull that reaches below its waterline, and a
    texture needs the mesh's texture coordinates.
    """
    if not scene.objects:
        return
    from ..io.meshes import MeshProblem, read_mesh  # noqa: PLC0415
    from ..io.paths import PathProblem, check_input_file  # noqa: PLC0415

    for index, obj in enumerate(scene.objects):
        where = f"{source}: [[objects]] {obj.name}"
        try:
            mesh = read_mesh(obj.mesh)
        except MeshProblem as exc:
            raise SceneError(f"{where} mesh: {exc}") from None
        if obj.albedo_texture is not None:
            try:
                check_input_file(obj.albedo_texture, 1 << 28)
            except PathProblem as exc:
                raise SceneError(f"{where} albedo_texture: {exc}") from None
            if mesh.uv is None:
                raise SceneError(f"{where} albedo_texture: the mesh {obj.mesh} has no texture coordinates")
        low = obj.position[2] + obj.scale * float(mesh.vertices[:, 2].min())
        # NOTE: a tilted or floating object may swing its lowest point down by up to its largest radius.
        radius = obj.scale * float(((mesh.vertices**2).sum(axis=1) ** 0.5).max())
        deepest = obj.position[2] - radius if (obj.pitch or obj.roll or obj.floating) else low
        if scene.coastal is None and deepest <= -scene.water.depth:
            raise SceneError(f"{where} position: the object can reach down to z = {deepest:g} m, the bottom is at "
                             f"{-scene.water.depth:g} m; expected it to fit the water depth ([water] depth)")
        if obj.floating:
            if not mesh.closed:
                raise SceneError(f"{where} mesh: a floating object needs a closed (watertight) hull; {obj.mesh} "
                                 f"has open edges")
            if low >= 0.0:
                raise SceneError(f"{where} position: a floating object's hull must reach below its waterline "
                                 f"(z = 0 of the mesh), its lowest point is at z = {low:g} m")


def with_view(scene: Scene, view: str, source: str = "command line") -> Scene:
    """The scene seen from its ``[camera.views.<view>]``, named ``<name>_<view>``; SceneError if it has no such view."""
    views = scene.camera.views
    if view not in views:
        have = ", ".join(sorted(views)) or "none"
        raise SceneError(f"{source}: --view {view}: the scene has no [camera.views.{view}] (its views: {have})")
    data = scene.model_dump()
    chosen = views[view]
    data["camera"] = {**data["camera"], "position": chosen.position, "target": chosen.target, "fov": chosen.fov}
    data["name"] = f"{scene.name}_{view}"[:100]
    return scene_from_dict(data, source)


def with_overrides(scene: Scene, source: str = "command line", **sections: dict) -> Scene:
    """Return a copy of ``scene`` with some keys replaced, validated again.

    ``with_overrides(scene, output={"spp": 4})`` validates as a file would, so
    command-line overrides are held to the same ranges.
    """
    data = scene.model_dump()
    for section, values in sections.items():
        if values:
            data[section] = {**(data[section] or {}), **values}  # (an optional section left out: None)
    return scene_from_dict(data, source)
