"""One-line messages for the user: values quoted short enough to read.

Every error the CLI prints is one line naming the file, the key and what was
expected (docs/hardening.md). A value echoed in it is the user's own text,
which can be thousands of characters long: :func:`quoted` shows at most
:data:`QUOTE_LIMIT` characters of it and says how long it was.
"""

from __future__ import annotations

#: The most characters of a value an error message quotes [-].
QUOTE_LIMIT = 80


def quoted(value: object, limit: int = QUOTE_LIMIT) -> str:
    """``repr(value)`` for an error message, cut to ``limit`` characters with the full length said.

    A 5000-character name is shown as ``'xxxx… (5002 characters)``, not echoed whole.
    """
    text = repr(value)
    if len(text) <= limit:
        return text
    return f"{text[:limit - 1]}… ({len(text)} characters)"
