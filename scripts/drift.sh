#!/usr/bin/env bash
# Drift check (the second job of .ci/run): install the newest versions that pyproject.toml's
# ranges allow into .venv-drift, ignoring requirements.lock, and run the fast tests (all but
# the Mitsuba renders) there. It reports drift as warnings and always exits 0: the locked
# suite is the one that must pass; this one tells whether the next `make lock` is safe.
# Logs: outputs/drift/{install,info,pytest}.log.
set -uo pipefail
cd "$(dirname "$0")/.."
PY=${PYTHON:-python3}
VENV=.venv-drift
LOG=outputs/drift
mkdir -p "$LOG"
warn() { echo "drift: WARNING: $*"; }

rm -rf "$VENV"
"$PY" -m venv "$VENV"
if ! timeout 1200 "$VENV/bin/python" -m pip install --upgrade --upgrade-strategy eager -e ".[test,spectra]" >"$LOG/install.log" 2>&1; then
  warn "could not install the newest allowed versions (registry unreachable or no solution; see $LOG/install.log)"
  exit 0
fi
timeout 600 "$VENV/bin/python" -m oceanrender info --all >"$LOG/info.log" 2>&1
# info's lines read "  NAME  INSTALLED  DIFFERS: lock pins LOCKED"
# (build tools are left out: this venv builds oceanrender in pip's isolated environment).
changed=$(grep -E 'DIFFERS: lock pins' "$LOG/info.log" | grep -v -E '^ +(setuptools|wheel|pip) ' \
  | sed -E 's/^ +([^ ]+) +(.*[^ ]) +DIFFERS: lock pins (.*)$/\1 \2 (lock \3)/' | paste -sd ';' | sed 's/;/; /g')
if [ -n "$changed" ]; then
  echo "drift: differs from the lock: $changed"
else
  echo "drift: the newest allowed versions are the locked ones"
fi

timeout 1800 "$VENV/bin/python" -m pytest -q -p no:cacheprovider -m "not render" >"$LOG/pytest.log" 2>&1
status=$?
# Counts in words of our own: CI reads pytest-style closing lines, and this job must not look like one.
failed=$(tail -n 1 "$LOG/pytest.log" | grep -o -E '[0-9]+ (failed|error)' | awk '{s += $1} END {print s + 0}')
case $status in
  0) echo "drift: the fast tests are green with the newest allowed versions: the next 'make lock' looks safe" ;;
  124) warn "the fast tests did not finish in 30 minutes with the newest versions (see $LOG/pytest.log)" ;;
  *) warn "the fast tests fail with the newest allowed versions, refresh the lock with care (see $LOG/pytest.log): $failed test(s) red" ;;
esac
exit 0
