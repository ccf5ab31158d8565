"""Tests for :mod:`oceanrender.vision.chromatic`."""

import colour
import numpy as np
import pytest

from oceanrender.vision.chromatic import (
    CCS_WHITE_D65,
    CHROMATIC_ADAPTATION_TRANSFORMS,
    XYZ_white_D65,
    chromatic_adaptation_to_D65,
)
from tests.tolerances import ROUNDOFF

#: Adaptation = 3×3 cone matrix, its inverse (LAPACK) and a diagonal scaling: relative,
#: well above their float64 round-off (cond ≲ 10), far below any visible difference.
RTOL = 1e-9

_CCS = colour.CCS_ILLUMINANTS["CIE 1931 2 Degree Standard Observer"]

# Adapting whites at arbitrary scales: illuminant A (2856 K, incandescent) and
# a CIE daylight at 5500 K.
WHITES = {
    "A": colour.xy_to_XYZ(_CCS["A"]) * 5000.0,
    "daylight 5500 K": colour.xy_to_XYZ(colour.temperature.CCT_to_xy_CIE_D(5500.0)) * 0.037,
}


def test_transform_names_come_from_colour():
    assert CHROMATIC_ADAPTATION_TRANSFORMS == tuple(colour.CHROMATIC_ADAPTATION_TRANSFORMS)
    for name in ("Von Kries", "Bradford", "CAT02", "CAT16", "XYZ Scaling"):
        assert name in CHROMATIC_ADAPTATION_TRANSFORMS


def test_D65_white():
    np.testing.assert_allclose(CCS_WHITE_D65, [0.3127, 0.3290], rtol=0, atol=ROUNDOFF)  # chromaticity, scale 1
    XYZ = XYZ_white_D65(1.0)
    np.testing.assert_allclose(XYZ, [0.3127 / 0.3290, 1.0, (1 - 0.3127 - 0.3290) / 0.3290], rtol=ROUNDOFF)
    assert XYZ_white_D65([1.0, 2.0]).shape == (2, 3)


@pytest.mark.parametrize("white", list(WHITES))
@pytest.mark.parametrize("transform", CHROMATIC_ADAPTATION_TRANSFORMS)
def test_adapting_white_maps_to_D65(white, transform):
    XYZ_w = WHITES[white]
    adapted = chromatic_adaptation_to_D65(XYZ_w, XYZ_w, transform)
    # Same luminance, D65 chromaticity.
    np.testing.assert_allclose(adapted, XYZ_white_D65(XYZ_w[1]), rtol=RTOL)
    np.testing.assert_allclose(colour.XYZ_to_xy(adapted), CCS_WHITE_D65, rtol=0, atol=ROUNDOFF)  # scale 1


@pytest.mark.parametrize("white", list(WHITES))
def test_scale_of_white_does_not_matter(white):
    XYZ = np.array([[0.2, 0.3, 0.1], [12.0, 10.0, 3.0]])
    XYZ_w = WHITES[white]
    np.testing.assert_allclose(
        chromatic_adaptation_to_D65(XYZ, XYZ_w),
        chromatic_adaptation_to_D65(XYZ, XYZ_w * 1e-3),
        rtol=RTOL,
    )


def test_Von_Kries_is_colour_von_kries():
    # Direct check against colour with XYZ_wr built by hand.
    XYZ = np.array([0.20654008, 0.12197225, 0.05136952])
    XYZ_w = WHITES["A"]
    XYZ_wr = colour.xy_to_XYZ(_CCS["D65"]) * XYZ_w[1]
    expected = colour.adaptation.chromatic_adaptation_VonKries(XYZ, XYZ_w, XYZ_wr, transform="Von Kries")
    # Same algebra, two implementations (ours and colour's): round-off, relative (all channels ~0.1).
    np.testing.assert_allclose(chromatic_adaptation_to_D65(XYZ, XYZ_w), expected, rtol=ROUNDOFF)
    # An incandescent white is yellow-red: adapting to D65 must raise Z and lower X.
    adapted = chromatic_adaptation_to_D65(XYZ_w, XYZ_w)
    assert adapted[2] > XYZ_w[2] and adapted[0] < XYZ_w[0]


@pytest.mark.parametrize("transform", ["Von Kries", "Bradford", "CAT02", "CAT16"])
def test_identity_for_D65_white(transform, rng):
    XYZ = rng.uniform(0.0, 3000.0, size=(4, 5, 3))
    XYZ_w = XYZ_white_D65(1700.0)
    # Uniform random channels can be small next to the others in their pixel; M⁻¹ M mixes
    # them, so the error is relative to the image's scale, not to each channel.
    scale = np.abs(XYZ).max()
    np.testing.assert_allclose(chromatic_adaptation_to_D65(XYZ, XYZ_w, transform), XYZ, rtol=0, atol=ROUNDOFF * scale)


def test_broadcasting_image():
    XYZ = np.tile(np.array([0.3, 0.4, 0.5]), (6, 7, 1))
    out = chromatic_adaptation_to_D65(XYZ, WHITES["A"], "Bradford")
    assert out.shape == (6, 7, 3)
    single = chromatic_adaptation_to_D65(XYZ[0, 0], WHITES["A"], "Bradford")
    np.testing.assert_allclose(out, np.broadcast_to(single, (6, 7, 3)), rtol=RTOL)


def test_unknown_transform_raises():
    with pytest.raises(ValueError, match="Bradford") as info:
        chromatic_adaptation_to_D65([1.0, 1.0, 1.0], WHITES["A"], transform="Von Kriess")
    for name in CHROMATIC_ADAPTATION_TRANSFORMS:
        assert repr(name) in str(info.value)


@pytest.mark.parametrize("Y_w", [0.0, -1.0, np.nan])
def test_invalid_white_raises(Y_w):
    with pytest.raises(ValueError, match="luminance"):
        chromatic_adaptation_to_D65([1.0, 1.0, 1.0], [1.0, Y_w, 1.0])
