#!/usr/bin/env bash
# The demo job: the whole evaluation (ssfx eval report) -> $2/index.html. With the DDAA
# author's data beside the checkout (../shared/reference/ppaa), the report also reproduces
# the paper's rows from it.
set -euo pipefail
SSFX=$1
OUT=$2
ROOT=$(cd "$(dirname "$0")/.." && pwd)
REF="$ROOT/../shared/reference/ppaa"
# Adaptive shading's Table 1 also on the GPU passes (lavapipe without a GPU), beside the CPU's.
args=(eval report --out "$OUT" --deferred-backend vulkan)
if [ -d "$REF" ]; then args+=(--author-data "$REF"); else echo "demo: $REF absent, the paper's rows are left out" >&2; fi
"$SSFX" "${args[@]}"
echo
echo "Quality (PSNR, x8 upscale vs x8 render; the paper's Table 2 protocol):"
awk 'NR > 2 { if ($0 == "") exit; print }' "$OUT/data/quality.md"
echo
echo "Flicker on 'animated' (lower is steadier):"
cat "$OUT/data/temporal.md"
echo
echo "demo: open $OUT/index.html"
