"""The water body of a scene, and the roughness of its surface.

:func:`scene_water_body` picks the open sea (:class:`~.open_sea.WaterBody`) or, for a
scene with a ``[coastal]`` section, the coastal body read from its simulation
(:class:`~.coastal_body.CoastalBody`), or, with ``[coastal] waves = "open sea"``,
the coast inside the open sea (:class:`~.coast_in_sea.CoastInSea`); all meet
:class:`~.frame.WaterSurface`.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..scene import Scene
from ..waves.roughness import beckmann_alpha, unresolved_slope_variance
from .frame import WaterSurface
from .open_sea import WaterBody


def scene_water_body(scene: Scene, coastal_store: str | Path | None = None) -> WaterSurface:
    """The scene's water body: the open sea, or the coast from the simulation fields in ``coastal_store``."""
    if scene.coastal is None:
        return WaterBody(scene)
    if coastal_store is None:
        raise ValueError("a coastal scene renders from its simulation's stored fields: give coastal_store")
    if scene.coastal.waves == "open sea":
        from .coast_in_sea import CoastInSea  # noqa: PLC0415

        return CoastInSea(scene, coastal_store)
    from .coastal_body import CoastalBody  # noqa: PLC0415

    return CoastalBody(scene, coastal_store)


def surface_roughness(scene: Scene, body: WaterSurface) -> float:
    """Beckmann α of the water surface [-]: the scene's, or the slopes of the waves finer than the geometry."""
    if scene.water.surface_roughness != "auto":
        return float(scene.water.surface_roughness)
    cutoff = np.pi / body.finest_cell
    return beckmann_alpha(unresolved_slope_variance(body.spectrum, cutoff))


def sun_lobe_alpha(scene: Scene, body: WaterSurface, roughness: float) -> float:
    """Beckmann roughness of the refracted-sun lobe [-]: the total rms slope of the water surface.

    ``body.total_slope_variance(roughness)`` (resolved waves plus the
    unresolved ones of Beckmann α ``roughness``), never below ``roughness``.
    """
    return float(max(beckmann_alpha(body.total_slope_variance(roughness)), roughness, 1e-3))
