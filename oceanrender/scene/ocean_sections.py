"""The sea's sections of a scene file: ``[ocean]`` (with its ``[[ocean.partitions]]``), ``[mesh]``,
``[foam]``, ``[water]`` and ``[composition]``.

Part of :mod:`.settings` (which re-exports every name here); units and conventions there.
"""

from __future__ import annotations

from typing import Literal

from pydantic import Field, field_validator, model_validator

from .section_base import SEED_MAX, _Section


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
