#!/bin/sh
# progress.t - the progress bar `rayo render` draws on standard error
# (cli/progress.c): only on a terminal, only after the first second, never
# with --quiet or -q, never over an image that goes to the terminal
# itself; one line "rayo: [###...] NN%  R/T rows  S.S s" redrawn in place,
# percentages that never go down, and erased ("\r", blanks, "\r") when
# the render ends or is stopped by SIGINT, so nothing is left on screen.
# The image is the same bytes with or without the bar.
#
# The terminal is a pseudo-terminal from script(1) (util-linux); without
# one the test is skipped.  The slow renders (examples/room.scene, 4x4
# samples, one thread) are sized here, by timing smaller ones, to take
# about two seconds on this machine, under valgrind (make check-valgrind)
# and the sanitizers too.
. "$(dirname "$0")/lib.sh"
export RAYO RAYO_SOURCE
LIB="$(cd "$(dirname "$0")" && pwd)/lib.sh"
SCENE="$RAYO_SOURCE/examples/room.scene"

if ! command -v script >/dev/null 2>&1 ||
    ! SHELL=/bin/sh script -qec 'test -t 0 && test -t 1 && test -t 2' \
        /dev/null </dev/null >/dev/null 2>&1; then
    echo "1..0 # SKIP no pseudo-terminal: script(1) from util-linux is missing or fails"
    exit 0
fi

now_ms() { echo $(($(date +%s%N) / 1000000)); }

q() { # q WORD: WORD quoted for sh
    printf "'%s'" "$(printf '%s' "$1" | sed "s/'/'\\\\''/g")"
}

skip() { # skip REASON: a test that cannot tell here
    tap_n=$((tap_n + 1))
    echo "ok $tap_n # SKIP $1"
}

# tty_command REDIRECTIONS ARGS...: a shell command that runs `rayo ARGS
# REDIRECTIONS` as the other tests do (lib.sh: under valgrind with
# RAYO_VALGRIND=1), writes its process id to $TMP/pid and waits for it.
tty_command() {
    redirections=$1
    shift
    cmd=". $(q "$LIB") && rayo_start"
    for arg in "$@"; do
        cmd="$cmd $(q "$arg")"
    done
    # shellcheck disable=SC2016 # $rayo_pid is the inner shell's
    printf '%s %s && echo "$rayo_pid" >%s && wait "$rayo_pid"' \
        "$cmd" "$redirections" "$(q "$TMP/pid")"
}

# on_tty NAME REDIRECTIONS ARGS...: `rayo ARGS` with standard input,
# output and error on a pseudo-terminal, except as REDIRECTIONS (shell
# syntax) say.  What the terminal showed lands in $TMP/NAME.tty, the exit
# status in $status, the milliseconds it took in $ms.
on_tty() {
    name=$1
    shift
    cmd=$(tty_command "$@")
    start=$(now_ms)
    status=0
    SHELL=/bin/sh script -qec "$cmd" /dev/null </dev/null \
        >"$TMP/$name.tty" 2>&1 || status=$?
    ms=$(($(now_ms) - start))
}

# --- timing: the size of a render of about two seconds --------------
# A render's time, less that of a 4x3 one (start-up: script, valgrind,
# the scene), is its rendering time, which the bar's delay counts.  The
# slow renders are W x H = 4S x 3S pixels: the same picture at any S, so
# their time grows as S squared.
slow_size() { W=$((4 * $1)) H=$((3 * $1)); }
on_tty base '>/dev/null' render "$SCENE" -W 4 -H 3 --samples 4 -j 1 -q
base=$ms
size=8
while :; do
    slow_size "$size"
    on_tty probe '>/dev/null' render "$SCENE" -W "$W" -H "$H" --samples 4 -j 1 -q
    work=$((ms - base))
    if [ "$work" -ge 400 ] || [ "$size" -ge 4096 ]; then break; fi
    size=$((size * 2))
done
# scale_size MS: $size times the square root of 1800 / MS
scale_size() {
    size=$(awk -v s="$size" -v ms="$1" 'BEGIN {
        s = int(s * sqrt(1800 / (ms < 1 ? 1 : ms)) + 0.5)
        print (s < 8 ? 8 : s > 8192 ? 8192 : s) }')
    slow_size "$size"
}
scale_size "$work"
diag "start-up $base ms; $W x $H pixels should take about 1.8 s"

# check_bars NAME ROWS: what the terminal showed in $TMP/NAME.tty is one
# or more bar lines for a ROWS-row render, each of the documented shape
# and at most 79 columns, percentages, rows and seconds never going down,
# the seconds at least the one-second delay, then the erase sequence.
check_bars() {
    name=$1 total=$2
    tr '\r' '\n' <"$TMP/$name.tty" | awk -v total="$total" '
        BEGIN { n = 0; shape = "none"; order = "none" }
        $0 == "" { next }
        $0 ~ /^ +$/ && length($0) == 79 { next }
        {
            bar = substr($2, 2, length($2) - 2)
            hashes = bar; gsub(/[^#]/, "", hashes)
            split($4, r, "/")
            want = sprintf("rayo: [%s] %3d%%  %d/%d rows  %.1f s", bar,
                           int(r[1] * 100 / total), r[1], total, $6)
            if ($0 != want || length($0) > 79 || length(bar) != 30 ||
                bar !~ /^#*\.*$/ || length(hashes) != int(r[1] * 30 / total) ||
                $6 < 1.0) {
                if (shape == "none") shape = $0
                next
            }
            if (n > 0 && ($3 + 0 < pct || r[1] + 0 < done || $6 + 0 < secs) &&
                order == "none")
                order = last " then " $0
            pct = $3 + 0; done = r[1] + 0; secs = $6 + 0; last = $0; n++
        }
        END { print n; print shape; print order }' >"$TMP/$name.bars"
    bars=$(sed -n 1p "$TMP/$name.bars")
    ok "$([ "$bars" -ge 1 ]; echo $?)" "$name: a bar is drawn"
    diag "$name: $bars bar lines"
    is "$(sed -n 2p "$TMP/$name.bars")" none \
        "$name: only bar lines of the documented shape, within 79 columns, and erasing blanks"
    is "$(sed -n 3p "$TMP/$name.bars")" none \
        "$name: percentages, rows and seconds never go down"
    printf '\r%79s\r' '' >"$TMP/erase"
    tail -c 81 "$TMP/$name.tty" | cmp -s - "$TMP/erase"
    ok $? "$name: it ends erased (CR, 79 blanks, CR): no bar left on screen"
}

# long_enough WHAT: whether the last render took long enough for a bar
# to be due (1.2 s), so that its absence means something; if not, a
# skipped test says so.
long_enough() {
    [ $((ms - base)) -ge 1200 ] && return 0
    skip "$1: the render took $((ms - base)) ms, too little to tell"
    return 1
}

# --- a slow render, stderr on a terminal: the bar -------------------
# The image goes to a file through stdout.  Rendered again, larger, if it
# took less than 1.3 s (a bar or two at most: the machine turned out
# quicker than timed).
tries=0
while :; do
    on_tty slow ">$(q "$TMP/slow.ppm")" \
        render "$SCENE" -W "$W" -H "$H" --samples 4 -j 1
    work=$((ms - base))
    if [ "$work" -ge 1300 ] || [ "$tries" -ge 2 ]; then break; fi
    scale_size "$work"
    diag "the render took $work ms; again, $W x $H"
    tries=$((tries + 1))
done
diag "slow render: $W x $H, $ms ms"
is "$status" 0 "slow render on a terminal: exit status 0"
check_bars slow "$H"

# --- the same with stderr to a file: no bar, the same image ---------
# (Standard input and output are still the terminal, which stays the
# controlling one: only stderr decides.)
on_tty notty ">$(q "$TMP/notty.ppm") 2>$(q "$TMP/notty.err")" \
    render "$SCENE" -W "$W" -H "$H" --samples 4 -j 1
is "$status" 0 "stderr to a file: exit status 0"
long_enough "stderr to a file" &&
    is "$(wc -c <"$TMP/notty.tty" | tr -d ' ')" 0 "stderr to a file: nothing on the terminal"
is "$(wc -c <"$TMP/notty.err" | tr -d ' ')" 0 "stderr to a file: nothing on stderr"
cmp -s "$TMP/slow.ppm" "$TMP/notty.ppm"
ok $? "the image rendered with the bar is byte-identical to the one without"

# --- --quiet and -q: no bar -----------------------------------------
for opt in --quiet -q; do
    on_tty "quiet$opt" ">$(q "$TMP/quiet.ppm")" \
        render "$SCENE" -W "$W" -H "$H" --samples 4 -j 1 "$opt"
    is "$status" 0 "$opt on a terminal: exit status 0"
    long_enough "$opt on a terminal" &&
        is "$(wc -c <"$TMP/quiet$opt.tty" | tr -d ' ')" 0 "$opt on a terminal: nothing on it"
    cmp -s "$TMP/notty.ppm" "$TMP/quiet.ppm"
    ok $? "$opt: the same image"
done

# --- the image on standard output, a terminal: its picture ----------
# (as `rayo view` draws it, after the bar is erased) and one line on how
# to save it, never the image's own text.
on_tty tty-image '' render "$SCENE" -W "$W" -H "$H" --samples 4 -j 1
is "$status" 0 "image to the terminal: exit status 0"
tr -d '\r' <"$TMP/tty-image.tty" | grep -c '^P3' >/dev/null
is "$?" 1 "image to the terminal: not its PPM text"
tr '\r' '\n' <"$TMP/tty-image.tty" | grep -Fxq "rayo: this is a picture of the image, because standard output is a terminal; to save it, use 'rayo > esfera.pbm' or 'rayo -o esfera.png'"
ok $? "image to the terminal: one line on how to save it"

# The same through -o /dev/tty, standard output elsewhere.
on_tty dev-tty '>/dev/null' render "$SCENE" -W "$W" -H "$H" --samples 4 -j 1 \
    -o /dev/tty
is "$status" 0 "image to /dev/tty: exit status 0"
long_enough "image to /dev/tty" &&
    is "$(grep -c 'rayo:' "$TMP/dev-tty.tty")" 0 "image to /dev/tty: no bar amid it"
tr -d '\r' <"$TMP/dev-tty.tty" | cmp -s - "$TMP/notty.ppm"
ok $? "image to /dev/tty: exactly the image's text"

# --- a quick render: none (the bar waits a second) ------------------
on_tty seed ">$(q "$TMP/seed.pbm")"
is "$status" 0 "the assignment on a terminal: exit status 0"
is "$(wc -c <"$TMP/seed.tty" | tr -d ' ')" 0 "the assignment (a quick render): nothing on the terminal"
is "$(head -c 2 "$TMP/seed.pbm")" P1 "the assignment: its image on stdout"

# --- SIGINT while the bar is drawn: the line erased, no file --------
# Twice the size (four times the time, about 7 s): the render is stopped
# once the bar shows, after a second, so it only has to outlast that even
# when the machine is quicker now than it was when timed (a busy machine
# at the timing, a quiet one here, left it a finished render and no bar).
mkdir "$TMP/d"
rm -f "$TMP/pid"
slow_size $((2 * size))
cmd=$(tty_command '' \
    render "$SCENE" -W "$W" -H "$H" --samples 4 -j 1 -o "$TMP/d/int.ppm")
SHELL=/bin/sh script -qec "$cmd" /dev/null </dev/null >"$TMP/sigint.tty" 2>&1 &
script_pid=$!
tries=0
until grep -q 'rayo: \[' "$TMP/sigint.tty" || ! kill -0 "$script_pid" 2>/dev/null ||
    [ "$tries" -ge 3000 ]; do
    sleep 0.05
    tries=$((tries + 1))
done
grep -q 'rayo: \[' "$TMP/sigint.tty" && kill -INT "$(cat "$TMP/pid")" 2>/dev/null
ok $? "SIGINT: sent once a bar was on the terminal"
status=0
wait "$script_pid" || status=$?
is "$status" 130 "SIGINT: the command dies of the signal (status 130)"
check_bars sigint "$H"
is "$(find "$TMP/d" -type f | wc -l | tr -d ' ')" 0 "SIGINT: no output or temporary file left"

done_testing
