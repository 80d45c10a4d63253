#!/bin/sh
# docs-images.sh - makes the pictures of docs/compare.md from the student
# programs of tests/grade (real submissions with one mistake each, written
# for the tests) and from `rayo compare --diff`: a sheet per exercise of
# what each mistake looks like, labelled with the diagnosis rayo gives,
# and two difference pictures.
#
#   scripts/docs-images.sh [BUILD]     (BUILD defaults to build)
#
# Needs a C compiler and the Netpbm tools (pamscale, pbmtext, pnmcat).
# The pictures are committed; run this again when a diagnosis changes.
set -eu
cd "$(dirname "$0")/.."
rayo=${1:-build}/rayo
out=docs/images
tmp=$(mktemp -d "${TMPDIR:-/tmp}/rayo-docs.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
[ -x "$rayo" ] || { echo "docs-images.sh: build $rayo first (make)" >&2; exit 1; }

# image NAME: the output of tests/grade/NAME, negative samples read as 0.
image() {
    cc -std=c99 -w -o "$tmp/$1" "tests/grade/$1/main.c" -lm
    (cd "$tmp" && "./$1") | sed 's/-[0-9][0-9]*/0/g' >"$tmp/$1.pnm"
}

# tile NAME LABEL: the image at a quarter of its size over its label.
tile() {
    pamscale -xsize 160 -ysize 120 "$tmp/$1.pnm" | pamtopnm >"$tmp/$1.small"
    pbmtext -builtin fixed "$2" | pnmpad -white -left 2 -right 2 -top 2 |
        pamscale -xsize 160 -ysize 16 | pnminvert | ppmtoppm >"$tmp/$1.label"
    pnmcat -tb "$tmp/$1.small" "$tmp/$1.label" | ppmtoppm >"$tmp/$1.tile"
}

# sheet OUT COLUMNS NAME=LABEL...: tiles in rows of COLUMNS.
sheet() {
    file=$1 columns=$2
    shift 2
    rows="" row="" n=0 k=0
    for item in "$@"; do
        name=${item%%=*} label=${item#*=}
        image "$name"
        tile "$name" "$label"
        row="$row $tmp/$name.tile"
        n=$((n + 1))
        if [ "$n" -eq "$columns" ]; then
            k=$((k + 1))
            pnmcat -lr -white $row >"$tmp/row$k.ppm"
            rows="$rows $tmp/row$k.ppm" row="" n=0
        fi
    done
    if [ -n "$row" ]; then
        k=$((k + 1))
        pnmcat -lr -white $row >"$tmp/row$k.ppm"
        rows="$rows $tmp/row$k.ppm"
    fi
    pnmcat -tb -jleft -black $rows | pnmtopng -compression 9 >"$file"
}

sheet "$out/mistakes-ej2.png" 4 \
    ej2_correct=correct ej2_no_shadows=no-shadows \
    ej2_self_shadow=self-shadow ej2_no_ambient=no-ambient \
    ej2_light_reversed=light-reversed ej2_no_ln_test=no-ln-test \
    ej2_far_root=far-root ej2_unnormalised_normal=unnormalised-normal
sheet "$out/mistakes-ej3.png" 4 \
    ej3_correct=correct ej3_channels_bgr=channels-swapped \
    ej3_ambient_not_absorbed=ambient-not-absorbed \
    ej3_point_as_directional=point-as-directional \
    ej3_ka_kd_swapped=ka-kd-swapped ej3_first_sphere=first-sphere \
    ej3_no_shadows=no-shadows ej3_wrapped=wrapped \
    ej3_light_reversed=light-reversed ej3_no_ln_test=no-ln-test \
    ej3_far_root=far-root ej3_unnormalised_normal=unnormalised-normal

# The difference pictures: a correct EJ2 render against the course's
# reference (consistent: amber outlines and shadow edges), and EJ3 with
# its channels printed in the wrong order (red: unexplained).
"$rayo" render examples/ej2.scene -o "$tmp/ej2.pgm"
"$rayo" compare data/course/referencia-catedra-ej2.png "$tmp/ej2.pgm" \
    --diff "$out/tone-consistent.png" >/dev/null
"$rayo" compare data/course/referencia-catedra-ej3.png \
    "$tmp/ej3_channels_bgr.pnm" --diff "$out/tone-diff.png" >/dev/null || true
echo "docs-images.sh: wrote $out/mistakes-ej2.png, mistakes-ej3.png, tone-consistent.png, tone-diff.png"
