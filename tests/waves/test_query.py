"""Tests for oceanrender.waves.query: heights at world points of a choppy sea."""

import numpy as np
import pytest

from oceanrender.surface.patch_mesh import water_body_vertices
from oceanrender.waves.fft_ocean import FFTOcean, OceanFields, OceanGrid
from oceanrender.waves.query import (
    SurfaceSample,
    periodic_sampler,
    query_height,
    spectral_sampler,
    sum_samplers,
    surface_normals,
)
from tests.tolerances import ROUNDOFF

#: Tolerance on the displaced position of a root, asked of the query [m].
POSITION_ATOL = 1e-6

#: Residual |x₀ + D(x₀) − x| asked of the "exact" inversions [m] (positions of scale PATCH:
#: ~30 ulp), and the error allowed on their roots and heights [m]: the root is off by
#: ≤ tol/J (J ≥ 0.19 here) and its height by |∇η| ≤ 1 times that; 20× slack on top.
INVERSION_TOL = 1e-12
INVERSION_ATOL = 100 * INVERSION_TOL

PATCH = 50.0


def ocean(choppiness, n=32):
    """A small float64 ocean, short waves suppressed below ℓ = 2 m (grid spacing 1.6 m); J > 0 for λ ≤ 1."""
    return FFTOcean(
        OceanGrid(n, PATCH), 8.0, 0.3, seed=3, choppiness=choppiness, small_wave_length=2.0, dtype=np.float64
    )


def gerstner_sampler(amplitude, wavelength, direction, phase=0.0):
    """One Gerstner (trochoidal) wave: D = −k̂ A sin θ, η = A cos θ, θ = k·x₀ − phase."""
    k = 2 * np.pi / wavelength
    kvec = k * np.array([np.cos(direction), np.sin(direction)])
    unit = kvec / k

    def sample(x0, y0):
        theta = x0 * kvec[0] + y0 * kvec[1] - phase
        sin, cos = np.sin(theta)[..., None], np.cos(theta)[..., None]
        return SurfaceSample(
            displacement=-amplitude * sin * unit,
            height=amplitude * cos[..., 0],
            slope=-amplitude * sin * kvec,
            displacement_gradient=-amplitude * cos[..., None] * unit[:, None] * kvec[None, :],
        )

    return sample


def random_points(rng, count, half_width=PATCH):
    return rng.uniform(-half_width, half_width, (2, count))


def test_flat_displacement_is_plain_interpolation(rng):
    sea = ocean(choppiness=0.0)
    sample = periodic_sampler(sea.fields(1.7), PATCH)
    x, y = random_points(rng, 500)
    result = query_height(sample, x, y)
    plain = sample(x, y)
    # without displacement the start x₀ = x is the root: the same sample, bit for bit
    np.testing.assert_array_equal(result.height, plain.height)
    np.testing.assert_array_equal(result.normal, plain.normal)
    np.testing.assert_array_equal(result.undisplaced, np.stack([x, y], -1))
    assert result.max_iterations == 0 and result.converged.all() and not result.folded.any()


@pytest.mark.parametrize("exact", [False, True], ids=["periodic cubic", "spectral"])
def test_choppy_root_is_displaced_onto_the_query_point(rng, exact):
    sea = ocean(choppiness=1.0)
    t = 2.3
    fields = sea.fields(t)
    assert fields.jacobian.min() > 0, "the test sea must not fold"
    sample = spectral_sampler(sea.grid, sea.h0, sea.omega, t, 1.0) if exact else periodic_sampler(fields, PATCH)
    x, y = random_points(rng, 400, half_width=3 * PATCH)
    result = query_height(sample, x, y)
    assert result.converged.all() and not result.folded.any()
    assert result.max_iterations <= 6  # Newton: quadratic convergence
    # independent check: displace the returned root with the sampler itself
    again = sample(result.undisplaced[..., 0], result.undisplaced[..., 1])
    displaced = result.undisplaced + again.displacement
    np.testing.assert_allclose(displaced, np.stack([x, y], -1), rtol=0, atol=POSITION_ATOL)
    # the same sampler at the same root (in another batch of points): round-off of the height's scale
    np.testing.assert_allclose(result.height, again.height, rtol=0, atol=ROUNDOFF * np.abs(again.height).max())
    assert np.abs(result.undisplaced - np.stack([x, y], -1)).max() > 0.1, "the displacement must matter"


def test_gerstner_wave_is_inverted_exactly(rng):
    sample = gerstner_sampler(amplitude=0.9, wavelength=7.0, direction=0.7, phase=0.4)  # kA = 0.81 < 1
    x0 = random_points(rng, 1000).T
    moved = sample(x0[:, 0], x0[:, 1])
    x = x0 + moved.displacement
    result = query_height(sample, x[:, 0], x[:, 1], tol=INVERSION_TOL)
    np.testing.assert_allclose(result.undisplaced, x0, rtol=0, atol=INVERSION_ATOL)
    np.testing.assert_allclose(result.height, moved.height, rtol=0, atol=INVERSION_ATOL)
    assert not result.folded.any()


def test_sum_of_samplers_is_inverted_exactly(rng):
    sample = sum_samplers(gerstner_sampler(0.3, 9.0, 0.2), gerstner_sampler(0.1, 2.5, 2.0, 1.0))  # Σ kA < 1
    x0 = random_points(rng, 500).T
    moved = sample(x0[:, 0], x0[:, 1])
    x = x0 + moved.displacement
    result = query_height(sample, x[:, 0], x[:, 1], tol=INVERSION_TOL)
    np.testing.assert_allclose(result.undisplaced, x0, rtol=0, atol=INVERSION_ATOL)
    np.testing.assert_allclose(result.height, moved.height, rtol=0, atol=INVERSION_ATOL)


def test_mesh_vertex_heights_are_reproduced_at_their_displaced_positions():
    sea = ocean(choppiness=1.0)
    fields = sea.fields(0.8)
    n = fields.resolution
    positions, normals = water_body_vertices(fields, PATCH, depth=20.0)
    top, top_normals = positions[: (n + 1) ** 2], normals[: (n + 1) ** 2]
    result = query_height(periodic_sampler(fields, PATCH), top[:, 0], top[:, 1])
    assert result.converged.all()
    # the vertices are float32: their xy carry ~2e-6 m of rounding, their z ~1e-7 m
    np.testing.assert_allclose(result.height, top[:, 2], rtol=0, atol=1e-5)
    grid = -PATCH / 2 + PATCH / n * np.arange(n + 1)
    gx, gy = np.meshgrid(grid, grid)
    np.testing.assert_allclose(result.undisplaced, np.stack([gx.ravel(), gy.ravel()], -1), rtol=0, atol=1e-4)
    # normals: from the interpolant's displacement gradient, not the spectral one
    angle = np.degrees(np.arccos(np.clip(np.sum(result.normal * top_normals, -1), -1, 1)))
    assert angle.max() < 0.5


def test_grid_points_are_reproduced_exactly():
    sea = ocean(choppiness=1.0)
    fields = sea.fields(4.0)
    sample = periodic_sampler(fields, PATCH)
    x = sea.grid.x + fields.displacement_x
    y = sea.grid.y + fields.displacement_y
    result = query_height(sample, x, y, tol=INVERSION_TOL)
    np.testing.assert_allclose(result.height, fields.height, rtol=0, atol=INVERSION_ATOL)
    np.testing.assert_allclose(result.undisplaced[..., 0], sea.grid.x, rtol=0, atol=INVERSION_ATOL)
    # J from the interpolant's displacement gradient, not the spectral one: interpolation error (7e-4 measured)
    np.testing.assert_allclose(result.jacobian, fields.jacobian, rtol=0, atol=0.02)


def test_interpolation_accuracy_against_the_fourier_series(rng):
    sea = ocean(choppiness=1.0)
    fields = sea.fields(1.1)
    x, y = random_points(rng, 2000)
    exact = spectral_sampler(sea.grid, sea.h0, sea.omega, 1.1, 1.0)(x, y)
    errors = {}
    for order in (3, 1):
        approx = periodic_sampler(fields, PATCH, order)(x, y)
        errors[order] = np.sqrt(np.mean((approx.height - exact.height) ** 2)) / np.std(exact.height)
    # measured: 3.8e-4 (cubic) and 1.7e-2 (bilinear) of the rms elevation
    assert errors[3] < 1e-3
    assert errors[1] > 10 * errors[3]


def test_periodic_sampler_is_periodic(rng):
    sample = periodic_sampler(ocean(1.0).fields(0.5), PATCH)
    x, y = random_points(rng, 100)
    a, b = sample(x, y), sample(x + PATCH, y - 2 * PATCH)
    # the shifted points carry round-off of their larger coordinates: relative to each field's scale
    np.testing.assert_allclose(b.height, a.height, rtol=0, atol=ROUNDOFF * np.abs(a.height).max())
    np.testing.assert_allclose(b.displacement_gradient, a.displacement_gradient, rtol=0,
                               atol=ROUNDOFF * np.abs(a.displacement_gradient).max())


def test_fold_is_flagged_or_refused():
    # kA = 1.5: the trochoid overturns; x = 0 is the image of θ = 0, where J = 1 − kA < 0,
    # and of θ = ±1.496; the iteration starts on the folded root and stays there.
    sample = gerstner_sampler(amplitude=1.5 * 10 / (2 * np.pi), wavelength=10.0, direction=0.0)
    x = np.array([0.0, 0.0, 5.0])
    y = np.array([0.0, 3.0, 0.0])
    result = query_height(sample, x, y)
    assert result.converged.all()
    np.testing.assert_array_equal(result.folded, [True, True, False])
    assert np.all(result.normal[result.folded, 2] < 0), "folded roots face down"
    np.testing.assert_array_equal(result.folded, result.jacobian <= 0)
    with pytest.raises(ValueError, match="fold"):
        query_height(sample, x, y, raise_on_fold=True)
    query_height(sample, x[2:], y[2:], raise_on_fold=True)  # no fold under this point


def test_folding_fft_sea_terminates_and_reports(rng):
    sea = FFTOcean(OceanGrid(32, PATCH), 12.0, 0.3, seed=3, choppiness=6.0, small_wave_length=0.5, dtype=np.float64)
    fields = sea.fields(1.0)
    assert fields.jacobian.min() < 0, "the test sea must fold"
    result = query_height(periodic_sampler(fields, PATCH), *random_points(rng, 2000), max_iterations=40)
    np.testing.assert_array_equal(result.converged, result.residual <= 1e-9)  # query_height's default tol
    np.testing.assert_array_equal(result.folded, result.jacobian <= 0)
    assert result.converged.mean() > 0.95
    assert result.iterations.max() <= 40


def test_shapes_are_kept():
    sample = gerstner_sampler(0.5, 8.0, 1.0)
    x, y = np.meshgrid(np.linspace(-5, 5, 4), np.linspace(-5, 5, 3))
    result = query_height(sample, x, y)
    assert result.height.shape == (3, 4) and result.normal.shape == (3, 4, 3) and result.undisplaced.shape == (3, 4, 2)
    scalar = query_height(sample, 1.0, 2.0)
    assert scalar.height.shape == () and scalar.normal.shape == (3,)


def test_surface_normals_of_a_height_field():
    slope = np.array([[0.3, -0.2], [0.0, 0.0]])
    expected = np.array([[-0.3, 0.2, 1.0], [0.0, 0.0, 1.0]])
    expected /= np.linalg.norm(expected, axis=-1, keepdims=True)
    np.testing.assert_allclose(surface_normals(slope, np.zeros((2, 2, 2))), expected, rtol=0, atol=ROUNDOFF)  # scale 1


def test_invalid_arguments_are_refused():
    sample = gerstner_sampler(0.5, 8.0, 1.0)
    with pytest.raises(ValueError, match="tol"):
        query_height(sample, 0.0, 0.0, tol=0.0)
    with pytest.raises(ValueError, match="damping"):
        query_height(sample, 0.0, 0.0, damping=1.5)
    with pytest.raises(ValueError, match="finite"):
        query_height(sample, np.nan, 0.0)
    zero = np.zeros((4, 4))
    fields = OceanFields(zero, zero, zero, zero, zero, zero + 1, np.zeros((4, 4, 3)))
    with pytest.raises(ValueError, match="order"):
        periodic_sampler(fields, 1.0, order=2)
    with pytest.raises(ValueError, match="patch_size"):
        periodic_sampler(fields, 0.0)
