"""The installed Python environment against the committed lock (``requirements.lock``).

The test suite was run with exactly the versions in ``requirements.lock``; an
environment that differs (a newer numpy, an older scipy) may compute different last
bits or behave differently. These pure functions parse the lock, read what is
installed and compare the two; ``oceanrender info`` prints the result.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from importlib import metadata
from pathlib import Path

#: The lock file's name, in the repository root beside ``pyproject.toml``.
LOCK_NAME = "requirements.lock"

_PIN = re.compile(r"^([A-Za-z0-9][A-Za-z0-9._-]*)==([^\s;\\#]+)", re.MULTILINE)
_REQUIREMENT_NAME = re.compile(r"^\s*([A-Za-z0-9][A-Za-z0-9._-]*)")
_EXTRA_MARKER = re.compile(r"\bextra\s*==")


def canonical_name(name: str) -> str:
    """A distribution name in PEP 503 normal form (``OpenEXR`` → ``openexr``)."""
    return re.sub(r"[-_.]+", "-", name).lower()


def parse_lock(text: str) -> dict[str, str]:
    """The ``name==version`` pins of a pip-compile lock, by canonical name."""
    return {canonical_name(name): version for name, version in _PIN.findall(text)}


def find_lock(package_file: str | Path) -> Path | None:
    """The lock beside the source checkout that holds ``package_file``, if any.

    An editable install (``scripts/bootstrap.sh``) imports the package from the
    checkout, so the lock is two levels above ``oceanrender/__init__.py``; a wheel
    install has no lock and gets None.
    """
    candidate = Path(package_file).resolve().parents[1] / LOCK_NAME
    return candidate if candidate.is_file() else None


def core_dependencies(distribution: str = "oceanrender") -> tuple[str, ...]:
    """Canonical names of the distribution's direct run-time dependencies (no extras)."""
    names = []
    for requirement in metadata.requires(distribution) or ():
        if _EXTRA_MARKER.search(requirement):
            continue
        match = _REQUIREMENT_NAME.match(requirement)
        if match:
            names.append(canonical_name(match.group(1)))
    return tuple(dict.fromkeys(names))


def installed_version(name: str) -> str | None:
    """The installed version of a distribution, or None when it is not installed."""
    try:
        return metadata.version(name)
    except metadata.PackageNotFoundError:
        return None


@dataclass(frozen=True)
class PinCheck:
    """One package: what is installed and what the lock pins (None: absent)."""

    name: str
    installed: str | None
    locked: str | None

    @property
    def matches(self) -> bool:
        """True when the installed version is exactly the locked one."""
        return self.installed is not None and self.installed == self.locked


def compare_with_lock(names: tuple[str, ...], locked: dict[str, str],
                      installed: dict[str, str | None]) -> tuple[PinCheck, ...]:
    """Pair each package's installed version with its pin, in the order given."""
    return tuple(PinCheck(name, installed.get(name), locked.get(name)) for name in names)
