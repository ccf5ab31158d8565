#!/usr/bin/env bash
# Set up (or refresh) everything oceanrender needs on a fresh Debian 12 machine:
#   1. a libLLVM that drjit 1.5 can drive (Debian's libllvm19; LLVM 14/15 abort it),
#   2. a virtual environment in .venv with the project and its test tools.
# Idempotent: a stamp file records the pyproject.toml it was made from.
set -euo pipefail
cd "$(dirname "$0")/.."
PY=${PYTHON:-python3}
VENV=.venv
STAMP=$VENV/.oceanrender-stamp

llvm_ok() {  # a libLLVM of major version 16 or newer is present
  local f
  for f in /usr/lib/*-linux-gnu/libLLVM*.so* /usr/lib/llvm-*/lib/libLLVM*.so*; do
    case "${f##*/}" in
      libLLVM-1[6-9]*|libLLVM-[2-9][0-9]*|libLLVM.so.1[6-9]*|libLLVM.so.[2-9][0-9]*) return 0 ;;
    esac
  done
  return 1
}

if ! llvm_ok; then
  if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null; then
    echo "bootstrap: installing libllvm19 (drjit's LLVM backend) with apt-get" >&2
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq >/dev/null
    apt-get install -y -qq libllvm19 >/dev/null || echo "bootstrap: warning: apt-get install libllvm19 failed" >&2
  fi
  llvm_ok || echo "bootstrap: warning: no libLLVM >= 16 found: renders fall back to the slow scalar_spectral variant" >&2
fi

want="$(sha256sum pyproject.toml | cut -d' ' -f1)"
if [ -x "$VENV/bin/python" ] && [ -f "$STAMP" ] && [ "$(cat "$STAMP")" = "$want" ]; then
  exit 0
fi
echo "bootstrap: creating $VENV and installing oceanrender (first run: about a minute)" >&2
"$PY" -m venv "$VENV"
"$VENV/bin/python" -m pip install -q --upgrade pip 2>&1 | grep -v -i "warning" >&2 || true
"$VENV/bin/python" -m pip install -q -e ".[test]" 2>&1 | grep -v -i -E "warning|location .* is ignored" >&2 || true
"$VENV/bin/python" -c "import oceanrender, mitsuba, drjit, colour, OpenEXR" || { echo "bootstrap: install failed" >&2; exit 1; }
echo "$want" > "$STAMP"
