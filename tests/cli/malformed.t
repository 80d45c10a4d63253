#!/bin/sh
# malformed.t - every file of the malformed-image corpus
# (tests/data/malformed/, made by generate.py there) is refused the same
# way: `rayo convert FILE OUT.pbm` exits 2, prints exactly one line that
# names the file, prints nothing on stdout and leaves no OUT.pbm (nor a
# temporary file beside it).  Under `make check-valgrind` every run is
# also checked for memory errors and leaks.
. "$(dirname "$0")/lib.sh"

CORPUS="$RAYO_SOURCE/tests/data/malformed"
count=0
for f in "$CORPUS"/*; do
    case $f in *.py) continue ;; esac
    name=$(basename "$f")
    count=$((count + 1))
    mkdir "$TMP/o"
    run_capture convert "$f" "$TMP/o/out.pbm"
    is "$status" 2 "$name: exit status 2"
    is "$(wc -l <"$TMP/err" | tr -d ' ')" 1 "$name: one line on stderr"
    grep -qF "rayo: $f: " "$TMP/err"
    ok $? "$name: the message names the file"
    is "$(wc -c <"$TMP/out" | tr -d ' ')" 0 "$name: nothing on stdout"
    is "$(ls -A "$TMP/o")" "" "$name: no output file, no temporary file"
    [ "$tap_failed" -eq 0 ] || sed 's/^/#   stderr: /' "$TMP/err"
    rm -rf "$TMP/o"
done
ok "$([ "$count" -ge 30 ]; echo $?)" "the corpus has at least 30 files ($count)"

# The same refusal when the bad file comes through standard input.
for name in p1-truncated.pbm p6-truncated.ppm png-no-iend.png; do
    status=0
    rayo convert - "$TMP/out.pbm" <"$CORPUS/$name" >"$TMP/out" \
        2>"$TMP/err" || status=$?
    is "$status" 2 "$name on stdin: exit status 2"
    grep -q '^rayo: standard input: ' "$TMP/err"
    ok $? "$name on stdin: the message names standard input"
    ok "$([ ! -e "$TMP/out.pbm" ]; echo $?)" "$name on stdin: no output file"
done
done_testing
