"""Reflectance of the seafloor: a Lambertian albedo linear in wavelength.

Scene files give a seafloor's (sand's, rock's) reflectance at 400 and 700 nm; the
spectrum between and beyond is the straight line through the two, clipped to
[0, 1]. Used by the renderer's terrain and by the real-time LUTs alike.
"""

from __future__ import annotations

import numpy as np

#: Wavelengths [nm] at which the linear seafloor reflectances are given.
ALBEDO_WAVELENGTHS = (400.0, 700.0)


def linear_reflectance(wavelengths, at_400_700: tuple[float, float]) -> np.ndarray:
    """Reflectance [-] linear in wavelength [nm] through its values at 400 and 700 nm, clipped to [0, 1]."""
    (l0, l1), (r0, r1) = ALBEDO_WAVELENGTHS, at_400_700
    w = np.asarray(wavelengths, dtype=np.float64)
    return np.clip(r0 + (r1 - r0) * (w - l0) / (l1 - l0), 0.0, 1.0)
