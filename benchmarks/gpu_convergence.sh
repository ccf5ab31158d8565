#!/usr/bin/env bash
# Issue 42 on a lent GPU, in one call of at most 6 minutes: the error curve of the default scene at
# 1920x1080 and the pipeline's frames (benchmarks/bench_convergence.py), arrays and JSON into $OUT.
#
# Here:   scripts/gpu_bundle.sh                      (once: outputs/gpu_bundle/site.tar.xz)
# There:  device run, carry ["outputs/gpu_bundle"], command "bash benchmarks/gpu_convergence.sh", timeout 420
# Back:   .venv/bin/python benchmarks/bench_convergence.py --grade <files_at>/convergence  (OIDN, the table)
#
# SIZE, SPP, REFERENCE_SPP, FRAMES and VARIANT override the defaults; with VARIANT=llvm_ad_spectral and
# a small SIZE it runs on the CPU machine too (the test before a lent call: SIZE=64x36 REFERENCE_SPP=256).
set -euo pipefail
cd "$(dirname "$0")/.."
SIZE=${SIZE:-1920x1080}
SPP=${SPP:-64,256,1024}
REFERENCE_SPP=${REFERENCE_SPP:-2048}
FRAMES=${FRAMES:-3}
VARIANT=${VARIANT:-cuda_ad_spectral}
OUT=${OUT:-outputs/gpu_run}
PYTHON=python3
if [ -x .venv/bin/python ]; then  # the project's own environment (this machine)
  PYTHON=.venv/bin/python
elif [ -f outputs/gpu_bundle/site.tar.xz ]; then  # the lent machine: the packages that travelled
  SITE=$(mktemp -d)
  tar -C "$SITE" -xJf outputs/gpu_bundle/site.tar.xz
  export PYTHONPATH="$SITE${PYTHONPATH:+:$PYTHONPATH}"
fi
mkdir -p "$OUT/convergence"
nvidia-smi --query-gpu=name,memory.total,driver_version --format=csv,noheader > "$OUT/device.txt" 2>/dev/null \
  || echo "no GPU: $(nproc) CPU cores" > "$OUT/device.txt"
"$PYTHON" benchmarks/bench_convergence.py --variant "$VARIANT" --size "$SIZE" --spp "$SPP" \
  --reference-spp "$REFERENCE_SPP" --frames "$FRAMES" --out "$OUT/convergence" 2>&1 \
  | grep -v 'WARN' | tee "$OUT/log.txt"
