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

from pydantic import AwareDatetime, BaseModel, ConfigDict, Field, ValidationError, field_validator, model_validator

from ..io.messages import QUOTE_LIMIT, quoted
from ..runtime.names import SPECTRAL_VARIANTS
from .arrays import MAX_INITIAL_SPEED
from .motion import SolarClock, frame_times, scene_camera_path, scene_sun_motion


class SceneError(ValueError):
    """A scene file that cannot be used; the message is one line for the user."""


#: Largest sampler/wave seed: Mitsuba's samplers take a 32-bit unsigned seed.
SEED_MAX = (1 << 32) - 1
#: Most frames one run may hold (69 min at 24 fps): every frame is validated (camera path, sun) at load.
MAX_FRAME_COUNT = 100_000
#: Largest frame number [-] (frame files are numbered frame_NNNN with at least 4 digits).
MAX_FRAME = 10_000_000
#: Lowest sun elevation accepted [deg]: the sun's disc (0.53° wide) clear of the horizon.
MIN_SUN_ELEVATION = 0.5
#: Largest scene file accepted [bytes].
MAX_SCENE_BYTES = 1 << 20
#: Most bands of the spectral EXR [-]: 5 nm bands over 360–830 nm. Each band is a channel of Mitsuba's film, compiled
#: into every kernel: measured here (16×9 px, 1 spp, cold kernel cache) 6 s to render with 16 bands, 10 s with 96,
#: 18 s with 256, 41 s with 470 (0.86 GB), and a run with 470 was seen compiling for over 7 min on a loaded machine
#: (issue 39). Narrower bands carry nothing the renderer has: the sky's spectra are tabulated every 40 nm
#: (Hosek & Wilkie 2012) and the water's tables every 1–5 nm.
MAX_SPECTRAL_BANDS = 94
#: A scene name: a safe folder name (no "..", no hidden folder, no separator), at most 100 characters.
SAFE_NAME = r"[A-Za-z0-9_][A-Za-z0-9_.-]{0,99}"


class _Section(BaseModel):
    # NOTE: allow_inf_nan=False: no NaN or infinity anywhere (vectors included) unless a field allows it.
    model_config = ConfigDict(extra="forbid", frozen=True, strict=False, allow_inf_nan=False)


Vec3 = tuple[float, float, float]


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


#: Peak periods a sea-state form accepts [s] (from short wind chop to the longest ocean swell).
TP_RANGE = (1.0, 30.0)
#: Frequency spectra that the sea-state form (hs, tp) and partitions accept.
SEA_STATE_SPECTRA = ("JONSWAP 1973", "Pierson-Moskowitz 1964", "TMA 1985")


class PartitionSettings(_Section):
    """One partition of a sea given by its statistics (``[[ocean.partitions]]``): a swell or a second wind sea.

    S(f) of ``spectrum`` scaled to Hs = 4 √m0 exactly, peaked at 1/Tp, spread
    about ``direction`` by cos^{2s}((θ − θ_m)/2).
    """

    spectrum: Literal["JONSWAP 1973", "Pierson-Moskowitz 1964", "TMA 1985"] = "JONSWAP 1973"
    hs: float = Field(gt=0, le=30, description="significant wave height Hs = 4 √m0 [m]")
    tp: float = Field(ge=TP_RANGE[0], le=TP_RANGE[1], description="peak period [s]")
    gamma: float = Field(3.3, ge=1, le=10, description="JONSWAP/TMA peak enhancement γ [-]")
    sigma_a: float = Field(0.07, gt=0, le=0.5, description="JONSWAP peak width below the peak σ_a [-]")
    sigma_b: float = Field(0.09, gt=0, le=0.5, description="JONSWAP peak width above the peak σ_b [-]")
    direction: float = Field(0.0, ge=-360, le=360, description="mean direction of travel, counter-clockwise from +x [deg]")
    spreading_s: float = Field(10.0, ge=0, le=1000, description="cos-2s spreading parameter s [-] (wind sea ~10, swell 25-75)")


class OceanSettings(_Section):
    """Open-sea geometry: the wave spectrum and how the surface is synthesised.

    ``model = "FFT"`` is Tessendorf's FFT sea, as ``cascades`` patches of
    incommensurate sizes (the largest is ``patch_size``); "sum of sines" and
    "Gerstner" draw ``wave_count`` components from the same spectrum.

    The sea is given in exactly one of three forms (docs/geometry.md, "Sea states"):

    * **wind**: ``wind_speed`` (U₁₀, at 10 m) and ``fetch`` (the default);
    * **sea state**: ``hs`` and ``tp`` (with ``gamma``, ``sigma_a``, ``sigma_b``,
      ``direction``, ``spreading_s``) for ``spectrum`` JONSWAP/TMA/Pierson–Moskowitz,
      plus any ``[[ocean.partitions]]`` (swells);
    * **file**: ``spectrum_file``, a measured or modelled E(f, θ) read with
      wavespectra, at ``spectrum_time`` and ``spectrum_site``.
    """

    model: Literal["FFT", "sum of sines", "Gerstner"] = "FFT"
    spectrum: Literal["Phillips 2001", "Pierson-Moskowitz 1964", "JONSWAP 1973", "TMA 1985", "Elfouhaily 1997"] = Field(
        "Elfouhaily 1997", description="wave spectrum; default 'Elfouhaily 1997' (wind form), 'JONSWAP 1973' when the "
                                       "sea-state form (hs, tp) is given")
    spreading: Literal["cos2", "Mitsuyasu 1975", "Hasselmann 1980", "Donelan-Banner 1985"] | None = Field(
        None, description="directional spreading; none = the spectrum's own (Phillips) or Mitsuyasu 1975"
    )
    wind_speed: float = Field(12.0, gt=0, le=60, description="wind speed 10 m above the sea [m s⁻¹]")
    wind_direction: float = Field(60.0, ge=-360, le=360, description="direction the wind blows toward, counter-clockwise from +x (east) [deg]")
    fetch: float = Field(5.0e4, gt=0, le=1.0e7, description="fetch of JONSWAP/TMA [m]")
    gamma: float = Field(3.3, ge=1, le=10, description="JONSWAP peak enhancement γ [-]")
    wave_depth: float = Field(float("inf"), gt=0, allow_inf_nan=True, description="water depth of the dispersion relation and TMA [m]; inf = deep")
    alpha: float | None = Field(None, gt=0, le=0.1, description="Phillips/PM constant α [-] (default 8.1e-3)")
    small_wave_length: float = Field(0.0, ge=0, le=10, description="suppression length ℓ of small waves [m]")
    swell_height: float = Field(0.0, ge=0, le=30, description="significant height of an added swell [m]")
    swell_period: float = Field(10.0, gt=0, le=40, description="swell peak period [s]")
    swell_direction: float = Field(0.0, ge=-360, le=360, description="swell direction of travel, counter-clockwise from +x [deg]")
    swell_spreading_s: float = Field(25.0, ge=0, le=1000, description="cos-2s spreading exponent of the swell [-]")
    patch_size: float = Field(2400.0, gt=0, le=100_000, description="side of the largest periodic patch [m]")
    cascades: int = Field(4, ge=1, le=6, description="number of FFT patches of decreasing size [-]")
    resolution: int = Field(1024, ge=8, le=8192, description="FFT grid points per side of each patch")
    choppiness: float = Field(0.8, ge=0, le=3, description="horizontal displacement scale λ [-]")
    loop_period: float = Field(0.0, ge=0, le=1e6, description="period after which the sea repeats exactly [s]; 0 = never")
    seed: int = Field(1, ge=0, le=SEED_MAX, description="random seed of the wave amplitudes")
    wave_count: int = Field(256, ge=1, le=4096, description="components of the sum-of-sines / Gerstner models")
    gerstner_steepness: float = Field(0.8, ge=0, le=3, description="Gerstner steepness q [-]")
    fractal_gamma: float = Field(0.0, ge=0, le=2, description="weight γ of the fractal detail ζ = η + γ η_fractal [-]; 0 = off")
    fractal_size: int = Field(512, ge=16, le=4096, description="points per side of the periodic fractal tile (power of 2)")
    surface_tension: float = Field(0.0, ge=0, le=0.1, description="surface tension σ of the dispersion relation "
                                   "ω² = (g k + σ k³/ρ) tanh(k d) [N m⁻¹]; 0 = gravity waves only, 0.074 = sea water")
    hs: float | None = Field(None, gt=0, le=30, description="sea-state form: significant wave height Hs = 4 √m0 [m]")
    tp: float | None = Field(None, ge=TP_RANGE[0], le=TP_RANGE[1], description="sea-state form: peak period [s]")
    sigma_a: float = Field(0.07, gt=0, le=0.5, description="sea-state form: JONSWAP peak width below the peak [-]")
    sigma_b: float = Field(0.09, gt=0, le=0.5, description="sea-state form: JONSWAP peak width above the peak [-]")
    direction: float | None = Field(None, ge=-360, le=360, description="sea-state form: mean direction of travel, "
                                    "counter-clockwise from +x [deg] (default: wind_direction)")
    spreading_s: float = Field(10.0, ge=0, le=1000, description="sea-state form: cos-2s spreading parameter s [-]")
    partitions: tuple[PartitionSettings, ...] = Field((), description="sea-state form: further partitions (swells)")
    spectrum_file: str | None = Field(None, description="file form: a 2-D spectrum E(f, θ) that wavespectra reads")
    spectrum_format: Literal["auto", "swan", "ww3", "netcdf", "octopus", "ncswan", "era5", "wwm", "json"] = Field(
        "auto", description="file form: wavespectra reader (auto: from the file name)")
    spectrum_time: str | None = Field(None, description="file form: time of the spectrum, ISO 8601 (default: the first)")
    spectrum_site: int = Field(0, ge=0, description="file form: index of the site in the file [-]")
    spectrum_tail: float = Field(5.0, ge=0, le=8, description="file form: exponent n of the f⁻ⁿ tail beyond the "
                                 "file's last frequency (its shorter waves; WAVEWATCH III's 5) [-]; 0 = none")

    @model_validator(mode="before")
    @classmethod
    def _form_spectrum(cls, data):
        # NOTE: one default per form: the wind form's is the default scene's Elfouhaily sea, the sea-state
        # form's (hs, tp) JONSWAP, the spectrum its statistics are usually given for.
        if isinstance(data, dict) and "spectrum" not in data and ({"hs", "tp"} & data.keys()):
            return {**data, "spectrum": "JONSWAP 1973"}
        return data

    @field_validator("fractal_size")
    @classmethod
    def _power_of_two(cls, value: int) -> int:
        if value & (value - 1):
            raise ValueError(f"expected a power of two, got {value}")
        return value

    @field_validator("resolution")
    @classmethod
    def _even(cls, value: int) -> int:
        if value % 2:
            raise ValueError(f"expected an even number of grid points, got {value}")
        return value

    @model_validator(mode="after")
    def _consistent(self) -> "OceanSettings":
        if self.spectrum == "Phillips 2001" and self.spreading is not None:
            raise ValueError("spreading must be left out for 'Phillips 2001' (it has its own cos² spreading)")
        if self.spectrum == "Elfouhaily 1997" and self.spreading is not None:
            raise ValueError("spreading must be left out for 'Elfouhaily 1997' (it has its own spreading)")
        if self.alpha is not None and self.spectrum in ("JONSWAP 1973", "TMA 1985"):
            raise ValueError("alpha follows from the fetch for JONSWAP/TMA; leave it out")
        if self.alpha is not None and self.spectrum == "Elfouhaily 1997":
            raise ValueError("alpha follows from the wave age and wind stress for 'Elfouhaily 1997'; leave it out")
        if self.gamma != 3.3 and self.spectrum == "Elfouhaily 1997":
            raise ValueError("gamma follows from the inverse wave age for 'Elfouhaily 1997'; leave it out")
        # NOTE: by value, not by the keys a file named: a scene re-validated with overrides names every key.
        given = {name for name, info in type(self).model_fields.items() if getattr(self, name) != info.default}
        if self.spectrum in ("Phillips 2001", "Pierson-Moskowitz 1964") and given & {"fetch", "gamma"}:
            raise ValueError(f"{' and '.join(sorted(given & {'fetch', 'gamma'}))}: {self.spectrum!r} has no fetch "
                             "law or peak enhancement; leave it out")
        wind = given & {"wind_speed", "fetch", "swell_height", "swell_period", "swell_direction", "swell_spreading_s"}
        state = given & {"hs", "tp", "sigma_a", "sigma_b", "direction", "spreading_s", "partitions"}
        file = given & {"spectrum_file", "spectrum_format", "spectrum_time", "spectrum_site", "spectrum_tail"}
        forms = [name for name, keys in (("wind (wind_speed, fetch)", wind), ("sea state (hs, tp)", state),
                                         ("file (spectrum_file)", file)) if keys]
        if len(forms) > 1:
            keys = ", ".join(sorted(wind | state | file))
            raise ValueError(f"give the sea in exactly one form, got {' and '.join(forms)} ({keys})")
        if state:
            if self.hs is None or self.tp is None:
                raise ValueError("the sea-state form needs both hs [m] and tp [s]")
            if self.spectrum not in SEA_STATE_SPECTRA:
                raise ValueError(f"the sea-state form (hs, tp) takes spectrum {' or '.join(map(repr, SEA_STATE_SPECTRA))}, "
                                 f"got {self.spectrum!r}")
            if self.spreading is not None:
                raise ValueError("the sea-state form spreads with cos-2s (spreading_s); leave spreading out")
            if self.alpha is not None:
                raise ValueError("alpha follows from hs and tp in the sea-state form; leave it out")
        if file and self.spectrum_file is None:
            raise ValueError("spectrum_format, spectrum_time, spectrum_site and spectrum_tail need spectrum_file")
        if 0 < self.spectrum_tail <= 1:
            raise ValueError("spectrum_tail: 0 (no tail) or > 1 (a finite variance)")
        if file and given & {"spectrum", "spreading", "gamma", "alpha", "wind_direction"}:
            extra = ", ".join(sorted(given & {"spectrum", "spreading", "gamma", "alpha", "wind_direction"}))
            raise ValueError(f"the file form takes the spectrum from spectrum_file; leave out {extra}")
        if self.surface_tension > 0 and self.model != "FFT":
            raise ValueError("surface_tension is applied by model 'FFT' only")
        return self

    @property
    def form(self) -> str:
        """How the sea is given: ``"wind"``, ``"sea state"`` or ``"file"``."""
        if self.spectrum_file is not None:
            return "file"
        return "sea state" if self.hs is not None else "wind"


class MeshSettings(_Section):
    """The rendered water body.

    ``kind = "patch"``: one FFT patch as a closed box (the whole patch).
    ``kind = "radial"``: a camera-centred polar grid with square cells growing
    with distance, out to ``outer_radius`` (the horizon), sampling every cascade.
    """

    kind: Literal["patch", "radial"] = "radial"
    inner_radius: float = Field(0.5, gt=0, description="radius of the first ring around the camera's nadir [m]")
    outer_radius: float = Field(8000.0, gt=0, le=1.0e6, description="radius of the last ring [m]")
    segments: int = Field(384, ge=8, le=16384, description="vertices per ring [-]")

    @model_validator(mode="after")
    def _radii(self) -> "MeshSettings":
        if self.outer_radius <= self.inner_radius:
            raise ValueError("outer_radius must exceed inner_radius")
        return self


class FoamSettings(_Section):
    """Whitecaps: breaking crests make foam that ages (fresh, then fading) and decays (docs/whitecaps.md).

    ``criterion = "crest acceleration"`` (default): a crest breaks where the
    whole sea's downward acceleration exceeds ``breaking_acceleration`` × g,
    judged on the Jacobian of the waves longer than ``filter_spacing`` allows
    (:func:`oceanrender.waves.foam.crest_acceleration_threshold`); the one
    constant α was fitted once, at 12 m s⁻¹. ``"Jacobian"``: foam where J <
    ``threshold`` (the older, wind-blind rule; ``threshold`` only then).
    """

    enabled: bool = True
    criterion: Literal["crest acceleration", "Jacobian"] = "crest acceleration"
    breaking_acceleration: float = Field(
        0.665, gt=0, le=2, description="α: crests break where a_z < −α g (whole-sea statistics) [g]; fitted at 12 m s⁻¹")
    threshold: float | None = Field(
        None, ge=-1, le=1, description="criterion 'Jacobian' only: foam forms where J is below this [-]")
    filter_spacing: float = Field(
        0.1, gt=0, le=10, description="the foam's Jacobian keeps the waves a mesh of this spacing carries [m]")
    decay_time: float = Field(2.0, gt=0, le=60, description="e-folding time of the whitecap coverage [s]")
    fresh_decay_time: float | None = Field(
        None, gt=0, le=60, description="e-folding time of a patch's reflectance [s]; None: Koepke's (1984) 0.4")
    gain: float = Field(1000.0, gt=0, le=1e4,
                        description="production rate per unit of J below the threshold [s⁻¹]; large: a breaking crest covers the water at once")
    history: float = Field(3.0, gt=0, le=10, description="history simulated before each frame, in decay times [-]")
    time_step: float = Field(0.25, ge=0.01, le=5, description="step of the foam history's fixed time grid [s]")
    radius: float = Field(200.0, gt=0, le=1e5,
                          description="foam is tracked per vertex this far from the camera, its mean beyond [m]")
    albedo: float = Field(0.55, ge=0, le=1, description="visible reflectance of fresh foam (Whitlock 1982) [-]")
    whitewater_dissipation: float = Field(
        100.0, gt=0, le=1e6, description="coast: white water where bores dissipate more than this [W m⁻²]")

    @model_validator(mode="after")
    def _criterion_keys(self) -> "FoamSettings":
        if self.criterion == "Jacobian" and self.threshold is None:
            raise ValueError("criterion 'Jacobian' needs a threshold (foam where J < threshold) [-]")
        if self.criterion == "crest acceleration" and self.threshold is not None:
            raise ValueError("threshold applies to criterion 'Jacobian' only; 'crest acceleration' uses "
                             "breaking_acceleration [g]")
        if self.history * self.decay_time / self.time_step > 2000:
            raise ValueError(f"history × decay_time / time_step = "
                             f"{self.history * self.decay_time / self.time_step:.0f} steps per frame; at most 2000")
        return self


class WaterSettings(_Section):
    """The water body and its medium."""

    depth: float = Field(1000.0, gt=0, le=11_000, description="depth of the water body's flat bottom [m]; without "
                         "bottom_albedo the water below it is deep (its light lost): deep enough for clear water")
    ior: float | None = Field(None, ge=1.1, le=2.0, description="refractive index of water [-] (a surface that "
                                                               "refracts: 1.1 to 2); left out: from temperature and "
                                                               "salinity when either is given (Quan & Fry 1995, at "
                                                               "550 nm), else 1.333")
    temperature: float | None = Field(None, ge=0, le=40, description="water temperature [°C], 0 to 40 (the range "
                                                                      "of the pure-water absorption model): the "
                                                                      "absorption of pure water (WOPP v3 Ψ_T) and the "
                                                                      "refractive index")
    salinity: float | None = Field(None, ge=0, le=40, description="salinity [PSU], 0 to 40 (the range of the "
                                                                   "pure-water absorption model): the absorption "
                                                                   "(WOPP v3 Ψ_S), the refractive index and the "
                                                                   "scattering of sea water (Morel 1974)")
    iop_table: str = Field("pure_seawater.csv", min_length=1, max_length=4096,
                           description="table of a, b [m⁻¹]: a bare file name is in spectra/, a path is relative "
                                       "to the scene file")
    jerlov_type: Literal["IB", "II", "III", "1C", "3C", "5C"] | None = Field(
        None, description="a Jerlov water type's measured IOPs (Williamson & Hollins 2022) instead of the table")
    bottom_albedo: float | None = Field(None, ge=0, le=1, description="open sea: an opaque Lambertian seafloor "
                                                                     "of this reflectance on the water body's flat "
                                                                     "bottom [-]; left out: none (deep water)")
    surface_roughness: float | Literal["auto"] = Field(
        "auto", description="Beckmann α of the surface [-], or 'auto' for the slopes of the waves finer than the mesh"
    )

    @field_validator("surface_roughness")
    @classmethod
    def _roughness(cls, value: float | str) -> float | str:
        if not isinstance(value, str) and not 0 <= value <= 1:
            raise ValueError(f"expected 'auto' or a Beckmann α in [0, 1], got {value}")
        return value

    @model_validator(mode="after")
    def _ior_or_water_state(self) -> "WaterSettings":
        if self.ior is not None and (self.temperature is not None or self.salinity is not None):
            raise ValueError("ior: leave it out when temperature or salinity is given (the index follows from "
                             "them, Quan & Fry 1995), or give ior alone")
        return self


class CompositionSettings(_Section):
    """What is in the water (issue 4): a preset and/or concentrations of each component.

    Keys left out take the preset's value (or zero without a preset). The water's
    temperature and salinity are ``[water]`` keys.
    """

    preset: Literal["clear open ocean", "green coastal", "turbid brown estuary"] | None = None
    chlorophyll_mg_m3: float | None = Field(None, ge=0, le=1000, description="chlorophyll a [mg m⁻³]")
    soil_g_m3: float | None = Field(None, ge=0, le=10_000, description="soil particles [g m⁻³]")
    kaolinite_g_m3: float | None = Field(None, ge=0, le=10_000, description="kaolinite clay [g m⁻³]")
    illite_g_m3: float | None = Field(None, ge=0, le=10_000, description="illite clay [g m⁻³]")
    calcite_g_m3: float | None = Field(None, ge=0, le=10_000, description="limestone/calcite particles [g m⁻³]")
    cdom_a440_per_m: float | None = Field(None, ge=0, le=100, description="CDOM absorption at 440 nm [m⁻¹]")
    cdom_slope_per_nm: float | None = Field(None, ge=0.005, le=0.03, description="CDOM spectral slope [nm⁻¹]")
    phytoplankton_absorption: Literal["Bricaud 1998", "Hoepffner-Sathyendranath 1991"] | None = Field(
        None, description="phytoplankton absorption: Bricaud et al. (1998)'s measured a_φ = A_φ Chl^E_φ (the "
                          "default), or the Gaussian-band model of Hoepffner & Sathyendranath (1991) with packaging")
    particle_phase: Literal["Henyey-Greenstein", "Fournier-Forand", "Petzold"] = Field(
        "Henyey-Greenstein", description="phase function of the particles: one HG lobe with g(λ) fitted to "
                                         "b_bp/b_p, Fournier-Forand per component, or Petzold's measured San Diego "
                                         "Harbor function, tabulated (docs/optics.md)")


#: Materials of ``[[objects]]`` (docs/objects.md): Mitsuba's ``diffuse``, ``roughplastic``,
#: ``roughconductor`` and ``roughdielectric``.
OBJECT_MATERIALS = ("diffuse", "rough plastic", "conductor", "dielectric")
#: Metals of ``material = "conductor"``: Mitsuba's measured spectral n, k tables of those names.
CONDUCTORS = ("Ag", "Al", "Au", "Cr", "Cu")


class ObjectSettings(_Section):
    """One ``[[objects]]`` entry: a mesh file, its pose and motion, and a material.

    The mesh's own frame: x forward (the bow), y to the left, z up, in metres ×
    ``scale``; for a floating object its origin is on the still waterline.
    """

    name: str = Field(..., pattern=f"^{SAFE_NAME}$", description="the object's name (letters, digits, _ . -)")
    mesh: str = Field(..., min_length=1, max_length=4096,
                      description="OBJ, PLY, glTF or GLB file, relative to the scene file")
    scale: float = Field(1.0, gt=0, le=1e4, description="scale of the mesh's units to metres [-]")
    position: Vec3 = Field((0.0, 0.0, 0.0), description="where the mesh's origin is at t = 0 [m]; a floating "
                                                        "object's z is its rest height above the still level")
    heading: float = Field(0.0, ge=-360, le=360, description="where the bow (+x) points, clockwise from north [deg]")
    pitch: float = Field(0.0, ge=-90, le=90, description="bow up [deg] (a floating object takes it from the sea)")
    roll: float = Field(0.0, ge=-180, le=180, description="starboard down [deg] (floating: from the sea)")
    speed: float = Field(0.0, ge=0, le=50, description="speed along the heading [m s⁻¹]")
    floating: bool = Field(False, description="heave, pitch and roll from the sea under the waterline, each frame")
    response_time: float = Field(1.0, ge=0, le=30, description="floating: time constant of the pose's critically "
                                                               "damped response to the sea [s]; 0: none")
    wake: bool = Field(True, description="leave the Kelvin wake of linear theory when moving (speed > 0)")
    material: Literal["diffuse", "rough plastic", "conductor", "dielectric"] = "diffuse"
    albedo: tuple[Annotated[float, Field(ge=0, le=1)], Annotated[float, Field(ge=0, le=1)],
                  Annotated[float, Field(ge=0, le=1)]] = Field(
        (0.5, 0.5, 0.5), description="sRGB reflectance (linear, 0 to 1), upsampled to a spectrum by Mitsuba")
    albedo_texture: str | None = Field(None, min_length=1, max_length=4096,
                                       description="an sRGB image instead of albedo (the mesh needs texture "
                                                   "coordinates), relative to the scene file")
    albedo_spectrum: str | None = Field(None, min_length=1, max_length=4096,
                                        description="a reflectance spectrum instead of albedo: a table "
                                                    "wavelength_nm,reflectance over 360-830 nm, relative to the "
                                                    "scene file")
    roughness: float = Field(0.1, ge=0.001, le=1, description="Beckmann α of rough plastic, conductor, dielectric [-]")
    conductor: Literal["Ag", "Al", "Au", "Cr", "Cu"] = Field("Al", description="the metal of a conductor")
    ior: float = Field(1.5, ge=1.0, le=3.0, description="refractive index of a dielectric [-]")

    @model_validator(mode="after")
    def _keys_of_its_kind(self) -> "ObjectSettings":
        if self.floating and (self.pitch != 0 or self.roll != 0):
            raise ValueError(f"{self.name}: pitch and roll come from the sea for a floating object; leave them out")
        for key in ("albedo_texture", "albedo_spectrum"):
            if getattr(self, key) is not None and self.material not in ("diffuse", "rough plastic"):
                raise ValueError(f"{self.name}: {key} applies to 'diffuse' and 'rough plastic' only")
        if self.albedo_texture is not None and self.albedo_spectrum is not None:
            raise ValueError(f"{self.name}: give albedo_texture or albedo_spectrum, not both")
        return self


#: Interpolations of keyframed motion (see :mod:`oceanrender.scene.motion`).
Interpolation = Literal["monotone cubic", "Catmull-Rom"]


def _first_key_fills(data, fields: dict[str, object], section: str) -> dict:
    """Fill the static keys of an animated section from its motion; refuse ones that contradict it.

    ``fields`` maps each static key to its value from the motion. A value
    written in the file must equal it (to 1e-9), so that a file, and the
    same settings dumped and validated again (:func:`with_overrides`), mean
    one thing.
    """
    data = dict(data)
    for name, value in fields.items():
        given = data.get(name)
        if given is None:
            data[name] = value
            continue
        try:
            same = all(abs(float(a) - float(b)) <= 1e-9 * max(1.0, abs(float(b)))
                       for a, b in zip(_as_tuple(given), _as_tuple(value), strict=True))
        except (TypeError, ValueError):
            same = False
        if not same:
            raise ValueError(f"{name} = {given!r} contradicts the motion, which gives {value!r} here; "
                             f"leave {name} out when [{section}] is animated")
    return data


def _as_tuple(value) -> tuple:
    return tuple(value) if isinstance(value, (list, tuple)) else (value,)


def _key_value(key, name: str):
    return key.get(name) if isinstance(key, dict) else getattr(key, name, None)


class SunKeySettings(_Section):
    """One sun keyframe (``[[sun.keys]]``)."""

    time: float = Field(..., ge=-1.0e6, le=1.0e6, description="key time, t = frame / fps [s]")
    elevation: float = Field(..., ge=MIN_SUN_ELEVATION, le=90,
                             description="sun elevation above the horizon at the key [deg]")
    azimuth: float = Field(..., ge=-720, le=720, description="sun azimuth clockwise from north (+y) [deg]; "
                                                             "write 350 then 370 to pass through north")


class SolarClockSettings(_Section):
    """The sun over a place as a clock runs (``[sun.clock]``): NOAA solar position at start + time_scale·t."""

    latitude: float = Field(..., ge=-90, le=90, description="geographic latitude, north positive [deg]")
    longitude: float = Field(..., ge=-180, le=180, description="longitude, east positive [deg]")
    start: AwareDatetime = Field(..., description="clock instant of scene time t = 0, ISO 8601 with a UTC offset, "
                                                  "e.g. 2024-06-21T18:30:00+02:00")
    time_scale: float = Field(1.0, ge=-1.0e6, le=1.0e6,
                              description="simulated (clock) seconds per scene second [-]; 600 = 10 min per second")
    apparent: bool = Field(True, description="use the refracted (apparent) elevation, as seen, or the geometric one")
    pressure: float = Field(1010.0, gt=0, le=1100, description="surface pressure for the refraction [hPa]")
    temperature: float = Field(10.0, ge=-90, le=60, description="air temperature for the refraction [°C]")

    def angles_at(self, t: float) -> tuple[float, float]:
        """(elevation, azimuth) of the sun at scene time t [s] [deg]."""
        clock = SolarClock(self.latitude, self.longitude, self.start, self.time_scale, self.apparent,
                           self.pressure, self.temperature)
        return tuple(clock.at(t))


class EnvironmentSettings(_Section):
    """``[environment]``: an equirectangular HDR image as the sky instead of ``sunsky``'s (docs/environment.md).

    The map's top row is the zenith, its bottom row the nadir; column u (0 at the left
    edge, 1 at the right) lies at azimuth 360° u + ``rotation``, clockwise from north (+y).
    """

    map: str = Field(..., min_length=1, max_length=4096,
                     description="equirectangular EXR or Radiance .hdr, 2:1, relative to the scene file")
    scale: float | None = Field(None, gt=0, le=1e9, description="radiance per map unit: an RGB of 1 is Mitsuba's "
                                                                 "upsampled white of about 1 W m⁻² sr⁻¹ nm⁻¹")
    illuminance: float | None = Field(None, gt=0, le=2e5, description="instead of scale: the map's illuminance on "
                                                                       "a horizontal plane [lx] (the sun not counted)")
    rotation: float = Field(0.0, ge=-360, le=360, description="azimuth of the map's left edge, clockwise from north "
                                                              "[deg]")
    sun: bool = Field(False, description="add the [sun]'s solar disk (sunsky's sun, no sky) to the map")

    @model_validator(mode="after")
    def _one_scale(self) -> "EnvironmentSettings":
        if self.scale is not None and self.illuminance is not None:
            raise ValueError("give scale or illuminance, not both")
        return self


class SunSettings(_Section):
    """Sun and sky: Mitsuba's ``sunsky`` (Hosek & Wilkie 2012/2013).

    The sun may move: ``[[sun.keys]]`` (at least two keyframes of elevation
    and azimuth, joined by ``interpolation``) or ``[sun.clock]`` (a place and
    a clock), not both. Then ``elevation`` and ``azimuth`` are those of the
    motion at its first key (keys) or at t = 0 s (clock); leave them out (if
    written they must equal those).
    """

    elevation: float = Field(22.0, ge=MIN_SUN_ELEVATION, le=90, description="sun elevation above the horizon [deg]")
    azimuth: float = Field(30.0, ge=-360, le=360, description="sun azimuth, clockwise from north (+y) [deg]")
    turbidity: float = Field(3.0, ge=1, le=10, description="atmospheric turbidity [-]")
    ground_albedo: float = Field(0.1, ge=0, le=1, description="ground albedo of the sky model [-]")
    sun_scale: float = Field(1.0, ge=0, le=1e3, description="scale of the solar radiance [-]")
    sky_scale: float = Field(1.0, ge=0, le=1e3, description="scale of the sky radiance [-]")
    keys: tuple[SunKeySettings, ...] = Field((), description="sun keyframes (time [s], elevation, azimuth [deg])")
    clock: SolarClockSettings | None = Field(None, description="a place and a clock instead of keyframes")
    interpolation: Interpolation = Field("monotone cubic", description="curve through the sun keyframes")

    @model_validator(mode="before")
    @classmethod
    def _static_from_motion(cls, data):
        if not isinstance(data, dict):
            return data
        keys, clock = data.get("keys") or (), data.get("clock")
        if keys and clock is not None:
            raise ValueError("give either [[sun.keys]] or [sun.clock], not both")
        if keys and isinstance(keys, (list, tuple)):
            first = keys[0]
            elevation, azimuth = _key_value(first, "elevation"), _key_value(first, "azimuth")
            # NOTE: a key out of range is reported with its own key path, not through the static fields.
            if (isinstance(elevation, (int, float)) and isinstance(azimuth, (int, float))
                    and MIN_SUN_ELEVATION <= elevation <= 90 and -720 <= azimuth <= 720):
                return _first_key_fills(data, {"elevation": float(elevation),
                                               "azimuth": float(azimuth) % 360.0}, "sun")
        if clock is not None:
            try:
                settings = SolarClockSettings.model_validate(clock)
            except ValidationError:
                return data  # reported with its key when the field itself is validated
            elevation, azimuth = settings.angles_at(0.0)
            if not elevation >= MIN_SUN_ELEVATION:
                raise ValueError(f"[sun.clock]: the sun is below the horizon (or within {MIN_SUN_ELEVATION}° of it) "
                                 f"at start ({settings.start.isoformat()}, t = 0 s): elevation {elevation:.2f} deg; sunsky needs it above")
            return _first_key_fills(data, {"elevation": elevation, "azimuth": azimuth}, "sun")
        return data

    @field_validator("keys")
    @classmethod
    def _key_times(cls, value: tuple[SunKeySettings, ...]) -> tuple[SunKeySettings, ...]:
        if value:
            _check_key_times([key.time for key in value], "sun")
        return value

    @property
    def animated(self) -> bool:
        """Whether the sun moves (keys or a clock)."""
        return bool(self.keys) or self.clock is not None


def _check_key_times(times: list[float], section: str) -> None:
    if len(times) < 2:
        raise ValueError(f"[[{section}.keys]] needs at least 2 keyframes, got {len(times)}")
    for i in range(1, len(times)):
        if not times[i] > times[i - 1]:
            raise ValueError(f"key times must strictly increase, but key {i + 1} at time = {times[i]:g} s "
                             f"follows time = {times[i - 1]:g} s")


class CameraKeySettings(_Section):
    """One camera keyframe (``[[camera.keys]]``)."""

    time: float = Field(..., ge=-1.0e6, le=1.0e6, description="key time, t = frame / fps [s]")
    position: Vec3 = Field(..., description="camera position [m]")
    target: Vec3 = Field(..., description="point looked at [m]")
    fov: float = Field(..., gt=0, lt=180, description="horizontal field of view [deg]")

    @model_validator(mode="after")
    def _distinct(self) -> "CameraKeySettings":
        if self.position == self.target:
            raise ValueError(f"camera key at time = {self.time:g} s: target must differ from position")
        return self


class CameraViewSettings(_Section):
    """Another viewpoint of the same scene (``[camera.views.NAME]``), rendered with ``oceanrender render --view NAME``."""

    position: Vec3 = Field(..., description="camera position [m]")
    target: Vec3 = Field(..., description="point looked at [m]")
    fov: float = Field(60.0, gt=0, lt=180, description="horizontal field of view [deg]")

    @model_validator(mode="after")
    def _distinct(self) -> "CameraViewSettings":
        if self.position == self.target:
            raise ValueError("target must differ from position")
        return self


class CameraSettings(_Section):
    """Pinhole camera (perspective).

    The camera may move: ``[[camera.keys]]``, at least two keyframes of
    position, target and fov at strictly increasing times, joined by
    ``interpolation``. Then ``position``, ``target`` and ``fov`` are the
    first key's; leave them out (if written they must equal it).
    """

    position: Vec3 = (0.0, 0.0, 8.0)
    target: Vec3 = (0.0, 40.0, 0.0)
    fov: float = Field(60.0, gt=0, lt=180, description="horizontal field of view [deg]")
    keys: tuple[CameraKeySettings, ...] = Field((), description="camera keyframes (time [s], position, target [m], "
                                                                "fov [deg])")
    interpolation: Interpolation = Field("monotone cubic", description="curve through the camera keyframes")
    views: dict[Annotated[str, Field(pattern=f"^{SAFE_NAME}$", max_length=40)], CameraViewSettings] = Field(
        default_factory=dict, description="other still viewpoints by name (render with --view NAME into the "
                                          "folder <name>_<view>)")

    @model_validator(mode="before")
    @classmethod
    def _static_from_keys(cls, data):
        if not isinstance(data, dict) or not data.get("keys") or not isinstance(data["keys"], (list, tuple)):
            return data
        first = data["keys"][0]
        values = {name: _key_value(first, name) for name in ("position", "target", "fov")}
        if any(value is None for value in values.values()):
            return data  # the key itself is reported as incomplete
        try:
            values = {"position": tuple(map(float, values["position"])),
                      "target": tuple(map(float, values["target"])), "fov": float(values["fov"])}
        except (TypeError, ValueError):
            return data
        if not 0 < values["fov"] < 180 or len(values["position"]) != 3 or len(values["target"]) != 3:
            return data  # reported with the key's own path
        return _first_key_fills(data, values, "camera")

    @field_validator("keys")
    @classmethod
    def _key_times(cls, value: tuple[CameraKeySettings, ...]) -> tuple[CameraKeySettings, ...]:
        if value:
            _check_key_times([key.time for key in value], "camera")
        return value

    @model_validator(mode="after")
    def _distinct(self) -> "CameraSettings":
        if self.position == self.target:
            raise ValueError("camera target must differ from its position")
        if self.views and self.keys:
            raise ValueError("views are still viewpoints: leave them out of a camera with keys")
        return self

    @property
    def animated(self) -> bool:
        """Whether the camera moves (keys)."""
        return bool(self.keys)


class VisionSettings(_Section):
    """The vision model Φ: brightness and chromatic adaptation, display."""

    brightness: Literal["Reinhard Devlin 2005", "Ward 1994", "Ferwerda 1996"] = Field(
        "Reinhard Devlin 2005", description="brightness adaptation: the compressive photoreceptor model "
                                            "(default) or a linear scale factor")
    chromatic_transform: Literal["Von Kries", "Bradford", "CAT02", "CAT16", "XYZ Scaling"] = "Von Kries"
    adaptation_luminance: float | Literal["frame", "daylight"] = Field(
        "frame", description="world adaptation luminance [cd m⁻²], 'frame' for the log-average of what the "
                             "camera sees (followed over time, see adaptation_time), or 'daylight' for an 18 % "
                             "grey card under the scene's sun and sky"
    )
    adaptation_time: float = Field(
        0.4, ge=0, le=60, description="time constant of the eye's light adaptation [s] for adaptation_luminance = "
                                      "'frame': a step in scene luminance is 95 % adapted to after 3x this; 0: "
                                      "every frame adapts at once to its own log-average")
    exposure: float = Field(0.0, ge=-10, le=10, description="exposure compensation [EV]: +1 doubles the light "
                                                            "before the display response")
    display_luminance: float = Field(100.0, ge=1, le=10_000, description="display white luminance [cd m⁻²]")

    @field_validator("adaptation_luminance")
    @classmethod
    def _positive(cls, value: float | str) -> float | str:
        if not isinstance(value, str) and not (value > 0 and math.isfinite(value)):
            raise ValueError(f"expected 'frame', 'daylight' or a finite luminance > 0 cd/m², got {value}")
        return value


#: How closely [ocean] wave_depth must match the offshore side's mean depth with waves = "open sea" [-].
OPEN_SEA_DEPTH_MATCH = 0.05

#: Array files accepted for bathymetry and the initial surface (rows = y south → north, columns = x).
ARRAY_SUFFIXES = (".npy", ".exr")


class CoastalSettings(_Section):
    """Coastal zone: the 2D shallow-water equations over a bathymetry (``oceanrender.coastal``).

    The grid has ``cells = [nx, ny]`` cells over ``size = [Lx, Ly]`` m with its
    south-west corner at ``origin``. ``bathymetry = "plane beach"`` is a beach
    rising towards the south: z_b = still_level − slope·(y − shoreline_y), no
    deeper than ``offshore_depth`` (the sea is to the north); a path to a
    ``.npy`` or ``.exr`` file (relative to the scene file; shape (ny, nx),
    elevation in m) is read instead. Waves enter through ``offshore_side``.
    """

    size: tuple[Annotated[float, Field(gt=0)], Annotated[float, Field(gt=0)]] = Field(
        (40.0, 30.0), description="domain extent along x and y [m]")
    cells: tuple[Annotated[int, Field(ge=4, le=8192)], Annotated[int, Field(ge=4, le=8192)]] = Field(
        (320, 240), description="cells along x and y [-]")
    origin: tuple[float, float] = Field((-20.0, -6.0), description="world (x, y) of the grid's south-west corner [m]")
    rotation: float = Field(0.0, ge=-360, le=360, description="angle from the world axes to the grid's axes, "
                                                              "counter-clockwise about origin [deg]")
    blend_width: float = Field(40.0, gt=0, le=1e5, description="('open sea') width of the zone inside the offshore "
                                                               "and lateral sides where the solver's surface fades "
                                                               "into the FFT sea's [m]")
    outer_slope: float = Field(0.02, ge=0, le=1, description="('open sea') fall of the sea floor per metre beyond "
                                                             "the offshore side [-]")
    outer_depth: float = Field(30.0, gt=0, le=11_000, description="('open sea') greatest depth of the sea floor "
                                                                  "beyond the offshore side [m]")
    bathymetry: str = Field("plane beach", description="'plane beach', or a .npy/.exr file of bed elevation [m]")
    still_level: float = Field(0.0, description="still-water level [m]")
    shoreline_y: float = Field(0.0, description="('plane beach') y where the bed meets the still level [m]")
    slope: float = Field(0.05, gt=0, le=1, description="('plane beach') rise of the bed per metre towards the shore [-]")
    offshore_depth: float = Field(2.0, gt=0, description="('plane beach') greatest still-water depth [m]")
    initial_surface: str = Field("still", description="'still', or a .npy/.exr file of the surface elevation η [m]")
    initial_u: float | str = Field(0.0, description="initial depth-averaged velocity along the grid's x axis: a "
                                                    "uniform value or a .npy/.exr file (ny, nx) [m s⁻¹]; 0 on dry cells")
    initial_v: float | str = Field(0.0, description="initial depth-averaged velocity along the grid's y axis: a "
                                                    "uniform value or a .npy/.exr file (ny, nx) [m s⁻¹]; 0 on dry cells")
    waves: Literal["train", "spectrum", "open sea", "none"] = Field(
        "train", description="incident waves: a monochromatic 'train', components of the [ocean] 'spectrum', the "
                             "long waves of the surrounding FFT sea ('open sea': the domain sits inside it, to the "
                             "horizon), or 'none'")
    wave_height: float = Field(0.3, ge=0, le=10, description="('train') crest-to-trough height [m]")
    wave_period: float = Field(5.0, gt=0, le=30, description="('train') period [s]")
    wave_direction: float = Field(-90.0, ge=-360, le=360,
                                  description="('train') direction of travel, counter-clockwise from +x [deg]")
    wave_count: int = Field(32, ge=1, le=1024, description="('spectrum') number of components")
    offshore_side: Literal["north", "south", "east", "west"] = Field("north", description="side the waves enter")
    lateral: Literal["wall", "transmissive"] = Field("transmissive", description="the two sides beside the offshore one")
    order: Literal[1, 2] = Field(2, description="1: first-order scheme; 2: second order")
    scheme: Literal["kinetic", "HLL split", "kinetic split", "dg"] = Field(
        "kinetic", description="'kinetic': the unsplit kinetic scheme; 'HLL split' (order 2): HLLE flux in "
                               "Strang-split sweeps; 'kinetic split': kinetic flux in Strang-split sweeps, "
                               "MUSCL-Hancock at order 2, cfl up to 1; 'dg' (order 2): the dissertation's "
                               "discontinuous Galerkin P1 with the kinetic flux, cfl up to 1/3 (docs/coastal.md)")
    limiter: Literal["MC", "van Leer", "minmod", "TVB"] = Field(
        "MC", description="(order 2) slope limiter; the dissertation's is minmod, MC halves the error here; "
                          "scheme 'dg' takes 'minmod' or 'TVB' (minmod kept where a slope is below "
                          "tvb_m · cell²: smooth extrema are not clipped)")
    tvb_m: float | None = Field(None, ge=0, le=1e6, description="(scheme 'dg', limiter 'TVB') the TVB constant M "
                                                               "[m⁻¹]; 50 when left out")
    cfl: float = Field(0.4, gt=0, le=1, description="Courant number [-]; ≤ 1 at first order, ≤ 0.5 at second "
                                                     "(≤ 1 with scheme 'kinetic split', ≤ 1/3 with 'dg')")
    h_min: float = Field(0.002, ge=0, le=1, description="dry threshold: cells with depth ≤ h_min are land [m]")
    manning: float = Field(0.02, ge=0, le=1, description="Manning friction coefficient [s m^-1/3]")
    spinup: float = Field(20.0, ge=0, le=1e5, description="simulated time before frame 0 [s]")
    checkpoint_interval: float = Field(10.0, ge=0.1, le=1e5, description="simulated time between checkpoints [s]")
    sand_albedo: tuple[Annotated[float, Field(ge=0, le=1)], Annotated[float, Field(ge=0, le=1)]] = Field(
        (0.25, 0.45), description="sand reflectance at 400 and 700 nm (linear in between) [-]")
    rock_albedo: tuple[Annotated[float, Field(ge=0, le=1)], Annotated[float, Field(ge=0, le=1)]] = Field(
        (0.06, 0.10), description="rock reflectance at 400 and 700 nm [-]")
    rock_cover: float = Field(0.15, ge=0, le=1, description="fraction of the seafloor that is rock [-]")
    seed: int = Field(3, ge=0, le=SEED_MAX, description="seed of the rock pattern and of the spectral wave phases")

    @field_validator("scheme")
    @classmethod
    def _dg_order(cls, value: str, info) -> str:
        if value == "dg" and info.data.get("order") != 2:
            raise ValueError(f"'dg' is the P1 (second-order) scheme: it needs order = 2, got order = "
                             f"{info.data.get('order')} with scheme 'dg'")
        return value

    @field_validator("limiter")
    @classmethod
    def _limiter_of_scheme(cls, value: str, info) -> str:
        dg = info.data.get("scheme") == "dg"
        if dg and value not in ("minmod", "TVB"):
            raise ValueError(f"scheme 'dg' takes limiter 'minmod' or 'TVB', got {quoted(value)}")
        if not dg and value == "TVB":
            raise ValueError(f"'TVB' is a limiter of scheme 'dg' only (the finite-volume schemes take 'MC', "
                             f"'van Leer' or 'minmod'), got {quoted(value)} with scheme "
                             f"{quoted(info.data.get('scheme'))}")
        return value

    @field_validator("tvb_m")
    @classmethod
    def _tvb_only(cls, value: float | None, info) -> float | None:
        if value is not None and info.data.get("limiter") != "TVB":
            raise ValueError(f"is used by limiter 'TVB' only (scheme 'dg'), got tvb_m = {value} with limiter "
                             f"{quoted(info.data.get('limiter'))}")
        if value is not None and not math.isfinite(value):
            raise ValueError(f"expected a finite TVB constant >= 0 [1/m], got {value}")
        return value

    @field_validator("cfl")
    @classmethod
    def _cfl_bound(cls, value: float, info) -> float:
        if info.data.get("scheme") == "dg" and value > 1.0 / 3.0:
            raise ValueError(f"must be ≤ 1/3 with scheme 'dg' (P1 with two-stage Runge-Kutta: the stability and "
                             f"positivity bound), got {value}")
        if info.data.get("order") == 2 and info.data.get("scheme") != "kinetic split" and value > 0.5:
            raise ValueError(f"must be ≤ 0.5 at order 2 with scheme {info.data.get('scheme')!r} (the scheme's "
                             f"positivity bound; 'kinetic split' allows ≤ 1), got {value}")
        return value

    @field_validator("initial_u", "initial_v")
    @classmethod
    def _velocity(cls, value: float | str) -> float | str:
        if isinstance(value, str):
            if not value.lower().endswith(ARRAY_SUFFIXES):
                raise ValueError(f"expected a velocity [m/s] or a {'/'.join(ARRAY_SUFFIXES)} file, got {quoted(value)}")
            return value
        if not (math.isfinite(value) and abs(value) <= MAX_INITIAL_SPEED):
            raise ValueError(f"expected a finite velocity within ±{MAX_INITIAL_SPEED:g} m/s, got {value}")
        return float(value)

    @field_validator("bathymetry", "initial_surface")
    @classmethod
    def _source(cls, value: str, info) -> str:
        word = "plane beach" if info.field_name == "bathymetry" else "still"
        if value != word and not value.lower().endswith(ARRAY_SUFFIXES):
            raise ValueError(f"expected {word!r} or a {'/'.join(ARRAY_SUFFIXES)} file, got {quoted(value)}")
        return value

    @property
    def spacing(self) -> tuple[float, float]:
        """Cell size (dx, dy) [m]."""
        return self.size[0] / self.cells[0], self.size[1] / self.cells[1]

    @property
    def shape(self) -> tuple[int, int]:
        """Array shape (ny, nx) of the fields."""
        return self.cells[1], self.cells[0]


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
