"""Shared fixtures: one seeded random generator, one Mitsuba variant per session."""

import warnings

import numpy as np
import pytest


@pytest.fixture
def rng():
    """A seeded generator: every random test is reproducible."""
    return np.random.default_rng(20261122)


@pytest.fixture(scope="session")
def variant():
    """Activate the Mitsuba spectral variant the CLI would pick; return its name."""
    from oceanrender.runtime.variants import activate_variant

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        info = activate_variant("auto")
    return info.variant
