#!/bin/sh
# compare_inputs.t - what compare's operands name: a --diff that is one of
# the inputs (the same name, another path to it, a symbolic or hard link)
# is refused with exit 2 and the input left as it was; course:ej1,
# course:ej2 and course:ej3 name the course's reference images from the
# source tree, from $RAYO_DATA_DIR, once installed and, with no file, the
# copy built into rayo; a file of that very name in the current
# directory wins.
. "$(dirname "$0")/lib.sh"

cd "$TMP" || exit 1
rayo -W 32 -H 24 -o a.png
rayo -W 32 -H 24 --sphere 0,0,3,1 -o b.png
cp a.png a.keep
ln -s a.png link.png
ln a.png hard.png
mkdir sub

# --- --diff must not be an input -------------------------------------------
for diff in a.png ./a.png sub/../a.png "$TMP/a.png" link.png hard.png; do
    expect_usage_error "--diff $diff, the reference" "--diff: '.*' is the reference; refusing to overwrite an input" \
        compare a.png b.png --diff "$diff"
    cmp -s a.png a.keep
    ok $? "--diff $diff: the reference is untouched"
done
expect_usage_error "--diff the image" "is the image; refusing" \
    compare b.png a.png --diff link.png
cmp -s a.png a.keep
ok $? "--diff the image: the image is untouched"
expect_usage_error "compare a.png a.png --diff a.png" "is the reference" \
    compare a.png a.png --diff a.png
cmp -s a.png a.keep
ok $? "compare a.png a.png --diff a.png: untouched"
run_capture compare a.png b.png --diff d.png
is "$status" 1 "--diff to another file: written (inconsistent: 1)"
ok "$([ -s d.png ]; echo $?)" "  the difference picture exists"
is "$(pngtopnm d.png | pamfile - | sed 's/.*:\t*//')" "PPM raw, 32 by 24  maxval 255" "  the reference's size, RGB"

# --- course:NAME -------------------------------------------------------------
course=$RAYO_SOURCE/data/course
# expect_course NAME ENV... : compare course:ej1 with the ej1 file itself
# is identical, in whichever way the command finds it.
run_capture compare course:ej1 "$course/referencia-catedra-ej1.png"
is "$status" 0 "course:ej1 from the source tree (build/rayo)"
grep -q "verdict: identical" "$TMP/out"
ok $? "  is the course's EJ1 image"
run_capture compare course:ej3 "$course/referencia-catedra-ej3.png"
grep -q "verdict: identical" "$TMP/out"
ok $? "course:ej3 is the course's EJ3 image"
run_capture compare course:ej2 "$course/referencia-catedra-ej3.png"
is "$status" 1 "course:ej2 is not EJ3's image"
rayo view --ascii --cols 40 course:ej1 >view.txt 2>"$TMP/err"
ok $? "view course:ej1"
rayo convert course:ej2 ej2.ppm 2>"$TMP/err"
is "$(head -c 2 ej2.ppm)" "P6" "convert course:ej2 (a PNG: raw PPM)"
pngtopnm "$course/referencia-catedra-ej2.png" | cmp -s - ej2.ppm
ok $? "  the same pixels as pngtopam's"

# the installed layout: PREFIX/bin/rayo beside PREFIX/share/rayo/course
mkdir -p prefix/bin prefix/share/rayo/course data/course
cp "$RAYO" prefix/bin/rayo
cp "$course"/*.png prefix/share/rayo/course/
status=0
prefix/bin/rayo compare course:ej2 "$course/referencia-catedra-ej2.png" >"$TMP/out" 2>"$TMP/err" || status=$?
is "$status" 0 "installed: course:ej2 found under share/rayo/course"
rm prefix/share/rayo/course/referencia-catedra-ej1.png
status=0
prefix/bin/rayo compare course:ej1 "$course/referencia-catedra-ej1.png" >"$TMP/out" 2>"$TMP/err" || status=$?
is "$status" 0 "installed, the image removed: the copy built into rayo"
grep -q "verdict: identical" "$TMP/out"
ok $? "  is the course's EJ1 image"
# $RAYO_DATA_DIR first: a stand-in there is what course:ej1 names
cp b.png data/course/referencia-catedra-ej1.png
status=0
RAYO_DATA_DIR=$TMP/data prefix/bin/rayo compare course:ej1 b.png >"$TMP/out" 2>"$TMP/err" || status=$?
grep -q "verdict: identical" "$TMP/out"
ok $? "\$RAYO_DATA_DIR/course comes first"

# a file of that very name wins; unknown names are refused
cp b.png course:ej1
run_capture compare course:ej1 b.png
grep -q "verdict: identical" "$TMP/out"
ok $? "a file named course:ej1 in the current directory wins"
rm course:ej1
expect_usage_error "course:ej4" "course:ej4: no such course image; expected course:ej1, course:ej2 or course:ej3" \
    compare course:ej4 b.png
done_testing
