"""Frames on a real Dask LocalCluster (two worker processes): identical frames, a killed worker, the CLI."""

import os
import signal
import threading
import time
from pathlib import Path

import imageio.v3 as iio
import numpy as np
import pytest

from oceanrender.cli import main
from oceanrender.io.frames import FRAME_CHANNELS, frame_is_complete, read_exr
from oceanrender.pipeline import frame_paths, render_sequence
from oceanrender.production.distributed import render_distributed, sequence_key, worker_threads
from tests.scenes import scene_from_dict, small_sea_text

pytestmark = pytest.mark.render

TINY = {
    "output": {"resolution": [24, 16], "spp": 4, "frames": [0, 4]},
    "ocean": {"resolution": 16, "patch_size": 40.0},
    "render": {"white_spp": 64, "max_depth": 6},
}


def tiny_scene(**output):
    data = {"name": "tiny", **{k: dict(v) for k, v in TINY.items()}}
    data["output"].update(output)
    return scene_from_dict(data)


def tiny_toml(tmp_path: Path) -> Path:
    path = tmp_path / "tiny.toml"
    path.write_text(small_sea_text("[output]\nframes = [0, 4]\nresolution = [24, 16]\nspp = 4\n"
                    f"directory = '{tmp_path / 'out'}'\n"
                    "[ocean]\nresolution = 16\npatch_size = 40.0\n[render]\nwhite_spp = 64\nmax_depth = 6\n"))
    return path


def assert_same_frame(mine, theirs, frame: int) -> None:
    """The renderer's XYZ bit for bit; the display RGB to float32 rounding and the PNG to one 8-bit level.

    The vision model (colour-science, numpy, OpenBLAS) gives last-bit differences between
    processes for the same XYZ (seen in about 1 run in 5: ≤ 3e-6 relative, up to 5e-5 where
    a channel nearly cancels, i.e. ≤ 1e-7 of the channel's scale; Dask workers run OpenBLAS
    on one thread, and SIMD paths depend on array alignment).
    """
    a, _ = read_exr(mine.exr)
    b, _ = read_exr(theirs.exr)
    for name in "XYZ":
        np.testing.assert_array_equal(a[name], b[name], err_msg=f"frame {frame} channel {name}")
    for name in "RGB":
        # Relative to the channel's scale: R = 3.24 X − 1.54 Y − 0.50 Z cancels where R is small.
        scale = float(np.abs(a[name]).max())
        np.testing.assert_allclose(a[name], b[name], rtol=1e-5, atol=1e-6 * scale, err_msg=f"frame {frame} channel {name}")
    png_a, png_b = iio.imread(mine.png).astype(int), iio.imread(theirs.png).astype(int)
    assert np.abs(png_a - png_b).max() <= 1 and np.mean(png_a != png_b) < 0.01


@pytest.fixture(scope="module")
def cluster():
    """A LocalCluster of two worker processes, shared by the tests of this module."""
    from dask.distributed import Client  # noqa: PLC0415

    from oceanrender.production.distributed import local_cluster  # noqa: PLC0415

    with local_cluster(2) as local, Client(local) as client:
        yield local, client


def test_worker_threads_share_the_cores():
    assert worker_threads(2, cores=2) == 1
    assert worker_threads(3, cores=16) == 5
    assert worker_threads(4, cores=2) == 1
    with pytest.raises(ValueError, match="at least one worker"):
        worker_threads(0, cores=2)


def test_sequence_key_names_what_the_pixels_depend_on():
    scene = tiny_scene()
    key = sequence_key(scene, "llvm_ad_spectral", 4, (24, 16), None)
    assert key == sequence_key(tiny_scene(), "llvm_ad_spectral", 4, (24, 16), None)
    assert key != sequence_key(tiny_scene(spp=8), "llvm_ad_spectral", 4, (24, 16), None)
    assert key != sequence_key(scene, "scalar_spectral", 4, (24, 16), None)
    assert key != sequence_key(scene, "llvm_ad_spectral", 8, (24, 16), None)
    assert key != sequence_key(scene, "llvm_ad_spectral", 4, (32, 16), None)
    assert key != sequence_key(scene, "llvm_ad_spectral", 4, (24, 16), "/data/coastal")
    # The frame range is not part of it: a worker renders any frame of the sequence.
    assert key == sequence_key(tiny_scene(frames=[10, 20], directory="elsewhere"), "llvm_ad_spectral", 4, (24, 16),
                               None)


@pytest.mark.slow
def test_cli_on_a_cluster_writes_the_single_process_frames(variant, cluster, tmp_path, capsys):
    local, client = cluster
    toml = tiny_toml(tmp_path)
    single = render_sequence(tiny_scene(), tmp_path / "single", variant)
    assert single.rendered == [0, 1, 2, 3]

    assert main(["render", str(toml), "--cluster", local.scheduler_address, "--no-progress"]) == 0
    out = tmp_path / "out" / "tiny"
    assert "2 Dask worker(s)" in capsys.readouterr().out
    for frame in range(4):
        mine, theirs = frame_paths(tmp_path / "single", frame), frame_paths(out, frame)
        assert frame_is_complete(theirs.exr, theirs.png, (24, 16))
        assert_same_frame(mine, theirs, frame)
        channels, meta = read_exr(theirs.exr)
        assert meta["frame"] == frame and meta["spp"] == 4 and set(FRAME_CHANNELS) <= set(channels)
        assert channels["Y"].mean() > 0
    # Both workers took part (four frames, two idle workers: the scheduler spreads them).
    # A second run finds every frame intact and submits nothing.
    stamps = [frame_paths(out, f).exr.stat().st_mtime_ns for f in range(4)]
    assert main(["render", str(toml), "--cluster", local.scheduler_address, "--no-progress"]) == 0
    assert "rendered 0 frame(s), skipped 4" in capsys.readouterr().out
    assert stamps == [frame_paths(out, f).exr.stat().st_mtime_ns for f in range(4)]


@pytest.mark.slow
def test_frames_of_a_killed_worker_are_rendered_again_exactly_once(variant, cluster, tmp_path):
    local, client = cluster
    # A new size: each worker loads a new scene; frames of a few seconds each, so a kill lands mid-task.
    scene = tiny_scene(resolution=[96, 64], spp=32, frames=[0, 6])
    pids = client.run(os.getpid)
    killed = {}

    def kill_a_busy_worker():
        deadline = time.monotonic() + 120
        while time.monotonic() < deadline:
            busy = sorted((worker, keys) for worker, keys in client.processing().items() if keys)
            if busy:
                worker, keys = busy[0]
                killed.update(pid=pids[worker], keys=list(keys))
                os.kill(pids[worker], signal.SIGKILL)
                return
            time.sleep(0.02)

    results, written = [], []
    killer = threading.Thread(target=kill_a_busy_worker)
    killer.start()
    report = render_distributed(scene, tmp_path, variant, client, on_result=results.append,
                                on_frame=lambda frame, seconds, skipped: written.append((frame, skipped)))
    killer.join()

    assert killed, "no worker was busy within 2 minutes"
    assert report.failed == []
    assert sorted(report.rendered) == list(range(6)) and len(report.rendered) == 6
    assert sorted(written) == [(f, False) for f in range(6)]
    for frame in range(6):
        paths = frame_paths(tmp_path, frame)
        assert frame_is_complete(paths.exr, paths.png, (96, 64))
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(
        [f"frame_{f:04d}.{ext}" for f in range(6) for ext in ("exr", "png")])
    # The frame the dead worker held was computed again, by another process.
    lost = [int(key.split("-")[2]) for key in killed["keys"]]
    by_frame = {r.rendered.frame: r.worker_pid for r in results}
    assert lost and all(by_frame[frame] != killed["pid"] for frame in lost)
    # The nanny restarted the dead worker: two workers again.
    deadline = time.monotonic() + 60
    while len(client.scheduler_info()["workers"]) < 2 and time.monotonic() < deadline:
        time.sleep(0.2)
    assert len(client.scheduler_info()["workers"]) == 2


def test_cli_refuses_bad_dask_options_before_any_work(tmp_path, capsys):
    toml = tiny_toml(tmp_path)
    assert main(["render", str(toml), "--workers", "0"]) == 2
    assert "--workers: expected a number of worker processes in [1, 256], got 0" in capsys.readouterr().err
    assert main(["render", str(toml), "--cluster", "localhost:8786"]) == 2
    assert "--cluster: expected a Dask scheduler address like tcp://HOST:8786" in capsys.readouterr().err
    with pytest.raises(SystemExit):
        main(["render", str(toml), "--workers", "2", "--cluster", "tcp://127.0.0.1:8786"])
    assert not (tmp_path / "out").exists()


@pytest.mark.slow
def test_a_coastal_scene_simulates_once_on_the_client_and_renders_from_its_fields(variant, cluster, tmp_path):
    from tests.coastal.test_simulation import TINY_COASTAL  # noqa: PLC0415 (tests/ is on sys.path under pytest)

    local, client = cluster
    scene = scene_from_dict({"name": "tinycoast", "output": {"frames": [0, 3], "fps": 10.0, "resolution": [24, 16],
                                                             "spp": 4},
                             "render": {"white_spp": 64, "max_depth": 6},
                             "camera": {"position": [0.0, 0.0, 5.0], "target": [0.0, 1.5, 0.0]},
                             "coastal": TINY_COASTAL})
    report = render_distributed(scene, tmp_path / "dask", variant, client)
    assert report.failed == [] and sorted(report.rendered) == [0, 1, 2]
    assert report.simulation.simulated == [0, 1, 2]  # on the client, before the frames
    assert (tmp_path / "dask" / "coastal" / "frame_0002.npz").is_file()
    single = render_sequence(scene, tmp_path / "single", variant)
    assert single.simulation.simulated == [0, 1, 2]
    for frame in range(3):
        assert_same_frame(frame_paths(tmp_path / "single", frame), frame_paths(tmp_path / "dask", frame), frame)
    last, first = (read_exr(frame_paths(tmp_path / "dask", f).exr)[0]["Y"] for f in (2, 0))
    assert not np.array_equal(last, first)  # the water moves


def test_workers_run_without_dasks_malloc_trim_setting(cluster):
    local, client = cluster
    assert set(client.run(lambda: os.environ.get("MALLOC_TRIM_THRESHOLD_")).values()) == {None}


def test_the_worker_config_file_for_other_machines_matches_the_local_one():
    import yaml  # noqa: PLC0415 (a dask dependency)

    from oceanrender.production.distributed import WORKER_CONFIG  # noqa: PLC0415

    settings = yaml.safe_load((Path(__file__).resolve().parents[2] / "scripts" / "dask.yaml").read_text())
    flat = {"distributed.nanny.pre-spawn-environ." + key: value
            for key, value in settings["distributed"]["nanny"]["pre-spawn-environ"].items()}
    assert flat == WORKER_CONFIG
