"""Bore fronts of the three coastal schemes side by side (issue 44, item 4): docs/images/dg_bore_fronts.png.

Top row: the surface elevation η = z_b + h [m] of ``scenes/coastal_beach.toml`` at frame 0 (τ = 20 s after
the swell started), simulated by first order (kinetic FVS), MUSCL–Hancock ("kinetic split", order 2, MC) and
the DG scheme (P1, minmod), the same grid (320 × 240, 12.5 cm) and incident waves; then a cross-shore
transect through all three. Bottom: a bore of 2 m running into 1 m of still water (30 m channel, 0.2 m
cells, t = 2.5 s) against the Rankine–Hugoniot solution (coastal/analytic.bore_jump), with each scheme's
front width (cells between 10 % and 90 % of the jump) and L1 error. Writes the figure and
docs/data/dg_bore_fronts.md.

Usage: ``.venv/bin/python scripts/dg_bore_fronts.py [--store DIR]`` (the DG beach simulation takes ~15 min on
2 cores; the stores under DIR are reused when their settings are unchanged).
"""

from __future__ import annotations

import argparse
import json
import pathlib
import sys

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

SCHEMES = {  # label: [coastal] overrides
    "first order (kinetic FVS)": {"order": 1, "scheme": "kinetic", "cfl": 0.9},
    "MUSCL-Hancock (kinetic split, MC)": {"order": 2, "scheme": "kinetic split", "limiter": "MC", "cfl": 0.9},
    "DG P1 (minmod)": {"order": 2, "scheme": "dg", "limiter": "minmod", "cfl": 0.3},
}


def beach_fields(store: pathlib.Path) -> dict[str, tuple[np.ndarray, np.ndarray, float]]:
    """Per scheme: (η where wet else NaN, bed, seconds) of the beach's frame 0."""
    from oceanrender.coastal.simulation import read_frame_fields, run_simulation
    from oceanrender.scene import with_overrides
    from oceanrender.scene.settings import load_scene

    base = load_scene(ROOT / "scenes" / "coastal_beach.toml")
    out = {}
    for i, (label, overrides) in enumerate(SCHEMES.items()):
        scene = with_overrides(base, coastal=overrides)
        folder = store / f"scheme{i}"
        report = run_simulation(scene, folder, frames=(0, 1), write_exr=False)
        timing = folder / "seconds.json"  # the simulation's own time, kept for reruns that find the frame
        if report.simulated:
            timing.write_text(json.dumps({"seconds": report.seconds}))
        seconds = json.loads(timing.read_text())["seconds"]
        fields = read_frame_fields(folder, 0)
        wet = fields["h"] > scene.coastal.h_min
        out[label] = (np.where(wet, fields["bed"] + fields["h"], np.nan), fields["bed"], seconds)
        print(f"{label}: {out[label][2]:.1f} s", flush=True)
    return out


def bore_profiles(n: int = 150, length: float = 30.0, t_end: float = 2.5):
    """x [m], exact h, and per scheme the depth after t_end of a 2 m bore into 1 m still water."""
    from oceanrender.coastal.analytic import bore_jump
    from oceanrender.coastal.boundaries import Boundaries, Transmissive
    from oceanrender.coastal.dg import DGParams, DGSolver1D, DGState
    from oceanrender.coastal.swe import ShallowWaterSolver, SolverParams, State

    jump = bore_jump(1.0, 0.0, 2.0)
    dx = length / n
    x = (np.arange(n) + 0.5) * dx
    behind = x < 10.0
    h = np.where(behind, 2.0, 1.0)
    q = np.where(behind, 2.0 * jump.u_behind, 0.0)
    front = 10.0 + jump.speed * t_end
    nodes, weights = np.polynomial.legendre.leggauss(8)
    exact = sum(w * np.where(x + 0.5 * dx * s < front, 2.0, 1.0) for s, w in zip(nodes, weights)) / 2.0
    out = {}
    for label, overrides in SCHEMES.items():
        if overrides["scheme"] == "dg":
            state = DGState(h.copy(), np.zeros(n), q.copy(), np.zeros(n))
            DGSolver1D(np.zeros(n + 1), DGParams(dx=dx, limiter="minmod", cfl=0.3)).advance(state, t_end)
            out[label] = state.h0
        else:
            params = SolverParams(dx=dx, dy=dx, order=overrides["order"], scheme=overrides["scheme"],
                                  cfl=overrides["cfl"], h_min=1e-6,
                                  boundaries=Boundaries(west=Transmissive(), east=Transmissive()))
            state = State(np.tile(h, (3, 1)), np.tile(q, (3, 1)), np.zeros((3, n)))
            ShallowWaterSolver(np.zeros((3, n)), params).advance(state, t_end)
            out[label] = state.h[1]
    return x, exact, out, front, dx


def front_width(h: np.ndarray, dx: float) -> float:
    """Width [m] over which h falls from 90 % to 10 % of the way from 2 m to 1 m (the last such crossing)."""
    level = (h - 1.0) / 1.0
    above90 = np.nonzero(level > 0.9)[0]
    below10 = np.nonzero(level < 0.1)[0]
    start = above90[above90 < below10.max()].max()
    end = below10[below10 > start].min()
    return (end - start - 1) * dx


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--store", type=pathlib.Path, default=pathlib.Path("/tmp/dg_bore_fronts"))
    args = parser.parse_args()
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    beach = beach_fields(args.store)
    x, exact, profiles, front, dx = bore_profiles()
    fig = plt.figure(figsize=(13, 8.4), dpi=110)
    grid = fig.add_gridspec(3, 3, height_ratios=[1.25, 0.8, 0.9], hspace=0.45, wspace=0.12)
    eta_all = np.concatenate([np.ravel(v[0]) for v in beach.values()])
    lo, hi = np.nanpercentile(eta_all, [1, 99])
    extent = (-20.0, 20.0, -6.0, 24.0)
    for i, (label, (eta, bed, seconds)) in enumerate(beach.items()):
        ax = fig.add_subplot(grid[0, i])
        image = ax.imshow(eta, origin="lower", extent=extent, cmap="RdBu_r", vmin=lo, vmax=hi)
        ax.contour(np.linspace(-20, 20, bed.shape[1]), np.linspace(-6, 24, bed.shape[0]), bed, levels=[0.0],
                   colors="k", linewidths=0.6)
        ax.axvline(0.0, color="0.3", lw=0.6, ls=":")
        ax.set_title(f"{label}\nsimulated in {seconds:.0f} s", fontsize=9)
        ax.set_xlabel("x [m]")
        if i == 0:
            ax.set_ylabel("y [m] (sea to the north)")
    fig.colorbar(image, ax=fig.axes[:3], shrink=0.8, label="η [m] (wet cells)")
    ax = fig.add_subplot(grid[1, :])
    for label, (eta, bed, _) in beach.items():
        column = eta.shape[1] // 2
        y = np.linspace(-6, 24, eta.shape[0])
        ax.plot(y, eta[:, column], lw=1.0, label=label)
    ax.plot(y, bed[:, column], color="0.5", lw=0.8, label="bed")
    ax.set_xlim(-3, 24)
    ax.set_ylim(-0.35, 0.45)
    ax.set_xlabel("y [m] along the transect x = 0 (dotted above)")
    ax.set_ylabel("η [m]")
    ax.set_title("coastal_beach, frame 0: bores on the beach (cross-shore transect)", fontsize=9)
    ax.legend(fontsize=8, ncol=4, loc="upper left")
    ax = fig.add_subplot(grid[2, :])
    window = (x > front - 4.0) & (x < front + 2.0)
    ax.step(x[window], exact[window], where="mid", color="k", lw=1.4, label="exact (Rankine-Hugoniot)")
    rows = ["| scheme | front width 10–90 % [cells] | L1 of h over the channel [m²] |", "|---|---:|---:|"]
    for label, h in profiles.items():
        width = front_width(h, dx)
        l1 = float(np.abs(h - exact).sum() * dx)
        rows.append(f"| {label} | {width / dx:.0f} | {l1:.3e} |")
        ax.plot(x[window], h[window], marker=".", ms=3, lw=0.9, label=f"{label}: front {width / dx:.0f} cells")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("h [m]")
    ax.set_title("bore of 2 m into 1 m still water, 0.2 m cells, t = 2.5 s", fontsize=9)
    ax.legend(fontsize=8, loc="lower left")
    out = ROOT / "docs" / "images" / "dg_bore_fronts.png"
    fig.savefig(out, bbox_inches="tight")
    times = [f"| {label} | {seconds:.1f} |" for label, (_, _, seconds) in beach.items()]
    table = ("Bore of 2 m into 1 m still water, 150 cells of 0.2 m, t = 2.5 s (scripts/dg_bore_fronts.py)\n\n"
             + "\n".join(rows) + "\n\ncoastal_beach to frame 0 (τ = 20 s, 320 × 240 cells), wall time on this "
             "machine [s]:\n\n| scheme | seconds |\n|---|---:|\n" + "\n".join(times) + "\n")
    (ROOT / "docs" / "data" / "dg_bore_fronts.md").write_text(table)
    print(table)
    print(f"wrote {out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
