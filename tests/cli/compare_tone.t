#!/bin/sh
# compare_tone.t - `rayo compare` on gray and colour images: the course's
# references for EJ2 and EJ3 against rayo's renders come out consistent;
# pairs made here with the Netpbm tools (channels swapped, flips, a shift,
# an offset, inversion, a wrong field of view) each get their verdict and
# diagnosis; counts, largest differences and PSNR agree with Netpbm's own
# arithmetic; --levels, --diff, --json and bad options.
. "$(dirname "$0")/lib.sh"

COURSE="$RAYO_SOURCE/data/course"
json() { jq -r "$1" "$TMP/out"; }
# Colour of pixel X Y of a PNG as "r g b".
pixel() { pngtopam "$1" | pamcut -left "$2" -top "$3" -width 1 -height 1 |
          pamtopnm -plain | tail -n 1 | tr -s ' \n' ' ' | sed 's/ $//'; }
# Pixels of a PGM whose value is above $2.
above() { pnmtoplainpnm "$1" | tail -n +4 | tr -s ' ' '\n' |
          awk -v t="$2" '$1 != "" && $1 > t { n++ } END { print n + 0 }'; }

rayo render "$RAYO_SOURCE/examples/ej2.scene" -o "$TMP/ej2.pgm"
rayo render "$RAYO_SOURCE/examples/ej3.scene" -o "$TMP/ej3.ppm"
pngtopam "$COURSE/referencia-catedra-ej2.png" | ppmtopgm >"$TMP/course2.pgm"

# --- the course's references -------------------------------------------
run_capture compare "$COURSE/referencia-catedra-ej2.png" "$TMP/ej2.pgm" --json
is "$status" 0 "EJ2 reference against rayo's render: exit 0"
is "$(json .kind)/$(json .verdict)" "tone/consistent" "  compared by value, consistent"
is "$(json '.channels | length')/$(json '.channels[0].name')" "1/gray" \
    "  an RGB PNG of equal channels is gray"
is "$(json .unexplained)" 0 "  every difference explained"
pamarith -difference "$TMP/course2.pgm" "$TMP/ej2.pgm" >"$TMP/d2.pgm"
is "$(json .differing)" "$(above "$TMP/d2.pgm" 1)" \
    "  pixels off by more than 1 level: as pamarith counts them"
is "$(json '.channels[0].max_difference')" \
    "$(pamsumm -max -brief "$TMP/d2.pgm")" "  largest difference: as pamsumm finds it"
psnr=$(pnmpsnr "$TMP/course2.pgm" "$TMP/ej2.pgm" 2>&1 | sed -n 's/.*lumina *\([0-9.]*\) dB.*/\1/p')
is "$(json '.channels[0].psnr' | awk '{ printf "%.2f", $1 }')" "$psnr" \
    "  PSNR $psnr dB: as pnmpsnr computes it"
is "$(json '.at_edges + .in_shading')" "$(json .differing)" \
    "  the differences lie at edges or in shading"
run_capture compare "$COURSE/referencia-catedra-ej2.png" "$TMP/ej2.pgm"
grep -q '^note: the differences at outlines and shadow edges' "$TMP/out"
ok $? "  the text says why outline pixels differ"
grep -q 'z = 321.5' "$TMP/out"
ok $? "  and names the course's focal distance"

run_capture compare "$COURSE/referencia-catedra-ej3.png" "$TMP/ej3.ppm" --json
is "$status/$(json .verdict)" "0/identical" \
    "EJ3 reference against rayo's render: identical within a level"
is "$(json '[.channels[].name] | join(",")')" "red,green,blue" "  three channels"
is "$(json '[.channels[].max_difference] | max')" 1 "  the largest difference is 1 level"
run_capture compare --levels 0 "$COURSE/referencia-catedra-ej3.png" "$TMP/ej3.ppm" --json
is "$status/$(json .verdict)/$(json .unexplained)" "0/consistent/0" \
    "  --levels 0: consistent, the 1-level differences explained"

# Under `make check-valgrind` (rayo under memcheck, some forty times
# slower) the course's references, two diagnoses and --diff are enough.
SHORT=${RAYO_VALGRIND:-0}

# --- mistakes made with the Netpbm tools --------------------------------
# expect NAME VERDICT KIND IMAGE [REFERENCE]
expect() {
    run_capture compare "${5:-$TMP/ej3.ppm}" "$4" --json
    is "$(json .verdict)/$(json .diagnosis.kind)" "$2/$3" "$1: $2, $3"
    [ "$status" -eq 1 ] || [ "$2" != inconsistent ]
    ok $? "  exit status 1 when inconsistent"
}

pamchannel -infile "$TMP/ej3.ppm" -tupletype RGB 2 1 0 | pamtopnm >"$TMP/bgr.ppm"
expect "channels as BGR" inconsistent channels-swapped "$TMP/bgr.ppm"
is "$(json '.diagnosis.order | map(tostring) | join(",")')" "2,1,0" \
    "  the image's red shows the reference's blue"
if [ "$SHORT" = 0 ]; then
pamchannel -infile "$TMP/ej3.ppm" -tupletype RGB 1 2 0 | pamtopnm >"$TMP/gbr.ppm"
expect "channels as GBR" inconsistent channels-swapped "$TMP/gbr.ppm"
is "$(json '.diagnosis.order | map(tostring) | join(",")')" "1,2,0" "  order 1,2,0"

pamflip -tb "$TMP/ej3.ppm" >"$TMP/tb.ppm"
expect "colour upside down" inconsistent flipped-vertically "$TMP/tb.ppm"
pamflip -lr "$TMP/ej2.pgm" >"$TMP/lr.pgm"
expect "gray mirrored" inconsistent flipped-horizontally "$TMP/lr.pgm" "$TMP/ej2.pgm"
pamflip -r180 "$TMP/ej3.ppm" >"$TMP/r180.ppm"
expect "colour half turn" inconsistent rotated-180 "$TMP/r180.ppm"

pamcut -top 2 "$TMP/ej3.ppm" | pnmpad -bottom=2 -black >"$TMP/up2.ppm"
expect "two rows up" inconsistent shifted "$TMP/up2.ppm"
is "$(json .diagnosis.shift.x),$(json .diagnosis.shift.y)" "0,-2" "  shift (0, -2)"
grep -q 'moved 2 rows up' "$TMP/out"
ok $? "  said in words: 2 rows up"
pamcut -top 1 "$TMP/ej2.pgm" | pnmpad -bottom=1 -black >"$TMP/up1.pgm"
expect "gray one row up" inconsistent shifted "$TMP/up1.pgm" "$TMP/ej2.pgm"

pamfunc -subtractor=10 "$TMP/ej2.pgm" >"$TMP/minus10.pgm"
expect "gray 10 levels darker" inconsistent offset "$TMP/minus10.pgm" "$TMP/ej2.pgm"
is "$(json '.diagnosis.offset[0]')" -10 "  offset -10"
pamfunc -adder=20 "$TMP/ej3.ppm" >"$TMP/plus20.ppm"
expect "colour 20 levels brighter" inconsistent offset "$TMP/plus20.ppm"
is "$(json '.diagnosis.offset | map(tostring) | join(",")')" "20,20,20" "  offset +20 in each channel"
pamfunc -adder=1 "$TMP/ej3.ppm" >"$TMP/plus1.ppm"
expect "one level brighter" identical none "$TMP/plus1.ppm"
run_capture compare --levels 0 "$TMP/ej3.ppm" "$TMP/plus1.ppm" --json
is "$(json .verdict)/$(json .diagnosis.kind)" "inconsistent/offset" \
    "  with --levels 0: an offset"

pnminvert "$TMP/ej2.pgm" >"$TMP/inverted.pgm"
expect "gray inverted" inconsistent inverted "$TMP/inverted.pgm" "$TMP/ej2.pgm"

rayo render "$RAYO_SOURCE/examples/ej3.scene" --fov 70 -o "$TMP/fov70.ppm"
expect "field of view 70" inconsistent scaled "$TMP/fov70.ppm"
scale=$(awk 'BEGIN { printf "%.2f", (320 / sin(atan2(1,1)) * cos(atan2(1,1))) / (320 / (sin(35 * atan2(1,1) / 45) / cos(35 * atan2(1,1) / 45))) }')
is "$(json .diagnosis.scale | awk '{ printf "%.2f", 1 / $1 }')" "$scale" \
    "  scale as tan(35 deg) / tan(45 deg) gives it ($scale)"

rayo render "$RAYO_SOURCE/examples/ej3.scene" -W 320 -H 240 -o "$TMP/small.ppm"
expect "half the size" inconsistent different-size "$TMP/small.ppm"

# Shadows removed, and a sphere shadowing itself: student programs of
# tests/grade, compared with the course's reference; the diagnosis is the
# course's mistake, found by rendering the scene with it.
for mistake in no_shadows self_shadow; do
    ${RAYO_CC:-cc} -std=c99 -w -o "$TMP/$mistake" \
        "$RAYO_SOURCE/tests/grade/ej2_$mistake/main.c" -lm
    (cd "$TMP" && "./$mistake") >"$TMP/$mistake.pgm"
    name=$(echo "$mistake" | tr _ -)
    expect "EJ2 $name (a student's program)" inconsistent mistake \
        "$TMP/$mistake.pgm" "$COURSE/referencia-catedra-ej2.png"
    is "$(json .diagnosis.mistake)/$(json .course)" "$name/ej2" "  the mistake $name of ej2"
done

# Values outside 0..255 (student programs that do not clamp): the
# image's samples are clamped to be compared and the verdict says why.
${RAYO_CC:-cc} -std=c99 -w -o "$TMP/no_clamp" \
    "$RAYO_SOURCE/tests/grade/ej2_no_clamp/main.c" -lm
(cd "$TMP" && ./no_clamp) >"$TMP/no_clamp.pgm"
above255=$(tail -n +4 "$TMP/no_clamp.pgm" | tr -s ' \n' '\n' | awk '$1 > 255' |
           wc -l | tr -d ' ')
expect "EJ2 without clamping" inconsistent out-of-range "$TMP/no_clamp.pgm" "$TMP/ej2.pgm"
is "$(json .image_clamped.high)" "$above255" "  $above255 samples above 255, as awk counts them"
grep -q 'values not clamped' "$TMP/out"
ok $? "  says the values are not clamped"
${RAYO_CC:-cc} -std=c99 -w -o "$TMP/no_ln" \
    "$RAYO_SOURCE/tests/grade/ej2_no_ln_test/main.c" -lm
(cd "$TMP" && ./no_ln) >"$TMP/no_ln.pgm"
negative=$(tail -n +4 "$TMP/no_ln.pgm" | tr -s ' \n' '\n' | grep -c '^-')
expect "EJ2 without the L.N > 0 test" inconsistent mistake "$TMP/no_ln.pgm" "$TMP/ej2.pgm"
is "$(json .diagnosis.mistake)/$(json .image_clamped.low)" "no-ln-test/$negative" \
    "  the mistake no-ln-test, and $negative negative samples clamped"
run_capture compare "$TMP/no_ln.pgm" "$TMP/ej2.pgm"
is "$status" 2 "  as a reference it is refused (exit 2)"
fi

# --- the difference picture ---------------------------------------------
run_capture compare "$TMP/ej3.ppm" "$TMP/bgr.ppm" --diff "$TMP/diff.png" --json
is "$(pngtopam "$TMP/diff.png" | pamfile | sed 's/.*: *//; s/^[[:space:]]*//')" \
    "PPM raw, 640 by 480  maxval 255" "--diff: an RGB PNG of the reference's size"
is "$(pixel "$TMP/diff.png" 0 0)" "0 0 0" "  black background stays black"
x=$(json .first_unexplained.x) y=$(json .first_unexplained.y)
set -- $(pixel "$TMP/diff.png" "$x" "$y")
[ "$1" -gt 100 ] && [ "$1" -gt $(($2 * 2)) ] && [ "$1" -gt $(($3 * 2)) ]
ok $? "  an unexplained pixel ($x, $y) is red: $*"
run_capture compare "$COURSE/referencia-catedra-ej2.png" "$TMP/ej2.pgm" --diff "$TMP/diff2.png" --json
x=$(json .first_unexplained.x)
is "$x" null "  EJ2: nothing unexplained"
[ "$SHORT" = 0 ] || { done_testing; exit $?; }

# --- text and JSON agree ------------------------------------------------
rayo compare "$TMP/ej3.ppm" "$TMP/tb.ppm" >"$TMP/text"
rayo compare "$TMP/ej3.ppm" "$TMP/tb.ppm" --json >"$TMP/out"
python3 -m json.tool "$TMP/out" >/dev/null
ok $? "--json is valid JSON"
is "$(sed -n 's/^differing pixels: \([0-9]*\) of.*/\1/p' "$TMP/text")" "$(json .differing)" \
    "text and JSON: the same differing pixels"
is "$(sed -n 's/^diagnosis: //p' "$TMP/text")" "$(json .diagnosis.text)" \
    "text and JSON: the same diagnosis"

# --- bad options --------------------------------------------------------
expect_usage_error "--levels 256" "--levels: '256'" compare --levels 256 "$TMP/ej2.pgm" "$TMP/ej2.pgm"
expect_usage_error "--exercise ej9" "unknown exercise 'ej9'" compare --exercise ej9 "$TMP/ej2.pgm" "$TMP/ej2.pgm"
run_capture compare --exercise none "$TMP/ej3.ppm" "$TMP/bgr.ppm" --json
is "$(json .course)/$(json .diagnosis.kind)" "null/channels-swapped" \
    "--exercise none: no course mistakes tried, still diagnosed"

done_testing
