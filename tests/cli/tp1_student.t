#!/bin/sh
# tp1_student.t - rayo's course-tp1 mode against a whole TP1 submission
# written independently, as a student of the course would
# (tests/grade/tp1/correct/: its own modules, lookup tables, STL reader
# and PPM and BMP writers; its hard-coded scene is examples/tp1.scene).
# Built with the course's flags, run at depth 0, 1 and 2 into .ppm and
# .bmp; rayo renders the scene file at the same depth, and rayo compare
# must find them identical but for the 4 pixels where the blue triangle's
# base edge lies in the floor plane: there the two are at the same
# distance and rounding picks one or the other (docs/shading.md,
# "course-tp1"). The student's BMP and PPM must be the same picture.
# Under RAYO_VALGRIND=1 the pictures are 320x240, where 2 pixels of that
# edge differ.
. "$(dirname "$0")/lib.sh"

SRC="$RAYO_SOURCE/tests/grade/tp1/correct"
if [ "${RAYO_VALGRIND:-0}" = 1 ]; then
    W=320 H=240 EDGE=2
else
    W=640 H=480 EDGE=4
fi

mkdir "$TMP/tp1"
cp "$SRC"/*.c "$SRC"/*.h "$SRC/Makefile" "$RAYO_SOURCE/examples/gema.stl" "$TMP/tp1/"
make -s -C "$TMP/tp1" CC="${RAYO_CC:-cc}" >"$TMP/make.log" 2>&1
ok $? "the submission builds with -std=c99 -Wall -Werror -pedantic"

for depth in 0 1 2; do
    (cd "$TMP/tp1" && ./20212_tp1 "$W" "$H" "$depth" "s$depth.ppm" &&
        ./20212_tp1 "$W" "$H" "$depth" "s$depth.bmp")
    ok $? "depth $depth: the submission writes its .ppm and .bmp"
    rayo render "$RAYO_SOURCE/examples/tp1.scene" --depth "$depth" \
        -W "$W" -H "$H" -o "$TMP/r$depth.ppm"
    ok $? "depth $depth: rayo renders examples/tp1.scene"

    run_capture compare "$TMP/tp1/s$depth.ppm" "$TMP/tp1/s$depth.bmp" --json
    is "$status:$(jq -r '.verdict + " " + (.differing | tostring)' "$TMP/out")" \
        "0:identical 0" "depth $depth: the student's BMP is its PPM"

    run_capture compare "$TMP/r$depth.ppm" "$TMP/tp1/s$depth.ppm" --json
    is "$status:$(jq -r '[.differing, .at_edges, .unexplained] | map(tostring) | join(" ")' "$TMP/out")" \
        "0:$EDGE $EDGE 0" \
        "depth $depth: rayo and the student differ only on the triangle's edge in the floor ($EDGE pixels)"
    if [ "$EDGE" -eq 0 ]; then want=identical; else want=consistent; fi
    is "$(jq -r .verdict "$TMP/out")" "$want" "depth $depth: rayo compare says $want"
done

# The statement's acceptance: no memory error and no leak, in valgrind mode.
if [ "${RAYO_VALGRIND:-0}" = 1 ]; then
    (cd "$TMP/tp1" && valgrind -q --error-exitcode=99 --leak-check=full \
        --errors-for-leak-kinds=definite,indirect,possible \
        ./20212_tp1 32 24 2 small.bmp)
    ok $? "the submission runs clean under valgrind"
fi

# Depth matters in this scene, or the test could not tell the levels apart.
cmp -s "$TMP/r0.ppm" "$TMP/r1.ppm"
ok "$([ $? -ne 0 ]; echo $?)" "depth 1 adds reflections to depth 0"
cmp -s "$TMP/r1.ppm" "$TMP/r2.ppm"
ok "$([ $? -ne 0 ]; echo $?)" "  and depth 2 to depth 1"
done_testing
