#!/usr/bin/env bash
# The GPU passes' benchmark on every kind of content (issue #34): the synthetic drawing, a
# photograph (../shared/bench/astronaut1080.png) and a rendered scene (ssfx render atrium,
# colour at 1920x1080), each in both sampling modes. Each run prints the method table and
# the per-dispatch table (luma, classify, edges, resolve; share of pixels listed as edges)
# and writes its JSON to OUT/IMAGE-SAMPLING.json.
# Usage: scripts/bench_gpu.sh [SSFX] [OUT] [extra ssfx bench options, e.g. --reps 8 --device 0]
set -euo pipefail
S=${1:-build/release/ssfx}
OUT=${2:-out/bench_gpu}
shift 2 || shift $#
SRC=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$OUT"
images=(drawing)
photo="$SRC/../shared/bench/astronaut1080.png"
if [ -f "$photo" ]; then images+=(photograph); else echo "bench_gpu: no $photo: the photograph is skipped" >&2; fi
"$S" render atrium --view nave --size 1920x1080 --out "$OUT/scene" >/dev/null
images+=(scene)
for image in "${images[@]}"; do
  case $image in
    drawing) input=() ;;  # ssfx bench's own 1920x1080 drawing
    photograph) input=(--image "$photo") ;;
    scene) input=(--image "$OUT/scene/color.png") ;;
  esac
  for sampling in model hardware; do
    echo "== $image, sampling=$sampling"
    "$S" bench --backend vulkan -p "sampling=$sampling" "${input[@]}" --json "$OUT/$image-$sampling.json" "$@"
  done
done
