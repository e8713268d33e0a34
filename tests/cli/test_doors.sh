#!/usr/bin/env bash
# Issue #35, "every door, round two": each numbered finding as a case that was run, kept
# right. Sequences and raw pipes, standard output, messages, refusals, empty outcomes,
# ownership. (Python's items 4, 15 and 16: python/tests/test_boundary.py.)
set -u
SSFX=$1
OUT=$2
SRC=$(cd "$(dirname "$0")/../.." && pwd)
MAKE="python3 $SRC/tests/cli/make_inputs.py"
rm -rf "$OUT" && mkdir -p "$OUT" && cd "$OUT" || exit 1
OUT=$PWD
fail=0
# shellcheck source=tests/cli/lib.sh
. "$SRC/tests/cli/lib.sh"  # check NAME EXPECTED_EXIT CMD...
contains() {  # contains NAME FILE TEXT
  grep -qF -- "$3" "$2" || { echo "FAIL $1: '$3' not in $2:"; cat "$2"; fail=1; }
}
absent() {  # absent NAME PATH: the run left no such file or folder
  [ ! -e "$2" ] || { echo "FAIL $1: $2 exists"; fail=1; }
}
bytes() { stat -c %s "$1"; }
# limited KIB COMMAND: the command under an address-space limit of KIB KiB, which the memory cases
# bound. A sanitizer build cannot run under one (ASan reserves terabytes of shadow address
# space at start), so there the command runs unlimited: its exit and message are still checked.
if ldd "$SSFX" 2>/dev/null | grep -q 'lib[at]san'; then
  echo "doors: a sanitizer build: the memory cases run without their address-space limit"
  limited() { bash -c "$2"; }
else
  limited() { bash -c "ulimit -v $1; $2"; }
fi

# Inputs: a 64x48 drawing; eight numbered frames of it (f.0001 .. f.0008, 12288 bytes raw each).
"$SSFX" testscene --out scene --width 64 --height 48 >/dev/null 2>&1 || { echo "FAIL setup: testscene"; exit 1; }
"$SSFX" testscene --out wide --width 66 --height 48 >/dev/null 2>&1
FRAME=12288
fresh_seq() {  # fresh_seq DIR: eight good frames
  rm -rf "$1" && mkdir -p "$1"
  for i in 1 2 3 4 5 6 7 8; do cp scene/scene.png "$1/f.000$i.png"; done
}

# ---- 1. frames of different sizes into one raw stream --------------------------------
fresh_seq s1 && cp wide/scene.png s1/f.0003.png
check i1_stdout 2 "$SSFX" aa -m noaa 's1/f.%04d.png' -o -
contains i1_stdout i1_stdout.err "s1/f.0003.png: 66x48, but the first frame (s1/f.0001.png) is 64x48"
[ "$(bytes i1_stdout.out)" = $((2 * FRAME)) ] || { echo "FAIL i1_stdout: $(bytes i1_stdout.out) bytes, not frames 1-2"; fail=1; }
check i1_file 2 "$SSFX" aa -m noaa 's1/f.%04d.png' -o s1.rgba --raw 64x48
contains i1_file i1_file.err "but --raw says 64x48"
absent i1_file s1.rgba
fresh_seq s1b
check i1_raw_wrong 2 "$SSFX" aa -m noaa 's1b/f.%04d.png' -o 'o1b/f.%04d.png' --raw 32x24
contains i1_raw_wrong i1_raw_wrong.err "s1b/f.0001.png: 64x48, but --raw says 32x24"
check i1_same_size 0 "$SSFX" aa -m noaa 's1b/f.%04d.png' -o s1b.rgba --raw 64x48
[ "$(bytes s1b.rgba)" = $((8 * FRAME)) ] || { echo "FAIL i1_same_size: $(bytes s1b.rgba) bytes"; fail=1; }

# ---- 2. an APNG inside a folder or a numbered sequence: refused by name ---------------
fresh_seq s2 && $MAKE apng s2/f.0005.png 64 48 3
check i2_folder 2 "$SSFX" aa -m noaa s2 -o o2
contains i2_folder i2_folder.err "s2/f.0005.png: an animated PNG in a frame sequence"
[ "$(ls o2 | wc -l)" = 4 ] || { echo "FAIL i2_folder: $(ls o2 | wc -l) frames written, not 1-4"; fail=1; }
check i2_numbered 2 "$SSFX" aa -m noaa 's2/f.%04d.png' -o 'o2n/f.%04d.png'
contains i2_numbered i2_numbered.err "an animated PNG"
check i2_alone 0 "$SSFX" aa -m noaa s2/f.0005.png -o o2.png  # on its own: every frame, an APNG out
python3 -c 'import sys; d = open(sys.argv[1], "rb").read(); sys.exit(not (b"acTL" in d and d.count(b"fcTL") == 3))' o2.png ||
  { echo "FAIL i2_alone: the output is not a 3-frame APNG"; fail=1; }

# ---- 3. -o /dev/stdout and friends: written into, never renamed over -------------------
"$SSFX" aa -m noaa scene/scene.png -o ref.png
printf 'earlier\n' >log.bin
"$SSFX" aa -m noaa scene/scene.png -o /dev/stdout >>log.bin 2>i3.err || { echo "FAIL i3_append: exit $?"; fail=1; }
{ printf 'earlier\n'; cat ref.png; } | cmp -s - log.bin || { echo "FAIL i3_append: log.bin lost its content"; fail=1; }
for dev in /dev/stdout /proc/self/fd/1; do
  "$SSFX" aa -m noaa scene/scene.png -o "$dev" 2>i3_pipe.err | cat >i3_pipe.png
  cmp -s i3_pipe.png ref.png || { echo "FAIL i3_pipe: -o $dev into a pipe"; cat i3_pipe.err; fail=1; }
done
"$SSFX" aa -m noaa scene/scene.png -o /dev/stderr 2>i3_stderr.png >/dev/null
cmp -s i3_stderr.png ref.png || { echo "FAIL i3_stderr: -o /dev/stderr"; fail=1; }
ln -sf /dev/stdout tostdout
"$SSFX" aa -m noaa scene/scene.png -o tostdout >i3_link.png || { echo "FAIL i3_link: exit $?"; fail=1; }
cmp -s i3_link.png ref.png && [ -L tostdout ] || { echo "FAIL i3_link: a link to /dev/stdout"; fail=1; }
printf 'earlier\n' >same.bin
"$SSFX" aa -m noaa scene/scene.png -o same.bin >>same.bin || { echo "FAIL i3_same: exit $?"; fail=1; }
{ printf 'earlier\n'; cat ref.png; } | cmp -s - same.bin || { echo "FAIL i3_same: the file stdout appends to was replaced"; fail=1; }

# ---- 5. a bad frame k: exactly frames 1..k-1 written, whatever the timing --------------
# Twenty runs of each output kind, four threads on two cores, with a busy loop beside them.
fresh_seq s5 && head -c 100 scene/scene.png >s5/f.0006.png
( end=$((SECONDS + 120)); while [ $SECONDS -lt $end ] && [ ! -e stop_load ]; do :; done ) &
load=$!
for run in $(seq 20); do
  "$SSFX" aa -m ddaa2 s5 -o - --raw 64x48 --threads 4 >i5.raw 2>i5.err
  [ $? = 2 ] && [ "$(bytes i5.raw)" = $((5 * FRAME)) ] ||
    { echo "FAIL i5_raw run $run: $(bytes i5.raw) bytes, not 5 frames"; cat i5.err; fail=1; break; }
  rm -rf o5
  "$SSFX" aa -m ddaa2 's5/f.%04d.png' -o 'o5/f.%04d.png' --threads 4 2>i5.err
  [ $? = 2 ] && [ "$(ls o5 | tr '\n' ' ')" = "f.0001.png f.0002.png f.0003.png f.0004.png f.0005.png " ] ||
    { echo "FAIL i5_files run $run: $(ls o5 | tr '\n' ' ')"; cat i5.err; fail=1; break; }
done
touch stop_load && wait $load
contains i5 i5.err "s5/f.0006.png"

# ---- 6. a FIFO named like a frame: refused by name, no hang -----------------------------
mkdir -p s6 && cp scene/scene.png s6/f.1.png && mkfifo s6/f.2.png
check i6 2 timeout 20 "$SSFX" aa -m noaa 's6/f.%d.png' -o 'o6/f.%d.png'
contains i6 i6.err "s6/f.2.png: a FIFO, not a regular file"
absent i6 o6

# ---- 7. --frames 0-999999999 in bounded memory (256 MiB of address space) ----------------
fresh_seq s7
check i7 2 limited 262144 "exec $SSFX aa -m noaa 's7/f.%04d.png' -o 'o7/f.%04d.png' --frames 0-999999999"
contains i7 i7.err "999999992 of 1000000000 frames are missing, the first: s7/f.0000.png"
absent i7 o7

# ---- 8. a PNG followed by endless data; an EXR claiming 16384^2 in a small file ----------
check i8_zero 0 limited 262144 "(cat scene/scene.png; cat /dev/zero) | timeout 60 $SSFX aa -m noaa /dev/stdin -o i8.png"
cmp -s i8.png ref.png || { echo "FAIL i8_zero: output differs"; fail=1; }
$MAKE bigchunk scene/scene.png chunky.png 20
check i8_chunk_ok 0 "$SSFX" aa -m noaa chunky.png -o i8c.png
check i8_chunk_limit 2 "$SSFX" --max-pixels 4096 aa -m noaa chunky.png -o i8d.png
contains i8_chunk_limit i8_chunk_limit.err "the limit for a PNG file at --max-pixels 4096"
absent i8_chunk_limit i8d.png
"$SSFX" ao --scene corner --size 8x4 -o one.exr >/dev/null 2>&1
printf '{"fov_y_deg": 60, "z_near": -0.1, "z_far": null}\n' >cam.json
$MAKE exrclaim one.exr claim.exr 16384 16384
check i8_exr 2 limited 524288 "exec $SSFX ao --depth claim.exr --camera cam.json -o i8.exr.png"
contains i8_exr i8_exr.err "claim.exr: corrupt EXR (scan-line block 0 packs 1048576 bytes of pixels into"
head -c 2000 claim.exr >cut.exr
check i8_exr_cut 2 limited 524288 "exec $SSFX ao --depth cut.exr --camera cam.json -o i8.exr.png"
contains i8_exr_cut i8_exr_cut.err "cut.exr"
$MAKE exrclaim one.exr fine.exr 8 4
check i8_exr_fine 0 "$SSFX" ao --depth fine.exr --camera cam.json -o i8fine.png

# ---- 9. --max-pixels applies to raw frames -------------------------------------------------
head -c $((2 * FRAME)) /dev/zero >two.rgba
check i9 2 "$SSFX" --max-pixels 1000 aa --raw 64x48 -m noaa two.rgba -o -
contains i9 i9.err "exceeds the pixel limit of 1000 (--max-pixels)"
check i9_ok 0 "$SSFX" --max-pixels 3072 aa --raw 64x48 -m noaa two.rgba -o -
# A bad parameter value is the run's error, named before any frame is read: no frame in the
# message, no output.
check i9_param 2 "$SSFX" aa --raw 64x48 -m ddaa2 -p strength=inf two.rgba -o i9_param.rgba
contains i9_param i9_param.err "ssfx: error: ddaa2: strength = inf is not in [0, 100]"
absent i9_param i9_param.rgba

# ---- 10. standard output that cannot be written --------------------------------------------
mkdir -p q10 && cp scene/scene.png q10/a.png && "$SSFX" testscene --out q10w --width 512 --height 384 >/dev/null 2>&1
cp q10w/scene.png q10/ax8.png
$MAKE apng t10.png 8 6 3 && $MAKE apng t10x8.png 64 48 3 && mkdir -p t10 && mv t10.png t10/t.png && mv t10x8.png t10/tx8.png
full_cases=("methods" "methods --json" "aa --list-presets" "--help" "--version" "aa --help"
  "bench --size 64 --reps 4 --warmup 0 --methods blur" "eval quality q10 --methods noaa"
  "eval temporal --dir t10 --image t --methods noaa" "eval kernels")
"$SSFX" devices >/dev/null 2>&1 && full_cases+=("devices --json" "devices")
for c in "${full_cases[@]}"; do
  # shellcheck disable=SC2086
  "$SSFX" $c >/dev/full 2>i10.err
  st=$?
  [ $st = 2 ] && grep -q "cannot write to standard output" i10.err ||
    { echo "FAIL i10 '$c' >/dev/full: exit $st"; cat i10.err; fail=1; }
done
"$SSFX" methods >&- 2>i10c.err
[ $? = 2 ] && grep -q "cannot write to standard output (it is closed)" i10c.err ||
  { echo "FAIL i10_closed: methods >&-"; cat i10c.err; fail=1; }
check i10_json_full 2 bash -c "$SSFX eval quality q10 --methods noaa --json - >/dev/full"

# ---- 11. messages that name the right thing; %% in plain paths ----------------------------
check i11_numbered_out 2 "$SSFX" aa -m noaa scene/scene.png -o 'o11/x.%04d.png'
contains i11_numbered_out i11_numbered_out.err "scene/scene.png is one image, but the output 'o11/x.%04d.png' is numbered"
absent i11_numbered_out o11
check i11_missing 2 "$SSFX" aa -m noaa missing.png -o 'o11/x.%04d.png'
contains i11_missing i11_missing.err "missing.png: no such file or folder"
check i11_percent 2 "$SSFX" aa -m noaa scene/scene.png -o 'out50%.png'
contains i11_percent i11_percent.err "(%% for a %)"
check i11_escape 0 "$SSFX" aa -m noaa scene/scene.png -o 'out50%%.png'
cmp -s 'out50%.png' ref.png || { echo "FAIL i11_escape: out50%.png"; fail=1; }
check i11_escape_in 0 "$SSFX" aa -m noaa 'out50%%.png' -o 'again%%.png'
cmp -s 'again%.png' ref.png || { echo "FAIL i11_escape_in: again%.png"; fail=1; }
printf '{"fov_y_deg": 180, "z_near": -0.1, "z_far": null}\n' >cam180.json
check i11_fov 2 "$SSFX" ao --depth fine.exr --camera cam180.json -o x.png
contains i11_fov i11_fov.err "'fov_y_deg' 180 is not in (0, 180) degrees"
check i11_maxpixels 2 "$SSFX" --max-pixels 99999999999999999999 aa -m noaa scene/scene.png -o x.png
contains i11_maxpixels i11_maxpixels.err "--max-pixels '99999999999999999999' is not a whole number"
mkdir -p q11 && cp q10/a.png q10/ax8.png q11/ && cp wide/scene.png q11/ax2.png
check i11_x2 2 "$SSFX" eval quality q11 --methods ssaax2
contains i11_x2 i11_x2.err "q11/ax2.png: 66x48, expected 128x96 (2 times q11/a.png, 64x48)"
cp t10/tx8.png t11x8.png && mkdir -p t11 && mv t11x8.png t11/tx8.png && cp t10/t.png t11/t.png && cp t10/t.png t11/tx2.png
check i11_temporal 2 "$SSFX" eval temporal --dir t11 --image t --methods ssaax2
contains i11_temporal i11_temporal.err "t11/tx2.png: 8x6, expected 16x12"

# ---- 12. options that would be ignored are refused -----------------------------------------
check i12_outputs 2 "$SSFX" eval quality q10 --source given --outputs o12
contains i12_outputs i12_outputs.err "--outputs goes with --source compute"
absent i12_outputs o12
check i12_same 2 "$SSFX" eval quality q10 --methods noaa --json same.txt --md ./same.txt
contains i12_same i12_same.err "name one file"
check i12_bench_device 2 "$SSFX" bench --device 0 --size 64 --reps 4
contains i12_bench_device i12_bench_device.err "--device goes with --backend vulkan"
if "$SSFX" devices >/dev/null 2>&1; then
  check i12_blank_device 2 "$SSFX" aa -m noaa --backend vulkan --device ' ' scene/scene.png -o x.png
  contains i12_blank_device i12_blank_device.err "is blank"
fi
mkdir -p q12 && cp q10/a.png q12/ && $MAKE apng q12/ax8.png 512 384 2
check i12_apng_truth 2 "$SSFX" eval quality q12 --methods noaa
contains i12_apng_truth i12_apng_truth.err "q12/ax8.png: an animated PNG, where a still image is expected"

# ---- 13. empty outcomes: no frames is an error with no output; no empty folders left -------
check i13_empty 2 "$SSFX" aa --raw 64x48 -m noaa /dev/null -o empty.rgba
contains i13_empty i13_empty.err "no frames (the raw stream is empty)"
absent i13_empty empty.rgba
check i13_empty_stdin 2 bash -c "$SSFX aa --raw 64x48 -m noaa - -o - </dev/null"
fresh_seq s13 && head -c 100 scene/scene.png >s13/f.0001.png
check i13_folder 2 "$SSFX" aa -m noaa s13 -o o13/deeper
absent i13_folder o13
check i13_pattern 2 "$SSFX" aa -m noaa 's13/f.%04d.png' -o 'o13p/a/f.%04d.png'
absent i13_pattern o13p
mkdir -p keep13 && check i13_existing 2 "$SSFX" aa -m noaa s13 -o keep13
[ -d keep13 ] || { echo "FAIL i13_existing: removed a folder it did not create"; fail=1; }

# ---- 14. a raw stream cut short: the help, the message and the behaviour agree -------------
head -c $((3 * FRAME + 100)) /dev/zero >cut.rgba
check i14_file 2 "$SSFX" aa --raw 64x48 -m noaa cut.rgba -o cut_out.rgba
contains i14_file i14_file.err "raw frame 3 is cut short: 100 of 12288 bytes (64x48 RGBA8), after 3 whole frame(s); cut_out.rgba is not written (a raw output file appears only whole)"
absent i14_file cut_out.rgba
"$SSFX" aa --raw 64x48 -m noaa cut.rgba -o - 2>i14_pipe.err | cat >i14_pipe.rgba
contains i14_pipe i14_pipe.err "the 3 frame(s) before it were written"
[ "$(bytes i14_pipe.rgba)" = $((3 * FRAME)) ] || { echo "FAIL i14_pipe: $(bytes i14_pipe.rgba) bytes"; fail=1; }
check i14_numbered 2 "$SSFX" aa --raw 64x48 -m noaa cut.rgba -o 'o14/f.%d.png'
[ "$(ls o14 | wc -l)" = 3 ] || { echo "FAIL i14_numbered: $(ls o14 | wc -l) files"; fail=1; }
check i14_help 0 "$SSFX" aa --help
contains i14_help i14_help.out "a raw output FILE appears only whole, so it is then not written at all"

# ---- 17. ownership: never a root-owned setuid file; a hard link is split -------------------
cp ref.png other.png && ln other.png linked.png
check i17_link 0 "$SSFX" aa -m blur scene/scene.png -o linked.png
cmp -s other.png ref.png && ! cmp -s linked.png ref.png || { echo "FAIL i17_link: the hard link was not split"; fail=1; }
if [ "$(id -u)" = 0 ] && id nobody >/dev/null 2>&1; then
  cp ref.png suid.png && chown nobody suid.png && chmod 4755 suid.png
  check i17_suid 0 "$SSFX" aa -m blur scene/scene.png -o suid.png
  [ "$(stat -c '%U %a' suid.png)" = "root 755" ] ||
    { echo "FAIL i17_suid: $(stat -c '%U %a' suid.png), expected 'root 755' (no set-user-ID bit)"; fail=1; }
  cp ref.png sgid.png && chgrp nogroup sgid.png 2>/dev/null && chmod 2775 sgid.png &&
    check i17_sgid 0 "$SSFX" aa -m blur scene/scene.png -o sgid.png &&
    { [ "$(stat -c '%a' sgid.png)" = 775 ] || { echo "FAIL i17_sgid: mode $(stat -c '%a' sgid.png)"; fail=1; }; }
  cp ref.png ownsuid.png && chmod 4755 ownsuid.png
  check i17_own 0 "$SSFX" aa -m blur scene/scene.png -o ownsuid.png
  [ "$(stat -c '%a' ownsuid.png)" = 4755 ] || { echo "FAIL i17_own: our own setuid file lost its mode"; fail=1; }
else
  echo "i17_suid: skipped (needs root and the user nobody: a file of another owner to write over)"
fi

exit $fail
