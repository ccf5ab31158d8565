"""Tests for oceanrender.waves.foam: production only on folds, exact decay, bounds, step independence."""

import numpy as np
import pytest

from oceanrender.waves.fft_ocean import FFTOcean, OceanGrid
from oceanrender.waves.foam import (
    FOAM_DECAY_TIME_SEAWATER,
    FoamAccumulator,
    crest_acceleration_threshold,
    foam_production_rate,
    foam_step,
    two_stage_foam_step,
    whitecap_fraction_MonahanOMuircheartaigh1980,
)
from tests.tolerances import QUADRATURE, ROUNDOFF


def test_no_foam_without_folding(rng):
    jacobian = rng.uniform(0.05, 2.0, (32, 32))  # compressed but never folded
    foam = foam_step(np.zeros_like(jacobian), jacobian, 0.5, threshold=0.0, decay_time=3.0, gain=10.0)
    assert np.all(foam == 0)
    # a real sea that does not fold: gentle waves, λ = 1
    ocean = FFTOcean(OceanGrid(64, 200.0), 4.0, 0.0, seed=3, dtype=np.float64)
    accumulator = FoamAccumulator(gain=5.0)
    for t in np.arange(0.0, 5.0, 0.5):
        fields = ocean.fields(t)
        assert fields.jacobian.min() > 0
        coverage = accumulator.advance(fields.jacobian, t)
    assert np.all(coverage == 0)


def test_foam_forms_where_the_surface_folds():
    jacobian = np.array([-0.4, 0.0, 0.2, 1.0])
    foam = foam_step(np.zeros(4), jacobian, 1.0, threshold=0.0, decay_time=3.0, gain=1.0)
    assert foam[0] > 0 and np.all(foam[1:] == 0)
    np.testing.assert_allclose(foam_production_rate(jacobian, 0.3, 2.0), [1.4, 0.6, 0.2, 0.0], rtol=0,
                               atol=ROUNDOFF * 1.4)  # scale: the largest rate


def test_decay_has_the_e_folding_time():
    tau = 2.5
    start = np.linspace(0.0, 1.0, 11)
    after = foam_step(start, np.ones(11), tau, threshold=0.0, decay_time=tau, gain=3.0)
    np.testing.assert_allclose(after, start / np.e, rtol=0, atol=ROUNDOFF)  # coverage: scale 1
    # and as a function of time
    for t in [0.1, 1.0, 7.0]:
        assert foam_step(1.0, 1.0, t, 0.0, tau, 1.0) == pytest.approx(np.exp(-t / tau), rel=ROUNDOFF)
    assert FOAM_DECAY_TIME_SEAWATER == pytest.approx(3.85)


def test_steady_state_and_bounds(rng):
    jacobian = rng.uniform(-3.0, 2.0, 1000)
    previous = rng.uniform(0.0, 1.0, 1000)
    for dt in [0.0, 1e-3, 0.04, 1.0, 1e3]:
        for gain in [0.0, 1.0, 1e3]:
            foam = foam_step(previous, jacobian, dt, threshold=0.5, decay_time=1.0, gain=gain)
            assert np.all((foam >= 0) & (foam <= 1))
    # after many τ the coverage is the equilibrium s/(s + 1/τ)
    s = foam_production_rate(jacobian, 0.5, 4.0)
    np.testing.assert_allclose(foam_step(previous, jacobian, 100.0, 0.5, 2.0, 4.0), s / (s + 0.5), rtol=0,
                               atol=ROUNDOFF)  # coverage: scale 1
    assert np.all(foam_step(0.0, -1e9, 1e9, 0.0, np.inf, 1e9) <= 1)
    for bad in [dict(dt=-1.0), dict(decay_time=0.0), dict(gain=-1.0)]:
        with pytest.raises(ValueError):
            foam_step(**(dict(previous=0.0, jacobian=0.0, dt=1.0, threshold=0.0, decay_time=1.0, gain=1.0) | bad))


def test_two_half_steps_equal_one_full_step(rng):
    previous = rng.uniform(0.0, 1.0, 500)
    j0, j1 = rng.uniform(-1.0, 1.5, (2, 500))
    kwargs = dict(threshold=0.2, decay_time=3.0, gain=2.0)
    # constant J: the exact solution makes this an identity
    full = foam_step(previous, j0, 0.1, **kwargs)
    half = foam_step(foam_step(previous, j0, 0.05, **kwargs), j0, 0.05, **kwargs)
    np.testing.assert_allclose(half, full, rtol=0, atol=ROUNDOFF)  # coverage: scale 1
    # J changing at a rate r: one step of dt with J at mid-step against two steps of dt/2
    # with J at their mid-steps; the difference vanishes faster than dt (first-order agreement)
    rate = (j1 - j0) / 0.1  # J sweeps [-1, 1.5] in 0.1 s: a harsh test
    errors = []
    for dt in [0.08, 0.04, 0.02, 0.01]:
        one = foam_step(previous, j0 + rate * dt / 2, dt, **kwargs)
        two = foam_step(foam_step(previous, j0 + rate * dt / 4, dt / 2, **kwargs), j0 + rate * 3 * dt / 4, dt / 2,
                        **kwargs)
        errors.append(np.abs(one - two).max() / dt)
    assert errors[-1] < 0.1 * errors[0]  # relative error per unit time → 0 as dt → 0


def test_accumulator_steps_and_checkpoints():
    jacobian = np.array([[-1.0, 0.5], [2.0, -0.2]])
    foam = FoamAccumulator(threshold=0.0, decay_time=2.0, gain=3.0)
    np.testing.assert_array_equal(foam.advance(jacobian, 1.0), 0.0)
    foam.advance(jacobian, 1.5)
    saved = foam.state()
    resumed = FoamAccumulator.from_state(saved)
    expected = foam.advance(jacobian, 2.25)
    # exact: a resumed accumulator takes the same step from the same state as the uninterrupted one
    np.testing.assert_array_equal(resumed.advance(jacobian, 2.25), expected)
    assert resumed.time == 2.25
    np.testing.assert_array_equal(foam_step(saved["coverage"], jacobian, 0.75, 0.0, 2.0, 3.0), expected)  # that step
    with pytest.raises(ValueError):
        foam.advance(jacobian, 1.0)  # backwards
    with pytest.raises(ValueError):
        FoamAccumulator(decay_time=0.0)


def test_monahan_whitecap_fraction_reference_values():
    # W = 3.84e-6 U^3.41 (Monahan & O'Muircheartaigh 1980, Eq. 5): 0.46 %, 1.8 %, 4.9 % at 8, 12, 16 m/s,
    # the values quoted to 2 figures (hence 3 %: half a unit in the last quoted digit of 0.46 is 1 %).
    W = whitecap_fraction_MonahanOMuircheartaigh1980([8.0, 12.0, 16.0])
    np.testing.assert_allclose(W, [0.0046, 0.018, 0.049], rtol=0.03)
    assert whitecap_fraction_MonahanOMuircheartaigh1980(0.0) == 0.0
    # the power law: doubling the wind multiplies W by 2^3.41
    assert W[2] / W[0] == pytest.approx(2**3.41, rel=ROUNDOFF)


def test_crest_acceleration_threshold_limits_and_gaussian_equivalence(rng):
    # All waves carried: J_c = 1 − λ α (J − 1 ≈ λ a_z/g, a_z < −α g)
    assert crest_acceleration_threshold(0.5, 0.8, 0.04, 0.04) == pytest.approx(0.6, rel=ROUNDOFF)
    # fewer waves carried: the threshold moves towards 1 as √(m_r/m_t)
    assert crest_acceleration_threshold(0.5, 0.8, 0.01, 0.04) == pytest.approx(0.8, rel=ROUNDOFF)
    # Gaussian sea: the resolved field below its threshold covers the fraction of the surface where the
    # whole field (resolved + an independent unresolved part) exceeds α — the point of the rescaling.
    m_r, m_t, alpha, lam = 0.02, 0.05, 0.5, 0.8
    n = 2_000_000
    resolved = rng.normal(0.0, np.sqrt(m_r), n)
    total = resolved + rng.normal(0.0, np.sqrt(m_t - m_r), n)
    j_resolved = 1 + lam * resolved  # J − 1 = λ a_z/g
    covered = np.mean(j_resolved < crest_acceleration_threshold(alpha, lam, m_r, m_t))
    breaking = np.mean(total < -alpha)
    # both ≈ 0.0127; binomial σ of each ≈ 8e-5: 6σ of the difference
    assert covered == pytest.approx(breaking, abs=6 * np.sqrt(2 * breaking / n))


def test_jacobian_minus_one_is_choppiness_times_vertical_acceleration_over_g():
    # Deep water, first order in λ: J − 1 = λ a_z / g, a_z = ∂²η/∂t² (the identity the criterion rests on)
    lam, g = 0.05, 9.81
    ocean = FFTOcean(OceanGrid(64, 200.0), 8.0, 0.0, seed=5, choppiness=lam, dtype=np.float64)
    dt, t = 1e-3, 3.0
    eta = [ocean.fields(t + s).height for s in (-dt, 0.0, dt)]
    a_z = (eta[0] - 2 * eta[1] + eta[2]) / dt**2
    j = ocean.fields(t).jacobian
    # Residual: the λ² term ((∂Dx/∂x)(∂Dy/∂y) − (∂Dx/∂y)²) and the O(dt²) difference error: 1 % of the scale
    np.testing.assert_allclose(j - 1, lam * a_z / g, rtol=0, atol=0.01 * np.abs(j - 1).max())


@pytest.mark.parametrize("jacobian", [-0.5, 0.2, 0.6, 0.65, 2.0])
def test_two_stage_step_is_the_exact_solution(jacobian):
    from scipy.integrate import solve_ivp

    gain, threshold, tau, tau_f, dt = 2.0, 0.7, 2.0, 1.5, 1.3
    s = gain * max(threshold - jacobian, 0.0)
    f0, b0 = 0.3, 0.1

    def rhs(_, y):
        return [s * (1 - y[0]) - y[0] / tau, s * (1 - y[1]) - y[1] * (1 / tau + 1 / tau_f)]

    ref = solve_ivp(rhs, [0, dt], [f0, b0], rtol=1e-11, atol=1e-13).y[:, -1]
    coverage, fresh = two_stage_foam_step(f0, b0, jacobian, dt, threshold, tau, tau_f, gain)
    # the integrator's target 1e-11 on values of scale 1: QUADRATURE
    np.testing.assert_allclose([coverage, fresh], ref, rtol=0, atol=QUADRATURE)
    # F is foam_step's coverage
    assert coverage == pytest.approx(foam_step(f0, jacobian, dt, threshold, tau, gain), abs=ROUNDOFF)


def test_two_stage_bounds_and_ageing(rng):
    coverage = rng.uniform(0, 1, 5000)
    fresh = coverage * rng.uniform(0, 1, 5000)
    jacobian = rng.uniform(-2, 2, 5000)
    for dt in [0.0, 0.01, 0.25, 3.0, 100.0]:
        for gain in [0.0, 1.0, 1e3]:
            f, b = two_stage_foam_step(coverage, fresh, jacobian, dt, 0.5, 2.0, 0.6, gain)
            assert np.all((0 <= b) & (b <= f) & (f <= 1))
    # no production: F decays with τ, B with 1/τ + 1/τ_f, so B/F = e^{−t/τ_f} (the foam's reflectance ageing)
    f, b = two_stage_foam_step(1.0, 1.0, 1.0, 1.2, 0.5, 2.0, 0.6, 50.0)
    assert f == pytest.approx(np.exp(-1.2 / 2.0), rel=ROUNDOFF)
    assert b / f == pytest.approx(np.exp(-1.2 / 0.6), rel=ROUNDOFF)
    # strong, lasting breaking (stage A): fresh foam saturates towards full coverage, old foam is renewed
    f, b = two_stage_foam_step(1.0, 0.0, -1.0, 1.0, 0.5, 2.0, 0.6, 1e3)
    assert f > 0.99 and b > 0.99
    with pytest.raises(ValueError):
        two_stage_foam_step(0.0, 0.0, 0.0, 1.0, 0.5, 2.0, 0.0, 1.0)


def test_crest_acceleration_threshold_is_finite_for_a_sea_without_slopes():
    """A wind of 1e-9 m/s gives m_t = 0 (issue 39: a 0/0 made the whole sea NaN, then black)."""
    threshold = crest_acceleration_threshold(0.665, 0.8, 0.0, 0.0)
    assert np.isfinite(threshold) and threshold == pytest.approx(1.0 - 0.8 * 0.665, rel=ROUNDOFF)
    # m_r a hair above m_t (rounding of total − unresolved) stays a ratio of 1, not above.
    assert crest_acceleration_threshold(0.5, 1.0, 0.04 * (1 + 1e-12), 0.04) == pytest.approx(0.5, rel=ROUNDOFF)
    with pytest.raises(ValueError, match="finite"):
        crest_acceleration_threshold(0.5, 1.0, np.nan, 0.04)


def test_a_near_calm_sea_with_foam_has_finite_fields_everywhere():
    """The water body of issue 39's black sea (U10 = 1e-9 m/s, foam on): every field finite, no foam."""
    from oceanrender.surface.open_sea import WaterBody
    from tests.scenes import scene_from_dict

    scene = scene_from_dict({"name": "calm", "ocean": {"wind_speed": 1e-9, "resolution": 32},
                             "mesh": {"kind": "radial", "segments": 24}, "foam": {"enabled": True}})
    body = WaterBody(scene)
    assert np.isfinite(body.foam_threshold)
    geometry = body.frame(0.5)
    assert geometry.non_finite() == {}
    assert geometry.foam is not None and float(np.max(geometry.foam)) == 0.0


def test_lace_tile_is_uniform_periodic_and_drawn_out_along_its_direction():
    import math

    from oceanrender.waves.foam import lace_tile_Perlin1985

    tile = lace_tile_Perlin1985(8.0, 256, 0.8, 3.0, math.radians(30.0), 1)
    assert tile.shape == (256, 256) and tile.dtype == np.float32
    # rank-mapped: uniform on [0, 1) exactly (to the half-texel offset)
    np.testing.assert_allclose(np.quantile(tile, [0.1, 0.5, 0.9]), [0.1, 0.5, 0.9], atol=1e-3)
    # foam drawn where tile < B covers the fraction B
    for cover in (0.05, 0.3, 0.8):
        assert np.mean(tile < cover) == pytest.approx(cover, abs=1e-3)
    # periodic: the jump across the tile's edge is like a step inside it (not a seam)
    inside = np.mean(np.abs(np.diff(tile, axis=1)))
    seam = np.mean(np.abs(tile[:, 0] - tile[:, -1]))
    assert seam < 1.5 * inside
    # elongated along 30°: the field changes more slowly along it than across it
    step = 3  # texels
    along = np.mean(np.abs(tile - np.roll(np.roll(tile, -round(step * math.cos(math.radians(30))), 1),
                                          -round(step * math.sin(math.radians(30))), 0)))
    across = np.mean(np.abs(tile - np.roll(np.roll(tile, round(step * math.sin(math.radians(30))), 1),
                                           -round(step * math.cos(math.radians(30))), 0)))
    assert along < 0.7 * across
