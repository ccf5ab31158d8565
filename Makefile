# The two quick-start commands (see README):
#   make render   render the default scene's short sequence into outputs/
#   make test     run the test suite's fast tier (all but the tests marked slow), in minutes
# Both set the machine up on first use (scripts/bootstrap.sh), from requirements.lock.
#   make test-slow  the long tests (marked slow); CI runs both tiers; make test-all runs both in one process
#   make lock     refresh the lock on purpose; replaces it only if the suite passes
#   make drift    newest allowed versions in .venv-drift, fast tests, warnings only

VENV := .venv
PY := $(VENV)/bin/python

.PHONY: setup render test test-slow test-all bench info lock drift

setup:
	@bash scripts/bootstrap.sh

render: setup
	$(VENV)/bin/oceanrender render scenes/open_ocean.toml

test: setup
	$(PY) -m pytest -q -m "not slow"

test-slow: setup
	$(PY) -m pytest -q -m slow

test-all: setup
	$(PY) -m pytest -q

bench: setup
	$(PY) benchmarks/bench_frame.py

info: setup
	$(VENV)/bin/oceanrender info

lock:
	@bash scripts/lock.sh

drift:
	@bash scripts/drift.sh
