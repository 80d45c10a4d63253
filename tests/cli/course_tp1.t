#!/bin/sh
# course_tp1.t - the course-tp1 shading mode against the TP1 statement's
# model computed independently (tests/cli/tp1_model.py: its own camera,
# intersections and Phong, in Python): spheres, a plane, a triangle, a
# point and a directional light, a sphere above the point light (a shadow
# only under the statement's literal reading), reflections at depth 0 to
# 3, and each reading of what the statement leaves open.  Every pixel
# must agree; and each reading must change the picture, or the test
# could not tell them apart.
. "$(dirname "$0")/lib.sh"

model() { # model NAME ARGS...: rayo's render and the model's, compared
    name=$1
    shift
    python3 "$RAYO_SOURCE/tests/cli/tp1_model.py" "$TMP/$name.scene" \
        "$TMP/$name.want.ppm" "$@"
    rayo render "$TMP/$name.scene" --raw -o "$TMP/$name.ppm"
    cmp -s "$TMP/$name.ppm" "$TMP/$name.want.ppm"
    ok $? "course-tp1, $name: every pixel is the statement's"
}
model plain
model depth0 depth 0
model depth3 depth 3
model tinted tinted
model to_light to-light
model both tinted to-light depth 2

differs() { # differs A B NAME
    cmp -s "$TMP/$1.ppm" "$TMP/$2.ppm"
    ok "$([ $? -ne 0 ]; echo $?)" "$3"
}
differs plain depth0 "depth 0 is the scene without reflections"
differs plain depth3 "  and deeper reflections add to it"
differs plain tinted "tinted reflections differ from untinted ones"
differs plain to_light "the sphere beyond the point light shadows only under the literal reading"

# The mode's settings on the shade line are checked.
printf 'shade course-tp1 epsilon 2\n' >"$TMP/bad.scene"
run_capture render "$TMP/bad.scene" -o "$TMP/bad.ppm"
is "$status:$(cat "$TMP/err")" "2:rayo: $TMP/bad.scene:1:26: epsilon 2 is not accepted; expected a number from 0 to 1" \
    "an epsilon over 1 is refused"
printf 'shade course-tp1 shiny\n' >"$TMP/bad.scene"
run_capture render "$TMP/bad.scene" -o "$TMP/bad.ppm"
is "$status:$(cat "$TMP/err")" "2:rayo: $TMP/bad.scene:1:18: found 'shiny'; expected tinted-reflections, shadows-to-light, epsilon or the end of the 'shade' line" \
    "an unknown reading is refused"
done_testing
