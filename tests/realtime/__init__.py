"""Tests of the real-time path (oceanrender.realtime), with shared synthetic inputs.

The synthetic light below stands in for Mitsuba's sun and sky where a test
checks the baking itself (no renderer needed): smooth, positive spectra on the
project's wavelength grid, and a sky that is black below the horizon.
"""

import numpy as np

from oceanrender.optics.report import REPORT_WAVELENGTHS
from oceanrender.realtime.bake import BakeSettings, SceneLight, bake_lut_set
from oceanrender.realtime.luts import envmap_directions, spectra_to_XYZ
from tests.scenes import scene_from_dict

#: A small coastal grid (as tests/coastal) and small textures: fast to bake.
TINY_COASTAL = {"cells": [24, 16], "size": [12.0, 8.0], "origin": [-6.0, -2.0], "slope": 0.2, "offshore_depth": 0.8,
                "wave_height": 0.1, "wave_period": 2.0, "order": 1, "cfl": 0.8, "spinup": 1.0,
                "checkpoint_interval": 0.5}
SMALL = BakeSettings(depth_texels=33, path_texels=17, fresnel_texels=65, sky_size=(32, 16), ripple_texels=32,
                     ripple_patch=1.0)


def synthetic_scene(coastal: bool = True, **sections):
    data = {"name": "synthetic", "vision": {"adaptation_luminance": 2000.0}, **sections}
    if coastal:
        data["coastal"] = dict(TINY_COASTAL)
    return scene_from_dict(data)


def synthetic_light(sky_size=SMALL.sky_size, constant_sky=None) -> SceneLight:
    """Sun and sky spectra [W m⁻² nm⁻¹] and a sky map; ``constant_sky`` (W,): that radiance everywhere."""
    wl = REPORT_WAVELENGTHS
    sun = 1.6 * np.exp(-(((wl - 560.0) / 220.0) ** 2))
    sky = 0.35 * (wl / 550.0) ** -4 * np.exp(-(((wl - 500.0) / 300.0) ** 2))
    directions = envmap_directions(*sky_size)
    if constant_sky is None:
        up = np.clip(directions[..., 2], 0.0, None)[..., None]
        radiance = (0.02 + 0.06 * (1.0 - up)) * (wl / 550.0) ** -4 * (up > 0)
    else:
        radiance = np.broadcast_to(constant_sky, directions.shape[:-1] + (len(wl),)).copy()
    cos_sun = np.sin(np.radians(40.0))  # the default [sun] elevation
    white = spectra_to_XYZ((sun * cos_sun + sky) / np.pi, wl)
    return SceneLight(wavelengths=wl, sun_irradiance=sun, sky_irradiance=sky, white_XYZ=white, sky_radiance=radiance)


def synthetic_lut_set(settings: BakeSettings = SMALL, coastal: bool = True, light: SceneLight | None = None,
                      adaptation: float = 2000.0):
    scene = synthetic_scene(coastal)
    return bake_lut_set(scene, light or synthetic_light(settings.sky_size), adaptation, "test", settings)
