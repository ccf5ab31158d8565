"""A scene's coastal simulation: per-frame fields on disk, resume from checkpoints, CLI, render."""

import bisect
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from oceanrender.cli import main
from oceanrender.coastal.simulation import (
    SAME_STOP_S,
    STORE_VERSION,
    frame_time,
    read_frame_fields,
    run_simulation,
    settings_digest,
    solver_for_scene,
    stop_times,
)
from oceanrender.io.frames import read_exr
from tests.scenes import scene_from_dict, small_sea_text
from oceanrender.scene.settings import CoastalSettings

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


def test_stop_times_are_every_frame_and_the_checkpoint_times_between():
    coastal = CoastalSettings(spinup=1.0, checkpoint_interval=0.25)
    stops = stop_times(coastal, 10.0, 4)
    assert stops == [(0.25, None), (0.5, None), (0.75, None), (1.0, 0), (1.1, 1), (1.2, 2), (1.25, None),
                     (1.3, 3), (1.4, 4)]
    assert [tau for tau, f in stops if f is not None] == [frame_time(coastal, 10.0, f) for f in range(5)]
    # a checkpoint time within rounding of a frame time is that frame's stop: 3 x 0.1 s = 0.30000000000000004 s
    fine = CoastalSettings(spinup=0.0, checkpoint_interval=0.1)
    tau = [frame_time(fine, 10.0 / 3.0, f) for f in range(3)]
    assert 3 * 0.1 != tau[1] and abs(3 * 0.1 - tau[1]) < SAME_STOP_S
    assert stop_times(fine, 10.0 / 3.0, 2) == [(tau[0], 0), (0.1, None), (0.2, None), (tau[1], 1), (0.4, None),
                                               (0.5, None), (tau[2], 2)]
    assert stop_times(CoastalSettings(spinup=0.0, checkpoint_interval=5.0), 24.0, 0) == [(0.0, 0)]
    with pytest.raises(ValueError):
        stop_times(coastal, 10.0, -1)


@settings(max_examples=200, deadline=None)
@given(spinup=st.floats(0.0, 30.0), fps=st.floats(0.5, 120.0), interval=st.floats(0.1, 30.0),
       last=st.integers(0, 40), more=st.integers(1, 40))
def test_stop_times_do_not_depend_on_where_a_run_ends(spinup, fps, interval, last, more):
    """The schedule to a later frame starts with the schedule to an earlier one: every run stops alike."""
    coastal = CoastalSettings(spinup=spinup, checkpoint_interval=interval)
    short = stop_times(coastal, fps, last)
    long = stop_times(coastal, fps, last + more)
    assert long[: len(short)] == short
    assert short[-1] == (frame_time(coastal, fps, last), last)
    taus = [tau for tau, _ in long]
    assert all(b - a > SAME_STOP_S for a, b in zip(taus, taus[1:]))  # strictly increasing, no near-repeats
    assert [f for _, f in long if f is not None] == list(range(last + more + 1))
    for tau, frame in long:
        if frame is None:  # a checkpoint time k · interval, off every frame time
            k = round(tau / interval)
            assert k >= 1 and tau == k * interval
    # every checkpoint time below the last frame is a stop (itself, or a frame's within SAME_STOP_S)
    for k in range(1, math.floor(taus[-1] / interval) + 1):
        if k * interval < taus[-1] - SAME_STOP_S:
            i = bisect.bisect_left(taus, k * interval)
            assert min(abs(k * interval - tau) for tau in taus[max(0, i - 1): i + 1]) <= SAME_STOP_S


def test_an_uninterrupted_run_is_the_solver_stepping_through_the_schedule(tmp_path):
    scene = tiny()
    run_simulation(scene, tmp_path, write_exr=False)
    solver, bed, state = solver_for_scene(scene)
    for tau, frame in stop_times(scene.coastal, 10.0, 2):
        state = solver.advance(state, tau)
        assert state.t == tau
        if frame is not None:
            fields = read_frame_fields(tmp_path, frame)
            for key in ("h", "hu", "hv"):
                np.testing.assert_array_equal(fields[key], getattr(state, key))
            np.testing.assert_array_equal(fields["bed"], bed)
    with np.load(tmp_path / "checkpoint.npz") as data:
        assert float(data["t"]) == frame_time(scene.coastal, 10.0, 2)
        np.testing.assert_array_equal(data["h"], state.h)


def test_the_digest_holds_the_store_version():
    assert STORE_VERSION == 2
    assert settings_digest(tiny()) == settings_digest(tiny())
    assert settings_digest(tiny()) != settings_digest(tiny(checkpoint_interval=0.25))


def test_changed_settings_start_the_simulation_anew(tmp_path):
    run_simulation(tiny(), tmp_path)
    report = run_simulation(tiny(wave_height=0.05), tmp_path)
    assert report.simulated == [0, 1, 2] and report.found == []


def test_cli_coastal_writes_fields(tmp_path, capsys):
    scene = tmp_path / "beach.toml"
    scene.write_text(small_sea_text("[output]\nframes = [0, 2]\nfps = 10.0\n[coastal]\n"
                     + "".join(f"{k} = {list(v) if isinstance(v, list) else v}\n" for k, v in TINY_COASTAL.items())))
    assert main(["coastal", str(scene), "--out", str(tmp_path / "fields"), "--no-progress"]) == 0
    out = capsys.readouterr().out
    assert "simulated 2 frame(s)" in out and "cell-updates/s" in out
    assert (tmp_path / "fields" / "frame_0001.npz").is_file()
    assert (tmp_path / "fields" / "frame_0001.exr").is_file()


@pytest.mark.slow
@pytest.mark.render
def test_cli_renders_a_tiny_coastal_scene(tmp_path, capsys):
    scene = tmp_path / "beach.toml"
    scene.write_text(small_sea_text(
        "[output]\nframes = [0, 1]\nfps = 10.0\nresolution = [24, 16]\nspp = 4\n"
        f"directory = '{tmp_path / 'out'}'\n[render]\nwhite_spp = 64\nmax_depth = 6\n"
        "[camera]\nposition = [0.0, 0.0, 5.0]\ntarget = [0.0, 1.5, 0.0]\n[coastal]\n"
        + "".join(f"{k} = {list(v) if isinstance(v, list) else v}\n" for k, v in TINY_COASTAL.items())))
    assert main(["render", str(scene), "--no-progress"]) == 0
    channels, meta = read_exr(tmp_path / "out" / "beach" / "frame_0000.exr")
    assert np.all(np.isfinite(channels["Y"])) and channels["Y"].min() > 0
    assert (tmp_path / "out" / "beach" / "coastal" / "frame_0000.npz").is_file()
