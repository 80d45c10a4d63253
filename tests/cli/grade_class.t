#!/bin/sh
# grade_class.t - a class at once: `rayo grade --each DIR -j N` prints the
# same table and JSON as -j 1, in the same order; --csv writes one row per
# submission that a CSV parser (python3's csv) reads back to the table's
# results, with names that hold quotes, commas, newlines or a formula kept
# as text; --gradescope writes Gradescope's results.json (parsed by jq):
# a score that is the sum of the tests', a test per criterion with points
# (--points), and a result that says why when the submission cannot be
# graded.  Options that cannot go together are refused (exit 2).
. "$(dirname "$0")/lib.sh"

STUDENTS="$RAYO_SOURCE/tests/grade"
NV=--no-valgrind

# A class of eight: one right, five with a different mistake, one right
# in a folder whose name a spreadsheet would run as a formula, and two
# with no C file, one with a comma and a newline in its name, one with a
# quote.
mkdir "$TMP/class"
for s in correct degrees dimensions_x lowercase_magic norma_int; do
    cp -r "$STUDENTS/$s" "$TMP/class/$s"
done
formula='=SUM(A1)'
odd=$(printf 'odd, na\nme')
mkdir "$TMP/class/$formula" "$TMP/class/$odd" "$TMP/class/zz_\"empty"
cp "$STUDENTS/correct/main.c" "$TMP/class/$formula/"

# ---- -j gives the same table ----
run_capture grade $NV -j 1 --each "$TMP/class"
is "$status" 1 "-j 1: exit 1 (some failed)"
cp "$TMP/out" "$TMP/table1"
run_capture grade $NV -j 3 --each "$TMP/class"
is "$status" 1 "-j 3: exit 1"
cmp -s "$TMP/table1" "$TMP/out"
ok $? "-j 3: the same table as -j 1, byte for byte"
run_capture grade $NV --jobs 2 --each "$TMP/class"
cmp -s "$TMP/table1" "$TMP/out"
ok $? "--jobs 2: the same table as -j 1"
is "$(sed '/submissions passed$/q' "$TMP/table1" | grep -c '')" 12 \
    "the table: how it was isolated, a header, 8 rows, a blank line, the tally"
head -n 1 "$TMP/table1" | grep -Eq '^(sandbox: bubblewrap|warning: not isolated)'
ok $? "the table's first line: the sandbox, or a warning that there is none"
is "$(sed -n 12p "$TMP/table1")" "2 of 8 submissions passed" "the tally"

# The JSON, but for the run's time (which differs from run to run).
untimed() { sed 's/ran to the end in [0-9.]* s/ran to the end in T s/g' "$1"; }
run_capture grade $NV -j 1 --json --each "$TMP/class"
untimed "$TMP/out" >"$TMP/json1"
run_capture grade $NV -j 4 --json --each "$TMP/class"
untimed "$TMP/out" >"$TMP/json4"
cmp -s "$TMP/json1" "$TMP/json4"
ok $? "-j 4 --json: the same JSON as -j 1"
is "$(jq -r 'map(.result) | join(" ")' "$TMP/out")" \
    "pass pass fail fail fail fail error error" "--json: results in folder order"

# ---- the summary of the class ----
# Computed here from the JSON's results and reasons: how many passed,
# failed or could not be graded; per criterion how many failed it, and
# its kinds of mistake (the first reason line, warnings and quotes passed
# over, up to its first ':', ';', ' (' or ', at '), most frequent first.
cat >"$TMP/summary.py" <<'PY'
import json, sys
reports = json.load(open(sys.argv[1]))
count = lambda r: sum(1 for x in reports if x['result'] == r)
print('summary: %d passed, %d failed, %d could not be graded'
      % (count('pass'), count('fail'), count('error')))
print('%-10s %6s  %s' % ('criterion', 'failed',
                         'mistakes, as the report names them (students)'))
names = ['compile', 'functions', 'run', 'output', 'image', 'valgrind']
for c, name in enumerate(names):
    kinds = {}
    failed = [x for x in reports if x['result'] == 'fail'
              and x['criteria'][c]['result'] == 'fail']
    for x in failed:
        lines = [l for l in x['criteria'][c]['reasons']
                 if not l.startswith(' ') and not l.startswith('warning: ')]
        kind = lines[0] if lines else ''
        for cut in (':', ';', ' (', ', at '):
            kind = kind.split(cut)[0]
        kinds[kind] = kinds.get(kind, 0) + 1
    order = sorted(kinds.items(), key=lambda k: (-k[1], k[0]))
    row = '%-10s %6d' % (name, len(failed))
    for i, (kind, n) in enumerate(order):
        row += ('  ' if i == 0 else '\n' + ' ' * 19) + '%s (%d)' % (kind, n)
    print(row)
PY
python3 "$TMP/summary.py" "$TMP/out" >"$TMP/summary.want"
sed '1,/submissions passed$/d' "$TMP/table1" | sed 1d >"$TMP/summary.got"
cmp -s "$TMP/summary.want" "$TMP/summary.got"
ok $? "the table ends with the class's summary, its counts as the JSON's"
[ "$tap_failed" -eq 0 ] || diff "$TMP/summary.want" "$TMP/summary.got" | sed 's/^/# /'
is "$(grep -c '^output          2  ' "$TMP/summary.got"):$(grep -c '^summary: 2 passed, 4 failed, 2 could not be graded$' "$TMP/summary.got")" \
    "1:1" "the summary: two failed the output, 2 passed, 4 failed, 2 could not be graded"

# ---- --points: a score column ----
run_capture grade $NV -j 2 --points image=50 --each "$TMP/class"
is "$(sed -n 2p "$TMP/out" | awk '{ print $(NF - 1) }')" score "--points: the table has a score column"
is "$(awk '$1 == "correct" || $1 == "degrees" || $1 == "norma_int" { print $1, $(NF - 1) }' "$TMP/out" | tr '\n' ' ')" \
    "correct 100/100 degrees 50/100 norma_int 80/100 " \
    "--points image=50 with --no-valgrind: 10+20+10+10+50 (valgrind 0); degrees loses the image's 50, norma_int the functions' 20"
is "$(sed -n 2p "$TMP/table1" | awk '{ print $(NF - 1) }')" valgrind "without --points: no score column"

# ---- --csv ----
run_capture grade $NV -j 2 --each "$TMP/class" --csv "$TMP/class.csv"
cmp -s "$TMP/table1" "$TMP/out"
ok $? "--csv FILE: the table still on stdout"
cat >"$TMP/read_csv.py" <<'PY'
import csv, sys
rows = list(csv.reader(open(sys.argv[1], newline='')))
header = rows[0]
print(len(rows) - 1)
print(','.join(header[:6]))
for r in rows[1:]:
    d = dict(zip(header, r))
    print('%s|%s|%s/%s|%s|%s|%s' % (d['student'], d['result'], d['score'],
          d['max_score'], d['compile'], d['image'], d['error']))
PY
python3 "$TMP/read_csv.py" "$TMP/class.csv" >"$TMP/csv.txt" 2>&1
ok $? "--csv: python3's csv module reads the file"
is "$(sed -n 1p "$TMP/csv.txt")" 8 "--csv: one row per submission"
is "$(sed -n 2p "$TMP/csv.txt")" "student,result,score,max_score,compile,compile_reason" \
    "--csv: the header"
is "$(sed -n '3,$p' "$TMP/csv.txt" | cut -d '|' -f 2 | tr '\n' ' ')" \
    "pass pass fail fail fail fail error error " "--csv: each row's result, in folder order"
line_of() { grep -F -- "$1" "$TMP/csv.txt" | head -n 1; }
is "$(line_of 'correct|')" "correct|pass|90/90|pass|pass|" \
    "--csv: a pass earns every point (with --no-valgrind, valgrind's are not counted)"
is "$(line_of 'degrees|')" "degrees|fail|50/90|pass|fail|" \
    "--csv: a wrong image loses the image's 40 points"
is "$(line_of 'SUM')" "'=SUM(A1)|pass|90/90|pass|pass|" \
    "--csv: a name that is a formula begins with an apostrophe"
is "$(line_of 'odd, na')" "odd, na\\nme|error|0/90|||$TMP/class/odd, na\\nme: no .c file in this folder; expected the submission's C sources" \
    "--csv: a comma and a newline in a name: one cell, the newline escaped"
is "$(line_of 'zz_')" "zz_\"empty|error|0/90|||$TMP/class/zz_\"empty: no .c file in this folder; expected the submission's C sources" \
    "--csv: a quote in a name; a folder that cannot be graded: error, and why"
is "$(grep -c "$(printf '\r')\$" "$TMP/class.csv")" 9 "--csv: CRLF line ends (RFC 4180), one per row"

run_capture grade $NV --each "$TMP/class" --csv -
is "$(head -n 1 "$TMP/out" | cut -c 1-30)" "student,result,score,max_score" \
    "--csv -: the CSV on stdout, instead of the table"
is "$(grep -c 'submissions passed' "$TMP/out")" 0 "--csv -: no table"

run_capture grade $NV --points image=50,valgrind=0 --csv - "$STUDENTS/degrees"
is "$(python3 -c 'import csv,sys; r=list(csv.DictReader(sys.stdin)); print(r[0]["score"], r[0]["max_score"])' <"$TMP/out")" \
    "50 100" "--csv with --points: the score out of the new total"

# ---- --gradescope ----
run_capture grade "$STUDENTS/degrees" --gradescope "$TMP/results.json"
is "$status" 1 "--gradescope: the exit status is the grading's"
is "$(jq -r '.score' "$TMP/results.json")" 60 "--gradescope: the score"
is "$(jq -r '[.tests[].score] | add' "$TMP/results.json")" 60 \
    "--gradescope: the score is the sum of the tests'"
is "$(jq -r '[.tests[] | .name + "=" + (.max_score|tostring) + ":" + .status] | join(" ")' "$TMP/results.json")" \
    "compile=10:passed functions=20:passed run=10:passed output=10:passed image=40:failed valgrind=10:passed" \
    "--gradescope: a test per criterion, its points and status"
jq -r '.output | split("\n")[1]' "$TMP/results.json" | grep -Eq '^(sandbox: bubblewrap|warning: not isolated)'
ok $? "--gradescope: the output's second line says how the submission was isolated"
jq -r '.tests[] | select(.name == "image") | .output' "$TMP/results.json" >"$TMP/image.txt"
grep -q 'tan() takes radians' "$TMP/image.txt"
ok $? "--gradescope: the image test's output explains the mistake"
is "$(jq -r '.output | split("\n")[0]' "$TMP/results.json")" "FAIL: 60 of 100 points" \
    "--gradescope: the summary"
run_capture grade $NV "$STUDENTS/correct" --gradescope -
is "$(jq -r '.score, (.tests | length), (.output | split("\n")[0])' "$TMP/out" | tr '\n' ' ')" "90 5 PASS: 90 of 90 points " \
    "--gradescope - with --no-valgrind: valgrind left out, 90 of 90 points"
run_capture grade $NV "$STUDENTS/correct" --gradescope - --points valgrind=10
is "$(jq -r '.score, (.output | split("\n")[0])' "$TMP/out" | tr '\n' ' ')" "90 PASS: 90 of 100 points " \
    "--gradescope - with --no-valgrind and --points valgrind=10: the points are lost"
run_capture grade $NV "$TMP/class/zz_\"empty" --gradescope "$TMP/empty.json"
is "$status" 2 "--gradescope, a folder with no C file: exit 2"
is "$(jq -r '.score, (.tests | length)' "$TMP/empty.json" | tr '\n' ' ')" "0 0 " \
    "--gradescope, no C file: score 0, no tests"
jq -r '.output' "$TMP/empty.json" | grep -q 'no \.c file in this folder'
ok $? "--gradescope, no C file: the output says why"

# The output is text from a submission: control bytes arrive escaped.
mkdir "$TMP/forge"
printf '#include <stdio.h>\nint main(void) { printf("P1\\n1 1\\n1\\n"); return 0; }\n#error "\033[2J\rPASS: 6 of 6"\n' \
    >"$TMP/forge/main.c"
run_capture grade $NV "$TMP/forge" --gradescope "$TMP/forge.json"
is "$(jq -r '.tests[0].output' "$TMP/forge.json" | tr -d -c '\033\r' | wc -c | tr -d ' ')" 0 \
    "--gradescope: no raw escape or carriage return from a submission"

# ---- what cannot go together ----
expect_usage_error "--gradescope with --each" "Gradescope grades one submission" \
    grade --each "$TMP/class" --gradescope "$TMP/x.json"
expect_usage_error "-j 0" "--jobs: '0'" grade -j 0 --each "$TMP/class"
expect_usage_error "--points with an unknown criterion" "'speed' is not a criterion" \
    grade --points speed=3 "$STUDENTS/correct"
expect_usage_error "--points out of range" "out of range" \
    grade --points image=5000 "$STUDENTS/correct"
expect_usage_error "--csv - with --json" "give --csv a FILE" \
    grade --json --csv - "$STUDENTS/correct"

# ---- the file appears whole or not at all ----
run_capture grade $NV "$STUDENTS/correct" --csv "$TMP/no/such/dir/x.csv"
is "$status" 1 "--csv into a missing folder: exit 1"
grep -q 'x.csv' "$TMP/err"
ok $? "--csv into a missing folder: the message names the file"

# A folder of an archive may be named anything: a quote and a newline in
# its name do not stop the functions' harness from including its source.
q=$(printf 'q"uo\nte')
mkdir "$TMP/$q"
cp "$STUDENTS/correct/main.c" "$TMP/$q/"
run_capture grade $NV "$TMP/$q"
is "$status" 0 "a folder named with a quote and a newline: graded, and it passes"
grep -q '^functions  pass' "$TMP/out"
ok $? "a folder named with a quote and a newline: the functions criterion passes"

done_testing
