#!/bin/sh
# jpeg.t - JPEG through libjpeg-turbo, against Netpbm's own JPEG tools
# (pnmtojpeg, jpegtopnm, which use the same library but none of rayo's
# code): what rayo writes, jpegtopnm decodes to what rayo reads back;
# what pnmtojpeg writes, rayo reads as jpegtopnm does; gray stays gray;
# --quality changes the file; broken files are refused with the byte.
. "$(dirname "$0")/lib.sh"

canon() { pamtopnm <"$1" 2>/dev/null; }
same_image() { # same_image NAME A B
    canon "$2" >"$TMP/a.canon"
    canon "$3" >"$TMP/b.canon"
    cmp -s "$TMP/a.canon" "$TMP/b.canon"
    ok $? "$1"
}

rayo render "$RAYO_SOURCE/examples/ej3.scene" -W 160 -H 120 -o "$TMP/ej3.ppm"
rayo convert "$TMP/ej3.ppm" "$TMP/ej3.jpg"
ok $? "convert x.ppm x.jpg"
is "$(od -An -N 3 -tx1 "$TMP/ej3.jpg" | tr -d ' ')" "ffd8ff" "  a JPEG (SOI, then a marker)"
rayo convert "$TMP/ej3.jpg" "$TMP/back.ppm"
jpegtopnm "$TMP/ej3.jpg" >"$TMP/netpbm.ppm" 2>/dev/null
same_image "  rayo reads back what Netpbm's jpegtopnm decodes" "$TMP/back.ppm" "$TMP/netpbm.ppm"
# Lossy, but close: 95% of the samples within 16 levels of the original
# and the mean absolute difference under 3 (edges of saturated colour
# lose most: chroma is kept at half resolution).
canon "$TMP/ej3.ppm" | tail -c $((160 * 120 * 3)) | od -An -v -tu1 -w1 >"$TMP/a.txt"
canon "$TMP/back.ppm" | tail -c $((160 * 120 * 3)) | od -An -v -tu1 -w1 >"$TMP/b.txt"
stats=$(paste "$TMP/a.txt" "$TMP/b.txt" | awk '{ d = $1 - $2; if (d < 0) d = -d; s += d; if (d <= 16) near++ } END { printf "%.4f %.2f", near / NR, s / NR }')
ok "$(echo "$stats" | awk '{ exit !($1 >= 0.95 && $2 < 3) }'; echo $?)" "  lossy but close to the original (share within 16 levels, mean difference: $stats)"

pnmtojpeg "$TMP/ej3.ppm" >"$TMP/netpbm.jpg" 2>/dev/null
rayo convert "$TMP/netpbm.jpg" "$TMP/from_netpbm.ppm"
jpegtopnm "$TMP/netpbm.jpg" >"$TMP/netpbm_back.ppm" 2>/dev/null
same_image "rayo reads pnmtojpeg's JPEG as jpegtopnm does" "$TMP/from_netpbm.ppm" "$TMP/netpbm_back.ppm"

rayo render "$RAYO_SOURCE/examples/ej2.scene" -W 64 -H 48 -o "$TMP/ej2.pgm"
rayo render "$RAYO_SOURCE/examples/ej2.scene" -W 64 -H 48 -o "$TMP/ej2.jpg"
ok $? "render -o x.jpg"
rayo convert "$TMP/ej2.jpg" - >"$TMP/ej2.back.pgm"
is "$(head -c 2 "$TMP/ej2.back.pgm")" "P5" "  a gray render stays gray"
rayo -o "$TMP/sphere.jpeg"
rayo convert "$TMP/sphere.jpeg" - | head -c 2 >"$TMP/magic"
is "$(cat "$TMP/magic")" "P5" "  .jpeg too; bilevel becomes gray"

rayo convert --quality 20 "$TMP/ej3.ppm" "$TMP/q20.jpg"
ok "$([ "$(wc -c <"$TMP/q20.jpg")" -lt "$(wc -c <"$TMP/ej3.jpg")" ]; echo $?)" "--quality 20 writes a smaller file than the default 90"
expect_usage_error "--quality 0" "--quality: '0'" convert --quality 0 "$TMP/ej3.ppm" "$TMP/x.jpg"

head -c 2000 "$TMP/ej3.jpg" >"$TMP/cut.jpg"
run_capture convert "$TMP/cut.jpg" "$TMP/cut.ppm"
is "$status:$(cat "$TMP/err")" "2:rayo: $TMP/cut.jpg: byte 2000: found the end of the file; expected the rest of the JPEG data" \
    "a JPEG cut short: refused with the byte"
printf '\377\330\377\376\000\004ab\377\231' >"$TMP/marker.jpg"
run_capture convert "$TMP/marker.jpg" "$TMP/marker.ppm"
is "$status:$(cat "$TMP/err")" "2:rayo: $TMP/marker.jpg: byte 10: libjpeg: Unsupported marker type 0x99" \
    "a broken marker: libjpeg's reason, and where"
[ ! -e "$TMP/cut.ppm" ] && [ ! -e "$TMP/marker.ppm" ]
ok $? "  nothing written"
# compare knows a JPEG is lossy: the course's scene 3 saved as JPEG is
# consistent with the course's image, saying so; upside down it is not;
# EJ1's sphere as JPEG is compared as a mask.
rayo render "$RAYO_SOURCE/examples/ej3.scene" -o "$TMP/full.ppm"
rayo convert "$TMP/full.ppm" "$TMP/full.jpg"
run_capture compare course:ej3 "$TMP/full.jpg"
is "$status:$(grep '^verdict' "$TMP/out")" "0:verdict: consistent" "compare: the course's scene 3 as JPEG is consistent"
grep -q "^note: the image is a JPEG, which is lossy: values were compared within 32 levels" "$TMP/out"
ok $? "  and the report says why the tolerance"
pamflip -tb "$TMP/full.ppm" >"$TMP/flip.ppm"
rayo convert "$TMP/flip.ppm" "$TMP/flip.jpg"
run_capture compare course:ej3 "$TMP/flip.jpg"
is "$status:$(grep -c '^diagnosis: the image is upside down' "$TMP/out")" "1:1" "  upside down as JPEG: inconsistent, named"
rayo -o "$TMP/sphere.jpg"
run_capture compare course:ej1 "$TMP/sphere.jpg"
is "$status:$(grep '^verdict' "$TMP/out")" "0:verdict: consistent" "EJ1's sphere as JPEG: consistent, as a mask"
run_capture compare --json course:ej3 "$TMP/full.jpg"
is "$(jq -c .image_file "$TMP/out")" '{"lossy_levels":32,"bmp_bits":0,"bmp_top_down":false,"bmp_unpadded":false}' "  --json has the tolerance"
done_testing
