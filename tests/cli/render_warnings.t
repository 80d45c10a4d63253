#!/bin/sh
# render_warnings.t - a scene file with no objects, or with no camera line,
# renders (exit 0) with one line of warning on stderr saying so; a scene
# with both, or a camera given on the command line, gets no such warning.
. "$(dirname "$0")/lib.sh"

cd "$TMP" || exit 1
: >empty.scene
printf '# nothing but a comment\nbackground 0.2 0.4 0.6\n' >bg.scene
printf 'sphere 0 0 3 1\n' >nocam.scene
printf 'camera size 16 12\n' >cam.scene
printf 'camera size 16 12\nsphere 0 0 3 1\n' >full.scene

# warns NAME PATTERN ARGS...: exit 0, one line on stderr matching PATTERN
warns() {
    name=$1 pattern=$2
    shift 2
    run_capture "$@"
    is "$status" 0 "$name: exit 0"
    is "$(wc -l <"$TMP/err" | tr -d ' ')" 1 "$name: one line on stderr"
    grep -Eq -- "$pattern" "$TMP/err"
    ok $? "$name: /$pattern/"
    [ "$tap_failed" -eq 0 ] || sed 's/^/#   stderr: /' "$TMP/err"
}
warns "empty scene" "^rayo: warning: empty.scene has no objects and no camera; the image is the background, 640x480$" \
    render empty.scene -o e.ppm
is "$(pamfile e.ppm | sed 's/.*:\t*//')" "PPM plain, 640 by 480  maxval 255" "  the image is 640x480"
warns "background only" "^rayo: warning: bg.scene has no objects and no camera" \
    render bg.scene -q -o bg.ppm
# Every pixel is the background colour (0.2 0.4 0.6 -> 51 102 153).
is "$(pnmtoplainpnm bg.ppm | tail -n +4 | tr -s ' \n' '\n\n' | sed '/^$/d' | sort -u | tr '\n' ' ')" "102 153 51 " \
    "  every pixel is the background"
warns "no camera" "^rayo: warning: nocam.scene has no camera; using the default one: 640x480, fov 90, at 0,0,0 looking down \+z$" \
    render nocam.scene -o n.ppm
warns "camera, no objects" "^rayo: warning: cam.scene has no objects; the image is the background$" \
    render cam.scene -o c.ppm
warns "no objects, camera options" "^rayo: warning: empty.scene has no objects; the image is the background$" \
    render empty.scene -W 8 -H 6 -o c2.ppm
warns "from standard input" "^rayo: warning: standard input has no objects and no camera" \
    render - -o std.ppm <empty.scene
run_capture render full.scene -o f.ppm
is "$status:$(wc -c <"$TMP/err" | tr -d ' ')" "0:0" "a scene with a camera and objects: no warning"
run_capture render nocam.scene -W 16 -H 12 -o n2.ppm
is "$status:$(wc -c <"$TMP/err" | tr -d ' ')" "0:0" "no camera line but -W -H: no warning"
run_capture -W 8 -H 6 -o s.pbm
is "$status:$(wc -c <"$TMP/err" | tr -d ' ')" "0:0" "no scene file: no warning"
done_testing
