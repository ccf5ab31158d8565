"""A scene's coastal simulation: per-frame fields on disk, resume from checkpoints, CLI, render."""

import numpy as np
import pytest

from oceanrender.cli import main
from oceanrender.coastal.simulation import read_frame_fields, run_simulation
from oceanrender.io.frames import read_exr
from oceanrender.scene import scene_from_dict

TINY_COASTAL = {"cells": [24, 16], "size": [12.0, 8.0], "origin": [-6.0, -2.0], "slope": 0.2, "offshore_depth": 0.8,
                "wave_height": 0.1, "wave_period": 2.0, "order": 1, "cfl": 0.8, "spinup": 1.0,
                "checkpoint_interval": 0.5}


def tiny(**coastal):
    return scene_from_dict({"name": "tinycoast", "output": {"frames": [0, 3], "fps": 10.0},
                            "coastal": {**TINY_COASTAL, **coastal}})


def test_fields_are_stored_per_frame_and_a_resumed_run_is_identical(tmp_path):
    scene = tiny()
    report = run_simulation(scene, tmp_path)
    assert report.simulated == [0, 1, 2] and report.found == []
    first = [read_frame_fields(tmp_path, f) for f in range(3)]
    for frame, fields in enumerate(first):
        assert fields["t"] == pytest.approx(frame / 10.0)
        assert np.all(fields["h"] >= 0) and np.all(np.isfinite(fields["hu"]))
        assert fields["h"].shape == (16, 24)
    assert not np.array_equal(first[0]["h"], first[2]["h"])  # the waves move
    channels, meta = read_exr(tmp_path / "frame_0001.exr")
    assert set(channels) == {"h", "eta", "u", "v", "bed"}
    # the EXR stores float32: rounding ≤ 6e-8 of each value
    np.testing.assert_allclose(channels["h"], first[1]["h"], rtol=1e-6, atol=1e-7)
    assert meta["frame"] == 1

    # Lose the last frame: the rerun keeps the others and resumes from the checkpoint.
    (tmp_path / "frame_0002.npz").unlink()
    again = run_simulation(scene, tmp_path)
    assert again.found == [0, 1] and again.simulated == [2]
    assert again.resumed_from is not None
    # exact: the resumed run repeats the uninterrupted run's steps from its saved state
    np.testing.assert_array_equal(read_frame_fields(tmp_path, 2)["h"], first[2]["h"])


def test_changed_settings_start_the_simulation_anew(tmp_path):
    run_simulation(tiny(), tmp_path)
    report = run_simulation(tiny(wave_height=0.05), tmp_path)
    assert report.simulated == [0, 1, 2] and report.found == []


def test_cli_coastal_writes_fields(tmp_path, capsys):
    scene = tmp_path / "beach.toml"
    scene.write_text("[output]\nframes = [0, 2]\nfps = 10.0\n[coastal]\n"
                     + "".join(f"{k} = {list(v) if isinstance(v, list) else v}\n" for k, v in TINY_COASTAL.items()))
    assert main(["coastal", str(scene), "--out", str(tmp_path / "fields"), "--no-progress"]) == 0
    out = capsys.readouterr().out
    assert "simulated 2 frame(s)" in out and "cell-updates/s" in out
    assert (tmp_path / "fields" / "frame_0001.npz").is_file()
    assert (tmp_path / "fields" / "frame_0001.exr").is_file()


@pytest.mark.render
def test_cli_renders_a_tiny_coastal_scene(tmp_path, capsys):
    scene = tmp_path / "beach.toml"
    scene.write_text(
        "[output]\nframes = [0, 1]\nfps = 10.0\nresolution = [24, 16]\nspp = 4\n"
        f"directory = '{tmp_path / 'out'}'\n[render]\nwhite_spp = 64\nmax_depth = 6\n"
        "[camera]\nposition = [0.0, 0.0, 5.0]\ntarget = [0.0, 1.5, 0.0]\n[coastal]\n"
        + "".join(f"{k} = {list(v) if isinstance(v, list) else v}\n" for k, v in TINY_COASTAL.items()))
    assert main(["render", str(scene), "--no-progress"]) == 0
    channels, meta = read_exr(tmp_path / "out" / "beach" / "frame_0000.exr")
    assert np.all(np.isfinite(channels["Y"])) and channels["Y"].min() > 0
    assert (tmp_path / "out" / "beach" / "coastal" / "frame_0000.npz").is_file()
