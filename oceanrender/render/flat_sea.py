"""Water-leaving radiance of a flat, deep sea as the renderer renders it (issue 19, item 4).

A scene's water (its medium, phase function, surface IOR), sun and sky and integrator
settings, but a level sea: a 4 km wide, 1 km deep block of the water under a surface of
Beckmann roughness α = 0.02 (rms slope 1.1°: level for the light field, and rough enough
that the ``split`` integrator's in-water sun sampling, which needs a lobe, works as in a
frame). A radiance meter 1 m above the surface looks straight down; the ``split``
integrator renders it with the transmission lobe of the first water hit alone (the
renderer's own two-pass split, :func:`oceanrender.render.integrator.split_integrator`),
which is the water-leaving radiance L_w at nadir. A second meter looks straight up
(the zenith sky, reported beside it).

Why not L_down − F(0) L_sky(zenith): in clear water in the red the reflected sky is
several times L_w, so a small error of the reflected part (the microfacet surface's
reflectance against Fresnel's F(0)) swamps L_w; the split has no such difference.

Units: radiance W m⁻² sr⁻¹ nm⁻¹ (band means), wavelengths nm.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..optics.scene_water import water_ior
from ..scene import Scene
from .scene import sun_direction, sunsky_emitter, volumetric_integrator, water_medium, water_surface_bsdf

__all__ = ["FLAT_ALPHA", "FlatSeaRadiance", "flat_sea_radiance"]

FLAT_ALPHA = 0.02
"""Beckmann roughness of the 'flat' sea [-] (module docstring)."""


@dataclass(frozen=True)
class FlatSeaRadiance:
    """Band-mean radiances of :func:`flat_sea_radiance` [W m⁻² sr⁻¹ nm⁻¹], each (B,), with standard errors."""

    wavelengths: np.ndarray
    water_leaving: np.ndarray
    water_leaving_error: np.ndarray
    sky_zenith: np.ndarray


def _band_film(wavelengths: np.ndarray, half_width: float) -> dict:
    film = {"type": "specfilm", "width": 1, "height": 1, "component_format": "float32", "rfilter": {"type": "box"}}
    for i, w in enumerate(wavelengths):
        film[f"band_{i:03d}"] = {"type": "spectrum", "value": [(w - half_width, 1.0), (w + half_width - 1e-3, 1.0)]}
    return film


def _integrator(scene: Scene, lobes: str = "both") -> dict:
    """The scene's integrator and path depth; ``split`` with its in-water sun sampling over the α of the flat sea."""
    kind = scene.render.integrator
    sampling = {}
    if kind == "split":
        sampling = {"sun": sun_direction(scene.sun.elevation, scene.sun.azimuth), "water_ior": water_ior(scene),
                    "sun_lobe_alpha": FLAT_ALPHA, "lobes": lobes}
    return volumetric_integrator(kind, scene.render.max_depth, rr_depth=scene.render.roulette_depth, **sampling)


def flat_sea_scene(scene: Scene, optics, wavelengths: np.ndarray, half_width: float, spp: int) -> dict:
    """The Mitsuba scene dict of the flat sea (module docstring); sensor 0 looks down, sensor 1 up."""
    import mitsuba as mi  # noqa: PLC0415

    from .phase import register, register_tabulated  # noqa: PLC0415

    register()
    register_tabulated()
    T = mi.ScalarTransform4f
    film = _band_film(wavelengths, half_width)
    meter = {"type": "radiancemeter", "film": film, "sampler": {"type": "independent", "sample_count": spp}}
    return {
        "type": "scene",
        "integrator": _integrator(scene),
        "sky": sunsky_emitter(scene.sun),
        "water": {"type": "cube", "bsdf": water_surface_bsdf(water_ior(scene), FLAT_ALPHA),
                  "interior": water_medium(optics),
                  "to_world": T().translate([0.0, 0.0, -500.0]).scale([2000.0, 2000.0, 500.0])},
        # NOTE: off the origin, where the two triangles of the cube's top meet (a ray through their
        # shared edge can miss both in float32).
        "down": {**meter, "origin": [0.3, 0.1, 1.0], "direction": [0.0, 0.0, -1.0]},
        "up": {**meter, "origin": [0.3, 0.1, 1.0], "direction": [0.0, 0.0, 1.0]},
    }


def flat_sea_radiance(scene: Scene, optics, wavelengths, half_width: float = 2.5, spp: int = 1 << 16,
                      passes: int = 4, seed: int = 0) -> FlatSeaRadiance:
    """L_w at nadir of the scene's water under a level surface, per band (module docstring).

    Parameters
    ----------
    scene : Scene           Sun, sky, water IOR and render settings (integrator, max_depth, roulette).
    optics                  The water (:func:`oceanrender.optics.scene_water.water_optics`).
    wavelengths : (B,)      Band centres [nm]; each band is ``2 half_width`` wide.
    spp, passes, seed       Paths per pass; independent passes give the standard error.

    Needs an active Mitsuba variant.
    """
    import mitsuba as mi  # noqa: PLC0415

    if scene.render.integrator != "split":
        raise ValueError("flat_sea_radiance: needs the 'split' integrator (its transmission lobe is L_w)")
    wavelengths = np.asarray(wavelengths, dtype=float)
    loaded = mi.load_dict(flat_sea_scene(scene, optics, wavelengths, half_width, spp))
    transmission = mi.load_dict(_integrator(scene, lobes="transmission"))
    width = 2.0 * half_width
    down = np.array([np.array(mi.render(loaded, sensor=0, integrator=transmission, seed=seed + 1000 * k,
                                        spp=spp)).ravel() for k in range(passes)]) / width  # L_w: the transmission lobe
    up = np.array(mi.render(loaded, sensor=1, seed=seed + 7, spp=max(spp // 16, 256))).ravel() / width
    return FlatSeaRadiance(wavelengths=wavelengths, water_leaving=down.mean(axis=0),
                           water_leaving_error=down.std(axis=0, ddof=1) / math.sqrt(passes), sky_zenith=up)
