#!/bin/sh
# limits.t - every documented limit (docs/limits.md, include/rayo/limits.h,
# scene_file.h, render.h) at the limit (accepted) and one past it (exit
# 2, nothing on stdout, one line on stderr naming the value and the
# limit, no output file).
#
# Where the largest accepted input would be slow to produce in full (2^30
# pixels, 8 GiB, 256 MiB), the test shows that it passed the limit check
# by what happens next: a render of 2^30 pixels sent to /dev/full stops
# at the first write (exit 1, "No space left on device"), a header of
# 2^30 pixels with no raster is refused for the missing raster, and
# sparse files of exactly 8 GiB or 256 MiB are read (a sparse file takes
# no space).
. "$(dirname "$0")/lib.sh"

cd "$TMP" || exit 1
big() { [ "${RAYO_VALGRIND:-0}" = 1 ]; } # heavy cases are skipped under valgrind

# accepted NAME ARGS...: exit 0, and the output file (-o last) exists.
accepted() {
    name=$1
    shift
    run_capture "$@"
    is "$status" 0 "$name: accepted"
    [ "$status" = 0 ] || sed 's/^/#   stderr: /' "$TMP/err"
}
# full NAME ARGS...: accepted, then stopped by /dev/full at the first write.
full() {
    name=$1
    shift
    run_capture "$@" -o /dev/full
    is "$status" 1 "$name: accepted (stopped by /dev/full, exit 1)"
    is "$(cat "$TMP/err")" "rayo: /dev/full: No space left on device" "$name: no limit was hit"
}

# --- image size: render options ------------------------------------------
accepted "-W 65536" render -W 65536 -H 1 -o w.pbm
is "$(sed -n 2p w.pbm)" "65536 1" "-W 65536: the image is 65536 pixels wide"
expect_usage_error "-W 65537" "--width: '65537' is out of range; expected 1 to 65536" render -W 65537 -H 1 -o w2.pbm
accepted "-H 65536" render -W 1 -H 65536 -o h.pbm
is "$(sed -n 2p h.pbm)" "1 65536" "-H 65536: the image is 65536 pixels high"
expect_usage_error "-H 65537" "--height: '65537' is out of range; expected 1 to 65536" render -W 1 -H 65537 -o h2.pbm
full "-W 32768 -H 32768 (2^30 pixels)" render -W 32768 -H 32768
full "-W 65536 -H 16384 (2^30 pixels)" render -W 65536 -H 16384 --format png
expect_usage_error "-W 32768 -H 32769" "1073774592 pixels; expected at most 1073741824" render -W 32768 -H 32769 -o p.pbm
ok "$([ ! -e w2.pbm ] && [ ! -e h2.pbm ] && [ ! -e p.pbm ]; echo $?)" "refused renders leave no file"

# --- image size: scene cameras -------------------------------------------
printf 'sphere 0 0 3 1\n' >s.body
scene() { { printf '%s\n' "$1"; cat s.body; } >"$2"; }
scene "camera size 65536 1" cam-w.scene
accepted "camera size 65536 1" render cam-w.scene --shade hit -o cw.pbm
scene "camera size 65537 1" cam-w2.scene
expect_usage_error "camera size 65537 1" "cam-w2.scene:1:13: the image width 65537 is out of range; expected 1 to 65536" render cam-w2.scene --shade hit
scene "camera size 32768 32768" cam-p.scene
full "camera size 32768 32768" render cam-p.scene --shade hit
scene "camera size 32768 32769" cam-p2.scene
expect_usage_error "camera size 32768 32769" "cam-p2.scene:1:1: 32768x32769 is too many pixels; expected at most 2\^30" render cam-p2.scene --shade hit

# --- image size: readers -------------------------------------------------
{ printf 'P4\n65536 1\n'; head -c 8192 /dev/zero; } >r-w.pbm
accepted "P4 65536x1" convert r-w.pbm r-w.png
is "$(pngtopnm r-w.png | pamfile)" "stdin:	PBM raw, 65536 by 1" "P4 65536x1: read and written whole"
{ printf 'P4\n65537 1\n'; head -c 8193 /dev/zero; } >r-w2.pbm
expect_usage_error "P4 65537x1" "r-w2.pbm: byte 3 \(line 2\): found width 65537 in the P4 header; expected at most 65536 pixels" convert r-w2.pbm x.png
pbmmake -white 1 65536 | pnmtopng >r-h.png
accepted "PNG 1x65536" convert r-h.png r-h.pbm
is "$(pamfile r-h.pbm)" "r-h.pbm:	PBM raw, 1 by 65536" "PNG 1x65536: read and written whole"
pbmmake -white 1 65537 | pnmtopng >r-h2.png
expect_usage_error "PNG 1x65537" "r-h2.png: .*65536" convert r-h2.png x.pbm
printf 'P4\n32768 32768\n' >r-p.pbm
expect_usage_error "P4 32768x32768 (2^30 pixels)" "r-p.pbm: byte 15: found 0 bytes of raster; expected 134217728" convert r-p.pbm x.pbm
printf 'P4\n32768 32769\n' >r-p2.pbm
expect_usage_error "P4 32768x32769" "r-p2.pbm: byte 9 \(line 2\): found 32768x32769 = 1073774592 pixels in the P4 header; expected at most 1073741824" convert r-p2.pbm x.pbm
ok "$([ ! -e x.png ] && [ ! -e x.pbm ]; echo $?)" "refused images leave no file"

# --- bytes read from one image: 8 GiB ------------------------------------
# Sparse files: a 1x1 P4 image followed by zeros.
sparse() { printf 'P4\n1 1\n\200' >"$2" && truncate -s "$1" "$2"; }
if sparse 8589934592 in-8g.pbm 2>/dev/null; then
    run_capture convert -v in-8g.pbm one.pbm
    is "$status" 0 "an 8 GiB image file: accepted"
    grep -q "8589934584 bytes after the image" "$TMP/err"
    ok $? "an 8 GiB image file: its trailing bytes are counted"
    sparse 8589934593 in-8g1.pbm
    expect_usage_error "an image file of 8 GiB + 1 byte" "in-8g1.pbm: the file is 8589934593 bytes; expected at most 8589934592" convert in-8g1.pbm x.pbm
    rm -f in-8g.pbm in-8g1.pbm
else
    ok 0 "an 8 GiB image file # SKIP no sparse files here"
fi

# --- scene files ---------------------------------------------------------
# Size: 256 MiB.  At the limit the file is read and refused for its
# content (a NUL on line 2), not for its size.
if ! big && printf 'sphere 0 0 3 1\n' >f.scene && truncate -s 268435456 f.scene 2>/dev/null; then
    expect_usage_error "a 256 MiB scene file" "f.scene:2:1: " render f.scene -o f.pbm
    grep -q "larger than" "$TMP/err"
    ok "$((! $?))" "a 256 MiB scene file: read, not refused for its size"
else
    ok 0 "a 256 MiB scene file # SKIP under valgrind or without sparse files"
fi
printf 'sphere 0 0 3 1\n' >f2.scene && truncate -s 268435457 f2.scene
expect_usage_error "a scene file of 256 MiB + 1 byte" "f2.scene: the file is larger than 268435456 bytes" render f2.scene -o f.pbm
rm -f f.scene f2.scene
# The same through a pipe, whose size is not known in advance: 256 MiB +
# 1 byte of comment lines, which read cleanly, is refused for its size.
if ! big; then
    mkfifo scene.fifo
    comment=$(printf '%04000d' 0 | tr 0 '#')
    yes "$comment" | head -c 268435457 >scene.fifo 2>/dev/null &
    expect_usage_error "256 MiB + 1 byte through a pipe" "scene.fifo: the file is larger than 268435456 bytes" render scene.fifo
    wait
else
    ok 0 "256 MiB + 1 byte through a pipe # SKIP under valgrind"
fi

# Lines: 4096 bytes, newline excluded.
pad() { # pad LENGTH: a sphere line padded with a comment to LENGTH bytes
    printf 'sphere 0 0 3 1 #'
    head -c $(($1 - 16)) /dev/zero | tr '\0' x
    printf '\n'
}
pad 4096 >line.scene
is "$(head -1 line.scene | tr -d '\n' | wc -c | tr -d ' ')" 4096 "the long line is 4096 bytes"
accepted "a line of 4096 bytes" render line.scene --shade hit -W 8 -H 6 -o line.pbm
pad 4097 >line2.scene
expect_usage_error "a line of 4097 bytes" "line2.scene:1:4097: line is longer than 4096 bytes" render line2.scene

# Lights: 4096.
lights() { awk -v n="$1" 'BEGIN { for (i = 0; i < n; i++) print "light point 0 5 -1 color 0.0001"; print "sphere 0 0 3 1" }'; }
lights 4096 >l.scene
accepted "4096 lights" render l.scene -W 4 -H 3 -o l.ppm
lights 4097 >l2.scene
expect_usage_error "4097 lights" "l2.scene:4097:1: more than 4096 lights in one scene" render l2.scene

# Materials: 2^20, the default (unnamed) material included.
materials() { awk -v n="$1" 'BEGIN { for (i = 1; i <= n; i++) print "material m" i; print "sphere 0 0 3 1 material m" n }'; }
if ! big; then
    materials 1048575 >m.scene
    accepted "2^20 - 1 named materials (2^20 with the default)" render m.scene -W 4 -H 3 -o m.ppm
else
    ok 0 "2^20 materials # SKIP under valgrind"
fi
materials 1048576 >m2.scene
expect_usage_error "2^20 named materials" "m2.scene:1048576:1: more than 1048576 materials in one scene" render m2.scene
rm -f m.scene m2.scene

# Numbers: magnitude 10^12.  Names: 64 bytes.
printf 'sphere 0 0 1e12 1e12\n' >n.scene
accepted "a number of 1e12" render n.scene --shade hit -W 4 -H 3 -o n.pbm
printf 'sphere 0 0 1.0000001e12 1\n' >n2.scene
expect_usage_error "a number over 1e12" "n2.scene:1:12: .*1.0000001e12" render n2.scene
name64=m$(head -c 63 /dev/zero | tr '\0' a)
printf 'material %s\nsphere 0 0 3 1 material %s\n' "$name64" "$name64" >name.scene
accepted "a material name of 64 bytes" render name.scene -W 4 -H 3 -o name.ppm
printf 'material %sa\n' "$name64" >name2.scene
expect_usage_error "a material name of 65 bytes" "name2.scene:1:10: .*64" render name2.scene

# --- render settings -----------------------------------------------------
accepted "--samples 16" render --samples 16 -W 8 -H 6 -o s.pbm
expect_usage_error "--samples 17" "--samples: '17' is out of range; expected 1 to 16" render --samples 17
printf 'samples 17\nsphere 0 0 3 1\n' >s2.scene
expect_usage_error "samples 17 in a scene" "s2.scene:1:9: .*17" render s2.scene
accepted "--depth 64" render "$RAYO_SOURCE/examples/room.scene" --depth 64 -W 8 -H 6 -o d.ppm
expect_usage_error "--depth 65" "--depth: '65' is out of range; expected 0 to 64" render --depth 65
accepted "--threads 256" render -j 256 -W 8 -H 300 -o j.pbm
expect_usage_error "--threads 257" "--threads: '257' is out of range; expected 1 to 256" render -j 257
spheres() { i=0; while [ "$i" -lt "$1" ]; do printf -- '--sphere\n0,0,3,%s\n' "0.$((i + 1))"; i=$((i + 1)); done; }
spheres 4096 >sp.args
# shellcheck disable=SC2046
accepted "4096 --sphere options" render $(cat sp.args) -W 8 -H 6 -o sp.pbm
spheres 4097 >sp2.args
# shellcheck disable=SC2046
expect_usage_error "4097 --sphere options" "--sphere: more than 4096 spheres; use a scene file" render $(cat sp2.args)
accepted "view --cols 10000" view --cols 10000 "$RAYO_SOURCE/fuzz/corpus/reader/ok-p1.pbm"
expect_usage_error "view --cols 10001" "--cols: '10001' is out of range; expected 1 to 10000" view --cols 10001 x.pbm

# --- memory for one render -----------------------------------------------
# Rows stream to the writer in bands: the largest image, phong-shaded,
# needs no frame in memory; under a 512 MiB address-space limit it runs
# until /dev/full stops it.  (Not under valgrind or AddressSanitizer,
# which reserve more address space than that for themselves.)
if ! big && ! grep -q __asan_init "$RAYO"; then
    status=0
    (ulimit -v 524288; rayo render "$RAYO_SOURCE/examples/room.scene" -W 65536 -H 16384 -j 2 -o /dev/full) 2>"$TMP/err" || status=$?
    is "$status" 1 "2^30 phong pixels within 512 MiB of address space: stopped only by /dev/full"
    is "$(cat "$TMP/err")" "rayo: /dev/full: No space left on device" "2^30 phong pixels: no out-of-memory"
else
    ok 0 "2^30 pixels within 512 MiB # SKIP under valgrind or ASan"
fi
done_testing
