"""Tests for :mod:`oceanrender.vision.temporal`."""

import math

import numpy as np
import pytest

from oceanrender.vision.temporal import (
    HISTORY_TIME_CONSTANTS,
    adaptation_history_frames,
    adaptation_step_DurandDorsey2000,
    adaptation_window,
    adapted_luminance,
)
from tests.tolerances import ROUNDOFF


def test_step_is_exponential_in_log_luminance():
    # One time constant after a step from 100 to 1000 cd/m²: ln L_a = ln 1000 + ln(0.1) e⁻¹.
    L = adaptation_step_DurandDorsey2000(100.0, 1000.0, 0.4, 0.4)
    assert float(L) == pytest.approx(1000.0 * 0.1 ** math.exp(-1.0), rel=ROUNDOFF)


def test_two_half_steps_equal_one_step():
    once = adaptation_step_DurandDorsey2000(50.0, 3000.0, 0.1, 0.4)
    half = adaptation_step_DurandDorsey2000(adaptation_step_DurandDorsey2000(50.0, 3000.0, 0.05, 0.4), 3000.0, 0.05, 0.4)
    assert float(half) == pytest.approx(float(once), rel=ROUNDOFF)


def test_zero_time_constant_adapts_at_once_and_steady_state_is_kept():
    assert float(adaptation_step_DurandDorsey2000(50.0, 3000.0, 1 / 24, 0.0)) == pytest.approx(3000.0, rel=ROUNDOFF)
    assert float(adaptation_step_DurandDorsey2000(3000.0, 3000.0, 1 / 24, 0.4)) == pytest.approx(3000.0, rel=ROUNDOFF)


def test_step_up_and_down_symmetric_in_ratio():
    up = adaptation_step_DurandDorsey2000(100.0, 1000.0, 0.2, 0.4)
    down = adaptation_step_DurandDorsey2000(1000.0, 100.0, 0.2, 0.4)
    assert float(up / 100.0) == pytest.approx(float(1000.0 / down), rel=ROUNDOFF)


def test_turn_towards_the_sun_adapts_over_about_a_second():
    # A tenfold step at 24 fps with τ = 0.4 s: < 10 % of the way (in log) after 1 frame, > 90 % after 1 s.
    fps, tau = 24.0, 0.4
    targets = [100.0] + [1000.0] * 48
    progress = [math.log10(adapted_luminance(targets[: n + 1], 1 / fps, tau) / 100.0) for n in range(49)]
    assert progress[1] < 0.1 and progress[24] > 0.9 and np.all(np.diff(progress) > 0)


def test_history_frames_and_window():
    assert adaptation_history_frames(0.4, 24.0) == math.ceil(HISTORY_TIME_CONSTANTS * 0.4 * 24.0) == 39
    assert adaptation_history_frames(0.0, 24.0) == 0
    assert list(adaptation_window(5, 0.4, 24.0)) == list(range(0, 6))
    assert list(adaptation_window(100, 0.4, 24.0)) == list(range(61, 101))
    assert list(adaptation_window(7, 0.0, 24.0)) == [7]


def test_truncated_window_weighs_start_below_two_percent():
    # Targets 1 until the window, then 10: the state after 4τ is within e⁻⁴ (in log) of 10.
    fps, tau = 24.0, 0.4
    n = adaptation_history_frames(tau, fps)
    L = adapted_luminance([1.0] + [10.0] * n, 1 / fps, tau)
    assert 1.0 - math.log10(L) < math.exp(-HISTORY_TIME_CONSTANTS) * 1.0001


@pytest.mark.parametrize("bad", [(-1.0, 1.0, 0.1, 0.4), (1.0, 0.0, 0.1, 0.4), (1.0, 1.0, -0.1, 0.4),
                                 (1.0, 1.0, 0.1, -0.4), (np.nan, 1.0, 0.1, 0.4)])
def test_step_rejects_bad_input(bad):
    with pytest.raises(ValueError):
        adaptation_step_DurandDorsey2000(*bad)


def test_history_rejects_bad_input():
    for tau, fps in [(-1.0, 24.0), (0.4, 0.0), (math.inf, 24.0)]:
        with pytest.raises(ValueError):
            adaptation_history_frames(tau, fps)
    with pytest.raises(ValueError):
        adapted_luminance([], 0.1, 0.4)
