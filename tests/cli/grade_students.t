#!/bin/sh
# grade_students.t - `rayo grade` on the student-style programs of
# tests/grade/, one typical mistake each: every program gets exactly the
# findings it deserves (which criteria pass, fail or are skipped) and the
# reasons name the mistake in the student's terms.
. "$(dirname "$0")/lib.sh"

STUDENTS="$RAYO_SOURCE/tests/grade"
HAVE_VALGRIND=0
command -v valgrind >/dev/null 2>&1 && HAVE_VALGRIND=1

# grade NAME [OPTIONS...]: grades tests/grade/NAME/main.c; the text
# report in $TMP/out, the exit status in $status, and one word per
# criterion in $results ("compile=pass functions=FAIL ...").
grade() {
    name=$1
    shift
    run_capture grade "$@" "$STUDENTS/$name/main.c"
    results=$(awk '$1 ~ /^(compile|functions|run|output|image|valgrind)$/ {
                       printf "%s%s=%s", sep, $1, $2; sep = " " }' "$TMP/out")
}

# says PATTERN NAME: the report has a line matching PATTERN (grep -E).
says() {
    found=0
    grep -Eq -- "$1" "$TMP/out" || found=1
    ok "$found" "$2"
    [ "$found" -eq 0 ] || sed 's/^/#   /' "$TMP/out"
}

ALL_PASS="compile=pass functions=pass run=pass output=pass image=pass"

grade correct --no-valgrind
is "$status" 0 "correct: exit status 0"
is "$results" "$ALL_PASS valgrind=skipped" "correct: every criterion passes"
says '^image +pass +(identical|consistent)' "correct: the image matches"
says '^PASS: 5 of 6 criteria passed, 1 skipped$' "correct: summary line"
is "$(wc -c <"$TMP/err" | tr -d ' ')" 0 "correct: nothing on stderr"

grade lowercase_magic --no-valgrind
is "$status" 1 "lowercase magic: exit status 1"
is "$results" "compile=pass functions=pass run=pass output=FAIL image=pass valgrind=skipped" \
    "lowercase magic: only the output fails"
says "'p1' in lowercase; Netpbm needs a capital 'P1'" "lowercase magic: named"
says 'pixels were read as if' "lowercase magic: the pixels are still compared"

grade dimensions_x --no-valgrind
is "$results" "compile=pass functions=pass run=pass output=FAIL image=pass valgrind=skipped" \
    "640x480 header: only the output fails"
says "written '640x480'; Netpbm needs two numbers separated by whitespace: '640 480'" \
    "640x480 header: named"

grade extra_row --no-valgrind
is "$results" "compile=pass functions=pass run=pass output=FAIL image=pass valgrind=skipped" \
    "one row too many: only the output fails"
says 'promises 640x480 = 307200 pixels but the output has 307840: 640 more, exactly 1 row too many' \
    "one row too many: counted in rows"

grade rows_flipped --no-valgrind
is "$results" "compile=pass functions=pass run=pass output=pass image=FAIL valgrind=skipped" \
    "rows flipped: only the image fails"
says 'upside down' "rows flipped: diagnosed"

grade degrees --no-valgrind
is "$results" "compile=pass functions=pass run=pass output=pass image=FAIL valgrind=skipped" \
    "degrees: only the image fails"
says 'the sphere is 0\.62 times the size' "degrees: the scale is measured"
says 'tan\(\) of FOV in degrees' "degrees: the cause is named"

grade no_normalise --no-valgrind
is "$results" "compile=pass functions=pass run=pass output=pass image=FAIL valgrind=skipped" \
    "no normalisation: only the image fails"
says 'is the direction normalised' "no normalisation: the likely cause is named"

grade norma_int --no-valgrind
is "$results" "compile=pass functions=FAIL run=pass output=pass image=pass valgrind=skipped" \
    "integer norma: only the functions fail"
says 'norma\(0\.5, 0\.5, 0\.5\) returned 0; expected 0\.8660254' \
    "integer norma: input, result and expected value"
says 'is an int used inside the function' "integer norma: truncation named"
says '^ +right on all their known inputs: producto_interno \(3\)' "integer norma: the others are right"

grade wrong_signature --no-valgrind
is "$results" "compile=pass functions=FAIL run=pass output=pass image=pass valgrind=skipped" \
    "wrong signature: only the functions fail"
says "norma: the signature differs from the assignment's float norma\(float x, float y, float z\)" \
    "wrong signature: reported, not fatal"
says 'double' "wrong signature: the student's types are quoted"
says '^ +right on all their known inputs: .*intersecta_esfera \(5\)$' "wrong signature: the others are still called"

grade werror --no-valgrind
is "$status" 1 "-Werror: exit status 1"
is "$results" "compile=FAIL functions=skipped run=skipped output=skipped image=skipped valgrind=skipped" \
    "-Werror: compile fails, the rest is skipped"
says 'unused variable' "-Werror: the compiler's first error is quoted"
says 'that -Werror turns into an error' "-Werror: explained"

grade macro_parameter --no-valgrind
is "$results" "compile=FAIL functions=skipped run=skipped output=skipped image=skipped valgrind=skipped" \
    "a parameter named as a macro: compile fails"
says "the first real error is at [^ ]*/macro_parameter/main\.c:23:30, where the name CX is one of the file's macros \(#define CX\): the preprocessor puts the macro's value in its place, so a parameter or a variable cannot have that name; rename it" \
    "a parameter named as a macro: the hint points at the parameter"

mkdir "$TMP/scratch"
TMPDIR="$TMP/scratch" grade infinite_loop --no-valgrind --timeout 1
is "$results" "compile=pass functions=pass run=FAIL output=skipped image=skipped valgrind=skipped" \
    "infinite loop: the run fails, output and image are skipped"
says 'did not finish within 1 s ' "infinite loop: the timeout is reported"
is "$(ls -A "$TMP/scratch")" "" "infinite loop: the temporary directory is removed"

if [ "$HAVE_VALGRIND" = 1 ]; then
    grade segfault
    is "$results" "compile=pass functions=pass run=FAIL output=skipped image=skipped valgrind=FAIL" \
        "segfault: run and valgrind fail"
    says 'crashed: segmentation fault \(SIGSEGV\)' "segfault: the signal is named"
    says 'Invalid write of size 4, at main \(main\.c:[0-9]+\)' \
        "segfault: valgrind says where"

    grade leak
    is "$results" "$ALL_PASS valgrind=FAIL" "leak: only valgrind fails"
    is "$(leaks_lost)" "1228800 480" "leak: 480 rows of 640 ints lost"
    says 'leak: [0-9]+ bytes in [0-9]+ blocks definitely lost' \
        "leak: definitely lost named"
    says 'allocated in main \(main\.c:[0-9]+\)' "leak: the allocation is located"

    grade interior_pointer
    is "$results" "$ALL_PASS valgrind=FAIL" "interior pointer: only valgrind fails"
    says '^valgrind +FAIL +leak: 2560 bytes in 1 blocks possibly lost' \
        "interior pointer: one row of 640 ints, possibly lost"
    says '^ +possibly lost: at exit valgrind saw only a pointer into the middle of the memory, not to its start; a leak all the same$' \
        "interior pointer: what possibly lost means, said"

    grade correct
    is "$results" "$ALL_PASS valgrind=pass" "correct under valgrind: all pass"
    says '^PASS: 6 of 6 criteria passed$' "correct under valgrind: summary"
else
    diag "valgrind is not installed: its criteria are not tested"
fi

done_testing
