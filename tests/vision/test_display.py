"""Tests for :mod:`oceanrender.vision.display`."""

import colour
import numpy as np
import pytest

from oceanrender.vision.chromatic import XYZ_white_D65
from oceanrender.vision.display import (
    RGB_COLOURSPACE_sRGB,
    XYZ_to_sRGB_linear,
    encode_sRGB_8bit,
    sRGB_linear_to_XYZ,
)
from tests.tolerances import ROUNDOFF

#: The precision of values published to 4 decimals (IEC 61966-2-1) [scale 1].
TOL = 1e-4

# IEC 61966-2-1 primaries and white (CIE 1931 xy), typed in independently of colour.
XY_PRIMARIES = np.array([[0.64, 0.33], [0.30, 0.60], [0.15, 0.06]])
XY_WHITE = np.array([0.3127, 0.3290])
# XYZ → RGB matrix as printed (4 decimals) in IEC 61966-2-1.
M_IEC = np.array(
    [[3.2406, -1.5372, -0.4986], [-0.9689, 1.8758, 0.0415], [0.0557, -0.2040, 1.0570]]
)


def _xy_to_XYZ(xy, Y=1.0):
    x, y = xy
    return np.array([x / y, 1.0, (1 - x - y) / y]) * Y


def _primaries_XYZ():
    """XYZ of R, G, B at full drive: columns scaled so that R+G+B = white (Y=1)."""
    P = np.stack([_xy_to_XYZ(xy) for xy in XY_PRIMARIES], axis=1)
    S = np.linalg.solve(P, _xy_to_XYZ(XY_WHITE))
    return (P * S).T  # rows: XYZ of red, green, blue


def test_D65_white_to_unit_rgb():
    np.testing.assert_allclose(XYZ_to_sRGB_linear(XYZ_white_D65(1.0)), [1.0, 1.0, 1.0], atol=TOL)
    np.testing.assert_allclose(XYZ_to_sRGB_linear(XYZ_white_D65(1.0)), [1.0, 1.0, 1.0], atol=ROUNDOFF)  # scale 1


def test_matrix_agrees_with_IEC_published():
    # The printed matrix was derived from rounded intermediates: it differs from the exact
    # one by up to 3.5e-4, hence 5e-4 (not the 5e-5 of its last printed digit).
    np.testing.assert_allclose(RGB_COLOURSPACE_sRGB.matrix_XYZ_to_RGB, M_IEC, atol=5e-4)
    # colour's stock sRGB colourspace is left untouched: exact, it stores the printed constants.
    np.testing.assert_array_equal(colour.RGB_COLOURSPACES["sRGB"].matrix_XYZ_to_RGB, M_IEC)


def test_primaries_map_to_unit_vectors():
    XYZ_rgb = _primaries_XYZ()
    # Luminances of the primaries are the Rec. 709 luma weights.
    np.testing.assert_allclose(XYZ_rgb[:, 1], [0.2126, 0.7152, 0.0722], atol=1e-4)
    # Our primaries come from np.linalg.solve, the module's matrix from colour: two code paths.
    np.testing.assert_allclose(XYZ_to_sRGB_linear(XYZ_rgb), np.eye(3), atol=ROUNDOFF)  # identity, scale 1


def test_primaries_round_trip():
    XYZ_rgb = _primaries_XYZ()
    np.testing.assert_allclose(sRGB_linear_to_XYZ(np.eye(3)), XYZ_rgb, rtol=0, atol=ROUNDOFF * np.abs(XYZ_rgb).max())
    RGB = np.array([[0.2, 0.5, 0.9], [1.0, 0.0, 0.0], [3.0, -0.1, 0.4]])
    np.testing.assert_allclose(XYZ_to_sRGB_linear(sRGB_linear_to_XYZ(RGB)), RGB, rtol=0, atol=ROUNDOFF * np.abs(RGB).max())


def test_no_chromatic_adaptation_inside():
    # An illuminant-A white must NOT come out neutral: this step does not adapt.
    XYZ_A = colour.xy_to_XYZ(colour.CCS_ILLUMINANTS["CIE 1931 2 Degree Standard Observer"]["A"])
    R, G, B = XYZ_to_sRGB_linear(XYZ_A)
    assert R > G > B


def test_XYZ_to_sRGB_linear_broadcasts():
    XYZ = np.broadcast_to(XYZ_white_D65(0.5), (4, 6, 3))
    RGB = XYZ_to_sRGB_linear(XYZ)
    assert RGB.shape == (4, 6, 3)
    np.testing.assert_allclose(RGB, 0.5, rtol=ROUNDOFF)


def test_encode_end_points():
    assert encode_sRGB_8bit(0.0) == 0
    assert encode_sRGB_8bit(1.0) == 255
    out = encode_sRGB_8bit([0.0, 1.0])
    assert out.dtype == np.uint8
    np.testing.assert_array_equal(out, [0, 255])


def test_encode_clips_and_zeroes_non_finite():
    out = encode_sRGB_8bit([np.nan, np.inf, -np.inf, -0.5, 2.0, 1e30])
    np.testing.assert_array_equal(out, [0, 0, 0, 0, 255, 255])


def test_encode_sRGB_breakpoint():
    L = 0.0031308
    linear_branch = 12.92 * L  # = 0.04044994
    power_branch = 1.055 * L ** (1 / 2.4) - 0.055  # = 0.04044991
    assert linear_branch == pytest.approx(power_branch, abs=1e-7)
    V = colour.models.eotf_inverse_sRGB(L)
    assert V == pytest.approx(linear_branch, abs=1e-7)
    # 255 × 0.0404499 = 10.31 → 10 on both sides of the breakpoint.
    np.testing.assert_array_equal(encode_sRGB_8bit([L * (1 - 1e-6), L, L * (1 + 1e-6)]), [10, 10, 10])
    # Well inside each branch.
    assert encode_sRGB_8bit(0.001) == round(255 * 12.92 * 0.001)  # 3.29 → 3
    assert encode_sRGB_8bit(0.18) == 118  # 1.055·0.18^(1/2.4) − 0.055 = 0.46136; ×255 = 117.65


def test_encode_is_monotone_and_shape_preserving():
    L = np.linspace(0.0, 1.0, 4097).reshape(17, 241)
    out = encode_sRGB_8bit(L)
    assert out.shape == (17, 241)
    assert np.all(np.diff(out.ravel().astype(int)) >= 0)
    assert set(np.unique(out)) == set(range(256))


def test_encode_round_trip_with_colour_eotf():
    codes = np.arange(256)
    L = colour.models.eotf_sRGB(codes / 255)
    # Exact: integer codes; the round trip's ~1e-13 cannot move a value across a rounding boundary.
    np.testing.assert_array_equal(encode_sRGB_8bit(L), codes)
