#!/bin/sh
# generate.sh - makes the valid images of the reader's seed corpus
# (fuzz/corpus/reader/ok-*) with rayo and the Netpbm tools; the malformed
# ones are copies of tests/data/malformed (tests/data/malformed/generate.py).
# The scene and command-line seeds are written by hand.  Run from the
# repository root after `make`:  RAYO=build/rayo fuzz/corpus/generate.sh
set -eu
: "${RAYO:=build/rayo}"
d=fuzz/corpus/reader
cp tests/data/malformed/*.p?m tests/data/malformed/*.png "$d/"
"$RAYO" -W 8 -H 6 >"$d/ok-p1.pbm"
"$RAYO" -W 9 -H 5 --raw -o "$d/ok-p4.pbm"
"$RAYO" render examples/ej2.scene -W 6 -H 4 --raw -o "$d/ok-p5.pgm"
"$RAYO" render examples/ej3.scene -W 4 -H 3 -o "$d/ok-p3.ppm"
printf 'P2\n# a comment\n3 2\n65535\n0 1 65535\n7 8 9\n' >"$d/ok-p2-16.pgm"
ppmmake rgb:10/80/ff 5 3 >"$d/ok-p6.ppm"
pnmdepth 65535 "$d/ok-p6.ppm" >"$d/ok-p6-16.ppm"
pnmtopng "$d/ok-p1.pbm" >"$d/ok-bit.png"
pnmtopng "$d/ok-p5.pgm" >"$d/ok-gray.png"
pnmdepth 15 "$d/ok-p5.pgm" | pnmtopng >"$d/ok-gray4.png"
pnmtopng "$d/ok-p6.ppm" >"$d/ok-rgb.png"
pnmtopng "$d/ok-p6-16.ppm" >"$d/ok-rgb16.png"
pnmtopng -interlace "$d/ok-p3.ppm" >"$d/ok-interlace.png"
pnmtopng -transparent=rgb:10/80/ff "$d/ok-p6.ppm" >"$d/ok-trns.png"
alpha=$(mktemp)
pgmmake 0.5 4 3 >"$alpha"
pnmtopng -alpha="$alpha" "$d/ok-p3.ppm" >"$d/ok-alpha.png"
pnmtopng -alpha="$alpha" "$d/ok-p5.pgm" >"$d/ok-gray-alpha.png" 2>/dev/null ||
    rm -f "$d/ok-gray-alpha.png"
rm -f "$alpha"
pnmtopng -force -palette="$d/ok-p3.ppm" "$d/ok-p3.ppm" >"$d/ok-palette.png" 2>/dev/null ||
    ppmquant 2 "$d/ok-p3.ppm" 2>/dev/null | pnmtopng >"$d/ok-palette.png"
