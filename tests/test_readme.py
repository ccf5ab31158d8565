"""The README says what is true where a test can tell (issue 45, item 2)."""

import re
from pathlib import Path

import pytest

from tests.conftest import LEFT_OUT, SELECTED, TIER

README = Path(__file__).resolve().parents[1] / "README.md"


def stated_count(command: str) -> int:
    """N of the README's "`COMMAND` runs ~N tests" [-]."""
    # (a sentence may wrap anywhere)
    stated = re.search(rf"`{command}`\s+runs\s+~(\d+)\s+(?:more\s+)?tests", README.read_text(encoding="utf-8"))
    assert stated, f"README: the sentence '`{command}` runs ~N tests' is gone"
    return int(stated.group(1))


def test_the_readme_states_the_test_counts(request):
    """``make test`` runs ~N tests, ``make test-slow`` ~M more: each within 10 % of what this run counted (the "~").

    A fast-tier run (``make test``) selects the N and leaves the M out by its marker expression, so it
    checks both; a whole run (``make test-all``) checks N + M.
    """
    stash = request.config.stash
    tier = stash.get(TIER, None)
    if tier is None:
        pytest.skip("only a run of a whole tier knows its count (make test, make test-all)")
    stated = {"make test": stated_count("make test"), "make test-slow": stated_count("make test-slow")}
    counted = {"make test": stash[SELECTED], "make test-slow": stash.get(LEFT_OUT, 0)}
    if tier == "all":
        stated, counted = {"make test-all": sum(stated.values())}, {"make test-all": stash[SELECTED]}
    for command, count in counted.items():
        assert abs(stated[command] - count) <= 0.1 * count, (
            f"README says `{command}` runs ~{stated[command]} tests; this run counted {count}")
