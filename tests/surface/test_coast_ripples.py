"""The wind sea's band finer than the solver's cells, as shading fields of an isolated coast (issue 41)."""

import numpy as np
import pytest

from oceanrender.surface.coast_ripples import CoastRipples, ripple_spectrum
from oceanrender.surface.open_sea import SHADING_SPACINGS
from oceanrender.waves.roughness import beckmann_alpha, unresolved_slope_variance
from oceanrender.waves.sea import directional_spectrum
from tests.scenes import scene_from_dict

#: The wind sea of scenes/coastal_beach.toml: 4 m/s, its band below 25 cm in patches of 14.6 m and 3.3 m.
BEACH_SEA = {"spectrum": "JONSWAP 1973", "wind_speed": 4.0, "wind_direction": -90.0, "fetch": 20000.0,
             "patch_size": 64.0, "cascades": 3, "resolution": 1024}


def test_the_band_is_the_spectrum_above_the_cells_cutoff_and_nothing_below():
    spectrum = directional_spectrum(scene_from_dict({"name": "ripples", "ocean": BEACH_SEA}).ocean)
    band = ripple_spectrum(spectrum, 0.125)  # k_c = π / 0.125 m = 25.1 rad/m
    k = np.array([5.0, 20.0, 25.0, 25.2, 40.0, 300.0])
    kx, ky = k * np.cos(0.3), k * np.sin(0.3)
    np.testing.assert_array_equal(band(kx, ky)[:3], 0.0)
    np.testing.assert_array_equal(band(kx, ky)[3:], spectrum(kx, ky)[3:])


def test_resolved_and_unresolved_slopes_of_the_band_add_up_to_today_s_roughness():
    # Where nothing is resolved (the coarsest shading spacing) the fields' α is the whole band's: the roughness
    # the coast had without fields, √(mss of k > π/Δ_c) from the spectrum's own quadrature (waves.roughness) —
    # an independent integral of the same band: within 0.5 % (log-spaced quadrature against the band's sharp
    # edge). Finer spacings resolve part of it: α falls, and never below the capillaries the cascades do not
    # reach (≈ 0.12 for this sea), whose slopes stay roughness at every spacing.
    scene = scene_from_dict({"name": "ripples", "ocean": BEACH_SEA})
    ripples = CoastRipples(scene, 0.125, (0.0, 0.0))
    today = beckmann_alpha(unresolved_slope_variance(directional_spectrum(scene.ocean), np.pi / 0.125))
    assert ripples.alpha[-1] == pytest.approx(today, rel=5e-3)
    assert ripples.resolves_any
    assert np.all(np.diff(ripples.alpha) >= -1e-12)  # α grows with the spacing
    at_1cm = ripples.alpha[np.searchsorted(SHADING_SPACINGS, 0.01)]
    assert 0.5 * today < at_1cm < 0.95 * today


def test_a_sea_whose_cascades_stop_short_of_the_band_resolves_none_of_it():
    # the tests' small sea: one 128 m patch of 256² (shortest wave ≈ 1 m) against cells of 12.5 cm
    assert not CoastRipples(scene_from_dict({"name": "ripples"}), 0.125, (0.0, 0.0)).resolves_any


def test_the_fields_join_the_body_only_where_it_is_wet():
    scene = scene_from_dict({"name": "ripples", "ocean": BEACH_SEA})
    ripples = CoastRipples(scene, 0.125, (1.0, 2.0))
    positions = np.array([[0.5, 0.5, 0.1], [1.5, 2.5, -0.2], [3.0, 1.0, 0.0], [0.0, 0.0, -3.0]], np.float32)
    wet = np.array([True, False, True])
    fields = ripples.fields(0.0, positions, 3, np.array([0.5, -0.1, 0.002]), wet)
    join = fields.join
    np.testing.assert_allclose(fields.texcoords[:3], positions[:3, :2] - [1.0, 2.0])
    np.testing.assert_array_equal(fields.texcoords[3], 0.0)  # (the body's base: never field-shaded)
    assert join.short_taper[0] == pytest.approx(1.0, abs=1e-6)  # 0.5 m deep: the mm-high band passes whole
    assert join.short_taper[1] == 0.0 and join.short_taper[3] == 0.0  # dry, and off the surface
    assert 0.0 < join.short_taper[2] < 1.0  # 2 mm of water: tapered (Thornton & Guza's saturation)
    np.testing.assert_array_equal(join.sea_normals[:, 2], 1.0)  # the body's mesh carries none of the band
    np.testing.assert_array_equal(join.sea_positions[:3, :2], positions[:3, :2])
    np.testing.assert_array_equal(join.sea_positions[:, 2], 0.0)
