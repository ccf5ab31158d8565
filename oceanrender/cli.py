"""Command-line interface: parse, validate everything, call a stage, report.

User errors (bad scene file, bad option, unusable variant) end with one line
on stderr and exit code 2; no traceback.
"""

from __future__ import annotations

import argparse
import contextlib
import math
import sys
import time
import warnings
from pathlib import Path
from typing import Iterator

from . import __version__
from .io.messages import quoted
from .scene import Scene, SceneError, load_scene, with_overrides, with_view
from .surface.frame import FrameError


class UserError(Exception):
    """An error the user can fix; printed as one line."""


def _frame_range(text: str) -> tuple[int, int]:
    try:
        start, end = (int(part) for part in text.split(":"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected START:END (e.g. 0:3), got {quoted(text)}") from None
    return start, end


def _point(text: str) -> tuple[float, float]:
    try:
        x, y = (float(part) for part in text.split(","))
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected X,Y in metres (e.g. 10.5,-3), got {quoted(text)}") from None
    if not (math.isfinite(x) and math.isfinite(y)):
        raise argparse.ArgumentTypeError(f"expected finite X,Y in metres, got {quoted(text)}")
    return x, y


def _resolution(text: str) -> tuple[int, int]:
    try:
        width, height = (int(part) for part in text.lower().split("x"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected WIDTHxHEIGHT (e.g. 320x180), got {quoted(text)}") from None
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
    render.add_argument("--denoise", action="store_true", help="denoise each frame (Intel Open Image Denoise)")
    render.add_argument("--exposure", type=float, metavar="EV",
                        help="exposure compensation in EV, -10..10 (default: the scene's [vision] exposure)")
    render.add_argument("--view", metavar="NAME",
                        help="render from the scene's [camera.views.NAME] into OUT/<scene name>_NAME/")
    where = render.add_mutually_exclusive_group()
    where.add_argument("--workers", type=int, metavar="N",
                       help="render frames on a local Dask cluster of N worker processes")
    where.add_argument("--cluster", metavar="tcp://HOST:PORT",
                       help="render frames on the workers of a running Dask scheduler (see README)")
    render.add_argument("--no-progress", action="store_true", help="no progress bar")

    geometry = commands.add_parser(
        "geometry", help="export the FFT sea's per-frame maps (EXR) and meshes (PLY)",
        description="Write, per frame and per cascade, float32 EXR maps (height, displacement, normal, Jacobian) "
                    "in Blender's baked-ocean layout, with metadata and a geometry.json sidecar, into "
                    "OUT/cascade_I/; with --ply also the closed water-body mesh of each patch.")
    geometry.add_argument("scene", type=Path, help="scene file (TOML)")
    geometry.add_argument("--frames", type=_frame_range, metavar="A:B", help="half-open frame range (default: the scene's)")
    geometry.add_argument("--out", type=Path, metavar="DIR", help="export folder of the maps (and --ply meshes)")
    geometry.add_argument("--usd", type=Path, metavar="FILE",
                          help="also (or only) write the animated sea, camera, sun and objects as a USD stage "
                               "(.usda, .usdc, .usd; metres, Z up; docs/geometry.md)")
    geometry.add_argument("--usd-extent", type=float, default=200.0, metavar="M",
                          help="width of the USD sea grid, centred under the camera [m] (default 200)")
    geometry.add_argument("--usd-points", type=int, default=256, metavar="N",
                          help="points per side of the USD sea grid (default 256)")
    geometry.add_argument("--ply", action="store_true", help="also write mesh_NNNN.ply per frame")
    geometry.add_argument("--camera-mesh", action="store_true",
                          help="also write the camera-following radial mesh and its per-ring LOD weights "
                               "(camera_mesh.ply, camera_mesh.json) for real-time engines")

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

    bake = commands.add_parser(
        "bake-luts", help="bake the real-time model's lookup textures (EXR + PNG + JSON)",
        description="Bake, from the scene's water optics, sun and sky and vision model, the LUTs of the "
                    "real-time water model: T0(h), T1(h, l), Fresnel (F and F^gamma), the sky environment map and "
                    "the ripple normal and seafloor-offset maps, each as float EXR, 8-bit PNG preview and JSON "
                    "sidecar, plus luts.json (docs/realtime.md). With adaptation_luminance = 'frame' the scene's "
                    "first frame is path-traced to measure it (or give --adaptation-luminance).")
    bake.add_argument("scene", type=Path, help="scene file (TOML)")
    bake.add_argument("--out", type=Path, metavar="DIR", required=True, help="LUT folder")
    bake.add_argument("--gamma", type=float, default=1.0, help="gamma of F^gamma in the Fresnel LUT (default 1)")
    bake.add_argument("--reference-albedo", type=_albedo_pair, metavar="R400,R700",
                      help="reference bottom albedo R0 of Eq. 22 (T0's bottom) at 400 and 700 nm (default 0,0)")
    bake.add_argument("--floor-albedo", type=_albedo_pair, metavar="R400,R700",
                      help="area-mean seafloor albedo that lights the bottom (T1) at 400 and 700 nm "
                           "(default: the scene's sand and rock mixed by rock_cover)")
    bake.add_argument("--adaptation-luminance", type=float, metavar="CD_M2",
                      help="world adaptation luminance of the vision model [cd/m2] (default: the scene's)")
    bake.add_argument("--resolution", type=_resolution, metavar="WxH",
                      help="size of the reference frame rendered for adaptation 'frame' (default: the scene's)")
    bake.add_argument("--spp", type=int, metavar="N", help="samples per pixel of that frame (default: the scene's)")
    bake.add_argument("--variant", metavar="V", help="Mitsuba variant ('auto' by default)")

    reference = commands.add_parser(
        "reference", help="path-traced reference images vs the real-time model: dE2000 maps, G-buffers, gamma fit",
        description="Per frame: the path-traced reference after the vision model, the real-time model's image "
                    "(from the LUTs), a per-pixel CIEDE2000 map with statistics, the camera (JSON), the water mesh "
                    "(PLY) and a G-buffer (EXR); then the gamma of F^gamma that minimises the mean dE over all "
                    "frames, and report.json/report.md. References already in OUT with the same settings are reused.")
    reference.add_argument("scene", type=Path, help="scene file (TOML)")
    reference.add_argument("--frames", type=_frame_range, metavar="A:B",
                           help="half-open frame range (default: the scene's)")
    reference.add_argument("--out", type=Path, metavar="DIR", required=True, help="reference-set folder")
    reference.add_argument("--luts", type=Path, metavar="DIR",
                           help="LUTs from `oceanrender bake-luts` (default: bake them into OUT/luts)")
    reference.add_argument("--spp", type=int, metavar="N", help="samples per pixel (default: the scene's)")
    reference.add_argument("--resolution", type=_resolution, metavar="WxH", help="image size in pixels")
    reference.add_argument("--noise-floor", action="store_true",
                           help="render the first frame again with another seed and report the reference's noise")
    reference.add_argument("--denoise", action="store_true",
                           help="denoise the references (Intel Open Image Denoise, colour only; the noise floor's "
                                "second render too)")
    reference.add_argument("--variant", metavar="V", help="Mitsuba variant ('auto' by default)")

    validate = commands.add_parser(
        "validate-shader", help="grade a GLSL fragment shader against a reference set (headless OpenGL)",
        description="Run FRAGMENT (GLSL 3.30 core, the interface of oceanrender/realtime/shaders/water.frag: "
                    "G-buffer textures, LUT textures, uniforms; docs/realtime.md) on every frame of a reference set "
                    "written by `oceanrender reference`, on a headless OpenGL context (EGL: Mesa's software "
                    "rasteriser without a GPU), and write its images, dE2000 maps against the references and against "
                    "the numpy model, worst regions, the gamma fit and report.json/report.md. A shader that does not "
                    "compile: one line per GLSL error, exit status 2. FRAGMENT 'shipped' is the reference shader.")
    validate.add_argument("fragment", metavar="FRAGMENT", help="fragment shader file, or 'shipped'")
    validate.add_argument("--reference", type=Path, metavar="DIR", required=True,
                          help="reference set from `oceanrender reference`")
    validate.add_argument("--out", type=Path, metavar="DIR",
                          help="output folder (default: DIR/shader_<name of FRAGMENT>)")
    validate.add_argument("--luts", type=Path, metavar="DIR", help="LUT folder (default: the reference set's)")
    validate.add_argument("--ripples", type=float, default=1.0, metavar="K",
                          help="ripple strength uniform u_ripple_strength (default 1: as baked; 0: none)")
    validate.add_argument("--gamma", type=float, metavar="G", help="u_gamma (default: the LUT set's)")

    movie = commands.add_parser(
        "movie", help="an MP4 and a contact sheet of a finished sequence",
        description="From DIR/frame_NNNN.png (a sequence `oceanrender render` wrote, e.g. outputs/open_ocean), "
                    "write DIR/<name>.mp4 (H.264, yuv420p, imageio-ffmpeg's own ffmpeg) and "
                    "DIR/contact_sheet.png; refuses a folder with a missing frame.")
    movie.add_argument("folder", type=Path, help="sequence folder with frame_NNNN.png")
    movie.add_argument("--fps", type=float, default=None,
                       help="frames per second (default: from the frames' EXR metadata, else 24)")
    movie.add_argument("--crf", type=int, default=18, help="H.264 quality, 0 (lossless) to 51 (default 18)")
    movie.add_argument("--columns", type=int, default=6, help="contact-sheet columns (default 6)")

    probe = commands.add_parser(
        "probe", help="the sea's height, water velocity and normal at points over time, as CSV",
        description="Print (or write with --out) one CSV row per frame and point: frame, time_s, x_m, y_m, "
                    "height_m (above the still level), u/v/w_m_s (the water's velocity at the surface), "
                    "normal_x/y/z, converged, folded. What floating objects stand on.")
    probe.add_argument("scene", type=Path, help="scene file (TOML) of an open sea (no [coastal])")
    probe.add_argument("--at", type=_point, action="append", required=True, metavar="X,Y",
                       help="a world point [m]; repeat for more points")
    probe.add_argument("--frames", type=_frame_range, metavar="A:B", help="half-open frame range (default: the scene's)")
    probe.add_argument("--out", type=Path, metavar="FILE", help="CSV file to write (default: standard output)")

    info = commands.add_parser(
        "info", help="versions against the lock, usable Mitsuba variants and the LLVM library",
        description="Report the installed version of every core dependency beside the version "
                    "requirements.lock pins, and probe which Mitsuba spectral variants work here.")
    info.add_argument("--all", action="store_true", help="compare every package in the lock, not only the core ones")
    info.add_argument("--check", action="store_true",
                      help="exit with status 1 when a compared package differs from the lock")
    return parser


def scene_with_cli_overrides(scene: Scene, args: argparse.Namespace) -> Scene:
    """Apply --frames/--spp/--resolution/--out/--variant/--denoise/--exposure, validated like the file."""
    output = {}
    if args.frames is not None:
        output["frames"] = args.frames
    if args.spp is not None:
        output["spp"] = args.spp
    if args.resolution is not None:
        output["resolution"] = args.resolution
    if args.out is not None:
        from .io.paths import name_problem  # noqa: PLC0415

        problem = name_problem(str(args.out))
        if problem:
            raise UserError(f"--out: {problem}; expected a folder that can be written")
        output["directory"] = str(args.out)
    render = {"variant": args.variant} if args.variant else {}
    if getattr(args, "denoise", False):
        render["denoise"] = True
    vision = {"exposure": args.exposure} if getattr(args, "exposure", None) is not None else {}
    if getattr(args, "view", None) is not None:
        scene = with_view(scene, args.view)
    return with_overrides(scene, "command line", output=output, render=render, vision=vision)


def check_run(scene: Scene, source: str, out: Path, out_key: str, *, tables: bool = True, sea: bool = True,
              renders: bool = True, needed_bytes: float | None = None) -> Path:
    """Check everything the run needs before any work (:mod:`oceanrender.checks`); the output folder, probed.

    Tables (``tables``), the open sea against its water body (``sea``), the
    memory estimate (the renderer's share with ``renders``) and the output
    folder ``out`` (created and written to), in that order.
    """
    from . import checks  # noqa: PLC0415

    if tables:
        checks.check_tables(scene, source)
    if sea:
        checks.check_sea(scene, source)
    checks.check_memory(scene, source, renders=renders)
    return checks.check_output(out, source, out_key, needed_bytes if needed_bytes is not None
                               else 2 * checks.frame_bytes(scene) + checks.SLACK_BYTES)


def scene_folder(scene: Scene, source: str) -> Path:
    """``<[output] directory>/<scene name>``, refused if it resolves outside the directory (a link)."""
    from .io.paths import PathProblem, check_inside  # noqa: PLC0415

    root = scene.output.directory
    try:
        # NOTE: taken literally ('~' and '$HOME' are folder names here): the one resolved folder every writer gets.
        return check_inside(Path(root) / scene.name, root)
    except PathProblem as exc:
        raise UserError(f"{source}: name: {exc}; expected a folder inside the output directory") from None
    except OSError as exc:
        raise UserError(f"{source}: [output] directory: {root}: {exc.strerror or exc}") from None


def activate(requested: str):
    from .runtime.variants import VariantError, activate_variant  # noqa: PLC0415

    try:
        return activate_variant(requested)
    except VariantError as exc:
        raise UserError(str(exc)) from None


#: Schemes of Dask scheduler addresses accepted by --cluster (distributed's TCP and TLS comms).
CLUSTER_SCHEMES = ("tcp", "tls")
#: Seconds to wait for a scheduler: the TCP connect, then the whole Dask handshake.
CLUSTER_CONNECT_S = 10.0


def parse_cluster_address(text: str) -> tuple[str, str, int]:
    """(scheme, host, port) of a scheduler address ``tcp://HOST:PORT`` / ``tls://HOST:PORT``; UserError if malformed."""
    from urllib.parse import urlsplit  # noqa: PLC0415

    expected = f"expected a Dask scheduler address like tcp://HOST:8786 ({' or '.join(CLUSTER_SCHEMES)}), got {quoted(text)}"
    try:
        parts = urlsplit(text)
        port = parts.port
    except ValueError:
        raise UserError(f"--cluster: {expected}") from None
    if (parts.scheme not in CLUSTER_SCHEMES or not parts.hostname or port is None or not 0 < port < 65536
            or parts.path not in ("", "/") or parts.query or parts.fragment or parts.username):
        raise UserError(f"--cluster: {expected}")
    return parts.scheme, parts.hostname, port


def check_dask_options(args: argparse.Namespace) -> None:
    """--workers N in [1, 256]; --cluster a scheduler address such as tcp://HOST:PORT."""
    if args.workers is not None and not 1 <= args.workers <= 256:
        raise UserError(f"--workers: expected a number of worker processes in [1, 256], got {args.workers}")
    if args.cluster is not None:
        parse_cluster_address(args.cluster)


def cmd_render(args: argparse.Namespace) -> int:
    check_dask_options(args)
    scene = load_scene(args.scene)
    scene = scene_with_cli_overrides(scene, args)
    source = str(args.scene)
    check_run(scene, source, scene_folder(scene, source),
              "--out" if args.out is not None else "[output] directory")
    with dask_client(args) as client:  # None: this process renders
        return _render(args, scene, client)


def connect_cluster(address: str, timeout_s: float = CLUSTER_CONNECT_S):
    """A Dask Client of the scheduler at ``address``, or UserError within about 2 × ``timeout_s`` seconds.

    A TCP connect with a timeout comes first (an unreachable host); then the
    Dask handshake runs in a daemon thread with a deadline, so a peer that
    accepts but never answers (or answers something else) cannot hang the run.
    """
    import socket  # noqa: PLC0415
    import threading  # noqa: PLC0415

    _, host, port = parse_cluster_address(address)
    try:
        socket.create_connection((host, port), timeout=timeout_s).close()
    except OSError as exc:
        raise UserError(f"--cluster {address}: no Dask scheduler reachable ({exc.strerror or exc})") from None
    result: dict[str, object] = {}

    def handshake() -> None:
        from dask.distributed import Client  # noqa: PLC0415

        try:
            result["client"] = Client(address, timeout=f"{timeout_s:g}s")
        except BaseException as exc:  # noqa: BLE001 (any failure of a foreign peer is reported in one line)
            result["error"] = exc

    thread = threading.Thread(target=handshake, daemon=True, name="dask-connect")
    thread.start()
    thread.join(timeout_s + 5.0)
    if "client" in result:
        return result["client"]
    error = result.get("error")
    reason = f"{type(error).__name__}: {error}" if error is not None else f"no answer within {timeout_s + 5:g} s"
    raise UserError(f"--cluster {address}: not a Dask scheduler that answers ({str(reason)[:200]})")


@contextlib.contextmanager
def dask_client(args: argparse.Namespace) -> Iterator[object]:
    """The Dask client of ``--workers N`` (a LocalCluster it owns) or ``--cluster ADDRESS``; else None.

    Connecting comes before any work, so an unreachable scheduler is a one-line error.
    """
    if args.workers is None and args.cluster is None:
        yield None
        return
    from dask.distributed import Client  # noqa: PLC0415

    if args.cluster is not None:
        with connect_cluster(args.cluster) as client:
            yield client
        return
    from .production.distributed import local_cluster  # noqa: PLC0415

    with local_cluster(args.workers) as cluster, Client(cluster) as client:
        yield client


def _render(args: argparse.Namespace, scene: Scene, client) -> int:
    runtime = activate(scene.render.variant)
    out_dir = scene_folder(scene, str(args.scene))
    start, end = scene.output.frames
    width, height = scene.output.resolution
    where = "" if client is None else (f", {len(client.scheduler_info()['workers'])} Dask worker(s)"
                                       + (f" at {args.cluster}" if args.cluster else ""))
    from .checks import time_estimate  # noqa: PLC0415
    from .pipeline import meter_samples  # noqa: PLC0415

    estimate = time_estimate(scene, runtime.variant, meter_samples(width, height))
    print(f"oceanrender {__version__}: {scene.name}, frames {start}:{end}, {width}x{height}, "
          f"{scene.output.spp} spp, variant {runtime.variant}"
          + (f" (LLVM {runtime.llvm_library})" if runtime.llvm_library else "") + f"{where} -> {out_dir}; "
          f"estimated {estimate.line()}" + ("" if client is None else " for one process"), flush=True)

    from tqdm import tqdm  # noqa: PLC0415

    bar = tqdm(total=end - start, unit="frame", disable=args.no_progress, dynamic_ncols=True)

    def on_frame(frame: int, seconds: float, skipped: bool) -> None:
        bar.set_postfix_str(f"frame {frame}: " + ("exists, skipped" if skipped else f"{seconds:.1f} s"))
        bar.update(1)

    tic = time.perf_counter()
    with bar:
        if client is None:
            from .pipeline import render_sequence  # noqa: PLC0415

            report = render_sequence(scene, out_dir, runtime.variant, on_frame=on_frame)
        else:
            from .production.distributed import render_distributed, worker_threads  # noqa: PLC0415

            threads = worker_threads(args.workers) if args.workers else None
            report = render_distributed(scene, out_dir, runtime.variant, client, threads=threads, on_frame=on_frame)
    total = time.perf_counter() - tic
    stages = ", ".join(f"{k} {v:.2f} s" for k, v in report.stage_seconds.items())
    print(f"rendered {len(report.rendered)} frame(s), skipped {len(report.skipped)} already complete, "
          f"in {total:.1f} s (setup {report.setup_seconds:.1f} s; {stages})")
    if report.repaired_pixels:
        print(f"warning: {report.repaired_pixels} non-finite pixel(s) repaired from their neighbours", file=sys.stderr)
    if report.failed:
        for failed in report.failed:
            print(f"error: frame {failed.frame} failed on every worker: {failed.error}", file=sys.stderr)
        print(f"{len(report.failed)} frame(s) not rendered; run the same command again to retry them", file=sys.stderr)
        return 1
    return 0


def cmd_info(args: argparse.Namespace) -> int:
    from .runtime.environment import (  # noqa: PLC0415
        compare_with_lock, core_dependencies, find_lock, installed_version, parse_lock)
    from .runtime.variants import SPECTRAL_VARIANTS, cuda_driver_present, find_llvm_library, probe_variant  # noqa: PLC0415

    print(f"oceanrender {__version__}, python {sys.version.split()[0]}")
    lock_path = find_lock(__file__)
    locked = parse_lock(lock_path.read_text()) if lock_path else {}
    names = tuple(sorted(locked)) if args.all and locked else core_dependencies()
    checks = compare_with_lock(names, locked, {name: installed_version(name) for name in names})
    print(f"lock: {lock_path}" if lock_path else
          "lock: none beside the package (not a source checkout): versions shown, not compared")
    for check in checks:
        verdict = ("" if not lock_path else "matches the lock" if check.matches else
                   "not in the lock" if check.locked is None else f"DIFFERS: lock pins {check.locked}")
        print(f"  {check.name:18s} {check.installed or 'not installed':14s} {verdict}")
    differ = [check.name for check in checks if lock_path and not check.matches]
    if lock_path:
        print(f"{len(checks) - len(differ)} of {len(checks)} {'locked' if args.all else 'core'} packages match the lock"
              + ("; rebuild .venv from it: OCEANRENDER_FRESH_VENV=1 make setup" if differ else ""))
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
    return 1 if args.check and differ else 0


def cmd_geometry(args: argparse.Namespace) -> int:
    scene = load_scene(args.scene)
    if args.frames is not None:
        scene = with_overrides(scene, "command line", output={"frames": args.frames})
    if args.out is None and args.usd is None:
        raise UserError("geometry: give --out DIR (wave maps), --usd FILE (USD stage), or both")
    usd_grid = _check_usd_options(scene, args) if args.usd is not None else None
    if args.out is None:
        return _write_usd(scene, args, usd_grid)
    if scene.ocean.model != "FFT":
        raise UserError(f"{args.scene}: [ocean] model: the wave maps need 'FFT', got {scene.ocean.model!r} "
                        "(--usd alone works for every model)")
    from .checks import geometry_frame_bytes  # noqa: PLC0415

    check_run(scene, str(args.scene), args.out, "--out", tables=False, sea=args.ply, renders=args.camera_mesh,
              needed_bytes=geometry_frame_bytes(scene))
    from .waves.sea import SeaSurface  # noqa: PLC0415
    from .export.wave_maps import export_geometry_sequence  # noqa: PLC0415

    from .waves.sea import sea_description  # noqa: PLC0415

    sea = SeaSurface(scene.ocean)
    start, end = scene.output.frames
    times = {frame: frame / scene.output.fps for frame in range(start, end)}
    written = 0
    description = sea_description(scene.ocean, sea.spectrum)
    print(f"sea ({description['form']}): Hs {description['significant_wave_height_m']:.3g} m, "
          f"Tp {description['peak_period_s']:.3g} s, mean direction {description['mean_direction_deg']:.1f} deg")
    for index, patch in enumerate(sea.cascades.cascades):
        folder = args.out / f"cascade_{index}"
        written += len(export_geometry_sequence(folder, patch, times, sea=description,
                                                mesh_depth=scene.water.depth if args.ply else None))
        print(f"cascade {index}: patch {patch.grid.patch_size:g} m, {patch.grid.resolution}² -> {folder}")
    if args.camera_mesh:
        from .export.camera_mesh import export_camera_mesh  # noqa: PLC0415

        ply, table = export_camera_mesh(scene, args.out)
        written += 2
        print(f"camera-following mesh -> {ply}, {table}")
    print(f"wrote {written} file(s) for frames {start}:{end}")
    return _write_usd(scene, args, usd_grid) if usd_grid is not None else 0


def _check_usd_options(scene: Scene, args: argparse.Namespace):
    """The USD sea grid of --usd-extent/--usd-points, and --usd checked, before any work."""
    from .export.usd_stage import USD_SUFFIXES, sea_grid  # noqa: PLC0415

    if args.usd.suffix.lower() not in USD_SUFFIXES:
        raise UserError(f"--usd: expected a file ending in {', '.join(USD_SUFFIXES)}, got {quoted(str(args.usd))}")
    if args.usd.is_dir():
        raise UserError(f"--usd: {args.usd} is a folder; expected a file name")
    if scene.coastal is not None:
        raise UserError(f"{args.scene}: [coastal]: --usd exports the open sea only")
    try:
        return sea_grid(scene, args.usd_extent, args.usd_points)
    except ValueError as exc:  # "extent: ..." or "points: ...", the option's own name after --usd-
        raise UserError(f"--usd-{exc}") from None


def _write_usd(scene: Scene, args: argparse.Namespace, grid) -> int:
    from .export.usd_stage import write_usd_stage  # noqa: PLC0415

    counts = write_usd_stage(scene, args.usd, grid, range(*scene.output.frames))
    print(f"wrote {args.usd}: {counts['frames']} frame(s), {counts['points']} sea points, "
          f"{counts['objects']} object(s), camera and sun")
    return 0


#: Columns of ``oceanrender probe``'s CSV, with their units in the names.
PROBE_COLUMNS = ("frame", "time_s", "x_m", "y_m", "height_m", "u_m_s", "v_m_s", "w_m_s",
                 "normal_x", "normal_y", "normal_z", "converged", "folded")


def cmd_probe(args: argparse.Namespace) -> int:
    scene = load_scene(args.scene)
    if args.frames is not None:
        scene = with_overrides(scene, "command line", output={"frames": args.frames})
    if scene.coastal is not None:
        raise UserError(f"{args.scene}: [coastal]: probe reads the open sea only; a coastal zone's heights are "
                        "the shallow-water fields (`oceanrender coastal` writes them)")
    if args.out is not None and args.out.is_dir():
        raise UserError(f"--out: {args.out} is a folder; expected a CSV file name")
    from .scene.motion import frame_times  # noqa: PLC0415
    from .surface.objects import scene_sea  # noqa: PLC0415
    from .waves.probe import probe_sea  # noqa: PLC0415

    frames = range(*scene.output.frames)
    x, y = (list(v) for v in zip(*args.at))
    result = probe_sea(scene_sea(scene), x, y, frame_times(scene.output.frames, scene.output.fps))
    rows = [",".join(PROBE_COLUMNS)]
    for i, frame in enumerate(frames):
        for j in range(len(x)):
            values = (result.times[i], result.x[j], result.y[j], result.height[i, j], *result.velocity[i, j],
                      *result.normal[i, j])
            rows.append(",".join([str(frame), *(repr(float(v)) for v in values),
                                  str(bool(result.converged[i, j])).lower(), str(bool(result.folded[i, j])).lower()]))
    text = "\n".join(rows) + "\n"
    if args.out is None:
        sys.stdout.write(text)
        return 0
    from .io.frames import atomic_path  # noqa: PLC0415

    with atomic_path(args.out, ".csv") as tmp:
        tmp.write_text(text)
    print(f"wrote {len(rows) - 1} rows ({len(frames)} frames x {len(x)} points) to {args.out}", file=sys.stderr)
    return 0


def _sequence_fps(folder: Path) -> float | None:
    """Frames per second from the EXR metadata (frame / time_s of a frame > 0), if any."""
    from .io.frames import read_exr  # noqa: PLC0415

    for exr in sorted(folder.glob("frame_*.exr"))[1:3]:
        try:
            _, meta = read_exr(exr)
            frame, time_s = float(meta["frame"]), float(meta["time_s"])
        except (OSError, KeyError, ValueError, RuntimeError):
            continue
        if frame > 0 and time_s > 0:
            return frame / time_s
    return None


def cmd_movie(args: argparse.Namespace) -> int:
    from .production.movie import SequenceError, write_contact_sheet, write_movie  # noqa: PLC0415

    folder = args.folder
    if not folder.is_dir():
        raise UserError(f"{folder}: not a folder")
    from .io.paths import PathProblem, check_output_folder  # noqa: PLC0415

    try:
        check_output_folder(folder)
    except PathProblem as exc:
        raise UserError(f"{folder}: {exc}") from None
    fps = args.fps or _sequence_fps(folder) or 24.0
    if not (0 < fps <= 1000 and 0 <= args.crf <= 51 and args.columns >= 1):
        raise UserError(f"--fps must be in (0, 1000], --crf in [0, 51], --columns ≥ 1; got {fps}, {args.crf}, "
                        f"{args.columns}")
    name = folder.resolve().name
    try:
        movie = write_movie(folder, folder / f"{name}.mp4", fps, crf=args.crf)
        sheet = write_contact_sheet(folder, folder / "contact_sheet.png", columns=args.columns)
    except SequenceError as exc:
        raise UserError(str(exc)) from None
    print(f"wrote {movie.path} ({movie.frames} frames, {fps:g} fps, {movie.size[0]}x{movie.size[1]}) "
          f"and {sheet.path} ({sheet.size[0]}x{sheet.size[1]})")
    return 0


def cmd_coastal(args: argparse.Namespace) -> int:
    scene = load_scene(args.scene)
    if args.frames is not None:
        scene = with_overrides(scene, "command line", output={"frames": args.frames})
    if scene.coastal is None:
        raise UserError(f"{args.scene}: [coastal]: the scene has no coastal section to simulate")
    from .checks import coastal_frame_bytes  # noqa: PLC0415

    check_run(scene, str(args.scene), args.out, "--out", tables=False, sea=False, renders=False,
              needed_bytes=coastal_frame_bytes(scene))
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
    rewritten = (f" ({len(report.exr_rewritten)} lost EXR(s) rewritten from their fields)"
                 if report.exr_rewritten else "")
    print(f"simulated {len(report.simulated)} frame(s), {len(report.found)} already stored{rewritten}{resumed}, "
          f"in {report.seconds:.1f} s ({rate:.1f} million cell-updates/s)")
    return 0


def cmd_optics(args: argparse.Namespace) -> int:
    import numpy as np  # noqa: PLC0415

    scene = load_scene(args.scene)
    _sunsky_only(scene, args)
    check_run(scene, str(args.scene), args.out, "--out", sea=False, renders=False)
    runtime = activate(args.variant or scene.render.variant)
    from .export.optics_report import write_optics_report  # noqa: PLC0415
    from .optics.report import REPORT_WAVELENGTHS, scene_optics  # noqa: PLC0415
    from .render.irradiance import sky_irradiance_spectra  # noqa: PLC0415
    from .optics.scene_water import scene_iops, water_composition, water_ior, water_phase_table  # noqa: PLC0415

    wavelengths = REPORT_WAVELENGTHS
    composition = water_composition(scene)
    a, b, bb = scene_iops(scene, wavelengths)
    direct, diffuse = sky_irradiance_spectra(scene.sun, wavelengths, spp=scene.render.white_spp)
    depth = scene.water.depth
    z = np.linspace(0.0, min(depth, 100.0), 101)
    report = scene_optics(a, b, bb, direct, diffuse, 90.0 - scene.sun.elevation, depth, z, n_water=water_ior(scene),
                          phase=water_phase_table(scene, wavelengths))
    metadata = {"scene": scene.name, "variant": runtime.variant, "oceanrender_version": __version__,
                "composition": None if composition is None else composition.__dict__,
                "jerlov_type": scene.water.jerlov_type,
                "bottom": "none (albedo 0): the rendered water body ends in a black floor at [water] depth"}
    written = write_optics_report(args.out, report, metadata)
    i = int(np.argmin(np.abs(wavelengths - 550.0)))
    print(f"{scene.name}: a(550) {a[i]:.4g} m⁻¹, b(550) {b[i]:.4g} m⁻¹, K_d(550) {report.light.K_d[i]:.4g} m⁻¹, "
          f"R(0⁻, 550) {report.light.R[i]:.4g}; wrote {', '.join(p.name for p in written)} to {args.out}")
    return 0


def _albedo_pair(text: str) -> tuple[float, float]:
    try:
        r400, r700 = (float(part) for part in text.split(","))
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected R400,R700 (e.g. 0.25,0.45), got {quoted(text)}") from None
    if not (0 <= r400 <= 1 and 0 <= r700 <= 1):
        raise argparse.ArgumentTypeError(f"albedos must lie in [0, 1], got {quoted(text)}")
    return r400, r700


def _realtime_scene(args: argparse.Namespace) -> Scene:
    """Load the scene with --frames/--spp/--resolution applied (validated like the file)."""
    scene = load_scene(args.scene)
    output = {key: value for key, value in (("frames", getattr(args, "frames", None)), ("spp", args.spp),
                                            ("resolution", args.resolution)) if value is not None}
    scene = with_overrides(scene, "command line", output=output)
    _sunsky_only(scene, args)
    check_run(scene, str(args.scene), args.out, "--out")
    return scene


def _sunsky_only(scene: Scene, args: argparse.Namespace) -> None:
    """The LUTs, references and the optics report use sunsky's sun and sky irradiance: refuse a map's scene."""
    if scene.environment is not None:
        raise UserError(f"{args.scene}: [environment]: {args.command} works under sunsky's sun and sky only; "
                        "leave [environment] out")


def _reference_renderer(scene: Scene, variant: str, frames: tuple[int, int], out: Path):
    """A ReferenceRenderer of the scene, after running (or reusing) its coastal simulation in ``out/coastal``."""
    from .pipeline import coastal_store  # noqa: PLC0415
    from .realtime.reference import ReferenceRenderer  # noqa: PLC0415

    store = None
    if scene.coastal is not None:
        from .coastal.simulation import run_simulation  # noqa: PLC0415

        # NOTE: under --out, as every output of the command; the layout is `oceanrender render`'s.
        store = coastal_store(out)
        print(f"coastal simulation -> {store}", flush=True)
        run_simulation(scene, store, frames)
    return ReferenceRenderer(scene, variant, first_frame=frames[0], coastal_store=store)


def _bake(scene: Scene, args, white_XYZ, reference_xyz=None):
    """Bake the LUT set; the adaptation from --adaptation-luminance, else the scene (and reference_xyz)."""
    import numpy as np  # noqa: PLC0415

    from .realtime.bake import BakeSettings, bake_lut_set, measure_scene_light  # noqa: PLC0415
    from .realtime.reference import scene_adaptation  # noqa: PLC0415

    settings = BakeSettings(gamma=getattr(args, "gamma", 1.0),
                            reference_albedo=getattr(args, "reference_albedo", None) or (0.0, 0.0),
                            floor_albedo=getattr(args, "floor_albedo", None))
    given = getattr(args, "adaptation_luminance", None)
    if given is not None:
        adaptation, source = float(given), "given on the command line"
    else:
        xyz = reference_xyz if reference_xyz is not None else np.zeros((1, 1, 3))
        adaptation, source = scene_adaptation(scene, xyz, white_XYZ)
    light = measure_scene_light(scene, settings, white_XYZ=white_XYZ)
    return bake_lut_set(scene, light, adaptation, source, settings)


def cmd_bake_luts(args: argparse.Namespace) -> int:
    if not args.gamma > 0:
        raise UserError(f"--gamma must be > 0, got {args.gamma}")
    if args.adaptation_luminance is not None and not args.adaptation_luminance > 0:
        raise UserError(f"--adaptation-luminance must be > 0 cd/m2, got {args.adaptation_luminance}")
    scene = _realtime_scene(args)
    runtime = activate(args.variant or scene.render.variant)
    from .realtime.files import write_lut_set  # noqa: PLC0415
    from .render.renderer import adapting_white_XYZ  # noqa: PLC0415

    tic = time.perf_counter()
    reference_xyz = None
    if scene.vision.adaptation_luminance == "frame" and args.adaptation_luminance is None:
        start = scene.output.frames[0]
        renderer = _reference_renderer(scene, runtime.variant, (start, start + 1), args.out)
        width, height = renderer.sequence.resolution
        print(f"rendering frame {start} ({width}x{height}, {renderer.sequence.spp} spp) for the adaptation "
              "luminance ('frame')", flush=True)
        reference_xyz, _ = renderer.render_xyz(start)
        white = renderer.white_XYZ
    else:
        white = adapting_white_XYZ(scene, seed=scene.render.seed)
    lut_set = _bake(scene, args, white, reference_xyz)
    written = write_lut_set(args.out, lut_set)
    vision = lut_set.constants["vision"]
    T0 = lut_set["T0"].data[0]
    print(f"{scene.name}: L_wa = {vision['adaptation_luminance_cd_m2']:.6g} cd/m2 ({vision['adaptation_source']}); "
          f"T0(0) = ({', '.join(f'{v:.4f}' for v in T0[0])}), T0(inf) = ({', '.join(f'{v:.4f}' for v in T0[-1])}); "
          f"wrote {len(written)} files to {args.out} in {time.perf_counter() - tic:.1f} s")
    return 0


def cmd_reference(args: argparse.Namespace) -> int:
    from .realtime.files import (  # noqa: PLC0415
        read_lut_set,
        read_reference_xyz,
        write_comparison,
        write_fitted,
        write_lut_set,
        write_report,
    )
    from .realtime.gamma_fit import fit_gamma, fit_view  # noqa: PLC0415
    from .optics.scene_water import water_ior  # noqa: PLC0415
    from .realtime.reference import compare_frame, reference_noise, reference_report, vision_state  # noqa: PLC0415

    scene = _realtime_scene(args)
    luts = None
    if args.luts is not None:
        if not (args.luts / "luts.json").is_file():
            raise UserError(f"--luts {args.luts}: no luts.json there (run `oceanrender bake-luts` first)")
        luts = read_lut_set(args.luts)
        if luts.constants.get("scene") != scene.name:
            print(f"warning: the LUTs were baked for scene {luts.constants.get('scene')!r}, not {scene.name!r}",
                  file=sys.stderr)
    runtime = activate(args.variant or scene.render.variant)
    start, end = scene.output.frames
    out = args.out
    tic = time.perf_counter()
    renderer = _reference_renderer(scene, runtime.variant, (start, end), out)
    (width, height), spp = renderer.sequence.resolution, renderer.sequence.spp
    print(f"oceanrender {__version__}: reference set of {scene.name}, frames {start}:{end}, {width}x{height}, "
          f"{spp} spp, variant {runtime.variant} -> {out}", flush=True)

    identity = {"scene": scene.name, "spp": spp, "resolution": f"{width}x{height}", "variant": runtime.variant,
                "seed": scene.render.seed, "denoised": int(bool(args.denoise))}
    frames = {}
    for frame in range(start, end):
        tac = time.perf_counter()
        xyz = read_reference_xyz(out / f"reference_{frame:04d}.exr", {**identity, "frame": frame})
        repaired = 0
        if xyz is None:
            xyz, repaired = renderer.render_xyz(frame, denoise=args.denoise)
            note = f"rendered in {time.perf_counter() - tac:.1f} s"
        else:
            note = "reused the stored reference"
        frames[frame] = (xyz, repaired, renderer.gbuffer(frame), renderer.geometry)
        print(f"frame {frame}: {note}", flush=True)

    lut_folder = args.luts
    if luts is None:
        lut_folder = out / "luts"
        luts = _bake(scene, args, renderer.white_XYZ, frames[start][0])
        write_lut_set(lut_folder, luts)
        print(f"baked the LUTs into {lut_folder}", flush=True)
    phi = vision_state(scene, luts)

    comparisons = {}
    for frame, (xyz, repaired, gbuffer, geometry) in frames.items():
        comparisons[frame] = comparison = compare_frame(xyz, gbuffer, luts, phi)
        write_comparison(out, frame, xyz, comparison, gbuffer, renderer.camera, geometry, renderer.faces,
                         {**identity, "frame": frame, "time_s": frame / scene.output.fps, "repaired_pixels": repaired,
                          "n_water": water_ior(scene)})
        print(f"frame {frame}: dE2000 water mean {comparison.water.mean:.2f}, p95 {comparison.water.p95:.2f}, "
              f"max {comparison.water.max:.2f} (gamma {luts.gamma:g})", flush=True)

    fit = fit_gamma([fit_view(c.terms, c.reference_rgb, phi.display) for c in comparisons.values()],
                    gamma_start=luts.gamma)
    fitted = {frame: c.at(fit.gamma) for frame, c in comparisons.items()}
    for frame in comparisons:
        write_fitted(out, frame, comparisons[frame], fitted[frame], {**identity, "frame": frame})
    noise = None
    if args.noise_floor:
        noise = reference_noise(renderer, start, comparisons[start], phi, denoise=args.denoise)
    report = reference_report(scene, (start, end), identity, lut_folder, phi, luts, fit, comparisons, fitted,
                              {frame: entry[1] for frame, entry in frames.items()}, noise)
    write_report(out, report)
    print(f"gamma fit over {len(comparisons)} frame(s): gamma = {fit.gamma:.4g}; water dE2000 mean "
          f"{fit.before.mean:.2f} -> {fit.after.mean:.2f}, p95 {fit.before.p95:.2f} -> {fit.after.p95:.2f}, "
          f"max {fit.before.max:.2f} -> {fit.after.max:.2f}"
          + (f"; reference noise (two seeds) mean {noise['water']['mean']:.2f}" if noise else "")
          + f"; report {out / 'report.md'} ({time.perf_counter() - tic:.0f} s)")
    return 0

def cmd_validate_shader(args: argparse.Namespace) -> int:
    from .realtime.files import shader_report, write_shader_frame, write_shader_report  # noqa: PLC0415
    from .realtime.glsl import GLContext, ShaderError, shipped_shader  # noqa: PLC0415
    from .realtime.validate import ShaderRunner, read_reference_set, source_digest, validate_shader  # noqa: PLC0415

    fragment = shipped_shader() if args.fragment == "shipped" else Path(args.fragment)
    try:
        source = fragment.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise UserError(f"FRAGMENT {fragment}: cannot read it ({exc.__class__.__name__}: {exc})") from None
    if not (math.isfinite(args.ripples) and args.ripples >= 0):
        raise UserError(f"--ripples: expected a finite number >= 0, got {args.ripples}")
    if args.gamma is not None and not (math.isfinite(args.gamma) and args.gamma > 0):
        raise UserError(f"--gamma: expected a finite number > 0, got {args.gamma}")
    try:
        references = read_reference_set(args.reference, args.luts)
    except (ValueError, KeyError, OSError) as exc:
        raise UserError(f"--reference {args.reference}: {one_line(exc)}") from None
    out = args.out or args.reference / f"shader_{fragment.stem}"
    tic = time.perf_counter()
    try:
        context = GLContext()
    except RuntimeError as exc:
        raise UserError(str(exc)) from None
    try:
        runner = ShaderRunner(context, source, str(fragment), references.luts, args.ripples)
    except ShaderError as exc:
        context.release()
        for message in exc.messages:
            print(message, file=sys.stderr)
        print(f"oceanrender: error: {fragment}: {len(exc.messages)} GLSL error(s)", file=sys.stderr)
        return 2
    print(f"oceanrender {__version__}: {fragment} on {context.renderer}; reference set {args.reference} "
          f"({len(references.views)} frame(s))", flush=True)
    try:
        grade = validate_shader(runner, references, args.gamma, progress=lambda text: print(text, flush=True))
    finally:
        runner.release()
    out.mkdir(parents=True, exist_ok=True)
    meta = {"shader": str(fragment), "reference_set": str(args.reference), "gamma": grade.gamma,
            "ripple_strength": args.ripples}
    for frame in grade.frames:
        write_shader_frame(out, frame, references.phi.display, {**meta, "frame": frame.frame})
    report = shader_report(grade, references, str(fragment), source_digest(source), context.renderer, args.ripples)
    write_shader_report(out, report)
    context.release()
    print(f"water dE2000 vs reference: mean {grade.before.mean:.2f}, p95 {grade.before.p95:.2f} "
          f"(numpy model {grade.model_vs_reference.mean:.2f}); vs numpy model mean {grade.shader_vs_model.mean:.3f}; "
          + (f"fitted gamma {grade.fitted_gamma:.4g}: mean {grade.after.mean:.2f}" if grade.gamma_sensitive
             else "the shader ignores u_gamma")
          + f"; report {out / 'report.md'} ({time.perf_counter() - tic:.1f} s)")
    return 0


COMMANDS = {"render": cmd_render, "geometry": cmd_geometry, "coastal": cmd_coastal, "optics": cmd_optics,
            "movie": cmd_movie, "info": cmd_info, "bake-luts": cmd_bake_luts, "reference": cmd_reference,
            "probe": cmd_probe, "validate-shader": cmd_validate_shader}


def one_line(message: object) -> str:
    """``message`` with control characters (NUL, newlines, escapes) shown as ``\\xNN``: one printable line."""
    return "".join(c if c.isprintable() else repr(c)[1:-1] for c in str(message))


def main(argv: list[str] | None = None) -> int:
    warnings.filterwarnings("ignore", message=".*Matplotlib.*")
    args = build_parser().parse_args(argv)
    try:
        return COMMANDS[args.command](args)
    except (SceneError, UserError) as exc:
        print(f"oceanrender: error: {one_line(exc)}", file=sys.stderr)
        return 2
    except FrameError as exc:  # a frame the scene cannot make right (non-finite): the frames before it are kept
        print(f"oceanrender: error: {one_line(args.scene if hasattr(args, 'scene') else '')}: {one_line(exc)}; "
              f"finished frames are kept", file=sys.stderr)
        return 1
    except OSError as exc:  # a file system failing mid-run (disk full, folder removed): finished work is kept
        from .io.paths import is_disk_full  # noqa: PLC0415

        what = "disk full" if is_disk_full(exc) else (exc.strerror or str(exc))
        print(f"oceanrender: error: {one_line(exc.filename or 'a file')}: {what}; finished frames are kept, "
              f"rerun the same command to resume", file=sys.stderr)
        return 1
    except MemoryError:
        print("oceanrender: error: out of memory; finished frames are kept; lower the sizes of the scene "
              "([output] resolution, [ocean] resolution, [mesh] segments)", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        print("oceanrender: interrupted; finished frames are kept, rerun to resume", file=sys.stderr)
        return 130


if __name__ == "__main__":
    sys.exit(main())
