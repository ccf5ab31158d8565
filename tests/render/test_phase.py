"""The water's spectral phase function (oceanrender.render.phase): b_b/b of the render at every λ, exact sampling."""

import math

import numpy as np
import pytest

from oceanrender.optics.components import (
    PRESETS,
    WaterComposition,
    composition_iops,
    composition_optics,
    henyey_greenstein_bb_ratio,
)
from oceanrender.render.scene import water_medium

#: Wavelengths of the checks [nm]: 360–830 every 10 nm, plus points between the 5 nm nodes of the medium's spectra.
CHECK_NM = np.concatenate([np.arange(360.0, 831.0, 10.0), [402.5, 441.3, 517.7, 688.8, 827.5]])


def _load_phase(optics):
    import mitsuba as mi

    from oceanrender.render.phase import register

    register()
    return mi.load_dict(water_medium(optics)["phase"])


def _medium_interaction(n, wavelengths):
    import drjit as dr
    import mitsuba as mi

    mei = dr.zeros(mi.MediumInteraction3f, n)
    mei.wi = mi.Vector3f(0.0, 0.0, 1.0)  # propagation along −z: μ = −wo_z
    mei.wavelengths = mi.UnpolarizedSpectrum(*[float(w) for w in wavelengths])
    return mei


def _backscatter_ratio(phase, wavelengths, nodes=400):
    """2π ∫_{−1}^{0} p_λ(μ) dμ per wavelength, by Gauss–Legendre on the backward hemisphere (p is smooth there)."""
    import mitsuba as mi

    x, wq = np.polynomial.legendre.leggauss(nodes)
    mu = 0.5 * (x - 1.0)  # [−1, 0]
    out = []
    for start in range(0, len(wavelengths), 4):
        chunk = list(wavelengths[start:start + 4])
        chunk += [chunk[-1]] * (4 - len(chunk))
        mei = _medium_interaction(nodes, chunk)
        wo = mi.Vector3f(np.sqrt(1.0 - mu**2), 0.0, -mu)  # forward cosine μ = dot(wo, −wi)
        value, _ = phase.eval_pdf(mi.PhaseFunctionContext(None), mei, wo)
        value = np.array(value)  # (4, nodes)
        out.extend((2.0 * math.pi * 0.5 * value @ wq)[: len(wavelengths[start:start + 4])])
    return np.array(out)


def _sample_consistently(phase, wavelengths, n, seed):
    """n samples of ``phase``: (directions, weights (4, n)), after asserting pdf(sample) = eval_pdf and weight = p_λ/p̄.

    Both to 1e-5 relative: the same float32 expressions evaluated twice.
    """
    import mitsuba as mi

    mei = _medium_interaction(n, wavelengths)
    sampler = mi.load_dict({"type": "independent"})
    sampler.seed(seed, n)
    ctx = mi.PhaseFunctionContext(None)
    wo, weight, pdf = phase.sample(ctx, mei, sampler.next_1d(), sampler.next_2d())
    value, pdf_eval = phase.eval_pdf(ctx, mei, wo)
    np.testing.assert_allclose(np.array(pdf), np.array(pdf_eval), rtol=1e-5)
    np.testing.assert_allclose(np.array(weight), np.array(value) / np.array(pdf)[None, :], rtol=1e-5)
    return wo, np.array(weight)


@pytest.mark.parametrize("name", ["Chl 0.03", *PRESETS])
def test_rendered_backscatter_ratio_equals_the_compositions_at_every_wavelength(variant, name):
    """Issue 19 item 1: b_b/b of the medium's phase function = the composition's, 360–830 nm, within 1 %.

    The old fixed 550 nm blend was 42 % low at 440 nm for Chl 0.03 mg m⁻³ (asserted below
    as the regression's size). Here the only differences are the linear interpolation of w
    and g between the 5 nm nodes and the float32 of Mitsuba's spectra (≤ 0.1 % measured);
    the quadrature is exact to ~1e-10 on this smooth hemisphere. 1 % is the issue's bound.
    """
    composition = WaterComposition(chlorophyll_mg_m3=0.03) if name == "Chl 0.03" else PRESETS[name]
    optics = composition_optics(composition)
    iops = composition_iops(composition, CHECK_NM)
    expected = iops.backscattering / iops.scattering
    rendered = _backscatter_ratio(_load_phase(optics), CHECK_NM)
    np.testing.assert_allclose(rendered, expected, rtol=0.01)
    if name == "Chl 0.03":  # the 550 nm blend of before, at 440 nm
        k = int(np.argmin(np.abs(CHECK_NM - 440.0)))
        old = (1 - optics.particle_fraction) * 0.5 + optics.particle_fraction * henyey_greenstein_bb_ratio(
            optics.particle_g)
        assert old < 0.7 * expected[k]


def test_sampling_is_exact(variant):
    """Sampled directions have the density eval_pdf reports, and the weights reproduce p_λ/p̄ (MC check).

    Over N = 2e5 samples the Monte Carlo estimate of the backscattered fraction per
    wavelength, mean(weight · [μ < 0]), has a standard error ≤ 0.002 (weights ≤ 4,
    fractions ~0.01–0.5): asserted within 5 standard errors of the quadrature. The pdf
    returned by sample() equals eval_pdf's at the sampled direction to float32 rounding.
    """
    import drjit as dr

    optics = composition_optics(PRESETS["green coastal"])
    phase = _load_phase(optics)
    n = 200_000
    wavelengths = [400.0, 480.0, 600.0, 700.0]
    wo, weights = _sample_consistently(phase, wavelengths, n, seed=7)
    mu = -np.array(wo.z)
    estimate = (weights * (mu < 0)[None, :]).mean(axis=1)
    error = (weights * (mu < 0)[None, :]).std(axis=1) / math.sqrt(n)
    exact = _backscatter_ratio(phase, wavelengths)
    assert np.all(np.abs(estimate - exact) < 5 * error + 1e-6)
    np.testing.assert_allclose(np.array(dr.norm(wo)), 1.0, atol=1e-5)
    # mean cosine of (1): Rayleigh's is 0, HG's is g, so ⟨μ⟩ = w g per wavelength (same 5σ bound)
    wl = optics.iops.wavelengths
    w = np.interp(wavelengths, wl, optics.particle_fraction_spectrum)
    g = np.interp(wavelengths, wl, optics.particle_g_spectrum)
    mean_mu = (weights * mu[None, :]).mean(axis=1)
    error_mu = (weights * mu[None, :]).std(axis=1) / math.sqrt(n)
    assert np.all(np.abs(mean_mu - w * g) < 5 * error_mu + 1e-4)


def test_pure_water_keeps_mitsubas_rayleigh():
    """No particles: Mitsuba's own ``rayleigh`` (b_b/b = ½ at every wavelength), no plugin."""
    optics = composition_optics(WaterComposition())
    assert water_medium(optics)["phase"] == {"type": "rayleigh"}


def _tabulated(name, particle_phase="Fournier-Forand"):
    optics = composition_optics(PRESETS[name], particle_phase=particle_phase)
    medium = water_medium(optics)
    assert medium["phase"]["type"] == "oceanrender_tabulated_phase"
    import mitsuba as mi

    from oceanrender.render.phase import register_tabulated

    register_tabulated()
    return optics, mi.load_dict(medium["phase"])


@pytest.mark.parametrize("name", list(PRESETS))
def test_fournier_forand_table_keeps_the_compositions_backscatter_ratio(variant, name):
    """Issue 19 item 2: the tabulated water + Fournier–Forand mixture has the composition's b_b/b, within 1 %.

    Differences: the table's nearest 5 nm row (checked at the nodes here), the piecewise-linear
    forward peak cut at 1e-5° (its normalisation moves b_b/b by < 0.2 %, measured), float32.
    """
    optics, phase = _tabulated(name)
    nodes = np.arange(360.0, 831.0, 10.0)
    iops = composition_iops(PRESETS[name], nodes)
    np.testing.assert_allclose(_backscatter_ratio(phase, nodes), iops.backscattering / iops.scattering, rtol=0.01)


def test_fournier_forand_table_is_sampled_exactly(variant):
    """As test_sampling_is_exact, for the table: pdf(sample) = eval_pdf, weights p_λ/p̄, b_b/b within 5σ."""
    optics, phase = _tabulated("green coastal")
    n = 200_000
    wavelengths = [400.0, 480.0, 600.0, 700.0]
    wo, weights = _sample_consistently(phase, wavelengths, n, seed=11)
    back = (-np.array(wo.z) < 0)[None, :]
    estimate = (weights * back).mean(axis=1)
    error = (weights * back).std(axis=1) / math.sqrt(n)
    exact = _backscatter_ratio(phase, wavelengths)
    assert np.all(np.abs(estimate - exact) < 5 * error + 1e-6)


def test_particle_phase_is_a_scene_key():
    from oceanrender.optics.scene_water import water_optics
    from tests.scenes import scene_from_dict

    scene = scene_from_dict({"name": "ff", "composition": {"preset": "green coastal", "particle_phase": "Fournier-Forand"}})
    assert water_optics(scene).phase_table is not None
    default = scene_from_dict({"name": "hg", "composition": {"preset": "green coastal"}})
    assert water_optics(default).phase_table is None
    with pytest.raises(ValueError, match="Henyey-Greenstein"):
        composition_optics(PRESETS["green coastal"], particle_phase="Kopelevich")


def _back_fraction(mu, p):
    """b_b/b of a table piecewise linear in μ, split exactly at μ = 0 (a node put there by linear interpolation)."""
    j = np.searchsorted(mu, 0.0)
    p0 = p[j - 1] + (p[j] - p[j - 1]) * (0.0 - mu[j - 1]) / (mu[j] - mu[j - 1])
    return np.trapezoid(np.append(p[:j], p0), np.append(mu[:j], 0.0)) / np.trapezoid(p, mu)


def test_petzold_particles_backscatter_as_petzold_measured():
    """Issue 19 item 2: the Petzold particle phase function's b_b/b is that of the report's three San
    Diego Harbor stations, 0.019, 0.018, 0.020 (printed to two digits): mean 0.019 within 0.001."""
    from oceanrender.optics.components import _tabulate, petzold_particle_phase

    mu, p = _tabulate(petzold_particle_phase)
    assert abs(_back_fraction(mu, p) - 0.019) <= 0.001
    assert 2 * math.pi * np.trapezoid(p, mu) == pytest.approx(1.0, rel=1e-3)  # normalised on the table


def test_petzold_table_renders_the_mixtures_backscatter_ratio(variant):
    """The loaded plugin's b_b/b equals the water + Petzold mixture's own, (b_w/2 + b_p B_P)/b, within 1 %."""
    from oceanrender.optics.components import _tabulate, petzold_particle_phase

    optics, phase = _tabulated("green coastal", "Petzold")
    B_p = _back_fraction(*_tabulate(petzold_particle_phase))
    nodes = np.arange(400.0, 701.0, 50.0)
    iops = composition_iops(PRESETS["green coastal"], nodes)
    b_w = iops.components["water"].scattering
    expected = (0.5 * b_w + B_p * (iops.scattering - b_w)) / iops.scattering
    np.testing.assert_allclose(_backscatter_ratio(phase, nodes), expected, rtol=0.01)
