"""The ripple maps' mip pyramid, level of detail and LEAN terms (oceanrender.realtime.ripples), in numpy."""

import numpy as np
import pytest

from oceanrender.realtime.ripples import (
    MIN_ALPHA,
    effective_alpha,
    mip_pyramid,
    perturbed_normal,
    pixel_angle,
    ripple_lod,
    ripple_pyramids,
    ripple_texcoord,
    sample_repeat,
    sample_ripples,
    sample_trilinear,
    slope_moments,
)
from tests.tolerances import ROUNDOFF, ROUNDOFF32


@pytest.fixture
def tile(rng):
    """A smooth periodic height field η on 32² texels of a 2 m tile, its unit normals and slopes."""
    n, L = 32, 2.0
    x = np.arange(n) * L / n
    X, Y = np.meshgrid(x, x)  # row j is y_j, column i is x_i
    k = 2 * np.pi / L
    sx = 0.1 * k * np.cos(k * X) * np.sin(2 * k * Y) + 0.02 * rng.standard_normal((n, n))
    sy = 0.2 * k * np.sin(k * X) * np.cos(2 * k * Y) + 0.02 * rng.standard_normal((n, n))
    normals = np.stack([-sx, -sy, np.ones_like(sx)], axis=-1)
    normals /= np.linalg.norm(normals, axis=-1, keepdims=True)
    return normals, np.stack([sx, sy], axis=-1), L


def test_slope_moments_invert_the_normal_map(tile):
    normals, slopes, _ = tile
    m = slope_moments(normals)
    np.testing.assert_allclose(m[..., :2], slopes, rtol=ROUNDOFF32 * 10, atol=ROUNDOFF32)
    np.testing.assert_allclose(m[..., 2:], slopes**2, rtol=ROUNDOFF32 * 10, atol=ROUNDOFF32)


def test_pyramid_levels_are_box_means_down_to_the_tile_mean(tile):
    _, slopes, _ = tile
    levels = mip_pyramid(slopes)
    assert [lv.shape[0] for lv in levels] == [32, 16, 8, 4, 2, 1]
    np.testing.assert_allclose(levels[1][3, 5], slopes[6:8, 10:12].mean(axis=(0, 1)), rtol=ROUNDOFF32 * 10)
    np.testing.assert_allclose(levels[-1][0, 0], slopes.mean(axis=(0, 1)), atol=ROUNDOFF32 * 10)
    with pytest.raises(ValueError, match="power-of-two"):
        mip_pyramid(np.zeros((12, 12, 1)))


def test_lean_variance_decomposition_holds_at_every_level(tile):
    """Mean over a level of |⟨s⟩|² + σ² is the tile's mean-square slope: box filters keep second moments."""
    normals, slopes, L = tile
    p = ripple_pyramids(normals, np.zeros(slopes.shape), L)
    mss = float(np.mean(np.sum(slopes**2, axis=-1)))
    assert p.mean_square_slope == pytest.approx(mss, rel=ROUNDOFF32 * 100)
    for level in p.moments:
        m = level.astype(np.float64)
        mean2 = np.sum(m[..., :2] ** 2, axis=-1)
        var = m[..., 2] + m[..., 3] - mean2
        assert np.all(var >= -ROUNDOFF32 * mss)
        assert np.mean(mean2 + var) == pytest.approx(mss, rel=ROUNDOFF32 * 100)
    assert np.all(np.abs(p.moments[0][..., 2] + p.moments[0][..., 3]
                         - np.sum(p.moments[0][..., :2].astype(np.float64) ** 2, axis=-1)) < ROUNDOFF32 * mss * 10)


def test_bilinear_repeat_hits_texel_centres_and_wraps(tile):
    _, slopes, L = tile
    level = slopes.astype(np.float32)
    i, j = 7, 30
    st = np.array([(i + 0.5) / 32, (j + 0.5) / 32])
    np.testing.assert_allclose(sample_repeat(level, st), level[j, i], rtol=ROUNDOFF * 10)
    np.testing.assert_allclose(sample_repeat(level, st + [3.0, -2.0]), level[j, i], rtol=ROUNDOFF * 1e3)
    # Half-way between the last and the first column: the mean of the two (wrap-around).
    half = sample_repeat(level, np.array([0.0, (j + 0.5) / 32]))
    np.testing.assert_allclose(half, 0.5 * (level[j, 0] + level[j, 31]), rtol=ROUNDOFF32 * 10)
    # The texture coordinate of world x puts texel i's centre at x = i L / N.
    np.testing.assert_allclose(ripple_texcoord([[i * L / 32, j * L / 32]], L, 32)[0], st, rtol=ROUNDOFF * 10)


def test_trilinear_mixes_neighbouring_levels(tile):
    _, slopes, _ = tile
    levels = mip_pyramid(slopes)
    st = np.array([[0.3, 0.7]])
    a, b = sample_repeat(levels[2], st), sample_repeat(levels[3], st)
    np.testing.assert_allclose(sample_trilinear(levels, st, np.array([2.0])), a, rtol=ROUNDOFF * 10)
    np.testing.assert_allclose(sample_trilinear(levels, st, np.array([2.25])), 0.75 * a + 0.25 * b,
                               rtol=ROUNDOFF * 100)
    np.testing.assert_allclose(sample_trilinear(levels, st, np.array([99.0])), levels[-1][0, 0][None],
                               rtol=ROUNDOFF32 * 10)


def test_level_of_detail_is_the_footprint_in_texels():
    texel = 2.0 / 256
    angle = pixel_angle(60.0, 320)
    assert angle == pytest.approx(2 * np.tan(np.radians(30.0)) / 320, rel=ROUNDOFF)
    d = texel / angle  # a straight-down view at this distance sees one texel per pixel
    lod = ripple_lod(np.array([d, 2 * d, 8 * d, d / 4, np.inf]), np.array([-1.0, -1.0, -1.0, -1.0, -1.0]), angle,
                     texel, 9)
    np.testing.assert_allclose(lod, [0.0, 1.0, 3.0, 0.0, 8.0], atol=ROUNDOFF * 100)
    # A grazing ray stretches the footprint by 1/|d_z| (capped).
    grazing = ripple_lod(np.array([d]), np.array([-0.25]), angle, texel, 9)
    assert grazing[0] == pytest.approx(2.0, abs=ROUNDOFF * 100)


def test_perturbed_normal_adds_slopes_of_height_fields():
    # A mean surface of slope (0.1, 0) and a ripple of slope (0.05, -0.2): the sum's normal.
    mean = np.array([-0.1, 0.0, 1.0]) / np.sqrt(1.01)
    n = perturbed_normal(mean, np.array([0.05, -0.2]))
    expected = np.array([-0.15, 0.2, 1.0]) / np.linalg.norm([-0.15, 0.2, 1.0])
    np.testing.assert_allclose(n, expected, rtol=ROUNDOFF * 10)
    np.testing.assert_allclose(perturbed_normal(mean, np.zeros(2)), mean, rtol=ROUNDOFF * 10)
    steep = np.array([0.99, 0.0, 0.141])  # a wave front: left as it is
    np.testing.assert_allclose(perturbed_normal(steep, np.array([0.3, 0.3])), steep)


def test_effective_alpha_keeps_the_unresolved_roughness():
    alpha, mss = 0.16, 0.0138
    assert effective_alpha(alpha, 1.0, mss, mss) == pytest.approx(alpha, rel=ROUNDOFF)  # nothing resolved
    assert effective_alpha(alpha, 1.0, mss, 0.0) == pytest.approx(np.sqrt(alpha**2 - mss), rel=ROUNDOFF)
    assert effective_alpha(alpha, 0.0, mss, 0.0) == pytest.approx(alpha, rel=ROUNDOFF)  # strength 0
    assert effective_alpha(0.05, 1.0, mss, 0.0) == pytest.approx(MIN_ALPHA, rel=ROUNDOFF)  # floored


def test_far_pixels_see_the_mean_surface_and_the_whole_roughness(tile):
    normals, slopes, L = tile
    p = ripple_pyramids(normals, np.zeros(slopes.shape), L)
    up = np.array([[0.0, 0.0, 1.0]])
    far = sample_ripples(p, np.array([[0.3, 0.4, 0.0]]), up, np.array([1e6]), np.array([-0.5]), 1e-3, 0.5, 1.0)
    # The tile's mean slope: the periodic part averages to 0, the noise to ~0.02/32 per component.
    np.testing.assert_allclose(far.normal[0], [0, 0, 1], atol=0.02 / 32 * 4)
    assert p.mean_square_slope < 0.25
    assert far.alpha[0] == pytest.approx(0.5, rel=1e-4)  # σ²_top = mss up to float32 sums
    near = sample_ripples(p, np.array([[3 * L / 32, 5 * L / 32, 0.0]]), up, np.array([1e-3]), np.array([-1.0]),
                          1e-3, 0.5, 1.0)
    # Level 0 at a texel's centre: the texel's own slope tilts the normal, no variance is left unresolved.
    expected = perturbed_normal(up[0], slopes[5, 3])  # texel (i, j) = (3, 5) is centred at (3, 5) L/N
    np.testing.assert_allclose(near.normal[0], expected, rtol=ROUNDOFF32, atol=ROUNDOFF32)
    assert near.alpha[0] == pytest.approx(np.sqrt(0.25 - p.mean_square_slope), rel=1e-4)
