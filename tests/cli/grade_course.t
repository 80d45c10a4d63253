#!/bin/sh
# grade_course.t - `rayo grade --exercise ej2|ej3` on the student corpus
# of tests/grade/ej2_*/ and ej3_*/ (one typical mistake each, described
# with what was measured in tests/grade/CORPUS.md), and the EJ1 program
# that reads the statement's rows literally: every program gets exactly
# the criteria its mistake deserves, and the report names the mistake in
# the student's terms.
#
# Valgrind runs for the programs whose mistake is about memory and for
# the correct ones; the others are graded with --no-valgrind to keep the
# test short.  Under `make check-valgrind` (rayo itself under memcheck)
# only a few programs are graded.
. "$(dirname "$0")/lib.sh"

STUDENTS="$RAYO_SOURCE/tests/grade"
HAVE_VALGRIND=0
command -v valgrind >/dev/null 2>&1 && HAVE_VALGRIND=1
SHORT=${RAYO_VALGRIND:-0}

# grade NAME [OPTIONS...]: grades tests/grade/NAME as its exercise; the
# text report in $TMP/out, the exit status in $status, one word per
# criterion in $results.
grade() {
    name=$1
    shift
    case $name in ej2_*) exercise=ej2 ;; ej3_*) exercise=ej3 ;; *) exercise=ej1 ;; esac
    run_capture grade --exercise "$exercise" "$@" "$STUDENTS/$name"
    results=$(awk '$1 ~ /^(compile|functions|run|output|image|valgrind)$/ {
                       printf "%s%s=%s", sep, $1, $2; sep = " " }' "$TMP/out")
}

says() { # says PATTERN NAME
    found=0
    grep -Eq -- "$1" "$TMP/out" || found=1
    ok "$found" "$2"
    [ "$found" -eq 0 ] || sed 's/^/#   /' "$TMP/out"
}

# check NAME RESULTS PATTERN...: graded without valgrind, the criteria
# are RESULTS (valgrind=skipped added) and each PATTERN is in the report.
check() {
    name=$1 want=$2
    shift 2
    grade "$name" --no-valgrind
    is "$results" "$want valgrind=skipped" "$name: $want"
    for pattern in "$@"; do
        says "$pattern" "$name: says /$pattern/"
    done
}

OK4="compile=pass functions=pass run=pass output=pass"
BAD_FN="compile=pass functions=FAIL run=pass output=pass"

# --- the correct programs and the course's own reference -----------------
if [ "$HAVE_VALGRIND" = 1 ] && [ "$SHORT" = 0 ]; then
    grade ej2_correct
    is "$status/$results" "0/$OK4 image=pass valgrind=pass" "ej2_correct: every criterion passes"
    says '^PASS: 6 of 6 criteria passed$' "ej2_correct: summary"
    grade ej3_correct
    is "$status/$results" "0/$OK4 image=pass valgrind=pass" "ej3_correct: every criterion passes"
else
    check ej2_correct "$OK4 image=pass"
    check ej3_correct "$OK4 image=pass"
fi
says 'plain PPM \(P3\), 640x480, maxval 255' "ej3_correct: the output is named"
says 'the same as the reference to within 1 level' "ej3_correct: 1-level differences said as such"

grade ej2_correct --no-valgrind --reference course
is "$status/$results" "0/$OK4 image=pass valgrind=skipped" \
    "ej2_correct against the course's image (--reference course): passes"
says '^image +pass +consistent with the reference' "  consistent"
says 'z = 321\.5' "  the course's focal distance named as the reason"

grade ej3_correct --no-valgrind --reference course
is "$status/$results" "0/$OK4 image=pass valgrind=skipped" \
    "ej3_correct against the course's image: passes"

check ej2_pi_course "$OK4 image=pass" 'yours is about 321\.5'

grade literal_rows --no-valgrind
is "$status/$results" "0/compile=pass functions=pass run=pass output=pass image=pass valgrind=skipped" \
    "EJ1 rows read literally (y from 239 down to -240): passes"
says 'note: the rows run from y = 239 down to -240' "  which reading it follows is said"
mkdir "$TMP/two_rows"
sed 's|for (y = ALTO / 2 - 1; y >= -ALTO / 2; y--)|for (y = ALTO / 2 - 2; y >= -ALTO / 2 - 1; y--)|' \
    "$STUDENTS/literal_rows/main.c" >"$TMP/two_rows/main.c"
run_capture grade --no-valgrind "$TMP/two_rows/main.c"
is "$status" 1 "EJ1 rows from 238 down to -241: fails"
says 'the image is moved 2 rows up' "  the shift said in words: 2 rows up"

if [ "$SHORT" = 1 ]; then
    check ej2_no_shadows "$BAD_FN image=FAIL" 'there are no shadows'
    check ej3_channels_bgr "$BAD_FN image=FAIL" 'channels are in another order'
    done_testing
    exit $?
fi

# --- exercise 2 ---------------------------------------------------------
check ej2_no_shadows "$BAD_FN image=FAIL" \
    '^image +FAIL +inconsistent' 'there are no shadows'
check ej2_self_shadow "$BAD_FN image=FAIL" 'speckled with shadow'
check ej2_first_sphere "$BAD_FN image=pass" \
    '^functions +FAIL +computar_intensidad on 2 spheres, the far one first'
check ej2_last_sphere "$BAD_FN image=FAIL" '^functions +FAIL +computar_intensidad'
check ej2_no_ln_test "compile=pass functions=FAIL run=pass output=FAIL image=FAIL" \
    '40808 negative numbers' 'L\.N < 0'
check ej2_no_clamp "compile=pass functions=FAIL run=pass output=FAIL image=pass" \
    '13 numbers above 255' 'not clamped'
check ej2_wrapped "$BAD_FN image=FAIL" 'wrap around 256'
check ej2_no_ambient "$BAD_FN image=FAIL" 'ambient term is missing'
check ej2_unnormalised_normal "$BAD_FN image=FAIL" 'unit normal'
check ej2_light_reversed "$BAD_FN image=FAIL" 'wrong side'
check ej2_far_root "$BAD_FN image=FAIL" \
    '^functions +FAIL +distancia_esfera.*returned the far root' 'far side'
check ej2_p5_text "compile=pass functions=pass run=pass output=FAIL image=pass" \
    'header says P5 .* a text PGM is P2'
check ej2_wrong_signature "$BAD_FN image=pass" \
    "normal_esfera: the signature differs from the statement's"

# --- exercise 3 ---------------------------------------------------------
check ej3_channels_bgr "$BAD_FN image=FAIL" \
    "channels are in another order: the image's red, green and blue show the reference's blue, green and red"
check ej3_ambient_not_absorbed "$BAD_FN image=FAIL" 'ambient light is not tinted by the colour of the sphere'
check ej3_point_as_directional "$BAD_FN image=FAIL" 'point lights are used as directions'
check ej3_ka_kd_swapped "$BAD_FN image=FAIL" 'ka and kd are swapped'
check ej3_scale_256 "compile=pass functions=FAIL run=pass output=FAIL image=pass" \
    '9363 numbers are 256' 'scaled by 256 instead of 255'
check ej3_realloc_loses "$BAD_FN image=pass" \
    '^functions +FAIL +arreglo_agregar lost the array when realloc failed'
check ej3_no_typedef "$BAD_FN image=pass" "vector_t: not defined as the statement's type"
check ej3_no_shadows "$BAD_FN image=FAIL" 'no shadows'
check ej3_self_shadow "$BAD_FN image=FAIL" 'speckled with shadow'
check ej3_first_sphere "$BAD_FN image=FAIL" 'farther sphere covers a nearer one'
check ej3_no_ln_test "compile=pass functions=FAIL run=pass output=FAIL image=FAIL" \
    '103234 negative numbers'
check ej3_no_clamp "compile=pass functions=FAIL run=pass output=FAIL image=pass" \
    '8947 numbers above 255'
check ej3_wrapped "$BAD_FN image=FAIL" 'wrap around'
check ej3_no_ambient "$BAD_FN image=FAIL" 'ambient term is missing'
check ej3_light_reversed "$BAD_FN image=FAIL" 'wrong side'
check ej3_unnormalised_normal "$BAD_FN image=FAIL" 'unit normal'
check ej3_far_root "$BAD_FN image=FAIL" 'far side'

if [ "$HAVE_VALGRIND" = 1 ]; then
    grade ej3_leak
    is "$results" "$OK4 image=pass valgrind=FAIL" "ej3_leak: only valgrind fails"
    is "$(leaks_lost)" "940 27" "ej3_leak: 23 spheres and 4 lights lost"
    says 'esfera_destruir' "ej3_leak: named in the statement's terms"
    grade ej3_write_past_end
    is "$results" "compile=pass functions=FAIL run=FAIL output=skipped image=skipped valgrind=FAIL" \
        "ej3_write_past_end: functions, run and valgrind fail"
    says 'arreglo_agregar wrote past the end of a->v' "ej3_write_past_end: the harness names it"
    says 'Invalid write of size 8, at arreglo_agregar' "ej3_write_past_end: valgrind says where"
else
    diag "valgrind is not installed: its criterion is not tested"
fi

# --- issue 24: NaN, and the statements' two readings ----------------------
check ej2_nan_miss "$BAD_FN image=pass" \
    'distancia_esfera\(\(0, 0, 3\), 1, \(0, 0, 0\), \(1, 0, 0\)\) returned nan \(not a number\): likely the square root of a negative discriminant'
check ej3_shadow_beyond_light "$OK4 image=pass" \
    "computar_intensidad: a sphere beyond a point light casts a shadow: the statement's rule .* read to the letter, accepted"
check ej3_imprimir_rounds "$OK4 image=pass" \
    "color_imprimir: rounds 255 c to the nearest integer \(0\.999 prints 255\) instead of taking its integer part \(254\): a reading of the statement's 'scale 0\.\.1 to the integers 0\.\.255', accepted"

# --- a class, and JSON ----------------------------------------------------
mkdir "$TMP/class"
cp -r "$STUDENTS/ej3_correct" "$STUDENTS/ej3_channels_bgr" "$TMP/class/"
run_capture grade --exercise ej3 --no-valgrind --each "$TMP/class"
is "$status" 1 "--each over two ej3 submissions: exit 1"
says '^ej3_channels_bgr +pass +FAIL +pass +pass +FAIL +skipped +FAIL$' "  the table's row"
says '^1 of 2 submissions passed$' "  the tally"
run_capture grade --exercise ej3 --no-valgrind --json "$STUDENTS/ej3_channels_bgr"
is "$(jq -r '.exercise + "/" + .verdict + "/" + .result' "$TMP/out")" "ej3/inconsistent/fail" \
    "--json: exercise, verdict, result"
run_capture grade --exercise ej3 --no-valgrind --diff "$TMP/diff.png" "$STUDENTS/ej3_channels_bgr"
is "$(pngtopam "$TMP/diff.png" | pamfile | sed 's/.*: *//; s/^[[:space:]]*//')" \
    "PPM raw, 640 by 480  maxval 255" "--diff: the tone difference picture, 640x480 RGB"
says 'difference picture: .*amber where it explains them' "  and the report says how to read it"

done_testing
