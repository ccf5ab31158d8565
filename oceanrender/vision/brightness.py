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
-   :func:`semi_saturation_ReinhardDevlin2005` and
    :func:`response_ReinhardDevlin2005`: Reinhard and Devlin's photoreceptor
    model, a *compressive* operator: the cone response I/(I + σ) saturates
    smoothly instead of clipping, with the semi-saturation σ set by the
    adaptation luminance (global light adaptation).
-   :data:`BRIGHTNESS_METHODS` and :func:`brightness_scale_factor`: choose one
    of them by name; :data:`BRIGHTNESS_RESPONSES` and
    :func:`brightness_response`: the pointwise response that follows the
    linear scale (the identity for Ward and Ferwerda).
-   :func:`adaptation_luminance_log_average`: the world adaptation luminance
    :math:`L_{wa}` of an image as the log-average of its luminance.

Every method is written as a linear scale ``m`` (display units per world
luminance, the adaptation state) followed by a pointwise response ``r``:
``display = r(m · L_w / L_d,max)``. For Ward and Ferwerda ``r`` is the
identity; for Reinhard and Devlin it is the photoreceptor's hyperbola. The
split keeps the adapted image linear in light up to the last step, which the
real-time LUTs rely on (sums of light are formed before ``r``). The scale
multiplies X, Y and Z alike, so chromaticity is unchanged by it; chromatic
adaptation lives in :mod:`oceanrender.vision.chromatic`.

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
.. [4] E. Reinhard and K. Devlin, "Dynamic range reduction inspired by
   photoreceptor physiology," IEEE Trans. Vis. Comput. Graph., vol. 11,
   no. 1, pp. 13–24, 2005. doi:10.1109/TVCG.2005.9
.. [5] K. I. Naka and W. A. H. Rushton, "S-potentials from colour units in the
   retina of fish (Cyprinidae)," J. Physiol., vol. 185, no. 3, pp. 536–555,
   1966. doi:10.1113/jphysiol.1966.sp008001
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
    "semi_saturation_ReinhardDevlin2005",
    "response_ReinhardDevlin2005",
    "scale_factor_ReinhardDevlin2005",
    "response_identity",
    "BRIGHTNESS_METHODS",
    "BRIGHTNESS_RESPONSES",
    "brightness_scale_factor",
    "brightness_response",
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


def semi_saturation_ReinhardDevlin2005(
    adaptation_luminance: ArrayLike, intensity: float = 1.0, contrast: float = 1.0
) -> NDArray[np.float64]:
    """Semi-saturation σ of the photoreceptor model, :math:`σ(I_a) = (f I_a)^m` [cd/m²].

    Parameters
    ----------
    adaptation_luminance : array_like
        Adaptation luminance :math:`I_a` [cd/m²]; with global light adaptation
        (Reinhard and Devlin's a = 0) and chromatic adaptation left to the von
        Kries step (their c = 0) it is the scene's world adaptation luminance
        :math:`L_{wa}`.
    intensity : float, optional
        :math:`f = e^{-f'}` of [1] [-], > 0; 1 (f' = 0) is the paper's default.
    contrast : float, optional
        :math:`m` of [1] [-], in (0, 1].

    Returns
    -------
    numpy.ndarray
        σ [cd/m²]: the luminance at which the response is half its maximum.

    Notes
    -----
    With m = 1 (the default here) σ = f I_a is proportional to the adaptation
    luminance: Weber-law light adaptation, and an operator independent of the
    unit of luminance (scaling the whole scene, its adaptation included,
    leaves the display image unchanged), which an absolutely calibrated
    renderer needs. Reinhard and Devlin choose m < 1 from the image's log
    range, which presumes images in arbitrary relative units and makes m (and
    so the display) change from frame to frame; it is available but not used
    by :func:`scale_factor_ReinhardDevlin2005`.

    References
    ----------
    .. [1] E. Reinhard and K. Devlin, "Dynamic range reduction inspired by
       photoreceptor physiology," IEEE Trans. Vis. Comput. Graph. 11(1),
       13–24, 2005. doi:10.1109/TVCG.2005.9
    """
    if not (intensity > 0 and 0 < contrast <= 1):
        raise ValueError(f"need intensity f > 0 and contrast m in (0, 1], got {intensity!r}, {contrast!r}")
    I_a = np.asarray(adaptation_luminance, dtype=np.float64)

    return (intensity * I_a) ** contrast  # σ(I_a) = (f I_a)^m, [1]


def response_ReinhardDevlin2005(relative_intensity: ArrayLike) -> NDArray[np.float64]:
    """Photoreceptor response :math:`V = I/(I + σ)` as a function of :math:`x = I/σ` [-].

    .. math:: V(x) = \\frac{x}{1 + |x|}

    Parameters
    ----------
    relative_intensity : array_like
        Stimulus per semi-saturation, :math:`x = I/σ` [-], any shape.

    Returns
    -------
    numpy.ndarray
        Response :math:`V/V_{max}` in (−1, 1) [-]: display-relative, 1 is the
        display's white, reached only as x → ∞ (no clipping).

    Notes
    -----
    -   For x ≥ 0 this is the Naka–Rushton hyperbola with exponent 1 [2], the
        photoreceptor model of [1]; x = 1 (the adaptation luminance) gives one
        half, the display adaptation luminance :math:`L_{d,max}/2` that Ward
        and Ferwerda et al. map the world adaptation luminance to as well.
    -   Negative x (colours outside the display gamut, after the matrix to
        sRGB) are mapped by the odd extension −V(−x), so the response is
        continuous, monotone and bounded for every finite input; [1] has
        no negative intensities.
    -   NaN stays NaN; ±inf gives ±1.

    References
    ----------
    .. [1] E. Reinhard and K. Devlin, IEEE Trans. Vis. Comput. Graph. 11(1),
       13–24, 2005. doi:10.1109/TVCG.2005.9
    .. [2] K. I. Naka and W. A. H. Rushton, J. Physiol. 185(3), 536–555, 1966.
       doi:10.1113/jphysiol.1966.sp008001

    Examples
    --------
    >>> response_ReinhardDevlin2005([0.0, 1.0, 3.0]).tolist()
    [0.0, 0.5, 0.75]
    """
    x = np.asarray(relative_intensity, dtype=np.float64)
    with np.errstate(invalid="ignore"):
        V = np.where(np.isinf(x), np.sign(x), x / (1.0 + np.abs(x)))  # V = I/(I + σ), [1], [2]

    return V


def scale_factor_ReinhardDevlin2005(
    adaptation_luminance: ArrayLike, display_max_luminance: float = 100.0
) -> NDArray[np.float64]:
    """Linear stage of Reinhard and Devlin's operator as a scale factor :math:`m = L_{d,max}/σ`.

    Parameters
    ----------
    adaptation_luminance : array_like
        World adaptation luminance :math:`L_{wa}` [cd/m²].
    display_max_luminance : float, optional
        Maximum luminance of the display :math:`L_{d,max}` [cd/m²].

    Returns
    -------
    numpy.ndarray
        m [dimensionless]: ``m · L_w / L_d,max = L_w / σ`` is the
        :func:`response_ReinhardDevlin2005` input, with σ =
        :func:`semi_saturation_ReinhardDevlin2005` at f =
        :data:`INTENSITY_GREY_CARD` and m = 1: σ ≈ 4.56 L_wa.

    Notes
    -----
    f is chosen so that the world adaptation luminance (the scene's
    log-average) is displayed as an 18 % grey, V(L_wa) = 0.18: the
    calibration of reflected-light exposure meters (ISO 2720) and the key
    value of Reinhard et al. 2002. It is Reinhard and Devlin's user
    parameter f' = −ln f = −1.52, inside their range [−8, 8]; an exposure
    compensation of k EV divides σ by 2^k.
    """
    return display_max_luminance / semi_saturation_ReinhardDevlin2005(adaptation_luminance, INTENSITY_GREY_CARD)


#: Reinhard and Devlin's intensity parameter f for which V(L_wa) = 0.18: (1 − 0.18)/0.18 [-].
INTENSITY_GREY_CARD = (1.0 - 0.18) / 0.18


def response_identity(relative_intensity: ArrayLike) -> NDArray[np.float64]:
    """The response of the linear operators (Ward, Ferwerda et al.): display = input [-]."""
    return np.asarray(relative_intensity, dtype=np.float64)


BRIGHTNESS_METHODS: dict[str, Callable[..., NDArray[np.float64]]] = {
    "Ward 1994": scale_factor_Ward1994,
    "Ferwerda 1996": scale_factor_Ferwerda1996,
    "Reinhard Devlin 2005": scale_factor_ReinhardDevlin2005,
}
"""Global brightness-adaptation scale factors (the linear stage), by published method name."""

BRIGHTNESS_RESPONSES: dict[str, Callable[[ArrayLike], NDArray[np.float64]]] = {
    "Ward 1994": response_identity,
    "Ferwerda 1996": response_identity,
    "Reinhard Devlin 2005": response_ReinhardDevlin2005,
}
"""Pointwise display response after the linear stage, by method name (same keys as the methods)."""


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
    return _known(method, BRIGHTNESS_METHODS)(adaptation_luminance, display_max_luminance)


def brightness_response(method: str, relative_intensity: ArrayLike) -> NDArray[np.float64]:
    """The named method's pointwise response [-] (display-relative, 1 = display white).

    Raises
    ------
    ValueError
        If ``method`` is not a known name; the message lists the known names.
    """
    return _known(method, BRIGHTNESS_RESPONSES)(relative_intensity)


def _known(method: str, functions: dict[str, Callable]) -> Callable:
    """``functions[method]``, or a ValueError that lists the known names."""
    if method not in functions:
        raise ValueError(
            f"unknown brightness method {method!r}; known methods: "
            f"{', '.join(repr(name) for name in functions)}"
        )
    return functions[method]
