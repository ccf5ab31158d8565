# The two quick-start commands (see README):
#   make render   render the default scene's short sequence into outputs/
#   make test     run the whole test suite
# Both set the machine up on first use (scripts/bootstrap.sh), from requirements.lock.
#   make lock     refresh the lock on purpose; replaces it only if the suite passes
#   make drift    newest allowed versions in .venv-drift, fast tests, warnings only

VENV := .venv
PY := $(VENV)/bin/python

.PHONY: setup render test bench info lock drift

setup:
	@bash scripts/bootstrap.sh

render: setup
	$(VENV)/bin/oceanrender render scenes/open_ocean.toml

test: setup
	$(PY) -m pytest -q

bench: setup
	$(PY) benchmarks/bench_frame.py

info: setup
	$(VENV)/bin/oceanrender info

lock:
	@bash scripts/lock.sh

drift:
	@bash scripts/drift.sh
