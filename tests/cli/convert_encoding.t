#!/bin/sh
# convert_encoding.t - convert keeps a Netpbm input's encoding: plain
# (P1-P3) stays plain, raw (P4-P6) stays raw, a PNG becomes raw; --plain
# and --raw decide otherwise, and both at once are refused.  Encodings are
# read from the output's magic number and from pamfile; pixels are checked
# against Netpbm's own conversions.
. "$(dirname "$0")/lib.sh"

cd "$TMP" || exit 1
# Inputs of every kind, made by Netpbm: plain and raw PBM, PGM, PPM; PNG.
rayo -W 13 -H 7 --raw -o r.pbm
pnmtoplainpnm r.pbm >p.pbm
rayo render "$RAYO_SOURCE/examples/ej2.scene" -W 13 -H 7 --raw -o r.pgm
pnmtoplainpnm r.pgm >p.pgm
rayo render "$RAYO_SOURCE/examples/ej3.scene" -W 13 -H 7 --raw -o r.ppm
pnmtoplainpnm r.ppm >p.ppm
pnmtopng r.ppm >in.png 2>/dev/null

magic() { head -c 2 "$1"; }
# expect_magic NAME WANT ARGS...: convert ARGS, then OUT's magic is WANT
expect_magic() {
    name=$1 want=$2
    shift 2
    run_capture convert "$@"
    is "$status" 0 "$name: exit 0"
    eval "last=\${$#}"
    is "$(magic "$last")" "$want" "$name: $want"
}

for ext in pbm pgm ppm; do
    case $ext in pbm) P=1 ;; pgm) P=2 ;; ppm) P=3 ;; esac
    R=$((P + 3))
    expect_magic "plain $ext to .$ext" "P$P" p.$ext o-p.$ext
    expect_magic "raw $ext to .$ext" "P$R" r.$ext o-r.$ext
    expect_magic "plain $ext --raw" "P$R" --raw p.$ext o-pr.$ext
    expect_magic "raw $ext --plain" "P$P" --plain r.$ext o-rp.$ext
    pamtopnm <o-p.$ext | cmp -s - r.$ext
    ok $? "plain $ext kept plain: the same pixels as the raw input"
    pamtopnm <o-pr.$ext | cmp -s - r.$ext
    ok $? "plain $ext --raw: byte for byte Netpbm's raw $ext"
done
# Across formats the encoding is kept too.
expect_magic "plain PBM to .ppm" P3 p.pbm o.ppm
expect_magic "raw PGM to .pbm" P4 r.pgm o.pbm
is "$(pamfile o.pbm | sed 's/.*:\t*//')" "PBM raw, 13 by 7" "  pamfile agrees: PBM raw"
# PNG input: raw unless --plain.
expect_magic "PNG to .ppm" P6 in.png o-png.ppm
pngtopnm in.png | cmp -s - o-png.ppm
ok $? "  byte for byte pngtopnm's"
expect_magic "PNG --plain to .ppm" P3 --plain in.png o-pngp.ppm
# Standard output without --format: the Netpbm format that holds it, in the
# input's encoding.
rayo convert p.pgm - >o-stdout 2>"$TMP/err"
is "$(magic o-stdout)" P2 "plain PGM to '-': plain PGM"
rayo convert r.pgm - >o-stdout 2>"$TMP/err"
is "$(magic o-stdout)" P5 "raw PGM to '-': raw PGM"
# -v says what it wrote.
run_capture convert -v p.ppm o-v.ppm
grep -q "wrote plain ppm" "$TMP/err"
ok $? "--verbose: wrote plain ppm"
expect_usage_error "--plain --raw" "--plain and --raw: give one of them" \
    convert --plain --raw p.pbm x.pbm
expect_usage_error "--raw with PNG" "--raw: applies only to PBM, PGM and PPM" \
    convert --raw p.pbm x.png
ok "$([ ! -e x.pbm ] && [ ! -e x.png ]; echo $?)" "refused: no file"
run_capture convert --help
grep -q -- "--raw" "$TMP/out"
ok $? "--help describes --raw"
done_testing
