#!/bin/sh
# render_threads.t - the bytes `rayo render` writes do not depend on the
# thread count: -j1, -j2 and -j7 give identical P1, P4 and PNG files for
# odd sizes, several spheres, the span fast path and the per-pixel loop
# (--samples 2 takes the sampled loop; a camera on a sphere's surface
# makes the spans test every pixel), and rows wider than a pipe's buffer.
# Also: -j/--threads validation and --quiet.
. "$(dirname "$0")/lib.sh"

render_all() { # render_all NAME EXT ARGS...: -j1, -j2, -j7 into $TMP/NAME.jN.EXT
    name=$1 ext=$2
    shift 2
    for j in 1 2 7; do
        rayo render "$@" -j "$j" -o "$TMP/$name.j$j.$ext" 2>"$TMP/err"
        is "$?" 0 "$name: -j$j exits 0"
    done
    cmp -s "$TMP/$name.j1.$ext" "$TMP/$name.j2.$ext"
    ok $? "$name: -j1 and -j2 give the same bytes"
    cmp -s "$TMP/$name.j1.$ext" "$TMP/$name.j7.$ext"
    ok $? "$name: -j1 and -j7 give the same bytes"
}

two="--sphere 0.5,0.75,1.9,0.8 --sphere -1,-0.5,3,1.2"
# shellcheck disable=SC2086 # word splitting of $two is intended
{
    render_all seed-p1 pbm
    render_all odd-p1 pbm -W 333 -H 211 $two
    render_all odd-p4 pbm -W 1001 -H 97 --raw $two
    render_all odd-png png -W 997 -H 101 $two
    render_all tiny-p4 pbm -W 7 -H 3 --raw
    render_all tall-png png -W 9 -H 1001 --fov 30
    render_all surface-p4 pbm -W 257 -H 65 --raw --sphere 0,0,2,2
    render_all sampled-p4 pbm -W 211 -H 67 --raw --samples 2 $two
}

# The files are what they claim to be, per the Netpbm tools.
is "$(pamfile "$TMP/odd-p4.j7.pbm" | sed 's/.*:[[:space:]]*//')" \
    "PBM raw, 1001 by 97" "pamfile reads the -j7 P4"
pngtopnm "$TMP/odd-png.j7.png" >"$TMP/png.pbm" 2>/dev/null &&
    rayo render -W 997 -H 101 --sphere 0.5,0.75,1.9,0.8 \
        --sphere -1,-0.5,3,1.2 --raw -j 1 -o "$TMP/same.pbm" &&
    cmp -s "$TMP/png.pbm" "$TMP/same.pbm"
ok $? "the -j7 PNG holds the pixels of the -j1 P4"

# The spans and the sampled loop agree where one sample is the centre:
# at --samples 1 both must equal the plain per-pixel loop's awk reference
# in render_basics.t; here, that P1 and P4 carry the same pixels.
pnmtoplainpnm "$TMP/odd-p4.j1.pbm" | tail -n +3 | tr -d ' \n' >"$TMP/a"
rayo render -W 1001 -H 97 --sphere 0.5,0.75,1.9,0.8 --sphere -1,-0.5,3,1.2 \
    -j 2 | tail -n +3 | tr -d '\n' >"$TMP/b"
cmp -s "$TMP/a" "$TMP/b"
ok $? "P1 and P4 carry the same pixels"

# Plain rows wider than the output's buffer (a pipe's 64 KiB) are
# formatted one at a time, and plain PBM rows of spheres reach the writer
# as runs of black pixels, not bits: the same bytes as Netpbm's own plain
# writer gives for the P4, which travels as bits.
rayo render -W 65536 -H 5 --raw -o "$TMP/wide-p4.pbm"
rayo render -W 65536 -H 5 -j 2 | cat >"$TMP/wide-p1.pbm"
pamtopnm -plain "$TMP/wide-p4.pbm" >"$TMP/wide-netpbm.pbm" 2>/dev/null
cmp -s "$TMP/wide-p1.pbm" "$TMP/wide-netpbm.pbm"
ok $? "65536-pixel rows through a pipe: P1 as pamtopnm -plain writes it"
[ "$(grep -c 1 "$TMP/wide-p1.pbm")" -gt 0 ]
ok $? "65536-pixel rows: the sphere is in them"

# Helpers start on a CPU other than the caller's (render.c); confined to
# one CPU there is none, and they start on that one: the same bytes.
if command -v taskset >/dev/null 2>&1 && taskset -c 0 true 2>/dev/null; then
    for j in 2 7; do
        taskset -c 0 "$RAYO" render -W 257 -H 65 --raw --sphere 0,0,2,2 \
            -j "$j" -o "$TMP/one-cpu.j$j.pbm"
        cmp -s "$TMP/surface-p4.j1.pbm" "$TMP/one-cpu.j$j.pbm"
        ok $? "one CPU (taskset), -j$j: the bytes of -j1"
    done
else
    ok 0 "one CPU, -j2 # SKIP taskset cannot confine rayo to one CPU here"
    ok 0 "one CPU, -j7 # SKIP taskset cannot confine rayo to one CPU here"
fi

expect_usage_error "-j 0" "threads.*'0'" render -j 0
expect_usage_error "-j 257" "threads.*'257'" render -j 257
expect_usage_error "-j x" "threads.*'x'" render --threads x

# --quiet changes nothing but the (terminal-only) progress bar.
run_capture render --quiet -W 64 -H 48
is "$status" 0 "--quiet exits 0"
rayo render -W 64 -H 48 >"$TMP/loud" 2>/dev/null
cmp -s "$TMP/out" "$TMP/loud"
ok $? "--quiet writes the same image"
is "$(wc -c <"$TMP/err" | tr -d ' ')" 0 "--quiet: nothing on stderr"
run_capture render -q -W 1000 -H 1000 --raw -j 2 -o "$TMP/big.pbm"
is "$(wc -c <"$TMP/err" | tr -d ' ')" 0 "stderr not a terminal: no bar"

done_testing
