#!/usr/bin/env bash
# Packs what the GPU checks need on a machine that has a GPU and its driver but none of our
# dependencies (the workplace's `device` machine: an NVIDIA H200 or H100 whose image holds
# CUDA, not Debian's libraries): the release binaries, every shared library they load but the
# C and C++ runtimes (the machine's own are newer and keep their ABI), the Vulkan loader, the
# Khronos validation layer with a manifest that points at the packed copy, and ../shared (the
# photograph, the reference drawings, the scenes' assets). scripts/device_checks.sh runs them.
#
# Usage: scripts/device_bundle.sh [BUILD] [DEST]   (defaults: build/release, .device)
# Writes DEST/bundle.tar.xz (about 27 MiB: 110 MiB unpacked, embree and the layer being most
# of it). DEST lies in the repository (ignored: .gitignore's /.device/), so that a device call
# can carry it beside the tree (64 MiB together): run(command="bash scripts/device_checks.sh",
# carry=[".device"]).
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=${1:-$ROOT/build/release}
DEST=${2:-$ROOT/.device}
bins=("$BUILD/ssfx" "$BUILD/tests/test_gpu" "$BUILD/bench/bench_ao")
for b in "${bins[@]}"; do
  [ -x "$b" ] || { echo "device_bundle: $b is missing (build the release preset first: make build)" >&2; exit 2; }
done
layer_json=/usr/share/vulkan/explicit_layer.d/VkLayer_khronos_validation.json
loader=$(ldconfig -p | awk '/libvulkan\.so\.1 .*x86-64/ {print $NF; exit}')
[ -f "$layer_json" ] || { echo "device_bundle: no $layer_json (Debian: vulkan-validationlayers)" >&2; exit 2; }
[ -n "$loader" ] || { echo "device_bundle: no libvulkan.so.1 (Debian: libvulkan1)" >&2; exit 2; }

rm -rf "$DEST"
STAGE=$(mktemp -d)
trap 'rm -rf "$STAGE"' EXIT
mkdir -p "$STAGE/bin" "$STAGE/lib" "$STAGE/layers"
cp "${bins[@]}" "$STAGE/bin/"
# The libraries the binaries, the loader and the layer load, but the C/C++ runtimes.
layer_lib=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["layer"]["library_path"])' "$layer_json")
case $layer_lib in /*) ;; *) layer_lib=$(ldconfig -p | awk -v n="$layer_lib" '$1 == n {print $NF; exit}') ;; esac
[ -f "$layer_lib" ] || { echo "device_bundle: the validation layer's library is missing" >&2; exit 2; }
runtime='^(libc|libm|libdl|librt|libpthread|libstdc\+\+|libgcc_s|ld-linux-x86-64|linux-vdso)\.'
for f in "${bins[@]}" "$loader" "$layer_lib"; do
  ldd "$f" | awk '$2 == "=>" && $3 ~ /^\// {print $3}'
done | sort -u | while read -r lib; do
  base=$(basename "$lib")
  [[ $base =~ $runtime ]] || cp -L "$lib" "$STAGE/lib/$base"
done
cp -L "$loader" "$STAGE/lib/libvulkan.so.1"
cp -L "$layer_lib" "$STAGE/lib/"
# The manifest's library path relative to the manifest (the loader resolves it so).
python3 - "$layer_json" "$STAGE/layers/VkLayer_khronos_validation.json" "$(basename "$layer_lib")" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
m["layer"]["library_path"] = "../lib/" + sys.argv[3]
json.dump(m, open(sys.argv[2], "w"), indent=1)
PY
if [ -d "$ROOT/../shared" ]; then
  mkdir -p "$STAGE/shared"
  for d in bench reference assets; do
    [ -d "$ROOT/../shared/$d" ] && cp -r "$ROOT/../shared/$d" "$STAGE/shared/"
  done
else
  echo "device_bundle: no ../shared: the photograph, the reference drawings and Sponza stay behind" >&2
fi
# What the tests were built against (they look for ../shared and write their outputs there).
{
  echo "commit $(git -C "$ROOT" rev-parse HEAD 2>/dev/null || echo unknown)"
  echo "built $(date -u +%Y-%m-%dT%H:%MZ) on $(. /etc/os-release && echo "$PRETTY_NAME")"
  # The test binaries' compiled-in paths (tests/CMakeLists.txt): where they look for ../shared.
  grep -o 'SSFX_SHARED_DIR=[^ ]*' "$BUILD/compile_commands.json" | head -1 | tr -d '\\"' | sed 's/=/ /' 
} >"$STAGE/BUILD_INFO"
mkdir -p "$DEST"
tar -C "$STAGE" -cf - . | xz -6 -T0 >"$DEST/bundle.tar.xz.part"
mv "$DEST/bundle.tar.xz.part" "$DEST/bundle.tar.xz"
size=$(du -sm "$DEST/bundle.tar.xz" | cut -f1)
echo "device_bundle: $DEST/bundle.tar.xz, ${size} MiB ($(du -sm "$STAGE" | cut -f1) MiB unpacked, $(ls "$STAGE/lib" | wc -l) libraries)"
if [ "$size" -gt 56 ]; then
  echo "device_bundle: over the 56 MiB that a device call can carry beside the tree" >&2
  exit 1
fi
