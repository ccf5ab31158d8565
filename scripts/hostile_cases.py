"""The bad inputs of issue 17, each through the real CLI in its own process: a markdown table of what happens.

Usage: ``.venv/bin/python scripts/hostile_cases.py > /tmp/cases.md`` (about 2
minutes; the few cases that are valid render an 8×6 frame). Each row: the
case, the exit status, the first line of stderr (or the last line of stdout
on success), seconds, and whether any file appeared outside ``--out``. The
table in docs/hardening.md comes from this script.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
OPEN = (ROOT / "scenes" / "open_ocean.toml").read_text(encoding="utf-8")
BEACH = (ROOT / "scenes" / "coastal_beach.toml").read_text(encoding="utf-8")
FLYOVER = (ROOT / "scenes" / "open_ocean_flyover.toml").read_text(encoding="utf-8")
TIMEOUT_S = 300


def set_key(text: str, section: str, key: str, value: str) -> str:
    """``text`` with ``key = value`` in ``[section]`` (replaced if present, else added)."""
    pattern = re.compile(rf"(^\[{re.escape(section)}\]\n(?:(?!\[).*\n)*?){re.escape(key)} = [^\n]*$", re.M)
    if pattern.search(text):
        return pattern.sub(lambda m: m.group(1) + f"{key} = {value}", text, count=1)
    return re.sub(rf"^\[{re.escape(section)}\]$", f"[{section}]\n{key} = {value}", text, count=1, flags=re.M)


def tiny(text: str) -> str:
    """Cheap sizes (the keys a case sets afterwards win)."""
    for section, key, value in [("ocean", "resolution", "64"), ("mesh", "segments", "48")]:
        if f"[{section}]" in text:
            text = set_key(text, section, key, value)
    text = re.sub(r"^cells = .*$", "cells = [40, 30]", text, flags=re.M)
    return text.replace("[render]\n", "[render]\nwhite_spp = 16\n", 1)


def cases(folder: Path):
    """(label, scene text or bytes, extra CLI arguments, command) for every case of the issue."""
    npy = folder / "arrays"
    npy.mkdir()
    buf = folder / "ok.npy"
    np.save(buf, np.zeros((30, 40)))
    good = buf.read_bytes()
    np.save(npy / "structured.npy", np.zeros((30, 40), dtype=[("a", "f8")]))
    (npy / "empty.npy").write_bytes(b"")
    (npy / "huge.npy").write_bytes(good.replace(b"(30, 40)", b"(100000, 100000)"))
    (folder / "binary.csv").write_bytes(bytes(range(256)) * 16)
    os.mkfifo(folder / "fifo.csv")
    header = "# units: nm, m^-1, m^-1; source: this script\n# wavelength_nm,a_per_m,b_per_m\n"
    for name, a, b in [("zeros", 0.0, 0.01), ("negative", -0.01, 0.01), ("huge", 1e308, 0.01)]:
        (folder / f"{name}.csv").write_text(header + f"360,{a},{b}\n830,{a},{b}\n")
    o, r = tiny(OPEN), tiny(BEACH)
    yield "scene file not UTF-8", o.encode() + b"# caf\xe9\n", [], "render"
    yield "tables nested 1000 deep", o + "x = " + "{a = " * 1000 + "1" + "}" * 1000 + "\n", [], "render"
    yield "iop_table binary", set_key(o, "water", "iop_table", f'"{folder}/binary.csv"'), [], "render"
    yield "iop_table with a NUL byte", set_key(o, "water", "iop_table", '"a\\u0000b.csv"'), [], "render"
    yield "iop_table 5000-character name", set_key(o, "water", "iop_table", '"' + "x" * 5000 + '.csv"'), [], "render"
    yield "iop_table /dev/zero", set_key(o, "water", "iop_table", '"/dev/zero"'), [], "render"
    yield "iop_table /dev/stdin", set_key(o, "water", "iop_table", '"/dev/stdin"'), [], "render"
    yield "iop_table a FIFO", set_key(o, "water", "iop_table", f'"{folder}/fifo.csv"'), [], "render"
    for name in ("zeros", "negative", "huge"):
        yield f"IOP table of {name}", set_key(o, "water", "iop_table", f'"{folder}/{name}.csv"'), [], "render"
    for name in ("structured", "empty", "huge"):
        yield (f"bathymetry .npy {name}", set_key(r, "coastal", "bathymetry", f'"{npy}/{name}.npy"'), [],
               "render")
    yield "--out /dev/null", o, ["--out", "/dev/null"], "render"
    yield "--out a regular file", o, ["--out", str(folder / "binary.csv")], "render"
    yield "--out name over 255 bytes", o, ["--out", str(folder / ("n" * 300))], "render"
    yield "--out read-only (/proc)", o, ["--out", "/proc/oceanrender"], "render"
    yield "render.seed = 2³²", set_key(o, "render", "seed", str(2**32)), [], "render"
    yield "seed + frame reaching 2³²", set_key(o, "render", "seed", str(2**32 - 2)), ["--frames", "0:3"], "render"
    yield "water.ior = 1.0", set_key(o, "water", "ior", "1.0"), [], "render"
    yield "loop_period = inf", set_key(o, "ocean", "loop_period", "inf"), [], "render"
    yield "ocean.resolution = 8, 3 cascades", set_key(set_key(o, "ocean", "resolution", "8"), "ocean", "cascades",
                                                     "3"), [], "render"
    yield "ocean.resolution = 8, 3 cascades (geometry)", set_key(set_key(o, "ocean", "resolution", "8"), "ocean",
                                                                "cascades", "3"), [], "geometry"
    yield "water.depth above the troughs", set_key(o, "water", "depth", "0.5"), [], "render"
    yield "sun.elevation = 1e-9", set_key(o, "sun", "elevation", "1e-9"), [], "render"
    yield "sun_scale = inf", set_key(o, "sun", "sun_scale", "inf"), [], "render"
    yield "adaptation_luminance = inf", set_key(o, "vision", "adaptation_luminance", "inf"), [], "render"
    yield "display_luminance = 1e-300", set_key(o, "vision", "display_luminance", "1e-300"), [], "render"
    yield "mesh.segments = 16384", set_key(o, "mesh", "segments", "16384"), [], "render"
    yield "ocean.resolution = 8192", set_key(o, "ocean", "resolution", "8192"), [], "render"
    yield "coastal.cells = [8192, 8192]", re.sub(r"^cells = .*$", "cells = [8192, 8192]", r, flags=re.M), [], \
        "render"
    yield "a 16384×16384 frame", o, ["--resolution", "16384x16384"], "render"
    yield "frames = [0, 1e12]", set_key(o, "output", "frames", "[0, 1000000000000]"), [], "render"
    yield "flyover frames = [0, 1e8]", set_key(tiny(FLYOVER), "output", "frames", "[0, 100000000]"), [], "render"
    yield "checkpoint_interval = 1e-9", set_key(r, "coastal", "checkpoint_interval", "1e-9"), [], "render"
    yield "camera position NaN", set_key(o, "camera", "position", "[nan, 0.0, 5.0]"), [], "render"
    yield "camera target inf", set_key(o, "camera", "target", "[0.0, inf, 0.0]"), [], "render"
    yield "coastal.origin NaN", set_key(r, "coastal", "origin", "[nan, -6.0]"), [], "render"
    yield "camera under the water", set_key(o, "camera", "position", "[0.0, 0.0, -2.0]"), [], "render"
    yield 'name = ".."', 'name = ".."\n' + o, [], "render"
    yield "scene file named ...toml", ("..", o), [], "render"
    yield "--cluster foo://x", o, ["--cluster", "foo://x"], "render"
    yield "--cluster tcp://", o, ["--cluster", "tcp://"], "render"
    yield "--cluster tcp://h:notaport", o, ["--cluster", "tcp://h:notaport"], "render"
    yield "the shipped open_ocean, 8×6", o, [], "render"
    # Issue 39 (16×9, 1 spp as the issue ran them; no --out where the scene's own folder is the case).
    small = ["--resolution", "16x9"]
    yield ("39.1 [output] directory = \"~/tilde\"", set_key(o, "output", "directory", '"~/tilde"'), small, "render",
           {"own_out": True})
    yield ("39.1 [output] directory = \"$HOME/x\"", set_key(o, "output", "directory", '"$HOME/x"'), small, "render",
           {"own_out": True})
    yield ("39.2 wind_speed = 1e-9, foam on", set_key(set_key(o, "ocean", "wind_speed", "1e-9"), "foam", "enabled",
                                                      "true"), small, "render")
    yield "39.3 spectral_bands = 470", set_key(o, "output", "spectral_bands", "470"), small, "render"
    yield "39.3 spectral_bands = 94", set_key(o, "output", "spectral_bands", "94"), small, "render"
    yield "39.4 an empty scene file", "", small, "render"
    yield "39.5 [output] directory with a NUL byte", set_key(o, "output", "directory", '"a\\u0000b"'), small, \
        "render", {"own_out": True}
    yield ("39.6 spp = 1048576 (stopped after 40 s: the estimate is the point)",
           set_key(o, "output", "spp", "1048576"), small, "render", {"spp": None, "timeout": 40})
    yield "39.6 a 5000-character name", 'name = "' + "x" * 5000 + '"\n' + o, small, "render"


def run_case(folder: Path, label, scene, extra, command, options=None):
    """One row; ``options``: ``own_out`` (no --out: the scene's folder, from the case's folder, with $HOME a
    folder of its own), ``spp`` (None: the scene's), ``timeout`` [s] (a run stopped on purpose)."""
    options = options or {}
    case = folder / re.sub(r"[^A-Za-z0-9]+", "_", label).strip("_")[:80]
    case.mkdir()
    home = folder / "home"
    home.mkdir(exist_ok=True)
    for cache in (".drjit", ".cache"):  # the real kernel caches, so nothing compiles twice
        if (Path.home() / cache).is_dir() and not (home / cache).exists():
            (home / cache).symlink_to(Path.home() / cache)
    stem = "scene"
    if isinstance(scene, tuple):
        stem, scene = scene
    path = case / f"{stem}.toml"
    path.write_bytes(scene if isinstance(scene, bytes) else scene.encode("utf-8"))
    out = case / "out"
    argv = [sys.executable, "-m", "oceanrender", command, str(path), "--frames", "0:1"]
    if command == "render":
        argv += ["--resolution", "8x6", "--no-progress"]
        argv += ["--spp", str(options.get("spp", 1))] if options.get("spp", 1) is not None else []
    if options.get("own_out"):
        out = case  # the scene's folder, whatever it expands to, must stay inside the case's folder
    else:
        argv += ["--out", str(out)]
    argv += extra
    before = {p for p in folder.rglob("*")}
    started = time.monotonic()
    env = {**os.environ, "HOME": str(home)}
    timeout = options.get("timeout", TIMEOUT_S)
    try:
        done = subprocess.run(argv, capture_output=True, text=True, timeout=timeout, cwd=case, stdin=subprocess.PIPE,
                              env=env)
        rc, err, std = done.returncode, done.stderr.strip().splitlines(), done.stdout.strip().splitlines()
    except subprocess.TimeoutExpired as exc:
        std = (exc.stdout or b"").decode("utf-8", "replace").strip().splitlines()
        rc, err = ("stopped" if "timeout" in options else "hang"), []
        std = std[:1]  # the run's first line
    seconds = time.monotonic() - started
    new = {p for p in folder.rglob("*") if p.is_file()} - before
    outside = [p for p in new if out not in p.parents and p != out]
    line = (err[0] if err else (std[-1] if std else ""))[:160].replace("|", "\\|").replace(str(folder), "…")
    if err and len(err[0]) > 160:
        line += f" … ({len(err[0])} characters)"
    return f"| {label} | {rc} | {line} | {seconds:.1f} | {'yes: ' + str(len(outside)) if outside else 'no'} |"


def main() -> None:
    print("| case | exit | first line of stderr (or last of stdout) | s | files outside --out |")
    print("|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        for label, scene, extra, command, *options in list(cases(folder)):
            print(run_case(folder, label, scene, extra, command, *options), flush=True)


if __name__ == "__main__":
    main()
