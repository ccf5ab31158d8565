"""Fuzzing the CLI with mutated shipped scenes: every outcome is a one-line error (exit 2) or a finite frame.

Each example takes one scene of ``scenes/``, makes it tiny (8×6 pixels, 1 spp,
a 64² FFT, a coarse coastal grid: sizes only, so that a render takes seconds)
and applies one to three mutations: a key set to a hostile value (NaN, ±inf,
huge, negative, the wrong type, a device, a FIFO, a folder, a binary file,
``..``, a 5000-character string), a number scaled, a list element replaced, a
key or a section deleted, an unknown key added, a key set at the edge of its
useful range (mostly valid: these examples render), or the file itself broken
(not UTF-8, nested 1000 deep, cut short, a NUL byte). The mutated scene goes
through ``oceanrender render`` (``cli.main``) in a worker process
(``tests/fuzz_worker.py``), and the outcome must be one of:

* exit 2 with exactly one printable line on stderr, ``oceanrender: error: …``, and no file
  written anywhere;
* exit 0 with the frame's EXR under ``--out``, every pixel finite, and no file
  written outside ``--out``;
* exit 1 with one line naming the frame and the stage that made it non-finite
  (``… frame 0 …: stage geometry: …``), and that frame not written (issue 39).

A scene whose ``[output] directory`` starts with ``~`` or ``$`` is rendered
without ``--out``, from a worker whose ``$HOME`` is a folder of its own: the
folder must be taken literally, and nothing may land in ``$HOME``.

Anything else fails: a traceback, another exit status, a crash (the worker
dies) or a hang (no answer within :data:`TIMEOUT_S`). The number of examples is
:data:`EXAMPLES` (a handful, so CI spends about a minute), or
``OCEANRENDER_FUZZ_EXAMPLES``; ``OCEANRENDER_FUZZ_REPORT=FILE`` appends one
JSON line per example (docs/hardening.md has the figures of a long run).
"""

from __future__ import annotations

import copy
import datetime
import json
import math
import os
import shutil
import subprocess
import sys
import time
import tomllib
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from oceanrender.io.frames import read_exr

ROOT = Path(__file__).resolve().parents[1]
SCENES = sorted((ROOT / "scenes").glob("*.toml"))
#: Examples per run: a handful in CI (each render costs seconds), more with the environment variable.
EXAMPLES = int(os.environ.get("OCEANRENDER_FUZZ_EXAMPLES", "6"))
#: Longest one example may take [s]: the first render in a fresh worker compiles Mitsuba's kernels (~60 s).
TIMEOUT_S = float(os.environ.get("OCEANRENDER_FUZZ_TIMEOUT_S", "300"))
REPORT = os.environ.get("OCEANRENDER_FUZZ_REPORT")

NAN, INF = float("nan"), float("inf")
#: Values no key should accept silently. "@…" names a file made in the example's folder.
HOSTILE = [NAN, INF, -INF, 0, -1, -1.0e308, 1.0e308, 1.0e-300, 2**32, 2**63 - 1, -(2**63), 0.5, "", "x" * 5000,
           "..", "../escape", "/dev/zero", "/dev/stdin", "/", "@fifo", "@folder", "@binary", "@nul", True, [],
           [NAN, NAN, NAN], [INF, 0.0, 1.0], [0.0, 0.0, -1.0e6], {"a": 1}, "naïve", "a/b", "\t",
           "~/tilde", "~", "$HOME/out", "${HOME}", "$PWD/x"]
#: Keys a mutation may set although the shipped scenes leave them at their defaults.
EXTRA_KEYS = [("water", "iop_table"), ("render", "seed"), ("ocean", "seed"), ("ocean", "loop_period"),
              ("ocean", "resolution"), ("ocean", "cascades"), ("mesh", "segments"), ("vision", "display_luminance"),
              ("vision", "adaptation_luminance"), ("sun", "elevation"), ("sun", "sun_scale"), ("sun", "sky_scale"),
              ("water", "depth"), ("water", "ior"), ("camera", "position"), ("camera", "target"),
              ("output", "frames"), ("output", "resolution"), ("coastal", "checkpoint_interval"),
              ("coastal", "origin"), ("coastal", "bathymetry"), ("coastal", "initial_surface"), ("coastal", "cells"),
              (None, "name"), ("render", "white_spp"), ("render", "max_depth"), ("render", "variant"),
              ("output", "directory"), ("output", "spectral_bands"), ("ocean", "wind_speed")]
FACTORS = [-1.0, 0.0, 0.5, 2.0, 10.0, 1.0e3, 1.0e6]
#: Values at the edges of what a careful user may choose: mostly valid, so that many examples render.
EDGES = {("sun", "elevation"): [0.5, 1.0, 89.99, 90.0], ("sun", "turbidity"): [1.7, 10.0],
         ("camera", "position"): [[0.0, 0.0, 0.05], [0.0, 0.0, 500.0], [1.0e5, 1.0e5, 5.0]],
         ("camera", "target"): [[0.0, 10.0, 5.0], [0.0, 0.0, -10.0], [0.0, 1.0e4, 0.0]],
         ("camera", "fov"): [1.0, 179.0], ("ocean", "wind_speed"): [1.0e-9, 1.0e-6, 0.5, 30.0, 60.0], ("ocean", "choppiness"): [0.0, 2.0],
         ("ocean", "resolution"): [8, 16], ("ocean", "cascades"): [1, 3, 8], ("water", "depth"): [0.5, 1.0e4],
         ("water", "ior"): [1.1, 2.5], ("vision", "display_luminance"): [1.0, 1.0e4],
         ("vision", "adaptation_luminance"): [1.0e-3, 1.0e5], ("render", "max_depth"): [1, 2],
         ("mesh", "outer_radius"): [10.0, 1.0e5], ("mesh", "segments"): [3, 8], ("foam", "enabled"): [False],
         ("composition", "chlorophyll_mg_m3"): [0.0, 100.0], ("render", "seed"): [2**32 - 2],
         ("coastal", "wave_height"): [0.0, 1.9], ("coastal", "slope"): [0.5], ("coastal", "manning"): [0.0],
         ("coastal", "cells"): [[2, 2], [3, 200]], ("output", "fps"): [0.001, 1000.0],
         # Issue 39: near-zero and extreme physical values, large band counts, paths a shell would expand.
         ("ocean", "fetch"): [1.0, 1.0e7], ("ocean", "swell_height"): [1.0e-9, 30.0],
         ("ocean", "fractal_gamma"): [2.0], ("ocean", "surface_tension"): [1.0e-9, 0.1],
         ("foam", "decay_time"): [1.0e-3, 1.0e4], ("output", "spectral_bands"): [1, 94, 95, 470, 10**6],
         ("output", "directory"): ["~/tilde", "$HOME/out", "${PWD}/x", "~"],
         ("water", "surface_roughness"): [0.0, 1.0]}
#: Every optional model of the open sea on at once (the "models" mutation), so extreme values meet them all.
ALL_MODELS = {("foam", "enabled"): True, ("ocean", "fractal_gamma"): 0.5, ("ocean", "swell_height"): 1.0,
              ("output", "passes"): ["Z", "N", "P", "water", "foam", "objects", "water_path"],
              ("output", "spectral_bands"): 4}


# --- the scenes -------------------------------------------------------------------------------------------------

def tiny(scene: dict) -> dict:
    """A shipped scene made cheap to render: sizes only, so its physics and its keys stay those of the file."""
    scene = copy.deepcopy(scene)
    scene.setdefault("render", {})["white_spp"] = 16
    ocean = scene.setdefault("ocean", {})
    ocean["resolution"] = min(int(ocean.get("resolution", 64)), 64)
    if "mesh" in scene:
        scene["mesh"]["segments"] = min(int(scene["mesh"].get("segments", 48)), 48)
    if "coastal" in scene:
        scene["coastal"]["cells"] = [40, 30]
        scene["coastal"]["spinup"] = min(float(scene["coastal"].get("spinup", 2.0)), 2.0)
    return scene


def tiny_with(scene: dict, where: tuple[str, str], value) -> dict:
    """A copy of ``scene`` with ``[section] key = value``."""
    scene = copy.deepcopy(scene)
    scene.setdefault(where[0], {})[where[1]] = value
    return scene


BASES = {path.stem: tiny(tomllib.loads(path.read_text(encoding="utf-8"))) for path in SCENES}


def toml_value(value) -> str:
    """``value`` as TOML (inline tables and arrays; nan and inf as TOML writes them)."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if math.isnan(value):
            return "nan"
        if math.isinf(value):
            return "inf" if value > 0 else "-inf"
        return repr(value)
    if isinstance(value, (datetime.datetime, datetime.date, datetime.time)):
        return value.isoformat()  # a TOML date-time literal
    if isinstance(value, str):
        return json.dumps(value)  # a TOML basic string is a JSON string for these characters
    if isinstance(value, list):
        return "[" + ", ".join(toml_value(v) for v in value) + "]"
    if isinstance(value, dict):
        return "{" + ", ".join(f"{json.dumps(k)} = {toml_value(v)}" for k, v in value.items()) + "}"
    raise TypeError(type(value))


def toml_text(scene: dict) -> str:
    """A scene dict as a TOML file: top-level keys, then one table per section."""
    lines = [f"{json.dumps(k)} = {toml_value(v)}" for k, v in scene.items() if not isinstance(v, dict)]
    for section, table in scene.items():
        if isinstance(table, dict):
            lines.append(f"[{json.dumps(section)}]")
            lines += [f"{json.dumps(k)} = {toml_value(v)}" for k, v in table.items()]
    return "\n".join(lines) + "\n"


# --- the mutations ----------------------------------------------------------------------------------------------

@st.composite
def mutated_scenes(draw) -> tuple[str, dict | bytes, list[str]]:
    """(base name, mutated scene dict or raw file bytes, what was done)."""
    base = draw(st.sampled_from(sorted(BASES)))
    scene = copy.deepcopy(BASES[base])
    done: list[str] = []
    for _ in range(draw(st.integers(1, 3))):
        kind = draw(st.sampled_from(["hostile", "hostile", "scale", "element", "delete", "unknown", "extra", "file",
                                     "edge", "edge", "edge", "models"]))
        leaves = [(s, k) for s, t in scene.items() if isinstance(t, dict) for k in t] + \
                 [(None, k) for k, v in scene.items() if not isinstance(v, dict)]
        if kind == "file":
            text = toml_text(scene).encode("utf-8")
            how = draw(st.sampled_from(["latin-1", "deep", "cut", "nul", "deep table"]))
            done.append(f"file: {how}")
            if how == "latin-1":
                return base, text + b"# caf\xe9\n", done
            if how == "deep":
                return base, text + b"x = " + b"[" * 1000 + b"]" * 1000 + b"\n", done
            if how == "deep table":
                return base, text + b"y = " + b"{a = " * 1000 + b"1" + b"}" * 1000 + b"\n", done
            if how == "cut":
                return base, text[: draw(st.integers(0, max(len(text) - 1, 0)))], done
            return base, text.replace(b"\n", b"\x00\n", 1), done
        if kind == "models":
            for (section, key), value in ALL_MODELS.items():
                scene.setdefault(section, {})[key] = copy.deepcopy(value)
            done.append("every optional model on")
        elif kind == "edge":
            section, key = draw(st.sampled_from(sorted(EDGES, key=str)))
            value = copy.deepcopy(draw(st.sampled_from(EDGES[section, key])))
            scene.setdefault(section, {})[key] = value
            done.append(f"{section}.{key} = {value!r}")
        elif kind in ("hostile", "extra") or not leaves:
            section, key = draw(st.sampled_from(leaves if kind == "hostile" and leaves else EXTRA_KEYS))
            value = draw(st.sampled_from(HOSTILE))
            (scene.setdefault(section, {}) if section else scene)[key] = value
            done.append(f"{section}.{key} = {str(value)[:40]!r}")
        elif kind == "scale":
            numeric = [(s, k) for s, k in leaves
                       if isinstance((scene[s] if s else scene)[k], (int, float))
                       and not isinstance((scene[s] if s else scene)[k], bool)]
            if numeric:
                section, key = draw(st.sampled_from(numeric))
                table = scene[section] if section else scene
                factor = draw(st.sampled_from(FACTORS))
                table[key] = type(table[key])(table[key] * factor) if math.isfinite(table[key] * factor) else NAN
                done.append(f"{section}.{key} *= {factor}")
        elif kind == "element":
            lists = [(s, k) for s, k in leaves if isinstance((scene[s] if s else scene)[k], list)
                     and (scene[s] if s else scene)[k]]
            if lists:
                section, key = draw(st.sampled_from(lists))
                items = (scene[section] if section else scene)[key]
                index = draw(st.integers(0, len(items) - 1))
                items[index] = draw(st.sampled_from(HOSTILE))
                done.append(f"{section}.{key}[{index}] = {str(items[index])[:40]!r}")
        elif kind == "delete":
            section, key = draw(st.sampled_from(leaves))
            if section and draw(st.booleans()):
                del scene[section]
                done.append(f"del [{section}]")
            else:
                del (scene[section] if section else scene)[key]
                done.append(f"del {section}.{key}")
        elif kind == "unknown":
            section = draw(st.sampled_from([s for s, t in scene.items() if isinstance(t, dict)] + [None]))
            (scene[section] if section else scene)["colour_of_the_sea"] = 1.0
            done.append(f"{section}.colour_of_the_sea = 1.0")
    return base, scene, done


def materialise(value, folder: Path):
    """Replace "@fifo"/"@folder"/"@binary"/"@nul" placeholders by paths made in ``folder``."""
    if isinstance(value, list):
        return [materialise(v, folder) for v in value]
    if isinstance(value, dict):
        return {k: materialise(v, folder) for k, v in value.items()}
    if isinstance(value, str) and value.startswith("@"):
        path = folder / f"{value[1:]}.npy"
        if path.exists() or path.is_fifo():  # the same placeholder twice in one scene
            return str(path)
        if value == "@fifo":
            os.mkfifo(path)
        elif value == "@folder":
            path.mkdir()
        elif value == "@binary":
            path.write_bytes(bytes(range(256)) * 64)
        else:
            path = folder / "nul\x00name.csv"
            return str(path)
        return str(path)
    return value


# --- the worker -------------------------------------------------------------------------------------------------

class Worker:
    """``tests/fuzz_worker.py`` in a child process; restarted after a crash or a hang."""

    def __init__(self, cwd: Path) -> None:
        self.cwd, self.process = cwd, None

    def start(self) -> None:
        # NOTE: $HOME is a folder of the worker's own, so a file sent there by a '~' (issue 39) is seen; its
        # kernel caches link to the real ones, so the worker compiles no more than it would.
        home = self.cwd / "home"
        home.mkdir(exist_ok=True)
        for cache in (".drjit", ".cache"):
            real = Path.home() / cache
            if real.is_dir() and not (home / cache).exists():
                (home / cache).symlink_to(real)
        env = {**os.environ, "PYTHONPATH": str(ROOT), "HOME": str(home)}
        self.process = subprocess.Popen([sys.executable, "-m", "tests.fuzz_worker"], cwd=self.cwd, env=env,
                                        stdin=subprocess.PIPE, text=True)

    def stop(self) -> None:
        if self.process is not None and self.process.poll() is None:
            self.process.kill()
            self.process.wait()
        self.process = None

    def run(self, argv: list[str], logs: Path) -> dict:
        """{"rc", "traceback", "stdout", "stderr"} or {"crash": signal/exit status} or {"hang": True}."""
        if self.process is None:
            self.start()
        result = logs / "result.json"
        request = {"argv": argv, "stdout": str(logs / "stdout.txt"), "stderr": str(logs / "stderr.txt"),
                   "result": str(result)}
        self.process.stdin.write(json.dumps(request) + "\n")
        self.process.stdin.flush()
        deadline = time.monotonic() + TIMEOUT_S
        while not result.exists():
            if self.process.poll() is not None:
                status = self.process.returncode
                self.process = None
                return {"crash": status, "stderr": _read(logs / "stderr.txt")}
            if time.monotonic() > deadline:
                self.stop()
                return {"hang": True, "stderr": _read(logs / "stderr.txt")}
            time.sleep(0.02)
        answer = json.loads(result.read_text(encoding="utf-8"))
        return {**answer, "stdout": _read(logs / "stdout.txt"), "stderr": _read(logs / "stderr.txt")}


def _read(path: Path) -> str:
    return path.read_text(encoding="utf-8", errors="replace") if path.exists() else ""


@pytest.fixture(scope="module")
def worker(tmp_path_factory):
    worker = Worker(tmp_path_factory.mktemp("fuzz-cwd"))
    yield worker
    worker.stop()


def files_under(folder: Path) -> set[Path]:
    return {p for p in folder.rglob("*") if not p.is_dir()}


# --- the test ---------------------------------------------------------------------------------------------------

def judge(answer: dict, out: Path, before: set[Path], after: set[Path]) -> tuple[str, str | None]:
    """(outcome, problem or None) of one example."""
    if "crash" in answer:
        return "crash", f"the CLI died (status {answer['crash']}): {answer['stderr'][-2000:]}"
    if "hang" in answer:
        return "hang", f"no answer within {TIMEOUT_S:.0f} s: {answer['stderr'][-2000:]}"
    if answer["traceback"]:
        return "traceback", answer["traceback"]
    lines = [line for line in answer["stderr"].splitlines() if line.strip()]
    new = after - before
    if answer["rc"] == 2:
        if len(lines) != 1 or not lines[0].startswith("oceanrender: error: ") or not lines[0].isprintable():
            return "bad error", f"expected one line 'oceanrender: error: …' on stderr, got {lines[:5]}"
        if new:
            return "wrote on error", f"files written before the error: {sorted(map(str, new))[:5]}"
        return "refused", None
    if answer["rc"] == 1 and len(lines) == 1 and lines[0].startswith("oceanrender: error: ") \
            and ": stage " in lines[0] and lines[0].isprintable():
        # A frame the scene cannot make right (non-finite fields or pixels): one line, the frame not written.
        if any(p.name.startswith("frame_") for p in new):
            return "wrote on error", f"a refused frame was written: {sorted(map(str, new))[:5]}"
        return "frame refused", None
    if answer["rc"] != 0:
        return f"exit {answer['rc']}", f"exit {answer['rc']}, stderr {lines[-5:]}"
    outside = [p for p in new if out not in p.parents]
    if outside:
        return "escaped", f"files written outside --out: {sorted(map(str, outside))[:5]}"
    exrs = sorted(p for p in new if p.suffix == ".exr" and p.parent.name != "coastal")  # not the coastal store
    if not exrs:
        return "no frame", f"exit 0 but no frame EXR under {out}: {sorted(map(str, new))[:5]}"
    for exr in exrs:
        channels, _ = read_exr(exr)
        bad = {name: int(np.count_nonzero(~np.isfinite(c))) for name, c in channels.items()}
        if any(bad.values()):
            return "non-finite", f"{exr.name}: non-finite pixels per channel {bad}"
    return "rendered", None


@settings(max_examples=EXAMPLES, deadline=None, database=None, derandomize=EXAMPLES <= 6,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture,
                                 HealthCheck.data_too_large])
@given(case=mutated_scenes())
@example(case=("open_ocean", tiny_with(BASES["open_ocean"], ("sun", "elevation"), 0.5), ["sun.elevation = 0.5"]))
@example(case=("open_ocean", tiny_with(BASES["open_ocean"], ("output", "directory"), "~/tilde"),
               ["output.directory = '~/tilde'"]))
@pytest.mark.slow
def test_a_mutated_scene_is_refused_in_one_line_or_renders_finite_pixels(case, worker, tmp_path_factory):
    base, scene, done = case
    folder = tmp_path_factory.mktemp("fuzz")
    (folder / "scene").mkdir()
    out = folder / "out"
    path = folder / "scene" / f"{base}.toml"
    if isinstance(scene, bytes):
        path.write_bytes(scene)
    else:
        path.write_text(toml_text(materialise(scene, folder / "scene")), encoding="utf-8")
    before = files_under(folder) | files_under(worker.cwd)
    logs = folder.parent / f"{folder.name}-logs"
    logs.mkdir()
    started = time.monotonic()
    argv = ["render", str(path), "--resolution", "8x6", "--spp", "1", "--frames", "0:1", "--no-progress"]
    directory = scene.get("output", {}).get("directory") if isinstance(scene, dict) else None
    if isinstance(directory, str) and directory.startswith(("~", "$")):
        # The scene's own folder, taken literally from the worker's folder (issue 39): no --out to hide it.
        out = Path(os.path.abspath(os.path.join(worker.cwd, directory)))
    else:
        argv += ["--out", str(out)]
    answer = worker.run(argv, logs)
    after = files_under(folder) | files_under(worker.cwd)
    outcome, problem = judge(answer, out, before, after)
    if REPORT:
        with open(REPORT, "a", encoding="utf-8") as handle:
            handle.write(json.dumps({"base": base, "mutations": done, "outcome": outcome,
                                     "seconds": round(time.monotonic() - started, 2),
                                     "stderr": answer.get("stderr", "")[-300:], "problem": problem}) + "\n")
    shutil.rmtree(folder, ignore_errors=True)
    shutil.rmtree(logs, ignore_errors=True)
    if worker.cwd in out.parents and out.name != "home":
        shutil.rmtree(out, ignore_errors=True)  # a '~/…' folder of this example: the next starts clean
    assert problem is None, f"{base} with {done}: {problem}"
