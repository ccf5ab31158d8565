"""The scene's ``[[objects]]`` as Mitsuba shapes: a small set of documented materials.

| ``material``      | Mitsuba plugin    | keys used                                   |
|-------------------|-------------------|---------------------------------------------|
| ``diffuse``       | ``diffuse``       | ``albedo``, ``albedo_texture`` or ``albedo_spectrum`` |
| ``rough plastic`` | ``roughplastic``  | ``albedo`` / ``albedo_texture``, ``roughness`` (Beckmann α) |
| ``conductor``     | ``roughconductor``| ``conductor`` (Mitsuba's measured n, k), ``roughness`` |
| ``dielectric``    | ``roughdielectric``| ``ior``, ``roughness``                     |

Albedos are a measured reflectance spectrum (``albedo_spectrum``, used as it is) or sRGB
values (or an sRGB image); in the spectral variants Mitsuba turns
them into smooth reflectance spectra (Jakob & Hanika 2019, "A low-dimensional
function space for efficient spectral upsampling", Comput. Graph. Forum 38(2)).
Objects carry no medium: the part of a hull under the water is reached by rays
that travel in the water and stay in it, so it is seen through the surface and lit
through the medium; the water surface inside a closed hull is hidden by the hull.
Objects are shaded with their faces' geometric normals (no interpolated normals:
a low-polygon hull keeps its sharp edges).
"""

from __future__ import annotations

import numpy as np

from ..optics.tables import read_reflectance_table
from ..scene import ObjectSettings
from .buffers import jit_floats, jit_uints
from .scene import irregular_spectrum

__all__ = ["object_id", "object_bsdf", "object_mesh", "update_object_positions"]


def object_id(name: str) -> str:
    """Key of an object's shape in the Mitsuba scene."""
    return f"object_{name}"


def _albedo(obj: ObjectSettings) -> dict:
    if obj.albedo_texture is not None:
        return {"type": "bitmap", "filename": obj.albedo_texture, "raw": False}
    if obj.albedo_spectrum is not None:  # a measured reflectance, as it is (no upsampling)
        table = read_reflectance_table(obj.albedo_spectrum)
        return irregular_spectrum(table.wavelengths, table.columns["reflectance"])
    return {"type": "rgb", "value": [float(v) for v in obj.albedo]}


def object_bsdf(obj: ObjectSettings) -> dict:
    """The Mitsuba BSDF dict of ``obj``'s material (module table)."""
    alpha = float(obj.roughness)
    if obj.material == "diffuse":
        return {"type": "diffuse", "reflectance": _albedo(obj)}
    if obj.material == "rough plastic":
        return {"type": "roughplastic", "diffuse_reflectance": _albedo(obj), "alpha": alpha,
                "distribution": "beckmann"}
    if obj.material == "conductor":
        return {"type": "roughconductor", "material": obj.conductor, "alpha": alpha, "distribution": "beckmann"}
    return {"type": "roughdielectric", "int_ior": float(obj.ior), "ext_ior": 1.000277, "alpha": alpha,
            "distribution": "beckmann"}


def object_mesh(obj: ObjectSettings, positions: np.ndarray, faces: np.ndarray, uv: np.ndarray | None):
    """``obj`` as a Mitsuba mesh with its material, at vertex ``positions`` (V, 3) [m]."""
    import mitsuba as mi  # noqa: PLC0415

    props = mi.Properties()
    props["bsdf"] = mi.load_dict(object_bsdf(obj))
    with_uv = uv is not None and obj.albedo_texture is not None
    mesh = mi.Mesh(object_id(obj.name), len(positions), len(faces), props, has_vertex_normals=False,
                   has_vertex_texcoords=with_uv)
    params = mi.traverse(mesh)
    params["vertex_positions"] = jit_floats(positions)
    params["faces"] = jit_uints(faces)
    if with_uv:
        params["vertex_texcoords"] = jit_floats(uv)
    params.update()
    return mesh


def update_object_positions(params, name: str, positions: np.ndarray) -> None:
    """Move a loaded object's vertices to ``positions`` (V, 3) [m], in place (call ``params.update()`` after)."""
    params[f"{object_id(name)}.vertex_positions"] = jit_floats(positions)
