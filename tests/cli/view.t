#!/bin/sh
# view.t - `rayo view`: the picture fits the width asked for (--cols,
# $COLUMNS, else 80), the sphere is where the image has it, and each
# style uses only its own characters; gray and colour images in colour
# blocks on a terminal ($COLORTERM: 24-bit, else 256 colours; none under
# $NO_COLOR, --ascii, --braille, for bilevel images, or into a file or a
# pipe unless --color=always), each half the mean of its pixels.
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

# --- colour -------------------------------------------------------------
# on_tty OUT ARGS...: rayo with standard output on a pseudo-terminal (raw:
# no CR added), what it wrote in OUT; stderr goes to $TMP/tty_err.
on_tty() {
    python3 -c 'import os, subprocess, sys, tty
master, slave = os.openpty()
tty.setraw(slave)
p = subprocess.Popen(sys.argv[2:], stdout=slave, stdin=subprocess.DEVNULL,
                     stderr=open(sys.argv[1] + ".err", "wb"))
os.close(slave)
data = b""
while True:
    try:
        chunk = os.read(master, 65536)
    except OSError:
        break
    if not chunk:
        break
    data += chunk
code = p.wait()
open(sys.argv[1], "wb").write(data)
sys.exit(code)' "$@"
}
# has FILE STRING: 1 when FILE holds STRING (escapes as in printf), else 0.
has() { python3 -c 'import sys
print(int(sys.argv[2].encode().decode("unicode_escape").encode("latin-1") in open(sys.argv[1], "rb").read()))' "$1" "$2"; }
ESC24='\x1b[38;2;'
ESC256='\x1b[38;5;'

rayo render "$RAYO_SOURCE/examples/ej3.scene" -W 64 -H 48 -o "$TMP/c.ppm"
ppmtopgm "$TMP/c.ppm" >"$TMP/c.pgm" # luminance, 256 levels (Netpbm)
is "$(head -c 2 "$TMP/c.ppm")$(head -c 2 "$TMP/c.pgm")" P3P5 "colour tests: a PPM of ej3.scene, 64x48, and its PGM"

(unset NO_COLOR; COLORTERM=truecolor on_tty "$TMP/t24" "$RAYO" view "$TMP/c.ppm")
is "$? $(has "$TMP/t24" "$ESC24") $(has "$TMP/t24" "$ESC256")" "0 1 0" \
   "COLORTERM=truecolor on a terminal: 24-bit colour, no 256-colour codes"
is "$(python3 -c 'import sys
t = open(sys.argv[1], encoding="utf-8").read()
ls = t.split("\n")[:-1]
print(len(ls), {l.count("\u2580") for l in ls}, all(l.endswith("\x1b[0m") for l in ls), t.endswith("\n"))' "$TMP/t24")" \
   "24 {64} True True" "  24 lines of 64 cells (never enlarged), each ending in ESC[0m"
is "$(wc -c <"$TMP/t24.err" | tr -d ' ')" 0 "  nothing on stderr"
# The means, worked out here from the plain PPM: 32 columns is 2x2
# pixels a half block, rounded to nearest, halves up.
COLORTERM=truecolor rayo view --cols 32 --color=always "$TMP/c.ppm" >"$TMP/m24"
is "$(python3 -c 'import re, sys
tok = open(sys.argv[1]).read().split()
w, h, v = int(tok[1]), int(tok[2]), list(map(int, tok[4:]))
px = lambda x, y, k: v[3 * (y * w + x) + k]
want = []
for r in range(h // 4):
    line = ""
    for c in range(w // 2):
        half = lambda y0: ";".join(str((2 * sum(px(x, y, k) for x in (2 * c, 2 * c + 1) for y in (y0, y0 + 1)) + 4) // 8) for k in range(3))
        line += "\x1b[38;2;%s;48;2;%sm\u2580" % (half(4 * r), half(4 * r + 2))
    want.append(line + "\x1b[0m")
got = open(sys.argv[2], encoding="utf-8").read().split("\n")[:-1]
print(len(got), sum(g == x for g, x in zip(got, want)), len(set(re.findall(r"38;2;[0-9;]+;48", "".join(got)))) > 20)' "$TMP/c.ppm" "$TMP/m24")" \
   "12 12 True" "--cols 32: every half block the mean of its 2x2 pixels, exactly (and many colours)"

(unset COLORTERM NO_COLOR; on_tty "$TMP/t256" "$RAYO" view "$TMP/c.ppm")
is "$? $(has "$TMP/t256" "$ESC24") $(has "$TMP/t256" "$ESC256")" "0 0 1" \
   "no COLORTERM on a terminal: 256 colours"
(unset NO_COLOR; COLORTERM=24bit on_tty "$TMP/t24b" "$RAYO" view "$TMP/c.ppm")
cmp -s "$TMP/t24b" "$TMP/t24"
ok $? "COLORTERM=24bit: the same 24-bit picture"
(unset NO_COLOR; COLORTERM=yes on_tty "$TMP/tyes" "$RAYO" view "$TMP/c.ppm")
cmp -s "$TMP/tyes" "$TMP/t256"
ok $? "COLORTERM=yes (neither word): 256 colours"

rayo view "$TMP/c.ppm" >"$TMP/plain"
is "$(has "$TMP/plain" '\x1b')" 0 "into a file: no escape sequence at all"
is "$(grep -c . "$TMP/plain")" 24 "  but the silhouette, 24 lines"
is "$(COLORTERM=truecolor rayo view "$TMP/c.ppm" | od -An -c | grep -c '033')" 0 \
   "into a pipe, even with COLORTERM=truecolor: no escape"
(COLORTERM=truecolor NO_COLOR=1 on_tty "$TMP/tno" "$RAYO" view "$TMP/c.ppm")
cmp -s "$TMP/tno" "$TMP/plain"
ok $? "NO_COLOR=1 on a terminal: the silhouette, as into a file"
(COLORTERM=truecolor NO_COLOR= on_tty "$TMP/tempty" "$RAYO" view "$TMP/c.ppm")
cmp -s "$TMP/tempty" "$TMP/t24"
ok $? "NO_COLOR empty: colour all the same (no-color.org)"
(unset NO_COLOR; COLORTERM=truecolor on_tty "$TMP/tascii" "$RAYO" view --ascii "$TMP/c.ppm")
rayo view --ascii "$TMP/c.ppm" >"$TMP/fascii"
is "$(has "$TMP/tascii" '\x1b')" 0 "--ascii on a terminal: no escape"
cmp -s "$TMP/tascii" "$TMP/fascii"
ok $? "  the ASCII silhouette, as into a file"
(unset NO_COLOR; COLORTERM=truecolor on_tty "$TMP/tbr" "$RAYO" view --braille "$TMP/c.ppm")
is "$(has "$TMP/tbr" '\x1b')" 0 "--braille on a terminal: no escape"
(unset NO_COLOR; COLORTERM=truecolor on_tty "$TMP/tnever" "$RAYO" view --color=never "$TMP/c.ppm")
cmp -s "$TMP/tnever" "$TMP/plain"
ok $? "--color=never on a terminal: the silhouette"
COLORTERM=truecolor NO_COLOR=1 rayo view --color "$TMP/c.ppm" >"$TMP/always"
cmp -s "$TMP/always" "$TMP/t24"
ok $? "--color (always) into a file, over NO_COLOR: the terminal's picture"
(unset COLORTERM; rayo view --color=always "$TMP/c.ppm" >"$TMP/always256")
cmp -s "$TMP/always256" "$TMP/t256"
ok $? "--color=always without COLORTERM: 256 colours"

# Gray: R = G = B in every colour; exact for a known 2x2 PPM.
(unset NO_COLOR; COLORTERM=truecolor on_tty "$TMP/g24" "$RAYO" view "$TMP/c.pgm")
is "$(has "$TMP/g24" "$ESC24") $(python3 -c 'import re, sys
cs = re.findall(r"[34]8;2;(\d+);(\d+);(\d+)", open(sys.argv[1], encoding="utf-8").read())
print(len(cs) == 2 * 64 * 24, all(r == g == b for r, g, b in cs), len({c for c in cs}) > 5)' "$TMP/g24")" \
   "1 True True True" "PGM on a terminal: 24-bit grays, R = G = B, many levels"
(unset COLORTERM NO_COLOR; on_tty "$TMP/g256" "$RAYO" view "$TMP/c.pgm")
is "$(has "$TMP/g256" "$ESC256") $(has "$TMP/g256" "$ESC24")" "1 0" "PGM, no COLORTERM: 256 colours"
printf 'P3\n2 2\n255\n255 0 0  0 255 0\n0 0 255  10 20 30\n' >"$TMP/four.ppm"
is "$(COLORTERM=truecolor rayo view --color "$TMP/four.ppm" | od -An -c | tr -s ' \n' ' ')" \
   "$(printf '\033[38;2;255;0;0;48;2;0;0;255m\342\226\200\033[38;2;0;255;0;48;2;10;20;30m\342\226\200\033[0m\n' | od -An -c | tr -s ' \n' ' ')" \
   "a 2x2 PPM in 24-bit: red over blue, green over (10,20,30)"
is "$( (unset COLORTERM; rayo view --color "$TMP/four.ppm") | od -An -c | tr -s ' \n' ' ')" \
   "$(printf '\033[38;5;196;48;5;21m\342\226\200\033[38;5;46;48;5;233m\342\226\200\033[0m\n' | od -An -c | tr -s ' \n' ' ')" \
   "  in 256 colours: 196 (red), 21 (blue), 46 (green), 233 (gray 18)"

# Bilevel: today's silhouette on a terminal too, byte for byte.
(unset NO_COLOR; COLORTERM=truecolor on_tty "$TMP/tpbm" "$RAYO" view --cols 40 "$D")
cmp -s "$TMP/tpbm" "$TMP/out"
ok $? "a PBM on a terminal with COLORTERM=truecolor: the silhouette, as into a file"

# render --preview: colour only when the picture goes to a terminal.
(unset NO_COLOR; COLORTERM=truecolor COLUMNS=80 on_tty "$TMP/rp" "$RAYO" render "$RAYO_SOURCE/examples/ej3.scene" -W 64 -H 48 --preview -o "$TMP/rp.ppm")
cmp -s "$TMP/rp" "$TMP/t24"
ok $? "render --preview on a terminal: the 24-bit picture view draws of the file"
cmp -s "$TMP/rp.ppm" "$TMP/c.ppm"
ok $? "  and the file is the usual image"
(unset NO_COLOR; COLORTERM=truecolor COLUMNS=80 rayo render "$RAYO_SOURCE/examples/ej3.scene" -W 64 -H 48 --preview -o "$TMP/rq.ppm" >"$TMP/rq" 2>"$TMP/rqerr")
cmp -s "$TMP/rq" "$TMP/plain"
ok $? "render --preview into a file: no escape, the silhouette view draws"
(unset NO_COLOR; COLORTERM=truecolor COLUMNS=80 rayo render "$RAYO_SOURCE/examples/ej3.scene" -W 64 -H 48 --preview >"$TMP/rs.ppm" 2>"$TMP/rserr")
cmp -s "$TMP/rs.ppm" "$TMP/c.ppm"
ok $? "render --preview, image on stdout: stdout holds only the image"
cmp -s "$TMP/rserr" "$TMP/plain"
ok $? "  the picture on stderr (a file): no escape"
(unset NO_COLOR; COLORTERM=truecolor COLUMNS=80 on_tty "$TMP/rg" "$RAYO" render "$RAYO_SOURCE/examples/ej3.scene" --shade course-gray -W 64 -H 48 --preview -o "$TMP/rg.pgm")
(unset NO_COLOR; COLORTERM=truecolor COLUMNS=80 on_tty "$TMP/rg2" "$RAYO" view "$TMP/rg.pgm")
is "$(has "$TMP/rg" "$ESC24")" 1 "render --preview of a gray render on a terminal: in colour"
cmp -s "$TMP/rg" "$TMP/rg2"
ok $? "  the picture view draws of its file"
(unset NO_COLOR; COLORTERM=truecolor COLUMNS=40 on_tty "$TMP/rb" "$RAYO" render --preview -o "$TMP/rb.pbm")
cmp -s "$TMP/rb" "$TMP/out"
ok $? "render --preview of a bilevel render on a terminal: today's silhouette"

expect_usage_error "bad --color" "--color: 'sometimes'" view --color=sometimes "$D"
expect_usage_error "no file" "expected one FILE" view
expect_usage_error "zero columns" "--cols" view --cols 0 "$D"
expect_usage_error "missing file" "nope\.pbm" view "$TMP/nope.pbm"
printf 'P2\n2 2\n0\n0 0 0 0\n' >"$TMP/bad.pgm"
expect_usage_error "maxval 0" "bad\.pgm" view "$TMP/bad.pgm"
done_testing
