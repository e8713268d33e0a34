#!/usr/bin/env bash
# Throughput of ssfx aa on a 1920x1080 frame sequence (24 copies of the synthetic drawing),
# 2 threads: the numbered sequence in one call, the per-file CLI in a loop, and raw frames
# file to file; three runs each, frames per second.
# Usage: scripts/bench_sequence.sh [SSFX] [METHOD...]   (default build/release/ssfx ddaa2 fxaa3c)
set -euo pipefail
S=${1:-build/release/ssfx}
shift || true
if [ $# -gt 0 ]; then methods=("$@"); else methods=(ddaa2 fxaa3c); fi
D=$(mktemp -d)
trap 'rm -rf "$D"' EXIT
"$S" testscene --out "$D/sc" --width 1920 --height 1080 >/dev/null
mkdir -p "$D/seq" "$D/loop"
for i in $(seq -w 1 24); do cp "$D/sc/scene.png" "$D/seq/f.00$i.png"; done
"$S" aa -m noaa "$D/seq/f.%04d.png" -o "$D/in.rgba" --raw 1920x1080
fps() { echo "scale=1; 24 / ($2 - $1)" | bc; }
for m in "${methods[@]}"; do
  for rep in 1 2 3; do
    a=$(date +%s.%N)
    "$S" aa -m "$m" "$D/seq/f.%04d.png" -o "$D/out/f.%04d.png" --threads 2
    b=$(date +%s.%N)
    for f in "$D"/seq/*.png; do "$S" aa -m "$m" "$f" -o "$D/loop/$(basename "$f")" --threads 2; done
    c=$(date +%s.%N)
    "$S" aa --raw 1920x1080 -m "$m" "$D/in.rgba" -o "$D/out.rgba" --threads 2
    d=$(date +%s.%N)
    echo "$m run $rep: sequence $(fps "$a" "$b") fps, per-file loop $(fps "$b" "$c") fps, raw $(fps "$c" "$d") fps"
  done
done
