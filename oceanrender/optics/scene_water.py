"""The water a scene describes: pure sea water, a Jerlov water type, or a ``[composition]``.

The one place where a scene's ``[water]`` and ``[composition]`` sections become the
optics of its medium; the renderer, the optics report and the real-time LUTs all
ask here.
"""

from __future__ import annotations

import dataclasses

from ..scene import Scene
import numpy as np

from .water import (
    DEFAULT_IOR,
    DEFAULT_SALINITY_PSU,
    DEFAULT_TEMPERATURE_C,
    IOR_WAVELENGTH_NM,
    PURE_SEAWATER_TABLE,
    TABLE_SALINITY_PSU,
    MediumOptics,
    WaterIOPs,
    aw_WOPP3,
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


def pure_seawater_state(scene: Scene) -> WaterIOPs:
    """Pure sea water of the scene: the ``iop_table``; the default table at ``[water] temperature`` and
    ``salinity`` when either is given (a_w of WOPP v3 at (T, S), b_sw scaled by Morel's salinity factor;
    the one left out at 20 °C / 35 PSU, the table's own state, so that giving 20 °C changes nothing)."""
    iops = pure_seawater_iops(scene.water.iop_table)
    w = scene.water
    if (w.temperature is None and w.salinity is None) or w.iop_table != PURE_SEAWATER_TABLE:
        return iops  # the table's state, or a table of the user's own: its a, b are what the user measured
    t = DEFAULT_TEMPERATURE_C if w.temperature is None else w.temperature
    salinity = TABLE_SALINITY_PSU if w.salinity is None else w.salinity
    factor = seawater_scattering_salinity_factor(salinity, TABLE_SALINITY_PSU)
    return dataclasses.replace(iops, absorption=aw_WOPP3(iops.wavelengths, t, salinity),
                               scattering=iops.scattering * factor,
                               source=f"{iops.source}\na_w at {t:g} degC, {salinity:g} PSU (WOPP v3); "
                                      f"b scaled to {salinity:g} PSU (Morel 1974)")


def water_optics(scene: Scene) -> WaterIOPs | MediumOptics:
    """What the medium is made of: pure sea water from its table, a Jerlov type, or the ``[composition]``."""
    if scene.water.jerlov_type is not None:
        from .jerlov_types import jerlov_type_optics  # noqa: PLC0415

        return jerlov_type_optics(scene.water.jerlov_type)
    composition = water_composition(scene)
    if composition is None:
        return pure_seawater_state(scene)
    from .components import composition_optics  # noqa: PLC0415

    return composition_optics(composition, particle_phase=scene.composition.particle_phase)


def scene_iops(scene: Scene, wavelengths_nm) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """a, b, b_b [m⁻¹] of the scene's water at ``wavelengths_nm`` [nm]: a Jerlov type's measured IOPs, the
    ``[composition]``'s component model, or pure sea water (:func:`pure_seawater_state`) with b_b = b/2
    (pure water's volume scattering function is symmetric about 90°, Morel 1974). For the optics report
    and the real-time LUTs."""
    wl = np.asarray(wavelengths_nm, dtype=float)
    if scene.water.jerlov_type is not None:
        from .jerlov_types import iops_WilliamsonHollins2022  # noqa: PLC0415

        return iops_WilliamsonHollins2022(scene.water.jerlov_type, wl)
    composition = water_composition(scene)
    if composition is None:
        iops = pure_seawater_state(scene)
        b = np.interp(wl, iops.wavelengths, iops.scattering)
        return np.interp(wl, iops.wavelengths, iops.absorption), b, b / 2
    from .components import composition_iops  # noqa: PLC0415

    result = composition_iops(composition, wl)
    return result.absorption, result.scattering, result.backscattering


def water_phase_table(scene: Scene, wavelengths_nm):
    """(μ, p (W, M)) of the phase function the renderer gives the scene's water [-, sr⁻¹]
    (:func:`oceanrender.optics.components.medium_phase_table`), for the four-flux coefficients."""
    from .components import medium_phase_table  # noqa: PLC0415

    return medium_phase_table(water_optics(scene), wavelengths_nm)
