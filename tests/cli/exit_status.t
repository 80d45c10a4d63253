#!/bin/sh
# exit_status.t - one rule for every command (man rayo, EXIT STATUS): an
# input that cannot be read (missing, unreadable, a directory, malformed)
# exits 2 with one line naming the file and the reason; an output that
# cannot be created exits 1; compare's and grade's 1 ("inconsistent",
# "failed") never means an unreadable input.  Checked per command, and
# every --help says the same.
. "$(dirname "$0")/lib.sh"

# Unreadable: mode 000.  Root reads it anyway, so as root the command runs
# as nobody (setpriv), with $TMP open to it.
chmod 755 "$TMP"
as_reader() {
    if [ "$(id -u)" = 0 ]; then
        setpriv --reuid=65534 --regid=65534 --clear-groups "$RAYO" "$@"
    else
        "$RAYO" "$@"
    fi
}

# expect NAME STATUS FILE ARGS...: that exit status, nothing on stdout,
# one line on stderr naming FILE.  With ARGS starting with "as_reader",
# run as the unprivileged reader.
expect() {
    name=$1 want=$2 file=$3
    shift 3
    status=0
    if [ "$1" = as_reader ]; then
        shift
        as_reader "$@" >"$TMP/out" 2>"$TMP/err" || status=$?
    else
        rayo "$@" >"$TMP/out" 2>"$TMP/err" || status=$?
    fi
    is "$status" "$want" "$name: exit status $want"
    is "$(wc -c <"$TMP/out" | tr -d ' ')" 0 "$name: nothing on stdout"
    is "$(wc -l <"$TMP/err" | tr -d ' ')" 1 "$name: one line on stderr"
    grep -qF -- "rayo: $file" "$TMP/err"
    ok $? "$name: the line names $file"
    [ "$tap_failed" -eq 0 ] || sed 's/^/#   stderr: /' "$TMP/err"
}

in=$TMP/in
mkdir "$in"
rayo -W 8 -H 6 -o "$in/good.pbm"
rayo -W 8 -H 6 -o "$in/good.png"
cp "$in/good.pbm" "$in/locked.pbm"
printf 'sphere 0 0 3 1\n' >"$in/good.scene"
cp "$in/good.scene" "$in/locked.scene"
printf 'int main(void) { return 0; }\n' >"$in/locked.c"
chmod 000 "$in/locked.pbm" "$in/locked.scene" "$in/locked.c"
malformed=$RAYO_SOURCE/tests/data/malformed/p6-truncated.ppm
printf 'sphere 0 0 3\n' >"$in/bad.scene"
mkdir "$in/folder.pbm" "$in/empty"
out=$TMP/out-dir
mkdir "$out"
chmod 777 "$out"
nodir=$TMP/no/such/dir

# --- convert IN OUT -------------------------------------------------------
expect "convert, missing IN" 2 "$in/missing.pbm" convert "$in/missing.pbm" "$out/x.pbm"
expect "convert, unreadable IN" 2 "$in/locked.pbm: Permission denied" \
    as_reader convert "$in/locked.pbm" "$out/x.pbm"
expect "convert, a directory as IN" 2 "$in/folder.pbm: Is a directory" \
    convert "$in/folder.pbm" "$out/x.pbm"
expect "convert, malformed IN" 2 "$malformed" convert "$malformed" "$out/x.pbm"
expect "convert, OUT in a missing folder" 1 "$nodir/x.pbm" \
    convert "$in/good.pbm" "$nodir/x.pbm"
ok "$([ ! -e "$out/x.pbm" ]; echo $?)" "convert: no output after a refused input"

# --- render SCENE -----------------------------------------------------------
expect "render, missing SCENE" 2 "$in/missing.scene" render "$in/missing.scene" -o "$out/x.ppm"
expect "render, unreadable SCENE" 2 "$in/locked.scene: Permission denied" \
    as_reader render "$in/locked.scene" -o "$out/x.ppm"
expect "render, a directory as SCENE" 2 "$in/empty: Is a directory" \
    render "$in/empty" -o "$out/x.ppm"
expect "render, malformed SCENE" 2 "$in/bad.scene:1:" render "$in/bad.scene" -o "$out/x.ppm"
expect "render, -o in a missing folder" 1 "$nodir/x.ppm" \
    render "$in/good.scene" -W 8 -H 6 -o "$nodir/x.ppm"
expect "render (no scene), -o in a missing folder" 1 "$nodir/x.pbm" \
    render -W 8 -H 6 -o "$nodir/x.pbm"
ok "$([ ! -e "$out/x.ppm" ]; echo $?)" "render: no output after a refused scene"
cp "$in/good.scene" "$in/keep.scene"
ln -s keep.scene "$in/link.scene"
expect "render, -o the scene itself (through a link)" 2 "--output: '$in/link.scene' is the scene file" \
    render "$in/keep.scene" --format ppm -o "$in/link.scene"
cmp -s "$in/good.scene" "$in/keep.scene"
ok $? "render: the scene file is untouched"

# --- view FILE ----------------------------------------------------------------
expect "view, missing FILE" 2 "$in/missing.pbm" view "$in/missing.pbm"
expect "view, unreadable FILE" 2 "$in/locked.pbm: Permission denied" \
    as_reader view "$in/locked.pbm"
expect "view, a directory" 2 "$in/folder.pbm: Is a directory" view "$in/folder.pbm"
expect "view, malformed FILE" 2 "$malformed" view "$malformed"
status=0
rayo view "$in/good.pbm" >/dev/full 2>"$TMP/err" || status=$?
is "$status" 1 "view, standard output full: exit status 1"
grep -q "No space left on device" "$TMP/err"
ok $? "view, standard output full: the reason"

# --- compare REFERENCE IMAGE ----------------------------------------------------
for side in reference image; do
    for case in missing locked folder malformed; do
        case $case in
        missing) f=$in/missing.pbm want=$f ;;
        locked) f=$in/locked.pbm want="$f: Permission denied" ;;
        folder) f=$in/folder.pbm want="$f: Is a directory" ;;
        malformed) f=$malformed want=$f ;;
        esac
        run=""
        [ "$case" = locked ] && run=as_reader
        if [ "$side" = reference ]; then
            expect "compare, $case REFERENCE" 2 "$want" $run compare "$f" "$in/good.pbm"
        else
            expect "compare, $case IMAGE" 2 "$want" $run compare "$in/good.pbm" "$f"
        fi
    done
done
status=0
rayo compare "$in/good.pbm" "$in/good.pbm" --diff "$nodir/d.png" >"$TMP/out" 2>"$TMP/err" || status=$?
is "$status" 1 "compare, --diff in a missing folder: exit status 1"
grep -qF "rayo: $nodir/d.png" "$TMP/err"
ok $? "compare, --diff in a missing folder: names it"
status=0
rayo compare "$in/good.pbm" "$in/good.pbm" >/dev/full 2>"$TMP/err" || status=$?
is "$status" 1 "compare, standard output full: exit status 1"

# --- grade SOURCE -----------------------------------------------------------------
correct=$RAYO_SOURCE/tests/grade/correct/main.c
expect "grade, missing SOURCE" 2 "$in/missing.c" grade --no-valgrind "$in/missing.c"
expect "grade, unreadable SOURCE" 2 "$in/locked.c: Permission denied" \
    as_reader grade --no-valgrind "$in/locked.c"
expect "grade, a folder without C sources" 2 "$in/empty: no .c file" \
    grade --no-valgrind "$in/empty"
expect "grade, missing --reference" 2 "$in/missing.png" \
    grade --no-valgrind --reference "$in/missing.png" "$correct"
expect "grade, unreadable --reference" 2 "$in/locked.pbm: Permission denied" \
    as_reader grade --no-valgrind --reference "$in/locked.pbm" "$correct"
expect "grade, a directory as --reference" 2 "$in/folder.pbm: Is a directory" \
    grade --no-valgrind --reference "$in/folder.pbm" "$correct"
expect "grade, malformed --reference" 2 "$malformed" \
    grade --no-valgrind --reference "$malformed" "$correct"
expect "grade --each, missing DIRECTORY" 2 "$in/missing" grade --each --no-valgrind "$in/missing"
expect "grade --each, a file" 2 "$correct: Not a directory" grade --each --no-valgrind "$correct"

# --- every --help says the rule --------------------------------------------------
for cmd in render convert compare view grade; do
    "$RAYO" "$cmd" --help >"$TMP/help" 2>&1
    grep -A3 "^exit status:" "$TMP/help" | tr '\n' ' ' | grep -q "2 bad options or an *input that cannot be read"
    ok $? "rayo $cmd --help: 2 is bad options or an input that cannot be read"
done
"$RAYO" --help >"$TMP/help" 2>&1
grep -q "input that cannot be read" "$TMP/help"
ok $? "rayo --help says it too"
sed -n '/^\.SH EXIT STATUS/,/^\.SH /p' "$RAYO_SOURCE/man/rayo.1" | tr '\n' ' ' |
    grep -q "cannot be read"
ok $? "man rayo: EXIT STATUS states the rule"
done_testing
