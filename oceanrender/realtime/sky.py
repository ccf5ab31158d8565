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

from ..render.buffers import jit_floats

__all__ = ["SUNSKY_LAST_NM", "sky_radiance_spectra", "sunsky_wavelengths"]

#: Wavelengths per Mitsuba spectral sample (``mi.Spectrum`` has four lanes).
_LANES = 4

#: The last wavelength of ``sunsky``'s tables [nm] (Hosek & Wilkie's 11 channels, 320–720 nm every 40 nm).
SUNSKY_LAST_NM = 720.0


def sunsky_wavelengths(wavelengths: ArrayLike) -> NDArray[np.float32]:
    """Wavelengths [nm] as float32 for ``sunsky.eval``, with exactly 720 nm moved one float32 step below.

    Mitsuba 3.9.1's ``sunsky`` (``include/mitsuba/render/sunsky.h``, ``eval``) takes λ as valid while
    (λ − 320)/40 ≤ 10 and interpolates between table entries ⌊·⌋ and ⌊·⌋ + 1: at exactly 720 nm that is
    entry 11 of an 11-entry table (and entries 99–107 of a 99-entry parameter table), read past the end
    and weighted by zero. Zero times whatever lies there is NaN when that memory holds a NaN, which
    depends on the drjit memory pool and the SIMD width (it held NaN after a render on 8-wide hosts):
    the "non-finite radiance now and then" that a retry used to hide. One float32 step below 720 nm
    both entries are in the tables; the radiance changes by one float32 step of its own (3e-8 relative).
    """
    lanes = np.asarray(wavelengths, dtype=np.float32).copy()
    lanes[lanes == np.float32(SUNSKY_LAST_NM)] = np.nextafter(np.float32(SUNSKY_LAST_NM), np.float32(0.0))
    return lanes


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
    lanes = np.pad(sunsky_wavelengths(wavelengths), (0, groups * _LANES - len(wavelengths)),
                   mode="edge").reshape(groups, _LANES)
    # NOTE: one kernel for all wavelength groups: every direction is repeated once per group of four
    # wavelengths, which are passed as arrays (literal wavelengths would compile a kernel per group).
    si = dr.zeros(mi.SurfaceInteraction3f, count * groups)
    si.wi = mi.Vector3f(*(jit_floats(np.tile(-flat[:, k], groups)) for k in range(3)))
    si.wavelengths = mi.Spectrum(*(jit_floats(np.repeat(lanes[:, j], count)) for j in range(_LANES)))
    values = np.array(emitter.eval(si), dtype=np.float64)  # (4, groups · count)
    if not np.all(np.isfinite(values)):  # a defect to find, not to retry around (sunsky_wavelengths)
        raise RuntimeError(f"Mitsuba's sunsky returned {int(np.sum(~np.isfinite(values)))} non-finite radiances")
    out = values.reshape(_LANES, groups, count).transpose(2, 1, 0).reshape(count, groups * _LANES)
    return out[:, : len(wavelengths)].reshape(d.shape[:-1] + (len(wavelengths),))
