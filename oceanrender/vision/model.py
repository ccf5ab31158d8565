"""
Human-vision operator Φ
=======================

Turns absolute CIE 1931 XYZ (Y = luminance [cd/m²]) into linear display sRGB
in three steps, each done in exactly one place:

1.  the linear stage of brightness adaptation:
    :func:`oceanrender.vision.brightness.brightness_scale_factor` gives
    :math:`m(L_{wa})`, and :math:`XYZ_d = 2^{EV} m \\, XYZ / L_{d,max}` (EV:
    the exposure compensation);
2.  chromatic adaptation from the scene's adapting white to D65:
    :func:`oceanrender.vision.chromatic.chromatic_adaptation_to_D65`;
3.  XYZ → linear sRGB: :func:`oceanrender.vision.display.XYZ_to_sRGB_linear`;
4.  the method's pointwise response per channel
    (:func:`oceanrender.vision.brightness.brightness_response`): the
    identity for Ward and Ferwerda et al., the photoreceptor hyperbola for
    Reinhard and Devlin, which compresses highlights towards display white
    instead of clipping them. It acts on the cone-like channels after
    chromatic adaptation, as the photoreceptors do [1]; steps 1–3 are linear
    in light (:meth:`VisionModel.linear`), so real-time shaders can sum
    light in that space and apply step 4 last (:meth:`VisionModel.response`).

References
----------
.. [1] E. Reinhard and K. Devlin, "Dynamic range reduction inspired by
   photoreceptor physiology," IEEE Trans. Vis. Comput. Graph. 11(1), 13–24,
   2005. doi:10.1109/TVCG.2005.9

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

from oceanrender.vision.brightness import BRIGHTNESS_METHODS, brightness_response, brightness_scale_factor
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
        ('Reinhard Devlin 2005' (default, compressive), 'Ward 1994',
        'Ferwerda 1996').
    chromatic_transform : str, optional
        Chromatic adaptation transform, one of
        :data:`oceanrender.vision.chromatic.CHROMATIC_ADAPTATION_TRANSFORMS`
        ('Von Kries', 'Bradford', 'CAT02', 'CAT16', 'XYZ Scaling', ...).
    display_max_luminance : float, optional
        Maximum luminance of the display :math:`L_{d,max}` [cd/m²]; display
        adaptation is taken at half of it.
    exposure : float, optional
        Exposure compensation [EV]: the linear stage is multiplied by
        :math:`2^{EV}` (+1 EV: twice as bright before the response), in
        [−10, 10].

    Raises
    ------
    ValueError
        On construction, if a name is unknown (the message names the field and
        lists the known values) or ``display_max_luminance`` is not positive
        and finite.
    """

    brightness: str = "Reinhard Devlin 2005"
    chromatic_transform: str = "Von Kries"
    display_max_luminance: float = 100.0
    exposure: float = 0.0

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
        if not (isinstance(self.exposure, (int, float)) and -10.0 <= self.exposure <= 10.0):
            raise ValueError(f"VisionModel.exposure must be a number of EV in [-10, 10], got {self.exposure!r}")

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

    def linear(
        self, XYZ_abs: ArrayLike, XYZ_white: ArrayLike, adaptation_luminance: float
    ) -> NDArray[np.float64]:
        """Steps 1–3 of Φ: absolute XYZ → linear sRGB before the response [relative].

        Linear in ``XYZ_abs`` for a fixed state (white, adaptation luminance).
        Parameters as in :meth:`apply`; returns float64 of shape (..., 3).
        """
        m = self.scale_factor(adaptation_luminance) * 2.0**self.exposure

        XYZ_d = np.asarray(XYZ_abs, dtype=np.float64) * (m / self.display_max_luminance)
        XYZ_d65 = chromatic_adaptation_to_D65(XYZ_d, XYZ_white, self.chromatic_transform)

        return np.asarray(XYZ_to_sRGB_linear(XYZ_d65), dtype=np.float64)

    def response(self, rgb_linear: ArrayLike) -> NDArray[np.float64]:
        """Step 4 of Φ: the method's pointwise response per channel [relative, 1 = display white]."""
        return brightness_response(self.brightness, rgb_linear)

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
            maximum. The linear operators keep values outside [0, 1] (clip or
            encode later); the compressive one stays inside (−1, 1). NaN input
            pixels stay NaN.
        """
        return self.response(self.linear(XYZ_abs, XYZ_white, adaptation_luminance)).astype(np.float32)


def XYZ_to_display_sRGB_linear(
    XYZ_abs: ArrayLike,
    XYZ_white: ArrayLike,
    adaptation_luminance: float,
    brightness: str = "Reinhard Devlin 2005",
    chromatic_transform: str = "Von Kries",
    display_max_luminance: float = 100.0,
    exposure: float = 0.0,
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
    brightness, chromatic_transform, display_max_luminance, exposure
        As in :class:`VisionModel` (display_max_luminance in [cd/m²], exposure in [EV]).

    Returns
    -------
    numpy.ndarray
        Linear sRGB, shape (..., 3), float32 [relative].
    """
    model = VisionModel(brightness, chromatic_transform, display_max_luminance, exposure)

    return model.apply(XYZ_abs, XYZ_white, adaptation_luminance)
