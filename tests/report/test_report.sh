#!/usr/bin/env bash
# ctest entry: writes a quick report and checks it in headless Chromium (test_report.mjs).
# Skips (exit 77) when Chromium, Node or playwright-core is not installed (scripts/setup.sh
# installs them).
set -euo pipefail
SSFX=$1
OUT=$2
HERE=$(cd "$(dirname "$0")" && pwd)
for tool in node "${CHROMIUM:-/usr/bin/chromium}"; do
  command -v "$tool" >/dev/null || { echo "skip: $tool not installed"; exit 77; }
done
[ -d "$HERE/node_modules/playwright-core" ] || { echo "skip: run scripts/setup.sh (npm ci in tests/report)"; exit 77; }
rm -rf "$OUT"
# Vulkan is loaded (the rendered atrium): no leak checking in sanitizer builds (tests/CMakeLists.txt).
ASAN_OPTIONS=detect_leaks=0 "$SSFX" eval report --quick --out "$OUT" 2>"$OUT.log" || { cat "$OUT.log"; exit 1; }
node "$HERE/test_report.mjs" "$OUT"
