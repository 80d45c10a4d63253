#!/bin/sh
# signals.t - every signal that ends rayo (SIGHUP, SIGALRM, SIGUSR1,
# SIGUSR2, SIGXCPU, SIGINT, SIGTERM) stops a render promptly, however
# slow its bands, removes the temporary file and ends the command with
# 128 + the signal (SIGXCPU without the core dump of its default
# action); the same for convert, whose handler removes the file
# itself (cli/output_guard.c); and a directory renamed mid-way loses the
# temporary file where it now is.
#
# The slow scene is legal and the slowest the limits allow per pixel:
# 4096 point lights inside a box of six mirrors, depth 64, 16 x 16
# samples, 65536 x 16 pixels.  One pixel takes seconds, one band
# minutes: a render that looked for the signal only between bands (or
# between pixels) would run on for minutes.  Each render is signalled
# half a second after its temporary file appears and must be gone within
# 3 seconds (the promise is one) on a machine with a processor to spare;
# on a busy one the bound grows with the load average per processor
# (load 12 on 2 processors: 18 s), which still fails a render that
# looks for the signal only between bands.  A render still running then
# is killed and the test fails.
#
# rayo is started through python3, which resets every signal tried here
# to its default first: a background job of a script starts with SIGINT
# ignored, a test run under nohup with SIGHUP ignored, and ignored
# signals are meant to stay ignored.
. "$(dirname "$0")/lib.sh"

leftovers() { find "$1" -name '.*.??????' | wc -l | tr -d ' '; }
entries() { find "$1" -mindepth 1 | wc -l | tr -d ' '; }
now_ms() { echo $(($(date +%s%N) / 1000000)); }

if ! command -v python3 >/dev/null 2>&1; then
    echo "1..0 # SKIP python3 is needed to start rayo with SIGINT at its default"
    exit 0
fi

# Under valgrind everything is tens of times slower; on a busy machine
# rayo's threads get a share of a processor.
bound_ms=3000
[ "${RAYO_VALGRIND:-0}" = 1 ] && bound_ms=60000
busy=$(awk -v n="$(nproc 2>/dev/null || echo 1)" \
    '{ b = $1 / n; print (b > 1 ? int(b * 1000) : 1000) }' /proc/loadavg 2>/dev/null)
bound_ms=$((bound_ms * ${busy:-1000} / 1000))

# start ARGS...: rayo ARGS in the background, every signal at its default
# action; its process id in $rayo_pid.
start() {
    if [ "${RAYO_VALGRIND:-0}" = 1 ]; then
        set -- valgrind -q --error-exitcode=99 --leak-check=full \
            --suppressions="$RAYO_SOURCE/tests/cli/valgrind.supp" \
            --show-leak-kinds=definite,indirect,possible \
            --errors-for-leak-kinds=definite,indirect,possible "$RAYO" "$@"
    else
        set -- "$RAYO" "$@"
    fi
    python3 -c 'import os, signal, sys
for s in (signal.SIGINT, signal.SIGQUIT, signal.SIGHUP, signal.SIGTERM,
          signal.SIGALRM, signal.SIGUSR1, signal.SIGUSR2, signal.SIGXCPU):
    signal.signal(s, signal.SIG_DFL)
os.execvp(sys.argv[1], sys.argv[1:])' "$@" &
    rayo_pid=$!
}

# wait_for_temp DIR: until a temporary file is in DIR (at most 20 s).
wait_for_temp() {
    tries=0
    while [ "$(leftovers "$1")" = 0 ] && [ "$tries" -lt 400 ] &&
        kill -0 "$rayo_pid" 2>/dev/null; do
        sleep 0.05
        tries=$((tries + 1))
    done
}

# stop_and_time SIGNAL: sends it to $rayo_pid and waits for the end:
# $elapsed (ms), $status; a command still running after the bound is
# killed (status 137).
stop_and_time() {
    kill -"$1" "$rayo_pid" 2>/dev/null
    sent=$(now_ms)
    while kill -0 "$rayo_pid" 2>/dev/null &&
        [ $(($(now_ms) - sent)) -lt "$bound_ms" ]; do
        sleep 0.02
    done
    elapsed=$(($(now_ms) - sent))
    kill -KILL "$rayo_pid" 2>/dev/null
    status=0
    wait "$rayo_pid" 2>/dev/null || status=$?
}

# The slow scene.
{
    echo "shade phong"
    echo "depth 64"
    echo "samples 16"
    echo "camera size 65536 16 fov 90 origin 0 0 0"
    echo "material mirror color 0.5 0.5 0.5 ka 0.1 kd 0.5 reflect 0.9"
    for p in "0 0 5  0 0 -1" "0 0 -5  0 0 1" "5 0 0  -1 0 0" \
        "-5 0 0  1 0 0" "0 5 0  0 -1 0" "0 -5 0  0 1 0"; do
        echo "plane $p material mirror"
    done
    awk 'BEGIN { for (i = 0; i < 4096; i++)
        printf "light point %g %g %g color 0.001\n", -4 + 8 * (i % 16) / 15,
            -4 + 8 * int(i / 16 % 16) / 15, -4 + 8 * int(i / 256) / 15 }'
} >"$TMP/slow.scene"
rayo render "$TMP/slow.scene" -W 1 -H 1 --samples 1 -o "$TMP/one.ppm"
is "$?" 0 "the slow scene is legal (one ray of it renders)"

mkdir "$TMP/d"
# render_signal SIGNAL NUMBER THREADS
render_signal() {
    printf 'precious\n' >"$TMP/d/slow.ppm"
    start render "$TMP/slow.scene" -q -j "$3" -o "$TMP/d/slow.ppm" \
        2>"$TMP/err"
    wait_for_temp "$TMP/d"
    sleep 0.5
    ok "$([ "$(leftovers "$TMP/d")" = 1 ]; echo $?)" \
        "SIG$1, -j $3: the render is writing its temporary file"
    stop_and_time "$1"
    is "$status" $((128 + $2)) "SIG$1, -j $3: ends with 128 + $2"
    ok "$([ "$elapsed" -lt "$bound_ms" ]; echo $?)" \
        "SIG$1, -j $3: within ${bound_ms} ms of the signal ($elapsed ms)"
    is "$(leftovers "$TMP/d")" 0 "SIG$1, -j $3: the temporary file is removed"
    is "$(cat "$TMP/d/slow.ppm")" precious "SIG$1, -j $3: the earlier file is intact"
    is "$(wc -c <"$TMP/err" | tr -d ' ')" 0 "SIG$1, -j $3: no message"
    # A render killed past the bound leaves its file: gone before the
    # next, so that one failure is reported once, not by every case after.
    find "$TMP/d" -name '.*.??????' -exec rm -f {} +
}
render_signal HUP 1 2
render_signal ALRM 14 2
render_signal USR1 10 2
render_signal USR2 12 2
render_signal XCPU 24 2
render_signal INT 2 2
render_signal TERM 15 2
render_signal TERM 15 1
render_signal INT 2 4

# SIGXCPU's default action dumps core: rayo turns that off before it
# dies of it.  Tried with core files allowed, in a folder of its own
# (where a core file would land), when the kernel writes plain files.
if [ "$(cat /proc/sys/kernel/core_pattern 2>/dev/null)" = core ] &&
    (ulimit -c unlimited) 2>/dev/null; then
    mkdir "$TMP/cwd"
    (
        cd "$TMP/cwd" && ulimit -c unlimited
        start render "$TMP/slow.scene" -q -o "$TMP/cwd/slow.ppm" 2>/dev/null
        wait_for_temp "$TMP/cwd"
        stop_and_time XCPU
        echo "$status" >"$TMP/xcpu.status"
    )
    is "$(cat "$TMP/xcpu.status")" 152 "SIGXCPU with core files allowed: ends with 152"
    is "$(entries "$TMP/cwd")" 0 "SIGXCPU: no core file, no temporary file"
else
    ok 1 "# SKIP core files go elsewhere (core_pattern) or are not allowed"
    ok 1 "# SKIP core files go elsewhere (core_pattern) or are not allowed"
fi

# The output's directory renamed mid-render, then the signal: the
# temporary file is removed where the directory now is.
mkdir "$TMP/before"
start render "$TMP/slow.scene" -q -o "$TMP/before/slow.ppm" 2>"$TMP/err"
wait_for_temp "$TMP/before"
mv "$TMP/before" "$TMP/after"
sleep 0.3
stop_and_time TERM
is "$status" 143 "renamed directory: the render ends with 143"
ok "$([ "$elapsed" -lt "$bound_ms" ]; echo $?)" \
    "renamed directory: within ${bound_ms} ms ($elapsed ms)"
is "$(entries "$TMP/after")" 0 "renamed directory: the temporary file is removed there"
ok "$([ ! -e "$TMP/before" ]; echo $?)" "renamed directory: nothing at the old name"

# convert writes an image already in memory: its handler removes the
# temporary file (cli/output_guard.c).  It is stopped as soon as its
# temporary file appears, signalled and continued, so the signal lands
# mid-write.
{ printf 'P5\n3000 3000\n255\n'; head -c 9000000 /dev/urandom; } >"$TMP/n9.pgm"
# convert_signal SIGNAL NUMBER DIRECTORY [RENAMED]
convert_signal() {
    mkdir -p "$TMP/$3"
    printf 'precious\n' >"$TMP/$3/c.png"
    start convert "$TMP/n9.pgm" "$TMP/$3/c.png" 2>"$TMP/err"
    tries=0
    while [ "$(leftovers "$TMP/$3")" = 0 ] && [ "$tries" -lt 20000 ]; do
        tries=$((tries + 1))
    done
    kill -STOP "$rayo_pid" 2>/dev/null
    ok "$([ "$(leftovers "$TMP/$3")" = 1 ]; echo $?)" \
        "convert, SIG$1: caught while writing its temporary file"
    where=$3
    if [ $# -gt 3 ]; then
        mv "$TMP/$3" "$TMP/$4"
        where=$4
    fi
    kill -"$1" "$rayo_pid" 2>/dev/null
    kill -CONT "$rayo_pid" 2>/dev/null
    status=0
    wait "$rayo_pid" 2>/dev/null || status=$?
    is "$status" $((128 + $2)) "convert, SIG$1: ends with 128 + $2"
    is "$(leftovers "$TMP/$where")" 0 "convert, SIG$1: the temporary file is removed${4:+ from the renamed directory}"
    is "$(cat "$TMP/$where/c.png")" precious "convert, SIG$1: the earlier file is intact"
}
convert_signal HUP 1 c
convert_signal ALRM 14 c
convert_signal USR1 10 c
convert_signal USR2 12 c
convert_signal XCPU 24 c
convert_signal INT 2 c
convert_signal TERM 15 c2 c2-renamed
done_testing
