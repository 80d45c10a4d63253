#!/bin/sh
# compare_corpus.sh - a corpus of image pairs for `rayo compare`, and its
# reports recorded or checked byte for byte, so that work on the
# comparison's speed can show it changed no report (issue 16).
#
#   sh tests/cli/compare_corpus.sh record RAYO DIR   reports of RAYO into DIR
#   sh tests/cli/compare_corpus.sh check RAYO DIR    RAYO's against DIR's
#
# The pairs (gray and colour, 640x480 and other sizes, consistent and
# not, the course's references and rayo's renders) are made with rayo
# render, the Netpbm tools, python3 and the student programs of
# tests/grade (compiled with cc).  Each pair gives three reports: the
# text, --json and the --diff picture.  About a minute here, so it is not
# part of `make check`: run it by hand (RAYO_SOURCE: the tree, default
# the current folder; RAYO_CORPUS_KEEP=DIR keeps the images and the list
# of pairs, pairs.txt, there).
set -eu
mode=$1 RAYO=$(cd "$(dirname "$2")" && pwd)/$(basename "$2") DIR=$3
SRC=${RAYO_SOURCE:-$PWD}
C2="$SRC/data/course/referencia-catedra-ej2.png"
C3="$SRC/data/course/referencia-catedra-ej3.png"
C1="$SRC/data/course/referencia-catedra-ej1.png"
mkdir -p "$DIR"
if [ -n "${RAYO_CORPUS_KEEP:-}" ]; then # the images and pairs.txt kept there
    W=$RAYO_CORPUS_KEEP
    mkdir -p "$W"
else
    W=$(mktemp -d "${TMPDIR:-/tmp}/rayo-corpus.XXXXXX")
    trap 'rm -rf "$W"' EXIT
fi
cd "$W"

# --- the images -----------------------------------------------------------
"$RAYO" render "$SRC/examples/ej2.scene" -o r2.pgm
"$RAYO" render "$SRC/examples/ej3.scene" -o r3.ppm
"$RAYO" render "$SRC/examples/ej1.scene" -o r1.pbm
"$RAYO" render "$SRC/examples/ej2.scene" --fov 80 -o r2fov80.pgm
"$RAYO" render "$SRC/examples/ej2.scene" --fov 100 -o r2fov100.pgm
"$RAYO" render "$SRC/examples/ej3.scene" --fov 70 -o r3fov70.ppm
"$RAYO" render "$SRC/examples/ej3.scene" --fov 88 -o r3fov88.ppm
"$RAYO" render "$SRC/examples/ej2.scene" -W 320 -H 240 -o r2small.pgm
"$RAYO" render "$SRC/examples/ej3.scene" -W 320 -H 240 -o r3small.ppm
"$RAYO" render "$SRC/examples/ej3.scene" -W 800 -H 600 -o r3big.ppm
"$RAYO" render "$SRC/examples/ej2.scene" -W 641 -H 479 -o r2odd.pgm
pngtopam "$C2" | ppmtopgm >c2.pgm
pngtopam "$C3" >c3.ppm
pamflip -lr r2.pgm >r2lr.pgm
pamflip -tb r2.pgm >r2tb.pgm
pamflip -r180 c2.pgm >c2r180.pgm
pamflip -tb r3.ppm >r3tb.ppm
pamflip -lr c3.ppm >c3lr.ppm
pamflip -r180 r3.ppm >r3r180.ppm
pamflip -tb r3small.ppm >r3smalltb.ppm
pamflip -lr r2small.pgm >r2smalllr.pgm
pamcut -top 1 r2.pgm | pnmpad -bottom=1 -black >r2up1.pgm
pamcut -top 2 c2.pgm | pnmpad -bottom=2 -black >c2up2.pgm
pamcut -left 3 c2.pgm | pnmpad -right=3 -black >c2left3.pgm
pamcut -top 2 r3.ppm | pnmpad -bottom=2 -black >r3up2.ppm
pamcut -left 1 c3.ppm | pnmpad -right=1 -black >c3left1.ppm
pnmpad -top=1 -black r3.ppm | pamcut -top 0 -height 480 >r3down1.ppm
pamcut -left 5 c3.ppm | pnmpad -right=5 -black >c3left5.ppm
pamfunc -subtractor=10 r2.pgm >r2minus10.pgm
pamfunc -adder=40 c2.pgm >c2plus40.pgm
pamfunc -adder=20 r3.ppm >r3plus20.ppm
pamfunc -subtractor=30 c3.ppm >c3minus30.ppm
pamfunc -adder=1 r3.ppm >r3plus1.ppm
pamfunc -multiplier=1.2 c2.pgm >c2times12.pgm
pnminvert r2.pgm >r2inv.pgm
pnminvert c3.ppm >c3inv.ppm
pamchannel -infile c3.ppm -tupletype RGB 2 1 0 | pamtopnm >c3bgr.ppm
pamchannel -infile r3.ppm -tupletype RGB 1 2 0 | pamtopnm >r3gbr.ppm
pamchannel -infile c3.ppm -tupletype RGB 0 2 1 | pamtopnm >c3rbg.ppm
pamchannel -infile r3small.ppm -tupletype RGB 2 0 1 | pamtopnm >r3smallbrg.ppm
pamscale 1.01 c2.pgm | pamcut -left 3 -top 2 -width 640 -height 480 >c2scale101.pgm
pamscale 0.98 c3.ppm | pnmpad -width 640 -height 480 -black >c3scale098.ppm
ppmtopgm c3.ppm >c3gray.pgm
pgmtoppm white c2.pgm >c2rgb.ppm
python3 - <<'EOF'
import random
def rd(f):
    b = open(f, 'rb').read()
    p = b.split(maxsplit=4)
    return p[0], int(p[1]), int(p[2]), bytearray(p[4])
def wr(f, m, w, h, d):
    open(f, 'wb').write(m + b'\n%d %d\n255\n' % (w, h) + bytes(d))
rng = random.Random(16)
for src, dst, amp, share in [('c2.pgm', 'c2noise3.pgm', 3, 1.0),
                             ('c2.pgm', 'c2noise40.pgm', 40, 0.02),
                             ('c3.ppm', 'c3noise2.ppm', 2, 1.0),
                             ('c3.ppm', 'c3noise60.ppm', 60, 0.01),
                             ('r2.pgm', 'r2speck.pgm', 255, 0.001)]:
    m, w, h, d = rd(src)
    for i in range(len(d)):
        if rng.random() < share:
            d[i] = max(0, min(255, d[i] + rng.randint(-amp, amp)))
    wr(dst, m, w, h, d)
m, w, h, d = rd('c3.ppm')
for i in range(0, len(d), 3):
    if d[i] + 80 > 255 and d[i] > 0:
        d[i] = (d[i] + 80) % 256
wr('c3wrap.ppm', m, w, h, d)
m, w, h, d = rd('c2.pgm')
for i in range(len(d)):
    if d[i] > 0:
        d[i] = max(0, d[i] - 5)
wr('c2noamb.pgm', m, w, h, d)
EOF
# Students' programs (tests/grade): their images, as a student hands them.
students=""
for dir in "$SRC"/tests/grade/ej2_* "$SRC"/tests/grade/ej3_*; do
    name=$(basename "$dir")
    case $name in ej2_wrong_signature|ej3_no_typedef) continue ;; esac
    if ${CC:-cc} -std=c99 -w -o "$name" "$dir/main.c" -lm 2>/dev/null &&
       timeout 20 "./$name" >"$name.out" 2>/dev/null && [ -s "$name.out" ]; then
        students="$students $name"
    fi
done

# --- the pairs: NAME|OPTIONS|REFERENCE|IMAGE --------------------------------
pairs() {
    cat <<EOF
c2-r2||$C2|r2.pgm
c2-c2||$C2|c2.pgm
r2-c2||r2.pgm|$C2
c2-plus40||$C2|c2plus40.pgm
c2-r2minus10||$C2|r2minus10.pgm
r2-minus10||r2.pgm|r2minus10.pgm
c2-times12||$C2|c2times12.pgm
c2-r2lr||$C2|r2lr.pgm
r2-r2tb||r2.pgm|r2tb.pgm
c2-r180||$C2|c2r180.pgm
c2-r2up1||$C2|r2up1.pgm
r2-up1||r2.pgm|r2up1.pgm
c2-up2||$C2|c2up2.pgm
c2-left3||$C2|c2left3.pgm
r2-inv||r2.pgm|r2inv.pgm
c2-noise3||$C2|c2noise3.pgm
c2-noise40||$C2|c2noise40.pgm
r2-speck||r2.pgm|r2speck.pgm
c2-fov80||$C2|r2fov80.pgm
c2-fov100||$C2|r2fov100.pgm
c2-scale101||$C2|c2scale101.pgm
c2-small||$C2|r2small.pgm
c2-odd||$C2|r2odd.pgm
r2small-lr||r2small.pgm|r2smalllr.pgm
c2-noamb||$C2|c2noamb.pgm
c2-levels0|--levels 0|$C2|r2.pgm
c2-tol1|--tolerance 1|$C2|r2.pgm
c2-tol4-noise|--tolerance 4|$C2|c2noise40.pgm
c2-none|--exercise none|$C2|c2plus40.pgm
c2-rgb||$C2|c2rgb.ppm
c2-c3||$C2|$C3
c3-r3||$C3|r3.ppm
r3-c3||r3.ppm|$C3
c3-bgr||$C3|c3bgr.ppm
c3-r3gbr||$C3|r3gbr.ppm
r3-c3rbg||r3.ppm|c3rbg.ppm
c3-r3tb||$C3|r3tb.ppm
c3-lr||$C3|c3lr.ppm
r3-r180||r3.ppm|r3r180.ppm
c3-r3up2||$C3|r3up2.ppm
c3-left1||$C3|c3left1.ppm
c3-down1||$C3|r3down1.ppm
c3-left5||$C3|c3left5.ppm
c3-plus20||$C3|r3plus20.ppm
c3-minus30||$C3|c3minus30.ppm
r3-plus1||r3.ppm|r3plus1.ppm
r3-plus1-levels0|--levels 0|r3.ppm|r3plus1.ppm
c3-inv||$C3|c3inv.ppm
c3-noise2||$C3|c3noise2.ppm
c3-noise60||$C3|c3noise60.ppm
c3-wrap||$C3|c3wrap.ppm
c3-fov70||$C3|r3fov70.ppm
c3-fov88||$C3|r3fov88.ppm
c3-scale098||$C3|c3scale098.ppm
c3-small||$C3|r3small.ppm
c3-big||$C3|r3big.ppm
r3small-tb||r3small.ppm|r3smalltb.ppm
r3small-brg||r3small.ppm|r3smallbrg.ppm
c3-gray||$C3|c3gray.pgm
c3-c2||$C3|$C2
c3-none-bgr|--exercise none|$C3|c3bgr.ppm
c3-ej3-bgr|--exercise ej3|$C3|c3bgr.ppm
c2-ej2-tb|--exercise ej2|$C2|r2tb.pgm
c1-r1||$C1|r1.pbm
EOF
    for s in $students; do
        case $s in
        ej2_*) echo "c2-$s||$C2|$s.out"; echo "r2-$s||r2.pgm|$s.out" ;;
        ej3_*) echo "c3-$s||$C3|$s.out"; echo "r3-$s||r3.ppm|$s.out" ;;
        esac
    done
}

n=0 same=0 differ=0
pairs >pairs.txt
while IFS='|' read -r name opts ref img; do
    n=$((n + 1))
    # shellcheck disable=SC2086
    "$RAYO" compare $opts "$ref" "$img" >"$name.txt" 2>&1 || echo "exit $?" >>"$name.txt"
    # shellcheck disable=SC2086
    "$RAYO" compare $opts "$ref" "$img" --json >"$name.json" 2>&1 || echo "exit $?" >>"$name.json"
    # shellcheck disable=SC2086
    "$RAYO" compare $opts "$ref" "$img" --diff "$name.png" >/dev/null 2>&1 || :
    [ -f "$name.png" ] || : >"$name.png"
    for f in "$name.txt" "$name.json" "$name.png"; do
        if [ "$mode" = record ]; then
            cp "$f" "$DIR/$f"
        elif cmp -s "$f" "$DIR/$f"; then
            same=$((same + 1))
        else
            differ=$((differ + 1))
            echo "DIFFERS: $f"
        fi
    done
done <pairs.txt
if [ "$mode" = record ]; then
    echo "recorded $n pairs ($((3 * n)) reports) in $DIR"
else
    echo "$n pairs: $same reports the same, $differ different"
    [ "$differ" -eq 0 ]
fi
