#!/bin/sh
# contrib.t - what contrib/ gives a teacher works as documented
# (docs/grading.md, "Gradescope and GitHub Classroom"): Gradescope's
# run_autograder, run against a fake /autograder tree, leaves a
# results.json (parsed by jq) for a right, a wrong and an empty
# submission; make-zip.sh builds a zip with setup.sh and run_autograder
# at its root and rayo's sources under rayo/ (read by python3's zipfile);
# the GitHub Classroom step grades a folder, exits as rayo grade does and
# writes the report into the job's summary.  setup.sh and the workflow
# install packages, so here they are only checked for syntax and for
# naming the scripts they run.
. "$(dirname "$0")/lib.sh"

CONTRIB="$RAYO_SOURCE/contrib"
STUDENTS="$RAYO_SOURCE/tests/grade"
# The scripts call `rayo` from the PATH, as on a machine where it is
# installed.
mkdir "$TMP/bin"
ln -s "$RAYO" "$TMP/bin/rayo"
PATH="$TMP/bin:$PATH"
export PATH

# ---- Gradescope ----
autograder() { # autograder SUBMISSION-FOLDER: a fresh tree, graded
    rm -rf "$TMP/ag"
    mkdir -p "$TMP/ag/source" "$TMP/ag/submission"
    [ -n "$1" ] && cp "$1"/*.c "$TMP/ag/submission/"
    AUTOGRADER_ROOT="$TMP/ag" RAYO_OPTIONS=--no-valgrind RAYO_POINTS=valgrind=0 \
        bash "$CONTRIB/gradescope/run_autograder" >"$TMP/out" 2>"$TMP/err"
    status=$?
    results="$TMP/ag/results/results.json"
}
autograder "$STUDENTS/correct"
is "$status" 0 "run_autograder, a right submission: exit 0 (Gradescope reads the results)"
is "$(jq -r '.score, (.tests | length)' "$results" | tr '\n' ' ')" "90 5 " \
    "run_autograder, a right submission: 90 points (no valgrind here), 5 tests"
autograder "$STUDENTS/degrees"
is "$status" 0 "run_autograder, a wrong submission: exit 0 all the same"
is "$(jq -r '[.tests[] | select(.status == "failed") | .name] | join(" ")' "$results")" \
    "image" "run_autograder, a wrong submission: the image test failed"
autograder ""
is "$(jq -r '.score' "$results")" 0 "run_autograder, no C file: score 0"
jq -r '.output' "$results" | grep -q 'no \.c file'
ok $? "run_autograder, no C file: the student is told why"
# rayo itself missing: the student still gets results saying so.
rm -rf "$TMP/ag" && mkdir -p "$TMP/ag/submission"
cp "$STUDENTS/correct/main.c" "$TMP/ag/submission/"
PATH="/usr/bin:/bin" AUTOGRADER_ROOT="$TMP/ag" \
    bash "$CONTRIB/gradescope/run_autograder" >/dev/null 2>&1
jq -r '.output' "$TMP/ag/results/results.json" | grep -q 'autograder failed'
ok $? "run_autograder without rayo: a results.json that says the autograder failed"

bash -n "$CONTRIB/gradescope/setup.sh"
ok $? "setup.sh: valid bash"
grep -q 'make -C "$source_dir/rayo" install' "$CONTRIB/gradescope/setup.sh"
ok $? "setup.sh: installs rayo from the zip's copy"

if git -C "$RAYO_SOURCE" rev-parse HEAD >/dev/null 2>&1; then
    bash "$CONTRIB/gradescope/make-zip.sh" "$TMP/ag.zip" >/dev/null 2>"$TMP/err"
    ok $? "make-zip.sh: builds the zip"
    python3 - "$TMP/ag.zip" >"$TMP/zip.txt" <<'PY'
import sys, zipfile
z = zipfile.ZipFile(sys.argv[1])
names = z.namelist()
for n in ('setup.sh', 'run_autograder', 'rayo/Makefile', 'rayo/src/seed/ejercicio1.c'):
    print(n, n in names)
print('run_autograder executable', (z.getinfo('run_autograder').external_attr >> 16) & 0o111 != 0)
PY
    is "$(tr '\n' ' ' <"$TMP/zip.txt")" \
        "setup.sh True run_autograder True rayo/Makefile True rayo/src/seed/ejercicio1.c True run_autograder executable True " \
        "make-zip.sh: the scripts at the root, rayo's sources under rayo/"
else
    ok 0 "# SKIP not a git checkout: make-zip.sh needs git archive"
    ok 0 "# SKIP not a git checkout"
fi

# ---- GitHub Classroom ----
mkdir "$TMP/repo" "$TMP/wrong"
cp "$STUDENTS/correct/main.c" "$TMP/repo/"
cp "$STUDENTS/degrees/main.c" "$TMP/wrong/"
: >"$TMP/summary"
GITHUB_STEP_SUMMARY="$TMP/summary" RAYO_OPTIONS=--no-valgrind \
    bash "$CONTRIB/github-classroom/grade.sh" "$TMP/repo" >"$TMP/out" 2>&1
is "$?" 0 "grade.sh, a right submission: exit 0"
grep -q '^PASS' "$TMP/out"
ok $? "grade.sh: the report on stdout"
is "$(sed -n '1p;3p' "$TMP/summary" | tr '\n' ' ')" '## rayo grade (ej1) ``` ' \
    "grade.sh: the summary has a heading and the report in a code block"
grep -q '^PASS' "$TMP/summary"
ok $? "grade.sh: the summary has the verdict"
GITHUB_STEP_SUMMARY= RAYO_OPTIONS=--no-valgrind \
    bash "$CONTRIB/github-classroom/grade.sh" "$TMP/wrong" >"$TMP/out" 2>&1
is "$?" 1 "grade.sh, a wrong submission: exit 1 (the check fails)"
grep -q 'contrib/github-classroom/grade.sh' "$CONTRIB/github-classroom/rayo-grade.yml"
ok $? "rayo-grade.yml runs grade.sh"

done_testing
