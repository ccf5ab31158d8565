#!/usr/bin/env bash
# The Python packages a lent GPU machine lacks, as one archive that travels with the working tree
# (issue 42, item 4; ../shared/NOTES.md: its python3 is CPython 3.12 with numpy, scipy, numba, pillow,
# matplotlib, tqdm, imageio; nothing can be fetched there; the tree that travels is capped at 64 MiB).
#
#   scripts/gpu_bundle.sh            -> outputs/gpu_bundle/site.tar.xz (~30 MB), built here from PyPI
#
# Then, with the device tool:  carry ["outputs/gpu_bundle"], command "bash benchmarks/gpu_convergence.sh"
# (benchmarks/gpu_convergence.sh unpacks it and runs benchmarks/bench_convergence.py in one call).
#
# What is kept of the mitsuba wheel (62.6 MB, 194 MB unpacked): the cuda_ad_spectral and llvm_ad_spectral
# extensions, the shared libraries, the sun-and-sky data and the plugins the open sea's scenes load
# (PLUGINS below; a missing one fails the scene load with its name).
set -euo pipefail
cd "$(dirname "$0")/.."
OUT=outputs/gpu_bundle
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
PY=3.12
PLATFORM=manylinux_2_28_x86_64
# the versions of the lock (requirements.lock): the GPU run renders what the tests ran with
pin() { { grep -iE "^$1==" requirements.lock || true; } | head -1 | cut -d' ' -f1; }
PACKAGES=(mitsuba drjit colour-science OpenEXR pydantic pydantic-core annotated-types typing-inspection
          typing-extensions)
SPECS=()
for p in "${PACKAGES[@]}"; do
  spec=$(pin "$p")
  [ -n "$spec" ] || { echo "gpu_bundle: $p is not in requirements.lock" >&2; exit 2; }
  SPECS+=("$spec")
done
.venv/bin/python -m pip download --quiet --no-deps --only-binary=:all: --python-version "$PY" \
  --platform "$PLATFORM" --platform manylinux2014_x86_64 --platform manylinux_2_17_x86_64 \
  --implementation cp --dest "$WORK/wheels" "${SPECS[@]}"
mkdir -p "$WORK/site"
for wheel in "$WORK"/wheels/*.whl; do
  .venv/bin/python -m zipfile -e "$wheel" "$WORK/site"
done
PLUGINS="blendbsdf box constvolume dielectric diffuse disk hdrfilm homogeneous independent irregular merge
mesh_attribute multijitter orthogonal path perspective rayleigh rectangle regular roughdielectric specfilm
sphere sunsky uniform volpath"
M="$WORK/site/mitsuba"
find "$M" -maxdepth 1 -name '*.so' ! -name 'cuda_ad_spectral.*' ! -name 'llvm_ad_spectral.*' \
  ! -name 'mitsuba_alias*' ! -name 'mitsuba_ext*' ! -name 'lib*.so*' -delete
for plugin in "$M"/plugins/*.so; do
  name=$(basename "$plugin" .so)
  case " $(echo $PLUGINS) " in *" $name "*) ;; *) rm -f "$plugin" ;; esac
done
rm -rf "$M/include" "$M/cmake" "$M/pkgconfig" "$M/mitsuba_stubs" "$WORK/site/colour/htmlcov"
find "$WORK/site" -name '__pycache__' -prune -exec rm -rf {} +
mkdir -p "$OUT"
tar -C "$WORK/site" -cJf "$OUT/site.tar.xz" .
ls -l "$OUT/site.tar.xz"
