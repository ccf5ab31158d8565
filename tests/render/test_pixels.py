"""Samples for chosen pixels (render/pixels.py): counts honoured, halves independent, film units exact."""

import numpy as np
import pytest

from oceanrender.render.pixels import PixelSampler, PixelSums
from oceanrender.render.renderer import K_M
from tests.render.constant_sky import cmf_integrals, constant_sky_scene


def test_samples_alternate_between_the_halves_per_pixel():
    sums = PixelSums(3, 2)
    pixels = np.array([0, 0, 0, 4, 4, 5])
    xyz = np.arange(18, dtype=float).reshape(6, 3)
    sums.add(pixels, xyz)
    sums.add(np.array([0, 5]), np.ones((2, 3)))
    # Pixel 0: samples 1st, 3rd → A and 2nd, 4th → B; pixel 5: 1st → A, 2nd → B.
    np.testing.assert_array_equal(sums.counts[:, 0], [2, 2])
    np.testing.assert_array_equal(sums.counts[:, 5], [1, 1])
    np.testing.assert_array_equal(sums.per_pixel_counts().ravel(), [4, 0, 0, 0, 2, 2])
    a, b = sums.halves()
    np.testing.assert_array_equal(a.reshape(-1, 3)[0], (xyz[0] + xyz[2]) / 2)
    np.testing.assert_array_equal(b.reshape(-1, 3)[0], (xyz[1] + 1.0) / 2)
    image = sums.image().reshape(-1, 3)
    np.testing.assert_array_equal(image[0], (xyz[0] + xyz[1] + xyz[2] + 1.0) / 4)
    np.testing.assert_array_equal(image[1], 0.0)  # no samples: 0, not NaN


@pytest.mark.render
def test_pixel_sampler_develops_the_film_as_specfilm_does(variant):
    # A constant environment of spectral radiance 1 W m⁻² sr⁻¹ nm⁻¹: every pixel's XYZ is
    # K_m ∫x̄ dλ, K_m ∫ȳ dλ, K_m ∫z̄ dλ (CIE 015:2018 Eq. 7.1) over the film's 360–830 nm.
    import mitsuba as mi

    scene = constant_sky_scene(16, 8, 4)
    sampler = PixelSampler(scene, lanes=4096)
    counts = np.tile([64, 192], (8, 8))  # 16 px wide: alternate columns get 64 and 192 samples
    sums = sampler.render(counts, seed=11)
    np.testing.assert_array_equal(sums.per_pixel_counts(), counts)
    expected = K_M * cmf_integrals()
    # 16 384 samples of 4 wavelengths each: the spectral Monte Carlo error of the mean is ≲ 0.5 %
    # (z̄, the peakiest, measured 1.2 % at 2048 samples).
    np.testing.assert_allclose(sums.image().reshape(-1, 3).mean(axis=0), expected, rtol=0.01)
    # ...and mi.render of the same scene, through Mitsuba's own film, agrees as closely.
    film = K_M * np.array(mi.render(scene, seed=3, spp=128)).reshape(-1, 3).mean(axis=0)
    np.testing.assert_allclose(sums.image().reshape(-1, 3).mean(axis=0), film, rtol=0.01)
    # Launches of the same seed repeat; another seed gives other samples.
    again = sampler.render(counts, seed=11).image()
    np.testing.assert_array_equal(again, sums.image())
    assert np.any(sampler.render(counts, seed=12).image() != sums.image())
