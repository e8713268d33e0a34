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
for t in png apng aa exr camera frames scene obj gltf; do
  # The APNG target takes inputs of up to 256 KiB, so that it can reach per-frame costs
  # (many frames, large ancillary chunks); the others keep libFuzzer's default.
  maxlen=(); [ "$t" = apng ] && maxlen=(-max_len=262144)
  # The frame parsers are two short strings: a third of the time covers them (CI's budget).
  seconds=$SECONDS_PER_TARGET; [ "$t" = frames ] && seconds=$(((SECONDS_PER_TARGET + 2) / 3))
  bin=build/fuzz/fuzz/fuzz_$t
  work=build/fuzz/corpus_$t
  mkdir -p "$work"
  seeds=fuzz/corpus/$t
  if ls fuzz/regressions/* >/dev/null 2>&1; then "$bin" fuzz/regressions/* >/dev/null 2>&1; fi
  echo "fuzz: $t for ${seconds}s"
  "$bin" -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 "${maxlen[@]}" \
    -artifact_prefix=build/fuzz/crashes/${t}- "$work" "$seeds" 2>build/fuzz/$t.log ||
    { tail -n 40 build/fuzz/$t.log; echo "fuzz: $t found a crash (see build/fuzz/crashes)"; exit 1; }
  grep -E "^#[0-9]+.*DONE" build/fuzz/$t.log | tail -n 1 || true
done
echo "fuzz: no crashes"
