#!/usr/bin/env bash
# The AO passes' GPU benchmark (issue #36): the paper's Figure 5 (sample pass vs radius at
# 2560x1600: SAO with and without the pyramid, AlchemyAO) and Table 3 (per-pass times at the
# four resolutions with their guard bands) from GPU timestamps, interleaved rounds, medians
# (ssfx eval ao --backend vulkan --speed-only, which also runs the CPU's columns), then the
# Google Benchmark GPU entries of bench_ao (manual time = GPU timestamps) when it is built.
# Writes OUT/data/ao.md and OUT/data/ao.json, and OUT/bench_ao.json.
# Usage: scripts/bench_gpu_ao.sh [SSFX] [OUT] [extra ssfx eval options, e.g. --device 0]
set -euo pipefail
S=${1:-build/release/ssfx}
OUT=${2:-out/bench_gpu_ao}
shift 2 || shift $#
mkdir -p "$OUT"
"$S" eval ao --backend vulkan --speed-only --ao-scene none --out "$OUT" "$@"
sed -n '/^### GPU/,$p' "$OUT/data/ao.md"
B="$(dirname "$S")/bench/bench_ao"
if [ -x "$B" ]; then
  "$B" --benchmark_filter='gpu/' --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
    --benchmark_out="$OUT/bench_ao.json" --benchmark_out_format=json
fi
