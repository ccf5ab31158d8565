#!/usr/bin/env bash
# Set up (or refresh) everything oceanrender needs on a fresh Debian 12 machine:
#   1. a libLLVM that drjit 1.5 can drive (Debian's libllvm19; LLVM 14/15 abort it),
#   2. Mesa's EGL (headless OpenGL for `oceanrender validate-shader`),
#   3. a virtual environment in .venv with exactly the versions in requirements.lock
#      (hash-checked), then the project itself, editable.
# Idempotent: a stamp file records the lock and pyproject.toml it was made from;
# OCEANRENDER_FRESH_VENV=1 rebuilds .venv regardless (CI does).
set -euo pipefail
cd "$(dirname "$0")/.."
# One set-up at a time: `make render` and `make test` started together (or a render beside the tests)
# would both rebuild .venv at once and break it (seen: pip's files removed under the other pip). The
# second waits here for the first, then finds .venv ready by its stamp and goes on.
exec 9>.bootstrap.lock
flock 9
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

# Headless OpenGL for `oceanrender validate-shader` (moderngl over EGL): Mesa's EGL and its drivers
# (llvmpipe, the software rasteriser, when there is no GPU).
egl_ok() { ls /usr/lib/*-linux-gnu/libEGL_mesa.so.0 /usr/lib/*-linux-gnu/libEGL.so.1 >/dev/null 2>&1; }
if ! egl_ok; then
  if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null; then
    echo "bootstrap: installing Mesa's EGL (libegl1 libegl-mesa0 libgl1-mesa-dri) with apt-get" >&2
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq >/dev/null
    apt-get install -y -qq libegl1 libegl-mesa0 libgl1-mesa-dri >/dev/null \
      || echo "bootstrap: warning: apt-get install of Mesa's EGL failed" >&2
  fi
  egl_ok || echo "bootstrap: warning: no EGL found: validate-shader cannot create an OpenGL context" >&2
fi

# The stamp is the hash of the lock and of pyproject.toml: a changed lock rebuilds .venv.
want="$(cat requirements.lock pyproject.toml | sha256sum | cut -d' ' -f1)"
if [ -z "${OCEANRENDER_FRESH_VENV:-}" ] && [ -x "$VENV/bin/python" ] && [ -f "$STAMP" ] && [ "$(cat "$STAMP")" = "$want" ]; then
  exit 0
fi
echo "bootstrap: creating $VENV from requirements.lock (first run: one to three minutes)" >&2
rm -rf "$VENV"
"$PY" -c 'import sys; sys.exit(sys.version_info[:2] != (3, 11))' \
  || echo "bootstrap: warning: requirements.lock was made for CPython 3.11; $("$PY" -V) may not find every pinned wheel" >&2
"$PY" -m venv "$VENV"
quiet() { grep -v -i -E "warning|location .* is ignored" >&2 || true; }
# Exactly the locked versions, each checked against its hash; --no-deps: the lock is complete.
"$VENV/bin/python" -m pip install -q --require-hashes --no-deps -r requirements.lock 2>&1 | quiet
# The project itself, built with the locked setuptools (no isolated build env that would fetch the newest).
"$VENV/bin/python" -m pip install -q --no-deps --no-build-isolation -e . 2>&1 | quiet
"$VENV/bin/python" -m pip check >&2 || { echo "bootstrap: pip check failed: requirements.lock is inconsistent" >&2; exit 1; }
"$VENV/bin/python" -c "import oceanrender, mitsuba, drjit, colour, OpenEXR" || { echo "bootstrap: install failed" >&2; exit 1; }
echo "$want" > "$STAMP"
