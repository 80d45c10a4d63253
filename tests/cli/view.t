#!/bin/sh
# view.t - `rayo view`: the picture fits the width asked for (--cols,
# $COLUMNS, else 80), the sphere is where the image has it, and each
# style uses only its own characters.
. "$(dirname "$0")/lib.sh"

rayo -o "$TMP/default.pbm"
D="$TMP/default.pbm"

# widths FILE: the distinct line lengths, in characters (not bytes).
widths() { python3 -c 'import sys
print(" ".join(sorted({str(len(l.rstrip("\n"))) for l in open(sys.argv[1], encoding="utf-8")})))' "$1"; }
lines() { wc -l <"$1" | tr -d ' '; }
# cell FILE LINE COLUMN (from 0): the character there.
cell() { python3 -c 'import sys
print(open(sys.argv[1], encoding="utf-8").read().split("\n")[int(sys.argv[2])][int(sys.argv[3])])' "$@"; }
count() { python3 -c 'import sys
print(open(sys.argv[1], encoding="utf-8").read().count(sys.argv[2]))' "$@"; }

# 640x480 in 40 columns: 16 pixels a sub-pixel, 30 sub-pixel rows, two a
# line for blocks and ASCII (15 lines), four for Braille (80 x 60 dots).
run_capture view --cols 40 "$D"
is "$status" 0 "view --cols 40: exit 0"
is "$(widths "$TMP/out")" 40 "  every line 40 characters"
is "$(lines "$TMP/out")" 15 "  15 lines (480 / 16 / 2)"
# The sphere's centre projects to pixel (404, 114): column 25, line 3.
is "$(cell "$TMP/out" 3 25)" "█" "  the sphere's centre is a full block"
is "$(cell "$TMP/out" 14 0)" " " "  the bottom left corner is blank"
is "$(cell "$TMP/out" 3 5)" " " "  left of the sphere is blank"
full=$(count "$TMP/out" "█")
ok "$([ "$full" -ge 110 ] && [ "$full" -le 126 ]; echo $?)" "  about 64503 / (16 x 32) = 126 full cells, fewer at the edge ($full)"
is "$(wc -c <"$TMP/err" | tr -d ' ')" 0 "  nothing on stderr"

rayo view --cols 40 --ascii "$D" >"$TMP/ascii"
is "$(widths "$TMP/ascii")" 40 "--ascii: every line 40 characters"
is "$(LC_ALL=C tr -d ' #+\n' <"$TMP/ascii" | wc -c | tr -d ' ')" 0 "  only ' ', '#', '+'"
is "$(cell "$TMP/ascii" 3 25)" "#" "  '#' at the sphere's centre"
is "$(cell "$TMP/ascii" 14 0)" " " "  ' ' in the bottom left corner"

rayo view --cols 40 --braille "$D" >"$TMP/braille"
is "$(widths "$TMP/braille")" 40 "--braille: every line 40 characters"
is "$(lines "$TMP/braille")" 15 "  15 lines (60 rows of dots / 4)"
is "$(cell "$TMP/braille" 3 25)" "⣿" "  all eight dots at the sphere's centre"
is "$(python3 -c 'import sys
print(all(0x2800 <= ord(c) <= 0x28ff for c in open(sys.argv[1], encoding="utf-8").read() if c != "\n"))' "$TMP/braille")" True \
   "  only Braille patterns"

# A sphere on the axis looks the same mirrored: every line a palindrome.
rayo --sphere 0,0,3,1 -W 161 -H 121 -o "$TMP/centred.pbm"
rayo view --cols 161 --ascii "$TMP/centred.pbm" >"$TMP/sym"
is "$(python3 -c 'import sys
print(all(l == l[::-1] for l in open(sys.argv[1]).read().split("\n")))' "$TMP/sym")" True \
   "a centred sphere: every line reads the same both ways"
is "$(count "$TMP/sym" "#" | awk '{ print ($1 > 0) }')" 1 "  and it is drawn"

# Width: never wider than the image, $COLUMNS, else 80.
is "$(rayo view --cols 500 "$TMP/centred.pbm" | head -n 1 | python3 -c 'import sys; print(len(sys.stdin.read().rstrip("\n")))')" 161 \
   "never enlarged: 161 columns for a 161-pixel image"
is "$(COLUMNS=50 rayo view "$D" | python3 -c 'import sys; print(len(sys.stdin.readline().rstrip("\n")))')" 50 "\$COLUMNS=50: 50 columns"
is "$( (unset COLUMNS; rayo view "$D") | python3 -c 'import sys; print(len(sys.stdin.readline().rstrip("\n")))')" 80 "no \$COLUMNS: 80 columns"
is "$(COLUMNS=junk rayo view "$D" | python3 -c 'import sys; print(len(sys.stdin.readline().rstrip("\n")))')" 80 "\$COLUMNS not a number: 80 columns"

# Gray and colour images are thresholded at half, like compare does.
pgmramp -lr 64 8 >"$TMP/ramp.pgm"
rayo view --cols 64 --ascii "$TMP/ramp.pgm" >"$TMP/ramp"
is "$(head -n 1 "$TMP/ramp")" "$(printf '%32s' '' | tr ' ' '#')$(printf '%32s' '')" \
   "a gray ramp: the dark half black, the light half blank"
rayo view - --cols 40 <"$D" >"$TMP/stdin"
cmp -s "$TMP/stdin" "$TMP/out"
ok $? "'-' reads standard input"

# rayo render --preview: the same picture as rayo view of the file;
# beside a file on stdout, beside an image on stdout on stderr.
COLUMNS=40 rayo render --preview -o "$TMP/p.pbm" >"$TMP/pv" 2>"$TMP/pverr"
cmp -s "$TMP/pv" "$TMP/out"
ok $? "render --preview -o FILE: the picture on stdout, as view draws the file"
is "$(wc -c <"$TMP/pverr" | tr -d ' ')" 0 "  nothing on stderr"
cmp -s "$TMP/p.pbm" "$D"
ok $? "  and the file is the usual image"
COLUMNS=40 rayo render --preview >"$TMP/p2.pbm" 2>"$TMP/p2err"
cmp -s "$TMP/p2.pbm" "$D"
ok $? "render --preview to stdout: stdout holds only the image"
cmp -s "$TMP/p2err" "$TMP/out"
ok $? "  and the picture goes to stderr"
COLUMNS=30 rayo render --shade course-gray --preview -o "$TMP/g.pgm" >"$TMP/gv"
rayo view --cols 30 "$TMP/g.pgm" >"$TMP/gv2"
cmp -s "$TMP/gv" "$TMP/gv2"
ok $? "a shaded (gray) render previews as view shows its file"

expect_usage_error "no file" "expected one FILE" view
expect_usage_error "zero columns" "--cols" view --cols 0 "$D"
expect_usage_error "missing file" "nope\.pbm" view "$TMP/nope.pbm"
printf 'P2\n2 2\n0\n0 0 0 0\n' >"$TMP/bad.pgm"
expect_usage_error "maxval 0" "bad\.pgm" view "$TMP/bad.pgm"
done_testing
