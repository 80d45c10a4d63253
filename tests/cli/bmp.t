#!/bin/sh
# bmp.t - BMP, the course's TP1 format: rayo's files in the course's
# layout (checked field by field with od, and byte for byte against
# Netpbm's ppmtobmp), read back by Netpbm's bmptopnm as the same pixels;
# and every layout rayo reads (tests/cli/bmp_make.py packs each one by
# hand, with the image it must become), and the broken ones refused with
# one line naming the byte.
. "$(dirname "$0")/lib.sh"

# canon FILE: the image as Netpbm's raw PNM (one byte layout for both).
canon() { pamtopnm <"$1" 2>/dev/null; }
same_image() { # same_image NAME A B
    canon "$2" >"$TMP/a.canon"
    canon "$3" >"$TMP/b.canon"
    cmp -s "$TMP/a.canon" "$TMP/b.canon"
    ok $? "$1"
}
# field FILE OFFSET BYTES: a little-endian unsigned field, in decimal.
field() { od -An -j "$2" -N "$3" -t "u$3" "$1" | tr -d ' '; }

# --- writing: the course's layout, a width whose rows need padding ------
S=$RAYO_SOURCE/examples/ej3.scene
rayo render "$S" -W 161 -H 121 -o "$TMP/ej3.ppm"
rayo render "$S" -W 161 -H 121 -o "$TMP/ej3.bmp"
ok $? "render -o x.bmp writes a BMP"
B=$TMP/ej3.bmp
is "$(head -c 2 "$B")" "BM" "  the magic BM"
stride=$(( (161 * 3 + 3) / 4 * 4 ))
is "$(field "$B" 2 4)" "$((54 + 121 * stride))" "  file size 54 + 121 rows of $stride bytes"
is "$(wc -c <"$B" | tr -d ' ')" "$((54 + 121 * stride))" "  and that is its size"
is "$(field "$B" 10 4):$(field "$B" 14 4)" "54:40" "  pixels at 54, a 40-byte BITMAPINFOHEADER"
is "$(field "$B" 18 4):$(field "$B" 22 4)" "161:121" "  width 161, positive height (rows bottom up)"
is "$(field "$B" 26 2):$(field "$B" 28 2):$(field "$B" 30 4)" "1:24:0" "  1 plane, 24 bits, no compression"
is "$(field "$B" 34 4):$(field "$B" 38 4):$(field "$B" 42 4):$(field "$B" 46 4):$(field "$B" 50 4)" \
    "0:0:0:0:0" "  image size, resolutions and colours 0, as the course writes them"
# The first stored row is the image's last, in B G R order, padded.
last=$(pamtopnm <"$TMP/ej3.ppm" | tail -c $((161 * 3)) | od -An -tu1 -w3 -v |
    awk '{ printf "%d %d %d\n", $3, $2, $1 }' | tr '\n' ' ')
first=$(od -An -j 54 -N 483 -tu1 -w3 -v "$B" | awk '{ printf "%d %d %d\n", $1, $2, $3 }' | tr '\n' ' ')
is "$first" "$last" "  the first stored row is the bottom one, B G R"
is "$(od -An -j $((54 + 483)) -N 1 -tu1 "$B" | tr -d ' ')" 0 "  and its padding byte is 0"
# Netpbm (scripts/deps.sh check installs it) as the independent reader
# and writer.
bmptopnm "$B" >"$TMP/back.ppm" 2>/dev/null
same_image "Netpbm's bmptopnm reads the render's pixels" "$TMP/back.ppm" "$TMP/ej3.ppm"
ppmtobmp "$TMP/ej3.ppm" >"$TMP/netpbm.bmp" 2>/dev/null
cmp -s "$TMP/netpbm.bmp" "$B"
ok $? "Netpbm's ppmtobmp writes the same bytes"

# Gray and bilevel go through palettes and come back the same.
rayo render "$RAYO_SOURCE/examples/ej2.scene" -W 61 -H 33 -o "$TMP/ej2.pgm"
rayo convert "$TMP/ej2.pgm" "$TMP/ej2.bmp"
is "$(field "$TMP/ej2.bmp" 28 2):$(field "$TMP/ej2.bmp" 46 4)" "8:256" "gray: 8 bits through 256 grays"
rayo convert "$TMP/ej2.bmp" "$TMP/ej2.back.pgm"
same_image "  and back to the same PGM" "$TMP/ej2.back.pgm" "$TMP/ej2.pgm"
rayo -W 37 -H 21 -o "$TMP/sphere.pbm"
rayo convert "$TMP/sphere.pbm" "$TMP/sphere.bmp"
is "$(field "$TMP/sphere.bmp" 28 2):$(field "$TMP/sphere.bmp" 46 4)" "1:2" "bilevel: 1 bit through white and black"
rayo convert "$TMP/sphere.bmp" "$TMP/sphere.back.pbm"
same_image "  and back to the same PBM" "$TMP/sphere.back.pbm" "$TMP/sphere.pbm"
bmptopnm "$TMP/sphere.bmp" >"$TMP/sphere.netpbm.pbm" 2>/dev/null
same_image "  which bmptopnm reads as the same bits" "$TMP/sphere.netpbm.pbm" "$TMP/sphere.pbm"
# 16-bit samples are scaled to 0-255, rounded: 65535 -> 255, 32896 -> 128.
printf 'P2 2 1 65535\n65535 32896\n' >"$TMP/g16.pgm"
rayo convert "$TMP/g16.pgm" "$TMP/g16.bmp"
rayo convert "$TMP/g16.bmp" - | pamtopnm -plain 2>/dev/null | tr -s ' \n' ' ' >"$TMP/g16.txt"
is "$(cat "$TMP/g16.txt")" "P2 2 1 255 255 128 " "16-bit samples scaled to 8 bits, rounded"

# --- reading: every layout, against the image it must become ------------
python3 "$RAYO_SOURCE/tests/cli/bmp_make.py" "$TMP"
for name in rgb24 rgb24_topdown rgb24_unpadded rgb32 rgb32_fields rgb32_v4 \
    rgb16_565 gray8 palette4 bilevel_black_first; do
    rayo convert "$TMP/$name.bmp" - >"$TMP/$name.got.pnm"
    same_image "reads $name" "$TMP/$name.got.pnm" "$TMP/$name.want.pnm"
done
is "$(head -c 2 "$TMP/gray8.got.pnm"):$(head -c 2 "$TMP/bilevel_black_first.got.pnm")" \
    "P5:P4" "a gray palette gives a gray image, black and white a bilevel one"
out=$(rayo convert -v "$TMP/rgb24_unpadded.bmp" "$TMP/x.ppm" 2>&1 | head -n 1)
is "$out" "rayo: $TMP/rgb24_unpadded.bmp: bmp, 13x7, RGB, maxval 255; 0 bytes after the image" \
    "convert -v names the format"

# --- compare names how a BMP departs from the course's layout ----------
rayo render "$RAYO_SOURCE/examples/ej3.scene" -o "$TMP/full.ppm"
python3 - "$TMP" <<'PY'
import struct, sys
d = sys.argv[1]
t = open(d + "/full.ppm", "rb").read().split()
w, h, v = int(t[1]), int(t[2]), list(map(int, t[4:]))
rows = b"".join(bytes(c for x in range(w) for c in reversed(v[(y * w + x) * 3:(y * w + x) * 3 + 3])) for y in range(h))
head = lambda height: b"BM" + struct.pack("<IHHI", 54 + len(rows), 0, 0, 54) + \
    struct.pack("<IiiHHIIiiII", 40, w, height, 1, 24, 0, 0, 0, 0, 0, 0)
open(d + "/topdown.bmp", "wb").write(head(-h) + rows)
open(d + "/upside.bmp", "wb").write(head(h) + rows)
PY
run_capture compare course:ej3 "$TMP/topdown.bmp"
is "$status:$(grep -c "^note: the BMP's rows are stored top down" "$TMP/out")" "0:1" \
    "compare: a BMP stored top down is the right picture, and the note says how it departs"
run_capture compare course:ej3 "$TMP/upside.bmp"
is "$status:$(grep -c "^note: a BMP with a positive height, as the course's layout has it, stores its rows bottom up" "$TMP/out")" "1:1" \
    "  rows written top first with a positive height: upside down, and why"
run_capture compare "$TMP/rgb24_unpadded.want.pnm" "$TMP/rgb24_unpadded.bmp"
is "$(grep -c "^note: the BMP's rows are not padded to a multiple of 4 bytes" "$TMP/out")" 1 \
    "  rows without padding: the note"

# --- broken files: one line each, the byte, exit status 2, no output ----
bad() { # bad NAME MESSAGE
    status=0
    rayo convert "$TMP/bad_$1.bmp" "$TMP/out_$1.ppm" 2>"$TMP/err" || status=$?
    is "$status:$(cat "$TMP/err")" "2:rayo: $TMP/bad_$1.bmp: $2" "$1: refused"
    [ ! -e "$TMP/out_$1.ppm" ]
    ok $? "  nothing written"
}
bad truncated "byte 54: found 180 bytes of pixels; expected 280 (7 rows of 40 bytes)"
bad rle8 "byte 30: found compression 1 (RLE8) with 8 bits; expected 0 (none), or bit fields with 16 or 32 bits"
bad planes "byte 26: found 2 planes; expected 1"
bad header_size "byte 14: found an information header of 41 bytes; expected 12, 40, 52, 56, 64, 108 or 124 (BITMAPINFOHEADER is 40)"
bad index_past_palette "byte 70: found palette index 9; expected an index below the palette's 4 entries"
bad zero_width "byte 18: found a size of 0x7; expected a width above 0 and a height other than 0"
bad huge "byte 18: found a 70000x70000 image in the BMP header; expected at most 65536 pixels each way and 1073741824 (2^30) in all"
done_testing
