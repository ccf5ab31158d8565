"""The water a scene describes: pure sea water, a Jerlov water type, or a ``[composition]``.

The one place where a scene's ``[water]`` and ``[composition]`` sections become the
optics of its medium; the renderer, the optics report and the real-time LUTs all
ask here.
"""

from __future__ import annotations

from ..scene import Scene
from .water import MediumOptics, WaterIOPs, pure_seawater_iops


def water_composition(scene: Scene):
    """The scene's :class:`~oceanrender.optics.components.WaterComposition`, or None for pure sea water."""
    if scene.composition is None:
        return None
    from .components import WaterComposition, preset  # noqa: PLC0415

    settings = scene.composition.model_dump()
    settings.pop("particle_phase")  # a property of the medium's phase model, not of the water (water_optics)
    base = preset(settings.pop("preset")) if scene.composition.preset else WaterComposition()
    explicit = {key: value for key, value in settings.items() if value is not None}
    return WaterComposition(**{**base.__dict__, **explicit})


def water_optics(scene: Scene) -> WaterIOPs | MediumOptics:
    """What the medium is made of: pure sea water from its table, a Jerlov type, or the ``[composition]``."""
    if scene.water.jerlov_type is not None:
        from .jerlov_types import jerlov_type_optics  # noqa: PLC0415

        return jerlov_type_optics(scene.water.jerlov_type)
    composition = water_composition(scene)
    if composition is None:
        return pure_seawater_iops(scene.water.iop_table)
    from .components import composition_optics  # noqa: PLC0415

    return composition_optics(composition, particle_phase=scene.composition.particle_phase)


def water_phase_table(scene: Scene, wavelengths_nm):
    """(μ, p (W, M)) of the phase function the renderer gives the scene's water [-, sr⁻¹]
    (:func:`oceanrender.optics.components.medium_phase_table`), for the four-flux coefficients."""
    from .components import medium_phase_table  # noqa: PLC0415

    return medium_phase_table(water_optics(scene), wavelengths_nm)
