#!/usr/bin/env bash
# Set up (or refresh) the separate virtual environment .venv-bench for
# benchmarks/bench_swe.py: oceanrender's shallow-water solver side by side with
# ANUGA 4.1 and PyClaw (clawpack 5.14). None of these is a dependency of the
# project itself; they live only in .venv-bench.
#
#   1. gfortran (apt-get, only when root and missing): clawpack has no wheel and
#      compiles its Riemann solvers and classic/sharpclaw steppers from Fortran.
#   2. numpy first (clawpack's meson build and ANUGA both compile/import against it),
#   3. anuga==4.1.* (a binary wheel),
#   4. meson-python, meson, ninja, then clawpack==5.14.* built from source with
#      --no-build-isolation so its extensions are compiled against the numpy of
#      this venv (an isolated build may pick another numpy),
#   5. the project itself, editable (`pip install -e .`), so the benchmark imports
#      `oceanrender` with its numba dependency.
#
# Idempotent: a stamp file records the hash of this script and pyproject.toml.
# First run: a few minutes (the clawpack build dominates). Each step's time is
# printed to stderr.
# Usage: bash scripts/bench_swe_env.sh   then
#        .venv-bench/bin/python benchmarks/bench_swe.py [--quick]
set -euo pipefail
SELF="$(cd "$(dirname "$0")" && pwd)/$(basename "$0")"
cd "$(dirname "$SELF")/.."
ROOT=$PWD
PY=${PYTHON:-python3}
VENV=.venv-bench
STAMP=$VENV/.bench-swe-stamp

want="$(cat "$SELF" pyproject.toml | sha256sum | cut -d' ' -f1)"
if [ -x "$VENV/bin/python" ] && [ -f "$STAMP" ] && [ "$(cat "$STAMP")" = "$want" ]; then
  exit 0
fi

step() {  # step NAME CMD...: run CMD, report its wall time, return its status
  local name=$1 t0 rc=0
  shift
  t0=$(date +%s)
  echo "bench_swe_env: $name ..." >&2
  "$@" || rc=$?
  echo "bench_swe_env: $name $([ "$rc" = 0 ] && echo done || echo "FAILED (exit $rc)") in $(($(date +%s) - t0)) s" >&2
  return "$rc"
}

if ! command -v gfortran >/dev/null; then
  if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null; then
    export DEBIAN_FRONTEND=noninteractive
    step "apt-get install gfortran" bash -c "apt-get update -qq >/dev/null && apt-get install -y -qq gfortran >/dev/null"
  else
    echo "bench_swe_env: warning: no gfortran and not root: clawpack will fail to build (PyClaw rows will say 'not installed')" >&2
  fi
fi

[ -x "$VENV/bin/python" ] || step "create $VENV" "$PY" -m venv "$VENV"
# NOTE: the venv's bin first on PATH: a build without isolation runs the `meson`
# and `ninja` executables installed in the venv.
export PATH="$PWD/$VENV/bin:$PATH"
pip_install() {  # quiet pip install; its log (minus absent local index folders) only on failure
  local rc=0 log
  log=$(mktemp)
  "$VENV/bin/python" -m pip install -q "$@" >"$log" 2>&1 || rc=$?
  [ "$rc" = 0 ] || grep -v -E "Location .* is ignored" "$log" | tail -40 >&2 || true
  rm -f "$log"
  return "$rc"
}
PIP=(pip_install)
step "pip upgrade" "${PIP[@]}" --upgrade pip
# NOTE: numpy before anything else, in the range numba (oceanrender) accepts.
step "numpy" "${PIP[@]}" "numpy>=1.26,<2.5"
step "anuga 4.1" "${PIP[@]}" "anuga==4.1.*" || echo "bench_swe_env: warning: anuga failed to install" >&2
step "meson-python, meson, ninja" "${PIP[@]}" meson-python meson ninja
# NOTE: no build isolation: build clawpack's Fortran extensions against this numpy.
if command -v gfortran >/dev/null; then
  step "clawpack 5.14 (from source, gfortran)" "${PIP[@]}" --no-build-isolation "clawpack==5.14.*" \
    || echo "bench_swe_env: warning: clawpack failed to build" >&2
fi
step "oceanrender (editable)" "${PIP[@]}" -e .

"$VENV/bin/python" - <<'EOF' >&2
import importlib.metadata as md
for name in ("numpy", "numba", "anuga", "clawpack", "oceanrender"):
    try:
        print(f"bench_swe_env: {name} {md.version(name)}")
    except md.PackageNotFoundError:
        print(f"bench_swe_env: {name} NOT INSTALLED")
import oceanrender  # noqa: F401  (the project must import; the baselines are optional)
EOF
# NOTE: stamp only a complete environment, so that a later run retries a failed baseline.
# (in /tmp: importing pyclaw writes pyclaw.log into the working directory)
if (cd /tmp && "$ROOT/$VENV/bin/python" -c "import anuga; from clawpack import pyclaw, riemann") >/dev/null 2>&1; then
  echo "$want" > "$STAMP"
else
  echo "bench_swe_env: warning: anuga or clawpack does not import; their rows will say 'not installed' (re-run to retry)" >&2
fi
