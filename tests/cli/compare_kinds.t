#!/bin/sh
# compare_kinds.t - compare meets a student who picked the wrong file: an
# image whose kind of picture (black and white, gray, colour) is not the
# reference's gets a note naming both, and, when the reference is one of
# the course's images (named course:ejN or equal to one pixel for
# pixel), naming its exercise and the one the image's kind belongs to;
# an image that is the course's picture while the reference is not gets
# one warning line on stderr that the operands look swapped, and the
# comparison is still made as asked.  The course's pictures are read
# here with netpbm's pngtopnm, not with rayo.
. "$(dirname "$0")/lib.sh"

cd "$TMP" || exit 1
course=$RAYO_SOURCE/data/course

# --- small pictures of each kind, no course image among them ----------------
printf 'P1\n2 2\n1 0\n0 1\n' >bw.pbm
printf 'P2\n2 2\n255\n0 128\n128 255\n' >gray.pgm
printf 'P2\n2 2\n255\n0 255\n255 0\n' >bw_as_gray.pgm
printf 'P3\n2 2\n255\n0 0 0 200 10 10\n10 200 10 255 255 255\n' >colour.ppm
printf 'P3\n2 2\n255\n0 0 0 128 128 128\n128 128 128 255 255 255\n' >gray_as_rgb.ppm

run_capture compare bw.pbm gray.pgm
is "$(grep '^note: your image' out)" \
    "note: your image is gray and the reference is black and white: are they pictures of the same exercise? A black and white picture is exercise 1's, a gray one exercise 2's, a colour one exercise 3's" \
    "gray image, black and white reference: both kinds named"
is "$(cat err)" "" "  nothing on stderr"
run_capture compare --json bw.pbm gray.pgm
grep -q '"kinds": {"reference": "bilevel", "image": "gray"}' out
ok $? "  --json: \"kinds\" without a course exercise"

run_capture compare gray.pgm colour.ppm
is "$(grep '^note: your image' out)" \
    "note: your image is in colour and the reference is gray: are they pictures of the same exercise? A black and white picture is exercise 1's, a gray one exercise 2's, a colour one exercise 3's" \
    "colour image, gray reference"

run_capture compare bw.pbm bw_as_gray.pgm
grep -q '^note: your image' out
ok "$((1 - $?))" "a PGM of only black and white is black and white: no note"
is "$status" 0 "  (the same picture: identical)"
run_capture compare gray.pgm gray_as_rgb.ppm
grep -q '^note: your image' out
ok "$((1 - $?))" "an RGB picture with equal channels is gray: no note"
is "$status" 0 "  (the same picture: identical)"
run_capture compare --json gray.pgm gray_as_rgb.ppm
grep -q '"kinds"' out
ok "$((1 - $?))" "  --json: no \"kinds\" when the kinds agree"

# --- against the course's images ----------------------------------------------
pngtopnm "$course/referencia-catedra-ej1.png" >catedra1.ppm
pngtopnm "$course/referencia-catedra-ej2.png" >catedra2.pgm
rayo -o esfera.pbm

run_capture compare course:ej1 catedra2.pgm
is "$(grep '^note: your image' out)" \
    "note: your image is gray; this reference is exercise 1's black and white sphere (course:ej1): is your image exercise 2's? Compare it with course:ej2" \
    "course:ej1 and a gray image: exercise 2?"
is "$status" 1 "  still compared: inconsistent"
run_capture compare --json course:ej1 catedra2.pgm
grep -q '"kinds": {"reference": "bilevel", "image": "gray", "reference_course": "ej1"}' out
ok $? "  --json: the reference's exercise"

run_capture compare catedra1.ppm catedra2.pgm
grep -q "this reference is exercise 1's black and white sphere (course:ej1)" out
ok $? "the course's EJ1 picture from another file (a PPM) is known by its pixels"

run_capture compare catedra2.pgm esfera.pbm
is "$(grep '^note: your image' out)" \
    "note: your image is black and white; this reference is exercise 2's gray scene (course:ej2): is your image exercise 1's? Compare it with course:ej1" \
    "the course's EJ2 picture and a black and white image: exercise 1?"

run_capture compare course:ej1 esfera.pbm
is "$status:$(cat err)" "0:" "course:ej1 then the student's sphere: no warning, consistent"
grep -q '^note: your image' out
ok "$((1 - $?))" "  and no note on kinds"

# --- swapped operands -------------------------------------------------------------
swapped="rayo: compare: warning: the arguments look swapped: IMAGE, the second, is the course's image of exercise 1, and REFERENCE, the first, is not one of the course's; the reference comes first: rayo compare course:ej1 'esfera.pbm'; compared as asked"
run_capture compare esfera.pbm course:ej1
is "$(cat err)" "$swapped" "IMAGE named course:ej1, REFERENCE a render: one warning line"
is "$status" 0 "  compared as asked (consistent)"
grep -q '^verdict: consistent' out
ok $? "  the report is printed"
run_capture compare esfera.pbm catedra1.ppm
is "$(cat err)" "$swapped" "IMAGE equal to the course's EJ1 picture: the same warning"
run_capture compare catedra1.ppm course:ej1
is "$status:$(cat err)" "0:" "both the course's: no warning"
run_capture compare --lang es esfera.pbm course:ej1
is "$(cat err)" "rayo: compare: atención: parece que los argumentos están al revés: IMAGEN, el segundo, es la imagen de la cátedra del ejercicio 1, y REFERENCIA, el primero, no es ninguna de las de la cátedra; la referencia va primero: rayo compare course:ej1 'esfera.pbm'; igual comparé como pediste" \
    "--lang es: the warning in Spanish"

done_testing
