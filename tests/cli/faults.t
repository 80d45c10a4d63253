#!/bin/sh
# faults.t - failures injected while rayo writes or reads, for convert,
# compare --diff and render (render_output.t covers render's own output
# cases: /dev/full, RLIMIT_FSIZE, missing or read-only directories, a
# closed pipe).  In every case: a clear one-line message naming the file
# and the system's reason, the documented exit status, no partial or
# temporary file left, and an earlier file of the same name intact.
#
# Injected: a full device (/dev/full), a file size limit reached mid-file
# (ulimit -f, RLIMIT_FSIZE), a full file system (a 64 KiB tmpfs, when
# mount is allowed), a read-only file system (the same tmpfs remounted
# read-only, which stops root too; or a chmod 555 folder for others), a
# reader of a pipe that goes away, SIGTERM and SIGINT during a render and
# during the writes of convert and compare --diff,
# an input that ends early (a FIFO), disappears (unlinked) or shrinks
# while it is read.
. "$(dirname "$0")/lib.sh"

leftovers() { find "$1" -name '.*.??????' | wc -l | tr -d ' '; }
one_line() { wc -l <"$1" | tr -d ' '; }

# Two 1000x1000 gray noise images (raw PGM, 1 MB each): incompressible,
# so every output made from them is large.
noise() { { printf 'P5\n1000 1000\n255\n'; head -c 1000000 /dev/urandom; } >"$1"; }
noise "$TMP/n1.pgm"
noise "$TMP/n2.pgm"
# n1 again: compare's diffs are made of two images that agree, so exit
# status 1 can only mean that the diff could not be written.
cp "$TMP/n1.pgm" "$TMP/same.pgm"
mkdir "$TMP/d"

# --- a full device ---------------------------------------------------
run_capture convert "$TMP/n1.pgm" /dev/full --format pgm
is "$status" 1 "convert to /dev/full: exit 1"
is "$(cat "$TMP/err")" "rayo: /dev/full: No space left on device" "convert to /dev/full: file and reason, one line"
run_capture compare "$TMP/n1.pgm" "$TMP/same.pgm" --diff /dev/full
is "$status" 1 "compare --diff /dev/full: exit 1"
is "$(cat "$TMP/err")" "rayo: /dev/full: No space left on device" "compare --diff /dev/full: file and reason, one line"
is "$(wc -c <"$TMP/out" | tr -d ' ')" 0 "compare --diff /dev/full: no report when the diff failed"

# --- a file size limit reached mid-file (RLIMIT_FSIZE) ----------------
limited() { # limited BLOCKS ARGS...: rayo under ulimit -f BLOCKS
    blocks=$1
    shift
    status=0
    (ulimit -f "$blocks"; rayo "$@") >"$TMP/out" 2>"$TMP/err" || status=$?
}
printf 'precious\n' >"$TMP/d/keep.pgm"
limited 64 convert "$TMP/n1.pgm" "$TMP/d/keep.pgm"
is "$status" 1 "convert, file size limit mid-file: exit 1"
is "$(cat "$TMP/err")" "rayo: $TMP/d/keep.pgm: File too large" "convert, file size limit: file and reason, one line"
is "$(cat "$TMP/d/keep.pgm")" "precious" "convert, file size limit: the earlier file is intact"
is "$(leftovers "$TMP/d")" 0 "convert, file size limit: no temporary file left"

printf 'precious\n' >"$TMP/d/diff.png"
limited 16 compare "$TMP/n1.pgm" "$TMP/same.pgm" --diff "$TMP/d/diff.png"
is "$status" 1 "compare --diff, file size limit mid-file: exit 1"
is "$(cat "$TMP/err")" "rayo: $TMP/d/diff.png: File too large" "compare --diff, file size limit: file and reason"
is "$(cat "$TMP/d/diff.png")" "precious" "compare --diff, file size limit: the earlier file is intact"
is "$(leftovers "$TMP/d")" 0 "compare --diff, file size limit: no temporary file left"

# --- a full file system, a read-only file system ---------------------
small="$TMP/small"
mkdir "$small"
mounted=0
if [ "$(id -u)" = 0 ] && mount -t tmpfs -o size=64k rayo-test "$small" 2>/dev/null; then
    mounted=1
    trap 'umount "$small" 2>/dev/null; rm -rf "$TMP"' EXIT
fi
if [ "$mounted" = 1 ]; then
    printf 'precious\n' >"$small/out.pgm"
    printf 'precious\n' >"$small/diff.png"
    printf 'precious\n' >"$small/r.pbm"
    used=$(df -k "$small" | awk 'NR == 2 { print $3 }')
    run_capture convert "$TMP/n1.pgm" "$small/out.pgm"
    is "$status" 1 "convert, file system full: exit 1"
    is "$(cat "$TMP/err")" "rayo: $small/out.pgm: No space left on device" "convert, file system full: file and reason"
    is "$(cat "$small/out.pgm")" "precious" "convert, file system full: the earlier file is intact"
    run_capture compare "$TMP/n1.pgm" "$TMP/same.pgm" --diff "$small/diff.png"
    is "$status" 1 "compare --diff, file system full: exit 1"
    is "$(cat "$TMP/err")" "rayo: $small/diff.png: No space left on device" "compare --diff, file system full: file and reason"
    is "$(cat "$small/diff.png")" "precious" "compare --diff, file system full: the earlier file is intact"
    run_capture render -W 1000 -H 1000 -o "$small/r.pbm"
    is "$status" 1 "render, file system full: exit 1"
    is "$(cat "$TMP/err")" "rayo: $small/r.pbm: No space left on device" "render, file system full: file and reason"
    is "$(cat "$small/r.pbm")" "precious" "render, file system full: the earlier file is intact"
    is "$(leftovers "$small")" 0 "file system full: no temporary file left"
    is "$(df -k "$small" | awk 'NR == 2 { print $3 }')" "$used" "file system full: the space is given back"
else
    for what in convert "compare --diff" render; do
        ok 0 "$what, file system full # SKIP cannot mount a small tmpfs here"
    done
fi

if [ "$mounted" = 1 ] && mount -o remount,ro "$small" 2>/dev/null; then
    ro="$small" reason="Read-only file system"
elif [ "$(id -u)" != 0 ]; then
    ro="$TMP/ro" reason="Permission denied"
    mkdir "$ro" && printf 'precious\n' >"$ro/out.pgm" &&
        printf 'precious\n' >"$ro/diff.png" && chmod 555 "$ro"
else
    ro=""
fi
if [ -n "$ro" ]; then
    run_capture convert "$TMP/n1.pgm" "$ro/out.pgm"
    is "$status" 1 "convert, read-only output folder: exit 1"
    grep -Eq "^rayo: $ro/[.]?out.pgm.*: $reason\$" "$TMP/err"
    ok $? "convert, read-only output folder: file and reason"
    is "$(one_line "$TMP/err")" 1 "convert, read-only output folder: one line"
    is "$(cat "$ro/out.pgm")" "precious" "convert, read-only output folder: the earlier file is intact"
    run_capture compare "$TMP/n1.pgm" "$TMP/same.pgm" --diff "$ro/diff.png"
    is "$status" 1 "compare --diff, read-only output folder: exit 1"
    grep -Eq "^rayo: $ro/[.]?diff.png.*: $reason\$" "$TMP/err"
    ok $? "compare --diff, read-only output folder: file and reason"
    is "$(cat "$ro/diff.png")" "precious" "compare --diff, read-only output folder: the earlier file is intact"
else
    for what in convert "compare --diff"; do
        ok 0 "$what, read-only output folder # SKIP root ignores permissions and no read-only mount is allowed"
    done
fi
if [ "$mounted" = 1 ]; then
    umount "$small"
    mounted=0
fi

# --- the reader of a pipe goes away ----------------------------------
{ rayo convert "$TMP/n1.pgm" - --format pgm 2>"$TMP/err"; echo $? >"$TMP/st"; } | head -c 10 >"$TMP/head"
is "$(head -c 2 "$TMP/head")" "P5" "convert to a pipe: the reader got the first bytes"
is "$(cat "$TMP/st")" 141 "convert to a closed pipe: ends by SIGPIPE, as cat does"
is "$(wc -c <"$TMP/err" | tr -d ' ')" 0 "convert to a closed pipe: no message"
{ rayo convert "$TMP/n1.pgm" - --format png 2>"$TMP/err"; echo $? >"$TMP/st"; } | head -c 8 >"$TMP/head"
is "$(od -An -c "$TMP/head" | tr -d ' ')" '211PNG\r\n032\n' "convert PNG to a pipe: the reader got the signature"
is "$(cat "$TMP/st")" 141 "convert PNG to a closed pipe: ends by SIGPIPE"
is "$(wc -c <"$TMP/err" | tr -d ' ')" 0 "convert PNG to a closed pipe: no message"

# --- a signal interrupts a long render -------------------------------
# The render stops at the next band, removes its temporary file and dies
# of the signal; the file it would have replaced is untouched.
interrupt() { # interrupt SIGNAL STATUS
    printf 'precious\n' >"$TMP/d/long.ppm"
    rayo_start render "$RAYO_SOURCE/examples/room.scene" -W 800 -H 600 \
        --samples 4 -j 1 -q -o "$TMP/d/long.ppm" 2>"$TMP/err"
    tries=0
    while [ "$(leftovers "$TMP/d")" = 0 ] && [ "$tries" -lt 1200 ]; do
        sleep 0.05
        tries=$((tries + 1))
    done
    kill -"$1" "$rayo_pid" 2>/dev/null
    ok $? "SIG$1: sent while the render was writing its temporary file"
    status=0
    wait "$rayo_pid" 2>/dev/null || status=$? # (no "Terminated" from sh)
    is "$status" "$2" "SIG$1: the command dies of the signal (status $2)"
    is "$(cat "$TMP/d/long.ppm")" "precious" "SIG$1: the earlier file is intact"
    is "$(leftovers "$TMP/d")" 0 "SIG$1: the temporary file is removed"
}
interrupt TERM 143
interrupt INT 130

# convert and compare --diff write an image already in memory: a signal
# during the write removes the temporary file (cli/output_guard.c).  The
# command is stopped as soon as its temporary file appears, signalled,
# and continued, so the signal always lands mid-write.  (SIGTERM only: a
# background job of a script starts with SIGINT ignored, and the guard
# leaves ignored signals ignored, as `nohup` expects.)
{ printf 'P5\n3000 3000\n255\n'; head -c 9000000 /dev/urandom; } >"$TMP/n9.pgm"
interrupt_write() { # interrupt_write SIGNAL STATUS NAME FILE ARGS...
    sig=$1 want=$2 what=$3 file=$4
    shift 4
    printf 'precious\n' >"$TMP/d/$file"
    rayo_start "$@" 2>"$TMP/err" >/dev/null
    tries=0
    while [ "$(leftovers "$TMP/d")" = 0 ] && [ "$tries" -lt 20000 ]; do
        tries=$((tries + 1))
    done
    kill -STOP "$rayo_pid" 2>/dev/null
    ok "$([ "$(leftovers "$TMP/d")" = 1 ]; echo $?)" "$what, SIG$sig: caught while writing its temporary file"
    kill -"$sig" "$rayo_pid" 2>/dev/null
    kill -CONT "$rayo_pid" 2>/dev/null
    status=0
    wait "$rayo_pid" 2>/dev/null || status=$?
    is "$status" "$want" "$what, SIG$sig: dies of the signal (status $want)"
    is "$(cat "$TMP/d/$file")" "precious" "$what, SIG$sig: the earlier file is intact"
    is "$(leftovers "$TMP/d")" 0 "$what, SIG$sig: the temporary file is removed"
}
interrupt_write TERM 143 convert c.png convert "$TMP/n9.pgm" "$TMP/d/c.png"
interrupt_write TERM 143 "compare --diff" diff.png compare "$TMP/n9.pgm" "$TMP/n1.pgm" --diff "$TMP/d/diff.png"

# --- the input ends early, disappears, or shrinks while it is read ---
printf 'precious\n' >"$TMP/d/keep.pgm"
mkfifo "$TMP/in.fifo"
{ printf 'P5\n1000 1000\n255\n'; head -c 5000 /dev/zero; } >"$TMP/in.fifo" &
run_capture convert "$TMP/in.fifo" "$TMP/d/keep.pgm"
wait
is "$status" 2 "input ends early (a FIFO): exit 2"
grep -q "^rayo: $TMP/in.fifo: byte [0-9]*: .*; expected" "$TMP/err"
ok $? "input ends early: the message names the input and the byte"
is "$(one_line "$TMP/err")" 1 "input ends early: one line"
is "$(cat "$TMP/d/keep.pgm")" "precious" "input ends early: the earlier output is intact"
is "$(leftovers "$TMP/d")" 0 "input ends early: no temporary file left"

run_capture convert "$TMP/no-such.pgm" "$TMP/d/keep.pgm"
is "$status" 2 "a missing input: exit 2 (an input that cannot be read)"
is "$(cat "$TMP/err")" "rayo: $TMP/no-such.pgm: No such file or directory" "a missing input: file and reason"
is "$(cat "$TMP/d/keep.pgm")" "precious" "a missing input: the earlier output is intact"

# 16 MB to read; the input is unlinked, or cut to 100000 bytes, while
# rayo holds it open (stopped with SIGSTOP once /proc shows it open).
{ printf 'P5\n4000 4000\n255\n'; head -c 16000000 /dev/urandom; } >"$TMP/big.pgm"
cp "$TMP/big.pgm" "$TMP/big-copy.pgm"
while_reading() { # while_reading ACTION: runs ACTION with rayo stopped
    rayo_start convert "$TMP/big.pgm" "$TMP/d/big.pgm" 2>"$TMP/err"
    tries=0
    until ls -l /proc/"$rayo_pid"/fd 2>/dev/null | grep -q "$TMP/big.pgm" ||
        [ "$tries" -ge 2000 ]; do
        tries=$((tries + 1))
    done
    kill -STOP "$rayo_pid" 2>/dev/null
    eval "$1"
    kill -CONT "$rayo_pid" 2>/dev/null
    status=0
    wait "$rayo_pid" || status=$?
}
printf 'precious\n' >"$TMP/d/big.pgm"
while_reading 'rm -f "$TMP/big.pgm"'
is "$status" 0 "input unlinked while read: the open file is read whole (exit 0)"
cmp -s "$TMP/d/big.pgm" "$TMP/big-copy.pgm"
ok $? "input unlinked while read: the output is complete"

cp "$TMP/big-copy.pgm" "$TMP/big.pgm"
printf 'precious\n' >"$TMP/d/big.pgm"
while_reading 'truncate -s 100000 "$TMP/big.pgm"'
if [ "$status" = 0 ]; then
    diag "the read finished before the input was cut"
    cmp -s "$TMP/d/big.pgm" "$TMP/big-copy.pgm"
    ok $? "input cut while read (too late): the output is the whole input"
    ok 0 "input cut while read: one line # SKIP the read finished first"
else
    is "$status" 2 "input cut while read: exit 2"
    grep -q "^rayo: $TMP/big.pgm: byte [0-9]*: .*; expected" "$TMP/err"
    ok $? "input cut while read: the message names the input and the byte"
    is "$(cat "$TMP/d/big.pgm")" "precious" "input cut while read: the earlier output is intact"
fi
is "$(leftovers "$TMP/d")" 0 "input cut while read: no temporary file left"
done_testing
