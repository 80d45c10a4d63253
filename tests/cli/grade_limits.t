#!/bin/sh
# grade_limits.t - `rayo grade` against submissions that try to exhaust
# the machine rather than escape it (tests/grade/hostile/include_zero,
# include_urandom, huge_array, fork_memory): each grade ends, fails the
# step it attacked as what it is, and the machine's available memory
# and the temporary folder's free disk never drop by more than the
# limit plus a margin.  A watchdog polls them, and the resident memory
# of the grade's own tree of processes, while each grade runs and kills
# it (failing the test) otherwise, so that a regression cannot take the
# test machine down.  As root (a cgroup per run where the
# machine has one), as an unprivileged user (setpriv, where possible),
# and --each -j 2 over two of them; and without a cgroup
# (RAYO_GRADE_NO_CGROUP=1), as root and as uid 65534, where the
# per-process limits' product bounds the tree.  Not a test of speed: the times
# below are ceilings far above what a grade takes.
. "${RAYO_SOURCE:-.}/tests/cli/lib.sh"

H="$RAYO_SOURCE/tests/grade/hostile"
RAYO_CC=${RAYO_CC:-cc}
export CC="${RAYO_CC%% *}"
chmod 755 "$TMP"
mkdir "$TMP/tmp"
chmod 1777 "$TMP/tmp"
# The grade's own tree is measured exactly (its resident memory, within
# TREE_MARGIN_MIB of the limit: bwrap, shells, shared pages counted
# again); MemAvailable is the backstop for memory no process holds (a
# tmpfs, the kernel's), with a wide margin: on a shared machine other
# work moves it by gigabytes (seen: 2.5 GiB in a few seconds).  A
# regression (20 children of 700 MB: 14 GB) trips both.
MARGIN_MIB=${RAYO_TEST_MEM_MARGIN_MIB:-3072}
TREE_MARGIN_MIB=256
DISK_MARGIN_MIB=1024 # the compile's outputs are bounded at 64 MiB each
CEILING=90           # seconds: every grade here ends far sooner

avail_kb() {
    while read -r key value unit; do
        if [ "$key" = MemAvailable: ]; then
            echo "$value"
            return
        fi
    done </proc/meminfo
    echo 0
}
disk_kb() { df -Pk "$TMP/tmp" | awk 'NR == 2 { print $4 }'; }
# tree_kb PID: the resident memory of PID and all its descendants (in
# their own sessions and PID namespaces too, as the host sees them).
tree_kb() {
    ps -e -o pid= -o ppid= -o rss= | awk -v root="$1" '
        { parent[$1] = $2; rss[$1] = $3 }
        END {
            for (p in parent) {
                q = p
                for (depth = 0; depth < 64 && q != "" && q != root && q > 1; depth++)
                    q = parent[q]
                if (q == root)
                    sum += rss[p]
            }
            print sum + 0
        }'
}

# guarded LIMIT_MIB COMMAND...: runs COMMAND (its output in $TMP/out,
# its status in $status) in a session of its own while the watchdog
# polls; $killed says why the watchdog killed it ("" when it did not).
guarded() {
    limit_kb=$((($1 + MARGIN_MIB) * 1024))
    tree_limit_kb=$((($1 + TREE_MARGIN_MIB) * 1024))
    shift
    mem0=$(avail_kb)
    disk0=$(disk_kb)
    killed=""
    ticks=0
    setsid "$@" >"$TMP/out" 2>"$TMP/err" &
    pid=$!
    while kill -0 "$pid" 2>/dev/null; do
        drop=$((mem0 - $(avail_kb)))
        disk_drop=$((disk0 - $(disk_kb)))
        tree=$(tree_kb "$pid")
        if [ "$tree" -gt "$tree_limit_kb" ]; then
            killed="memory: its processes hold $((tree / 1024)) MiB"
        elif [ "$drop" -gt "$limit_kb" ]; then
            killed="memory: MemAvailable dropped by $((drop / 1024)) MiB"
        elif [ "$disk_drop" -gt $((DISK_MARGIN_MIB * 1024)) ]; then
            killed="disk: $((disk_drop / 1024)) MiB written"
        elif [ "$ticks" -gt $((CEILING * 5)) ]; then
            killed="time: still running after $CEILING s"
        fi
        if [ -n "$killed" ]; then
            kill -9 "-$pid" 2>/dev/null
            kill -9 "$pid" 2>/dev/null
            break
        fi
        ticks=$((ticks + 1))
        sleep 0.2
    done
    status=0
    wait "$pid" || status=$?
}

# held NAME: the watchdog did not have to step in.
held() {
    is "$killed" "" "$1: memory and disk held, and it ended"
}
says() {
    found=0
    grep -Eq -- "$1" "$TMP/out" || found=1
    ok "$found" "$2"
    [ "$found" -eq 0 ] || sed 's/^/#   /' "$TMP/out" "$TMP/err" 2>/dev/null
}

if ! "$RAYO" grade --sandbox=require --check >"$TMP/out" 2>&1; then
    diag "no sandbox can be made here: $(cat "$TMP/out")"
    sandbox=0
else
    sandbox=1
fi
cgroup=0
grep -Eq '; limits: cgroup v[12] on the whole tree' "$TMP/out" && cgroup=1
says '; limits: (cgroup v[12] on the whole tree \([0-9]+ MiB memory, [0-9]+ processes\)|per process only)' \
    "--check: the first line says which limits hold"
[ "$cgroup" = 1 ] || diag "no cgroup can be made here: the tree's limits are not tested as such"

# The grade, with its temporary folder in $TMP/tmp (a command, not a
# function: the watchdog starts it with setsid).
G="env TMPDIR=$TMP/tmp $RAYO grade"

# ---- the compiler ----
if [ "$sandbox" = 1 ]; then
    for device in zero urandom; do
        guarded 256 $G --no-valgrind --memory 256 "$H/include_$device"
        held "#include /dev/$device"
        is "$status" 1 "#include /dev/$device: graded, failed"
        says "^compile +FAIL +it includes a device \\(/dev/$device\\): the compiler sees no device but /dev/null" \
            "#include /dev/$device: named as what it is"
    done
fi
# Without the sandbox the device is there: the limits alone stop it.
guarded 256 $G --no-valgrind --sandbox=off --memory 256 "$H/include_zero"
held "#include /dev/zero, no sandbox"
# gcc reads the device until the limit stops it; clang takes a device
# for an empty file, and the program compiles.
case $(basename "$CC") in
clang*)
    says '^compile +pass' "#include /dev/zero, no sandbox: clang reads it as empty" ;;
*)
    says '^compile +FAIL +memory limit exceeded: the compiler used more than 256 MiB' \
        "#include /dev/zero, no sandbox: the memory limit named" ;;
esac
guarded 256 $G --no-valgrind --sandbox=off --memory 256 "$H/include_urandom"
held "#include /dev/urandom, no sandbox"
case $(basename "$CC") in
clang*)
    says '^compile +pass' "#include /dev/urandom, no sandbox: clang reads it as empty" ;;
*)
    says '^compile +FAIL +(memory|CPU time) limit exceeded: the compiler' \
        "#include /dev/urandom, no sandbox: the limit named" ;;
esac

for mode in auto off; do
    guarded 256 $G --no-valgrind --sandbox=$mode --memory 256 "$H/huge_array"
    held "huge array ($mode)"
    says '^compile +FAIL +disk limit exceeded: the compiler.s output grew past 64 MiB' \
        "huge array ($mode): the disk limit named"
    is "$(find "$TMP/tmp" -mindepth 1 | wc -l | tr -d ' ')" 0 \
        "huge array ($mode): nothing left in the temporary folder"
done

# ---- the devices the program keeps ----
if [ "$sandbox" = 1 ]; then
    cat >"$TMP/devices.c" <<'EOF_C'
#include <stdio.h>

int main(void)
{
    static const char *const kept[] = {"/dev/null", "/dev/zero", "/dev/full",
                                       "/dev/random", "/dev/urandom"};
    unsigned i;
    int c;
    for (i = 0; i < 5; i++) {
        FILE *f = fopen(kept[i], "r");
        if (f == NULL)
            return 10 + (int)i;
        c = fgetc(f);
        fclose(f);
        if (i == 1 && c != 0)
            return 20;
    }
    if (fopen("/dev/tty", "r") != NULL || fopen("/dev/sda", "r") != NULL)
        return 30;
    return 0;
}
EOF_C
    guarded 256 $G --no-valgrind --memory 256 "$TMP/devices.c"
    held "devices"
    says '^run +pass ' "devices: the program opens null, zero, full, random and urandom, and no other"
fi

# ---- the program: 20 children of 700 MB each ----
if [ "$cgroup" = 1 ]; then
    guarded 1024 $G --no-valgrind --memory 1024 --timeout 20 "$H/fork_memory"
    held "fork memory"
    says '^run +FAIL +memory limit exceeded: its processes together used more than 1024 MiB' \
        "fork memory: the tree's memory limit named"
    is "$(find /sys/fs/cgroup -maxdepth 8 -name "rayo-$pid-*" 2>/dev/null | wc -l | tr -d ' ')" 0 \
        "fork memory: the run's cgroups are removed"
fi
guarded 256 $G --no-valgrind --memory 256 --timeout 5 "$H/fork_memory"
held "fork memory, 256 MiB"
says '^run +FAIL ' "fork memory, 256 MiB: the run fails"

# ---- a class, two at a time ----
mkdir "$TMP/class" "$TMP/class/ana" "$TMP/class/beto"
cp "$H/fork_memory/main.c" "$TMP/class/ana/"
cp "$H/include_zero/main.c" "$TMP/class/beto/"
guarded 2048 $G --no-valgrind --memory 1024 --timeout 10 --each -j 2 "$TMP/class"
held "--each -j 2"
is "$status" 1 "--each -j 2: graded, none passed"
says '^0 of 2 submissions passed$' "--each -j 2: both graded, both failed"

# ---- without a cgroup (RAYO_GRADE_NO_CGROUP=1: as on a machine whose
# cgroups are read-only, or a user's without delegation) ----
# forked_at_most N: the program's "forked K" (quoted from its standard
# error) says it made between 1 and N children.
forked_at_most() {
    forked=$(sed -n 's/^ *forked \([0-9]*\)$/\1/p' "$TMP/out" | head -n 1)
    [ -n "$forked" ] && [ "$forked" -ge 1 ] && [ "$forked" -le "$1" ]
    ok $? "$2 (forked ${forked:-?})"
}
# alone PREFIX WHO DIR: the fork bomb and the fork-memory bomb of DIR,
# under the per-process limits alone, run by PREFIX (empty, or setpriv).
alone() {
    A="env RAYO_GRADE_NO_CGROUP=1 TMPDIR=$TMP/tmp $1 $RAYO grade --no-valgrind"
    who=$2
    D=$3
    # 8 processes in the sandbox of 256 MiB each: 2 GiB at most.
    guarded 2048 $A --memory 256 --timeout 5 "$D/fork_bomb"
    held "$who, no cgroup: fork bomb"
    says "; limits: per process only, no cgroup here.* \\(256 MiB address space each, 8 processes in the sandbox: at most 2048 MiB in all" \
        "$who, no cgroup: the first line says the product bounds the tree"
    says '^run +FAIL +did not finish within 5 s' "$who, no cgroup: fork bomb stopped by the wall clock"
    forked_at_most 7 "$who, no cgroup: fork bomb: no more children than the sandbox's processes"
    # 6 processes of 1 GiB: 3 children of 700 MB fit, 2.1 GB; the
    # twenty of an unbounded tree would take 14 GB.
    guarded 6144 $A --memory 1024 --processes 6 --timeout 5 "$D/fork_memory"
    held "$who, no cgroup: fork memory"
    says "at most 6144 MiB in all" "$who, no cgroup: fork memory: 6 processes of 1024 MiB named"
    says '^run +FAIL ' "$who, no cgroup: fork memory fails"
    forked_at_most 5 "$who, no cgroup: fork memory: no more children than the sandbox's processes"
}
if [ "$sandbox" = 1 ]; then
    if [ "$(id -u)" = 0 ]; then
        alone "" root "$H"
        says '; the sandbox runs as a uid of its own' "root, no cgroup: the sandbox runs as a uid of its own"
        # (Zombies aside: they hold nothing, and a pid 1 that does not
        # reap keeps them.)
        is "$(ps -e -o uid= -o stat= | awk '$1 >= 1879048192 && $1 < 2147483648 && $2 !~ /^Z/' |
            wc -l | tr -d ' ')" 0 "root, no cgroup: no process of the grades' uids is left"
        # Two at once, each grade under a uid of its own: each tree is
        # bounded apart (6 GiB each at most; 2.1 GB and next to nothing).
        mkdir "$TMP/class_alone" "$TMP/class_alone/ana" "$TMP/class_alone/beto"
        cp "$H/fork_memory/main.c" "$TMP/class_alone/ana/"
        cp "$H/fork_bomb/main.c" "$TMP/class_alone/beto/"
        guarded 12288 env RAYO_GRADE_NO_CGROUP=1 $G --no-valgrind --memory 1024 --processes 6 \
            --timeout 5 --each -j 2 "$TMP/class_alone"
        held "root, no cgroup: --each -j 2"
        says '^0 of 2 submissions passed$' "root, no cgroup: --each -j 2: both graded, both failed"
        # That uid cannot read a folder of root's: the sources are
        # copied for it, and the report is the one the cgroup gives.
        mkdir "$TMP/private"
        cp "$RAYO_SOURCE/tests/grade/correct/main.c" "$TMP/private/"
        chmod 700 "$TMP/private"
        chmod 600 "$TMP/private/main.c"
        # (valgrind too: without a cgroup it has an address-space limit.)
        (cd "$TMP/private" && env TMPDIR="$TMP/tmp" "$RAYO" grade main.c) \
            >"$TMP/with" 2>&1
        status=0
        (cd "$TMP/private" && env RAYO_GRADE_NO_CGROUP=1 TMPDIR="$TMP/tmp" "$RAYO" grade \
            main.c) >"$TMP/out" 2>&1 || status=$?
        is "$status" 0 "root, no cgroup: a source only root can read is graded"
        is "$(sed -e 1d -e 's/ in [0-9.]* s / in N s /' "$TMP/out")" \
            "$(sed -e 1d -e 's/ in [0-9.]* s / in N s /' "$TMP/with")" \
            "root, no cgroup: the report is the one with a cgroup"
        is "$(find "$TMP/tmp" -mindepth 1 | wc -l | tr -d ' ')" 0 \
            "root, no cgroup: nothing left in the temporary folder"
    fi
    if [ "$(id -u)" = 0 ] && command -v setpriv >/dev/null 2>&1 &&
        setpriv --reuid 65534 --regid 65534 --clear-groups test -x "$RAYO"; then
        mkdir "$TMP/alone"
        cp -r "$H/fork_bomb" "$H/fork_memory" "$TMP/alone/"
        chmod -R a+rX "$TMP/alone"
        alone "setpriv --reuid 65534 --regid 65534 --clear-groups env HOME=$TMP/tmp" "uid 65534" "$TMP/alone"
    fi
fi

# ---- as an unprivileged user, where the machine allows ----
if [ "$(id -u)" = 0 ] && command -v setpriv >/dev/null 2>&1 &&
    setpriv --reuid 65534 --regid 65534 --clear-groups test -x "$RAYO"; then
    for h in include_zero huge_array fork_memory; do
        cp -r "$H/$h" "$TMP/"
        chmod -R a+rX "$TMP/$h"
    done
    NOBODY="setpriv --reuid 65534 --regid 65534 --clear-groups env HOME=$TMP/tmp TMPDIR=$TMP/tmp $RAYO grade"
    guarded 256 $NOBODY --no-valgrind --memory 256 "$TMP/include_zero"
    held "unprivileged: #include /dev/zero"
    says '^compile +FAIL +(it includes a device \(/dev/zero\)|memory limit exceeded)' \
        "unprivileged: #include /dev/zero named"
    guarded 256 $NOBODY --no-valgrind --memory 256 "$TMP/huge_array"
    held "unprivileged: huge array"
    says '^compile +FAIL +disk limit exceeded' "unprivileged: huge array named"
    guarded 256 $NOBODY --no-valgrind --memory 256 --timeout 5 "$TMP/fork_memory"
    held "unprivileged: fork memory"
    says '^run +FAIL ' "unprivileged: fork memory fails"
    says '; limits: ' "unprivileged: the first line says which limits hold"
else
    diag "not root or no setpriv: the unprivileged runs are skipped"
fi

done_testing
