"""Tests for oceanrender.waves.kelvin_wake: the cusp angle against Kelvin's and Havelock's
closed forms and limits, the FFT wake against the cusp angle, the transverse wavelength,
the radiation condition, the hydrostatic limit, the free-surface conditions, scaling laws
and input validation."""

import numpy as np
import pytest
from scipy.optimize import brentq

from oceanrender.waves.kelvin_wake import (
    KELVIN_ANGLE_DEEP_WATER,
    WAKE_SOURCE_CUTOFF,
    WAKE_WRAP_EFOLDS,
    WakeSource,
    default_wake_damping,
    depth_froude_number,
    kelvin_cusp_angle,
    kelvin_wake_grid,
    kelvin_wake_spacing,
    wake_response,
)
from oceanrender.waves.wave_spectra import GRAVITY, SEAWATER_DENSITY
from tests.tolerances import EPS64, QUADRATURE, ROUNDOFF

HULL = WakeSource(length=50.0, beam=10.0, draft=3.0)

#: A 6 km × 6 km grid at 4 m: every Kelvin wave the hull excites at these speeds is
#: resolved (kelvin_wake_spacing ≥ 4.4 m), and the default damping leaves a decay
#: length U/ε = 1.7 km, several times the 200–1000 m over which the cusp is measured.
GRID = dict(size=6000.0, resolution=1500)

#: Hull Froude number U/√(g L) ≈ 0.5 in deep water: the footprint (σ_x = L/4) excites the
#: cusp waves (k σ_x ≈ 1.5) as strongly as the transverse ones, so the wake's brightest
#: line is its caustic. At U/√(g L) ≳ 0.6 the short diverging waves dominate and the
#: brightest line narrows (Rabaud & Moisy 2013), which is a property of the source, not
#: an error of the wake.
DEEP_SPEED = 11.0

#: Depth, speed of the two shallow cases: Fr_h = 0.8 and 0.9, cusp waves again at k σ_x ≈ 2.
SHALLOW = {0.8: 11.0, 0.9: 6.5}

#: Distances behind the hull over which the cusp line is fitted [m]: from about four cusp
#: wavelengths (where the near field has died out) to 0.6 of the damping's decay length.
FIT_RANGE = (200.0, 1000.0)

#: Measured cusp angle against the analytic one [rad]. One grid cell (4 m) seen from the
#: nearest fitted distance (200 m) subtends 1.1°, a bound on the error of each column's
#: peak (located by a parabola to a fraction of a cell), and the fit averages 200 columns;
#: the Rayleigh damping tilts the envelope and moves the measured angle by 0.1–0.3°
#: (halving ε changes it by that much). 1° covers both with room to spare.
ANGLE_TOLERANCE = np.radians(1.0)


def shallow_speed(froude, depth):
    return froude * np.sqrt(GRAVITY * depth)


@pytest.fixture(scope="module")
def deep_wake():
    return kelvin_wake_grid(HULL, DEEP_SPEED, np.inf, **GRID)


@pytest.fixture(scope="module", params=sorted(SHALLOW))
def shallow_wake(request):
    froude = request.param
    depth = SHALLOW[froude]
    return froude, depth, kelvin_wake_grid(HULL, shallow_speed(froude, depth), depth, **GRID)


def wave_envelope(eta):
    """|η + i H_x η|: the amplitude of the waves, from the analytic signal along x.

    Every stationary wave has k_x ≠ 0; keeping only k_x > 0 (doubled) turns each wave
    train into a complex exponential whose modulus is its local amplitude, and drops the
    x-mean (k_x = 0) of the hull's static depression.
    """
    spectrum = np.fft.fft(eta, axis=1)
    kx = np.fft.fftfreq(eta.shape[1])
    return np.abs(np.fft.ifft(spectrum * np.where(kx > 0, 2.0, 0.0), axis=1))


def measured_cusp_angle(x, y, eta, near=FIT_RANGE[0], far=FIT_RANGE[1]):
    """Half-angle of the wake's cusp line measured from the field η [rad].

    For each column between ``near`` and ``far`` metres behind the hull, the outermost
    local maximum of the wave envelope over y > 0 that reaches half the column's largest
    value: the first Airy maximum inside the caustic, where the amplitude is largest
    (transverse waves near the track can be as strong in shallow water, which is why the
    outermost peak and not the largest is taken). It is refined by a parabola through
    three points. Near the caustic the elevation is an Airy function of
    (y − X tan ψ_c) X^{−1/3} (Ursell 1960, J. Fluid Mech. 8, 418–431), so the peak lies a
    distance ∝ X^{1/3} inside the cusp line; the fit y = X tan ψ + b X^{1/3} + c (c the
    virtual origin of the extended hull) returns ψ.
    """
    columns = (x <= -near) & (x >= -far)
    upper = y > 0
    amplitude = wave_envelope(eta)[np.ix_(upper, columns)]
    y_up = y[upper]
    inner = amplitude[1:-1]
    peaks = (inner >= amplitude[:-2]) & (inner >= amplitude[2:]) & (inner >= 0.5 * amplitude.max(axis=0))
    row = (np.arange(1, y_up.size - 1)[:, None] * peaks).max(axis=0)
    column = np.arange(amplitude.shape[1])
    below, centre, above = amplitude[row - 1, column], amplitude[row, column], amplitude[row + 1, column]
    offset = 0.5 * (below - above) / (below - 2 * centre + above)  # vertex of the parabola, in cells
    y_peak = y_up[row] + offset * (y_up[1] - y_up[0])
    distance = -x[columns]
    design = np.stack([distance, np.cbrt(distance), np.ones_like(distance)], axis=1)
    slope = np.linalg.lstsq(design, y_peak, rcond=None)[0][0]
    return float(np.arctan(slope))


def track_wavenumber(froude):
    """Wavenumber × depth of the transverse wave on the track: phase speed U, tanh κ/κ = Fr_h²."""
    return brentq(lambda kappa: np.tanh(kappa) / kappa - froude**2, 1e-9, 10 / froude**2)


def ray_angles(froude, count=400_001):
    """Ray angle ψ [rad] of every stationary wave, from Eq. 2 of kelvin_cusp_angle, on a dense κ grid.

    Independent of the cusp condition (Eq. 3): stationary waves have tanh κ/κ = Fr² cos²θ,
    their energy moves at c_g k̂ − U x̂ relative to the hull. Subcritical: from the
    transverse wave on the track to κ 40 times longer (θ ≈ 80°); supercritical: from the
    longest waves (κ = 1e-6) to κ = 100.
    """
    if froude < 1:
        kappa = track_wavenumber(froude) * np.exp(np.linspace(0.0, np.log(40.0), count))
    else:
        kappa = np.exp(np.linspace(np.log(1e-6), np.log(100.0), count))
    cos2 = np.minimum(np.tanh(kappa) / (kappa * froude**2), 1.0)  # rounding at the track
    n = 0.5 + kappa / np.sinh(2 * kappa)  # c_g/c
    return np.arctan2(n * np.sqrt(cos2 * (1 - cos2)), 1 - n * cos2)


# --------------------------------------------------------------------------- cusp angle


def test_deep_water_cusp_is_asin_one_third():
    # Kelvin's angle; Fr_h = 0 takes the closed form, small Fr_h the root finder
    assert KELVIN_ANGLE_DEEP_WATER == pytest.approx(np.arcsin(1 / 3), rel=ROUNDOFF)
    assert np.degrees(KELVIN_ANGLE_DEEP_WATER) == pytest.approx(19.4712206, abs=1e-7)  # the printed digits
    deep = float(kelvin_cusp_angle(depth_froude_number(5.0, np.inf)))
    assert deep == pytest.approx(np.arcsin(1 / 3), rel=ROUNDOFF)
    # finite depth enters through e^{−2 k h}, k h ≈ 1.5/Fr²: below 1e-13 for Fr_h ≤ 0.3; Brent to QUADRATURE
    np.testing.assert_allclose(kelvin_cusp_angle([1e-3, 0.1, 0.3]), np.arcsin(1 / 3), rtol=QUADRATURE)


def test_cusp_angle_is_the_largest_ray_angle_of_the_stationary_waves():
    # Eq. 3 (the root) against the maximum of Eq. 2 over 400 001 stationary waves: the
    # maximum of a smooth function on a grid of relative step 1e-5 is low by ~1e-10
    for froude in (0.5, 0.7, 0.8, 0.9, 0.95, 0.99):
        assert float(kelvin_cusp_angle(froude)) == pytest.approx(ray_angles(froude).max(), rel=QUADRATURE)


def test_cusp_angle_widens_monotonically_to_ninety_degrees():
    froude = np.linspace(0.45, 0.9999, 400)  # below ~0.4 the increase is under the rounding
    angles = kelvin_cusp_angle(froude)
    assert np.all(np.diff(angles) > 0)
    assert np.all(kelvin_cusp_angle(np.linspace(0.0, 0.45, 50)) >= KELVIN_ANGLE_DEEP_WATER * (1 - ROUNDOFF))
    assert float(kelvin_cusp_angle(1.0)) == pytest.approx(np.pi / 2, rel=ROUNDOFF)


@pytest.mark.parametrize("froude", [0.999, 0.9999, 0.99999])
def test_near_critical_cusp_follows_the_long_wave_expansion(froude):
    # κ² ≪ 1 in Eqs. 1–3: tan ψ_c = 1/√(8 (1 − Fr²)) with a relative error of order 1 − Fr²
    # (measured 0.9 (1 − Fr²)); 2 (1 − Fr²) bounds the first neglected term
    deficit = 1 - froude**2
    cot = 1 / np.tan(float(kelvin_cusp_angle(froude)))
    assert cot / np.sqrt(8 * deficit) == pytest.approx(1.0, abs=2 * deficit)


def test_supercritical_wedge_is_the_mach_angle():
    froude = np.array([1.0 + 1e-9, 1.2, 2.0, 5.0])
    np.testing.assert_allclose(kelvin_cusp_angle(froude), np.arcsin(1 / froude), rtol=ROUNDOFF)
    # and it is the supremum of the ray angles: the longest waves (κ → 0) have it
    for value in froude[1:]:
        rays = ray_angles(value)
        assert rays.max() <= np.arcsin(1 / value) * (1 + ROUNDOFF)
        assert rays.max() == pytest.approx(np.arcsin(1 / value), rel=QUADRATURE)  # κ_min = 1e-6: error O(κ²)
    # continuous through Fr_h = 1 from both sides (both ≈ 90° − √(8(1 − Fr²)))
    assert float(kelvin_cusp_angle(1 - 1e-8)) == pytest.approx(np.pi / 2, abs=1e-3)
    assert float(kelvin_cusp_angle(1 + 1e-8)) == pytest.approx(np.pi / 2, abs=1e-3)


def test_cusp_angle_broadcasts_and_propagates_nan():
    angles = kelvin_cusp_angle([[0.0, np.nan], [np.inf, 2.0]])
    assert angles.shape == (2, 2) and angles.dtype == np.float64
    assert np.isnan(angles[0, 1]) and angles[1, 0] == 0.0
    with pytest.raises(ValueError, match="^depth_froude"):
        kelvin_cusp_angle(-0.1)


# --------------------------------------------------------------------------- response


def test_response_satisfies_the_linear_free_surface_conditions(rng):
    # the transfer function against the two boundary conditions it was derived from:
    # s η̂ = k tanh(kh) φ̂ (kinematic) and s φ̂ + g η̂ + p̂/ρ = 0 (Bernoulli), s = ε − i U k_x
    kx, ky = rng.uniform(-0.5, 0.5, (2, 1000))
    speed, damping = 9.0, 0.02
    for depth in (np.inf, 7.0):
        eta = wake_response(kx, ky, speed, depth, damping)  # η̂ for p̂ = 1 Pa m²
        k = np.hypot(kx, ky)
        restoring = k * (np.tanh(k * depth) if np.isfinite(depth) else 1.0)
        s = damping - 1j * speed * kx
        phi = s * eta / restoring  # from the kinematic condition
        residual = s * phi + GRAVITY * eta + 1 / SEAWATER_DENSITY
        # terms up to |g η̂| (large near the Kelvin poles) cancel: relative to them
        scale = GRAVITY * np.abs(eta) + 1 / SEAWATER_DENSITY
        assert np.all(np.abs(residual) <= ROUNDOFF * scale)


def test_response_is_hermitian_and_hydrostatic_at_rest(rng):
    kx, ky = rng.uniform(-2, 2, (2, 500))
    response = wake_response(kx, ky, 8.0, 12.0, 0.01)
    np.testing.assert_allclose(wake_response(-kx, -ky, 8.0, 12.0, 0.01), np.conj(response),
                               rtol=ROUNDOFF)  # a real pressure gives a real elevation
    # U → 0: η̂ = −p̂/(ρ g), the hydrostatic depression; the corrections U² k/g ~ 1e-16
    at_rest = wake_response(kx, ky, 1e-8, 12.0, 1e-12)
    np.testing.assert_allclose(at_rest, -1 / (SEAWATER_DENSITY * GRAVITY), rtol=ROUNDOFF)


def test_pressure_spectrum_is_the_fourier_transform_of_the_pressure():
    # a Riemann sum of a Gaussian over ±4σ… converges spectrally: far below QUADRATURE
    x = np.linspace(-2 * HULL.length, 2 * HULL.length, 801)
    y = np.linspace(-2 * HULL.beam, 2 * HULL.beam, 401)
    pressure = HULL.pressure(x[None, :], y[:, None])
    cell = (x[1] - x[0]) * (y[1] - y[0])
    for kx, ky in [(0.0, 0.0), (0.1, 0.0), (0.05, 0.3), (-0.2, 0.5)]:
        numeric = np.sum(pressure * np.exp(-1j * (kx * x[None, :] + ky * y[:, None]))) * cell
        peak = float(HULL.pressure_spectrum(0.0, 0.0))
        assert abs(numeric - HULL.pressure_spectrum(kx, ky)) <= QUADRATURE * peak
    assert float(HULL.pressure(0.0, 0.0)) == pytest.approx(SEAWATER_DENSITY * GRAVITY * HULL.draft, rel=ROUNDOFF)
    assert HULL.pressure_spectrum(0.0, 0.0) / (SEAWATER_DENSITY * GRAVITY) == pytest.approx(
        HULL.displaced_volume, rel=ROUNDOFF)


# --------------------------------------------------------------------------- the FFT wake


def test_deep_water_wake_has_kelvins_angle(deep_wake):
    x, y, eta = deep_wake
    assert measured_cusp_angle(x, y, eta) == pytest.approx(np.arcsin(1 / 3), abs=ANGLE_TOLERANCE)


def test_shallow_water_wake_widens_as_havelock_predicts(shallow_wake):
    froude, depth, (x, y, eta) = shallow_wake
    measured = measured_cusp_angle(x, y, eta)
    analytic = float(kelvin_cusp_angle(froude))
    assert measured == pytest.approx(analytic, abs=ANGLE_TOLERANCE)
    assert measured > KELVIN_ANGLE_DEEP_WATER + np.radians(4.0)  # clearly wider than 19.47°


def peak_track_wavenumber(x, y, eta):
    """Wavenumber of the strongest wave along the track, 200–1500 m behind the hull [rad m⁻¹],
    and the record's Fourier bin width [rad m⁻¹]."""
    record = (x <= -200.0) & (x >= -1500.0)
    row = eta[np.argmin(np.abs(y)), record]
    padded = 1 << 16
    spectrum = np.abs(np.fft.rfft(row * np.hanning(row.size), padded))
    k = 2 * np.pi * np.fft.rfftfreq(padded, x[1] - x[0])
    return k[np.argmax(spectrum)], 2 * np.pi / (row.size * (x[1] - x[0]))


def test_deep_transverse_waves_have_the_stationary_wavelength(deep_wake):
    # waves on the track (θ = 0) stand still behind the hull when their phase speed is U:
    # k = g/U²; the peak of a zero-padded, Hann-windowed record is located to well within
    # half a Fourier bin
    k, bin_width = peak_track_wavenumber(*deep_wake)
    assert k == pytest.approx(GRAVITY / DEEP_SPEED**2, abs=bin_width / 2)


def test_shallow_transverse_waves_have_the_stationary_wavelength(shallow_wake):
    # as above, with the finite-depth phase speed: tanh(kh)/(kh) = Fr_h²
    froude, depth, wake = shallow_wake
    k, bin_width = peak_track_wavenumber(*wake)
    assert k == pytest.approx(track_wavenumber(froude) / depth, abs=bin_width / 2)


def energy_ahead_over_behind(x, eta):
    """Mean square of η more than two hull lengths ahead over that more than two behind [-]."""
    return np.mean(eta[:, x > 2 * HULL.length] ** 2) / np.mean(eta[:, x < -2 * HULL.length] ** 2)


#: The radiation condition puts the waves behind the hull. What is left ahead, beyond the
#: hull's near field (two hull lengths), is the wrapped wake of the periodic images, whose
#: waves the default damping cuts by ≥ e^{−3} in amplitude (e^{−6} ≈ 2.5e-3 in energy
#: relative to equally distant waves; measured 1.1e-3 to 5.9e-3 of the wake's energy, the
#: largest at Fr_h = 0.9 where the upstream near field decays slowly). With the wrong
#: sign of ε the waves would be ahead and the ratio ≫ 1.
AHEAD_ENERGY = 1e-2


def test_no_waves_ahead_of_the_hull_in_deep_water(deep_wake):
    x, _, eta = deep_wake
    assert energy_ahead_over_behind(x, eta) < AHEAD_ENERGY


def test_no_waves_ahead_of_the_hull_in_shallow_water(shallow_wake):
    x, _, eta = shallow_wake[2]
    assert energy_ahead_over_behind(x, eta) < AHEAD_ENERGY


def test_a_slow_hull_sinks_the_surface_by_its_draft():
    # U → 0: the hydrostatic depression η = −p/(ρ g) (minus its mean on the periodic grid).
    # First-order dynamic corrections |ρ g η̂/p̂ + 1| ≤ (U² |k_x| + 2 ε U)/g, integrated over
    # the Gaussian footprint (E|k_x| = √(2/π)/σ_x), bound the difference.
    speed, size, resolution = 0.2, (512.0, 256.0), (512, 256)  # 1 m cells: σ_y = 2.5 m resolved
    for depth in (np.inf, 10.0):
        x, y, eta = kelvin_wake_grid(HULL, speed, depth, size, resolution)
        static = -HULL.pressure(x[None, :], y[:, None]) / (SEAWATER_DENSITY * GRAVITY)
        static -= static.mean()
        damping = default_wake_damping(speed, depth, size)
        bound = HULL.draft * (speed**2 * np.sqrt(2 / np.pi) / HULL.widths[0] + 2 * damping * speed) / GRAVITY
        assert np.abs(eta - static).max() <= bound
        assert eta[np.argmin(np.abs(y)), np.argmin(np.abs(x))] == pytest.approx(-HULL.draft, rel=0.01)


def test_grid_layout_and_types(deep_wake):
    x, y, eta = deep_wake
    assert x.dtype == y.dtype == eta.dtype == np.float64
    assert x.shape == (1500,) and y.shape == (1500,) and eta.shape == (1500, 1500)
    assert 0.0 in x and 0.0 in y  # the hull's centre is a grid point
    assert x[-1] == pytest.approx(0.15 * 6000 - 4.0, rel=ROUNDOFF)  # 15 % of the grid ahead
    assert abs(eta.mean()) <= ROUNDOFF * np.abs(eta).max()  # the zero wavenumber is dropped
    assert np.all(np.isfinite(eta))


def test_wake_is_linear_in_the_draft_and_independent_of_density():
    args = (9.0, np.inf, (1200.0, 800.0), (300, 200))
    _, _, eta = kelvin_wake_grid(HULL, *args)
    _, _, deeper = kelvin_wake_grid(WakeSource(HULL.length, HULL.beam, 2 * HULL.draft), *args)
    np.testing.assert_allclose(deeper, 2 * eta, rtol=0, atol=ROUNDOFF * np.abs(eta).max())
    _, _, fresh = kelvin_wake_grid(HULL, *args, density=1000.0)
    np.testing.assert_allclose(fresh, eta, rtol=0, atol=ROUNDOFF * np.abs(eta).max())


def test_froude_scaling():
    # the linear problem has one length scale and the time scale √(L/g): a hull, depth and
    # grid s times larger at √s times the speed give an s times higher wake at s x
    scale = 4.0
    small = WakeSource(HULL.length, HULL.beam, HULL.draft)
    large = WakeSource(scale * HULL.length, scale * HULL.beam, scale * HULL.draft)
    x, y, eta = kelvin_wake_grid(small, 7.0, 12.0, (1200.0, 800.0), (300, 200))
    xs, ys, eta_s = kelvin_wake_grid(large, 7.0 * np.sqrt(scale), 12.0 * scale, (4800.0, 3200.0), (300, 200))
    np.testing.assert_allclose(xs, scale * x, rtol=ROUNDOFF)
    np.testing.assert_allclose(eta_s, scale * eta, rtol=0, atol=ROUNDOFF * scale * np.abs(eta).max())


def test_default_damping_and_spacing():
    # ε = 3 U/d_wrap, d_wrap the shorter of the path along the track and across the wedge
    size = (6000.0, 2000.0)
    expected = WAKE_WRAP_EFOLDS * 11.0 / min(0.85 * 6000.0, 1000.0 / np.sin(np.arcsin(1 / 3)))
    assert default_wake_damping(11.0, np.inf, size) == pytest.approx(expected, rel=ROUNDOFF)
    # deep water: Δ = π g σ_x²/(9 U²); shallow water needs finer cells (shorter waves at a given ω)
    sigma_x = HULL.widths[0]
    assert kelvin_wake_spacing(HULL, 11.0) == pytest.approx(
        np.pi * GRAVITY * sigma_x**2 / (WAKE_SOURCE_CUTOFF**2 * 11.0**2), rel=ROUNDOFF)
    assert kelvin_wake_spacing(HULL, 11.0, 5.0) < kelvin_wake_spacing(HULL, 11.0)
    assert kelvin_wake_spacing(HULL, DEEP_SPEED) >= 6000.0 / 1500 * (1 - 64 * EPS64)  # GRID resolves it


# --------------------------------------------------------------------------- validation


@pytest.mark.parametrize("field, values", [("length", (-50.0, 10.0, 3.0)), ("beam", (50.0, np.nan, 3.0)),
                                           ("draft", (50.0, 10.0, 0.0))])
def test_bad_hull_is_refused_by_name(field, values):
    with pytest.raises(ValueError, match=f"^{field}"):
        WakeSource(*values)


@pytest.mark.parametrize("keyword, value, name", [
    ("speed", np.nan, "speed"), ("speed", np.inf, "speed"), ("speed", 0.0, "speed"), ("speed", -3.0, "speed"),
    ("depth", 0.0, "depth"), ("depth", -10.0, "depth"), ("depth", np.nan, "depth"), ("depth", 2.0, "depth"),
    ("size", -100.0, "size"), ("resolution", 1, "resolution"), ("resolution", 64.5, "resolution"),
    ("resolution", np.nan, "resolution"), ("resolution", (64, 32, 16), "resolution"),
    ("ahead", 1.0, "ahead"), ("damping", 0.0, "damping"), ("damping", -0.01, "damping"),
])
def test_bad_grid_inputs_are_refused_by_name(keyword, value, name):
    arguments = dict(source=HULL, speed=9.0, depth=np.inf, size=1000.0, resolution=64)
    arguments[keyword] = value
    with pytest.raises(ValueError, match=f"^{name}"):
        kelvin_wake_grid(**arguments)
