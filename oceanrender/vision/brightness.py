"""
Global brightness adaptation
============================

Linear scale factors ``m`` that map world luminance :math:`L_w` [cd/m²] to
display luminance :math:`L_d = m L_w` [cd/m²] so that a just-visible contrast in
the scene stays just visible on the display:

-   :func:`scale_factor_Ward1994`: Ward's contrast-based scale factor, built
    on Blackwell's threshold-versus-intensity data.
-   :func:`scale_factor_Ferwerda1996`: the photopic (cone) scale factor of
    Ferwerda, Pattanaik, Shirley and Greenberg.
-   :data:`BRIGHTNESS_METHODS` and :func:`brightness_scale_factor`: choose one
    of them by name.
-   :func:`adaptation_luminance_log_average`: the world adaptation luminance
    :math:`L_{wa}` of an image as the log-average of its luminance.

The factor multiplies all three of X, Y and Z, so chromaticity is unchanged:
only luminance is adapted here; chromatic adaptation lives in
:mod:`oceanrender.vision.chromatic`.

Both methods take the display adaptation luminance as half the display's
maximum luminance, :math:`L_{da} = L_{d,max}/2`, as Ward [1] suggests and
Ferwerda et al. [2] adopt.

References
----------
.. [1] G. Ward, "A contrast-based scalefactor for luminance display," in
   Graphics Gems IV, P. S. Heckbert, Ed. Boston, MA, USA: Academic Press,
   1994, pp. 415–421.
.. [2] J. A. Ferwerda, S. N. Pattanaik, P. Shirley and D. P. Greenberg, "A
   model of visual adaptation for realistic image synthesis," in Proc.
   SIGGRAPH 96, 1996, pp. 249–258. doi:10.1145/237170.237262
.. [3] E. Reinhard, M. Stark, P. Shirley and J. Ferwerda, "Photographic tone
   reproduction for digital images," ACM Trans. Graph., vol. 21, no. 3,
   pp. 267–276, 2002. doi:10.1145/566654.566575
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = [
    "adaptation_luminance_log_average",
    "threshold_photopic_Ferwerda1996",
    "scale_factor_Ward1994",
    "scale_factor_Ferwerda1996",
    "BRIGHTNESS_METHODS",
    "brightness_scale_factor",
]


def adaptation_luminance_log_average(Y: ArrayLike, delta: float = 1e-4) -> float:
    """World adaptation luminance :math:`L_{wa}` as the log-average luminance.

    .. math:: L_{wa} = \\exp\\left(\\frac{1}{N}\\sum \\ln(\\delta + L_w)\\right)

    Parameters
    ----------
    Y : array_like
        Absolute luminance of every pixel, any shape [cd/m²].
    delta : float, optional
        Small offset that keeps black pixels from sending the logarithm to
        :math:`-\\infty` [cd/m²].

    Returns
    -------
    float
        Log-average luminance [cd/m²]. It includes ``delta``: a constant image
        of luminance ``L`` gives ``L + delta``.

    Raises
    ------
    ValueError
        If ``Y`` holds no finite value.

    Notes
    -----
    -   Non-finite values (NaN, ±inf, e.g. failed path-tracer samples) are
        ignored: they are left out of both the sum and the count N.
    -   Negative values, which non-negative radiance cannot produce but a
        denoiser can, are clipped to 0 (treated as black).
    -   Reinhard et al. [2] print the :math:`1/N` outside the exponential in
        their Eq. 1; the log-average meant (and used by Ward [1]) has it
        inside, as here.

    References
    ----------
    .. [1] G. Ward, "A contrast-based scalefactor for luminance display," in
       Graphics Gems IV. Academic Press, 1994, pp. 415–421.
    .. [2] E. Reinhard, M. Stark, P. Shirley and J. Ferwerda, "Photographic
       tone reproduction for digital images," ACM Trans. Graph., vol. 21,
       no. 3, pp. 267–276, 2002. doi:10.1145/566654.566575

    Examples
    --------
    >>> adaptation_luminance_log_average([1.0, 100.0], delta=0.0)  # doctest: +ELLIPSIS
    10.0...
    """
    Y = np.asarray(Y, dtype=np.float64)
    Y = Y[np.isfinite(Y)]
    if Y.size == 0:
        raise ValueError("no finite luminance value to average")
    # NOTE: clip, not drop, negatives: dropping them would bias L_wa upwards.
    Y = np.maximum(Y, 0.0)

    return float(np.exp(np.mean(np.log(delta + Y))))  # Eq. 1 of [2]


def scale_factor_Ward1994(
    adaptation_luminance: ArrayLike, display_max_luminance: float = 100.0
) -> NDArray[np.float64]:
    """Ward's contrast-based scale factor :math:`m` (display per world luminance).

    .. math::

        m = \\left[\\frac{1.219 + L_{da}^{0.4}}{1.219 + L_{wa}^{0.4}}\\right]^{2.5},
        \\qquad L_{da} = L_{d,max}/2, \\qquad L_d = m L_w

    Parameters
    ----------
    adaptation_luminance : array_like
        World adaptation luminance :math:`L_{wa}` [cd/m²].
    display_max_luminance : float, optional
        Maximum luminance of the display :math:`L_{d,max}` [cd/m²].

    Returns
    -------
    numpy.ndarray
        Scale factor :math:`m` [dimensionless] (display luminance [cd/m²] per world
        luminance [cd/m²]); divide :math:`m L_w` by :math:`L_{d,max}` to get the
        display input in [0, 1].

    Notes
    -----
    The constants come from Blackwell's threshold-versus-intensity fit
    :math:`\\Delta L(L_a) = 0.0594 (1.219 + L_a^{0.4})^{2.5}` [1]; requiring
    :math:`\\Delta L(L_{da}) = m \\Delta L(L_{wa})` gives the factor above.
    :math:`m` decreases monotonically with :math:`L_{wa}` and equals 1 when
    :math:`L_{wa} = L_{da}`.

    References
    ----------
    .. [1] G. Ward, "A contrast-based scalefactor for luminance display," in
       Graphics Gems IV, P. S. Heckbert, Ed. Academic Press, 1994,
       pp. 415–421.

    Examples
    --------
    >>> float(scale_factor_Ward1994(1000.0, 100.0))  # doctest: +ELLIPSIS
    0.0732932...
    """
    L_wa = np.asarray(adaptation_luminance, dtype=np.float64)
    L_da = display_max_luminance / 2  # Ward's choice L_da = L_dmax / 2 [1]

    return ((1.219 + L_da**0.4) / (1.219 + L_wa**0.4)) ** 2.5  # [1], scale factor m


def threshold_photopic_Ferwerda1996(adaptation_luminance: ArrayLike) -> NDArray[np.float64]:
    """Photopic (cone) threshold-versus-intensity :math:`t_p(L_a)` [cd/m²].

    .. math::

        \\log_{10} t_p = \\begin{cases}
            -0.72 & \\log_{10} L_a \\le -2.6 \\\\
            \\log_{10} L_a - 1.255 & \\log_{10} L_a \\ge 1.9 \\\\
            (0.249 \\log_{10} L_a + 0.65)^{2.7} - 0.72 & \\text{otherwise}
        \\end{cases}

    Parameters
    ----------
    adaptation_luminance : array_like
        Adaptation luminance :math:`L_a` [cd/m²].

    Returns
    -------
    numpy.ndarray
        Just-detectable luminance increment :math:`t_p` [cd/m²].

    Notes
    -----
    The published piecewise fit is continuous at :math:`\\log_{10} L_a = -2.6`
    to about 1e-7 decades, but at :math:`\\log_{10} L_a = 1.9` the middle branch
    gives 0.64814 and the Weber branch 0.645: a jump of 3.1e-3 decades (0.72 %
    in :math:`t_p`), from the rounding of the published constants. The
    constants are kept as published; nothing is smoothed.

    References
    ----------
    .. [1] J. A. Ferwerda, S. N. Pattanaik, P. Shirley and D. P. Greenberg, "A
       model of visual adaptation for realistic image synthesis," in Proc.
       SIGGRAPH 96, 1996, pp. 249–258. doi:10.1145/237170.237262
    """
    with np.errstate(divide="ignore", invalid="ignore"):
        x = np.log10(np.asarray(adaptation_luminance, dtype=np.float64))
    # NOTE: the base is negative below log10 L_a ≈ -2.61, where this branch is
    # not selected anyway; clip it so that the unused branch stays finite.
    middle = np.maximum(0.249 * x + 0.65, 0.0) ** 2.7 - 0.72

    log_t_p = np.where(
        x <= -2.6,
        -0.72,  # [1], photopic TVI, threshold (dark) branch
        np.where(
            x >= 1.9,
            x - 1.255,  # [1], photopic TVI, Weber branch
            middle,  # [1], photopic TVI, transition branch
        ),
    )
    # NaN (negative or NaN L_a) fails both comparisons: let it through.
    log_t_p = np.where(np.isnan(x), np.nan, log_t_p)

    return 10.0**log_t_p


def scale_factor_Ferwerda1996(
    adaptation_luminance: ArrayLike, display_max_luminance: float = 100.0
) -> NDArray[np.float64]:
    """Ferwerda et al. photopic scale factor :math:`m_p` (display per world luminance).

    .. math:: m_p = \\frac{t_p(L_{da})}{t_p(L_{wa})}, \\qquad L_{da} = L_{d,max}/2

    with :math:`t_p` from :func:`threshold_photopic_Ferwerda1996`.

    Parameters
    ----------
    adaptation_luminance : array_like
        World adaptation luminance :math:`L_{wa}` [cd/m²].
    display_max_luminance : float, optional
        Maximum luminance of the display :math:`L_{d,max}` [cd/m²].

    Returns
    -------
    numpy.ndarray
        Scale factor :math:`m_p` [dimensionless]; display luminance :math:`L_d = m_p L_w`
        [cd/m²].

    Notes
    -----
    -   Only the photopic (cone) term is implemented. The full model adds a
        scotopic (rod) term :math:`m_s L_{w,scotopic}` that matters only in the
        scotopic and mesopic ranges, i.e. for adaptation luminances below about
        3 cd/m². Daylight sea scenes adapt at 10²–10⁴ cd/m², and the display
        adaptation :math:`L_{da} = 50` cd/m² (for a 100 cd/m² display) is
        photopic too, so the rod term is omitted. Do not use this function for
        night or deep-twilight scenes (:math:`L_{wa}` ≲ 3 cd/m²).
    -   For :math:`L_{wa} \\ge 10^{1.9} \\approx 79` cd/m² the Weber branch of
        :math:`t_p` makes :math:`m_p \\propto 1/L_{wa}`: the scene's
        adaptation luminance is mapped to a fixed display luminance.

    References
    ----------
    .. [1] J. A. Ferwerda, S. N. Pattanaik, P. Shirley and D. P. Greenberg, "A
       model of visual adaptation for realistic image synthesis," in Proc.
       SIGGRAPH 96, 1996, pp. 249–258. doi:10.1145/237170.237262

    Examples
    --------
    >>> float(scale_factor_Ferwerda1996(1000.0, 100.0))  # doctest: +ELLIPSIS
    0.05554816...
    """
    L_da = display_max_luminance / 2  # L_da = L_dmax / 2, as in [1]

    return threshold_photopic_Ferwerda1996(L_da) / threshold_photopic_Ferwerda1996(
        adaptation_luminance
    )  # [1], photopic scale factor m_p


BRIGHTNESS_METHODS: dict[str, Callable[..., NDArray[np.float64]]] = {
    "Ward 1994": scale_factor_Ward1994,
    "Ferwerda 1996": scale_factor_Ferwerda1996,
}
"""Global brightness-adaptation scale factors, by published method name."""


def brightness_scale_factor(
    method: str,
    adaptation_luminance: ArrayLike,
    display_max_luminance: float = 100.0,
) -> NDArray[np.float64]:
    """Brightness scale factor :math:`m` by the named method.

    Parameters
    ----------
    method : str
        A key of :data:`BRIGHTNESS_METHODS` (exact spelling).
    adaptation_luminance : array_like
        World adaptation luminance :math:`L_{wa}` [cd/m²].
    display_max_luminance : float, optional
        Maximum luminance of the display :math:`L_{d,max}` [cd/m²].

    Returns
    -------
    numpy.ndarray
        Scale factor :math:`m` [dimensionless]; display luminance :math:`L_d = m L_w`
        [cd/m²].

    Raises
    ------
    ValueError
        If ``method`` is not a known name; the message lists the known names.
    """
    if method not in BRIGHTNESS_METHODS:
        raise ValueError(
            f"unknown brightness method {method!r}; known methods: "
            f"{', '.join(repr(name) for name in BRIGHTNESS_METHODS)}"
        )

    return BRIGHTNESS_METHODS[method](adaptation_luminance, display_max_luminance)
