"""
Human-vision operator Φ
=======================

Turns absolute CIE 1931 XYZ (Y = luminance [cd/m²]) into linear display sRGB
in three steps, each done in exactly one place:

1.  brightness adaptation: :func:`oceanrender.vision.brightness.brightness_scale_factor`
    gives :math:`m(L_{wa})`, and :math:`XYZ_d = m \\, XYZ / L_{d,max}` puts the
    display's maximum white at Y = 1;
2.  chromatic adaptation from the scene's adapting white to D65:
    :func:`oceanrender.vision.chromatic.chromatic_adaptation_to_D65`;
3.  XYZ → linear sRGB: :func:`oceanrender.vision.display.XYZ_to_sRGB_linear`.

8-bit encoding (:func:`oceanrender.vision.display.encode_sRGB_8bit`) is left to
the caller, so that the linear result can also be written to EXR.

-   :class:`VisionModel`: the validated, frozen choice of methods.
-   :func:`XYZ_to_display_sRGB_linear`: the same operator as a function.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from oceanrender.vision.brightness import BRIGHTNESS_METHODS, brightness_scale_factor
from oceanrender.vision.chromatic import (
    CHROMATIC_ADAPTATION_TRANSFORMS,
    chromatic_adaptation_to_D65,
)
from oceanrender.vision.display import XYZ_to_sRGB_linear

__all__ = ["VisionModel", "XYZ_to_display_sRGB_linear"]


@dataclass(frozen=True)
class VisionModel:
    """Choice of methods for the human-vision operator Φ.

    Parameters
    ----------
    brightness : str, optional
        Brightness-adaptation method, a key of
        :data:`oceanrender.vision.brightness.BRIGHTNESS_METHODS`
        ('Ward 1994', 'Ferwerda 1996').
    chromatic_transform : str, optional
        Chromatic adaptation transform, one of
        :data:`oceanrender.vision.chromatic.CHROMATIC_ADAPTATION_TRANSFORMS`
        ('Von Kries', 'Bradford', 'CAT02', 'CAT16', 'XYZ Scaling', ...).
    display_max_luminance : float, optional
        Maximum luminance of the display :math:`L_{d,max}` [cd/m²]; display
        adaptation is taken at half of it.

    Raises
    ------
    ValueError
        On construction, if a name is unknown (the message names the field and
        lists the known values) or ``display_max_luminance`` is not positive
        and finite.
    """

    brightness: str = "Ward 1994"
    chromatic_transform: str = "Von Kries"
    display_max_luminance: float = 100.0

    def __post_init__(self) -> None:
        if self.brightness not in BRIGHTNESS_METHODS:
            raise ValueError(
                f"VisionModel.brightness: unknown method {self.brightness!r}; known: "
                f"{', '.join(repr(name) for name in BRIGHTNESS_METHODS)}"
            )
        if self.chromatic_transform not in CHROMATIC_ADAPTATION_TRANSFORMS:
            raise ValueError(
                f"VisionModel.chromatic_transform: unknown transform "
                f"{self.chromatic_transform!r}; known: "
                f"{', '.join(repr(name) for name in CHROMATIC_ADAPTATION_TRANSFORMS)}"
            )
        if not (math.isfinite(self.display_max_luminance) and self.display_max_luminance > 0):
            raise ValueError(
                "VisionModel.display_max_luminance must be positive and finite [cd/m²], "
                f"got {self.display_max_luminance!r}"
            )

    def scale_factor(self, adaptation_luminance: float) -> float:
        """Brightness scale factor :math:`m` for this model [dimensionless].

        Parameters
        ----------
        adaptation_luminance : float
            World adaptation luminance :math:`L_{wa}` [cd/m²], positive.

        Returns
        -------
        float
            :math:`m`; display luminance :math:`L_d = m L_w` [cd/m²].
        """
        L_wa = float(adaptation_luminance)
        if not (math.isfinite(L_wa) and L_wa > 0):
            raise ValueError(
                f"adaptation_luminance must be positive and finite [cd/m²], got {L_wa!r}"
            )

        return float(brightness_scale_factor(self.brightness, L_wa, self.display_max_luminance))

    def apply(
        self, XYZ_abs: ArrayLike, XYZ_white: ArrayLike, adaptation_luminance: float
    ) -> NDArray[np.float32]:
        """Apply Φ: absolute XYZ → linear display sRGB.

        Parameters
        ----------
        XYZ_abs : array_like
            Absolute CIE 1931 XYZ, shape (..., 3), e.g. (H, W, 3); Y is
            luminance [cd/m²].
        XYZ_white : array_like
            CIE XYZ of the scene's adapting white, shape (3,), any scale
            (e.g. the sky-plus-sun irradiance colour); Y must be positive.
        adaptation_luminance : float
            World adaptation luminance :math:`L_{wa}` [cd/m²], e.g. from
            :func:`oceanrender.vision.brightness.adaptation_luminance_log_average`.

        Returns
        -------
        numpy.ndarray
            Linear sRGB, shape (..., 3), float32 [relative]; 1 is the display's
            maximum, values outside [0, 1] are kept (clip or encode later). NaN
            input pixels stay NaN.
        """
        m = self.scale_factor(adaptation_luminance)

        XYZ_d = np.asarray(XYZ_abs, dtype=np.float64) * (m / self.display_max_luminance)
        XYZ_d65 = chromatic_adaptation_to_D65(XYZ_d, XYZ_white, self.chromatic_transform)

        return XYZ_to_sRGB_linear(XYZ_d65).astype(np.float32)


def XYZ_to_display_sRGB_linear(
    XYZ_abs: ArrayLike,
    XYZ_white: ArrayLike,
    adaptation_luminance: float,
    brightness: str = "Ward 1994",
    chromatic_transform: str = "Von Kries",
    display_max_luminance: float = 100.0,
) -> NDArray[np.float32]:
    """Human-vision operator Φ as a function; see :meth:`VisionModel.apply`.

    Parameters
    ----------
    XYZ_abs : array_like
        Absolute CIE 1931 XYZ, shape (..., 3); Y is luminance [cd/m²].
    XYZ_white : array_like
        CIE XYZ of the scene's adapting white, shape (3,), any scale.
    adaptation_luminance : float
        World adaptation luminance :math:`L_{wa}` [cd/m²].
    brightness, chromatic_transform, display_max_luminance
        As in :class:`VisionModel` (display_max_luminance in [cd/m²]).

    Returns
    -------
    numpy.ndarray
        Linear sRGB, shape (..., 3), float32 [relative].
    """
    model = VisionModel(brightness, chromatic_transform, display_max_luminance)

    return model.apply(XYZ_abs, XYZ_white, adaptation_luminance)
