"""Tests for oceanrender.waves.foam: production only on folds, exact decay, bounds, step independence."""

import numpy as np
import pytest

from oceanrender.waves.fft_ocean import FFTOcean, OceanGrid
from oceanrender.waves.foam import FOAM_DECAY_TIME_SEAWATER, FoamAccumulator, foam_production_rate, foam_step
from tests.tolerances import ROUNDOFF


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
