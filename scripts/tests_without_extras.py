"""Run tests as on a machine without the optional extras (issue 45, item 4): each extra's modules are made
unimportable (``sys.modules[name] = None``) before pytest starts, so a test that needs one must skip with
its reason instead of failing.

Usage: ``.venv/bin/python scripts/tests_without_extras.py [PYTEST ARGS]`` (default: the tests that read
spectrum files and the scenes' loading, ~1 min). Extras: ``spectra`` (wavespectra).
NOTE: tests that start Dask workers cannot run under it (the workers re-import this script).
"""

import sys

import pytest

EXTRAS = {"spectra": ("wavespectra",)}
DEFAULT = ["tests/scene/test_settings.py", "tests/waves/test_sea_state.py", "tests/test_fuzz_scenes.py",
           "tests/test_pipeline.py::test_cli_geometry_export_of_measured_sea_states", "tests/test_cli.py",
           "tests/test_checks.py", "tests/io"]

if __name__ == "__main__":
    for modules in EXTRAS.values():
        for module in modules:
            sys.modules[module] = None  # import raises ImportError, as when not installed
    sys.exit(pytest.main(["-q", "-p", "no:cacheprovider", "-rs", *(sys.argv[1:] or DEFAULT)]))
