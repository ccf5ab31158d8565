"""Mie theory for particle populations: published reference values, limits, PSD averaging."""

import numpy as np
import pytest

from oceanrender.optics.mie import (
    JungePSD,
    LogNormalPSD,
    mass_specific_iops,
    rayleigh_scattering_efficiency,
    sphere_efficiencies,
)
from tests.tolerances import ROUNDOFF

# Du (2004) Appl. Opt. 43:1951, Table 1 (Wiscombe's 1979 test cases): x, m = n + ik, Qext, Qsca.
DU2004_TABLE1 = [
    (0.099, 0.75 + 0j, 7.417859e-06, 7.417859e-06),
    (10.0, 0.75 + 0j, 2.232265, 2.232265),
    (100.0, 1.33 + 1e-5j, 2.101321, 2.096594),
    (0.055, 1.5 + 1j, 0.101491, 1.131687e-05),
    (100.0, 1.5 + 1j, 2.097502, 1.283697),
    (1.0, 10 + 10j, 2.532993, 2.049405),
]


@pytest.mark.parametrize("x, m, q_ext, q_sca", DU2004_TABLE1)
def test_efficiencies_match_published_reference_values(x, m, q_ext, q_sca):
    eff = sphere_efficiencies(m, [x])
    assert eff.q_ext[0] == pytest.approx(q_ext, rel=2e-6)
    assert eff.q_sca[0] == pytest.approx(q_sca, rel=2e-6)


def test_efficiencies_and_asymmetry_agree_with_miepython():
    import miepython

    x = np.array([0.3, 2.0, 7.5, 40.0])
    m = 1.18 + 0.004j
    ours = sphere_efficiencies(m, x)
    q_ext, q_sca, _, g = miepython.efficiencies_mx(np.full(x.size, m.conjugate()), x)  # miepython: n − ik
    # Two independent series implementations (different recurrences and term counts):
    # 1e-9 relative is well above their round-off and far below any physical effect.
    np.testing.assert_allclose(ours.q_ext, q_ext, rtol=1e-9)
    np.testing.assert_allclose(ours.q_sca, q_sca, rtol=1e-9)
    np.testing.assert_allclose(ours.g, g, rtol=1e-9)


def test_backscattering_efficiency_against_direct_integration():
    import miepython

    m, x = 1.2 + 0.001j, 6.0
    mu = np.linspace(-1.0, 0.0, 20001)
    # miepython's "qsca" normalisation: ∫ i dΩ over 4π equals Q_sca.
    i = miepython.i_unpolarized(m.conjugate(), x, mu, norm="qsca")
    q_bsca = 2.0 * np.pi * np.trapezoid(i, mu)
    assert sphere_efficiencies(m, [x]).q_bsca[0] == pytest.approx(q_bsca, rel=1e-5)


def test_rayleigh_limit():
    # Small spheres: Q_sca = (8/3) x⁴ |(m²−1)/(m²+2)|² and a symmetric (dipole) pattern, b_b/b = 1/2.
    m, x = 1.2 + 0j, np.array([0.005, 0.01])
    eff = sphere_efficiencies(m, x)
    np.testing.assert_allclose(eff.q_sca, rayleigh_scattering_efficiency(m, x), rtol=1e-3)
    np.testing.assert_allclose(eff.q_bsca / eff.q_sca, 0.5, rtol=1e-3)
    np.testing.assert_allclose(eff.g, 0.0, atol=1e-4)


def test_extinction_paradox_for_large_spheres():
    # van de Hulst (1957): Q_ext → 2 as x → ∞ (for any m ≠ 1); the edge term decays as x^(-2/3).
    # An absorbing sphere damps the interference ripple that would hide the trend.
    eff = sphere_efficiencies(1.2 + 0.05j, [50.0, 300.0, 1000.0])
    deviation = eff.q_ext - 2.0
    assert 0 < deviation[2] < deviation[1] < deviation[0]
    assert deviation[2] < 0.02
    assert deviation[2] == pytest.approx(deviation[0] * (50.0 / 1000.0) ** (2 / 3), rel=0.1)


def test_narrow_lognormal_reproduces_single_sphere():
    # A nearly monodisperse population: b* = 3 Q_sca / (2 ρ D) with ρ in g m⁻³.
    d, rho, lam, n_w, m = 2e-6, 2600.0, 550.0, 1.34, 1.17 + 0.002j
    iops = mass_specific_iops([lam], m, LogNormalPSD(d, 1.002), rho, n_water=n_w, n_diameters=41)
    eff = sphere_efficiencies(m, [np.pi * d * n_w / (lam * 1e-9)])
    assert iops.scattering[0] == pytest.approx(3 * eff.q_sca[0] / (2 * rho * 1e3 * d), rel=2e-3)
    assert iops.absorption[0] == pytest.approx(3 * eff.q_abs[0] / (2 * rho * 1e3 * d), rel=2e-3)


@pytest.fixture(scope="module")
def marine_mineral():
    """Typical marine mineral (m = 1.17, Junge ξ = 4, 0.2-100 µm) at 443 and 555 nm."""
    return mass_specific_iops([443.0, 555.0], 1.17 + 0.001j, JungePSD(4.0, 0.2e-6, 100e-6), 2650.0, n_diameters=60)


def test_mineral_backscattering_ratio_in_published_range(marine_mineral):
    # Twardowski et al. (2001) JGR 106:14129: b_bp/b_p ≈ 0.01-0.03 for mineral-rich particles with ξ ≈ 4.
    assert np.all((marine_mineral.backscattering_ratio > 0.01) & (marine_mineral.backscattering_ratio < 0.03))
    # Babin et al. (2003) L&O 48:843: b*_p(555) ≈ 0.5 m² g⁻¹ in coastal waters.
    assert 0.3 < marine_mineral.scattering[1] < 0.7


def test_phase_function_is_normalised_and_consistent(marine_mineral):
    mu = np.cos(np.radians(marine_mineral.angles_deg))
    for p, bb_ratio, g in zip(marine_mineral.phase_function, marine_mineral.backscattering_ratio, marine_mineral.asymmetry):
        assert -2 * np.pi * np.trapezoid(p, mu) == pytest.approx(1.0, abs=0.02)
        back = marine_mineral.angles_deg >= 90
        assert -2 * np.pi * np.trapezoid(p[back], mu[back]) == pytest.approx(bb_ratio, rel=0.05)
        assert 0.8 < g < 0.95


def test_mass_specific_values_scale_with_inverse_density():
    kw = dict(psd=JungePSD(4.0, 0.5e-6, 20e-6), n_diameters=30)
    light = mass_specific_iops([550.0], 1.15 + 0.001j, density_kg_m3=1000.0, **kw)
    heavy = mass_specific_iops([550.0], 1.15 + 0.001j, density_kg_m3=2000.0, **kw)
    assert light.scattering[0] == pytest.approx(2 * heavy.scattering[0], rel=ROUNDOFF)
    assert light.absorption[0] == pytest.approx(2 * heavy.absorption[0], rel=ROUNDOFF)


def test_non_absorbing_particles_do_not_absorb():
    iops = mass_specific_iops([500.0], 1.2 + 0j, JungePSD(4.0, 0.5e-6, 10e-6), 2650.0, n_diameters=20)
    assert abs(iops.absorption[0]) < 1e-9 * iops.scattering[0]  # Q_ext − Q_sca: cancellation residual


def test_callable_index_and_bad_inputs():
    psd = JungePSD(4.0, 0.5e-6, 5e-6)
    iops = mass_specific_iops([450.0, 650.0], lambda wl: 1.15 + 1e-3j * (450.0 / wl), psd, 2650.0, n_diameters=15)
    assert iops.absorption[0] > iops.absorption[1]
    with pytest.raises(ValueError, match="m_particle"):
        mass_specific_iops([500.0], 1.2 - 0.01j, psd, 2650.0)
    with pytest.raises(ValueError, match="density_kg_m3"):
        mass_specific_iops([500.0], 1.2, psd, -1.0)
    with pytest.raises(ValueError, match="d_min_m < d_max_m"):
        JungePSD(4.0, 10e-6, 1e-6)
    with pytest.raises(ValueError, match="geometric_sd"):
        LogNormalPSD(1e-6, 0.9)
