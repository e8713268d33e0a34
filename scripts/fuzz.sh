#!/usr/bin/env bash
# Builds the libFuzzer targets (preset "fuzz", clang) and runs each for $1 seconds (default
# 60) from the committed seed corpus; first it replays every past crash in
# fuzz/regressions/ (each must now pass). A new crash fails the run; its input is kept under
# build/fuzz/crashes/ -- add it to fuzz/regressions/ with the fix.
set -euo pipefail
SECONDS_PER_TARGET=${1:-60}
cd "$(dirname "$0")/.."
if ! command -v clang++ >/dev/null; then echo "fuzz: clang++ missing (run scripts/setup.sh)" >&2; exit 1; fi
cmake --preset fuzz >/dev/null
cmake --build build/fuzz -j "$(nproc)" >/dev/null
mkdir -p build/fuzz/crashes
export LSAN_OPTIONS="suppressions=$PWD/fuzz/lsan.supp${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
# One target a core at a time (libFuzzer runs one process on one core): each target still gets
# its full time, and CI's fuzz step takes about 1 / nproc of its serial length.
run_target() {
  local t=$1 maxlen=() seconds=$SECONDS_PER_TARGET
  # The APNG target takes inputs of up to 256 KiB, so that it can reach per-frame costs
  # (many frames, large ancillary chunks); the others keep libFuzzer's default.
  [ "$t" = apng ] && maxlen=(-max_len=262144)
  # The frame parsers are two short strings: a third of the time covers them (CI's budget).
  [ "$t" = frames ] && seconds=$(((SECONDS_PER_TARGET + 2) / 3))
  local bin=build/fuzz/fuzz/fuzz_$t work=build/fuzz/corpus_$t seeds=fuzz/corpus/$t
  mkdir -p "$work"
  if ls fuzz/regressions/* >/dev/null 2>&1; then
    "$bin" fuzz/regressions/* >build/fuzz/$t.regressions.log 2>&1 ||
      { tail -n 40 build/fuzz/$t.regressions.log; echo "fuzz: $t fails a past crash in fuzz/regressions"; return 1; }
  fi
  "$bin" -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 "${maxlen[@]}" \
    -artifact_prefix=build/fuzz/crashes/${t}- "$work" "$seeds" 2>build/fuzz/$t.log ||
    { tail -n 40 build/fuzz/$t.log; echo "fuzz: $t found a crash (see build/fuzz/crashes)"; return 1; }
  echo "fuzz: $t for ${seconds}s: $(grep -E "^#[0-9]+.*DONE" build/fuzz/$t.log | tail -n 1)"
}
slots=$(nproc)
failed=0
running=0
for t in png apng aa exr camera frames scene obj gltf; do
  if [ "$running" -ge "$slots" ]; then wait -n || failed=1; running=$((running - 1)); fi
  run_target "$t" &
  running=$((running + 1))
done
while [ "$running" -gt 0 ]; do wait -n || failed=1; running=$((running - 1)); done
if [ "$failed" -ne 0 ]; then echo "fuzz: a target failed (above)" >&2; exit 1; fi
echo "fuzz: no crashes"
