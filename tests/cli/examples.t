#!/bin/sh
# examples.t - the C examples of the library's API (examples/*.c), built
# by make check with the course's flags: render_png renders a scene file
# to the PNG `rayo render SCENE -o OUT.png` writes, pixel for pixel (both
# decoded by Netpbm's pngtopnm), and reports a bad scene in one line.
. "$(dirname "$0")/lib.sh"

example=$RAYO_BUILD/examples/render_png
ok "$([ -x "$example" ]; echo $?)" "make check built examples/render_png.c"
for scene in showcase ej2 ej3 ej1; do
    src=$RAYO_SOURCE/examples/$scene.scene
    "$example" "$src" "$TMP/$scene.png" 2>"$TMP/err"
    ok $? "render_png $scene.scene: exit 0"
    rayo render "$src" -q -o "$TMP/$scene-rayo.png"
    pngtopnm "$TMP/$scene.png" >"$TMP/a.pnm" 2>/dev/null &&
        pngtopnm "$TMP/$scene-rayo.png" >"$TMP/b.pnm" 2>/dev/null &&
        [ -s "$TMP/a.pnm" ] && cmp -s "$TMP/a.pnm" "$TMP/b.pnm"
    ok $? "  the same pixels as rayo render's PNG"
done
is "$(pngtopnm "$TMP/showcase.png" 2>/dev/null | pamfile - | sed 's/.*:\t*//')" \
    "PPM raw, 640 by 480  maxval 255" "showcase: 640x480 colour, as its camera line says"
printf 'sphere 0 0 3\n' >"$TMP/bad.scene"
status=0
"$example" "$TMP/bad.scene" "$TMP/bad.png" 2>"$TMP/err" || status=$?
is "$status" 2 "a malformed scene: exit 2"
grep -q "^render_png: $TMP/bad.scene:1:" "$TMP/err"
ok $? "  one line naming the file and line"
ok "$([ ! -e "$TMP/bad.png" ]; echo $?)" "  and no PNG"
status=0
"$example" >/dev/null 2>&1 || status=$?
is "$status" 2 "no arguments: usage, exit 2"
done_testing
