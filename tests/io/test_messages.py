"""Quoted values in one-line errors."""

from oceanrender.io.messages import QUOTE_LIMIT, quoted


def test_short_values_are_quoted_whole():
    assert quoted("abc") == "'abc'" and quoted(1.5) == "1.5"


def test_long_values_are_cut_and_their_length_is_said():
    shown = quoted("x" * 5000)
    assert shown.startswith("'xxx") and shown.endswith("(5002 characters)")
    assert len(shown) <= QUOTE_LIMIT + len(" (5002 characters)")
