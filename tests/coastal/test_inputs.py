"""Coastal boundary inputs: the incident waves offshore, monochromatic or from the ocean spectrum."""

import numpy as np
import pytest

from oceanrender.coastal import inputs
from oceanrender.coastal.boundaries import IncidentWave, Transmissive, Wall
from tests.scenes import scene_from_dict
from tests.scene.test_arrays import SMALL, coastal
from tests.tolerances import ROUNDOFF


def test_boundaries_put_the_waves_offshore():
    c = coastal(offshore_side="north", lateral="transmissive", wave_height=0.4, wave_period=5.0)
    b = inputs.boundaries(c)
    assert isinstance(b.north, IncidentWave) and isinstance(b.south, Wall)
    assert isinstance(b.east, Transmissive) and isinstance(b.west, Transmissive)
    assert b.north.amplitudes == (0.2,)  # H/2: halving is exact
    assert b.north.omegas[0] == pytest.approx(2 * np.pi / 5.0)


def test_spectral_waves_come_from_the_ocean_spectrum_and_travel_inshore():
    scene = scene_from_dict({"name": "c", "ocean": {"wind_speed": 6.0, "wind_direction": -90.0},
                             "coastal": {**SMALL, "waves": "spectrum", "wave_count": 12}})
    wave = inputs.incident_waves(scene.coastal, scene.ocean)
    assert 0 < len(wave.amplitudes) <= 12
    # Travelling into the domain through the north side: a southward component.
    assert all(np.sin(d) < 0 for d in wave.directions)
    k = np.array(wave.wavenumbers)
    # the wavenumbers invert the dispersion relation by Newton iterations to convergence
    np.testing.assert_allclose(np.array(wave.omegas) ** 2, 9.81 * k * np.tanh(k * scene.coastal.offshore_depth),
                               rtol=ROUNDOFF)


def test_a_uniform_current_from_the_scene_flows_on_unchanged():
    """An initial u₀ along a flat channel with transmissive ends: the exact solution is the current itself."""
    from oceanrender.coastal.simulation import solver_for_scene

    scene = scene_from_dict({"name": "c", "coastal": {
        "cells": [24, 8], "size": [12.0, 4.0], "origin": [0.0, 0.0], "shoreline_y": -1000.0,
        "offshore_depth": 1.5, "waves": "none", "initial_u": 0.3, "manning": 0.0, "order": 2}})
    solver, bed, state = solver_for_scene(scene)
    np.testing.assert_array_equal(state.hu, 0.3 * state.h)
    state = solver.advance(state, 1.0)
    np.testing.assert_allclose(state.h, 1.5, rtol=ROUNDOFF)
    np.testing.assert_allclose(state.hu, 0.45, rtol=ROUNDOFF)
    np.testing.assert_allclose(state.hv, 0.0, atol=ROUNDOFF * 0.45)
