#!/bin/sh
# compare_reports.t - `rayo compare --json` gives, figure for figure, the
# reports recorded in tests/data/compare/reports.txt, on 58 pairs made
# here (rayo renders and the Netpbm tools: flips, inversion, transposed,
# shifted, another field of view, another sphere, noise, one colour),
# at several tolerances, in frames of one band and of several bands.
#
# The recorded reports come from the build before the search for the
# farthest mismatch was bounded (commit 03fba86 and after: near.c and
# farthest.c), when every mismatch's exact distance from the outline was
# computed; so this checks that the faster way changes no reported
# value.  Two lines were recorded again on purpose when consistency came
# to need the shapes to agree (band.c): gray-reference (a checkerboard
# against an inverted sphere) and noise-tol5 (noise against sparse
# noise), consistent before only because every pixel of a busy
# reference is near its outline, are now inconsistent; every other line
# is as it was.  noise-tol5's diagnosis was recorded again when a
# candidate came to need agreement beyond chance too (diagnose.c): its
# "scaled by 2.017" was the luckiest of the scales searched over noise
# (a scale up places a fraction of the frame, which halves the
# mismatches by itself); it is now "unknown".  To record them again (only after a deliberate change of what
# compare reports), with images made by RAYO and reports by RECORD_WITH:
#   RECORD=1 RAYO=build/rayo RECORD_WITH=old/rayo RAYO_SOURCE=. \
#       sh tests/cli/compare_reports.t >tests/data/compare/reports.txt
. "$(dirname "$0")/lib.sh"

WANT="$RAYO_SOURCE/tests/data/compare/reports.txt"
R="$RAYO" # the images are made without valgrind; the comparisons use it

# --- the images ------------------------------------------------------
# Small (one band; a width that is no multiple of 8, 32 or 64).
"$R" -W 333 -H 251 -o "$TMP/s.pbm"
pamflip -tb "$TMP/s.pbm" >"$TMP/s_tb.pbm"
pamflip -lr "$TMP/s.pbm" >"$TMP/s_lr.pbm"
pamflip -r180 "$TMP/s.pbm" >"$TMP/s_r180.pbm"
pamflip -transpose "$TMP/s.pbm" >"$TMP/s_tr.pbm"
pnminvert "$TMP/s.pbm" >"$TMP/s_inv.pbm"
"$R" -W 333 -H 251 --fov 80 -o "$TMP/s_fov.pbm"
"$R" -W 333 -H 251 --fov 60 -o "$TMP/s_fov60.pbm"
"$R" -W 333 -H 251 --fov 100 -o "$TMP/s_fov100.pbm"
pamflip -tb "$TMP/s_fov.pbm" >"$TMP/s_fovtb.pbm"
"$R" -W 333 -H 251 --sphere 0.52,0.75,1.9,0.8 -o "$TMP/s_moved.pbm"
"$R" -W 333 -H 251 --sphere -0.6,0,2,0.4 --sphere 0.6,0,2,0.4 -o "$TMP/s_two.pbm"
pamcut -left 0 -width 326 -top 0 -height 248 "$TMP/s.pbm" |
    pnmpad -white -left 7 -top 3 >"$TMP/s_shift.pbm"
pbmmake -white 333 251 >"$TMP/s_white.pbm"
pbmmake -black 333 251 >"$TMP/s_black.pbm"
pbmmake -gray 333 251 >"$TMP/s_gray.pbm"
pgmnoise -randomseed=7 333 251 | pgmtopbm -threshold >"$TMP/s_noise.pbm"
pgmnoise -randomseed=8 333 251 | pgmtopbm -threshold -value 0.9 >"$TMP/s_sparse.pbm"
pamflip -tb "$TMP/s_noise.pbm" >"$TMP/s_noisetb.pbm"
"$R" -W 360 -H 251 -o "$TMP/s_wide.pbm"
# Large: more than 2^21 pixels, so measured in bands by several threads
# where there are CPUs for them.
"$R" -W 1537 -H 1401 -o "$TMP/b.pbm"
pamflip -tb "$TMP/b.pbm" >"$TMP/b_tb.pbm"
pnminvert "$TMP/b.pbm" >"$TMP/b_inv.pbm"
"$R" -W 1537 -H 1401 --fov 89.7 -o "$TMP/b_fov.pbm"
pamflip -tb "$TMP/b_fov.pbm" >"$TMP/b_fovtb.pbm"
"$R" -W 1537 -H 1401 --sphere 0.52,0.75,1.9,0.8 -o "$TMP/b_moved.pbm"
"$R" -o "$TMP/default.pbm"

# --- the pairs ---------------------------------------------------------
# Lines: name, reference, image, options.
cat >"$TMP/pairs" <<'EOF'
same s s
flipped s s_tb
flipped-lr s s_lr
r180 s s_r180
transposed s s_tr
inverted s s_inv
fov s s_fov
fov-flipped s s_fovtb
fov60 s s_fov60
fov100 s s_fov100
fov100-as-reference s_fov100 s
moved s s_moved
two s s_two
shifted s s_shift
white s s_white
black s s_black
gray s s_gray
noise s s_noise
sparse s s_sparse
wide s s_wide
flipped-as-reference s_tb s
noise-as-reference s_noise s
noise-flipped s_noise s_noisetb
sparse-as-reference s_sparse s_moved
white-reference s_white s
black-reference s_black s_noise
gray-reference s_gray s_inv
big-flipped b b_tb
big-inverted b b_inv
big-fov-flipped b b_fovtb
big-moved b b_moved
big-fov b b_fov
big-flipped-tol0 b b_tb --tolerance 0
big-flipped-tol8.5 b b_tb --tolerance 8.5
course SEED default
course-tol1 SEED default --tolerance 1
EOF
for tol in 0 1.5 3.7 8 8.01 12; do
    for p in tb inv noise; do
        echo "s_$p-tol$tol s s_$p --tolerance $tol" >>"$TMP/pairs"
    done
done
echo "s_shift-tol0 s s_shift --tolerance 0" >>"$TMP/pairs"
echo "s_moved-tol0.5 s s_moved --tolerance 0.5" >>"$TMP/pairs"
echo "noise-tol5 s_noise s_sparse --tolerance 5" >>"$TMP/pairs"
echo "gray-tol3 s s_gray --tolerance 3" >>"$TMP/pairs"

# --- compare them ------------------------------------------------------
[ "${RECORD:-0}" = 1 ] && RAYO=${RECORD_WITH:-$RAYO}
file() {
    if [ "$1" = SEED ]; then echo "$SEED/referencia-catedra.png"
    else echo "$TMP/$1.pbm"; fi
}
while read -r name ref img opts; do
    # shellcheck disable=SC2086 # opts is a list of words
    run_capture compare "$(file "$ref")" "$(file "$img")" --json $opts
    got="$name	$status	$(cat "$TMP/out")"
    if [ "${RECORD:-0}" = 1 ]; then
        printf '%s\n' "$got"
        continue
    fi
    want=$(awk -F '\t' -v n="$name" '$1 == n' "$WANT")
    is "$got" "$want" "$name: the recorded report"
done <"$TMP/pairs"
[ "${RECORD:-0}" = 1 ] && exit 0
is "$(wc -l <"$TMP/pairs" | tr -d ' ')" "$(wc -l <"$WANT" | tr -d ' ')" "every recorded pair compared"
done_testing
