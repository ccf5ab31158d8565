"""
sRGB display encoding
=====================

From display-relative CIE XYZ (display white D65 at Y = 1) to linear sRGB and
to 8-bit sRGB code values, both through colour-science:

-   :data:`RGB_COLOURSPACE_sRGB`: colour's sRGB colourspace, with its XYZ↔RGB
    matrices derived from the primaries and white point.
-   :func:`XYZ_to_sRGB_linear` and its inverse :func:`sRGB_linear_to_XYZ`.
-   :func:`encode_sRGB_8bit`: clip, apply the sRGB inverse EOTF, quantise.

References
----------
.. [1] IEC 61966-2-1:1999, Multimedia systems and equipment — Colour
   measurement and management — Part 2-1: Colour management — Default RGB
   colour space — sRGB. International Electrotechnical Commission, 1999.
"""

from __future__ import annotations

import colour
import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = [
    "RGB_COLOURSPACE_sRGB",
    "XYZ_to_sRGB_linear",
    "sRGB_linear_to_XYZ",
    "encode_sRGB_8bit",
]


def _sRGB_with_derived_matrices() -> colour.RGB_Colourspace:
    """Copy of colour's sRGB colourspace using matrices derived from its primaries."""
    colourspace = colour.RGB_COLOURSPACES["sRGB"].copy()
    colourspace.name = "sRGB (derived matrices)"
    colourspace.use_derived_transformation_matrices(True)

    return colourspace


RGB_COLOURSPACE_sRGB: colour.RGB_Colourspace = _sRGB_with_derived_matrices()
"""sRGB (ITU-R BT.709 primaries, D65 white) with XYZ↔RGB matrices derived from
the primaries and white point.

NOTE: colour's stock sRGB colourspace uses the 4-decimal matrix printed in IEC
61966-2-1 [1]; it maps the D65 white (Y = 1) to RGB (0.99984, 1.00010,
1.00007), so a neutral grey would come out 1.6e-4 off neutral. The derived
matrix maps D65 to (1, 1, 1) to machine precision and differs from the printed
one by less than 5e-4 per entry."""


def XYZ_to_sRGB_linear(XYZ: ArrayLike) -> NDArray[np.float64]:
    """Convert display-relative CIE XYZ to linear sRGB.

    Parameters
    ----------
    XYZ : array_like
        CIE 1931 XYZ relative to the display white, shape (..., 3): D65 with
        Y = 1 is the display's maximum white [relative].

    Returns
    -------
    numpy.ndarray
        Linear (not gamma-encoded) sRGB, shape (..., 3) [relative]; values
        outside [0, 1] are out of gamut or too bright and are kept.

    Notes
    -----
    No chromatic adaptation is applied here (``chromatic_adaptation_transform
    =None``): the input must already be adapted to D65, e.g. by
    :func:`oceanrender.vision.chromatic.chromatic_adaptation_to_D65`.

    References
    ----------
    .. [1] IEC 61966-2-1:1999, Default RGB colour space — sRGB.
    """
    return colour.XYZ_to_RGB(
        XYZ, RGB_COLOURSPACE_sRGB, illuminant=None, chromatic_adaptation_transform=None
    )


def sRGB_linear_to_XYZ(RGB_linear: ArrayLike) -> NDArray[np.float64]:
    """Convert linear sRGB to display-relative CIE XYZ (inverse of :func:`XYZ_to_sRGB_linear`).

    Parameters
    ----------
    RGB_linear : array_like
        Linear sRGB, shape (..., 3) [relative].

    Returns
    -------
    numpy.ndarray
        CIE 1931 XYZ relative to the D65 display white (Y = 1), shape (..., 3).
    """
    return colour.RGB_to_XYZ(
        RGB_linear, RGB_COLOURSPACE_sRGB, illuminant=None, chromatic_adaptation_transform=None
    )


def encode_sRGB_8bit(RGB_linear: ArrayLike) -> NDArray[np.uint8]:
    """Encode linear sRGB to 8-bit sRGB code values.

    Linear values are clipped to [0, 1], encoded with colour's sRGB inverse EOTF
    (:math:`12.92 L` up to :math:`L = 0.0031308`, :math:`1.055 L^{1/2.4} - 0.055`
    above) and rounded to the nearest of 0–255.

    Parameters
    ----------
    RGB_linear : array_like
        Linear sRGB, any shape [relative].

    Returns
    -------
    numpy.ndarray
        Code values, same shape, dtype ``uint8``.

    Notes
    -----
    Non-finite values (NaN, ±inf) become 0. NOTE: that includes +inf, so an
    overflowing sun disc turns black here: clamp or replace infinities upstream
    if they are expected.

    References
    ----------
    .. [1] IEC 61966-2-1:1999, Default RGB colour space — sRGB.
    """
    RGB = np.asarray(RGB_linear, dtype=np.float64)
    RGB = np.where(np.isfinite(RGB), RGB, 0.0)
    RGB = np.clip(RGB, 0.0, 1.0)

    V = colour.models.eotf_inverse_sRGB(RGB)  # sRGB inverse EOTF of [1]

    return np.rint(V * 255).astype(np.uint8)
