"""The optics report's figures: limits that keep the light-field plot readable (issue 19, item 6)."""

import numpy as np

from oceanrender.export.optics_report import LIGHTFIELD_DECADES, lightfield_limits
from oceanrender.optics.components import PRESETS, composition_iops
from oceanrender.optics.report import scene_optics


def _turbid_light_field():
    wavelengths = np.array([450.0, 550.0, 650.0])
    iops = composition_iops(PRESETS["turbid brown estuary"], wavelengths)
    z = np.linspace(0.0, 50.0, 101)
    return scene_optics(iops.absorption, iops.scattering, iops.backscattering, np.full(3, 1.2), np.full(3, 0.3),
                        30.0, np.inf, z, wavelengths=wavelengths)


def test_light_field_plot_spans_six_decades_not_the_whole_column():
    """Turbid water's E_d falls by many tens of decades over 50 m; the plot shows 6 below the top, to where E_d gets there."""
    light = _turbid_light_field().light
    z, E_d, E_u = np.asarray(light.z), np.asarray(light.E_d), np.asarray(light.E_u)
    assert E_d[:, -1].min() / E_d[:, 0].max() < 1e-30  # the range the old plot had to show
    z_max, lo, hi = lightfield_limits(z, E_d, E_u)
    top = max(E_d.max(), E_u.max())
    assert hi / lo == 2.0 * 10.0**LIGHTFIELD_DECADES and lo == top * 10.0**-LIGHTFIELD_DECADES
    # the depth axis ends just past the last depth where some plotted E_d is above the floor (5 % margin)
    last = z[np.any(E_d >= lo, axis=0)].max()
    assert last <= z_max <= 1.05 * last + 1e-12 and z_max < z[-1]
    assert np.all(E_d[:, z > z_max] < lo)


def test_clear_water_keeps_the_whole_column():
    """Where E_d stays within the decades shown, the plot runs to the bottom of the profile."""
    z = np.linspace(0.0, 10.0, 11)
    E_d = np.exp(-0.05 * z)[None, :]
    z_max, lo, hi = lightfield_limits(z, E_d, 0.02 * E_d)
    assert z_max == 10.0 and lo == 10.0**-LIGHTFIELD_DECADES
