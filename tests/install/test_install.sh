#!/usr/bin/env bash
# Installs ssfx into a temporary prefix, then builds and runs a tiny consumer with
# find_package(ssfx) and with pkg-config.
set -euo pipefail
BUILD=$1
SRC=$2
OUT=$3
rm -rf "$OUT" && mkdir -p "$OUT"
cmake --install "$BUILD" --prefix "$OUT/prefix" >/dev/null
cmake -S "$SRC" -B "$OUT/consumer" -DCMAKE_PREFIX_PATH="$OUT/prefix" >/dev/null
cmake --build "$OUT/consumer" >/dev/null
"$OUT/consumer/consumer"
if [ -x "$OUT/consumer/consumer_render" ]; then "$OUT/consumer/consumer_render"; fi
if [ -x "$OUT/consumer/consumer_gpu" ]; then
  ASAN_OPTIONS=detect_leaks=0 "$OUT/consumer/consumer_gpu"
  for f in aa/ppaa.glsl aa/edge_list.glsl aa/aa_constants.h aa/ddaa2.comp common/exact.glsl ddaa2.comp.spv \
    ddaa2.comp.device.spv ssaax4.comp.spv; do
    test -s "$OUT/prefix/share/ssfx/shaders/$f" || { echo "install: share/ssfx/shaders/$f missing"; exit 1; }
  done
fi
PKG_CONFIG_PATH="$OUT/prefix/lib/pkgconfig" c++ -std=c++20 "$SRC/consumer.cpp" -o "$OUT/consumer_pc" \
  $(PKG_CONFIG_PATH="$OUT/prefix/lib/pkgconfig" pkg-config --cflags --libs --static ssfx)
"$OUT/consumer_pc"
test -x "$OUT/prefix/bin/ssfx"
# The Python package, when it was built: importable from the prefix's site directory.
site=$(ls -d "$OUT"/prefix/lib/python3*/dist-packages 2>/dev/null | head -n 1)
if [ -n "$site" ] && [ -e "$site/ssfx/__init__.py" ]; then
  test -e "$site/ssfx/__init__.pyi"
  (cd "$OUT" && PYTHONPATH="$site" /usr/bin/python3 -c "
import numpy as np, ssfx
img = np.zeros((16, 16, 3), np.uint8); img[:, 8:] = 255
assert ssfx.aa(img, 'ddaa2').shape == (16, 16, 3)
assert ssfx.__file__.startswith('$site'), ssfx.__file__
")
  echo "install: the Python package imports from $site"
fi
echo "install: consumer built with CMake and pkg-config"
