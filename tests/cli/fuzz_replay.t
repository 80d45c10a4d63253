#!/bin/sh
# fuzz_replay.t - every fuzz target (fuzz/fuzz_*.c), built without
# libFuzzer as $RAYO_BUILD/fuzz/replay-NAME, runs on its seed corpus
# (fuzz/corpus/NAME) and on every input that ever crashed, leaked or hung
# it (fuzz/regression/NAME).  A target aborts when the library breaks a
# promise (a refusal that is not one line, an image over the limits); a
# crash fails the test, and `make check-sanitize` replays the same
# inputs under ASan and UBSan.  Under RAYO_VALGRIND=1 the replays run
# under memcheck too, so a leak on any of these inputs fails.
. "$(dirname "$0")/lib.sh"

replay() { # replay NAME DIR...
    bin="$RAYO_BUILD/fuzz/replay-$1"
    shift
    if [ "${RAYO_VALGRIND:-0}" = 1 ]; then
        valgrind -q --error-exitcode=99 --leak-check=full \
            --errors-for-leak-kinds=definite,indirect,possible \
            "$bin" --count-to "$TMP/count" "$@" >/dev/null 2>"$TMP/err"
    else
        "$bin" --count-to "$TMP/count" "$@" >/dev/null 2>"$TMP/err"
    fi
}

for src in "$RAYO_SOURCE"/fuzz/fuzz_*.c; do
    name=$(basename "$src" .c)
    name=${name#fuzz_}
    corpus="$RAYO_SOURCE/fuzz/corpus/$name"
    regression="$RAYO_SOURCE/fuzz/regression/$name"
    ok "$([ -x "$RAYO_BUILD/fuzz/replay-$name" ]; echo $?)" "$name: replay driver built"
    files=$(find "$corpus" "$regression" -type f ! -name '.*' | wc -l | tr -d ' ')
    ok "$([ "$files" -gt 0 ]; echo $?)" "$name: $files inputs to replay"
    status=0
    replay "$name" "$corpus" "$regression" || status=$?
    is "$status" 0 "$name: every input replayed without a crash"
    [ "$status" = 0 ] || sed 's/^/#   /' "$TMP/err" | tail -20
    is "$(cat "$TMP/count" 2>/dev/null)" "replayed $files files" "$name: all $files inputs ran"
done
done_testing
