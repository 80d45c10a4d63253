#!/bin/sh
# render_basics.t - what `rayo` writes: the default image byte for byte,
# the option forms, and agreement with the Netpbm tools and libpng.
. "$(dirname "$0")/lib.sh"

# An independent renderer of the convention, in awk (double precision):
# the seed sphere, w x h, fov 90, as rows of 0/1 digits.
reference() { # reference W H FOV CX CY CZ R
    awk -v w="$1" -v h="$2" -v fov="$3" -v cx="$4" -v cy="$5" -v cz="$6" -v r="$7" 'BEGIN {
        pi = atan2(0, -1); f = w / (2 * sin(fov * pi / 360) / cos(fov * pi / 360))
        for (j = 0; j < h; j++) {
            line = ""
            for (i = 0; i < w; i++) {
                x = i - int(w / 2); y = j - int(h / 2)
                n = sqrt(x * x + y * y + f * f); dx = x / n; dy = -y / n; dz = f / n
                b = cx * dx + cy * dy + cz * dz
                d = b * b - (cx * cx + cy * cy + cz * cz) + r * r
                hit = (d >= 0 && (b - sqrt(d > 0 ? d : 0) > 0 || b + sqrt(d > 0 ? d : 0) > 0))
                line = line (hit ? "1" : "0")
            }
            print line
        }
    }'
}
# The raster of a PBM as one row of digits per line (via the Netpbm tools).
digits() { pnmtoplainpnm "$1" | tail -n +3 | tr -d ' \n' | fold -w "$2"; echo; }

run_capture
is "$status" 0 "rayo exits 0"
is "$(head -n 2 "$TMP/out" | tr '\n' ' ')" "P1 640 480 " "plain PBM header, 640x480"
longest=$(awk 'NR > 2 { if (length($0) > m) m = length($0) } END { print m }' "$TMP/out")
ok "$([ "$longest" -le 70 ]; echo $?)" "no raster line longer than 70 characters ($longest)"
is "$(wc -c <"$TMP/err" | tr -d ' ')" 0 "nothing on stderr"
cp "$TMP/out" "$TMP/default.pbm"

reference 640 480 90 0.5 0.75 1.9 0.8 >"$TMP/ref.txt"
digits "$TMP/default.pbm" 640 >"$TMP/got.txt"
cmp -s "$TMP/ref.txt" "$TMP/got.txt"
ok $? "default image: every pixel as an independent awk computation"
is "$(tr -cd 1 <"$TMP/ref.txt" | wc -c | tr -d ' ')" 64503 "the seed sphere covers 64503 pixels"

rayo render >"$TMP/sub.pbm"
cmp -s "$TMP/default.pbm" "$TMP/sub.pbm"
ok $? "'rayo render' is the same command"
rayo -W 640 --height=480 --fov 90 --sphere 0.5,0.75,1.9,0.8 --origin 0,0,0 -o - >"$TMP/explicit.pbm"
cmp -s "$TMP/default.pbm" "$TMP/explicit.pbm"
ok $? "explicit seed options give the same bytes"

# Another size, field of view, origin and two spheres, by the awk reference.
rayo -W 97 -H 61 --fov 60 --sphere 0.2,0.1,3,0.9 >"$TMP/odd.pbm"
reference 97 61 60 0.2 0.1 3 0.9 >"$TMP/ref.txt"
digits "$TMP/odd.pbm" 97 >"$TMP/got.txt"
cmp -s "$TMP/ref.txt" "$TMP/got.txt"
ok $? "97x61, fov 60: every pixel as the awk computation"
rayo -W 80 -H 60 --origin 0,0,-1 --sphere 0.5,0.75,0.9,0.8 >"$TMP/moved.pbm"
rayo -W 80 -H 60 >"$TMP/plain.pbm"
cmp -s "$TMP/moved.pbm" "$TMP/plain.pbm"
ok $? "moving the camera and the sphere together changes nothing"

# Raw PBM and PNG: the Netpbm tools agree on every pixel.
rayo --raw -o "$TMP/raw.pbm"
is "$(head -c 2 "$TMP/raw.pbm")" "P4" "--raw writes P4"
is "$(pamfile "$TMP/raw.pbm" | sed 's/.*:[[:space:]]*//')" "PBM raw, 640 by 480" "pamfile reads our P4"
is "$(pamfile "$TMP/default.pbm" | sed 's/.*:[[:space:]]*//')" "PBM plain, 640 by 480" "pamfile reads our P1"
pamtopnm -plain "$TMP/raw.pbm" | tail -n +3 | tr -d ' \n' >"$TMP/a"
pamtopnm -plain "$TMP/default.pbm" | tail -n +3 | tr -d ' \n' >"$TMP/b"
cmp -s "$TMP/a" "$TMP/b"
ok $? "P4 and P1 hold the same pixels (Netpbm)"
rayo -o "$TMP/seed.png"
is "$(head -c 8 "$TMP/seed.png" | od -An -tx1 | tr -d ' \n')" "89504e470d0a1a0a" "-o .png writes a PNG signature"
pngtopnm "$TMP/seed.png" | pamtopnm -plain | tail -n +3 | tr -d ' \n' >"$TMP/c"
cmp -s "$TMP/b" "$TMP/c"
ok $? "pngtopnm decodes our PNG to the same pixels as the PBM"
rayo --format png -o - >"$TMP/stdout.png" && cmp -s "$TMP/seed.png" "$TMP/stdout.png"
ok $? "--format png to standard output: the same PNG"
rayo -o "$TMP/UPPER.PNG" && cmp -s "$TMP/seed.png" "$TMP/UPPER.PNG"
ok $? "extensions are matched without regard to case"
rayo --format pbm -o "$TMP/named.png" && is "$(head -c 2 "$TMP/named.png")" "P1" "--format overrides the extension"

# Help and version.
rayo --help >"$TMP/help"
ok $? "--help exits 0"
grep -q -- "--sphere CX,CY,CZ,R" "$TMP/help"
ok $? "--help lists --sphere"
is "$(rayo -V)" "rayo $(sed -n 's/^#define RAYO_VERSION "\(.*\)"/\1/p' "$RAYO_SOURCE/include/rayo.h")" "-V prints the version"
done_testing
