"""Seas given by Hs/Tp partitions or by a directional spectrum file (oceanrender.waves.sea_state, io.spectrum_files).

The generated seas are checked against their input: significant height, peak period and mean
direction within 2 % (direction: 2°), averaged over seeds, on a lattice that resolves the spectrum
(the issue's numbers); the shapes against wavespectra's independent constructors and closed forms.
"""

import math

import numpy as np
import pytest

from oceanrender.io.spectrum_files import read_spectrum_file
from oceanrender.waves.fft_ocean import FFTOcean, OceanGrid, initial_amplitudes
from oceanrender.waves.sea_state import (
    Partition,
    PartitionedSpectrum,
    TabulatedSpectrum,
    partition_spectrum,
)
from oceanrender.waves.wave_spectra import GRAVITY, SEAWATER_SURFACE_TENSION, dispersion_relation
from tests.extras import needs_spectra
from tests.tolerances import QUADRATURE

ROOT = __import__("pathlib").Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "scenes" / "sea_states" / "bimodal.swn"

#: Seeds the generated statistics are averaged over.
SEEDS = (1, 2, 3, 4)


@pytest.mark.parametrize("spectrum", ["JONSWAP 1973", "Pierson-Moskowitz 1964", "TMA 1985"])
def test_a_partition_carries_hs_exactly_and_peaks_at_tp(spectrum):
    kwargs = {} if spectrum == "Pierson-Moskowitz 1964" else {"gamma": 4.0}
    p = Partition(spectrum, hs=2.5, tp=9.0, **kwargs)
    f = np.geomspace(0.02, 5.0, 200_001)
    S = partition_spectrum(p, f, depth=12.0)
    assert 4 * math.sqrt(np.trapezoid(S, f)) == pytest.approx(2.5, rel=1e-5)  # the scaling's own quadrature: 1e-6
    peak = f[np.argmax(S)]
    # TMA's depth function (12 m) moves the peak a little; JONSWAP and PM peak at 1/Tp.
    assert peak == pytest.approx(1 / 9.0, rel=0.03 if spectrum == "TMA 1985" else 1e-4)


def test_pierson_moskowitz_is_the_closed_form():
    """S(f) = (5/16) Hs² f_p⁴ f⁻⁵ exp(−5/4 (f_p/f)⁴) (DNV-RP-C205 2019, Eq. 3.5.4), whose m0 is Hs²/16."""
    f = np.linspace(0.03, 1.0, 500)
    S = partition_spectrum(Partition("Pierson-Moskowitz 1964", hs=3.0, tp=10.0), f)
    fp = 0.1
    np.testing.assert_allclose(S, 5 / 16 * 3.0**2 * fp**4 * f**-5 * np.exp(-1.25 * (fp / f) ** 4), rtol=1e-5)


def test_jonswap_agrees_with_wavespectra():
    """An independent implementation: wavespectra.construct.frequency.jonswap scaled to the same Hs."""
    wavespectra = pytest.importorskip("wavespectra.construct.frequency")
    f = np.geomspace(0.02, 2.0, 4000)
    ours = partition_spectrum(Partition("JONSWAP 1973", hs=1.7, tp=7.0, gamma=2.0, sigma_a=0.08, sigma_b=0.1), f)
    theirs = np.asarray(wavespectra.jonswap(f, fp=1 / 7.0, gamma=2.0, sigma_a=0.08, sigma_b=0.1, hs=1.7))
    # wavespectra scales with its own rectangle-rule m0 on this grid: the shapes agree to 1e-12, the scale to
    # the two quadratures' difference (< 1e-3 on 4000 log-spaced points).
    np.testing.assert_allclose(ours / ours.max(), theirs / theirs.max(), rtol=1e-9, atol=1e-12)
    assert ours.max() == pytest.approx(theirs.max(), rel=1e-3)


@pytest.mark.parametrize(("depth", "tension"), [(np.inf, 0.0), (15.0, 0.0), (np.inf, SEAWATER_SURFACE_TENSION)])
def test_psi_keeps_the_variance_of_e_f_theta(depth, tension):
    """Eq. 1: ∫∫ Ψ dkx dky = ∫∫ E df dθ at any depth and with capillarity (the Jacobian c_g/(2π k))."""
    sea = PartitionedSpectrum(partitions=(Partition(hs=1.2, tp=6.0, direction=0.3),
                                          Partition(hs=0.8, tp=11.0, gamma=6.0, direction=2.0, spreading_s=40.0)),
                              depth=depth, surface_tension=tension)
    f = np.geomspace(0.02, 10.0, 6000)
    k = np.array([_wavenumber(fi, depth, tension) for fi in f])
    theta = (np.arange(720) + 0.5) * 2 * np.pi / 720
    psi = sea(k[:, None] * np.cos(theta), k[:, None] * np.sin(theta))
    m0 = np.trapezoid(np.sum(psi, axis=1) * (2 * np.pi / 720) * k, k)
    assert m0 == pytest.approx(sea.elevation_variance(), rel=2e-4)  # quadrature on a 6000 × 720 polar grid


def _wavenumber(f, depth, tension):
    from scipy.optimize import brentq

    return brentq(lambda k: dispersion_relation(k, depth, GRAVITY, tension) - 2 * np.pi * f, 1e-8, 1e5)


def generated(spectrum, grid, seeds=SEEDS):
    """Per seed: the FFT sea's height variance, and |h̃₀|² on the lattice (the power of each travelling mode)."""
    variances, powers = [], []
    for seed in seeds:
        ocean = FFTOcean(grid, seed=seed, choppiness=0.0, dtype=np.float64, spectrum_function=spectrum,
                         engine="numpy")
        variances.append(float(np.var(ocean.fields(0.0).height)))
        powers.append(np.abs(initial_amplitudes(grid, ocean.spectrum_values, seed)) ** 2)
    return np.array(variances), np.mean(powers, axis=0)


def peak_period(power, grid, depth=np.inf):
    """Tp of the generated power binned in frequency (1 % bins), the peak refined by a parabola in ln f."""
    f = dispersion_relation(grid.k, depth) / (2 * np.pi)
    keep = f > 0
    edges = np.geomspace(f[keep].min(), f[keep].max(), 2000)
    S, _ = np.histogram(f[keep], edges, weights=power[keep])
    S = S / np.diff(edges)
    centres = np.sqrt(edges[1:] * edges[:-1])
    smooth = np.convolve(S, np.ones(9) / 9, mode="same")  # the lattice puts 0–3 modes in a bin
    i = int(np.argmax(smooth))
    x, y = np.log(centres[i - 1: i + 2]), smooth[i - 1: i + 2]
    a, b, _ = np.polyfit(x, y, 2)
    return 1.0 / math.exp(-b / (2 * a))


def direction_of(power, grid):
    theta = np.arctan2(grid.ky, grid.kx)
    return math.atan2(np.sum(power * np.sin(theta)), np.sum(power * np.cos(theta)))


@pytest.fixture(scope="module")
def resolving_grid():
    # 4 km patch: Δk = 1.6e-3 rad/m, 2.5 % of a 8 s peak's k_p; 1024 points reach k = 0.80 rad/m,
    # f = 0.45 Hz = 3.6 f_p of a 8 s sea.
    return OceanGrid(1024, 4000.0)


def test_generated_sea_state_matches_its_hs_tp_and_direction(resolving_grid):
    p = Partition("JONSWAP 1973", hs=2.0, tp=8.0, gamma=3.3, direction=math.radians(35.0), spreading_s=15.0)
    sea = PartitionedSpectrum(partitions=(p,))
    variances, power = generated(sea, resolving_grid)
    # The lattice keeps f ≤ 3.6 f_p: the JONSWAP tail above holds ~0.6 % of m0 (Hs 0.3 % low).
    assert 4 * math.sqrt(np.mean(variances)) == pytest.approx(2.0, rel=0.02)
    assert peak_period(power, resolving_grid) == pytest.approx(8.0, rel=0.02)
    assert math.degrees(direction_of(power, resolving_grid)) == pytest.approx(35.0, abs=2.0)


@needs_spectra
def test_the_example_file_is_read_in_the_projects_frame():
    table = read_spectrum_file(EXAMPLE, "swan", "2026-03-14T07:00:00", 1)
    assert (table.time, table.site, table.sites) == ("2026-03-14T07:00:00", 1, 2)
    assert table.frequency[0] == pytest.approx(0.04, rel=1e-4) and len(table.direction) == 36
    sea = TabulatedSpectrum(frequency=table.frequency, direction=table.direction, table=table.density)
    # scripts/make_example_spectrum.py: Hs² = (1.2 · 1.2)² + (1.0 · 1.2 · 1.1)² at site 1, hour 1, within the
    # file's 4-5 significant digits and the SWAN frequency grid (wavespectra scaled each on it).
    expected = math.hypot(1.2 * 1.2, 1.0 * 1.2 * 1.1)
    assert sea.significant_wave_height() == pytest.approx(expected, rel=0.01)
    # The direction density per frequency: the swell (from 160° nautical) travels toward θ = 270° − 160° = 110°.
    swell = np.argmin(np.abs(table.frequency - 1 / 12.0))
    assert math.degrees(table.direction[np.argmax(table.density[swell])]) == pytest.approx(110.0, abs=5.0)


@needs_spectra
def test_bimodal_file_gives_two_peaks_at_the_right_directions(resolving_grid):
    """The generated (kx, ky) power has its two maxima where the file puts the wind sea (θ = 20°) and the
    swell (θ = 110°), within the file's 10° direction bins."""
    table = read_spectrum_file(EXAMPLE, "swan", None, 0)
    sea = TabulatedSpectrum(frequency=table.frequency, direction=table.direction, table=table.density)
    variances, power = generated(sea, resolving_grid, seeds=(1, 2))
    assert 4 * math.sqrt(np.mean(variances)) == pytest.approx(sea.significant_wave_height(), rel=0.02)
    theta = np.degrees(np.arctan2(resolving_grid.ky, resolving_grid.kx)) % 360
    histogram, edges = np.histogram(theta, np.arange(0, 365, 5.0), weights=power)
    smooth = np.convolve(np.r_[histogram[-2:], histogram, histogram[:2]], np.ones(5) / 5, mode="valid")
    centres = (edges[1:] + edges[:-1]) / 2
    peaks = [i for i in range(len(smooth)) if smooth[i] >= smooth[i - 1] and smooth[i] > smooth[(i + 1) % len(smooth)]
             and smooth[i] > 0.2 * smooth.max()]
    found = sorted(centres[i] for i in peaks)
    assert len(found) == 2
    assert found[0] == pytest.approx(20.0, abs=5.0) and found[1] == pytest.approx(110.0, abs=5.0)
    # Its peak period is the swell's (12 s), on the file's frequency grid (its nodes are 8 % apart there).
    assert 2 * math.pi / sea.peak_frequency == pytest.approx(12.0, rel=0.05)


def test_tabulated_interpolation_wraps_in_direction_and_is_zero_outside_the_band():
    f = np.array([0.1, 0.2, 0.3])
    d = np.radians([10.0, 100.0, 190.0, 280.0])
    E = np.arange(12.0).reshape(3, 4) + 1
    sea = TabulatedSpectrum(frequency=f, direction=d, table=E, tail_exponent=0.0)
    np.testing.assert_allclose(sea.density(np.array([0.2]), np.array([d[2]])), [E[1, 2]], rtol=QUADRATURE)
    # Half-way from 280° to 370° (= 10°): across 2π.
    np.testing.assert_allclose(sea.density(np.array([0.1]), np.radians([325.0])), [(E[0, 3] + E[0, 0]) / 2],
                               rtol=QUADRATURE)
    assert sea.density(np.array([0.05, 0.31]), np.array([1.0, 1.0])).tolist() == [0.0, 0.0]
    # m0 of the bilinear table: trapezoids in f, each direction's share of 2π (90° here).
    assert sea.elevation_variance() == pytest.approx(float(np.trapezoid(E.sum(axis=1) * np.pi / 2, f)),
                                                     rel=QUADRATURE)


def test_the_file_spectrum_continues_as_an_f_minus_n_tail():
    """Beyond the file's last frequency: E(f_max, θ) (f/f_max)⁻⁵ (WAVEWATCH III's tail), its variance
    S(f_max) f_max/4 added to m0; tail_exponent = 0 keeps the file's band only."""
    f = np.array([0.1, 0.2, 0.3])
    d = np.radians([10.0, 100.0, 190.0, 280.0])
    E = np.arange(12.0).reshape(3, 4) + 1
    sea = TabulatedSpectrum(frequency=f, direction=d, table=E)
    np.testing.assert_allclose(sea.density(np.array([0.6]), np.array([d[1]])), [E[2, 1] * 2.0**-5], rtol=QUADRATURE)
    band = TabulatedSpectrum(frequency=f, direction=d, table=E, tail_exponent=0.0)
    S_max = E[2].sum() * np.pi / 2
    assert sea.elevation_variance() == pytest.approx(band.elevation_variance() + S_max * 0.3 / 4, rel=QUADRATURE)
    # The tail's analytic variance against quadrature of the density out to 1000 f_max.
    ft = np.geomspace(0.3, 300.0, 20001)
    numeric = np.trapezoid(sea.frequency_spectrum_hz(ft, directions=4 * 90), ft)
    assert numeric == pytest.approx(S_max * 0.3 / 4, rel=1e-4)
    with pytest.raises(ValueError, match="tail_exponent"):
        TabulatedSpectrum(frequency=f, direction=d, table=E, tail_exponent=0.5)
