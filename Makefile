# The two quick-start commands (see README):
#   make render   render the default scene's short sequence into outputs/
#   make test     run the whole test suite
# Both set the machine up on first use (scripts/bootstrap.sh).

VENV := .venv
PY := $(VENV)/bin/python

.PHONY: setup render test bench info

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
