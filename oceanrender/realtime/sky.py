"""Spectral sky radiance of the scene's Mitsuba ``sunsky`` in given directions.

The sky environment map of the real-time model must be the sky the path
tracer sees, so it is evaluated from the very emitter the renderer loads
(:func:`oceanrender.render.scene.sunsky_emitter`), at chosen wavelengths,
through ``Emitter.eval`` — no sampling, no noise. Needs an active Mitsuba
spectral variant.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["sky_radiance_spectra"]

#: Wavelengths per Mitsuba spectral sample (``mi.Spectrum`` has four lanes).
_LANES = 4

#: Evaluations tried before giving up on non-finite values.
#: NOTE: after a render in the same process, the llvm variant intermittently returned NaN for one
#: wavelength over one contiguous block of 65 536 lanes (seen in 3 runs of `oceanrender reference` on
#: the open-sea scene, not reproducible on demand); evaluating again gave finite values each time.
#: The cause, in drjit or Mitsuba, is not known (docs/realtime.md).
ATTEMPTS = 3


def sky_radiance_spectra(sun, directions: ArrayLike, wavelengths: ArrayLike, include_sun: bool = False
                         ) -> NDArray[np.float64]:
    """Radiance of Mitsuba's ``sunsky`` arriving from unit world directions [W m⁻² sr⁻¹ nm⁻¹].

    Parameters
    ----------
    sun : SunSettings
        The scene's ``[sun]`` section.
    directions : array_like (..., 3)
        Unit directions towards the sky (world frame, z up).
    wavelengths : array_like (W,)
        Wavelengths [nm].
    include_sun : bool
        Include the solar disc (default False: the sky alone, so that a
        texel-sized map is not dominated by whether a texel centre happens to
        fall on the 0.5° disc).

    Returns
    -------
    ndarray (..., W)
        Spectral radiance; 0 below the horizon and above 720 nm (the model's data end there).
    """
    import drjit as dr  # noqa: PLC0415
    import mitsuba as mi  # noqa: PLC0415

    from ..render.scene import sunsky_emitter  # noqa: PLC0415

    settings = sunsky_emitter(sun)
    if not include_sun:
        settings["sun_scale"] = 0.0
    emitter = mi.load_dict(settings)
    d = np.asarray(directions, dtype=np.float64)
    flat = d.reshape(-1, 3).astype(np.float32)
    wavelengths = np.asarray(wavelengths, dtype=np.float64)
    count, groups = len(flat), -(-len(wavelengths) // _LANES)
    lanes = np.pad(wavelengths, (0, groups * _LANES - len(wavelengths)), mode="edge").reshape(groups, _LANES)
    # NOTE: one kernel for all wavelength groups: every direction is repeated once per group of four
    # wavelengths, which are passed as arrays (literal wavelengths would compile a kernel per group).
    si = dr.zeros(mi.SurfaceInteraction3f, count * groups)
    si.wi = mi.Vector3f(*(mi.Float(np.tile(-flat[:, k], groups)) for k in range(3)))
    si.wavelengths = mi.Spectrum(*(mi.Float(np.repeat(lanes[:, j], count).astype(np.float32)) for j in range(_LANES)))
    for _ in range(ATTEMPTS):
        values = np.array(emitter.eval(si), dtype=np.float64)  # (4, groups · count)
        if np.all(np.isfinite(values)):
            break
    else:
        raise RuntimeError(f"Mitsuba's sunsky returned non-finite radiance in {ATTEMPTS} evaluations")
    out = values.reshape(_LANES, groups, count).transpose(2, 1, 0).reshape(count, groups * _LANES)
    return out[:, : len(wavelengths)].reshape(d.shape[:-1] + (len(wavelengths),))
