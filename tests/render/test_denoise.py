"""OIDN denoising: the feature images line up with the camera, and denoising cuts the error of a noisy render.

Error measure (as in benchmarks/bench_denoise.py): relative MSE of
luminance, relMSE = mean over pixels of (Y − Y_ref)² / (Y_ref² + ε) with both
images divided by the reference's mean luminance and ε = 0.01 (Rousselle,
Knaus & Zwicker 2011, ACM TOG 30(6) 159, doi:10.1145/2070781.2024193: the
ε keeps dark pixels from dominating), leaving out the 0.1 % of pixels with
the largest error (a single caustic firefly can otherwise decide it).
"""

import numpy as np
import pytest

from oceanrender.render.denoise import (
    denoise_frame,
    smooth_chroma,
    LINEAR_SRGB_TO_XYZ,
    XYZ_TO_LINEAR_SRGB,
    FeatureRenderer,
    XYZ_to_linear_sRGB,
    denoise,
    denoise_XYZ,
    equal_energy_white_rgb,
    linear_sRGB_to_XYZ,
    split_features,
)
from tests.scenes import scene_from_dict
from oceanrender.surface.frame import FrameGeometry
from tests.tolerances import ROUNDOFF


def rel_mse(image, reference, eps=1e-2, trim=1e-3):
    """Trimmed relMSE of luminance (channel 1 of XYZ), both scaled by the reference's mean luminance."""
    scale = reference[..., 1].mean()
    y, r = image[..., 1] / scale, reference[..., 1] / scale
    errors = np.sort(((y - r) ** 2 / (r**2 + eps)).ravel())
    return float(errors[: errors.size - int(np.ceil(trim * errors.size))].mean())


def test_colour_matrices_are_inverse_and_white_is_sensible():
    np.testing.assert_allclose(XYZ_TO_LINEAR_SRGB @ LINEAR_SRGB_TO_XYZ, np.eye(3), atol=ROUNDOFF)  # identity, scale 1
    xyz = np.array([[0.3, 0.5, 0.9], [1e4, 2e4, 5e3]])
    np.testing.assert_allclose(linear_sRGB_to_XYZ(XYZ_to_linear_sRGB(xyz)), xyz, rtol=ROUNDOFF)  # channels ≫ 0
    # D65 white (Y = 1) maps to R = G = B = 1 (sRGB is defined so), to the matrix's 4 decimals.
    np.testing.assert_allclose(XYZ_to_linear_sRGB([0.95047, 1.0, 1.08883]), 1.0, atol=2e-3)
    np.testing.assert_allclose(equal_energy_white_rgb(), [1.2049, 0.9483, 0.9091], atol=2e-3)


def test_AP0_matrix_is_colour_sciences_and_keeps_the_spectral_locus_non_negative():
    import colour  # noqa: PLC0415

    from oceanrender.render.denoise import AP0_TO_XYZ, XYZ_TO_AP0  # noqa: PLC0415

    # Entries of order 1: 1e-9 absolute, far below a visible difference.
    np.testing.assert_allclose(XYZ_TO_AP0, colour.RGB_COLOURSPACES["ACES2065-1"].matrix_XYZ_to_RGB, atol=1e-9)
    np.testing.assert_allclose(XYZ_TO_AP0 @ AP0_TO_XYZ, np.eye(3), atol=ROUNDOFF)  # identity, scale 1
    cmfs = colour.MSDS_CMFS["CIE 1931 2 Degree Standard Observer"].values  # every monochromatic colour
    assert (cmfs @ XYZ_TO_AP0.T).min() > -1e-6
    assert (cmfs @ XYZ_TO_LINEAR_SRGB.T).min() < -0.1  # whereas Rec. 709 cannot hold them


def test_a_violet_firefly_is_denoised_not_left_as_a_dark_dot():
    # Flat water-like blue with one spectral firefly at 410 nm (x, y ≈ 0.17, 0.005), as the
    # in-water sun sampling makes them: the denoised frame must have no pixel far below the flat level.
    import colour  # noqa: PLC0415

    xyz = np.tile(np.array([1200.0, 1400.0, 2600.0]), (48, 64, 1))
    violet = colour.MSDS_CMFS["CIE 1931 2 Degree Standard Observer"][410]
    xyz[24, 32] += 2e6 * violet / violet[1]
    out = denoise_XYZ(xyz)
    assert out[..., 1].min() > 0.8 * 1400.0
    assert np.isfinite(out).all()


def test_denoise_reduces_the_error_of_a_noisy_synthetic_image(rng):
    # A smooth HDR image plus zero-mean multiplicative noise: the denoiser must get closer to it.
    y, x = np.mgrid[0:64, 0:96] / 64.0
    clean = np.stack([1e3 * (1 + x), 1e3 * (1 + y), 1e3 * (2 - x * y)], axis=-1).astype(np.float32)
    noisy = clean * rng.gamma(4.0, 0.25, clean.shape).astype(np.float32)  # mean 1, 50 % rms
    out = denoise(noisy)
    assert out.shape == clean.shape and out.dtype == np.float32
    assert np.mean((out - clean) ** 2) < 0.1 * np.mean((noisy - clean) ** 2)


def test_negative_values_pass_through_and_bad_input_is_refused():
    image = np.full((8, 8, 3), 5.0, np.float32)
    image[..., 2] = -0.25  # out of gamut: not denoised, kept
    out = denoise(image)
    np.testing.assert_allclose(out[..., 2], -0.25 + np.maximum(0, out[..., 2] + 0.25), atol=1e-6)
    assert np.all(out[..., 2] >= -0.25 - 1e-6)
    with pytest.raises(ValueError, match="shape"):
        denoise(np.zeros((8, 8)))
    with pytest.raises(ValueError, match="non-finite"):
        bad = image.copy()
        bad[1, 1, 0] = np.nan
        denoise(bad)
    with pytest.raises(ValueError, match="albedo image"):
        denoise(image, normal=np.zeros_like(image))
    with pytest.raises(ValueError, match="has shape"):
        denoise(image, albedo=np.zeros((4, 4, 3)))
    with pytest.raises(ValueError, match="unknown quality"):
        denoise(image, quality="best")


def test_split_features_picks_channels_by_name():
    image = np.arange(2 * 2 * 6, dtype=float).reshape(2, 2, 6)
    names = ["nn.X", "nn.Y", "nn.Z", "albedo.R", "albedo.G", "albedo.B"]
    features = split_features(image, names, np.array([1.0, 2.0, 4.0]))
    np.testing.assert_allclose(features.normal, image[..., :3])
    np.testing.assert_allclose(features.albedo, image[..., 3:] / [1.0, 2.0, 4.0])
    with pytest.raises(ValueError, match="lacks channel"):
        split_features(image, names[:5] + ["other"], np.ones(3))


def flat_sea(half_size=1.0e4):
    """A flat square of water at z = 0 (two triangles), normals up."""
    s = half_size
    positions = np.array([[-s, -s, 0], [s, -s, 0], [s, s, 0], [-s, s, 0]], np.float32)
    normals = np.tile(np.array([0, 0, 1], np.float32), (4, 1))
    faces = np.array([[0, 1, 2], [0, 2, 3]], np.uint32)
    return faces, FrameGeometry(positions=positions, normals=normals, foam=None)


@pytest.mark.render
def test_feature_images_line_up_with_the_camera(variant):
    # Camera 1 m above a flat sea looking level: the horizon is the middle row; below it the water's
    # stand-in albedo (0.5, neutral after the white division) and normal +z, above it the sky (all 0).
    scene = scene_from_dict({"name": "t", "camera": {"position": [0, 0, 1], "target": [0, 100, 1], "fov": 40}})
    faces, geometry = flat_sea()
    renderer = FeatureRenderer.build(scene, faces, geometry, resolution=(32, 20), spp=64, water_albedo=0.5)
    features = renderer.render(seed=2)
    below, above = features.albedo[12:], features.albedo[:9]
    np.testing.assert_allclose(below.mean(axis=(0, 1)), 0.5, atol=0.02)
    np.testing.assert_allclose(features.normal[12:].mean(axis=(0, 1)), [0, 0, 1], atol=1e-3)
    assert np.all(above == 0) and np.all(features.normal[:9] == 0)  # exact: no hit writes zeros
    # update_water moves the mesh in place: shifted 20 km east, the sea leaves the 40° field of view.
    shifted = FrameGeometry(positions=geometry.positions + np.float32([2e4, 0, 0]), normals=geometry.normals, foam=None)
    renderer.update_water(shifted)
    assert renderer.render(seed=3).albedo.max() == 0


@pytest.mark.render
def test_denoising_a_noisy_render_gets_closer_to_the_reference(variant):
    # A tiny sea (one 40 m patch, volpath) at 64×36: 2 spp, denoised, against a 256 spp reference.
    scene = scene_from_dict({
        "name": "tiny",
        "output": {"resolution": [64, 36], "spp": 2},
        "ocean": {"resolution": 32, "patch_size": 40.0},
        "render": {"white_spp": 64, "max_depth": 6, "integrator": "volpath"},
        "camera": {"position": [0, -10, 4], "target": [0, 20, 0]},
    })
    from oceanrender.pipeline import Sequence

    sequence = Sequence(scene, variant)
    geometry = sequence.geometry(0)
    features = FeatureRenderer.build(scene, sequence.faces, geometry).render(seed=0)
    noisy, _ = sequence.renderer.render_xyz(2, seed=1)
    reference, _ = sequence.renderer.render_xyz(256, seed=7)
    plain = denoise_XYZ(noisy)
    guided = denoise_XYZ(noisy, features.albedo, features.normal)
    before = rel_mse(noisy, reference)
    # Measured here: relMSE 1.3 noisy, 0.05 denoised (either way); ask for 4x at least.
    assert rel_mse(plain, reference) < before / 4
    assert rel_mse(guided, reference) < before / 4
    # Denoising keeps the image's overall level (mean luminance within 10 %).
    assert guided[..., 1].mean() == pytest.approx(reference[..., 1].mean(), rel=0.1)


def _bilateral_chroma(xyz, guide, radius, sigma):
    """The cross-bilateral chroma sums of smooth_chroma computed directly (every pair of pixels), for the test."""
    h, w, _ = xyz.shape
    log_g = np.log(guide)
    out = np.zeros_like(xyz)
    pad = np.pad(xyz, ((radius, radius), (radius, radius), (0, 0)), mode="edge")
    pad_g = np.pad(log_g, radius, mode="edge")
    for dy in range(2 * radius + 1):
        for dx in range(2 * radius + 1):
            weight = np.exp(-0.5 * ((log_g - pad_g[dy:dy + h, dx:dx + w]) / sigma) ** 2)
            out += weight[..., None] * pad[dy:dy + h, dx:dx + w]
    return out / out[..., 1:2] * guide[..., None]


def test_the_chroma_filter_keeps_the_luminance_and_averages_the_colour_by_it(rng):
    # Water of one colour (x, y) = (0.20, 0.22), luminance varying over the image, its chromaticity noisy per
    # pixel as four wavelengths per sample make it (X and Z ±30 %, Y exact).
    h, w = 40, 60
    Y = 50.0 * np.exp(0.3 * np.sin(np.arange(w) / 7.0))[None, :] * np.ones((h, 1))
    true = np.stack([0.20 / 0.22 * Y, Y, 0.58 / 0.22 * Y], axis=-1)
    noisy = true * np.stack([1 + 0.3 * rng.standard_normal((h, w)), np.ones((h, w)),
                             1 + 0.3 * rng.standard_normal((h, w))], axis=-1)
    out = smooth_chroma(noisy, Y, radius=4, sigma=0.1)
    np.testing.assert_allclose(out[..., 1], Y, rtol=1e-12)  # the luminance is the guide's
    before = np.std(noisy[..., 0] / Y)
    after = np.std(out[..., 0] / Y)
    # up to 81 neighbours of similar luminance: the ratio's noise falls several-fold (1/9 at best)
    assert after < 0.3 * before, (before, after)
    np.testing.assert_allclose(np.mean(out[..., 0] / Y), 0.20 / 0.22, rtol=0.01)  # no bias in the mean
    # Durand & Dorsey's piecewise-linear evaluation against the direct cross-bilateral sums: the levels
    # every σ interpolate the Gaussian weights within a few % of the weights, far less in the ratio.
    direct = _bilateral_chroma(noisy, Y, 4, 0.1)
    np.testing.assert_allclose(out[..., 0] / Y, direct[..., 0] / Y, rtol=0.01)


def test_the_chroma_filter_keeps_colours_apart_across_a_luminance_edge():
    # A dark blue sea (Y = 100) below a bright grey-white sky (Y = 10 000): ln 100 = 4.6 σ-steps of 0.1
    # apart, so no pixel's colour takes anything from the other side (the range weight is e^-1000).
    h, w = 20, 20
    Y = np.where(np.arange(h)[:, None] < 10, 1e4, 1e2) * np.ones((1, w))
    sky, sea = np.array([0.95, 1.0, 1.09]), np.array([0.5, 1.0, 3.0])
    xyz = np.where((np.arange(h)[:, None] < 10)[..., None], sky, sea) * Y[..., None]
    out = smooth_chroma(xyz, Y, radius=4, sigma=0.1)
    np.testing.assert_allclose(out / Y[..., None], xyz / Y[..., None], rtol=1e-9)
    with pytest.raises(ValueError):
        smooth_chroma(xyz, Y[:, :5])
    with pytest.raises(ValueError):
        smooth_chroma(xyz, Y, radius=-1)


def test_denoise_frame_without_a_chroma_radius_is_oidn_alone(rng):
    xyz = np.abs(rng.normal(100.0, 20.0, (24, 32, 3)))
    np.testing.assert_array_equal(denoise_frame(xyz, 0), denoise_XYZ(xyz))
    out = denoise_frame(xyz, 2)
    np.testing.assert_allclose(out[..., 1], denoise_XYZ(xyz)[..., 1], rtol=1e-6)
