"""The package graph is the pipeline: the import-linter contracts in pyproject.toml hold,
and they would catch an upward import or a cycle (docs/architecture.md)."""

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
LINT_IMPORTS = Path(sys.executable).with_name("lint-imports")


def lint_imports(package_parent: Path) -> subprocess.CompletedProcess:
    """Run ``lint-imports`` with the repository's contracts on the package found in ``package_parent``."""
    env = {**os.environ, "PYTHONPATH": str(package_parent)}
    return subprocess.run([str(LINT_IMPORTS), "--config", str(ROOT / "pyproject.toml"), "--no-cache"],
                          cwd=package_parent, env=env, capture_output=True, text=True, timeout=300)


def test_the_package_keeps_every_contract():
    result = lint_imports(ROOT)
    assert result.returncode == 0, result.stdout + result.stderr
    assert "0 broken" in result.stdout


@pytest.fixture
def package_copy(tmp_path):
    """A copy of the package beside nothing else, to break on purpose."""
    shutil.copytree(ROOT / "oceanrender", tmp_path / "oceanrender", ignore=shutil.ignore_patterns("__pycache__"))
    return tmp_path


def append_import(package: Path, module: str, line: str) -> None:
    path = package / "oceanrender" / (module.replace(".", "/") + ".py")
    path.write_text(path.read_text() + f"\n\ndef _injected():\n    {line}  # deliberately against the layers\n")


def test_an_upward_import_breaks_the_layers(package_copy):
    # the wave physics reaching up into the renderer, even lazily inside a function
    append_import(package_copy, "waves.sea", "from ..render import renderer")
    result = lint_imports(package_copy)
    assert result.returncode != 0
    assert "stages depend only downward BROKEN" in result.stdout
    assert "oceanrender.waves.sea -> oceanrender.render.renderer" in result.stdout


def test_a_cycle_between_sibling_modules_is_refused(package_copy):
    # optics.water importing the composition model, which imports optics.water: the old cycle
    append_import(package_copy, "optics.water", "from .components import composition_iops")
    result = lint_imports(package_copy)
    assert result.returncode != 0
    assert "no import cycles between sibling modules or packages BROKEN" in result.stdout


def test_the_motion_may_not_reach_up_into_the_settings(package_copy):
    # scene.settings validates animated sections with scene.motion; the old circle ran back up, lazily
    append_import(package_copy, "scene.motion", "from .settings import Scene")
    result = lint_imports(package_copy)
    assert result.returncode != 0
    assert "a scene's settings sit above its motion BROKEN" in result.stdout


def test_mitsuba_stays_out_of_the_physics(package_copy):
    append_import(package_copy, "surface.open_sea", "import mitsuba")
    result = lint_imports(package_copy)
    assert result.returncode != 0
    assert "only the renderer and the stages above it talk to Mitsuba and drjit BROKEN" in result.stdout
