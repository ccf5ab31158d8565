"""Human-vision operator Φ: absolute CIE XYZ [cd/m²] → display sRGB.

-   :mod:`~oceanrender.vision.brightness`: global brightness adaptation
    (Ward 1994, Ferwerda et al. 1996, and the compressive photoreceptor model of
    Reinhard & Devlin 2005) and the log-average adaptation luminance.
-   :mod:`~oceanrender.vision.chromatic`: von Kries-type chromatic adaptation
    to the D65 display white (colour-science).
-   :mod:`~oceanrender.vision.display`: display-relative XYZ → linear sRGB →
    8-bit sRGB (colour-science).
-   :mod:`~oceanrender.vision.model`: :class:`VisionModel`, the three steps
    chained.
"""

from oceanrender.vision.brightness import (
    BRIGHTNESS_METHODS,
    BRIGHTNESS_RESPONSES,
    adaptation_luminance_log_average,
    brightness_response,
    brightness_scale_factor,
    response_ReinhardDevlin2005,
    scale_factor_ReinhardDevlin2005,
    semi_saturation_ReinhardDevlin2005,
    scale_factor_Ferwerda1996,
    scale_factor_Ward1994,
    threshold_photopic_Ferwerda1996,
)
from oceanrender.vision.chromatic import (
    CCS_WHITE_D65,
    CHROMATIC_ADAPTATION_TRANSFORMS,
    XYZ_white_D65,
    chromatic_adaptation_to_D65,
    validate_chromatic_adaptation_transform,
)
from oceanrender.vision.display import (
    RGB_COLOURSPACE_sRGB,
    XYZ_to_sRGB_linear,
    encode_sRGB_8bit,
    sRGB_linear_to_XYZ,
)
from oceanrender.vision.model import VisionModel, XYZ_to_display_sRGB_linear

__all__ = [
    "BRIGHTNESS_METHODS",
    "BRIGHTNESS_RESPONSES",
    "adaptation_luminance_log_average",
    "brightness_response",
    "brightness_scale_factor",
    "response_ReinhardDevlin2005",
    "scale_factor_ReinhardDevlin2005",
    "semi_saturation_ReinhardDevlin2005",
    "scale_factor_Ferwerda1996",
    "scale_factor_Ward1994",
    "threshold_photopic_Ferwerda1996",
    "CCS_WHITE_D65",
    "CHROMATIC_ADAPTATION_TRANSFORMS",
    "XYZ_white_D65",
    "chromatic_adaptation_to_D65",
    "validate_chromatic_adaptation_transform",
    "RGB_COLOURSPACE_sRGB",
    "XYZ_to_sRGB_linear",
    "encode_sRGB_8bit",
    "sRGB_linear_to_XYZ",
    "VisionModel",
    "XYZ_to_display_sRGB_linear",
]
