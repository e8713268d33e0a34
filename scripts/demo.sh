#!/usr/bin/env bash
# The demo job: draw the synthetic test scene at 1x/2x/4x, anti-alias it with every method,
# and time them (Table 3 layout). Outputs land in $2.
set -euo pipefail
SSFX=$1
OUT=$2
"$SSFX" testscene --out "$OUT"
for m in $("$SSFX" methods --ids); do
  case $m in
    ssaax2|ddaa2p) in="$OUT/scenex2.png" ;;
    ssaax4) in="$OUT/scenex4.png" ;;
    *) in="$OUT/scene.png" ;;
  esac
  "$SSFX" aa -m "$m" "$in" -o "$OUT/scene_$m.png"
done
echo "demo: wrote $(ls "$OUT" | wc -l) images to $OUT"
"$SSFX" bench --reps 20 --json "$OUT/bench.json"
