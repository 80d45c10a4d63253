#!/bin/sh
# convert.t - `rayo convert` against the Netpbm tools.  Images made by
# Netpbm (pbmtext, pgmramp, ppmrainbow, pamdepth) and by awk (16-bit
# samples) are written by Netpbm in every form rayo reads: raw, plain
# (pnmtoplainpnm), PNG of every colour type and depth pnmtopng makes
# (1/2/4/8/16-bit gray, palette, RGB 8/16, gray+alpha, RGBA 8/16,
# interlaced); rayo converts each back to Netpbm and the result must be
# the image Netpbm itself decodes (pamtopnm, pngtopnm -mix
# -background=white for alpha), byte for byte after pamtopnm makes both
# raw.  Then rayo's own writers round-trip, and the command's options,
# standard input and output, --verbose and exit statuses.
. "$(dirname "$0")/lib.sh"

# canon FILE: the image as Netpbm's raw PNM (one byte layout for both).
canon() { pamtopnm <"$1"; }

# same_image NAME A B: A and B hold the same image.
same_image() {
    canon "$2" >"$TMP/a.canon" 2>/dev/null
    canon "$3" >"$TMP/b.canon" 2>/dev/null
    cmp -s "$TMP/a.canon" "$TMP/b.canon"
    ok $? "$1"
}

# --- sources, made by Netpbm and awk -----------------------------------
pbmtext -builtin fixed "Rayo" >"$TMP/text.pbm" 2>/dev/null
pgmramp -diagonal 29 17 >"$TMP/ramp.pgm"
pamdepth 1000 "$TMP/ramp.pgm" >"$TMP/ramp1000.pgm"
pamdepth 15 "$TMP/ramp.pgm" >"$TMP/ramp15.pgm"
pamdepth 3 "$TMP/ramp.pgm" >"$TMP/ramp3.pgm"
ppmrainbow -width=23 -height=19 red green blue >"$TMP/rainbow.ppm"
pamdepth 7 "$TMP/rainbow.ppm" >"$TMP/rainbow7.ppm"
pgmramp -lr 23 19 >"$TMP/alpha.pgm"
awk 'BEGIN { print "P2 29 7 65535"
  for (y = 0; y < 7; y++) for (x = 0; x < 29; x++)
    print (x * 2731 + y * 9973 + x * y * 17) % 65536 }' >"$TMP/gray16.pgm"
awk 'BEGIN { print "P3 29 7 65535"
  for (y = 0; y < 7; y++) for (x = 0; x < 29; x++)
    print (x * 2731 + y * 9973) % 65536, (x * 577 + y * 31) % 65536,
          (x * y * 101) % 65536 }' >"$TMP/rgb16.ppm"
awk 'BEGIN { print "P2 29 7 65535"
  for (y = 0; y < 7; y++) for (x = 0; x < 29; x++)
    print (x * 4099 + y * 1237 + x * y * 31) % 65536 }' >"$TMP/alpha16.pgm"

# --- Netpbm files: raw and plain ---------------------------------------
for src in text.pbm ramp.pgm ramp1000.pgm ramp15.pgm rainbow.ppm \
    rainbow7.ppm gray16.pgm rgb16.ppm; do
    ext=${src##*.}
    pamtopnm <"$TMP/$src" >"$TMP/raw.$ext"
    pnmtoplainpnm <"$TMP/$src" >"$TMP/plain.$ext"
    for form in raw plain; do
        run_capture convert "$TMP/$form.$ext" "$TMP/out.$ext"
        is "$status" 0 "$form $src: converted"
        same_image "$form $src: same image as Netpbm's" "$TMP/$src" \
            "$TMP/out.$ext"
    done
done

# --- PNG files written by pnmtopng -------------------------------------
# png_case NAME EXPECTED-TYPE PNMTOPNG-ARGS...: rayo reads what pnmtopng
# wrote as pngtopnm (compositing over white) does.
png_case() {
    name=$1 want=$2
    shift 2
    pnmtopng "$@" >"$TMP/in.png" 2>/dev/null
    case $(file -b "$TMP/in.png") in
    *"$want"*) ok 0 "$name: pnmtopng wrote $want" ;;
    *) ok 1 "$name: pnmtopng wrote $want (got $(file -b "$TMP/in.png"))" ;;
    esac
    pngtopnm -mix -background=white "$TMP/in.png" >"$TMP/netpbm.pnm" \
        2>/dev/null
    run_capture convert --format "$(pamfile "$TMP/netpbm.pnm" |
        sed -n 's/.*\(P[BGP]M\).*/\1/p' | tr 'A-Z' 'a-z')" \
        "$TMP/in.png" "$TMP/out.pnm"
    is "$status" 0 "$name: converted"
    same_image "$name: same image as pngtopnm's" "$TMP/netpbm.pnm" \
        "$TMP/out.pnm"
}
png_case "1-bit gray" "1-bit grayscale" "$TMP/text.pbm"
png_case "2-bit gray" "2-bit grayscale" "$TMP/ramp3.pgm"
png_case "4-bit gray" "4-bit grayscale" "$TMP/ramp15.pgm"
png_case "8-bit gray" "8-bit grayscale" "$TMP/ramp.pgm"
png_case "16-bit gray" "16-bit grayscale" "$TMP/gray16.pgm"
png_case "8-bit RGB" "8-bit/color RGB" -force "$TMP/rainbow.ppm"
png_case "16-bit RGB" "16-bit/color RGB" "$TMP/rgb16.ppm"
ppmmake red 3 2 >"$TMP/red.ppm"
ppmmake blue 3 2 >"$TMP/blue.ppm"
pnmcat -lr "$TMP/red.ppm" "$TMP/blue.ppm" >"$TMP/two.ppm"
png_case "1-bit palette" "1-bit colormap" "$TMP/two.ppm"
# palette_image N: a 16x4 image using N distinct colours.
palette_image() {
    awk -v n="$1" 'BEGIN { print "P3 16 4 255"
      for (y = 0; y < 4; y++) for (x = 0; x < 16; x++) {
        i = (x + 16 * y) % n
        print (i * 37 + 11) % 256, (i * 91 + 7) % 256, 255 - i } }'
}
palette_image 4 >"$TMP/four.ppm"
palette_image 16 >"$TMP/sixteen.ppm"
png_case "2-bit palette" "2-bit colormap" "$TMP/four.ppm"
png_case "4-bit palette" "4-bit colormap" "$TMP/sixteen.ppm"
png_case "8-bit palette" "8-bit colormap" "$TMP/rainbow.ppm"
png_case "palette with alpha" "8-bit colormap" -alpha="$TMP/alpha.pgm" \
    "$TMP/rainbow.ppm"
png_case "8-bit gray+alpha" "8-bit gray+alpha" -force \
    -alpha="$TMP/alpha.pgm" "$TMP/alpha.pgm"
png_case "16-bit gray+alpha" "16-bit gray+alpha" -force \
    -alpha="$TMP/alpha16.pgm" "$TMP/gray16.pgm"
png_case "8-bit RGBA" "8-bit/color RGBA" -force -alpha="$TMP/alpha.pgm" \
    "$TMP/rainbow.ppm"
png_case "16-bit RGBA" "16-bit/color RGBA" -force \
    -alpha="$TMP/alpha16.pgm" "$TMP/rgb16.ppm"
png_case "transparent colour (tRNS)" "colormap" -transparent=red \
    "$TMP/two.ppm"
png_case "interlaced 1-bit gray" "interlaced" -interlace "$TMP/text.pbm"
png_case "interlaced RGB" "interlaced" -interlace -force "$TMP/rainbow.ppm"
png_case "interlaced 16-bit RGBA" "interlaced" -interlace -force \
    -alpha="$TMP/alpha16.pgm" "$TMP/rgb16.ppm"

# --- rayo's writers round-trip ------------------------------------------
for src in text.pbm ramp.pgm ramp1000.pgm rainbow.ppm rgb16.ppm; do
    ext=${src##*.}
    for plain in "" --plain; do
        run_capture convert $plain "$TMP/$src" "$TMP/out.$ext"
        is "$status" 0 "$src${plain:+ $plain}: written"
        run_capture convert "$TMP/out.$ext" "$TMP/back.$ext"
        same_image "$src${plain:+ $plain}: read back unchanged" \
            "$TMP/$src" "$TMP/back.$ext"
    done
    run_capture convert "$TMP/$src" "$TMP/out.png"
    run_capture convert "$TMP/out.png" "$TMP/back.$ext"
    pngtopnm "$TMP/out.png" >"$TMP/netpbm.pnm" 2>/dev/null
    same_image "$src via PNG: pngtopnm agrees with rayo" "$TMP/netpbm.pnm" \
        "$TMP/back.$ext"
done
# PBM -> PNG -> PBM is exact, and the PNG is 1-bit gray.
run_capture convert "$TMP/text.pbm" "$TMP/text.png"
case $(file -b "$TMP/text.png") in *"1-bit grayscale"*) r=0 ;; *) r=1 ;; esac
ok $r "PBM becomes 1-bit gray PNG"
run_capture convert "$TMP/text.png" "$TMP/text-back.pbm"
cmp -s "$TMP/text-back.pbm" "$(pamtopnm <"$TMP/text.pbm" >"$TMP/t.pbm" &&
    echo "$TMP/t.pbm")"
ok $? "PBM -> PNG -> PBM is byte for byte Netpbm's raw PBM"

# --- layout conversions pick the target's layout --------------------------
run_capture convert "$TMP/rainbow.ppm" "$TMP/mask.pbm"
is "$(pamfile "$TMP/mask.pbm" | sed 's/.*:\t*//')" "PBM raw, 23 by 19" \
    "colour to .pbm is a bilevel mask"
run_capture convert "$TMP/text.pbm" "$TMP/text.pgm"
is "$(sed -n 3p "$TMP/text.pgm")" "255" "bilevel to .pgm has maxval 255"
run_capture convert --plain "$TMP/gray16.pgm" "$TMP/g.ppm"
is "$(sed -n 1p "$TMP/g.ppm")" "P3" "--plain writes P3"
is "$(sed -n 4p "$TMP/g.ppm" | awk '{ print $1, $2, $3 }')" "0 0 0" \
    "gray repeated in three channels"

# --- standard input and output ------------------------------------------
status=0
rayo convert - - <"$TMP/rainbow.ppm" >"$TMP/out" 2>"$TMP/err" || status=$?
is "$status" 0 "stdin to stdout"
is "$(head -c 2 "$TMP/out")" "P6" "stdout without --format: the Netpbm format that holds it"
status=0
rayo convert --format png - - <"$TMP/text.pbm" >"$TMP/out.png" \
    2>"$TMP/err" || status=$?
is "$status" 0 "--format png to stdout"
pngtopnm "$TMP/out.png" >"$TMP/out.pbm" 2>/dev/null
same_image "PNG on stdout is the image" "$TMP/text.pbm" "$TMP/out.pbm"

# --- --verbose reports what was read, with trailing data ----------------
{ cat "$TMP/ramp.pgm"; printf 'xyz'; } >"$TMP/trailing.pgm"
run_capture convert --verbose "$TMP/trailing.pgm" "$TMP/out.pgm"
is "$status" 0 "trailing data is accepted"
grep -q "raw pgm, 29x17, gray, maxval 255; 3 bytes after the image" "$TMP/err"
ok $? "--verbose reports format, size, maxval and 3 trailing bytes"
same_image "trailing data does not change the image" "$TMP/ramp.pgm" \
    "$TMP/out.pgm"

# --- usage and failures -------------------------------------------------
run_capture convert --help
is "$status" 0 "--help exits 0"
grep -q "usage: rayo convert" "$TMP/out"
ok $? "--help prints the usage"
expect_usage_error "one argument" "expected IN and OUT" convert "$TMP/text.pbm"
expect_usage_error "unknown extension" "cannot tell the format of" \
    convert "$TMP/text.pbm" "$TMP/out.gif"
ok "$([ ! -e "$TMP/out.gif" ]; echo $?)" "unknown extension: no file"
expect_usage_error "bad --format" "--format: 'gif'" \
    convert --format gif "$TMP/text.pbm" "$TMP/out.pbm"
expect_usage_error "--plain with PNG" "--plain: applies only" \
    convert --plain "$TMP/text.pbm" "$TMP/x.png"
expect_usage_error "unknown option" "unknown option" \
    convert --frobnicate "$TMP/text.pbm" "$TMP/x.pbm"
run_capture convert "$TMP/missing.pbm" "$TMP/x.pbm"
is "$status" 2 "missing input: exit 2"
grep -q "missing.pbm: No such file or directory" "$TMP/err"
ok $? "missing input: file and reason"
run_capture convert "$TMP/text.pbm" "$TMP/no/such/dir/x.pbm"
is "$status" 1 "unwritable output: exit 1"
echo "keep" >"$TMP/keep.pbm"
run_capture convert "$RAYO_SOURCE/tests/data/malformed/p6-truncated.ppm" \
    "$TMP/keep.pbm"
is "$status" 2 "bad input: exit 2"
is "$(cat "$TMP/keep.pbm")" "keep" "bad input: an existing OUT is untouched"
done_testing
