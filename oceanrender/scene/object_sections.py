"""The ``[[objects]]`` entries of a scene file: a mesh, its pose and motion, and a material.

Part of :mod:`.settings` (which re-exports every name here); units and conventions there.
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field, model_validator

from .section_base import SAFE_NAME, Vec3, _Section


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
