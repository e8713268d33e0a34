#!/usr/bin/env bash
# Adaptive shading's GPU benchmark (issue #38): the paper's Table 1 on the GPU passes beside
# the CPU's (ssfx eval deferred --backend vulkan: every rest-pass schedule, GPU timestamps
# after a warm-up, medians), at two stalls, then one run per lookup on Sponza at 1920x1080,
# m = 4, with a heavy stall (the issue's "at least 1.6x faster than brute force with the
# stalled shader" on a real GPU), printing each schedule's rest-pass time and idle lanes; then
# the whole frame (ssfx frame) on Sponza at 1920x1080, m = 4, SAO and DDAA2 along a path through
# its three views: the per-pass profile (the issue's "under 4 ms per frame").
# Writes OUT/stall*/data/deferred.{md,json}, OUT/sponza_*/, OUT/frame_sponza.{apng,json}.
# Usage: scripts/bench_gpu_deferred.sh [SSFX] [OUT] [SIZE] [extra ssfx options, e.g. --device 0]
set -euo pipefail
S=${1:-build/release/ssfx}
OUT=${2:-out/bench_gpu_deferred}
SIZE=${3:-1024x768}
shift 3 || shift $#
mkdir -p "$OUT"
for stall in 400 4000; do
  "$S" eval deferred --backend vulkan --size "$SIZE" --stall "$stall" --reps 5 --out "$OUT/stall$stall" "$@" >/dev/null
  echo "## stall $stall"
  sed -n '/^### The same on the GPU/,$p' "$OUT/stall$stall/data/deferred.md"
done
ROOT=$(cd "$(dirname "$0")/.." && pwd)
SPONZA="$ROOT/scenes/sponza.json"
if [ -d "$ROOT/../shared/assets" ]; then
  for lookup in model hardware; do
    "$S" deferred --backend vulkan --lookup "$lookup" --scene "$SPONZA" --size 1920x1080 --ss 4 --stall 4000 \
      --brute-force --out "$OUT/sponza_$lookup" "$@"
  done
  # The frame: 16 frames through the views atrium -> arcade -> upper (scenes/sponza_path.json).
  for schedule in pixel list; do
    "$S" frame --scene "$SPONZA" --path "$ROOT/scenes/sponza_path.json" --frames 16 --size 1920x1080 --ss 4 --ao sao \
      --ao-param guardBand=64 --aa ddaa2 --schedule "$schedule" --profile "$OUT/frame_sponza_$schedule.json" \
      -o "$OUT/frame_sponza_$schedule.apng" "$@"
  done
else
  echo "bench_gpu_deferred: ../shared/assets absent, the Sponza runs are left out" >&2
fi
