#!/bin/sh
# grade_sandbox.t - `rayo grade` against hostile submissions
# (tests/grade/hostile/, one per attack): each is contained by the
# bubblewrap sandbox; where it matters, the same submission with
# --sandbox=off shows the attack is real.  Also the fallback without a
# sandbox (the warning, the JSON, --sandbox=require) and, when run as
# root with setpriv, the sandbox for an unprivileged user.
. "${RAYO_SOURCE:-.}/tests/cli/lib.sh"

H="$RAYO_SOURCE/tests/grade/hostile"
# The compiler that built rayo, without its flags: under check-sanitize
# RAYO_CC carries -fsanitize, and a sanitized program cannot map its
# shadow memory within the grader's address-space limit.
RAYO_CC=${RAYO_CC:-cc}
export CC="${RAYO_CC%% *}"
NV=--no-valgrind
chmod 755 "$TMP"
mkdir "$TMP/tmp"
chmod 1777 "$TMP/tmp"
says() {
    found=0
    grep -Eq -- "$1" "$TMP/out" || found=1
    ok "$found" "$2"
    [ "$found" -eq 0 ] || sed 's/^/#   /' "$TMP/out" "$TMP/err" 2>/dev/null
}
lacks() { ! grep -Eq -- "$1" "$TMP/out"; ok $? "$2"; }
# says_native PATTERN NAME: says, but skipped when the grader itself runs
# under valgrind (make check-valgrind): valgrind only pretends to lower
# the descriptor limit of the grader's children before their exec, so
# there the program reaches valgrind's log, and what it shows depends on
# that (the criterion still fails, checked apart).
says_native() {
    if [ "${RAYO_VALGRIND:-0}" = 1 ]; then
        ok 0 "$2 # SKIP the grader runs under valgrind, which cannot lower its children's descriptor limit"
    else
        says "$1" "$2"
    fi
}
# grade_in DIR ARGS...: grades with TMPDIR=$TMP/tmp (its temporary
# folder there, so the tests can see it is removed).
grade_in() {
    status=0
    TMPDIR="$TMP/tmp" rayo grade "$@" >"$TMP/out" 2>"$TMP/err" || status=$?
}
left_in_tmp() { find "$TMP/tmp" -mindepth 1 -maxdepth 1 | wc -l | tr -d ' '; }

# ---- the fallback: no sandbox can be made ----
mkdir "$TMP/fakebin"
printf '#!/bin/sh\necho "bwrap: No permissions to create a new namespace" >&2\nexit 1\n' \
    >"$TMP/fakebin/bwrap"
chmod 755 "$TMP/fakebin/bwrap"
status=0
PATH="$TMP/fakebin:$PATH" rayo grade $NV "$RAYO_SOURCE/tests/grade/correct" \
    >"$TMP/out" 2>"$TMP/err" || status=$?
is "$(head -n 1 "$TMP/out" | sed 's/; limits: .*//')" "warning: not isolated: bubblewrap cannot make a sandbox here (no user namespaces?): bwrap: No permissions to create a new namespace; the submission runs with your rights" \
    "no sandbox: the report's first line says why"
is "$status" 0 "no sandbox: still graded (auto)"
PATH="$TMP/fakebin:$PATH" rayo grade $NV --json "$RAYO_SOURCE/tests/grade/correct" \
    >"$TMP/out" 2>"$TMP/err"
says '"sandbox": \{"isolated": false, "detail": "not isolated: bubblewrap cannot' \
    "no sandbox: the JSON says so"
status=0
PATH="$TMP/fakebin:$PATH" rayo grade $NV --sandbox=require "$RAYO_SOURCE/tests/grade/correct" \
    >"$TMP/out" 2>"$TMP/err" || status=$?
is "$status" 2 "no sandbox: --sandbox=require refuses (exit 2)"
is "$(wc -l <"$TMP/err" | tr -d ' '):$(wc -c <"$TMP/out" | tr -d ' ')" "1:0" \
    "no sandbox: --sandbox=require: one line on stderr, nothing graded"
status=0
PATH="$TMP/fakebin:$PATH" rayo grade --sandbox=require --check >"$TMP/out" 2>&1 || status=$?
is "$status" 2 "no sandbox: --sandbox=require --check exits 2"
rayo grade $NV --sandbox=off "$RAYO_SOURCE/tests/grade/correct" >"$TMP/out" 2>&1
is "$(head -n 1 "$TMP/out" | cut -c1-7)" "compile" "--sandbox=off: no warning line"

# ---- the sandbox itself ----
if ! rayo grade --sandbox=require --check >"$TMP/out" 2>&1; then
    diag "no sandbox can be made here: $(cat "$TMP/out"); hostile tests skipped"
    done_testing
    exit $?
fi
says '^sandbox: bubblewrap \(user, pid, net, ipc, uts namespaces; read-only system; 256 MiB disk; no capabilities\); limits: (cgroup v[12] on the whole tree|per process only)' \
    "--check: the sandbox works"
grade_in $NV "$RAYO_SOURCE/tests/grade/correct"
is "$(head -n 1 "$TMP/out" | sed 's/; limits: .*//')" "sandbox: bubblewrap (user, pid, net, ipc, uts namespaces; read-only system; 256 MiB disk; no capabilities)" \
    "the report's first line names the sandbox"

secret="TOPSECRET-$$-rayo"
echo "$secret" >/tmp/rayo-hostile-secret
chmod 644 /tmp/rayo-hostile-secret
rm -f /tmp/rayo-hostile-written
trap 'rm -rf "$TMP"; rm -f /tmp/rayo-hostile-secret /tmp/rayo-hostile-written' EXIT

# A file outside, /etc/shadow.
grade_in $NV "$H/read_outside"
says '^ +could not read the secret$' "read outside: the file is not there"
says '^ +shadow unreadable$' "read outside: /etc/shadow is not there"
lacks "$secret" "read outside: nothing of it in the report"
grade_in $NV --sandbox=off "$H/read_outside"
says "LEAKED $secret" "read outside, --sandbox=off: the attack is real"

# #include of a file outside.
grade_in $NV "$H/include_outside"
says '^compile +FAIL' "include outside: does not compile"
lacks "$secret" "include outside: the compiler quotes nothing of it"
grade_in $NV --sandbox=off "$H/include_outside"
says "$secret" "include outside, --sandbox=off: the attack is real"

# Another process's environment.
status=0
RAYO_HOSTILE_MARK=1 TMPDIR="$TMP/tmp" rayo grade $NV "$H/env_grader" >"$TMP/out" 2>&1 || status=$?
lacks 'LEAKED' "environment: the grader's is out of reach"
says '^ +processes seen: [1-3]$' "environment: /proc shows only the sandbox's"
RAYO_HOSTILE_MARK=1 TMPDIR="$TMP/tmp" rayo grade $NV --sandbox=off "$H/env_grader" >"$TMP/out" 2>&1
says 'LEAKED' "environment, --sandbox=off: the attack is real"

# Writing outside.
grade_in $NV "$H/write_outside"
says '^ +write refused$' "write outside: refused"
[ ! -e /tmp/rayo-hostile-written ]
ok $? "write outside: nothing written"

# A local listener.
port_file="$TMP/port.log"
python3 -c '
import socket, sys
s = socket.socket(); s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
try:
    s.bind(("127.0.0.1", 47321))
except OSError:
    sys.exit(0)
s.listen(1); s.settimeout(20)
try:
    c, _ = s.accept(); open(sys.argv[1], "w").write(c.recv(100).decode())
except socket.timeout:
    pass
' "$port_file" &
listener=$!
sleep 0.5
grade_in $NV "$H/connect"
says '^ +connect refused$' "network: the connection is refused"
[ ! -s "$port_file" ]
ok $? "network: the listener got nothing"
kill "$listener" 2>/dev/null
wait "$listener" 2>/dev/null

# A daemon left behind, a fork bomb: nothing outlives the run.
grade_in $NV "$H/daemon"
sleep 0.3
is "$(pgrep -f '^rayo-hostile-daemon' | wc -l | tr -d ' ')" 0 "daemon: none left running"
grade_in $NV --timeout 3 --processes 64 "$H/fork_bomb"
says '^run +FAIL +did not finish within 3 s' "fork bomb: stopped by the wall clock"
sleep 0.3
is "$(pgrep -f "$TMP/tmp" | wc -l | tr -d ' ')" 0 "fork bomb: no process left"

# Filling the disk: the tmpfs holds --disk MiB in all.
grade_in $NV --disk 48 "$H/fill_disk"
got=$(sed -n 's/^ *wrote \([0-9]*\) MiB$/\1/p' "$TMP/out")
[ -n "$got" ] && [ "$got" -le 48 ] && [ "$got" -ge 16 ]
ok $? "fill the disk: stopped at the 48 MiB disk (wrote ${got:-?} MiB)"
is "$(left_in_tmp)" 0 "fill the disk: nothing left in TMPDIR"

# Killing and stopping the grader.
status=0
TMPDIR="$TMP/tmp" timeout 60 "$RAYO" grade $NV "$H/kill_grader" >"$TMP/out" 2>&1 || status=$?
is "$status" 1 "kill the grader: the grader lives and reports (exit 1)"
says '^ +still here$' "kill the grader: the program ran on, alone"
is "$(left_in_tmp)" 0 "kill the grader: the temporary folder is removed"
status=0
TMPDIR="$TMP/tmp" timeout 60 "$RAYO" grade $NV --timeout 2 "$H/stop_grader" >"$TMP/out" 2>&1 || status=$?
is "$status" 1 "stop the grader: it was not stopped (no timeout(1) kill)"
says '^run +FAIL +did not finish within 2 s' "stop the grader: the wall clock held"
# The grader's own clock: stopped from outside while the program runs,
# the run that ends after the limit is not a pass.
cat >"$TMP/slow.c" <<'EOF'
#include <stdio.h>
#include <unistd.h>
int main(void) { sleep(1); printf("P1\n1 1\n0\n"); return 0; }
EOF
TMPDIR="$TMP/tmp" "$RAYO" grade $NV --timeout 3 "$TMP/slow.c" >"$TMP/out" 2>&1 &
grader=$!
# Stopped once the program runs (the compiler's time is its own).
tries=0
while ! pgrep -f -- "--ro-bind $TMP/tmp/rayo-grade[^ ]*/programa" >/dev/null && [ $tries -lt 300 ]; do
    sleep 0.1
    tries=$((tries + 1))
done
kill -STOP "$grader"
sleep 4
kill -CONT "$grader"
wait "$grader"
says '^run +FAIL +did not finish within 3 s' "stopped from outside: the grader's clock counts"

# FIFO traps and links: the grader opens none of them.
for mode in auto off; do
    status=0
    TMPDIR="$TMP/tmp" timeout 60 "$RAYO" grade $NV --sandbox=$mode "$H/fifo_trap" \
        >"$TMP/out" 2>&1 || status=$?
    is "$status" 1 "FIFO traps ($mode): the grader ends (no hang)"
    says 'wrote nothing on standard output' "FIFO traps ($mode): no FIFO read as output"
    is "$(left_in_tmp)" 0 "FIFO traps ($mode): the temporary folder is removed"
done

# Deep folders past PATH_MAX without write permission.
for mode in auto off; do
    grade_in $NV --sandbox=$mode "$H/deep_folders"
    says '^ +nested 60$' "deep folders ($mode): nested 60 levels"
    is "$(left_in_tmp)" 0 "deep folders ($mode): all removed"
done

# The valgrind dodge.
if command -v valgrind >/dev/null 2>&1; then
    for mode in auto off; do
        grade_in --sandbox=$mode "$H/valgrind_dodge"
        says '^valgrind +FAIL +leak: ' "valgrind dodge ($mode): valgrind fails on a leak"
        is "$(leaks_lost)" "1000000 1" "valgrind dodge ($mode): the megabyte is found lost"
        # (Which sign is seen depends on the host: a grader itself run
        # under valgrind, as check-valgrind does, cannot lower the real
        # descriptor limit, and then the forged NUL is what shows.)
        says_native "^ +the program wrote into the grader's channel: " \
            "valgrind dodge ($mode): its writes into valgrind's descriptors are a finding"
    done
    # The forged summary and NUL on descriptor 3 (once valgrind's log),
    # then on every descriptor: the real findings stay, and the attempt
    # is a finding of its own.
    for mode in auto off; do
        grade_in --sandbox=$mode "$H/valgrind_forge"
        says_native '^valgrind +FAIL +Invalid read of size 4, at main \(main\.c:[0-9]+\)$' \
            "valgrind forge ($mode): the real invalid read is reported"
        is "$(leaks_lost)" "4000 1" "valgrind forge ($mode): the real leak is reported"
        says "^ +the program wrote into the grader's channel: " \
            "valgrind forge ($mode): the forgery is a finding"
        lacks 'no invalid access and no leak' "valgrind forge ($mode): no pass"
    done
    # A clean summary printed on standard output and error.
    grade_in "$H/valgrind_forge_text"
    says '^valgrind +FAIL +Conditional jump or move depends on uninitialised value\(s\), at main' \
        "valgrind forge on stdout/stderr: the real error is reported"
    is "$(leaks_lost)" "4000 1" "valgrind forge on stdout/stderr: the real leak is reported"
    says "^ +the program wrote into the grader's channel: it printed lines framed like valgrind's log" \
        "valgrind forge on stdout/stderr: the forgery is a finding"
    # Writing into valgrind's own descriptors by their /proc names stops
    # valgrind before its summary: a failure, not a skip.
    grade_in "$H/valgrind_crash"
    says_native '^valgrind +FAIL +valgrind stopped on an internal error while it ran the program' \
        "valgrind crash: the criterion fails"
    says_native '^ +valgrind: .*Assertion' "valgrind crash: valgrind's own line is quoted"
fi

# An image far larger than the exercise's, as a PNG of 13 MB: refused by
# its header before anything decodes it; the grader's peak memory (GNU
# time's maximum resident set, which covers rayo and what it waits for)
# stays far below the 2 GiB the pixels would take.  The address space
# is capped at 3 GiB all the same, so that a regression fails here
# instead of taking the machine's memory; not under AddressSanitizer
# (make check-sanitize), which reserves terabytes of address space for
# its shadow: there the resident peak alone is checked.
case "${RAYO_CC:-}" in
*-fsanitize=*) cap=":" ;;
*) cap="ulimit -v 3145728" ;;
esac
if [ -x /usr/bin/time ]; then
    status=0
    ($cap && TMPDIR="$TMP/tmp" exec timeout 120 /usr/bin/time -f '%M' \
        -o "$TMP/peak" "$RAYO" grade $NV "$H/huge_png") >"$TMP/out" 2>"$TMP/err" || status=$?
    is "$status" 1 "huge PNG: graded, and failed (exit 1)"
    says '^output +FAIL +the program printed a 65536x16384 PNG; the exercise asks for a plain PBM of 640x480$' \
        "huge PNG: refused by its header, with the sizes"
    says '^image +skipped +not compared: the output.s header promises an image far larger' \
        "huge PNG: not compared"
    peak=$(tail -n 1 "$TMP/peak")
    [ -n "$peak" ] && [ "$peak" -lt 262144 ]
    ok $? "huge PNG: the grader's peak memory is under 256 MiB (${peak:-?} KiB)"
else
    diag "no /usr/bin/time: the huge PNG's memory is not measured"
fi

# Both at once, as a class graded two at a time.
if command -v valgrind >/dev/null 2>&1; then
    mkdir "$TMP/class"
    cp -r "$H/huge_png" "$H/valgrind_forge" "$TMP/class/"
    status=0
    ($cap && TMPDIR="$TMP/tmp" exec timeout 300 "$RAYO" grade --each "$TMP/class" \
        -j 2 --csv -) >"$TMP/out" 2>"$TMP/err" || status=$?
    is "$status" 1 "--each -j 2 over two hostile submissions: graded (exit 1)"
    says '^"huge_png",fail,.*,fail,"the program printed a 65536x16384 PNG; the exercise asks for a plain PBM of 640x480' \
        "--each -j 2: the huge PNG refused by its header"
    says "^\"valgrind_forge\",fail,.*,fail,\"Invalid read of size 4, at main .*the program wrote into the grader's channel" \
        "--each -j 2: the valgrind forge fails with its real error and the finding"
fi

# A forged report: control bytes escaped, the long line cut.
grade_in $NV "$H/forged_report"
is "$(tr -d '\n' <"$TMP/out" | tr -d '[:print:]' | wc -c | tr -d ' ')" 0 \
    "forged report: no control byte in the report"
says '\\r\\x1b\[2K\\x1b\[1A\\x1b\[2KPASS: 6 of 6' "forged report: the forgery shown escaped"
lacks '^PASS' "forged report: no forged summary line"
is "$(awk 'length > 400' "$TMP/out" | wc -l | tr -d ' ')" 0 "forged report: the megabyte line cut"

# As an unprivileged user, where the machine allows.
if [ "$(id -u)" = 0 ] && command -v setpriv >/dev/null 2>&1 &&
    setpriv --reuid 65534 --regid 65534 --clear-groups test -x "$RAYO"; then
    cp -r "$H/read_outside" "$H/write_outside" "$H/valgrind_forge" "$H/huge_png" "$TMP/"
    chmod -R a+rX "$TMP/read_outside" "$TMP/write_outside" "$TMP/valgrind_forge" "$TMP/huge_png"
    status=0
    (cd "$TMP" && setpriv --reuid 65534 --regid 65534 --clear-groups env HOME="$TMP/tmp" \
        TMPDIR="$TMP/tmp" "$RAYO" grade $NV --sandbox=require read_outside) \
        >"$TMP/out" 2>&1 || status=$?
    says '^sandbox: bubblewrap' "unprivileged: the sandbox works"
    says '^ +could not read the secret$' "unprivileged: read outside contained"
    (cd "$TMP" && setpriv --reuid 65534 --regid 65534 --clear-groups env HOME="$TMP/tmp" \
        TMPDIR="$TMP/tmp" "$RAYO" grade $NV --sandbox=require write_outside) \
        >"$TMP/out" 2>&1
    says '^ +write refused$' "unprivileged: write outside contained"
    if command -v valgrind >/dev/null 2>&1; then
        (cd "$TMP" && setpriv --reuid 65534 --regid 65534 --clear-groups env HOME="$TMP/tmp" \
            TMPDIR="$TMP/tmp" "$RAYO" grade --sandbox=require valgrind_forge) \
            >"$TMP/out" 2>&1
        says '^valgrind +FAIL +Invalid read of size 4' "unprivileged: valgrind forge: the real error stays"
        says "^ +the program wrote into the grader's channel" "unprivileged: valgrind forge: the forgery is a finding"
    fi
    (cd "$TMP" && setpriv --reuid 65534 --regid 65534 --clear-groups env HOME="$TMP/tmp" \
        TMPDIR="$TMP/tmp" "$RAYO" grade $NV --sandbox=require huge_png) \
        >"$TMP/out" 2>&1
    says '^output +FAIL +the program printed a 65536x16384 PNG' "unprivileged: huge PNG refused by its header"
else
    diag "not root or no setpriv: the unprivileged runs are skipped"
fi

done_testing
