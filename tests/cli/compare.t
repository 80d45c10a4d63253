#!/bin/sh
# compare.t - `rayo compare`: the course's reference against rayo's
# default render is consistent; wrong images made here with rayo's
# options and the Netpbm tools each get the right verdict and diagnosis;
# counts agree with Netpbm's own arithmetic; --json and --diff; bad input.
. "$(dirname "$0")/lib.sh"

REF="$SEED/referencia-catedra.png"
rayo -o "$TMP/default.pbm"
D="$TMP/default.pbm"

# Number of 1 (black) pixels of a PBM, counted by the Netpbm tools.
black() { pnmtoplainpnm "$1" | tail -n +3 | tr -cd 1 | wc -c | tr -d ' '; }
white() { pnmtoplainpnm "$1" | tail -n +3 | tr -cd 0 | wc -c | tr -d ' '; }
# Colour of pixel X Y of a PNG, as "r g b", read back by pngtopnm.
pixel() { pngtopnm "$1" | pamcut -left "$2" -top "$3" -width 1 -height 1 |
          pamtopnm -plain | tail -n 1 | tr -s ' \n' ' ' | sed 's/ $//'; }
json() { jq -r "$1" "$TMP/out"; }

# --- the course's reference and the correct render ---------------------
run_capture compare "$REF" "$D" --json
is "$status" 0 "default render vs the course's reference: exit 0"
is "$(json .verdict)" consistent "  verdict consistent"
is "$(json .diagnosis.kind)" none "  no diagnosis"
# The reference as a PBM, thresholded at half by the Netpbm tools.  Note
# that pamarith works on PAM samples, where a bilevel 1 is white: so
# "-and" of the inverted reference and the image is white exactly where
# the reference is black and the image white, and "-xor" is white where
# they differ.
pngtopnm "$REF" | ppmtopgm | pamthreshold -simple -threshold 0.5 | pamtopnm >"$TMP/ref.pbm"
pnminvert "$TMP/ref.pbm" >"$TMP/notref.pbm"
pamarith -and "$TMP/notref.pbm" "$D" | pamtopnm >"$TMP/refonly.pbm"
is "$(json .reference_only)" "$(white "$TMP/refonly.pbm")" "  black only in the reference: as Netpbm counts it"
pamarith -xor "$TMP/ref.pbm" "$D" | pamtopnm >"$TMP/xor.pbm"
mism=$(white "$TMP/xor.pbm")
is "$(json .mismatches)" "$mism" "  mismatches: as Netpbm counts them ($mism)"
ok "$([ "$mism" -ge 100 ] && [ "$mism" -le 1000 ]; echo $?)" "  a few hundred mismatches"
ok "$(jq -e '.max_distance <= 2 and .beyond_tolerance == 0' "$TMP/out" >/dev/null; echo $?)" "  all within 2 px of the outline"
is "$(json .reference.black)" "$(black "$TMP/ref.pbm")" "  reference's black pixels"
is "$(json .image.black)" 64503 "  image's black pixels"
ok "$(jq -e '.iou > 0.99 and .iou < 1' "$TMP/out" >/dev/null; echo $?)" "  IoU just under 1"
rayo compare "$REF" "$D" --tolerance 1 >/dev/null
is "$?" 1 "  with --tolerance 1 it is inconsistent (exit 1)"
run_capture compare "$D" "$D"
is "$status" 0 "an image against itself: exit 0"
grep -q '^verdict: identical$' "$TMP/out"
ok $? "  verdict identical"

# Text and JSON say the same.
rayo compare "$REF" "$D" >"$TMP/text"
rayo compare "$REF" "$D" --json >"$TMP/out"
python3 -m json.tool "$TMP/out" >/dev/null
ok $? "--json is valid JSON (python3 -m json.tool)"
is "$(sed -n 's/^mismatched pixels: \([0-9]*\) of.*/\1/p' "$TMP/text")" "$(json .mismatches)" "text and JSON: the same mismatches"
is "$(sed -n 's/^verdict: //p' "$TMP/text")" "$(json .verdict)" "text and JSON: the same verdict"
is "$(sed -n 's/^reference: \([0-9x]*\),.*/\1/p' "$TMP/text")" "640x480" "text: the reference's size"

# --- wrong images, and what is wrong with each ---------------------------
# expect NAME VERDICT DIAGNOSIS FILE: compares FILE with the course's
# reference; checks exit status (1), verdict and diagnosis.
expect() {
    run_capture compare "$REF" "$4" --json
    is "$status" 1 "$1: exit 1"
    is "$(json .verdict)/$(json .diagnosis.kind)" "$2/$3" "$1: $2, $3"
}
pamflip -tb "$D" >"$TMP/tb.pbm"
expect "flipped top to bottom (pamflip -tb)" inconsistent flipped-vertically "$TMP/tb.pbm"
pamflip -lr "$D" >"$TMP/lr.pbm"
expect "flipped left to right (pamflip -lr)" inconsistent flipped-horizontally "$TMP/lr.pbm"
pamflip -r180 "$D" >"$TMP/r180.pbm"
expect "half a turn (pamflip -r180)" inconsistent rotated-180 "$TMP/r180.pbm"
pnminvert "$D" >"$TMP/inv.pbm"
expect "inverted (pnminvert)" inconsistent inverted "$TMP/inv.pbm"
pamflip -transpose "$D" >"$TMP/tr.pbm"
expect "transposed (pamflip -transpose)" inconsistent transposed "$TMP/tr.pbm"
is "$(json .image.width)x$(json .image.height)" 480x640 "  transposed: the image's size is reported"

pamcut -top 0 -height 479 "$D" | pnmpad -white -top 1 >"$TMP/down1.pbm"
expect "one row down (pamcut + pnmpad)" inconsistent shifted "$TMP/down1.pbm"
is "$(json .diagnosis.shift.x),$(json .diagnosis.shift.y)" "0,1" "  shifted by (0, 1)"
# A sphere clear of the frame, one row down: every mismatch is on the
# outline, yet the whole shape moved.
rayo --sphere 0.3,-0.2,3,0.7 -o "$TMP/clear.pbm"
pamcut -top 0 -height 479 "$TMP/clear.pbm" | pnmpad -white -top 1 >"$TMP/clear1.pbm"
run_capture compare "$TMP/clear.pbm" "$TMP/clear1.pbm" --json
is "$status/$(json .verdict)/$(json .diagnosis.kind)/$(json .beyond_tolerance)" "1/inconsistent/shifted/0" \
   "  shifted although every mismatch is within 1 px of the outline"
pamcut -left 0 -width 600 -top 0 -height 455 "$D" | pnmpad -white -left 40 -top 25 >"$TMP/far.pbm"
expect "40 right, 25 down (pamcut + pnmpad)" inconsistent shifted "$TMP/far.pbm"
is "$(json .diagnosis.shift.x),$(json .diagnosis.shift.y)" "40,25" "  shifted by (40, 25)"
pamcut -left 7 -width 633 "$D" | pnmpad -white -right 7 >"$TMP/left7.pbm"
expect "7 left (pamcut + pnmpad)" inconsistent shifted "$TMP/left7.pbm"
is "$(json .diagnosis.shift.x),$(json .diagnosis.shift.y)" "-7,0" "  shifted by (-7, 0)"

# A field of view f' scales the picture by tan(45)/tan(f'/2) about the
# centre; the reference itself is 0.5% larger than the formula.
rayo --fov 60 -o "$TMP/fov60.pbm"
expect "--fov 60" inconsistent scaled "$TMP/fov60.pbm"
ok "$(jq -e '.diagnosis.scale > 1.70 and .diagnosis.scale < 1.75' "$TMP/out" >/dev/null; echo $?)" "  scale about 1.72 = tan(45)/tan(30)/1.005 ($(json .diagnosis.scale))"
rayo --fov 100 -o "$TMP/fov100.pbm"
expect "--fov 100" inconsistent scaled "$TMP/fov100.pbm"
ok "$(jq -e '.diagnosis.scale > 0.82 and .diagnosis.scale < 0.85' "$TMP/out" >/dev/null; echo $?)" "  scale about 0.835 = tan(45)/tan(50)/1.005 ($(json .diagnosis.scale))"

rayo --sphere 0.5,0.75,1.9,0.6 -o "$TMP/small.pbm"
expect "a smaller sphere (--sphere 0.5,0.75,1.9,0.6)" inconsistent other-sphere "$TMP/small.pbm"
rayo --sphere 0,0,1.9,0.8 -o "$TMP/centred.pbm"
expect "a centred sphere (--sphere 0,0,1.9,0.8)" inconsistent other-sphere "$TMP/centred.pbm"
rayo --sphere -0.6,0,2,0.4 --sphere 0.6,0,2,0.4 -o "$TMP/two.pbm"
expect "two spheres" inconsistent not-a-sphere "$TMP/two.pbm"
pgmramp -lr 640 480 >"$TMP/ramp.pgm"
expect "a gray ramp (pgmramp): compared by value" inconsistent unknown "$TMP/ramp.pgm"
pbmmake -white 640 480 >"$TMP/white.pbm"
expect "all white (pbmmake)" inconsistent empty "$TMP/white.pbm"
rayo -W 800 -o "$TMP/w800.pbm"
expect "--width 800" inconsistent different-size "$TMP/w800.pbm"
grep -q '"text": "the image is 800x480 but the reference is 640x480' "$TMP/out"
ok $? "  the sizes are named"

# A frame large enough to be measured in bands by several threads (more
# than 2^21 pixels): the counts still agree with Netpbm's.
rayo -W 1600 -H 1400 --sphere 0.4,0.5,2,0.8 -o "$TMP/big.pbm"
pamflip -tb "$TMP/big.pbm" >"$TMP/bigtb.pbm"
run_capture compare "$TMP/big.pbm" "$TMP/bigtb.pbm" --json
is "$(json .verdict)/$(json .diagnosis.kind)" "inconsistent/flipped-vertically" "1600x1400 flipped: flipped vertically"
is "$(json .mismatches)" "$(pamarith -xor "$TMP/big.pbm" "$TMP/bigtb.pbm" | pamtopnm | white /dev/stdin)" \
   "  mismatches as Netpbm counts them"

# The text names the mistake for a student.
rayo compare "$REF" "$TMP/tb.pbm" >"$TMP/text"
grep -q '^diagnosis: the image is upside down (flipped vertically)' "$TMP/text"
ok $? "text: the diagnosis in words"

# --- the difference picture --------------------------------------------
run_capture compare "$REF" "$TMP/tb.pbm" --diff "$TMP/diff.png"
is "$status" 1 "--diff with an inconsistent image: exit 1"
is "$(pngtopnm "$TMP/diff.png" | pamfile | sed 's/.*:[[:space:]]*//')" "PPM raw, 640 by 480  maxval 255" "--diff: a 640x480 colour PNG"
is "$(pixel "$TMP/diff.png" 404 114)" "224 16 16" "  sphere's centre, black only in the reference: red"
is "$(pixel "$TMP/diff.png" 404 365)" "16 96 240" "  flipped sphere's centre, black only in the image: blue"
is "$(pixel "$TMP/diff.png" 5 470)" "255 255 255" "  white in both: white"
rayo compare "$REF" "$D" --diff "$TMP/diff2.png" >/dev/null
is "$(pixel "$TMP/diff2.png" 404 114)" "0 0 0" "  black in both: black"
is "$(pngtopnm "$TMP/diff2.png" | ppmhist -noheader | awk '$1 == 224 && $2 == 16 { print $5 }')" \
   "$(white "$TMP/refonly.pbm")" "  red pixels: exactly the reference-only ones Netpbm counts"
rayo compare "$REF" "$TMP/w800.pbm" --diff "$TMP/diff3.png" >/dev/null
is "$(pngtopnm "$TMP/diff3.png" | pamfile | sed 's/.*:[[:space:]]*//')" "PPM raw, 640 by 480  maxval 255" "  another size: the diff has the reference's size"

# Standard input as the image.
run_capture compare "$REF" - <"$D"
is "$status" 0 "IMAGE '-' reads standard input"

# --- bad input -----------------------------------------------------------
expect_usage_error "missing image" "expected REFERENCE and IMAGE" compare "$REF"
expect_usage_error "three arguments" "expected REFERENCE and IMAGE" compare "$REF" "$D" "$D"
expect_usage_error "no such file" "nope\.pbm" compare "$REF" "$TMP/nope.pbm"
printf 'P1\n3 2\n0 1 x\n' >"$TMP/bad.pbm"
expect_usage_error "malformed image" "bad\.pbm" compare "$REF" "$TMP/bad.pbm" --diff "$TMP/none.png"
ok "$([ ! -e "$TMP/none.png" ]; echo $?)" "  no diff written"
head -c 100 "$REF" >"$TMP/cut.png"
expect_usage_error "truncated PNG reference" "cut\.png" compare "$TMP/cut.png" "$D"
expect_usage_error "negative tolerance" "--tolerance" compare --tolerance -1 "$REF" "$D"
expect_usage_error "tolerance not a number" "--tolerance" compare --tolerance two "$REF" "$D"
expect_usage_error "unknown option" "--frobnicate" compare --frobnicate "$REF" "$D"
expect_usage_error "both from standard input" "standard input" compare - -

rayo compare --help >"$TMP/help"
grep -q "red .*black only in the reference" "$TMP/help"
ok $? "--help gives the diff's legend"
done_testing
