"""The ``[coastal]`` section of a scene file: the shallow-water domain, its bathymetry, waves, scheme and
shore.

Part of :mod:`.settings` (which re-exports every name here); units and conventions there.
"""

from __future__ import annotations

import math
from typing import Annotated, Literal

from pydantic import Field, field_validator

from ..io.messages import quoted
from .arrays import MAX_INITIAL_SPEED
from .section_base import SEED_MAX, _Section


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
