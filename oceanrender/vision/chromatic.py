"""
Chromatic adaptation to the display white
=========================================

von Kries-type chromatic adaptation, computed by colour-science, from the
scene's adapting white (e.g. the colour of sunlight plus skylight at the sea
surface) to the sRGB display white, CIE D65:

-   :data:`CHROMATIC_ADAPTATION_TRANSFORMS`: the transform names colour knows.
-   :func:`XYZ_white_D65`: CIE XYZ of the D65 white at a given luminance.
-   :func:`chromatic_adaptation_to_D65`: adapt XYZ from any white to D65.

References
----------
.. [1] M. D. Fairchild, Color Appearance Models, 3rd ed. Chichester, UK:
   Wiley, 2013. doi:10.1002/9781118653128
"""

from __future__ import annotations

import colour
import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = [
    "CHROMATIC_ADAPTATION_TRANSFORMS",
    "CCS_WHITE_D65",
    "XYZ_white_D65",
    "validate_chromatic_adaptation_transform",
    "chromatic_adaptation_to_D65",
]

CHROMATIC_ADAPTATION_TRANSFORMS: tuple[str, ...] = tuple(colour.CHROMATIC_ADAPTATION_TRANSFORMS)
"""Names of the cone-response transforms colour-science provides ('Von Kries',
'Bradford', 'CAT02', 'CAT16', 'XYZ Scaling', ...), taken from its own mapping."""

CCS_WHITE_D65: NDArray[np.float64] = np.array(
    colour.CCS_ILLUMINANTS["CIE 1931 2 Degree Standard Observer"]["D65"], dtype=np.float64
)
"""CIE 1931 xy chromaticity of CIE D65, the sRGB display white (0.3127, 0.3290)."""


def XYZ_white_D65(Y: ArrayLike = 1.0) -> NDArray[np.float64]:
    """CIE XYZ of the D65 white at luminance ``Y``.

    Parameters
    ----------
    Y : array_like, optional
        Luminance of the white, any scale (relative [1] or absolute [cd/m²]).

    Returns
    -------
    numpy.ndarray
        XYZ of D65 with the given Y, shape ``np.shape(Y) + (3,)``, in the units
        of ``Y``.
    """
    Y = np.asarray(Y, dtype=np.float64)

    return colour.xy_to_XYZ(CCS_WHITE_D65) * Y[..., np.newaxis]


def validate_chromatic_adaptation_transform(transform: str) -> str:
    """Return ``transform`` if colour-science knows it, else raise.

    Parameters
    ----------
    transform : str
        Transform name, spelled exactly as in
        :data:`CHROMATIC_ADAPTATION_TRANSFORMS`.

    Returns
    -------
    str
        ``transform``, unchanged.

    Raises
    ------
    ValueError
        If ``transform`` is unknown; the message lists the known names.
    """
    # NOTE: colour itself accepts any letter case; we require the exact
    # spelling so that a scene file names one transform one way.
    if transform not in CHROMATIC_ADAPTATION_TRANSFORMS:
        raise ValueError(
            f"unknown chromatic adaptation transform {transform!r}; known transforms: "
            f"{', '.join(repr(name) for name in CHROMATIC_ADAPTATION_TRANSFORMS)}"
        )

    return transform


def chromatic_adaptation_to_D65(
    XYZ: ArrayLike, XYZ_w: ArrayLike, transform: str = "Von Kries"
) -> NDArray[np.float64]:
    """Adapt CIE XYZ from the scene's adapting white to the D65 display white.

    The reference white is D65 at the luminance of the adapting white,
    :math:`XYZ_{wr} = Y_w \\, XYZ_{D65}(Y=1)`, so the adaptation changes
    chromaticity only: the adapting white keeps its luminance and maps exactly
    onto D65. The von Kries scaling itself is
    ``colour.adaptation.chromatic_adaptation_VonKries``:

    .. math:: XYZ_a = M^{-1} \\, \\mathrm{diag}(M XYZ_{wr} / M XYZ_w) \\, M \\, XYZ

    with :math:`M` the cone-response matrix named by ``transform``.

    Parameters
    ----------
    XYZ : array_like
        CIE XYZ to adapt, shape (..., 3), any scale (relative or [cd/m²]).
    XYZ_w : array_like
        CIE XYZ of the scene's adapting white, shape (3,) or broadcastable to
        ``XYZ``, any scale; its Y must be positive.
    transform : str, optional
        Cone-response transform, one of :data:`CHROMATIC_ADAPTATION_TRANSFORMS`
        ('Von Kries', 'Bradford', 'CAT02', 'CAT16', 'XYZ Scaling', ...).

    Returns
    -------
    numpy.ndarray
        Adapted CIE XYZ, shape of the broadcast inputs, same scale as ``XYZ``.

    Raises
    ------
    ValueError
        If ``transform`` is unknown (the message lists the known names) or the
        luminance of ``XYZ_w`` is not positive and finite.

    Notes
    -----
    The default 'Von Kries' matrix is the Hunt–Pointer–Estévez cone
    fundamentals, i.e. the classical von Kries transform; 'Bradford' and
    'CAT02' are the sharpened matrices of later models [1].

    References
    ----------
    .. [1] M. D. Fairchild, Color Appearance Models, 3rd ed. Chichester, UK:
       Wiley, 2013. doi:10.1002/9781118653128

    Examples
    --------
    >>> XYZ_A = colour.xy_to_XYZ(
    ...     colour.CCS_ILLUMINANTS["CIE 1931 2 Degree Standard Observer"]["A"]) * 10
    >>> chromatic_adaptation_to_D65(XYZ_A, XYZ_A)  # doctest: +ELLIPSIS
    array([  9.504...,  10.   ...,  10.890...])
    """
    validate_chromatic_adaptation_transform(transform)
    XYZ = np.asarray(XYZ, dtype=np.float64)
    XYZ_w = np.asarray(XYZ_w, dtype=np.float64)
    Y_w = XYZ_w[..., 1]
    if not np.all(np.isfinite(Y_w) & (Y_w > 0)):
        raise ValueError(f"adapting white luminance must be positive and finite, got {Y_w}")

    XYZ_wr = XYZ_white_D65(Y_w)  # D65 scaled to the adapting white's luminance

    return colour.adaptation.chromatic_adaptation_VonKries(XYZ, XYZ_w, XYZ_wr, transform=transform)
