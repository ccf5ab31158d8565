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


#: How many tests this run collected, and whether it is the whole suite (no paths, no -k, no -m): what
#: tests/test_readme.py compares with the README's count.
COLLECTED = pytest.StashKey[int]()
WHOLE_SUITE = pytest.StashKey[bool]()


def pytest_collection_modifyitems(session, config, items):
    config.stash[COLLECTED] = len(items)
    config.stash[WHOLE_SUITE] = (not config.args or config.args == config.getini("testpaths")) and \
        not config.option.keyword and not config.option.markexpr and not config.option.deselect
