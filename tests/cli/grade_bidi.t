#!/bin/sh
# grade_bidi.t - a folder's name cannot reorder what a teacher reads: the
# bidirectional controls (U+061C, U+200E, U+200F, U+202A-U+202E,
# U+2066-U+2069) and the line and paragraph separators (U+2028, U+2029)
# in a submission's name reach `rayo grade --each`'s table, its --csv and
# the messages as \uHHHH, never as the character itself; other UTF-8 is
# kept.  The folders hold no C file, so nothing is compiled.
. "$(dirname "$0")/lib.sh"

# Every code point the escape covers, each in a name of its own, and one
# name with accents that must stay as it is.
mkdir "$TMP/class"
codes="061c 200e 200f 2028 2029 202a 202b 202c 202d 202e 2066 2067 2068 2069"
for c in $codes; do
    name=$(python3 -c "import sys; sys.stdout.write('a_' + chr(0x$c) + 'fdp.c')")
    mkdir "$TMP/class/$name"
done
mkdir "$TMP/class/zz_Nuñez"
# A byte pattern of any of them in the output, as UTF-8.
raw=$(python3 -c "import sys; sys.stdout.write('|'.join(chr(int(c, 16)) for c in sys.argv[1:]))" $codes)

run_capture grade --no-valgrind --each "$TMP/class"
is "$status" 1 "--each: exit 1 (no submission passed)"
grep -Eq "$raw" "$TMP/out"
is $? 1 "--each: no bidirectional control or separator raw in the table"
n=0
for c in $codes; do
    grep -Fq "a_\\u${c}fdp.c" "$TMP/out" && n=$((n + 1))
done
is "$n" 14 "--each: each name in the table with its control as \\uHHHH"
grep -q "zz_Nuñez" "$TMP/out"
ok $? "--each: other UTF-8 kept as it is"
# The student column is as wide in every row (the escape counts its
# columns): each row's result starts at the same byte as the header's.
python3 - "$TMP/out" >"$TMP/columns" <<'PY'
import sys
rows = [l for l in open(sys.argv[1], encoding='utf-8').read().split('\n')
        if l.startswith('a_') or l.startswith('zz_')]
print(len(rows), len(set(l.index(' error') for l in rows)))
PY
is "$(cat "$TMP/columns")" "15 1" "--each: the rows' columns line up"

run_capture grade --no-valgrind --each "$TMP/class" --csv -
grep -Eq "$raw" "$TMP/out"
is $? 1 "--csv: no bidirectional control or separator raw in the CSV"
is "$(python3 -c 'import csv,sys; print(" ".join(r[0] for r in csv.reader(sys.stdin))) ' <"$TMP/out" | cut -d ' ' -f 2-3)" \
    'a_\u061cfdp.c a_\u200efdp.c' "--csv: the cells hold the escaped names"

# A message about a file names it escaped too.
name=$(python3 -c "import sys; sys.stdout.write('x' + chr(0x202e) + 'gnp.pbm')")
run_capture render -o "$TMP/no/such/$name"
grep -Eq "$raw" "$TMP/err"
is $? 1 "a message: no right-to-left override raw on stderr"
grep -Fq 'x\u202egnp.pbm' "$TMP/err"
ok $? "a message: the name with \\u202e"

done_testing
