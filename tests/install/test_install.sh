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
PKG_CONFIG_PATH="$OUT/prefix/lib/pkgconfig" c++ -std=c++20 "$SRC/consumer.cpp" -o "$OUT/consumer_pc" \
  $(PKG_CONFIG_PATH="$OUT/prefix/lib/pkgconfig" pkg-config --cflags --libs --static ssfx)
"$OUT/consumer_pc"
test -x "$OUT/prefix/bin/ssfx"
echo "install: consumer built with CMake and pkg-config"
