"""The water a scene describes: pure sea water, a Jerlov water type, or a ``[composition]``.

The one place where a scene's ``[water]`` and ``[composition]`` sections become the
optics of its medium; the renderer, the optics report and the real-time LUTs all
ask here.
"""

from __future__ import annotations

import dataclasses

from ..scene import Scene
from .water import (
    DEFAULT_IOR,
    DEFAULT_SALINITY_PSU,
    DEFAULT_TEMPERATURE_C,
    IOR_WAVELENGTH_NM,
    PURE_SEAWATER_TABLE,
    TABLE_SALINITY_PSU,
    MediumOptics,
    WaterIOPs,
    pure_seawater_iops,
    seawater_refractive_index,
    seawater_scattering_salinity_factor,
)


def water_ior(scene: Scene) -> float:
    """The water's refractive index [-]: ``[water] ior``; else n(550 nm, T, S) of Quan & Fry (1995)
    when ``temperature`` or ``salinity`` is given (the other at 20 °C / 35 PSU); else 1.333."""
    w = scene.water
    if w.ior is not None:
        return float(w.ior)
    if w.temperature is None and w.salinity is None:
        return DEFAULT_IOR
    t = DEFAULT_TEMPERATURE_C if w.temperature is None else w.temperature
    s = DEFAULT_SALINITY_PSU if w.salinity is None else w.salinity
    return float(seawater_refractive_index(IOR_WAVELENGTH_NM, t, s))


def water_composition(scene: Scene):
    """The scene's :class:`~oceanrender.optics.components.WaterComposition`, or None for pure sea water."""
    if scene.composition is None:
        return None
    from .components import WaterComposition, preset  # noqa: PLC0415

    settings = scene.composition.model_dump()
    settings.pop("particle_phase")  # a property of the medium's phase model, not of the water (water_optics)
    base = preset(settings.pop("preset")) if scene.composition.preset else WaterComposition()
    explicit = {key: value for key, value in settings.items() if value is not None}
    state = {"temperature_c": scene.water.temperature, "salinity_psu": scene.water.salinity}
    explicit.update({key: value for key, value in state.items() if value is not None})
    return dataclasses.replace(base, **explicit)


def water_optics(scene: Scene) -> WaterIOPs | MediumOptics:
    """What the medium is made of: pure sea water from its table, a Jerlov type, or the ``[composition]``."""
    if scene.water.jerlov_type is not None:
        from .jerlov_types import jerlov_type_optics  # noqa: PLC0415

        return jerlov_type_optics(scene.water.jerlov_type)
    composition = water_composition(scene)
    if composition is None:
        iops = pure_seawater_iops(scene.water.iop_table)
        if scene.water.salinity is None or scene.water.iop_table != PURE_SEAWATER_TABLE:
            return iops  # a table of the user's own: its b is what the user measured
        factor = seawater_scattering_salinity_factor(scene.water.salinity, TABLE_SALINITY_PSU)
        return dataclasses.replace(iops, scattering=iops.scattering * factor,
                                   source=f"{iops.source}\nb scaled to {scene.water.salinity:g} PSU (Morel 1974)")
    from .components import composition_optics  # noqa: PLC0415

    return composition_optics(composition, particle_phase=scene.composition.particle_phase)


def water_phase_table(scene: Scene, wavelengths_nm):
    """(μ, p (W, M)) of the phase function the renderer gives the scene's water [-, sr⁻¹]
    (:func:`oceanrender.optics.components.medium_phase_table`), for the four-flux coefficients."""
    from .components import medium_phase_table  # noqa: PLC0415

    return medium_phase_table(water_optics(scene), wavelengths_nm)
