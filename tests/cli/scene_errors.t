#!/bin/sh
# scene_errors.t - every class of scene file error: one line on stderr,
# "FILE:LINE:COL: found ...; expected ...", exit status 2, nothing on
# standard output, and no output file left behind.
. "$(dirname "$0")/lib.sh"

S="$TMP/s.scene"
OUT="$TMP/out.png"

# bad NAME PATTERN TEXT: TEXT (printf %b) as the scene must be refused.
bad() {
    name=$1 pattern=$2
    printf '%b' "$3" >"$S"
    expect_usage_error "$name" "^rayo: $S:$pattern" render "$S" -o "$OUT"
    ok "$([ ! -e "$OUT" ]; echo $?)" "$name: no output file"
}

bad "unknown keyword" "1:1: unknown keyword 'sphear'; expected camera, shade, samples, depth, background, ambient, light, material, sphere, plane, triangle or mesh$" \
    'sphear 0 0 1 1\n'
bad "unknown keyword after comments" "3:3: unknown keyword 'cube'" \
    '# a comment\n\n  cube 1 # another\n'
bad "missing number" "1:13: found the end of the line; expected the sphere's radius \\(a number\\)$" \
    'sphere 0 0 1\n'
bad "missing number before a comment" "1:14: found the end of the line; expected the sphere's radius" \
    'sphere 0 0 1 # r?\n'
bad "word for a number" "1:12: found 'abc'; expected the z of the sphere's centre \\(a finite decimal number\\)$" \
    'sphere 0 0 abc 1\n'
bad "NaN radius" "1:14: found 'nan'; expected the sphere's radius \\(a finite decimal number\\)$" \
    'sphere 0 0 1 nan\n'
bad "hexadecimal number" "1:8: found '0x1p1'; expected the x of the sphere's centre \\(a finite decimal number\\)$" \
    'sphere 0x1p1 0 3 1\n'
bad "negative radius" "1:14: radius -1 is not accepted; expected a number > 0$" \
    'sphere 0 0 1 -1\n'
bad "zero radius on line 2" "2:14: radius 0 is not accepted" \
    'sphere 0 0 1 1\nsphere 0 0 1 0\n'
bad "zero-length light direction" "1:19: the direction towards the light 0 0 0 has zero length; expected a non-zero vector$" \
    'light directional 0 0 0\n'
bad "zero-length plane normal" "1:13: the plane's normal 0 0 0 has zero length" \
    'plane 0 0 0 0 0 0\n'
bad "zero-length up vector" "1:11: the up vector 0 0 0 has zero length" \
    'camera up 0 0 0\n'
bad "absurd width" "1:13: the image width 100000 is out of range; expected 1 to 65536$" \
    'camera size 100000 480\n'
bad "absurd pixel count" "1:1: 65536x65536 is too many pixels; expected at most 2\\^30$" \
    'camera size 65536 65536\n'
bad "absurd coordinate" "1:8: '1e300' is out of range; expected the x of the sphere's centre between -1e12 and 1e12$" \
    'sphere 1e300 0 1 1\n'
bad "field of view 180" "1:12: field of view 180 is not accepted; expected degrees strictly between 0 and 180$" \
    'camera fov 180\n'
bad "duplicate camera" "2:1: a second 'camera' line; expected one \\(the first is on line 1\\)$" \
    'camera fov 60\ncamera size 10 10\n'
bad "duplicate shade" "3:1: a second 'shade' line" \
    'shade hit\n\nshade phong\n'
bad "unknown camera setting" "1:8: found 'zoom'; expected size, width, height, fov, origin, look-at, up or the end of the 'camera' line$" \
    'camera zoom 2\n'
bad "camera looking at itself" "1:1: look-at point equals the camera origin" \
    'camera origin 1 2 3 look-at 1 2 3\n'
bad "unknown shading mode" "1:7: found 'gouraud'; expected a shading mode: hit, course-gray, course-color, phong or course-tp1$" \
    'shade gouraud\n'
bad "samples out of range" "1:9: the samples per pixel side 17 is out of range; expected 1 to 16$" \
    'samples 17\n'
bad "samples not whole" "1:9: the samples per pixel side 2.5 is not a whole number" \
    'samples 2.5\n'
bad "unknown light kind" "1:7: found 'spot'; expected the kind of light \\(directional or point\\)$" \
    'light spot 0 0 0\n'
bad "negative light colour" "1:25: the light's colour -1 is not accepted; expected a number >= 0$" \
    'light point 0 0 0 color -1\n'
bad "unknown material" "1:25: unknown material 'nope'; expected a name defined on an earlier 'material' line$" \
    'sphere 0 0 1 1 material nope\n'
bad "material defined twice" "2:10: material 'a' is defined again; expected a new name \\(the first is on line 1\\)$" \
    'material a\nmaterial a kd 0.5\n'
bad "material colour above 1" "1:18: the material's colour 2 is not accepted; expected a number from 0 to 1$" \
    'material a color 2 0 0\n'
bad "bad material name" "1:10: found '1abc'; expected a material name" \
    'material 1abc\n'
bad "unknown material setting" "1:12: found 'gloss'; expected color, ka, kd, ks, shininess, reflect or the end of the 'material' line$" \
    'material a gloss 3\n'
bad "trailing word" "1:16: found 'extra'; expected 'material' or the end of the 'sphere' line$" \
    'sphere 0 0 1 1 extra\n'
bad "collinear triangle" "1:1: the triangle's corners are collinear" \
    'triangle 0 0 0 1 1 1 2 2 2\n'
bad "NUL byte" "2:3: found a NUL byte; expected text$" \
    'sphere 0 0 1 1\nsp\000here\n'

python3 -c "print('sphere 0 0 1 1 #' + 'x' * 5000)" >"$S"
expect_usage_error "line too long" "^rayo: $S:1:4097: line is longer than 4096 bytes" render "$S" -o "$OUT"
awk 'BEGIN { for (i = 0; i < 4097; i++) print "light point 0 10 0" }' >"$S"
expect_usage_error "too many lights" "^rayo: $S:4097:1: more than 4096 lights" render "$S" -o "$OUT"
: >"$S" && truncate -s 300M "$S"
expect_usage_error "file too large (sparse, never read)" "^rayo: $S: the file is larger than 268435456 bytes" render "$S" -o "$OUT"
rm -f "$S"

# A file that cannot be read is bad input, as in every command: exit 2.
run_capture render "$TMP/missing.scene" -o "$OUT"
is "$status" 2 "missing scene file: exit status 2"
grep -q "missing.scene: No such file or directory" "$TMP/err"
ok $? "missing scene file: the path and the system's reason"
ok "$([ ! -e "$OUT" ]; echo $?)" "no output file after any refused scene"

# Options that do not fit a scene.
printf 'sphere 0 0 3 1\n' >"$S"
expect_usage_error "--sphere with a scene" "--sphere: cannot be combined with the scene file" render "$S" --sphere 0,0,1,1
expect_usage_error "two scene files" "unexpected argument 'other.scene'" render "$S" other.scene
expect_usage_error "unknown --shade" "--shade: 'flat' is not accepted; expected hit, course-gray, course-color, phong or course-tp1" render "$S" --shade flat
expect_usage_error "--samples 0" "--samples: '0' is out of range; expected 1 to 16" render "$S" --samples 0
expect_usage_error "PGM for a phong render" "--output: '$TMP/x.pgm' is PGM, which cannot hold a phong render; expected .ppm, .png, .bmp or .jpg" render "$S" -o "$TMP/x.pgm"
expect_usage_error "PPM for a hit render" "--format: 'ppm' is not accepted; expected pbm, png, bmp or jpeg for a hit render" render "$S" --shade hit --format ppm
done_testing
