#!/bin/sh
# render_output.t - output files appear whole or not at all; I/O failures
# name the file and the system's reason (exit 1); devices and pipes are
# written directly; a closed pipe ends the command quietly.
. "$(dirname "$0")/lib.sh"

leftovers() { find "$1" -name '.*.??????' | wc -l | tr -d ' '; }

mkdir "$TMP/d"
run_capture -o "$TMP/d/out.pbm"
is "$status" 0 "writing a new file: exit 0"
is "$(head -c 2 "$TMP/d/out.pbm")" "P1" "the file is complete"
is "$(stat -c %a "$TMP/d/out.pbm")" "$(umask -S >/dev/null; printf '%o' $((0666 & ~$(umask))))" "a new file gets 0666 less the umask"
is "$(leftovers "$TMP/d")" 0 "no temporary file left"

printf 'precious\n' >"$TMP/d/keep.pbm"
chmod 640 "$TMP/d/keep.pbm"
run_capture -o "$TMP/d/keep.pbm"
is "$(stat -c %a "$TMP/d/keep.pbm")" 640 "replacing a file keeps its mode"

printf 'precious\n' >"$TMP/d/keep.pbm"
status=0
(ulimit -f 64; rayo -o "$TMP/d/keep.pbm" 2>"$TMP/err") || status=$?
is "$status" 1 "file size limit reached mid-write: exit 1"
grep -q "keep.pbm: File too large" "$TMP/err"
ok $? "the message names the file and the reason"
is "$(cat "$TMP/d/keep.pbm")" "precious" "the earlier file is intact"
is "$(leftovers "$TMP/d")" 0 "the partial temporary file is removed"

run_capture -o /dev/full
is "$status" 1 "-o /dev/full: exit 1"
is "$(cat "$TMP/err")" "rayo: /dev/full: No space left on device" "-o /dev/full: file and reason"
ok "$([ -c /dev/full ]; echo $?)" "/dev/full is still a device"

run_capture -o "$TMP/no/such/dir/out.pbm"
is "$status" 1 "missing directory: exit 1"
grep -q "out.pbm: No such file or directory" "$TMP/err"
ok $? "missing directory: file and reason"
is "$(wc -l <"$TMP/err" | tr -d ' ')" 1 "missing directory: one line"

run_capture -o "$TMP/d"
is "$status" 1 "a directory as output: exit 1"
grep -q "Is a directory" "$TMP/err"
ok $? "a directory as output: reason"

if [ "$(id -u)" != 0 ]; then
    mkdir "$TMP/ro" && chmod 555 "$TMP/ro"
    run_capture -o "$TMP/ro/out.pbm"
    is "$status" 1 "read-only directory: exit 1"
else
    ok 0 "read-only directory: skipped as root # SKIP root ignores permissions"
fi

run_capture -o /dev/null
is "$status" 0 "-o /dev/null: exit 0"
ok "$([ -c /dev/null ]; echo $?)" "/dev/null is still a device"

mkfifo "$TMP/fifo"
cat "$TMP/fifo" >"$TMP/from-fifo" &
rayo -o "$TMP/fifo.pbm" >/dev/null 2>&1
rayo --format pbm -o "$TMP/fifo"
wait
cmp -s "$TMP/from-fifo" "$TMP/fifo.pbm"
ok $? "a named pipe is written directly"
ok "$([ -p "$TMP/fifo" ]; echo $?)" "the named pipe is still a pipe"

ln -s "$TMP/d/target.pbm" "$TMP/d/link.pbm"
printf 'old\n' >"$TMP/d/target.pbm"
rayo -W 8 -H 2 -o "$TMP/d/link.pbm"
ok "$([ -L "$TMP/d/link.pbm" ]; echo $?)" "a symbolic link stays a link"
is "$(head -c 2 "$TMP/d/target.pbm")" "P1" "its target is replaced"

# A reader that goes away: no message.
rayo -W 4000 -H 4000 2>"$TMP/err" | head -c 10 >"$TMP/head"
is "$(cat "$TMP/head")" "P1
4000 40" "the reader got the first bytes"
is "$(wc -c <"$TMP/err" | tr -d ' ')" 0 "a closed pipe ends quietly"
done_testing
