#!/bin/sh
# png_hostile.t - PNG files built to cost memory or time (issue 14): text
# chunks that inflate to gigabytes, chunks that declare 2 GiB and hold 3
# bytes, a zlib bomb after a complete image, damage after the image, and an
# interlaced 16-bit RGBA image that once needed a second full-size buffer.
# Each runs under an address-space and a CPU limit (png_hostile.py run), so
# that a regression fails here instead of taking the machine, and its peak
# memory and CPU time are asserted.
#
# convert, compare, view and grade read PNG through one function
# (rayo_png_read, behind rayo_image_read_file and _memory), so each case
# runs through convert and the 1x1 ones through compare too; the ceiling
# case through convert and view.  Under valgrind or AddressSanitizer (which
# need address space and time of their own) the exit statuses and messages
# are checked, not the bounds.
. "${RAYO_SOURCE:-.}/tests/cli/lib.sh"
GEN="$RAYO_SOURCE/tests/cli/png_hostile.py"
cd "$TMP" || exit 1

measured=1
if [ "${RAYO_VALGRIND:-0}" = 1 ] || grep -q __asan_init "$RAYO"; then
    measured=0
fi

# bounded AS_MIB CPU_S ARGS...: rayo ARGS under the limits; $status, $rss
# (peak MiB), $cpu (ms), $TMP/out and $TMP/err.
bounded() {
    as=$1 cpu_limit=$2
    shift 2
    if [ "$measured" = 1 ]; then
        python3 "$GEN" run "$TMP/measure" "$as" "$cpu_limit" "$TMP/out" \
            "$TMP/err" "$RAYO" "$@"
        read -r status rss cpu <"$TMP/measure"
    else
        run_capture "$@"
        rss=0 cpu=0
    fi
}

# within NAME MIB: the last run peaked under MIB MiB and a second of CPU.
within() {
    if [ "$measured" = 1 ]; then
        [ "$rss" -lt "$2" ]
        ok $? "$1: peak memory ${rss} MiB, under $2 MiB"
        [ "$cpu" -lt 1000 ]
        ok $? "$1: ${cpu} ms of CPU, under a second"
    else
        ok 0 "$1: memory # SKIP under valgrind or ASan"
        ok 0 "$1: CPU time # SKIP under valgrind or ASan"
    fi
}

# fine NAME ARGS...: under 64 MiB beyond the baseline (80 MiB of address
# space) and 2 s, exit 0, nothing on stderr, and within 64 MiB and 1 s.
fine() {
    name=$1
    shift
    bounded 80 2 "$@"
    is "$status" 0 "$name: exit status 0"
    is "$(wc -c <"$TMP/err" | tr -d ' ')" 0 "$name: nothing on stderr"
    [ "$status" = 0 ] || sed 's/^/#   stderr: /' "$TMP/err"
    within "$name" 64
}

# refused NAME PATTERN ARGS...: the same limits, exit 2, one line matching.
refused() {
    name=$1 pattern=$2
    shift 2
    bounded 80 2 "$@"
    is "$status" 2 "$name: exit status 2"
    is "$(wc -l <"$TMP/err" | tr -d ' ')" 1 "$name: one line on stderr"
    grep -Eq -- "$pattern" "$TMP/err"
    ok $? "$name: message matches /$pattern/"
    [ "$status" = 2 ] || sed 's/^/#   stderr: /' "$TMP/err"
    within "$name" 64
}

# A 1x1 gray image of value 128, for compare and for the expected output.
printf 'P5\n1 1\n255\n\200' >one.pgm

# --- text that inflates to gigabytes ---------------------------------------
# 1000 zTXt (or iTXt) chunks, each 8 KB inflating to 8000 KiB: 8 MB of file,
# 7.8 GiB of text that libpng used to inflate and keep.
for type in zTXt iTXt; do
    python3 "$GEN" text-bomb "$type.png" "$type" 1000 8000
    fine "1000 $type chunks of 8000 KiB each" convert "$type.png" out.pgm
    cmp -s out.pgm one.pgm
    ok $? "1000 $type chunks: the image read right"
    fine "1000 $type chunks, through compare" compare one.pgm "$type.png"
done

# --- chunks that declare more than the file holds --------------------------
# 44 bytes: IHDR, then a chunk declaring 2^31-1 bytes that holds 3.  The
# file is cut short: exit 2, without allocating for the declared length.
for type in tEXt zTXt iTXt sPLT; do
    python3 "$GEN" long-chunk "long-$type.png" "$type"
    refused "44-byte PNG, $type of 2^31-1 bytes" \
        "^rayo: long-$type.png: byte 44: found the end of the file; expected more PNG data" \
        convert "long-$type.png" out.pgm
done
refused "44-byte PNG, tEXt of 2^31-1 bytes, through compare" \
    "^rayo: long-tEXt.png: byte 44: found the end of the file" \
    compare one.pgm long-tEXt.png
# The same with 2^29 declared, under 1 GiB of address space, where libpng
# could allocate (and clear) the 512 MiB it used to.
python3 "$GEN" long-chunk long-512.png tEXt 536870912
bounded 1024 2 convert long-512.png out.pgm
is "$status" 2 "tEXt declaring 512 MiB, cut short: exit status 2"
within "tEXt declaring 512 MiB, cut short" 64
# A complete tEXt of 12 MiB (over libpng's 8 MB default cap): skipped.
python3 "$GEN" big-text big-text.png tEXt 12
fine "a 12 MiB tEXt chunk" convert big-text.png out.pgm
cmp -s out.pgm one.pgm
ok $? "a 12 MiB tEXt chunk: the image read right"

# --- a zlib bomb after a complete image --------------------------------------
# 1x1, then the same zlib stream goes on with 8 GiB of zeros (8 MB of IDAT):
# reading stops inflating at the image's last row.
python3 "$GEN" idat-bomb bomb.png 8
fine "1x1 image, then 8 GiB of zeros in IDAT" convert bomb.png out.pgm
cmp -s out.pgm one.pgm
ok $? "zlib bomb: the image read right"
fine "1x1 image, then 8 GiB of zeros in IDAT, through compare" \
    compare one.pgm bomb.png
bounded 80 2 convert -v bomb.png out.pgm
grep -q "0 bytes after the image" "$TMP/err"
ok $? "zlib bomb: read up to IEND, nothing after it"

# --- what follows the image is still checked --------------------------------
python3 "$GEN" after-image after-crc.png crc
refused "a damaged CRC in the IDAT that completes the image" \
    "^rayo: after-crc.png: byte 55: found IDAT: CRC error; expected a well-formed PNG stream" \
    convert after-crc.png out.pgm
python3 "$GEN" after-image after-no-iend.png no-iend
refused "no IEND after the image" \
    "^rayo: after-no-iend.png: byte 55: found the end of the file; expected more PNG data" \
    convert after-no-iend.png out.pgm
python3 "$GEN" after-image after-plte.png plte
refused "a PLTE after the image data" \
    "^rayo: after-plte.png: byte 55: found a PLTE chunk after the image data; expected IEND" \
    convert after-plte.png out.pgm

# --- the memory ceiling: one image's worth --------------------------------
# 8192x4096 interlaced 16-bit RGBA: 192 MiB as rayo holds it (16-bit RGB);
# libpng's own layout would be 256 MiB more.  Under 192 + 80 MiB of address
# space; every pixel composited over white, checked as it streams out.
if [ "$measured" = 1 ]; then
    python3 "$GEN" rgba16 rgba.png 8192 4096
    python3 "$GEN" run "$TMP/measure" 272 10 - "$TMP/err" \
        "$RAYO" convert rgba.png - --format ppm |
        python3 "$GEN" check-ppm 8192 4096 35097 49151 65535 >check.txt
    read -r status rss cpu <"$TMP/measure"
    is "$status" 0 "8192x4096 interlaced RGBA16: convert within 272 MiB of address space"
    [ "$status" = 0 ] || sed 's/^/#   stderr: /' "$TMP/err"
    is "$(cat check.txt)" ok "8192x4096 interlaced RGBA16: every pixel composited over white"
    [ "$rss" -lt 256 ]
    ok $? "8192x4096 interlaced RGBA16: convert peaked at $rss MiB, under 192 + 64"
    python3 "$GEN" run "$TMP/measure" 272 10 /dev/null "$TMP/err" \
        "$RAYO" view rgba.png
    read -r status rss cpu <"$TMP/measure"
    is "$status" 0 "8192x4096 interlaced RGBA16: view within 272 MiB of address space"
    [ "$rss" -lt 256 ]
    ok $? "8192x4096 interlaced RGBA16: view peaked at $rss MiB, under 192 + 64"
else
    ok 0 "8192x4096 interlaced RGBA16 # SKIP under valgrind or ASan"
fi
done_testing
