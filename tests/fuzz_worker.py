"""A long-lived process that runs ``oceanrender.cli.main`` once per request, for the scene fuzz test.

Started by ``tests/test_fuzz_scenes.py`` as ``python -m tests.fuzz_worker``
from the repository root. Each request is one JSON line on stdin::

    {"argv": [...], "stdout": PATH, "stderr": PATH, "result": PATH}

The worker points file descriptors 1 and 2 at the two log files (so Mitsuba's
and drjit's own output is caught too), calls ``main(argv)`` exactly as the
``oceanrender`` console script does, and writes ``{"rc": int, "traceback": str
| null}`` to ``result`` (atomically). An exception escaping ``main`` is what
the console script would print as a traceback; a crash (signal) or a hang is
seen by the parent as a dead or silent worker. One process serves many
scenes so that Mitsuba's import and its JIT kernels are paid once, not per
scene (a fresh process spends ~30 s on them before a 8×6 frame).
"""

from __future__ import annotations

import json
import os
import sys
import traceback


def serve_one(request: dict) -> dict:
    """Run ``main(request["argv"])`` with fds 1 and 2 sent to the request's log files."""
    from oceanrender.cli import main  # noqa: PLC0415 (imported once, on the first request)

    saved = os.dup(1), os.dup(2)
    logs = (os.open(request["stdout"], os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o644),
            os.open(request["stderr"], os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o644))
    sys.stdout.flush()
    sys.stderr.flush()
    os.dup2(logs[0], 1)
    os.dup2(logs[1], 2)
    error = None
    try:
        try:
            rc = main(request["argv"])
        except SystemExit as exc:  # argparse's own errors
            rc = exc.code if isinstance(exc.code, int) else 1
        except BaseException:  # noqa: BLE001 (what would reach the user as a traceback)
            rc, error = 1, traceback.format_exc()
        sys.stdout.flush()
        sys.stderr.flush()
    finally:
        for fd, log in zip((1, 2), logs):
            os.dup2(saved[fd - 1], fd)
            os.close(log)
    return {"rc": int(rc or 0), "traceback": error}


def main() -> None:
    for line in sys.stdin:
        request = json.loads(line)
        result = serve_one(request)
        tmp = request["result"] + ".part"
        with open(tmp, "w", encoding="utf-8") as handle:
            json.dump(result, handle)
        os.replace(tmp, request["result"])


if __name__ == "__main__":
    main()
