"""The README says what is true where a test can tell (issue 45, item 2)."""

import re
from pathlib import Path

import pytest

from tests.conftest import COLLECTED, WHOLE_SUITE

README = Path(__file__).resolve().parents[1] / "README.md"


def test_the_readme_states_the_test_count(request):
    """``make test`` runs ~N tests: N within 10 % of what this run collected (the README's "~")."""
    if not request.config.stash.get(WHOLE_SUITE, False):
        pytest.skip("only a run of the whole suite knows its count (make test, .ci/run)")
    stated = re.search(r"`make test` runs ~(\d+) tests", README.read_text(encoding="utf-8"))
    assert stated, "README: the sentence '`make test` runs ~N tests' is gone"
    count = request.config.stash[COLLECTED]
    assert abs(int(stated.group(1)) - count) <= 0.1 * count, (
        f"README says ~{stated.group(1)} tests; this run collected {count}")
