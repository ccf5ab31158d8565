"""The four-flux model against the Mitsuba Monte Carlo slabs of ``scripts/fourflux_slab_mc.py``.

For every cell of ``docs/data/fourflux_slab_mc.json`` (issue 19, item 3) it compares, with
the Monte Carlo numbers alone as the reference:

* K_d over the first optical depth: 1/z₁ with ln E_d(z₁) = ln E_d(0) − 1, from a quadratic in z
  through ln E_d at the three metered depths around z₁;
* K_d over 0–10 m: −ln(E_d(10 m)/E_d(0))/10 m;
* R(0⁻) = E_u(0⁻)/E_d(0⁻);

for today's fixed closure (μ_d = 0.83, μ_u = 0.40, b_b for every stream, c = a + b with the
forward scattering feeding E_dif: how the LUTs and ``oceanrender optics`` called it), for the
coefficients from the phase function and the refracted sun (``oceanrender.optics.streams``),
and for the discrete-ordinate solution those coefficients are derived from. Both models are
run as the slab is set up: index-matched surface, beam only (n_water = 1 at the refracted angle).

Writes ``docs/data/fourflux_agreement.md`` (the table) and ``docs/images/fourflux_agreement.png``.
"""

from __future__ import annotations

import json
import math
import pathlib
import sys

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))


def compare(record) -> dict:
    """Monte Carlo, old, new and discrete-ordinate K_1, K_10, R of one cell."""
    from oceanrender.optics.components import tabulated_fournier_forand
    from oceanrender.optics.fourflux import four_flux
    from oceanrender.optics.streams import deep_layer, first_optical_depth, legendre_moments, stream_coefficients
    from oceanrender.render.slab import first_optical_depth_K

    a, b, bb, theta = record["a_per_m"], record["b_per_m"], record["bb_per_m"], record["zenith_in_water_deg"]
    z = np.array(record["z_m"])
    E = np.array(record["E_d"])
    E0 = record["E_d0"]
    mc = {"K1": first_optical_depth_K(z[:3], E[:3], E0), "K10": -math.log(E[3] / E0) / z[3], "R": record["E_u0"] / E0}
    mu, p = tabulated_fournier_forand(record["bb_over_b"])
    mu_w = math.cos(math.radians(theta))
    out = {"mc": mc}
    for name, co in (("old", None), ("new", stream_coefficients([a], [b], mu, p[None], mu_w))):
        m = four_flux([a], [bb], 1.0, 0.0, theta, np.inf, 0.0, [0.0, z[3]], b=[b], n_water=1.0, coefficients=co)
        out[name] = {"K1": float(m.K_d[0]), "K10": float(-np.log(m.E_d[0, 1] / m.E_d[0, 0]) / z[3]), "R": float(m.R[0])}
    layer = deep_layer(a, b, legendre_moments(mu, p, 65), mu_w)
    E10 = float(np.sum(layer.irradiances(z[3])[:2]))
    out["do"] = {"K1": 1.0 / first_optical_depth(layer), "K10": -math.log(E10 / mu_w) / z[3], "R": layer.E_u0 / mu_w}
    out["mc_rel_error"] = {"E_d": float(np.max(np.array(record["E_d_error"]) / E)),
                           "R": record["E_u0_error"] / record["E_u0"]}
    return out


def main() -> int:
    data = json.loads((ROOT / "docs" / "data" / "fourflux_slab_mc.json").read_text())
    rows, errors = [], {m: {q: [] for q in ("K1", "K10", "R")} for m in ("old", "new", "do")}
    lines = ["| b_b/a | ω₀ | b_b/b | sun (air) | K_d z₁ MC [m⁻¹] | today | new | K_d 0–10 m MC | today | new "
             "| R(0⁻) MC | today | new | DO: K z₁ / K 10 m / R | MC σ (E_d, R) |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for rec in data["records"]:
        c = compare(rec)
        rows.append((rec, c))
        for m in errors:
            for q in ("K1", "K10", "R"):
                errors[m][q].append(c[m][q] / c["mc"][q] - 1.0)
        e = {m: {q: 100 * (c[m][q] / c["mc"][q] - 1.0) for q in ("K1", "K10", "R")} for m in errors}
        lines.append(
            f"| {rec['bb_over_a']:g} | {rec['albedo']:g} | {rec['bb_over_b']:.2g} | {rec['sun_zenith_deg']:.0f}° "
            f"| {c['mc']['K1']:.4g} | {e['old']['K1']:+.1f} % | {e['new']['K1']:+.1f} % "
            f"| {c['mc']['K10']:.4g} | {e['old']['K10']:+.1f} % | {e['new']['K10']:+.1f} % "
            f"| {c['mc']['R']:.4g} | {e['old']['R']:+.1f} % | {e['new']['R']:+.1f} % "
            f"| {e['do']['K1']:+.1f} / {e['do']['K10']:+.1f} / {e['do']['R']:+.1f} % "
            f"| {100 * c['mc_rel_error']['E_d']:.2f} / {100 * c['mc_rel_error']['R']:.2f} % |")
    summary = ["", "| largest |error| over the grid | K_d first optical depth | K_d 0–10 m | R(0⁻) |", "|---|---|---|---|"]
    for m, label in (("old", "today's fixed closure"), ("new", "coefficients from the phase function"),
                     ("do", "discrete ordinates (what they are derived from)")):
        summary.append(f"| {label} | " + " | ".join(f"{100 * np.max(np.abs(errors[m][q])):.1f} %"
                                                    for q in ("K1", "K10", "R")) + " |")
    meta = data["meta"]
    text = "\n".join([f"Monte Carlo: {meta['generator']} ({meta['variant']}, {meta['spp_per_pass']} paths × "
                      f"{meta['passes']} passes per depth, {meta['spp_per_pass_E_u']} for E_u; {meta['date']}, "
                      f"{meta['seconds']} s).{' ' + meta['recheck'] + '.' if 'recheck' in meta else ''} "
                      "Errors: model/MC − 1.", ""]
                     + lines + summary) + "\n"
    (ROOT / "docs" / "data" / "fourflux_agreement.md").write_text(text)
    print(text)
    plot(rows, ROOT / "docs" / "images" / "fourflux_agreement.png")
    return 0


def plot(rows, path: pathlib.Path) -> None:
    """Model/MC − 1 for each quantity, today's closure and the new coefficients, against b_b/b."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 3, figsize=(13, 4), sharey=True)
    labels = {"K1": "K_d, first optical depth", "K10": "K_d, 0–10 m", "R": "R(0⁻)"}
    for ax, q in zip(axes, ("K1", "K10", "R")):
        for m, style in (("old", dict(marker="o", color="tab:red", label="today: fixed closure")),
                         ("new", dict(marker="s", color="tab:blue", label="from the phase function"))):
            # the three sun angles side by side around each b_b/b (0°, 30°, 60°: ×0.9, ×1, ×1.1)
            x = [rec["bb_over_b"] * (1.0 + rec["sun_zenith_deg"] / 300.0 - 0.1) for rec, _ in rows]
            y = [100 * (c[m][q] / c["mc"][q] - 1.0) for _, c in rows]
            ax.scatter(x, y, s=18, alpha=0.8, **style)
        ax.axhspan(-5, 5, color="0.9", zorder=0, label="±5 % (goal)")
        ax.axhline(0, color="0.4", lw=0.8)
        ax.set_xscale("log")
        ax.set_xlabel("b_b/b (Fournier–Forand); sun 0°, 30°, 60° left to right", fontsize=9)
        ax.set_title(labels[q])
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("model / Mitsuba Monte Carlo − 1 [%]")
    axes[0].legend(fontsize=8, loc="lower left")
    fig.suptitle("Four-flux model vs Mitsuba slab, a = 0.1 m⁻¹, b_b/a 0.001–1, ω₀ 0.1–0.95, sun 0–60°")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


if __name__ == "__main__":
    raise SystemExit(main())
