#!/bin/sh
# grade_tp1.t - `rayo grade --exercise tp1` on a folder submission: the
# correct TP1 of tests/grade/tp1/correct/ (with examples/gema.stl, the
# mesh its scene reads) passes every criterion but the image, which has
# no reference; each mistake of the corpus (tests/grade/CORPUS.md, "TP1")
# is made here from a copy of it by one small edit, and its verdict and
# its reason line are asserted.
. "$(dirname "$0")/lib.sh"

SRC="$RAYO_SOURCE/tests/grade/tp1/correct"
HAVE_VALGRIND=0
command -v valgrind >/dev/null 2>&1 && HAVE_VALGRIND=1

# submission NAME: a fresh copy of correct/ in $TMP/NAME (its path in $dir).
submission() {
    dir="$TMP/$1"
    mkdir "$dir"
    cp "$SRC"/*.c "$SRC"/*.h "$SRC/Makefile" "$RAYO_SOURCE/examples/gema.stl" "$dir/"
}

# grade [OPTIONS...]: grades $dir; $status, and $results one word per
# criterion ("compile=pass functions=FAIL ...").
grade() {
    run_capture grade --exercise tp1 "$@" "$dir"
    results=$(awk '/^(compile|functions|run|output|image|valgrind) / {
                       printf "%s%s=%s", sep, $1, $2; sep = " " }' "$TMP/out")
}

# says PATTERN NAME: the report has a line matching PATTERN (grep -E).
says() {
    found=0
    grep -Eq -- "$1" "$TMP/out" || found=1
    ok "$found" "$2"
    [ "$found" -eq 0 ] || sed 's/^/#   /' "$TMP/out"
}

FIRST="compile=pass functions=pass run=pass"

submission correct
if [ "$HAVE_VALGRIND" = 1 ]; then grade; want=pass; else grade --no-valgrind; want=skipped; fi
is "$status" 0 "correct: exit status 0"
is "$results" "$FIRST output=pass image=skipped valgrind=$want" \
    "correct: every criterion passes, the image has no reference"
says '^compile +pass +make ran 11 compile commands, each with -std=c99 -Wall -Werror -pedantic$' \
    "correct: make's 11 compile commands carry the course's flags"
says "objeto_distancia has the statement's prototype" "correct: objeto_distancia"
says "computar_intensidad has the statement's prototype" "correct: computar_intensidad"
says "tp1.ppm and tp1.bmp hold the same pixels" "correct: the PPM and the BMP agree"
says "both 161x121 as asked" "correct: the size of the arguments"
says "it printed a message and failed" "correct: wrong arguments"
grep -q '^ *note: ' "$TMP/out"
ok "$([ $? -ne 0 ]; echo $?)" "correct: no lookup-table note"

# A Makefile that spells gcc itself and links without the flags: the
# compiles are what the flags are checked on.
submission gcc_spelled
sed -i 's/\$(CC) \$(CFLAGS) \$(OBJS)/gcc $(OBJS)/; s/\$(CC) \$(CFLAGS) -c/gcc $(CFLAGS) -c/' "$dir/Makefile"
grade --no-valgrind
is "$status:$results" "0:$FIRST output=pass image=skipped valgrind=skipped" "gcc_spelled: passes"
says '^compile +pass +make ran 11 compile commands' "gcc_spelled: its 11 compiles checked"

# The BMP's rows written top first under a positive height.
submission bmp_top_down
sed -i 's/for (y = im->alto; y-- > 0;) {/for (y = 0; y < im->alto; y++) {/' "$dir/imagen.c"
grade --no-valgrind
is "$status:$results" "1:$FIRST output=FAIL image=skipped valgrind=skipped" "bmp_top_down: output fails"
says "tp1.bmp is tp1.ppm upside down: its rows are stored top first" "bmp_top_down: named"

# The rows top first under a negative height: the same picture, not the
# course's layout.
submission bmp_negative_height
sed -i 's/for (y = im->alto; y-- > 0;) {/for (y = 0; y < im->alto; y++) {/; s/escribir_int32_little_endian(f, (int32_t)im->alto);/escribir_int32_little_endian(f, -(int32_t)im->alto);/' "$dir/imagen.c"
grade --no-valgrind
is "$status:$results" "1:$FIRST output=FAIL image=skipped valgrind=skipped" "bmp_negative_height: output fails"
says "tp1.bmp: its rows are stored top-down \(height -121\); the course's BMP has a positive height" \
    "bmp_negative_height: named"
says "tp1.ppm and tp1.bmp hold the same pixels" "bmp_negative_height: the picture itself is right"

# The BMP's rows without their padding to 4 bytes.
submission bmp_unpadded
sed -i 's|size_t fila = (3 \* im->ancho + 3) / 4 \* 4;|size_t fila = 3 * im->ancho;|' "$dir/imagen.c"
grade --no-valgrind
is "$status:$results" "1:$FIRST output=FAIL image=skipped valgrind=skipped" "bmp_unpadded: output fails"
says "tp1.bmp: its rows are not padded: each has 483 bytes; the course pads them with zeros to 484" \
    "bmp_unpadded: named, with the bytes"

# The BMP's pixels in R G B order.
submission bmp_rgb
sed -i 's/color_byte(c\.b), f)/color_byte(c.X), f)/; s/color_byte(c\.r), f)/color_byte(c.b), f)/; s/color_byte(c\.X), f)/color_byte(c.r), f)/' "$dir/imagen.c"
grade --no-valgrind
is "$status:$results" "1:$FIRST output=FAIL image=skipped valgrind=skipped" "bmp_rgb: output fails"
says "tp1.bmp holds its pixels in R G B order" "bmp_rgb: named"

# No check of the argument count: it reads argv[1] that is not there.
submission no_usage
sed -i 's/if (argc != 5) {/if (argc < 0) {/' "$dir/main.c"
grade --no-valgrind
is "$status:$results" "1:compile=pass functions=pass run=FAIL output=pass image=skipped valgrind=skipped" \
    "no_usage: run fails, the files are still checked"
says "run with no arguments, it crashed \(segmentation fault" "no_usage: the crash named"

# -Werror left out of the Makefile, and a variable never used.
submission warning
sed -i 's/ -Werror//' "$dir/Makefile"
sed -i '/^int main(int argc, char \*argv\[\])$/{n;s/$/\n    int sin_usar;/}' "$dir/main.c"
grade --no-valgrind
is "$status:$results" "1:compile=FAIL functions=skipped run=skipped output=skipped image=skipped valgrind=skipped" \
    "warning: compile fails"
says "^compile +FAIL +the compile command '[^ ]+ -std=c99 -Wall -pedantic -c main.c' lacks -Werror; the course builds with -std=c99 -Wall -Werror -pedantic$" \
    "warning: the flag missing named"
says "the build printed warnings; the statement asks for none" "warning: the warning named"
says "unused variable .sin_usar." "warning: the compiler's warning quoted"

# A leak: the lights are never freed.
submission leak
sed -i '/imagen_destruir(im);/{n;n;d}' "$dir/main.c"
if [ "$HAVE_VALGRIND" = 1 ]; then
    grade
    is "$status:$results" "1:$FIRST output=pass image=skipped valgrind=FAIL" "leak: valgrind fails"
    says "definitely lost" "leak: the leak named"
else
    diag "valgrind is not installed: leak not checked"
fi

# A switch on the geometry's kind instead of the lookup table: a note,
# no failure.
submission switch_kind
sed -i 's/^    destructores\[objeto->geometria\](objeto->g);$/    switch (objeto->geometria) {\n    default:\n        destructores[objeto->geometria](objeto->g);\n    }/' "$dir/objeto.c"
grade --no-valgrind
is "$status:$results" "0:$FIRST output=pass image=skipped valgrind=skipped" "switch_kind: passes"
says "note: objeto.c:[0-9]+ chooses by the geometry's kind with 'switch \(objeto->geometria\)'; the statement asks for lookup tables" \
    "switch_kind: the note for the teacher"

# The statement's prototype with another parameter's name: the names do
# not change a function's type, so it is the statement's, with a line
# that says so.
submission renamed_parameter
sed -i '/^color_t computar_intensidad(int profundidad/,/^}/s/profundidad/nivel/g' "$dir/main.c"
grade --no-valgrind
is "$(echo "$results" | cut -d' ' -f2)" "functions=pass" "renamed_parameter: functions passes"
says "computar_intensidad has the statement's prototype, with other names for its parameters" \
    "renamed_parameter: said"

# A prototype of another type: profundidad unsigned.
submission signature
sed -i 's/^color_t computar_intensidad(int profundidad/color_t computar_intensidad(unsigned profundidad/' "$dir/main.c"
grade --no-valgrind
is "$(echo "$results" | cut -d' ' -f2)" "functions=FAIL" "signature: functions fails"
says "no computar_intensidad with the statement's prototype, color_t computar_intensidad\(int profundidad," "signature: named"

# A submission folder with no Makefile.
submission no_makefile
rm "$dir/Makefile"
grade --no-valgrind
is "$status:$(echo "$results" | cut -d' ' -f1)" "1:compile=FAIL" "no_makefile: compile fails"
says "make did not build the program" "no_makefile: named"

done_testing
