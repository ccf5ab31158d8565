"""Sunlight inside the water (issue 41): the sun's beam refracted through the surface, against optics."""

import numpy as np
import pytest

from oceanrender.surface.sunlight import (facet_power, paraxial_focal_depth, plane_irradiance, refined_plane_irradiance,
                                         refracted_beam)

N_WATER = 1.34


def sinusoid_beam(amplitude, wavelength, rays):
    """(points, directions, power) of a vertical beam of 1 W m⁻² through η = a cos kx, ``rays`` per wavelength,
    per unit length along y (one cell of the irradiance grid: see the callers' ``cell``)."""
    k = 2 * np.pi / wavelength
    x = (np.arange(rays) + 0.5) * (wavelength / rays)
    eta = amplitude * np.cos(k * x)
    slope = -amplitude * k * np.sin(k * x)
    area = np.column_stack([-slope, np.zeros_like(x), np.ones_like(x)])  # ∂p/∂x × ∂p/∂y, no displacement
    normals = area / np.linalg.norm(area, axis=1, keepdims=True)
    sun = (0.0, 0.0, 1.0)
    directions, transmittance = refracted_beam(normals, sun, N_WATER)
    points = np.column_stack([x, np.zeros_like(x), eta])
    return points, directions, area, transmittance


def test_paraxial_focal_depth_of_the_issue_s_example():
    # the issue's example: a 0.5 m wave of 1 cm amplitude focuses at ≈ 2.5 m (n = 1.34)
    assert paraxial_focal_depth(0.01, 2 * np.pi / 0.5, N_WATER) == pytest.approx(2.5, rel=0.01)


def test_refraction_is_snell_s_and_a_flat_sea_transmits_fresnel_s_share():
    # a flat sea under a sun 40° high: the beam goes down at asin(cos 40° / n) from the vertical
    sun = np.array([np.cos(np.radians(40)), 0.0, np.sin(np.radians(40))])
    d, t = refracted_beam(np.array([[0.0, 0.0, 1.0]]), sun, N_WATER)
    sin_t = np.hypot(d[0, 0], d[0, 1])
    assert sin_t == pytest.approx(np.cos(np.radians(40)) / N_WATER, rel=1e-12)
    assert d[0, 2] < 0 and d[0, 0] < 0  # down, away from the sun
    # Fresnel at 50° incidence, n = 1.34 (Born & Wolf §1.5.2, by hand): θ_t = 34.87°,
    # r_s = −0.2621, r_p = 0.0243, R = (0.0687 + 0.0006)/2 = 0.0346, T = 0.9654 (to the hand's 4 digits)
    assert t[0] == pytest.approx(0.9654, abs=1e-4)
    # a facet facing away from the sun gets nothing
    _, t = refracted_beam(np.array([[-0.9, 0.0, 0.436]]) / np.linalg.norm([-0.9, 0.0, 0.436]), sun, N_WATER)
    assert t[0] == 0.0


@pytest.mark.parametrize("amplitude", [0.01, 0.02])
def test_a_sinusoid_focuses_the_zenith_sun_at_the_crest_s_paraxial_focal_depth(amplitude):
    # η = a cos kx, λ = 0.5 m, sun at the zenith, clear water (attenuation changes no position):
    # the sharpest caustic — the depth where the brightest cell is brightest — is the crest's
    # paraxial focus n/((n − 1) a k²) (2.50 m and 1.25 m): its cusp. Resolution: 16 384 rays
    # and 2048 cells per wavelength (0.24 mm), planes every 5 mm; the cusp's peak on that
    # histogram is within a few cells of depth of the focus: 3 % allowed.
    wavelength = 0.5
    rays, cells = 16384, 2048
    cell = wavelength / cells
    points, directions, area, transmittance = sinusoid_beam(amplitude, wavelength, rays)
    power = facet_power(area, (0.0, 0.0, 1.0), 1.0, (wavelength / rays) * cell) * transmittance
    focus = paraxial_focal_depth(amplitude, 2 * np.pi / wavelength, N_WATER)
    depths = -np.arange(0.2, 2.2 * focus, 0.005)
    irradiance = plane_irradiance(points, directions, power, depths, (0.0, -cell / 2), cell, (1, cells))
    peak = irradiance.max(axis=(1, 2))
    sharpest = amplitude - depths[np.argmax(peak)]  # below the crest
    assert sharpest == pytest.approx(focus, rel=0.03)
    # and it is a focus: the brightest cell there is many times the flat sea's irradiance
    assert peak.max() > 20 * np.mean(transmittance)


def test_waves_redistribute_the_beam_and_create_no_light():
    # A choppy 8 m/s sea (a 64 m periodic patch, 512², displaced), sun 50° high: the mean
    # downward irradiance on planes 0.5–20 m down equals a flat sea's with the same
    # transmitted flux within 2 % (the issue's check), without absorption (exactly: every ray
    # lands in the periodic grid) and with c = 0.1 m⁻¹ (the tilted rays' longer paths).
    from oceanrender.waves.fft_ocean import FFTOcean, OceanGrid

    size, n = 64.0, 512
    ocean = FFTOcean(OceanGrid(n, size), wind_speed=8.0, seed=5, choppiness=1.0, dtype=np.float64)
    f = ocean.fields(2.0)
    h = size / n
    x0 = (np.arange(n) - n / 2) * h
    xx, yy = np.meshgrid(x0, x0)
    points = np.stack([xx + f.displacement_x, yy + f.displacement_y, f.height], -1).reshape(-1, 3)
    jxx, jyy, jxy = f.jacobian_xx, f.jacobian_yy, f.jacobian_xy
    sx, sy = f.slope_x, f.slope_y
    area = np.stack([jxy * sy - jyy * sx, jxy * sx - jxx * sy, jxx * jyy - jxy * jxy], -1).reshape(-1, 3)
    normals = area / np.linalg.norm(area, axis=1, keepdims=True)
    elevation = np.radians(50)
    sun = np.array([np.cos(elevation), 0.0, np.sin(elevation)])
    directions, transmittance = refracted_beam(normals, sun, N_WATER)
    power = facet_power(area, sun, 1.0, h * h) * transmittance
    flux = power.sum()
    assert flux > 0.9 * np.sin(elevation) * size**2  # most of the beam is transmitted
    depths = -np.array([0.5, 2.0, 5.0, 10.0, 20.0])
    flat_d, _ = refracted_beam(np.array([[0.0, 0.0, 1.0]]), sun, N_WATER)
    cell = 0.25
    for c in (0.0, 0.1):
        irradiance = plane_irradiance(points, directions, power, depths, (-size / 2, -size / 2), cell,
                                      (int(size / cell), int(size / cell)), attenuation=c)
        mean = irradiance.mean(axis=(1, 2))
        flat = flux / size**2 * np.exp(-c * (-depths) / -flat_d[0, 2])
        np.testing.assert_allclose(mean, flat, rtol=0.02)
    # and the waves do redistribute it: the planes are far from uniform near the surface
    near = plane_irradiance(points, directions, power, [-2.0], (-size / 2, -size / 2), 0.05,
                            (int(size / 0.05), int(size / 0.05)))
    assert near.std() > 0.3 * near.mean()


def test_the_focus_converges_as_the_cells_are_refined():
    # The histogram's only bias is its cell (with rays 8× finer): the sharpest caustic's offset
    # from the paraxial focus shrinks with the cell (measured: +4.0 % at 512 cells per
    # wavelength, +1.6 % at 2048, +0.6 % at 8192; docs/sunlight.md), and the peak grows as the
    # cusp's singular irradiance is resolved.
    wavelength, amplitude = 0.5, 0.01
    focus = paraxial_focal_depth(amplitude, 2 * np.pi / wavelength, N_WATER)
    errors, peaks = [], []
    for cells in (512, 2048):
        cell = wavelength / cells
        points, directions, area, transmittance = sinusoid_beam(amplitude, wavelength, 8 * cells)
        power = facet_power(area, (0.0, 0.0, 1.0), 1.0, (wavelength / (8 * cells)) * cell) * transmittance
        depths = -np.arange(0.5 * focus, 1.5 * focus, 0.0025)
        peak = plane_irradiance(points, directions, power, depths, (0.0, -cell / 2), cell, (1, cells)).max(axis=(1, 2))
        errors.append(abs(amplitude - depths[np.argmax(peak)] - focus) / focus)
        peaks.append(peak.max())
    assert errors[1] < 0.5 * errors[0]
    assert peaks[1] > 2 * peaks[0]


def test_refined_rays_are_the_dense_rays_without_their_hatching():
    # Rays on a coarse grid (one per cell) refined 8× per direction inside each quad give the
    # irradiance of a grid 8× denser: the same focus (3 %) and, over the wavelength, the same
    # profile at the focus (mean absolute difference ≤ 10 % of the mean: the two estimate the
    # same field with the same cells, the dense one's own rays just 8× closer); the power that
    # lands in the window is the power sent through it (no absorption, a window far from the
    # open grid's edges: 1e-9 of the total, float64 sums).
    wavelength, amplitude, cells = 0.5, 0.01, 1024
    cell = wavelength / cells
    focus = paraxial_focal_depth(amplitude, 2 * np.pi / wavelength, N_WATER)
    depths = -np.arange(0.5 * focus, 1.5 * focus, 0.005)

    def grid(rays_per_wavelength):
        # three wavelengths of rays (x from −λ to 2λ), two rows (y = 0 and one cell): a grid of quads
        points, directions, area, transmittance = sinusoid_beam(amplitude, wavelength, rays_per_wavelength)
        h = wavelength / rays_per_wavelength
        power = facet_power(area, (0.0, 0.0, 1.0), 1.0, h * cell) * transmittance
        tile = [(points + (shift, 0.0, 0.0)) for shift in (-wavelength, 0.0, wavelength)]
        p = np.concatenate(tile)
        p = np.stack([p, p + (0.0, cell, 0.0)])
        d = np.stack([np.concatenate([directions] * 3)] * 2)
        w = np.stack([np.concatenate([power] * 3)] * 2)
        return p, d, w

    # (the window: three rows of cells around the quads' row, summed: the power per unit length)
    p, d, w = grid(cells)
    coarse = refined_plane_irradiance(p, d, w, depths, (0.0, -cell), cell, (3, cells), refine=8).sum(axis=1)
    p, d, w = grid(8 * cells)
    dense = refined_plane_irradiance(p, d, w, depths, (0.0, -cell), cell, (3, cells), refine=1).sum(axis=1)
    for estimate in (coarse, dense):
        peak = estimate.max(axis=1)
        assert amplitude - depths[np.argmax(peak)] == pytest.approx(focus, rel=0.03)
    at_focus = np.argmin(np.abs(amplitude - depths - focus))
    difference = np.abs(coarse[at_focus] - dense[at_focus]).mean()
    assert difference <= 0.1 * dense[at_focus].mean()
    # power: the quads of the middle wavelength (one row of quads: one row of nodes' power)
    near = refined_plane_irradiance(p, d, w, [-0.3], (0.0, -cell), cell, (3, cells), refine=2)
    sent = w[0, 8 * cells: 16 * cells].sum()
    assert near.sum() * cell**2 == pytest.approx(sent, rel=1e-9)
