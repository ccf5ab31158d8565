"""Samples for chosen pixels (render/pixels.py): counts honoured, halves independent, film units exact."""

import numpy as np
import pytest

from oceanrender.render.pixels import PixelSampler, PixelSums, block_means, block_slots, grid_mean, grid_shape
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


def test_a_grid_of_blocks_covers_the_view_in_its_aspect():
    # 80 blocks across a 16:9 frame: 45 rows, whatever the resolution; never more blocks than pixels.
    assert grid_shape(1280, 720, 80) == (45, 80) == grid_shape(320, 180, 80)
    assert grid_shape(24, 16, 80) == (16, 24)
    # The block means of an image: a ramp's mean over each block is the mean of its pixels' values.
    image = np.add.outer(np.arange(180.0), 10.0 * np.arange(320.0))
    means = grid_mean(image, 80)
    assert means.shape == (45, 80)
    np.testing.assert_allclose(means[0, 0], image[:4, :4].mean())
    np.testing.assert_allclose(means[-1, -1], image[-4:, -4:].mean())
    # Uneven blocks (7 columns over 20 pixels: widths 2 or 3) keep the mean of the whole image.
    odd = np.random.default_rng(1).random((9, 20))
    w = np.diff((np.arange(8) * 20) // 7)
    h = np.diff((np.arange(4) * 9) // 3)
    assert grid_shape(20, 9, 7) == (3, 7)
    np.testing.assert_allclose((grid_mean(odd, 7) * np.outer(h, w)).sum(), odd.sum())


def test_block_slots_fall_in_their_blocks_and_repeat_per_seed():
    pixels, blocks, shape = block_slots(100, 50, 10, 32, seed=5)
    assert shape == (5, 10) and pixels.size == blocks.size == 5 * 10 * 32
    assert np.all(np.bincount(blocks) == 32)
    x, y = pixels % 100, pixels // 100
    assert np.all(x // 10 == blocks % 10) and np.all(y // 10 == blocks // 10)
    # every pixel of a block is drawn (32 draws over 100 pixels cover many; over all blocks, all 5000)
    assert np.unique(pixels).size > 0.9 * 5000 * (1 - np.exp(-32 / 100))
    again, _, _ = block_slots(100, 50, 10, 32, seed=5)
    np.testing.assert_array_equal(again, pixels)
    assert np.any(block_slots(100, 50, 10, 32, seed=6)[0] != pixels)


def test_block_means_of_a_constant_sky(variant):
    # Every block of a constant environment of 1 W m⁻² sr⁻¹ nm⁻¹ has XYZ = K_m ∫(x̄, ȳ, z̄) dλ; 512 samples of
    # 4 wavelengths per block, 32 blocks: 16 384 samples, the spectral error of the mean ≲ 0.5 % (as above).
    scene = constant_sky_scene(16, 8, 4)
    sampler = PixelSampler(scene, lanes=4096)
    pixels, blocks, shape = block_slots(16, 8, 8, 512, seed=2)
    means = block_means(sampler, pixels, blocks, shape, seed=9)
    assert means.shape == (4, 8, 3)
    np.testing.assert_allclose(means.reshape(-1, 3).mean(axis=0), K_M * cmf_integrals(), rtol=0.01)
