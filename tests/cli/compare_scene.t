#!/bin/sh
# compare_scene.t - `rayo compare` against one of the course's scenes
# names what a student's image differs in, in the statement's terms
# (src/compare/tone/tone_scene.c): the student-style programs of tests/grade
# with one such mistake each (tests/grade/CORPUS.md) are compiled, run,
# and compared with the course's reference; each gets the finding its
# mistake deserves, with numbers worked out here from the statement (a
# sphere's place in the picture, the ambient's byte) or counted here in
# the images.  Also EJ1's pi = sqrt(9.81), said as the course's focal
# distance, not rounding; and where nothing fits, where the differences
# lie instead of a first pixel.  A sphere's radius changed is named by
# its size, the light's direction changed by where it seems to come
# from (worked out here from the statement's geometry and the program's
# own vector); EJ3's point light placed elsewhere by where it seems to
# be (the program's own place), also through a little noise, and not
# named in a right image with noise; a point light's colour changed or
# the light left out, read the same way with its place held; the
# directional light's direction, as EJ2's; a sphere whose centre another
# hides, named by its size from the part of it that shows, or moved,
# placed from the circle of its outline.
. "$(dirname "$0")/lib.sh"

STUDENTS="$RAYO_SOURCE/tests/grade"
COURSE="$RAYO_SOURCE/data/course"
CC_STUDENT=${RAYO_CC:-cc}
json() { jq -r "$1" "$TMP/out"; }
# within GOT WANT SLACK: |GOT - WANT| <= SLACK (0/1 as a status)
within() { awk -v g="$1" -v w="$2" -v s="$3" 'BEGIN { d = g - w; if (d < 0) d = -d; exit !(d <= s) }'; }

# near3 WANTS SLACK NAME: the first finding's value[0..2] each within
# SLACK of the comma-separated WANTS, the program's own numbers
near3() {
    for c in 0 1 2; do
        want=$(echo "$1" | cut -d, -f$((c + 1)))
        within "$(json ".diagnosis.findings[0].value[$c]")" "$want" "$2"
        ok $? "  $3[$c] $(json ".diagnosis.findings[0].value[$c]"), the program's $want"
    done
}

# student NAME: tests/grade/NAME compiled and run, its image in $TMP/NAME.out
student() {
    # shellcheck disable=SC2086
    $CC_STUDENT -std=c99 -O2 -o "$TMP/$1" "$STUDENTS/$1/main.c" -lm &&
        "$TMP/$1" >"$TMP/$1.out"
}

# scene NAME REFERENCE: compares NAME's image with REFERENCE, --json; a
# pair compared before is not compared again (its output and status
# kept).  Under valgrind (make check-valgrind) an image with noise
# (NAME_LEVELS, noisy below) is compared without it: the same code as
# the image it was made from, which was compared under valgrind.
scene() {
    key="$TMP/$1.$(basename "$2")"
    if [ -f "$key.json" ]; then
        cp "$key.json" "$TMP/out"
        status=$(cat "$key.status")
        return
    fi
    case "$1" in
    *_[0-9]) quiet=${RAYO_VALGRIND:-0} RAYO_VALGRIND=0 ;;
    *) quiet= ;;
    esac
    run_capture compare "$2" "$TMP/$1.out" --json
    [ -z "$quiet" ] || RAYO_VALGRIND=$quiet
    cp "$TMP/out" "$key.json"
    echo "$status" >"$key.status"
}

# Where the centre (X, Y, Z) of a sphere appears: column and row, with
# the formula's focal distance 320 (640 pixels, 90 degrees).
column() { awk -v x="$1" -v z="$2" 'BEGIN { printf "%.1f", 320 + 320 * x / z }'; }
row() { awk -v y="$1" -v z="$2" 'BEGIN { printf "%.1f", 240 - 320 * y / z }'; }

for p in ej2_correct ej2_ambient_20 ej2_seventh_sphere ej2_background_ambient \
         ej2_shadow_zero ej2_missing_sphere ej2_last_sphere ej3_background_ambient \
         ej3_sphere_moved ej3_ambient_doubled correct pi_course \
         ej2_big_sphere ej2_small_sphere ej2_light_moved ej3_light_moved \
         ej3_correct ej3_hidden_sphere_bigger ej3_light_colour \
         ej3_light_missing ej3_directional_moved ej3_hidden_sphere_moved; do
    student "$p"
    ok $? "$p compiles and runs"
done
rayo render "$RAYO_SOURCE/examples/ej2.scene" -o "$TMP/r2.pgm"
rayo render "$RAYO_SOURCE/examples/ej1.scene" -o "$TMP/r1.pbm"
C2="$COURSE/referencia-catedra-ej2.png"
C3="$COURSE/referencia-catedra-ej3.png"

# --- a right image gets no findings ------------------------------------------
scene ej2_correct "$C2"
is "$(json .verdict)/$(json '.diagnosis.findings')" "consistent/null" \
    "ej2_correct: consistent, nothing found"

# --- EJ2 -------------------------------------------------------------------
scene ej2_ambient_20 "$C2"
is "$status/$(json .diagnosis.kind)" "1/scene" "IA = 20: inconsistent, a scene finding"
is "$(json '[.diagnosis.findings[].kind] | join(",")')" "ambient" "  only the ambient term"
is "$(json '.diagnosis.findings[0].value[0]')/$(json '.diagnosis.findings[0].expected[0]')" \
    "20/5" "  20 seen, the statement's 5"
json .diagnosis.text | grep -q "^the ambient intensity looks like 20, not the statement's IA = 5"
ok $? "  said as the statement's IA"

scene ej2_background_ambient "$C2"
is "$(json .diagnosis.kind)/$(json '[.diagnosis.findings[].kind] | join(",")')" \
    "scene/background" "background at IA: the background found"
is "$(json '.diagnosis.findings[0].value[0]')" 5 "  at 5"
json .diagnosis.text | grep -q "^the background is 5, the ambient intensity IA, not 0 (black): a ray that meets no sphere gives 0"
ok $? "  said as the statement says a ray that meets nothing"

scene ej2_seventh_sphere "$C2"
is "$(json .diagnosis.kind)/$(json '[.diagnosis.findings[].kind] | join(",")')" \
    "scene/added" "a seventh sphere: one object added"
x=$(column -2 3) y=$(row 1 3) # the added sphere's centre, (-2, 1, 3)
within "$(json '.diagnosis.findings[0].x')" "$x" 8
ok $? "  its column $(json '.diagnosis.findings[0].x') near $x, where (-2, 1, 3) appears"
within "$(json '.diagnosis.findings[0].y')" "$y" 8
ok $? "  its row $(json '.diagnosis.findings[0].y') near $y"
json .diagnosis.text | grep -q "^there is a sphere at about ([0-9]*, [0-9]*) px (columns [0-9]* to [0-9]*, rows [0-9]* to [0-9]*) that is not in the course's scene$"
ok $? "  said as a sphere not in the course's scene"

scene ej2_missing_sphere "$C2"
is "$(json .diagnosis.kind)/$(json '[.diagnosis.findings[].kind] | join(",")')" \
    "scene/missing" "a sphere left out: missing"
is "$(json '.diagnosis.findings[0].ball')" 3 "  the fourth of the statement's array"
within "$(json '.diagnosis.findings[0].x')" "$(column 3 5)" 0.05 &&
    within "$(json '.diagnosis.findings[0].y')" "$(row 1.5 5)" 0.05
ok $? "  where (3, 1.5, 5) appears: $(column 3 5), $(row 1.5 5)"
json .diagnosis.text | grep -q "^the sphere at about (512, 144) px, centre (3, 1.5, 5) and radius 0.4 in the statement, is missing"
ok $? "  named by its place and the statement's numbers"

scene ej2_shadow_zero "$C2"
is "$(json .diagnosis.kind)/$(json '[.diagnosis.findings[].kind] | join(",")')" \
    "scene/below-ambient" "shadow at 0: values below IA"
# Pixels that are 0 in the student's image where rayo's render has IA:
# the finding counts those away from the outlines, so a little fewer.
zeros=$(pnmtoplainpnm "$TMP/ej2_shadow_zero.out" | tail -n +4 | tr -s ' ' '\n' | grep -v '^$' >"$TMP/a";
        pnmtoplainpnm "$TMP/r2.pgm" | tail -n +4 | tr -s ' ' '\n' | grep -v '^$' >"$TMP/b";
        paste "$TMP/a" "$TMP/b" | awk '$1 == 0 && $2 == 5 { n++ } END { print n + 0 }')
got=$(json '.diagnosis.findings[0].pixels')
[ "$got" -le "$zeros" ] && [ $((got * 10)) -ge $((zeros * 9)) ]
ok $? "  $got pixels below IA: at most the $zeros counted here, and 90% of them"
is "$(json '.diagnosis.findings[0].shadowed')" "$got" "  all in a shadow another sphere casts"
json .diagnosis.text | grep -q "^$got pixels of the spheres are darker than IA = 5, which the model never gives"
ok $? "  said against the model: I is never below IA"

# A sphere of radius R at distance D spans asin(R / D) from the camera:
# its picture's size goes as the tangent of that.
span() { awk -v r="$1" -v x="$2" -v y="$3" -v z="$4" 'BEGIN { d = sqrt(x*x + y*y + z*z); a = atan2(r / d, sqrt(1 - (r / d)^2)); printf "%.4f", sin(a) / cos(a) }'; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.4f", a / b }'; }
# sized R STATED X Y Z: the first finding's sphere drawn R / STATED
# times as large as the scene's (at its distance), radius R
sized() {
    want=$(ratio "$(span "$1" "$3" "$4" "$5")" "$(span "$2" "$3" "$4" "$5")")
    got=$(ratio "$(json '.diagnosis.findings[0].radius_px')" "$(json '.diagnosis.findings[0].expected_px')")
    within "$got" "$want" 0.05
    ok $? "  drawn $got times the scene's size, about $want ($1 for $2 at its distance)"
    within "$(json '.diagnosis.findings[0].radius')" "$1" 0.02
    ok $? "  radius $(json '.diagnosis.findings[0].radius') in the statement's units, about $1"
}

scene ej2_big_sphere "$C2"
is "$(json .diagnosis.kind)/$(json '[.diagnosis.findings[].kind] | join(",")')" \
    "scene/size" "a radius 0.6 for 0.4: the sphere's size, nothing added"
is "$(json '.diagnosis.findings[0].ball')" 4 "  the fifth of the statement's array"
sized 0.6 0.4 3 -1.5 4
json .diagnosis.text | grep -q "^the sphere at about (560, 360) px, centre (3, -1.5, 4) and radius 0.4 in the statement, is drawn with a radius of about 0.6[0-9]* ([0-9]* px instead of [0-9]*): check its radius$"
ok $? "  said in the statement's terms"

scene ej2_small_sphere "$C2"
is "$(json .diagnosis.kind)/$(json '[.diagnosis.findings[].kind] | join(",")')" \
    "scene/size" "a radius 0.6 for 0.85: the sphere's size, not partly drawn"
is "$(json '.diagnosis.findings[0].ball')" 1 "  the second of the statement's array"
sized 0.6 0.85 -0.55 -0.4 2
json .diagnosis.text | grep -q "^the sphere at about (232, 304) px, centre (-0.55, -0.4, 2) and radius 0.85 in the statement, is drawn with a radius of about 0.[56][0-9]* ([0-9]* px instead of [0-9]*)"
ok $? "  said in the statement's terms"

# A picture of another field of view moves every sphere (outwards) and
# enlarges it a little: not a size, whichever way the spheres' rays read.
rayo render "$RAYO_SOURCE/examples/ej3.scene" --fov 88 -o "$TMP/fov88.ppm" &&
    mv "$TMP/fov88.ppm" "$TMP/fov88.out"
scene fov88 "$C3"
json '[.diagnosis.findings[]?.kind] | index("size")' | grep -qx null
ok $? "EJ3 at fov 88: no sphere named by its size ($(json .diagnosis.kind))"

scene ej2_light_moved "$C2"
is "$(json .diagnosis.kind)/$(json '[.diagnosis.findings[].kind] | join(",")')" \
    "scene/light-direction" "the light's x negated: the light's direction"
for c in 0 1 2; do
    want=$(sed -n 's/^const float luz\[3\] = {\(.*\)};$/\1/p' "$STUDENTS/ej2_light_moved/main.c" | cut -d, -f$((c + 1)))
    within "$(json ".diagnosis.findings[0].value[$c]")" "$want" 0.02
    ok $? "  L[$c] $(json ".diagnosis.findings[0].value[$c]"), the program's $want"
done
within "$(json '.diagnosis.findings[0].expected[0]')" 0.2873 0.001
ok $? "  against the statement's (0.287, 0.958, 0)"
json .diagnosis.text | grep -q "^the light seems to come from (-0.29, 0.96, 0.00), not the statement's (0.287, 0.958, 0): I = IA + II (L.N) fits"
ok $? "  said as where the light comes from"

# --- EJ3 -------------------------------------------------------------------
scene ej3_background_ambient "$C3"
is "$(json .diagnosis.kind)/$(json '[.diagnosis.findings[].kind] | join(",")')" \
    "scene/background" "EJ3 background at Ia: the background found"
b=$(awk 'BEGIN { printf "%d", 255 * 0.05 }')
is "$(json '.diagnosis.findings[0].value | map(tostring) | join(",")')" "$b,$b,$b" \
    "  at the byte of Ia = 0.05: $b"
json .diagnosis.text | grep -q "^the background is ($b, $b, $b), not black (0, 0, 0): a ray that meets no sphere gives black$"
ok $? "  said as the statement says"

scene ej3_ambient_doubled "$C3"
is "$(json .diagnosis.kind)/$(json '[.diagnosis.findings[].kind] | join(",")')" \
    "scene/ambient" "Ia doubled: the ambient term found"
for c in 0 1 2; do
    within "$(json ".diagnosis.findings[0].value[$c]")" 0.1 0.004
    ok $? "  channel $c: $(json ".diagnosis.findings[0].value[$c]"), about 0.1"
done
json .diagnosis.text | grep -q "^the ambient light looks like (0.100, 0.100, 0.100), not the statement's Ia = (0.05, 0.05, 0.05)"
ok $? "  said as the statement's Ia"

scene ej3_sphere_moved "$C3"
is "$(json .diagnosis.kind)/$(json '[.diagnosis.findings[].kind] | join(",")')" \
    "scene/moved" "a centre mistyped: the sphere moved"
[ "$(json '.diagnosis.findings[0].ball')" = 7 ] &&
    within "$(json '.diagnosis.findings[0].x')" "$(column 1.73 2)" 0.05 &&
    within "$(json '.diagnosis.findings[0].y')" "$(row -0.6 2)" 0.05
ok $? "  the blue sphere, (1.73, -0.6, 2), where it appears: $(column 1.73 2), $(row -0.6 2)"
within "$(json '.diagnosis.findings[0].to.x')" "$(column 1.73 2)" 8 &&
    within "$(json '.diagnosis.findings[0].to.y')" "$(row 0.3 2)" 8
ok $? "  found near where (1.73, 0.3, 2) appears: $(json '.diagnosis.findings[0].to.x'), $(json '.diagnosis.findings[0].to.y')"

scene ej3_light_moved "$C3"
is "$(json .diagnosis.kind)/$(json '[.diagnosis.findings[].kind] | join(",")')" \
    "scene/lamp-position" "the green light's x lost its sign: the light's place"
is "$(json '.diagnosis.findings[0].lamp')" 2 "  the third of the statement's lights, the green one"
place=$(sed -n 's/.*luz_crear((vector_t){\([^}]*\)}, (color_t){0, .9, 0}, true).*/\1/p' "$STUDENTS/ej3_light_moved/main.c")
near3 "$place" 0.02 P
is "$(json '.diagnosis.findings[0].expected | map(tostring) | join(",")')" "2,10,2.5" \
    "  against the statement's (2, 10, 2.5)"
json .diagnosis.text | grep -q "^the point light at (2, 10, 2.5) in the statement seems to be at about (-2.0, 10.0, 2.5) in the image: C = Ia ka + Ii kd (L.N) fits [0-9]* of the [0-9]* pixels it lights"
ok $? "  said as where the light is"

# noise: every sample moved by up to A levels (a fixed seed), plain PPM
noisy() {
    pnmtoplainpnm "$TMP/$1.out" | awk -v a="$2" 'BEGIN { srand(7) }
        NR <= 3 { print; next }
        { for (i = 1; i <= NF; i++) { v = $i + int(rand() * (2 * a + 1)) - a;
              if (v < 0) v = 0; if (v > 255) v = 255; printf "%d ", v }
          print "" }' >"$TMP/$1_$2.out"
}
noisy ej3_light_moved 1
scene ej3_light_moved_1 "$C3"
is "$(json '[.diagnosis.findings[].kind] | join(",")')/$(json '.diagnosis.findings[0].value | map(. * 10 | round / 10) | map(tostring) | join(",")')" \
    "lamp-position/-2,10,2.5" "  through noise of a level: the same place"
for a in 2 4; do
    noisy ej3_correct $a
    scene "ej3_correct_$a" "$C3"
    json '[.diagnosis.findings[]?.kind] | index("lamp-position")' | grep -qx null
    ok $? "a right EJ3 image with noise of $a levels: no light named ($(json .diagnosis.kind))"
done

# The red light's colour typed (.5, 0, 0): read from the red channel,
# the light's place held; the program's own colour.
scene ej3_light_colour "$C3"
is "$(json .diagnosis.kind)/$(json '[.diagnosis.findings[].kind] | join(",")')" \
    "scene/lamp-colour" "the red light's colour typed .5: the light's colour"
is "$(json '.diagnosis.findings[0].lamp')" 1 "  the second of the statement's lights, the red one"
colour=$(sed -n 's/.*luz_crear((vector_t){-2, 10, 2.5}, (color_t){\([^}]*\)}, true).*/\1/p' "$STUDENTS/ej3_light_colour/main.c")
near3 "$colour" 0.01 Ii
is "$(json '.diagnosis.findings[0].expected | map(tostring) | join(",")')" "0.9,0,0" \
    "  against the statement's (0.9, 0, 0)"
json .diagnosis.text | grep -q "^the light at (-2, 10, 2.5) looks like colour (0.50, 0.00, 0.00), not the statement's (0.9, 0, 0): C = Ia ka + Ii kd (L.N) fits [0-9]* of the [0-9]* pixels it lights with that Ii$"
ok $? "  said as the light's colour"

# The blue light left out: its channel stays at Ia ka where it lit.
scene ej3_light_missing "$C3"
is "$(json .diagnosis.kind)/$(json '[.diagnosis.findings[].kind] | join(",")')" \
    "scene/lamp-missing" "the blue light left out: the light missing"
is "$(json '.diagnosis.findings[0].lamp')/$(json '.diagnosis.findings[0].value[2]')" "3/0" \
    "  the fourth of the statement's lights, the blue one, at 0"
json .diagnosis.text | grep -q "^the light at (0, 10, 5) of the statement is not in your image: "
ok $? "  said as a light not in the image"

# Through noise of 2 levels the same, and the right image gets neither.
for p in ej3_light_colour ej3_light_missing; do
    noisy $p 2
    scene "${p}_2" "$C3"
    is "$(json '[.diagnosis.findings[].kind] | join(",")')" "$(echo $p | sed 's/ej3_light_/lamp-/')" \
        "$p with noise of 2 levels: the same finding"
done
for a in 2 4; do
    scene "ej3_correct_$a" "$C3"
    json '[.diagnosis.findings[]?.kind] | (index("lamp-colour") // index("lamp-missing"))' | grep -qx null
    ok $? "a right EJ3 image with noise of $a levels: no light's colour named"
done

# The directional light typed (1, 1, 0): its direction read on every
# channel once the point lights are taken off, the program's own vector
# normalised; through noise of 2 levels the same.
scene ej3_directional_moved "$C3"
is "$(json .diagnosis.kind)/$(json '[.diagnosis.findings[].kind] | join(",")')" \
    "scene/light-direction" "EJ3's directional light typed (1, 1, 0): its direction"
near3 "$(awk 'BEGIN { printf "%.4f,%.4f,0", 1 / sqrt(2), 1 / sqrt(2) }')" 0.02 L
is "$(json '.diagnosis.findings[0].expected | map(tostring) | join(",")')" "0,1,0" \
    "  against the statement's (0, 1, 0)"
json .diagnosis.text | grep -q "^the directional light seems to come from (0.71, 0.71, 0.00), not the statement's (0, 1, 0): C = Ia ka + Ii kd (L.N) fits [0-9]* of the [0-9]* values it lights with that L$"
ok $? "  said as where the directional light comes from"
noisy ej3_directional_moved 2
scene ej3_directional_moved_2 "$C3"
is "$(json '[.diagnosis.findings[].kind] | join(",")')/$(json '.diagnosis.findings[0].value | map(. * 10 | round / 10) | map(tostring) | join(",")')" \
    "light-direction/0.7,0.7,0" "  through noise of 2 levels: the same direction"
for a in 2 4; do
    scene "ej3_correct_$a" "$C3"
    json '[.diagnosis.findings[]?.kind] | index("light-direction")' | grep -qx null
    ok $? "a right EJ3 image with noise of $a levels: no direction named"
done

# The blue sphere's centre is behind the cyan one (1, -0.6, 1.26): only
# its outer crescent shows, and that is what its size is read from.
scene ej3_hidden_sphere_bigger "$C3"
is "$(json .diagnosis.kind)/$(json '[.diagnosis.findings[].kind] | join(",")')" \
    "scene/size" "a hidden-centred sphere's radius 0.4 for 0.3: its size, not partly drawn"
is "$(json '.diagnosis.findings[0].ball')" 7 "  the blue sphere, the eighth of the statement's array"
sized 0.4 0.3 1.73 -0.6 2
json .diagnosis.text | grep -q "^the sphere at about (597, 336) px, centre (1.73, -0.6, 2) and radius 0.3 in the statement, is drawn with a radius of about 0.4[0-9]* ([0-9]* px instead of [0-9]*): check its radius$"
ok $? "  said in the statement's terms"

# The same blue sphere's centre typed (1.73, -.5, 2): still hidden, its
# crescent moved up: placed from its outline, not named by its size;
# the place near where (1.73, -0.5, 2) appears, its centre near it.
scene ej3_hidden_sphere_moved "$C3"
is "$(json .diagnosis.kind)/$(json '[.diagnosis.findings[].kind] | join(",")')" \
    "scene/moved" "a hidden-centred sphere moved 0.1 up: moved, not another size"
is "$(json '.diagnosis.findings[0].ball')" 7 "  the blue sphere"
within "$(json '.diagnosis.findings[0].to.x')" "$(column 1.73 2)" 4 &&
    within "$(json '.diagnosis.findings[0].to.y')" "$(row -0.5 2)" 4
ok $? "  drawn near where (1.73, -0.5, 2) appears, $(column 1.73 2), $(row -0.5 2): $(json '.diagnosis.findings[0].to.x'), $(json '.diagnosis.findings[0].to.y')"
within "$(json '.diagnosis.findings[0].centre[1]')" -0.5 0.04
ok $? "  its centre's y about -0.5: $(json '.diagnosis.findings[0].centre[1]')"
json .diagnosis.text | grep -q "^the sphere at about (597, 336) px, centre (1.73, -0.6, 2) and radius 0.3 in the statement, whose centre is hidden, is drawn centred at about ([0-9]*, [0-9]*) px, as a centre of about (1.7[0-9], -0.5[0-9], 2) would be: the outline that shows is the scene's moved; check its centre$"
ok $? "  said as its centre"
# noise of 2 or 4 levels: no size or move named, on this one or a right one
for p in ej3_correct ej3_hidden_sphere_moved; do
    for a in 2 4; do
        [ -f "$TMP/${p}_$a.out" ] || noisy $p $a
        scene "${p}_$a" "$C3"
        json '[.diagnosis.findings[]?.kind] | (index("size") // index("moved"))' | grep -qx null
        ok $? "$p with noise of $a levels: no sphere named moved or another size ($(json .diagnosis.kind))"
    done
done
# the picture at fov 88 moves every sphere: no hidden one named moved
scene fov88 "$C3"
json '[.diagnosis.findings[]?.kind] | index("moved")' | grep -qx null
ok $? "EJ3 at fov 88: no sphere named moved"

# Other mistakes of the model: none of these findings, which read the
# statement's lights and spheres, is named for them.
for p in ej3_light_reversed ej3_point_as_directional ej3_no_shadows ej3_ka_kd_swapped; do
    student "$p"
    scene "$p" "$C3"
    json '[.diagnosis.findings[]?.kind] | map(select(. == "lamp-colour" or . == "lamp-missing" or . == "light-direction" or . == "moved")) | length' | grep -qx 0
    ok $? "$p: no light's colour, absence or direction, nor a sphere moved, named ($(json .diagnosis.kind))"
done

# --- nothing fits: where the differences lie -------------------------------
scene ej2_last_sphere "$TMP/r2.pgm"
is "$(json .diagnosis.kind)/$(json '.diagnosis.findings[0].kind')" "unknown/where" \
    "the last sphere drawn over the nearer: unknown, and where"
is "$(json '.diagnosis.findings[0].ball')" 2 \
    "  most on the sphere (3, 1.5, 4), which (3, 1.5, 5) is drawn over"
json .diagnosis.text | grep -q "^no single mistake explains the differences: [0-9]* of the [0-9]* pixels of the sphere at about ($(column 3 4 | cut -d. -f1), $(row 1.5 4 | cut -d. -f1)) px differ"
ok $? "  said as which sphere, not a first pixel"

# --- EJ1: pi = sqrt(9.81) ----------------------------------------------------
focal=$(awk 'BEGIN { printf "%.4f", 1 / (sin(sqrt(9.81) / 4) / cos(sqrt(9.81) / 4)) }')
run_capture compare "$TMP/r1.pbm" "$TMP/pi_course.out"
is "$status" 0 "EJ1 with pi = sqrt(9.81): consistent with rayo's render"
grep -q "^note: the image is the reference enlarged $focal times about the centre" "$TMP/out"
ok $? "  the sphere $focal times larger: the course's focal distance"
run_capture compare "$TMP/r1.pbm" "$TMP/correct.out"
grep -q "^note:" "$TMP/out"
is $? 1 "  the right program's image (identical) gets no such note"
run_capture compare "$COURSE/referencia-catedra-ej1.png" "$TMP/correct.out"
grep -q "^note: the reference is the image enlarged $focal times" "$TMP/out"
ok $? "  a right image against the course's reference: the reference's focal distance"
run_capture grade --exercise ej1 --no-valgrind "$STUDENTS/pi_course"
grep -q "^image  *pass  *consistent with the reference: .*, because your sphere is 0.48% larger than the formula's, as in the course's own reference" "$TMP/out"
ok $? "  grade: passes, and says the sphere is 0.48% larger, not rounding"

done_testing
