"""Tests for :mod:`oceanrender.vision.model`."""

import dataclasses

import colour
import numpy as np
import pytest

from oceanrender.vision import (
    BRIGHTNESS_METHODS,
    CHROMATIC_ADAPTATION_TRANSFORMS,
    VisionModel,
    XYZ_to_display_sRGB_linear,
    XYZ_white_D65,
    brightness_response,
    brightness_scale_factor,
)
from tests.tolerances import ROUNDOFF, ROUNDOFF32

RTOL = ROUNDOFF32  # float32 output

XYZ_A_5000 = colour.xy_to_XYZ(colour.CCS_ILLUMINANTS["CIE 1931 2 Degree Standard Observer"]["A"]) * 5000.0


@pytest.mark.parametrize("brightness", list(BRIGHTNESS_METHODS))
@pytest.mark.parametrize("transform", ["Von Kries", "Bradford", "CAT02", "CAT16", "XYZ Scaling"])
def test_neutral_grey_under_illuminant_A_is_neutral(brightness, transform):
    model = VisionModel(brightness, transform, 100.0)
    grey = 0.18 * XYZ_A_5000  # 18 % grey card lit by the adapting white: Y = 900 cd/m²
    L_wa = 900.0
    RGB = model.apply(grey, XYZ_A_5000, L_wa)
    assert RGB.dtype == np.float32
    np.testing.assert_allclose(RGB, RGB[1], rtol=RTOL)
    # Level: display Y = r(m · 900 / 100) (r: the method's response), and D65 at Y maps to RGB = Y.
    m = brightness_scale_factor(brightness, L_wa, 100.0)
    np.testing.assert_allclose(RGB, brightness_response(brightness, m * 9.0), rtol=RTOL)


def test_default_is_the_compressive_operator():
    assert VisionModel().brightness == "Reinhard Devlin 2005"


def test_D65_white_at_display_adaptation_is_display_white():
    # Ward's m = 1 when L_wa = L_da = 50 cd/m²; 100 cd/m² D65 is then the display's white.
    model = VisionModel("Ward 1994")
    RGB = model.apply(XYZ_white_D65(100.0), XYZ_white_D65(1.0), 50.0)
    np.testing.assert_allclose(RGB, [1.0, 1.0, 1.0], rtol=RTOL)


def test_chromatic_adaptation_changes_colour():
    # The same stimulus looks bluer when the eye is adapted to a warmer white.
    stimulus = XYZ_white_D65(500.0)
    model = VisionModel("Ward 1994")
    under_D65 = model.apply(stimulus, XYZ_white_D65(1.0), 500.0)
    under_A = model.apply(stimulus, XYZ_A_5000, 500.0)
    np.testing.assert_allclose(under_D65, under_D65[0], rtol=RTOL)
    assert under_A[2] > under_A[1] > under_A[0]


def test_broadcasting_image_and_pixel(rng):
    model = VisionModel("Ferwerda 1996", "CAT02", 200.0)
    XYZ = rng.uniform(0.0, 4000.0, size=(5, 7, 3))
    image = model.apply(XYZ, XYZ_A_5000, 1500.0)
    assert image.shape == (5, 7, 3) and image.dtype == np.float32
    pixel = model.apply(XYZ[3, 4], XYZ_A_5000, 1500.0)
    assert pixel.shape == (3,)
    # One pixel and a whole image may take different matrix kernels (float64 last bits, then
    # a float32 cast); random XYZ give out-of-gamut channels near 0: relative to the image's scale.
    scale = np.abs(image).max()
    np.testing.assert_allclose(image[3, 4], pixel, rtol=0, atol=ROUNDOFF32 * scale)
    # Exact: the function builds the same VisionModel and calls apply on the same inputs.
    np.testing.assert_array_equal(
        XYZ_to_display_sRGB_linear(XYZ, XYZ_A_5000, 1500.0, "Ferwerda 1996", "CAT02", 200.0),
        image,
    )


@pytest.mark.parametrize("brightness", list(BRIGHTNESS_METHODS))
def test_chromatic_adaptation_changes_colour_any_operator(brightness):
    stimulus = XYZ_white_D65(500.0)
    under_A = VisionModel(brightness).apply(stimulus, XYZ_A_5000, 500.0)
    assert under_A[2] > under_A[1] > under_A[0]


def test_linear_stage_is_linear_for_every_operator(rng):
    XYZ = rng.uniform(0.0, 4000.0, size=(3, 3))
    for brightness in BRIGHTNESS_METHODS:
        model = VisionModel(brightness)
        once = 2.0 * model.linear(XYZ, XYZ_A_5000, 900.0)
        np.testing.assert_allclose(model.linear(2.0 * XYZ, XYZ_A_5000, 900.0), once, rtol=0,
                                   atol=ROUNDOFF * np.abs(once).max())
        # apply = response(linear), in float32.
        np.testing.assert_allclose(model.apply(XYZ, XYZ_A_5000, 900.0), model.response(once / 2.0),
                                   rtol=0, atol=ROUNDOFF32)


def test_compressive_operator_never_reaches_white(rng):
    # Luminances from 10⁻² to 10⁸ × the adaptation luminance (sky to sun disc): all channels < 1,
    # order of luminance kept, and the adaptation luminance's D65 grey displayed as 18 %.
    model = VisionModel()
    Y = np.logspace(0, 10, 101)
    linear = model.linear(XYZ_white_D65(1.0)[None, :] * Y[:, None], XYZ_white_D65(1.0), 100.0)
    RGB = model.response(linear)  # float64: the float32 output rounds to 1 only above ~10⁷ σ
    assert np.all(RGB < 1.0) and np.all(np.diff(RGB[:, 1]) > 0)
    np.testing.assert_allclose(model.apply(XYZ_white_D65(100.0), XYZ_white_D65(1.0), 100.0), 0.18, rtol=RTOL)


@pytest.mark.parametrize("brightness", list(BRIGHTNESS_METHODS))
def test_exposure_doubles_linear_stage(brightness):
    XYZ = XYZ_white_D65(321.0)
    plain = VisionModel(brightness).linear(XYZ, XYZ_A_5000, 900.0)
    np.testing.assert_allclose(VisionModel(brightness, exposure=1.0).linear(XYZ, XYZ_A_5000, 900.0), 2.0 * plain,
                               rtol=ROUNDOFF)
    np.testing.assert_allclose(VisionModel(brightness, exposure=-2.5).linear(XYZ, XYZ_A_5000, 900.0),
                               2.0**-2.5 * plain, rtol=ROUNDOFF)


@pytest.mark.parametrize("value", [11.0, -10.5, float("nan"), float("inf"), "1"])
def test_invalid_exposure(value):
    with pytest.raises(ValueError, match="exposure"):
        VisionModel(exposure=value)


def test_linear_in_XYZ(rng):
    model = VisionModel("Ward 1994")
    XYZ = rng.uniform(0.0, 4000.0, size=(3, 3))
    once = 2.0 * model.apply(XYZ, XYZ_A_5000, 900.0)
    # float32 output; channels of random XYZ can be near 0 after the matrices: relative to the scale.
    np.testing.assert_allclose(
        model.apply(2.0 * XYZ, XYZ_A_5000, 900.0), once, rtol=0, atol=ROUNDOFF32 * np.abs(once).max()
    )


def test_nan_pixels_stay_nan():
    XYZ = np.array([[np.nan, 1.0, 1.0], [100.0, 100.0, 100.0]])
    RGB = VisionModel().apply(XYZ, XYZ_A_5000, 100.0)
    assert np.all(np.isnan(RGB[0])) and np.all(np.isfinite(RGB[1]))


def test_unknown_brightness_names_field():
    with pytest.raises(ValueError, match="brightness") as info:
        VisionModel(brightness="Reinhard 2002")
    assert "'Ward 1994'" in str(info.value) and "'Ferwerda 1996'" in str(info.value)


def test_unknown_transform_names_field():
    with pytest.raises(ValueError, match="chromatic_transform") as info:
        VisionModel(chromatic_transform="von kries 1902")
    for name in CHROMATIC_ADAPTATION_TRANSFORMS:
        assert repr(name) in str(info.value)


@pytest.mark.parametrize("value", [0.0, -100.0, float("nan"), float("inf")])
def test_invalid_display_max_luminance(value):
    with pytest.raises(ValueError, match="display_max_luminance"):
        VisionModel(display_max_luminance=value)


@pytest.mark.parametrize("value", [0.0, -1.0, float("nan")])
def test_invalid_adaptation_luminance(value):
    with pytest.raises(ValueError, match="adaptation_luminance"):
        VisionModel().apply(XYZ_white_D65(1.0), XYZ_A_5000, value)


def test_frozen():
    model = VisionModel()
    with pytest.raises(dataclasses.FrozenInstanceError):
        model.brightness = "Ferwerda 1996"
