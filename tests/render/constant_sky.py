"""A test scene shared by the film tests: a camera under a constant sky of spectral radiance 1.

Every camera ray sees L(λ) = 1 W m⁻² sr⁻¹ nm⁻¹, so each pixel's film channels are
∫x̄ dλ, ∫ȳ dλ, ∫z̄ dλ over the film's 360–830 nm (:func:`cmf_integrals`), in W m⁻² sr⁻¹.
"""

import colour
import numpy as np

from oceanrender.render.scene import CIE1931, xyz_film


def cmf_integrals() -> np.ndarray:
    """∫x̄ dλ, ∫ȳ dλ, ∫z̄ dλ of the CIE 1931 2° observer over 360–830 nm [nm]."""
    cmfs = colour.MSDS_CMFS[CIE1931].copy().trim(colour.SpectralShape(360, 830, 1))
    return cmfs.values.sum(axis=0)  # Δλ = 1 nm


def constant_sky_scene(width: int, height: int, spp: int):
    """A Mitsuba scene: ``path`` (depth 1), perspective camera, ``xyz_film``, constant environment of 1."""
    import mitsuba as mi

    return mi.load_dict({
        "type": "scene",
        "integrator": {"type": "path", "max_depth": 1},
        "sensor": {"type": "perspective", "film": xyz_film(width, height),
                   "sampler": {"type": "independent", "sample_count": spp}},
        "environment": {"type": "constant", "radiance": {"type": "spectrum", "value": 1.0}},
    })
