"""The compiled periodic bilinear stencil against the cascades' numpy one."""

import numpy as np

from oceanrender.waves.cascades import bilinear_corners
from oceanrender.waves.fft_ocean import OceanGrid
from oceanrender.waves.grid_sampling import add_periodic_bilinear
from tests.tolerances import ROUNDOFF


def test_matches_the_numpy_stencil_and_accumulates(rng):
    grid = OceanGrid(32, 20.0)
    field = rng.standard_normal((32, 32))
    x, y = rng.uniform(-50.0, 50.0, (2, 1000))  # beyond the patch: periodic
    corners, weights = bilinear_corners(grid, x, y)
    expected = sum(field.ravel()[c] * w for c, w in zip(corners, weights))
    out = np.full(x.size, 2.0)
    add_periodic_bilinear(field, grid.patch_size, x, y, 0.5, out)
    np.testing.assert_allclose(out, 2.0 + 0.5 * expected, rtol=0, atol=ROUNDOFF * np.abs(field).max())


def test_nodes_give_the_field(rng):
    field = rng.standard_normal((8, 8))
    n, size = 8, 4.0
    j, i = np.meshgrid(np.arange(n), np.arange(n), indexing="ij")
    x, y = i.ravel() * size / n - size / 2, j.ravel() * size / n - size / 2
    out = np.zeros(x.size)
    add_periodic_bilinear(field, size, x, y, 1.0, out)
    np.testing.assert_allclose(out, field.ravel(), rtol=0, atol=ROUNDOFF)
