"""Command-line interface: parse, validate everything, call a stage, report.

User errors (bad scene file, bad option, unusable variant) end with one line
on stderr and exit code 2; no traceback.
"""

from __future__ import annotations

import argparse
import sys
import time
import warnings
from pathlib import Path

from . import __version__
from .config import Scene, SceneError, load_scene, with_overrides


class UserError(Exception):
    """An error the user can fix; printed as one line."""


def _frame_range(text: str) -> tuple[int, int]:
    try:
        start, end = (int(part) for part in text.split(":"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected START:END (e.g. 0:3), got {text!r}") from None
    return start, end


def _resolution(text: str) -> tuple[int, int]:
    try:
        width, height = (int(part) for part in text.lower().split("x"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected WIDTHxHEIGHT (e.g. 320x180), got {text!r}") from None
    return width, height


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="oceanrender", description="Physically based spectral renderer for the sea.")
    parser.add_argument("--version", action="version", version=f"oceanrender {__version__}")
    commands = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")

    render = commands.add_parser("render", help="render a scene's image sequence (EXR + PNG per frame)",
                                 description="Render frames of SCENE into OUT/<scene name>/frame_NNNN.{exr,png}; "
                                             "frames already written intact are skipped (resume).")
    render.add_argument("scene", type=Path, help="scene file (TOML), e.g. scenes/open_ocean.toml")
    render.add_argument("--frames", type=_frame_range, metavar="A:B", help="half-open frame range (default: the scene's)")
    render.add_argument("--spp", type=int, metavar="N", help="samples per pixel (default: the scene's)")
    render.add_argument("--resolution", type=_resolution, metavar="WxH", help="image size in pixels")
    render.add_argument("--out", type=Path, metavar="DIR", help="output root (default: the scene's, 'outputs')")
    render.add_argument("--variant", metavar="V", help="Mitsuba variant: 'auto' or e.g. llvm_ad_spectral")
    render.add_argument("--no-progress", action="store_true", help="no progress bar")

    geometry = commands.add_parser(
        "geometry", help="export the FFT sea's per-frame maps (EXR) and meshes (PLY)",
        description="Write, per frame and per cascade, float32 EXR maps (height, displacement, normal, Jacobian) "
                    "in Blender's baked-ocean layout, with metadata and a geometry.json sidecar, into "
                    "OUT/cascade_I/; with --ply also the closed water-body mesh of each patch.")
    geometry.add_argument("scene", type=Path, help="scene file (TOML)")
    geometry.add_argument("--frames", type=_frame_range, metavar="A:B", help="half-open frame range (default: the scene's)")
    geometry.add_argument("--out", type=Path, metavar="DIR", required=True, help="export folder")
    geometry.add_argument("--ply", action="store_true", help="also write mesh_NNNN.ply per frame")

    optics = commands.add_parser(
        "optics", help="the water's IOPs and four-flux light field: CSV, JSON and plots",
        description="Write a, b, b_b, c, K_d, R(0-) per wavelength (optics.csv), the irradiance profiles "
                    "E_d(z), E_u(z) (lightfield.json) and plots (iops.png, lightfield.png) for the scene's "
                    "water under its sun and sky.")
    optics.add_argument("scene", type=Path, help="scene file (TOML)")
    optics.add_argument("--out", type=Path, metavar="DIR", required=True, help="report folder")
    optics.add_argument("--variant", metavar="V", help="Mitsuba variant for the sky irradiance ('auto' by default)")

    coastal = commands.add_parser(
        "coastal", help="run a scene's shallow-water simulation alone: per-frame fields as .npz and EXR",
        description="Simulate the scene's [coastal] zone up to its last frame and write, per frame, "
                    "OUT/frame_NNNN.npz (h, hu, hv, bed, t and the grid, float64) and OUT/frame_NNNN.exr "
                    "(h, eta, u, v, bed, float32, with metadata); resumes from OUT/checkpoint.npz. "
                    "`oceanrender render` runs the same simulation into OUT/<scene>/coastal/ by itself.")
    coastal.add_argument("scene", type=Path, help="scene file (TOML) with a [coastal] section")
    coastal.add_argument("--frames", type=_frame_range, metavar="A:B", help="half-open frame range (default: the scene's)")
    coastal.add_argument("--out", type=Path, metavar="DIR", required=True, help="fields folder")
    coastal.add_argument("--no-progress", action="store_true", help="no progress bar")

    commands.add_parser("info", help="versions, usable Mitsuba variants and the LLVM library",
                        description="Report versions and probe which Mitsuba spectral variants work here.")
    return parser


def scene_with_cli_overrides(scene: Scene, args: argparse.Namespace) -> Scene:
    """Apply --frames/--spp/--resolution/--out/--variant, validated like the file."""
    output = {}
    if args.frames is not None:
        output["frames"] = args.frames
    if args.spp is not None:
        output["spp"] = args.spp
    if args.resolution is not None:
        output["resolution"] = args.resolution
    if args.out is not None:
        output["directory"] = str(args.out)
    render = {"variant": args.variant} if args.variant else {}
    return with_overrides(scene, "command line", output=output, render=render)


def check_resources(scene: Scene, source: str) -> None:
    """Load the data the scene names, so a bad table fails before any work."""
    from .optics.tables import SpectralDataError  # noqa: PLC0415
    from .optics.water import pure_seawater_iops  # noqa: PLC0415

    try:
        pure_seawater_iops(scene.water.iop_table)
    except SpectralDataError as exc:
        raise UserError(f"{source}: [water] iop_table: {exc}") from None
    from .pipeline import water_composition  # noqa: PLC0415

    try:
        water_composition(scene)
    except ValueError as exc:
        raise UserError(f"{source}: [composition]: {exc}") from None


def activate(requested: str):
    from .runtime.variants import VariantError, activate_variant  # noqa: PLC0415

    try:
        return activate_variant(requested)
    except VariantError as exc:
        raise UserError(str(exc)) from None


def cmd_render(args: argparse.Namespace) -> int:
    scene = load_scene(args.scene)
    scene = scene_with_cli_overrides(scene, args)
    check_resources(scene, str(args.scene))
    runtime = activate(scene.render.variant)
    out_dir = Path(scene.output.directory) / scene.name
    start, end = scene.output.frames
    width, height = scene.output.resolution
    print(f"oceanrender {__version__}: {scene.name}, frames {start}:{end}, {width}x{height}, "
          f"{scene.output.spp} spp, variant {runtime.variant}"
          + (f" (LLVM {runtime.llvm_library})" if runtime.llvm_library else "") + f" -> {out_dir}", flush=True)

    from tqdm import tqdm  # noqa: PLC0415

    from .pipeline import render_sequence  # noqa: PLC0415

    bar = tqdm(total=end - start, unit="frame", disable=args.no_progress, dynamic_ncols=True)

    def on_frame(frame: int, seconds: float, skipped: bool) -> None:
        bar.set_postfix_str(f"frame {frame}: " + ("exists, skipped" if skipped else f"{seconds:.1f} s"))
        bar.update(1)

    tic = time.perf_counter()
    with bar:
        report = render_sequence(scene, out_dir, runtime.variant, on_frame=on_frame)
    total = time.perf_counter() - tic
    stages = ", ".join(f"{k} {v:.2f} s" for k, v in report.stage_seconds.items())
    print(f"rendered {len(report.rendered)} frame(s), skipped {len(report.skipped)} already complete, "
          f"in {total:.1f} s (setup {report.setup_seconds:.1f} s; {stages})")
    if report.repaired_pixels:
        print(f"warning: {report.repaired_pixels} non-finite pixel(s) repaired from their neighbours", file=sys.stderr)
    return 0


def cmd_info(_: argparse.Namespace) -> int:
    import colour  # noqa: PLC0415
    import drjit  # noqa: PLC0415
    import mitsuba as mi  # noqa: PLC0415
    import numpy  # noqa: PLC0415

    from .runtime.variants import SPECTRAL_VARIANTS, cuda_driver_present, find_llvm_library, probe_variant  # noqa: PLC0415

    print(f"oceanrender {__version__}")
    print(f"python {sys.version.split()[0]}, numpy {numpy.__version__}, mitsuba {mi.__version__}, "
          f"drjit {drjit.__version__}, colour-science {colour.__version__}")
    llvm = find_llvm_library()
    print(f"libLLVM for drjit: {llvm or 'none found (apt-get install libllvm19)'}")
    for variant in SPECTRAL_VARIANTS:
        if variant.startswith("cuda") and not cuda_driver_present():
            verdict = "no NVIDIA driver (libcuda) found"
        elif variant.startswith("llvm") and llvm is None:
            verdict = "no usable libLLVM"
        else:
            verdict = probe_variant(variant, llvm)
        print(f"  {variant:18s} {'works' if verdict == 'ok' else 'unusable: ' + verdict}")
    return 0


def cmd_geometry(args: argparse.Namespace) -> int:
    scene = load_scene(args.scene)
    if args.frames is not None:
        scene = with_overrides(scene, "command line", output={"frames": args.frames})
    if scene.ocean.model != "FFT":
        raise UserError(f"{args.scene}: [ocean] model: geometry export needs 'FFT', got {scene.ocean.model!r}")
    from .geometry.sea import SeaSurface  # noqa: PLC0415
    from .io.geometry_export import export_geometry_sequence  # noqa: PLC0415

    sea = SeaSurface(scene.ocean)
    start, end = scene.output.frames
    times = {frame: frame / scene.output.fps for frame in range(start, end)}
    written = 0
    for index, patch in enumerate(sea.cascades.cascades):
        folder = args.out / f"cascade_{index}"
        written += len(export_geometry_sequence(folder, patch, times,
                                                mesh_depth=scene.water.depth if args.ply else None))
        print(f"cascade {index}: patch {patch.grid.patch_size:g} m, {patch.grid.resolution}² -> {folder}")
    print(f"wrote {written} file(s) for frames {start}:{end}")
    return 0


def cmd_coastal(args: argparse.Namespace) -> int:
    scene = load_scene(args.scene)
    if args.frames is not None:
        scene = with_overrides(scene, "command line", output={"frames": args.frames})
    if scene.coastal is None:
        raise UserError(f"{args.scene}: [coastal]: the scene has no coastal section to simulate")
    from tqdm import tqdm  # noqa: PLC0415

    from .coastal.simulation import run_simulation  # noqa: PLC0415

    start, end = scene.output.frames
    c = scene.coastal
    print(f"oceanrender {__version__}: {scene.name}, shallow water {c.cells[0]}x{c.cells[1]} cells, order {c.order}, "
          f"frames {start}:{end} after {c.spinup:g} s spin-up -> {args.out}", flush=True)
    bar = tqdm(total=1.0, unit="sim", disable=args.no_progress, dynamic_ncols=True,
               bar_format="{l_bar}{bar}| {postfix}")

    def on_progress(t: float, t_end: float) -> None:
        bar.n = min(t / t_end, 1.0) if t_end > 0 else 1.0
        bar.set_postfix_str(f"τ = {t:.2f} / {t_end:.2f} s")

    with bar:
        report = run_simulation(scene, args.out, on_progress=on_progress)
    rate = report.cell_updates / report.seconds / 1e6 if report.seconds > 0 else 0.0
    resumed = f", resumed at τ = {report.resumed_from:.2f} s" if report.resumed_from is not None else ""
    print(f"simulated {len(report.simulated)} frame(s), {len(report.found)} already stored{resumed}, "
          f"in {report.seconds:.1f} s ({rate:.1f} million cell-updates/s)")
    return 0


def cmd_optics(args: argparse.Namespace) -> int:
    import numpy as np  # noqa: PLC0415

    scene = load_scene(args.scene)
    check_resources(scene, str(args.scene))
    runtime = activate(args.variant or scene.render.variant)
    from .io.optics_report import write_optics_report  # noqa: PLC0415
    from .optics.report import REPORT_WAVELENGTHS, scene_optics, sky_irradiance_spectra  # noqa: PLC0415
    from .optics.water import pure_seawater_iops  # noqa: PLC0415
    from .pipeline import water_composition  # noqa: PLC0415

    wavelengths = REPORT_WAVELENGTHS
    composition = water_composition(scene)
    if scene.water.jerlov_type is not None:
        from .optics.jerlov_types import iops_WilliamsonHollins2022  # noqa: PLC0415

        a, b, bb = iops_WilliamsonHollins2022(scene.water.jerlov_type, wavelengths)
    elif composition is None:
        iops = pure_seawater_iops(scene.water.iop_table)
        a = np.interp(wavelengths, iops.wavelengths, iops.absorption)
        b = np.interp(wavelengths, iops.wavelengths, iops.scattering)
        bb = b / 2  # pure water's VSF is symmetric about 90° (Morel 1974)
    else:
        from .optics.components import composition_iops  # noqa: PLC0415

        result = composition_iops(composition, wavelengths)
        a, b, bb = result.absorption, result.scattering, result.backscattering
    direct, diffuse = sky_irradiance_spectra(scene.sun, wavelengths, spp=scene.render.white_spp)
    depth = scene.water.depth
    z = np.linspace(0.0, min(depth, 100.0), 101)
    report = scene_optics(a, b, bb, direct, diffuse, 90.0 - scene.sun.elevation, depth, z, n_water=scene.water.ior)
    metadata = {"scene": scene.name, "variant": runtime.variant, "oceanrender_version": __version__,
                "composition": None if composition is None else composition.__dict__,
                "jerlov_type": scene.water.jerlov_type,
                "bottom": "none (albedo 0): the rendered water body ends in a transparent bottom"}
    written = write_optics_report(args.out, report, metadata)
    i = int(np.argmin(np.abs(wavelengths - 550.0)))
    print(f"{scene.name}: a(550) {a[i]:.4g} m⁻¹, b(550) {b[i]:.4g} m⁻¹, K_d(550) {report.light.K_d[i]:.4g} m⁻¹, "
          f"R(0⁻, 550) {report.light.R[i]:.4g}; wrote {', '.join(p.name for p in written)} to {args.out}")
    return 0


COMMANDS = {"render": cmd_render, "geometry": cmd_geometry, "coastal": cmd_coastal, "optics": cmd_optics,
            "info": cmd_info}


def main(argv: list[str] | None = None) -> int:
    warnings.filterwarnings("ignore", message=".*Matplotlib.*")
    args = build_parser().parse_args(argv)
    try:
        return COMMANDS[args.command](args)
    except (SceneError, UserError) as exc:
        print(f"oceanrender: error: {exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("oceanrender: interrupted; finished frames are kept, rerun to resume", file=sys.stderr)
        return 130


if __name__ == "__main__":
    sys.exit(main())
