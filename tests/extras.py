"""Tests that need an optional extra skip, naming it, where it is not installed (CI installs every extra).

``spectra`` (wavespectra): reading measured spectrum files, ``[ocean] spectrum_file``.
"""

import importlib

import pytest


def installed(module: str) -> bool:
    """Whether ``module`` imports (a module set to None in sys.modules counts as absent)."""
    try:
        importlib.import_module(module)
    except ImportError:
        return False
    return True


needs_spectra = pytest.mark.skipif(
    not installed("wavespectra"),
    reason="needs the optional extra 'spectra' (wavespectra) to read spectrum files: "
           "pip install -e '.[spectra]' (make setup and CI install it)")
