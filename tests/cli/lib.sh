# lib.sh - shared helpers for the command tests (tests/cli/*.t), which are
# shell scripts printing TAP.  Sourced, not run.
#
# Environment (set by `make check`): RAYO (the command), RAYO_BUILD (the
# build folder), RAYO_SOURCE (the repository), RAYO_CC (the compiler).
# With RAYO_VALGRIND=1 (make check-valgrind) every `rayo` runs under
# valgrind memcheck, and a memory error or leak fails the command.
set -u
: "${RAYO:?run through make check}"
# The command's messages in English, whatever the machine's language
# (docs/i18n.md); i18n.t asks for Spanish itself.
export LANGUAGE=en
: "${RAYO_SOURCE:=$(pwd)}"
SEED="$RAYO_SOURCE/tests/data/seed"
TMP=$(mktemp -d "${TMPDIR:-/tmp}/rayo-test.XXXXXX")
trap 'rm -rf "$TMP"' EXIT
tap_n=0
tap_failed=0

rayo() {
    if [ "${RAYO_VALGRIND:-0}" = 1 ]; then
        valgrind -q --error-exitcode=99 --leak-check=full \
            --suppressions="$RAYO_SOURCE/tests/cli/valgrind.supp" \
            --show-leak-kinds=definite,indirect,possible \
            --errors-for-leak-kinds=definite,indirect,possible "$RAYO" "$@"
    else
        "$RAYO" "$@"
    fi
}

# rayo_start ARGS...: the same, in the background, so that a test can
# signal it: its process id (valgrind's, which is rayo's) is $rayo_pid.
rayo_start() {
    if [ "${RAYO_VALGRIND:-0}" = 1 ]; then
        valgrind -q --error-exitcode=99 --leak-check=full \
            --suppressions="$RAYO_SOURCE/tests/cli/valgrind.supp" \
            --show-leak-kinds=definite,indirect,possible \
            --errors-for-leak-kinds=definite,indirect,possible "$RAYO" "$@" &
    else
        "$RAYO" "$@" &
    fi
    rayo_pid=$!
}

ok() { # ok CONDITION-STATUS NAME
    tap_n=$((tap_n + 1))
    if [ "$1" -eq 0 ]; then
        echo "ok $tap_n - $2"
    else
        echo "not ok $tap_n - $2"
        tap_failed=$((tap_failed + 1))
    fi
}

is() { # is GOT WANT NAME
    tap_n=$((tap_n + 1))
    if [ "$1" = "$2" ]; then
        echo "ok $tap_n - $3"
    else
        echo "not ok $tap_n - $3"
        printf '#   got:      %s\n#   expected: %s\n' "$1" "$2"
        tap_failed=$((tap_failed + 1))
    fi
}

diag() { echo "# $*"; }

done_testing() {
    echo "1..$tap_n"
    [ "$tap_failed" -eq 0 ]
}

# run_capture ARGS...: runs rayo, leaving stdout in $TMP/out, stderr in
# $TMP/err and the exit status in $status.
run_capture() {
    status=0
    rayo "$@" >"$TMP/out" 2>"$TMP/err" || status=$?
}

# leaks_lost [FILE]: "BYTES BLOCKS", the sum of a grade report's "leak:
# N bytes in M blocks definitely lost" and "... possibly lost" lines
# ($TMP/out by default).  valgrind's leak scan is conservative: a stale
# word left in a register or on the stack that points inside a lost
# block makes it "possibly lost" now and then (seen in 1 run of 6), so
# a test of how much leaked adds the two.
leaks_lost() {
    awk '{ for (i = 1; i + 7 <= NF; i++)
               if ($i == "leak:" && $(i + 2) == "bytes" && $(i + 7) == "lost" &&
                   ($(i + 6) == "definitely" || $(i + 6) == "possibly")) {
                   bytes += $(i + 1); blocks += $(i + 4)
               } }
         END { print bytes + 0, blocks + 0 }' "${1:-$TMP/out}"
}

# expect_usage_error NAME PATTERN ARGS...: exit status 2, nothing on
# stdout, exactly one line on stderr matching PATTERN (grep -E).
expect_usage_error() {
    name=$1 pattern=$2
    shift 2
    run_capture "$@"
    is "$status" 2 "$name: exit status 2"
    is "$(wc -c <"$TMP/out" | tr -d ' ')" 0 "$name: nothing on stdout"
    is "$(wc -l <"$TMP/err" | tr -d ' ')" 1 "$name: one line on stderr"
    grep -Eq -- "$pattern" "$TMP/err"
    ok $? "$name: message matches /$pattern/"
    [ "$tap_failed" -eq 0 ] || sed 's/^/#   stderr: /' "$TMP/err"
}
