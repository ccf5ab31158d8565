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


#: How many tests this run selected and left out by its marker expression, and which tier of the suite it is:
#: "fast" (``make test``: -m "not slow"), "all" (``make test-all``: no marker expression), None for any
#: other run (paths, -k, deselections, ``make test-slow``, which holds no test of the README): what
#: tests/test_readme.py compares with the README's counts.
SELECTED = pytest.StashKey[int]()
LEFT_OUT = pytest.StashKey[int]()
TIER = pytest.StashKey[str | None]()
TIERS = {"": "all", "not slow": "fast"}


def pytest_deselected(items):
    config = items[0].config if items else None
    if config is not None:
        config.stash[LEFT_OUT] = config.stash.get(LEFT_OUT, 0) + len(items)


def pytest_collection_finish(session):
    config = session.config
    config.stash[SELECTED] = len(session.items)
    whole = (not config.args or config.args == config.getini("testpaths")) and \
        not config.option.keyword and not config.option.deselect
    config.stash[TIER] = TIERS.get((config.option.markexpr or "").strip()) if whole else None
