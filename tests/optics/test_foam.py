"""Tests for oceanrender.optics.foam: published whitecap reflectances and Koepke's efficiency factor."""

import math

import numpy as np
import pytest
from scipy.integrate import quad

from oceanrender.optics.foam import (
    EFFECTIVE_WHITECAP_REFLECTANCE_KOEPKE1984,
    FRESH_FOAM_REFLECTANCE_WHITLOCK1982,
    WHITECAP_EFFICIENCY_KOEPKE1984,
    foam_spectral_factor_Frouin1996,
    fresh_foam_decay_time,
)
from tests.tolerances import QUADRATURE, ROUNDOFF


def test_published_values():
    assert FRESH_FOAM_REFLECTANCE_WHITLOCK1982 == 0.55
    assert EFFECTIVE_WHITECAP_REFLECTANCE_KOEPKE1984 == 0.22
    # Koepke's effective reflectance is his efficiency factor times fresh foam's (0.4 × 0.55 = 0.22)
    assert WHITECAP_EFFICIENCY_KOEPKE1984 * FRESH_FOAM_REFLECTANCE_WHITLOCK1982 == pytest.approx(
        EFFECTIVE_WHITECAP_REFLECTANCE_KOEPKE1984, rel=ROUNDOFF)


def test_frouin_spectral_shape():
    factor = foam_spectral_factor_Frouin1996([400.0, 555.0, 700.0, 850.0, 1000.0])
    np.testing.assert_allclose(factor[[0, 1]], 1.0, rtol=ROUNDOFF)  # flat in the visible
    assert factor[3] == pytest.approx(0.6, rel=ROUNDOFF)  # −40 % at 850 nm
    assert 0.6 < factor[2] < 1.0 and factor[4] == pytest.approx(0.6, rel=ROUNDOFF)


@pytest.mark.parametrize("tau", [0.5, 2.0, 3.85])
def test_fresh_decay_time_gives_koepkes_efficiency(tau):
    tau_f = fresh_foam_decay_time(tau)
    life = tau * math.log(2.0)  # coverage from 1 to 1/2
    mean, _ = quad(lambda a: math.exp(-a / tau_f), 0.0, life)
    assert mean / life == pytest.approx(WHITECAP_EFFICIENCY_KOEPKE1984, rel=QUADRATURE)
    assert tau_f / tau == pytest.approx(0.3104, rel=1e-3)  # the root of (1 − e^{−x})/x = 0.4, 4 figures
    for bad in [dict(decay_time=0.0), dict(decay_time=1.0, efficiency=1.0)]:
        with pytest.raises(ValueError):
            fresh_foam_decay_time(**bad)
