"""The lock file, the pyproject ranges and the installed environment agree."""

import subprocess
import sys
import tomllib
from pathlib import Path

from packaging.requirements import Requirement

import oceanrender
from oceanrender.runtime.environment import (
    PinCheck,
    canonical_name,
    compare_with_lock,
    core_dependencies,
    find_lock,
    parse_lock,
)

ROOT = Path(__file__).resolve().parents[2]

SAMPLE_LOCK = """\
# a comment with numpy==0.0 inside is not a pin
OpenEXR==3.5.3 \\
    --hash=sha256:0123
    # via oceanrender (pyproject.toml)
pydantic_core==2.50.5 ; python_version >= "3.11" \\
    --hash=sha256:4567
zope.interface==7.0
"""


def test_canonical_names_follow_pep503():
    assert canonical_name("OpenEXR") == "openexr"
    assert canonical_name("pydantic_core") == "pydantic-core"
    assert canonical_name("zope.interface") == canonical_name("Zope__Interface") == "zope-interface"


def test_parse_lock_reads_pins_with_hashes_and_markers_but_not_comments():
    assert parse_lock(SAMPLE_LOCK) == {"openexr": "3.5.3", "pydantic-core": "2.50.5", "zope-interface": "7.0"}


def test_compare_with_lock_tells_match_difference_and_absence():
    checks = compare_with_lock(("a", "b", "c", "d"), {"a": "1.0", "b": "2.0", "d": "4.0"},
                               {"a": "1.0", "b": "2.1", "c": "3.0", "d": None})
    assert checks == (PinCheck("a", "1.0", "1.0"), PinCheck("b", "2.1", "2.0"),
                      PinCheck("c", "3.0", None), PinCheck("d", None, "4.0"))
    assert [check.matches for check in checks] == [True, False, False, False]


def test_core_dependencies_are_the_run_time_requirements_without_extras():
    core = core_dependencies()
    assert {"numpy", "scipy", "mitsuba", "drjit", "colour-science", "openexr"} <= set(core)
    assert "pytest" not in core and "plyfile" not in core


def test_the_repository_lock_is_found_beside_the_package():
    assert find_lock(oceanrender.__file__) == ROOT / "requirements.lock"
    assert find_lock(ROOT / "no" / "such" / "file.py") is None


def test_lock_pins_every_requirement_inside_its_pyproject_range():
    """The lock is complete (every direct and test requirement pinned) and consistent
    with pyproject.toml: each pin satisfies the range people get without the lock."""
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    locked = parse_lock((ROOT / "requirements.lock").read_text())
    requirements = [Requirement(text) for text in
                    project["dependencies"] + project["optional-dependencies"]["test"]]
    for requirement in requirements:
        name = canonical_name(requirement.name)
        assert name in locked, f"{name} is not pinned in requirements.lock"
        assert requirement.specifier.contains(locked[name], prereleases=True), (
            f"{name}=={locked[name]} in the lock is outside pyproject's {requirement.specifier}")
    build = tomllib.loads((ROOT / "pyproject.toml").read_text())["build-system"]["requires"]
    for requirement in map(Requirement, build):  # bootstrap builds with --no-build-isolation
        assert requirement.specifier.contains(locked[canonical_name(requirement.name)])


def test_info_lists_every_core_dependency_against_the_lock():
    out = subprocess.run([sys.executable, "-m", "oceanrender", "info"], capture_output=True,
                         text=True, timeout=300, check=True).stdout
    assert "lock: " + str(ROOT / "requirements.lock") in out
    for name in core_dependencies():
        assert any(line.split()[:1] == [name] for line in out.splitlines()), f"{name} missing from info"
    assert f"of {len(core_dependencies())} core packages match the lock" in out
