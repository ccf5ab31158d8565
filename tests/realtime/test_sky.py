"""The renderer's sky evaluated in given directions (realtime/sky.py): no read outside Mitsuba's sunsky tables.

Mitsuba 3.9.1's sunsky reads past the end of its tables at exactly 720 nm (docs/realtime.md, "Non-finite sky
radiance"); what it reads there decides whether the radiance is finite, so the evaluation was flaky. drjit's
debug mode checks every gather and reports an out-of-bounds read on the process's stderr: these tests read
that stream (file descriptor 2, where drjit's C++ logger writes).
"""

import numpy as np
import pytest

from oceanrender.realtime.sky import SUNSKY_LAST_NM, sky_radiance_spectra, sunsky_wavelengths
from oceanrender.scene.settings import SunSettings

OUT_OF_BOUNDS = "out-of-bounds read"


@pytest.fixture
def debug_gathers(variant):
    """drjit's debug mode (bounds-checked gathers) for one test."""
    import drjit as dr

    level = dr.log_level()
    dr.set_flag(dr.JitFlag.Debug, True)
    dr.set_log_level(dr.LogLevel.Warn)  # the bounds checks report as warnings
    yield dr
    dr.set_flag(dr.JitFlag.Debug, False)
    dr.set_log_level(level)


def test_the_guard_moves_only_720_nm_and_by_one_float_step():
    wavelengths = np.array([400.0, 719.0, 720.0, 721.0])
    lanes = sunsky_wavelengths(wavelengths)
    assert lanes.dtype == np.float32
    assert lanes[2] < np.float32(SUNSKY_LAST_NM) and np.nextafter(lanes[2], np.float32(1e9)) == np.float32(720.0)
    np.testing.assert_array_equal(lanes[[0, 1, 3]], wavelengths[[0, 1, 3]].astype(np.float32))


def test_sky_evaluation_reads_inside_the_tables_at_every_wavelength(debug_gathers, capfd):
    """The sky at 360–830 nm (720 nm included) in 64 directions: finite, and no out-of-bounds read reported."""
    rng = np.random.default_rng(3)
    directions = rng.normal(size=(64, 3))
    directions[:, 2] = np.abs(directions[:, 2]) + 0.05  # above the horizon
    directions /= np.linalg.norm(directions, axis=1, keepdims=True)
    wavelengths = np.arange(360.0, 831.0, 5.0)
    assert SUNSKY_LAST_NM in wavelengths
    capfd.readouterr()
    radiance = sky_radiance_spectra(SunSettings(), directions, wavelengths)
    debug_gathers.sync_thread()
    err = capfd.readouterr().err
    assert OUT_OF_BOUNDS not in err, err[-2000:]
    assert np.all(np.isfinite(radiance))
    at_720 = list(wavelengths).index(SUNSKY_LAST_NM)
    # the radiance at 720 nm is the tables' last entry, not zero (the guard keeps the wavelength inside them)
    assert np.all(radiance[:, at_720] > 0.0)
    assert np.all(radiance[:, wavelengths > SUNSKY_LAST_NM] == 0.0)


def test_without_the_guard_sunsky_reads_past_its_tables_at_720_nm(debug_gathers, capfd):
    """The control: the same emitter evaluated at exactly 720 nm reports the out-of-bounds read (so the test
    above would fail without the guard)."""
    import mitsuba as mi

    from oceanrender.render.scene import sunsky_emitter

    settings = sunsky_emitter(SunSettings())
    settings["sun_scale"] = 0.0
    emitter = mi.load_dict(settings)
    si = debug_gathers.zeros(mi.SurfaceInteraction3f, 8)
    si.wi = mi.Vector3f(0.0, 0.0, -1.0)
    lanes = mi.Float(np.full(8, 720.0, dtype=np.float32))  # an array, as the evaluation passes them
    si.wavelengths = mi.Spectrum(lanes, lanes, lanes, lanes)
    capfd.readouterr()
    np.array(emitter.eval(si))
    debug_gathers.sync_thread()
    assert OUT_OF_BOUNDS in capfd.readouterr().err
