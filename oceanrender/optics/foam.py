"""Reflectance of whitecap foam: fresh, effective (life-averaged) and its spectral shape.

Fresh, dense foam reflects about 55 % of visible light, nearly flat in
wavelength (Whitlock, Bartlett & Gurganus 1982). A whitecap does not stay
fresh: its foam thins and its reflectance falls as it ages, so averaged over
the area and lifetime of the whitecaps seen in photographs (those the whitecap
fraction W of Monahan & O'Muircheartaigh 1980 counts) the reflectance is
0.4 ± 0.2 of the fresh value, 22 % in the visible (Koepke 1984). In the near
infrared the foam's reflectance falls, by about 40 % at 850 nm against the
visible (Frouin, Schwindling & Deschamps 1996), as water absorbs inside the
foam layer.

:func:`fresh_foam_decay_time` turns Koepke's efficiency factor into the
e-folding time of a patch's reflectance used by
:func:`oceanrender.waves.foam.two_stage_foam_step`.

References
----------
.. [1] C. H. Whitlock, D. S. Bartlett and E. A. Gurganus, "Sea foam
   reflectance and influence on optimum wavelength for remote sensing of
   ocean aerosols", Geophys. Res. Lett. 9(6), 719–722, 1982.
.. [2] P. Koepke, "Effective reflectance of oceanic whitecaps", Appl. Opt.
   23(11), 1816–1824, 1984, doi:10.1364/AO.23.001816.
.. [3] R. Frouin, M. Schwindling and P.-Y. Deschamps, "Spectral reflectance
   of sea foam in the visible and near-infrared: in situ measurements and
   remote sensing implications", J. Geophys. Res. 101(C6), 14361–14371,
   1996, doi:10.1029/96JC00629.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.optimize import brentq

__all__ = [
    "FRESH_FOAM_REFLECTANCE_WHITLOCK1982",
    "EFFECTIVE_WHITECAP_REFLECTANCE_KOEPKE1984",
    "WHITECAP_EFFICIENCY_KOEPKE1984",
    "foam_spectral_factor_Frouin1996",
    "fresh_foam_decay_time",
]

FRESH_FOAM_REFLECTANCE_WHITLOCK1982: float = 0.55
"""Reflectance of fresh, dense sea foam in the visible, Whitlock et al. (1982) as used by Koepke (1984) [-]."""

WHITECAP_EFFICIENCY_KOEPKE1984: float = 0.4
"""Mean reflectance of the whitecaps W counts over that of fresh foam, Koepke (1984) (± 0.2) [-]."""

EFFECTIVE_WHITECAP_REFLECTANCE_KOEPKE1984: float = 0.22
"""Effective reflectance of oceanic whitecaps in the visible, Koepke (1984) (0.22 ± 0.11) [-]."""


def foam_spectral_factor_Frouin1996(wavelength: ArrayLike) -> NDArray[np.floating]:
    """Foam reflectance relative to its visible value [-], after Frouin et al. (1996).

    1 up to 555 nm, falling linearly to 0.6 at 850 nm (their 40 % decrease at
    850 nm), held at 0.6 beyond.

    Parameters
    ----------
    wavelength : array_like
        Wavelength [nm].

    Returns
    -------
    ndarray
        Factor in (0, 1] [-].

    Notes
    -----
    [3] report decreases of 40 %, 50 % and 85 % at 850 nm, 1.02 µm and
    1.65 µm against the visible; the linear ramp from 555 nm is the shape of
    NASA's ocean-colour whitecap correction built on them (1 to 555 nm, 0.889 at
    670 nm, 0.645 at 865 nm), simplified to one line.
    """
    wavelength = np.asarray(wavelength, dtype=np.float64)
    return np.interp(wavelength, [555.0, 850.0], [1.0, 0.6])  # −40 % at 850 nm, [3]


def fresh_foam_decay_time(decay_time: float, efficiency: float = WHITECAP_EFFICIENCY_KOEPKE1984) -> float:
    """e-folding time τ_f of a whitecap patch's reflectance that gives Koepke's efficiency factor [s].

    A patch formed at full coverage decays as e^{−a/τ} and counts as a
    whitecap while its coverage is at least ½, for L = τ ln 2. Its
    reflectance, fresh foam's times e^{−a/τ_f}, averages ``efficiency`` times
    fresh over that life when (1 − e^{−x})/x = efficiency, x = L/τ_f.

    Parameters
    ----------
    decay_time : float
        τ > 0, e-folding time of the whitecap coverage [s].
    efficiency : float, optional
        Life-averaged over fresh reflectance, in (0, 1) [-]; 0.4 (Koepke 1984).

    Returns
    -------
    float
        τ_f [s]; 0.310 τ for the default.
    """
    if not decay_time > 0:
        raise ValueError(f"decay_time must be > 0 [s], got {decay_time!r}")
    if not 0 < efficiency < 1:
        raise ValueError(f"efficiency must lie in (0, 1), got {efficiency!r}")
    x = brentq(lambda x: -math.expm1(-x) / x - efficiency, 1e-9, 1e3, xtol=1e-14)
    return decay_time * math.log(2.0) / x
