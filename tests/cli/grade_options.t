#!/bin/sh
# grade_options.t - `rayo grade` beyond the typical mistakes: usage
# errors, the limits (output size, CPU, wall clock and the process
# group), submissions of several files or a folder, a class graded with
# --each, --json, --diff and --reference, and what happens to the
# temporary directory.
. "$(dirname "$0")/lib.sh"

STUDENTS="$RAYO_SOURCE/tests/grade"
NV=--no-valgrind

# results: one word per criterion of the text report in $TMP/out.
results() {
    awk '$1 ~ /^(compile|functions|run|output|image|valgrind)$/ {
             printf "%s%s=%s", sep, $1, $2; sep = " " }' "$TMP/out"
}
says() {
    found=0
    grep -Eq -- "$1" "$TMP/out" || found=1
    ok "$found" "$2"
    [ "$found" -eq 0 ] || sed 's/^/#   /' "$TMP/out"
}
json_valid() { # json_valid FILE: 0 when FILE is one JSON value
    if command -v python3 >/dev/null 2>&1; then
        python3 -c 'import json, sys; json.load(open(sys.argv[1]))' "$1"
    elif command -v jq >/dev/null 2>&1; then
        jq . "$1" >/dev/null
    else
        return 0
    fi
}

# ---- usage errors: exit 2, one line, nothing on stdout ----
expect_usage_error "no submission" 'no submission given' grade
expect_usage_error "unknown exercise" "--exercise: unknown exercise 'ej9'" \
    grade --exercise ej9 "$STUDENTS/correct/main.c"
expect_usage_error "zero timeout" "--timeout: '0' is out of range" \
    grade --timeout 0 "$STUDENTS/correct/main.c"
expect_usage_error "timeout not a number" "--timeout: 'diez' is not a finite number" \
    grade --timeout diez "$STUDENTS/correct/main.c"
expect_usage_error "memory out of range" "--memory: '0' is out of range" \
    grade --memory 0 "$STUDENTS/correct/main.c"
expect_usage_error "--each with two folders" '--each takes one DIRECTORY, not 2' \
    grade --each "$STUDENTS" "$STUDENTS"
expect_usage_error "--diff with --each" '--diff: applies to one submission' \
    grade --each --diff "$TMP/d.png" "$STUDENTS"
expect_usage_error "unknown option" "unknown option '--fast'" \
    grade --fast "$STUDENTS/correct/main.c"
mkdir "$TMP/empty"
expect_usage_error "folder without sources" 'no \.c file in this folder' \
    grade "$TMP/empty"

run_capture grade "$TMP/nothing-here.c"
is "$status" 2 "missing source: exit 2 (an input that cannot be read)"
grep -q "nothing-here.c: No such file or directory" "$TMP/err"
ok $? "missing source: the file and the system's reason"

run_capture grade --help
is "$status" 0 "--help: exit 0"
says '^  ej1 ' "--help lists the exercises"
says '^      --sandbox MODE +auto' "--help names the sandbox's modes"

# ---- submissions of several files, or a folder ----
mkdir "$TMP/multi"
cat >"$TMP/multi/vector.h" <<'C'
#ifndef VECTOR_H
#define VECTOR_H
float producto_interno(float x1, float y1, float z1, float x2, float y2,
                       float z2);
float norma(float x, float y, float z);
#endif
C
cat >"$TMP/multi/vector.c" <<'C'
#include <math.h>
#include "vector.h"
float producto_interno(float x1, float y1, float z1, float x2, float y2,
                       float z2)
{
    return x1 * x2 + y1 * y2 + z1 * z2;
}
float norma(float x, float y, float z)
{
    return sqrtf(producto_interno(x, y, z, x, y, z));
}
C
sed -n '/^int intersecta_esfera/,$p' "$STUDENTS/correct/main.c" >"$TMP/body"
{
    printf '#include <math.h>\n#include <stdio.h>\n#include "vector.h"\n'
    printf '#define CX 0.5\n#define CY 0.75\n#define CZ 1.9\n#define R 0.8\n'
    printf '#define ANCHO 640\n#define ALTO 480\n#define FOV 90\n'
    printf '#define PI 3.14159265358979323846\n'
    cat "$TMP/body"
} >"$TMP/multi/main.c"
run_capture grade $NV "$TMP/multi/main.c" "$TMP/multi/vector.c"
is "$status" 0 "two files: exit 0"
is "$(results)" "compile=pass functions=pass run=pass output=pass image=pass valgrind=skipped" \
    "two files: the functions are found in either"
run_capture grade $NV "$TMP/multi"
is "$(results)" "compile=pass functions=pass run=pass output=pass image=pass valgrind=skipped" \
    "a folder: its .c files are the submission"

# ---- the limits ----
cat >"$TMP/forever.c" <<'C'
#include <stdio.h>
int main(void)
{
    for (;;)
        putchar('1');
}
C
run_capture grade $NV --output-limit 1 "$TMP/forever.c"
says '^run +FAIL +wrote more than 1048576 bytes \(the output limit\)' \
    "endless output: stopped at the output limit"
says "producto_interno: not defined; the assignment asks for float producto_interno" \
    "missing functions are reported, not fatal"

cat >"$TMP/spin.c" <<'C'
int main(void)
{
    for (;;)
        ;
}
C
run_capture grade --cpu 1 --timeout 30 "$TMP/spin.c"
says '^run +FAIL +used more than 1 s of CPU time' "spinning: stopped by the CPU limit"
says '^valgrind +skipped +not run: the program was stopped by a limit' \
    "spinning: not run again under valgrind"

# A program whose child outlives it: the whole process group is killed,
# and nothing is left in the temporary directory.
cat >"$TMP/orphan.c" <<'C'
#define _POSIX_C_SOURCE 200809L
#include <unistd.h>
int main(void)
{
    if (fork() == 0)
        for (;;)
            pause();
    for (;;)
        pause();
}
C
mkdir "$TMP/scratch"
TMPDIR="$TMP/scratch" run_capture grade $NV --timeout 1 "$TMP/orphan.c"
says '^run +FAIL +did not finish within 1 s' "orphan: timed out"
pgrep -f "$TMP/scratch" >/dev/null 2>&1
is "$?" 1 "orphan: no process of the submission is left"
is "$(ls -A "$TMP/scratch")" "" "orphan: the temporary directory is removed"

# SIGTERM while the program runs: rayo kills it, removes its temporary
# directory and dies of the signal.
mkdir "$TMP/scratch2"
TMPDIR="$TMP/scratch2" "$RAYO" grade $NV --timeout 60 "$TMP/orphan.c" \
    >"$TMP/out" 2>"$TMP/err" &
pid=$!
sleep 1
kill -TERM "$pid"
status=0
wait "$pid" 2>/dev/null || status=$? # (no "Terminated" from sh)
is "$status" 143 "SIGTERM: rayo dies of the signal"
pgrep -f "$TMP/scratch2" >/dev/null 2>&1
is "$?" 1 "SIGTERM: no process of the submission is left"
is "$(ls -A "$TMP/scratch2")" "" "SIGTERM: the temporary directory is removed"

cat >"$TMP/three.c" <<'C'
int main(void)
{
    return 3;
}
C
run_capture grade $NV "$TMP/three.c"
says '^run +FAIL +exited with status 3; main must return 0' "exit status 3: reported"

cat >"$TMP/tofile.c" <<'C'
#include <stdio.h>
int main(void)
{
    FILE *f = fopen("imagen.pbm", "w");
    int i;
    if (f == NULL)
        return 1;
    fprintf(f, "P1\n640 480\n");
    for (i = 0; i < 640 * 480; i++)
        fputs("0\n", f);
    return fclose(f) != 0;
}
C
run_capture grade $NV "$TMP/tofile.c"
says "warning: wrote nothing on standard output but wrote the file 'imagen.pbm'" \
    "image written to a file: noticed"
says '^output +pass' "image written to a file: the file is checked"
says '^image +FAIL .*' "image written to a file: an all-white image is wrong"
says 'all white' "all white: diagnosed"

run_capture grade $NV --cc /nonexistent/cc "$STUDENTS/correct/main.c"
says "could not run the compiler '/nonexistent/cc'" "a missing compiler is named"

# ---- --json ----
run_capture grade $NV --json "$STUDENTS/lowercase_magic/main.c"
is "$status" 1 "--json: exit status still 1 on failure"
json_valid "$TMP/out"
ok $? "--json: valid JSON"
says '"result": "fail", "verdict": "identical"' "--json: result and verdict"
says '"name": "output", "result": "fail", "reasons": \["the magic number is .p1. in lowercase' \
    "--json: criteria with their reasons"

# ---- --diff and --reference ----
run_capture grade $NV --diff "$TMP/diff.png" "$STUDENTS/rows_flipped/main.c"
says "difference picture: $TMP/diff.png" "--diff: announced"
is "$(pngtopnm "$TMP/diff.png" 2>/dev/null | pamfile 2>/dev/null | sed 's/.*, //')" \
    "640 by 480  maxval 255" "--diff: a 640x480 colour PNG"

run_capture grade $NV --reference "$SEED/referencia-catedra.png" \
    "$STUDENTS/correct/main.c"
is "$status" 0 "--reference the course's PNG: passes"
says '^image +pass +(identical|consistent)' "--reference: compared with the course's image"

run_capture grade $NV --reference "$TMP/no-such.png" "$STUDENTS/correct/main.c"
is "$status" 2 "a missing reference: exit 2"
is "$(wc -c <"$TMP/out" | tr -d ' ')" 0 "a missing reference: nothing graded"

# ---- a class ----
mkdir "$TMP/class" "$TMP/class/ana" "$TMP/class/beto" "$TMP/class/carla"
cp "$STUDENTS/correct/main.c" "$TMP/class/ana/"
cp "$STUDENTS/lowercase_magic/main.c" "$TMP/class/beto/"
cp "$STUDENTS/werror/main.c" "$TMP/class/carla/"
run_capture grade $NV --each "$TMP/class"
is "$status" 1 "--each: exit 1 when one fails"
is "$(awk '$1 == "ana" || $1 == "beto" || $1 == "carla"' "$TMP/out" | tr -s ' ')" \
"ana pass pass pass pass pass skipped PASS
beto pass pass pass FAIL pass skipped FAIL
carla FAIL skipped skipped skipped skipped skipped FAIL" "--each: one row per student"
says '^1 of 3 submissions passed$' "--each: the tally"

run_capture grade $NV --each --json "$TMP/class"
json_valid "$TMP/out"
ok $? "--each --json: valid JSON"
is "$(grep -o '"student": "[a-z]*"' "$TMP/out" | tr '\n' ' ')" \
    '"student": "ana" "student": "beto" "student": "carla" ' \
    "--each --json: every student, in order"

done_testing
