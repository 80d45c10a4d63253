#!/bin/sh
# grade_fixes.t - `rayo grade`'s report says the right thing where it
# used to mislead: a real compile error among -Werror ones is named as
# the one to fix; the compile line shown is the one that ran (every word
# of --cc, -g, shell quoting); the --each table fits long folder names
# and cannot be forged by one holding a newline; valgrind's leaks and
# overruns in exercise 3's constructors are said in the statement's
# terms (fixtures in tests/grade/fixes/).
. "$(dirname "$0")/lib.sh"

FIXES="$RAYO_SOURCE/tests/grade/fixes"
STUDENTS="$RAYO_SOURCE/tests/grade"
NV=--no-valgrind

says() {
    found=0
    grep -Eq -- "$1" "$TMP/out" || found=1
    ok "$found" "$2"
    [ "$found" -eq 0 ] || sed 's/^/#   /' "$TMP/out"
}
says_not() {
    found=0
    grep -Eq -- "$1" "$TMP/out" && found=1
    ok "$found" "$2"
    [ "$found" -eq 0 ] || sed 's/^/#   /' "$TMP/out"
}
# line PATTERN: the first line of the report matching PATTERN, trimmed.
line() { grep -E -- "$1" "$TMP/out" | head -n 1 | sed 's/^ *//'; }
# The table's first line says how the submissions are isolated
# (grade_sandbox.t checks it); the table follows.
strip_isolation() {
    sed '1{/^sandbox: /d;/^warning: not isolated/d;}' "$TMP/out" >"$TMP/out.t" &&
        mv "$TMP/out.t" "$TMP/out"
}

# ---- 1. a real error before a -Werror one ----
cp "$FIXES/real_error.c" "$TMP/real_error.c"
(cd "$TMP" && rayo grade $NV real_error.c) >"$TMP/out" 2>"$TMP/err"
says '^compile +FAIL' "real error: compile fails"
says_not 'that -Werror turns into an error' \
    "real error: not blamed on -Werror"
# The compiler's own first error that is not a -Werror one.  (gcc also
# reports the unused variable; clang stops at the error.)
(cd "$TMP" && ${CC:-cc} -std=c99 -Wall -Werror -pedantic -c real_error.c \
     -o /dev/null) >"$TMP/cc.txt" 2>&1
first=$(grep -v -e '\[-Werror' "$TMP/cc.txt" | grep -m 1 'error: ')
if grep -q '\[-Werror' "$TMP/cc.txt"; then
    is "$(line 'the first real error')" \
        "the first real error, not a warning, is the one to fix first: $first" \
        "real error: the compiler's first real error is quoted, word for word"
else
    ok 0 "# SKIP the compiler reports no -Werror error beside the real one"
fi
says 'undeclared' "real error: it is the undeclared identifier"

run_capture grade $NV "$STUDENTS/werror/main.c"
says 'a warning \(unused variable .i.\) that -Werror turns into an error' \
    "-Werror alone: still explained as a warning made fatal"

# ---- 2. the compile line that ran ----
mkdir "$TMP/it's here"
cp "$STUDENTS/correct/main.c" "$TMP/it's here/main.c"
run_capture grade $NV --cc "cc -O1 -DRAYO_FIXES=1" "$TMP/it's here/main.c"
is "$(awk '$1 == "compile" { $1 = ""; $2 = ""; sub(/^ +/, ""); print }' "$TMP/out")" \
    "cc -O1 -DRAYO_FIXES=1 -std=c99 -Wall -Werror -pedantic -g -o programa '$TMP/it'\\''s here/main.c' -lm" \
    "--cc: every word shown, with -g, the path quoted for a shell"
# The line, pasted into a shell, compiles (programa stands for the
# temporary program).
cmd=$(awk '$1 == "compile" { $1 = ""; $2 = ""; print }' "$TMP/out" |
      sed "s| -o programa | -o $TMP/pasted |")
(eval "$cmd") >/dev/null 2>&1
ok $? "the line shown compiles when run by a shell"
if command -v gcc >/dev/null 2>&1 && [ "$(uname -m)" = x86_64 ]; then
    run_capture grade $NV --cc "gcc -m64 -O1" "$STUDENTS/werror/main.c"
    is "$(line '^ +gcc ')" \
        "gcc -m64 -O1 -std=c99 -Wall -Werror -pedantic -g -o programa $STUDENTS/werror/main.c -lm" \
        "--cc 'gcc -m64 -O1': shown whole on failure too"
else
    ok 0 "# SKIP gcc for x86_64 is not installed"
fi

# ---- 3. the --each table ----
long=abcdefghijklmnopqrstuvwxyz0123 # 30 characters
nl=$(printf 'a\nPASS')
mkdir "$TMP/class" "$TMP/class/ana" "$TMP/class/$long" "$TMP/class/$nl" \
    "$TMP/class/$(printf 'esc\033[31m')" "$TMP/class/empty" \
    "$TMP/class/$(printf 'x%.0s' 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 \
                    18 19 20 21 22 23 24 25 26 27 28 29 30 31 32 33 34 35 \
                    36 37 38 39 40 41 42 43 44 45)"
for d in ana "$long" "$nl"; do
    cp "$STUDENTS/correct/main.c" "$TMP/class/$d/"
done
cp "$STUDENTS/lowercase_magic/main.c" "$TMP/class/esc"*/
cp "$STUDENTS/correct/main.c" "$TMP/class/xxx"*/
run_capture grade $NV --each "$TMP/class"
strip_isolation
# Every row's result starts where the header's does (rows end at the
# blank line before the tally); names sort by their bytes.
header_result=$(head -n 1 "$TMP/out" | awk '{ print index($0, "result") }')
is "$(head -n 1 "$TMP/out" | tr -s ' ')" \
    "student compile functions run output image valgrind result" "--each: the header"
is "$(awk -v at="$header_result" '/^$/ { exit } NR > 1 && $2 != "error:" &&
          substr($0, at) !~ /^(PASS|FAIL)$/ { print NR": "$0 }' "$TMP/out")" "" \
    "--each: every row's result under the header's"
is "$(awk '/^$/ { exit } NR > 1 { print $1 }' "$TMP/out" | tr '\n' ' ')" \
    "a\\nPASS $long ana empty esc\\x1b[31m xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx... " \
    "--each: names escaped, in order, the longest cut at 40 columns"
is "$(grep -c '^PASS' "$TMP/out")" 0 "--each: a name holding a newline forges no line"
is "$(grep -c "$(printf '\033')" "$TMP/out")" 0 "--each: no raw escape byte"
is "$(head -n 1 "$TMP/out" | awk '{ print index($0, "compile") }')" 42 \
    "--each: the student column is 40 wide"
says '^empty +error: .*/class/empty: no \.c file' "--each: a folder's error on its row"
rm -rf "$TMP/class/xxx"* "$TMP/class/empty"
run_capture grade $NV --each "$TMP/class"
strip_isolation
is "$(head -n 1 "$TMP/out" | awk '{ print index($0, "compile") }')" 32 \
    "--each: the column fits a 30-character name"
run_capture grade $NV --each --json "$TMP/class"
if command -v python3 >/dev/null 2>&1; then
    is "$(python3 -c 'import json, sys
print(" ".join(repr(x["student"]) for x in json.load(open(sys.argv[1]))))' "$TMP/out")" \
        "'a\\nPASS' '$long' 'ana' 'esc\\x1b[31m'" "--each --json: the names, escaped as JSON"
else
    ok 0 "# SKIP python3 is not installed"
fi

# ---- 4. valgrind in exercise 3's terms ----
if command -v valgrind >/dev/null 2>&1; then
    for f in escena.h escena.c leak_spheres.c leak_lights.c leak_array.c \
             leak_all.c overrun.c; do
        cp "$FIXES/$f" "$TMP/$f"
    done
    vg() { (cd "$TMP" && rayo grade "$1") >"$TMP/out" 2>"$TMP/err"; }
    vg leak_spheres.c
    says '^valgrind +FAIL +leak: ' "spheres: valgrind fails on a leak"
    is "$(leaks_lost)" "72 2" "spheres: two 36-byte spheres lost"
    says '^ +spheres made by esfera_crear are never destroyed: call esfera_destruir on each before freeing the array$' \
        "spheres: named in the statement's terms"
    says_not 'luz_crear|the arrays' "spheres: nothing else blamed"
    vg leak_lights.c
    says '^ +lights made by luz_crear are never destroyed: call luz_destruir on each before freeing the array$' \
        "lights: named in the statement's terms"
    says_not 'esfera_crear|the arrays' "lights: nothing else blamed"
    vg leak_array.c
    says "^ +the arrays' v is never freed" "arrays: v never freed, named"
    says_not 'esfera_crear|luz_crear' "arrays: the elements were destroyed"
    vg leak_all.c
    says 'indirectly lost' "all: the spheres are lost through v"
    says "^ +the arrays' v is never freed" "all: v named"
    says '^ +spheres made by esfera_crear are never destroyed' "all: the spheres named"
    vg overrun.c
    says '^valgrind +FAIL +Invalid write of size 8, at arreglo_agregar \(overrun\.c:[0-9]+\)' \
        "overrun: the invalid write is located"
    says '^ +a write past the end of v: grow it to n \+ 1 elements before writing v\[n\]$' \
        "overrun: explained"
    says_not 'leak:' "overrun: no leak"
    run_capture grade "$STUDENTS/leak/main.c"
    says_not 'esfera_|luz_|arreglo_' "ej1's leak: no exercise 3 words"
else
    ok 0 "# SKIP valgrind is not installed"
fi

done_testing
