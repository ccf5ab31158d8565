"""Colour differences between display images: CIEDE2000 maps and their summary statistics.

Both images are linear display sRGB (1 = display white); they are compared as
a viewer sees them on the display: clipped to [0, 1], converted to CIE XYZ
with the D65 white at Y = 1 and to CIELAB (colour-science), and compared with
the CIEDE2000 formula (``colour.delta_E(..., method="CIE 2000")``).

References
----------
.. [1] CIE 142-2001, Improvement to industrial colour-difference evaluation.
.. [2] G. Sharma, W. Wu and E. N. Dalal, "The CIEDE2000 color-difference
   formula: implementation notes, supplementary test data, and mathematical
   observations," Color Res. Appl. 30(1), 21–30, 2005. doi:10.1002/col.20070
"""

from __future__ import annotations

from dataclasses import dataclass

import colour
import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..vision.display import sRGB_linear_to_XYZ

__all__ = ["display_to_Lab", "delta_E_2000", "ErrorStats", "error_stats"]

#: D65 chromaticity of the CIE 1931 observer: the display white of the Lab conversion.
D65_xy = colour.CCS_ILLUMINANTS["CIE 1931 2 Degree Standard Observer"]["D65"]


def display_to_Lab(rgb: ArrayLike) -> NDArray[np.float64]:
    """CIELAB of linear display sRGB as shown: clipped to [0, 1], → XYZ (D65, Y = 1 white) → L*a*b*.

    The clip is what the display does (and what the 8-bit PNG holds): a pixel
    brighter than display white is seen as white.
    """
    rgb = np.clip(np.nan_to_num(np.asarray(rgb, dtype=np.float64), nan=0.0, posinf=1.0), 0.0, 1.0)
    return colour.XYZ_to_Lab(sRGB_linear_to_XYZ(rgb), D65_xy)


def delta_E_2000(rgb_a: ArrayLike, rgb_b: ArrayLike) -> NDArray[np.float64]:
    """Per-pixel CIEDE2000 ΔE between two linear display sRGB images (..., 3) → (...)."""
    return np.asarray(colour.delta_E(display_to_Lab(rgb_a), display_to_Lab(rgb_b), method="CIE 2000"))


@dataclass(frozen=True)
class ErrorStats:
    """Summary of a ΔE map over a set of pixels."""

    mean: float
    p95: float
    max: float
    pixels: int

    def describe(self) -> dict[str, float | int]:
        return {"mean": self.mean, "p95": self.p95, "max": self.max, "pixels": self.pixels}


def error_stats(delta_E: ArrayLike, mask: ArrayLike | None = None) -> ErrorStats:
    """Mean, 95th percentile and maximum of ΔE over ``mask`` (all pixels by default)."""
    values = np.asarray(delta_E, dtype=np.float64)
    if mask is not None:
        values = values[np.asarray(mask, dtype=bool)]
    values = values[np.isfinite(values)]
    if values.size == 0:
        return ErrorStats(float("nan"), float("nan"), float("nan"), 0)
    return ErrorStats(float(values.mean()), float(np.percentile(values, 95)), float(values.max()), int(values.size))
