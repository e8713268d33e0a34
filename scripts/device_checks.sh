#!/usr/bin/env bash
# The GPU checks of issues #34 (anti-aliasing passes), #37 (GTAO) and #38 (adaptive shading,
# the frame) in one run on a machine with a GPU, from the bundle of scripts/device_bundle.sh:
#  1. the device and driver (nvidia-smi, ssfx devices);
#  2. test_gpu with the validation layer (synchronization validation on): model parity with
#     the CPU's bytes, hardware-mode agreement, AO and GTAO parity, adaptive shading parity;
#  3. #34: ssfx bench --backend vulkan in both sampling modes on the drawing, the photograph
#     and a rendered scene at 1920x1080, the drawing and the photograph (tiled 2 x 2) at
#     3840x2160, the photograph on both edge paths and with both of ddaa2's search reads;
#  4. #37: bench_ao's GPU entries for SAO and GTAO (low, high, ultra) at 1080p + 64 px guard
#     band, per-pass times from GPU timestamps;
#  5. #38: ssfx deferred on Sponza at 1920x1080, m = 4, both lookups, stall 400 and 4000, with
#     brute force; the frame (ssfx frame) along Sponza's views with --profile, both schedules;
#     the GPU Table 1 (ssfx eval deferred --backend vulkan) at 1024x768.
# Each stage has its own time limit and a failing stage does not stop the others; the limits
# add up to 9 minutes (a device call allows 10; run it with timeout_s=580), and a session's
# 15 minutes of device time leave no room for a second full run: try the script here first
# (SSFX_DEVICE_QUICK=1 on lavapipe), and on the device rerun only a failed stage if need be.
# Everything printed goes to OUT/checks.log; the stages' JSON and markdown to
# OUT/results.tar.gz (a device call returns at most 8 files).
#
# Usage, on the device from the repository root: bash scripts/device_checks.sh
#   here first: make build && scripts/device_bundle.sh   (then the device call carries .device)
# Environment: OUT (the results folder; the device tool sets it; default out/device_checks),
#   BUNDLE (default .device/bundle.tar.xz), DEVICE (ssfx's --device; default: a GPU, else
#   lavapipe), SSFX_DEVICE_QUICK=1 (small sizes and few rounds: to try the script on lavapipe),
#   STAGES (the stages to run, default "devices test_gpu aa ao deferred table1").
set -uo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
OUT=${OUT:-$ROOT/out/device_checks}
BUNDLE=${BUNDLE:-$ROOT/.device/bundle.tar.xz}
QUICK=${SSFX_DEVICE_QUICK:-0}
mkdir -p "$OUT"
exec > >(tee "$OUT/checks.log") 2>&1
[ -f "$BUNDLE" ] || { echo "device_checks: no $BUNDLE (run scripts/device_bundle.sh here, then carry .device)"; exit 2; }
D=$(mktemp -d)
R=$(mktemp -d)  # the stages' outputs, packed into OUT/results.tar.gz at the end
SCRATCH=$(mktemp -d)  # large outputs (frames) that do not come back
# (python3's tarfile where tar has no xz)
tar -C "$D" -xJf "$BUNDLE" 2>/dev/null ||
  python3 -c 'import sys, tarfile; tarfile.open(sys.argv[1]).extractall(sys.argv[2])' "$BUNDLE" "$D" ||
  { echo "device_checks: cannot unpack $BUNDLE"; exit 2; }
cat "$D/BUILD_INFO"
export LD_LIBRARY_PATH="$D/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
export VK_LAYER_PATH="$D/layers"
# NVIDIA's images keep the driver's ICD manifest under /usr/local/nvidia (the device tool's notes).
for icd in /usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json /usr/share/vulkan/icd.d/nvidia_icd.json \
  /etc/vulkan/icd.d/nvidia_icd.json; do
  if [ -z "${VK_DRIVER_FILES:-}" ] && [ -f "$icd" ]; then export VK_DRIVER_FILES=$icd VK_ICD_FILENAMES=$icd; fi
done
# The test binaries look for ../shared where it was at build time, the scripts beside the tree.
shared_dir=$(awk '$1 == "SSFX_SHARED_DIR" {print $2}' "$D/BUILD_INFO")
if [ -d "$D/shared" ]; then
  for link in "$shared_dir" "$ROOT/../shared"; do
    if [ -n "$link" ] && [ ! -e "$link" ]; then mkdir -p "$(dirname "$link")" && ln -s "$D/shared" "$link"; fi
  done
fi
S="$D/bin/ssfx"
DEVOPT=${DEVICE:+--device $DEVICE}  # (a name without spaces, or an index)

STAGES=${STAGES:-devices test_gpu aa ao deferred table1}
stage() {  # stage NAME LIMIT_S COMMAND...: runs it under a time limit, prints its status and time
  local name=$1 limit=$2 t0=$SECONDS rc
  shift 2
  [[ " $STAGES " == *" $name "* ]] || return 0
  echo "=== $name (limit ${limit} s) $(date -u +%T)"
  if [ "$(type -t "$1")" = function ]; then  # the stage functions below, exported
    timeout --kill-after=5 "$limit" bash -c "$1"
  else
    timeout --kill-after=5 "$limit" "$@"
  fi
  rc=$?
  echo "=== $name: rc $rc, $((SECONDS - t0)) s"
}

if [ "$QUICK" = 1 ]; then
  size=480x270 big=960x540 reps=4 warmup=1 aoFilter='gpu/(sao/full/1080p\+64|gtao/full/1080p\+64/low)'
  aoReps=1 frameSize=320x180 frames=2 evalSize=256x192 testLimit=90 testFilter='GpuShaders.*:GpuAa.*'
else
  size=1920x1080 big=3840x2160 reps=25 warmup=3 aoFilter='gpu/(sao/full/1080p\+64|gtao/full/1080p\+64/)'
  aoReps=5 frameSize=1920x1080 frames=16 evalSize=1024x768 testLimit=150 testFilter='*'
fi
width=${size%x*} bigWidth=${big%x*}
export ROOT D R SCRATCH S DEVOPT size big width bigWidth reps warmup frameSize frames

# 1. The device.
stage devices 30 bash -c "if command -v nvidia-smi >/dev/null; then nvidia-smi -L; fi; \"$S\" devices"

# 2. The GPU tests under the validation layer (SSFX_VK_VALIDATION: every context they make).
stage test_gpu "$testLimit" env SSFX_VK_VALIDATION=1 "$D/bin/test_gpu" --gtest_brief=1 --gtest_filter="$testFilter" \
  --gtest_output="json:$R/test_gpu.json"

# The photograph at the size asked (cropped or tiled from the 1920x1080 one) and tiled 2 x 2
# (python3 with PIL: the device's image has it).
cat >"$SCRATCH/tile.py" <<'PY'
import sys
from PIL import Image
src = Image.open(sys.argv[1]).convert("RGBA")
for name, wh in (("photo", sys.argv[3]), ("photo_big", sys.argv[4])):
    w, h = map(int, wh.split("x"))
    out = Image.new("RGBA", (w, h))
    for y in range(0, h, src.height):
        for x in range(0, w, src.width):
            out.paste(src, (x, y))
    out.save(f"{sys.argv[2]}/{name}.png")
PY

# 3. #34: the anti-aliasing passes, both sampling modes, three kinds of content, two sizes.
aa() {  # aa NAME SIZE_ARGS...: both sampling modes on one image
  local name=$1
  shift
  for sampling in model hardware; do
    echo "== $name, sampling=$sampling"
    "$S" bench --backend vulkan $DEVOPT -p "sampling=$sampling" --methods blur fxaa3c fxaa3d ddaa1 ddaa2 \
      --reps "$reps" --warmup "$warmup" --json "$R/aa-$name-$sampling.json" "$@" >"$R/aa-$name-$sampling.txt"
    cat "$R/aa-$name-$sampling.txt"
  done
}
aa_all() {
  local photo="$D/shared/bench/astronaut1080.png"
  aa "drawing-$size" --size "$width"
  aa "drawing-$big" --size "$bigWidth"
  "$S" render atrium --view nave --size "$size" $DEVOPT --out "$SCRATCH/scene" >/dev/null &&
    aa "atrium-$size" --image "$SCRATCH/scene/color.png"
  if [ -f "$photo" ]; then
    if python3 "$SCRATCH/tile.py" "$photo" "$SCRATCH" "$size" "$big"; then
      aa "photo-$size" --image "$SCRATCH/photo.png"
      aa "photo-$big" --image "$SCRATCH/photo_big.png"
      for path in list one-pass segments; do
        echo "== photo-$size, edges=$path (both modes)"
        for sampling in model hardware; do
          "$S" bench --backend vulkan $DEVOPT -p "sampling=$sampling" -p "edges=$path" \
            --methods blur fxaa3c fxaa3d ddaa1 ddaa2 --reps "$reps" --warmup "$warmup" \
            --image "$SCRATCH/photo.png" --json "$R/aa-photo-$size-$sampling-$path.json" | tail -8
        done
      done
      # fxaa3d's walk and ddaa2's search: both sides a step (the GPU's default, the paper's)
      # against one side a step (a CPU device's, docs/gpu.md), both modes, same run.
      for walk in 0 1; do
        for sampling in model hardware; do
          echo "== photo-$size, $sampling, SSFX_GPU_SIDE_SEARCH=$walk"
          SSFX_GPU_SIDE_SEARCH=$walk "$S" bench --backend vulkan $DEVOPT -p "sampling=$sampling" \
            --methods blur fxaa3d ddaa2 --reps "$reps" --warmup "$warmup" --image "$SCRATCH/photo.png" \
            --json "$R/aa-photo-$size-$sampling-sidesearch$walk.json" | tail -4
        done
      done
      # ddaa2's search reads in the hardware mode: the GPU's default (the device's filtered
      # reads) against the texel pairs that a CPU device takes (docs/gpu.md), same run.
      for reads in 1 0; do
        echo "== photo-$size, hardware, SSFX_GPU_COORDINATE_READS=$reads"
        SSFX_GPU_COORDINATE_READS=$reads "$S" bench --backend vulkan $DEVOPT -p sampling=hardware \
          --methods blur fxaa3d ddaa2 --reps "$reps" --warmup "$warmup" --image "$SCRATCH/photo.png" \
          --json "$R/aa-photo-$size-hardware-reads$reads.json"
      done
    else
      echo "device_checks: no PIL here: the photograph's runs are left out"
    fi
  fi
}
export -f aa aa_all
stage aa 120 aa_all

# 4. #37: SAO and GTAO on the GPU, per-pass times (bench_ao's counters: GPU timestamps).
stage ao 60 "$D/bin/bench_ao" --benchmark_filter="$aoFilter" --benchmark_repetitions="$aoReps" \
  --benchmark_report_aggregates_only=true --benchmark_out="$R/bench_ao.json" --benchmark_out_format=json

# 5. #38: adaptive shading against brute force on Sponza, the frame's profile, the GPU Table 1.
deferred_all() {
  local sponza="$ROOT/scenes/sponza.json"
  if [ ! -d "$ROOT/../shared/assets" ]; then
    echo "device_checks: no ../shared/assets: Sponza's runs are left out"
    return 0
  fi
  for lookup in model hardware; do
    for stall in 400 4000; do
      echo "== Sponza $size m=4, lookup $lookup, stall $stall"
      "$S" deferred --backend vulkan $DEVOPT --lookup "$lookup" --scene "$sponza" --size "$size" --ss 4 \
        --stall "$stall" --brute-force --out "$SCRATCH/sponza_${lookup}_$stall"
    done
  done
  for schedule in pixel list; do
    echo "== the frame on Sponza, $frameSize, m=4, SAO, DDAA2, schedule $schedule"
    "$S" frame $DEVOPT --scene "$sponza" --path "$ROOT/scenes/sponza_path.json" --frames "$frames" \
      --size "$frameSize" --ss 4 --ao sao --ao-param guardBand=64 --aa ddaa2 --schedule "$schedule" \
      --profile "$R/frame_sponza_$schedule.json" -o "$SCRATCH/frame_sponza_$schedule.apng"
  done
}
export -f deferred_all
stage deferred 120 deferred_all
stage table1 60 "$S" eval deferred --backend vulkan $DEVOPT --size "$evalSize" --reps 3 --out "$SCRATCH/table1"
if [ -f "$SCRATCH/table1/data/deferred.md" ]; then cp "$SCRATCH/table1/data/deferred.md" "$SCRATCH/table1/data/deferred.json" "$R/"; fi

tar -C "$R" -czf "$OUT/results.tar.gz" .
echo "device_checks: done in $SECONDS s; $OUT/checks.log, $OUT/results.tar.gz ($(ls "$R" | wc -l) files)"
