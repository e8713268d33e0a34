#!/usr/bin/env bash
# ssfx aa inside an ffmpeg pipeline: ffmpeg decodes a lossless video to raw RGBA on a pipe,
# ssfx runs ddaa2 on it, ffmpeg encodes the result losslessly (FFV1); every frame must be the
# bytes that the per-file CLI gives on the same frame as a PNG.
# Usage: test_ffmpeg.sh SSFX OUT_DIR. Exit 77 (skipped) without ffmpeg (setup.sh installs it).
set -u
SSFX=$1
OUT=$2
command -v ffmpeg >/dev/null || { echo "ffmpeg: not installed; skipped"; exit 77; }
rm -rf "$OUT" && mkdir -p "$OUT/frames" "$OUT/perfile"
ff() { ffmpeg -hide_banner -loglevel error -nostdin -y "$@"; }
W=160 H=96 N=12
# The input: ffmpeg's test pattern (moving, sharp edges), stored losslessly.
ff -f lavfi -i "testsrc=size=${W}x${H}:rate=12" -frames:v $N -c:v ffv1 -pix_fmt bgra "$OUT/in.mkv" || exit 1
ff -i "$OUT/in.mkv" -pix_fmt rgba "$OUT/frames/f%03d.png" || exit 1
# The pipe.
set -o pipefail
ff -i "$OUT/in.mkv" -f rawvideo -pix_fmt rgba - |
  "$SSFX" aa --raw ${W}x${H} -m ddaa2 - -o - |
  ff -f rawvideo -pix_fmt rgba -s ${W}x${H} -r 12 -i - -c:v ffv1 -pix_fmt bgra "$OUT/out.mkv" ||
  { echo "FAIL ffmpeg: the pipe failed"; exit 1; }
set +o pipefail
# The per-file CLI, one call per frame.
for f in "$OUT"/frames/f*.png; do
  "$SSFX" aa -m ddaa2 "$f" -o "$OUT/perfile/$(basename "$f")" || { echo "FAIL ffmpeg: per-file $f"; exit 1; }
done
ff -i "$OUT/out.mkv" -f rawvideo -pix_fmt rgba "$OUT/piped.rgba" || exit 1
ff -i "$OUT/perfile/f%03d.png" -f rawvideo -pix_fmt rgba "$OUT/perfile.rgba" || exit 1
frame=$((W * H * 4))
[ "$(stat -c %s "$OUT/piped.rgba")" = $((N * frame)) ] || { echo "FAIL ffmpeg: $(stat -c %s "$OUT/piped.rgba") bytes, not $N frames"; exit 1; }
if ! cmp -s "$OUT/piped.rgba" "$OUT/perfile.rgba"; then
  first=$(cmp "$OUT/piped.rgba" "$OUT/perfile.rgba" | awk '{print $5}' | tr -d ,)
  echo "FAIL ffmpeg: frame $(((first - 1) / frame)) differs from the per-file CLI"
  exit 1
fi
# The input changes from frame to frame (the test is not of one frame repeated).
cmp -s <(head -c $frame "$OUT/perfile.rgba") <(tail -c $frame "$OUT/perfile.rgba") &&
  { echo "FAIL ffmpeg: the first and last frames are the same"; exit 1; }
echo "ffmpeg: $N frames of ${W}x${H} through ffmpeg | ssfx aa --raw | ffmpeg (FFV1) equal the per-file CLI"
