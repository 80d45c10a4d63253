#!/bin/sh
# grade_functions.t - `rayo grade --exercise ej2|ej3` and its functions
# criterion on the fixtures of tests/grade/functions (the statement's
# functions, one mistake each) and on the student corpus of tests/grade:
# the reason lines name the mistake in the student's terms, a crash or a
# hang is pinned on its call, and the other functions are still called.
# ej2 and ej3 must be in the registry and their corpus there: when a help
# text or a folder changes, the test fails rather than skipping.
. "$(dirname "$0")/lib.sh"

FIX="$RAYO_SOURCE/tests/grade/functions"
STUDENTS="$RAYO_SOURCE/tests/grade"

# grade EXERCISE FILE [OPTIONS...]: the report in $TMP/out, the
# functions criterion's result in $result and its lines in $TMP/functions.
grade() {
    exercise=$1 file=$2
    shift 2
    run_capture grade --no-valgrind --exercise "$exercise" "$@" "$file"
    awk '$1 ~ /^(compile|run|output|image|valgrind)$/ { inside = 0 }
         $1 == "functions" { inside = 1; sub(/^functions +[A-Za-z]+ +/, "") }
         inside { sub(/^ +/, ""); print }' "$TMP/out" >"$TMP/functions"
    result=$(awk '$1 == "functions" { print $2 }' "$TMP/out")
}

# says LINE NAME: the functions criterion has exactly this line.
says() {
    found=0
    grep -Fxq -- "$1" "$TMP/functions" || found=1
    ok "$found" "$2"
    [ "$found" -eq 0 ] || sed 's/^/#   /' "$TMP/functions"
}

# right NAME N NAME: the one line that sums up the passing functions
# names NAME with its N known inputs.
right() {
    found=0
    grep -q "^right on all their known inputs: \(.*, \)\{0,1\}$1 ($2)\(,\|\$\)" "$TMP/functions" || found=1
    ok "$found" "$3"
    [ "$found" -eq 0 ] || sed 's/^/#   /' "$TMP/functions"
}

registered() {
    rayo grade --help 2>/dev/null | grep -q "^  $1 "
}

# The channel (issue 25): a submission whose functions are all wrong and
# that prints the expected results on its first call fails, named.
grade ej1 "$STUDENTS/hostile/forge_functions/main.c"
is "$result" FAIL "forge_functions: the functions fail"
says "the program wrote into the grader's channel: 12 lines posing as the harness's results (the first: \"result producto_interno 0 32\"); a function's results come from what it returns, never from what it prints" \
    "forge_functions: the channel finding, first"
is "$(head -n 1 "$TMP/functions" | cut -c1-44)" "the program wrote into the grader's channel:" \
    "forge_functions: the finding is the first line"
says "norma(3, 4, 12) returned 169; expected 13" \
    "forge_functions: the real results are judged"
says "intersecta_esfera(0, 0, 1) returned 1; expected 0 (this ray misses the sphere)" \
    "forge_functions: intersecta_esfera's real result"

if registered ej2; then
    grade ej2 "$FIX/ej2_right.c"
    is "$result" pass "ej2 right: the functions pass"
    is "$(wc -l <"$TMP/functions" | tr -d ' ')" 1 "ej2 right: the eight functions in one line"
    right distancia_esfera 6 "ej2 right: distancia_esfera"
    right computar_intensidad 11 \
        "ej2 right: computar_intensidad"

    grade ej2 "$FIX/ej2_near_root_always.c"
    is "$result" FAIL "ej2 near root behind the origin: fails"
    says "distancia_esfera((0, 0, 1), 2, (0, 0, 0), (0, 0, 1)) returned -1, a root behind the origin (t < 0), for a ray that starts inside the sphere; expected 3: when beta - sqrt(delta) <= 0 the answer is beta + sqrt(delta)" \
        "ej2 near root behind the origin: named"

    grade ej2 "$FIX/ej2_normal_crash.c"
    says "normal_esfera(n, (1, 2, 3), 2, (1, 2, 5)) crashed: segmentation fault (SIGSEGV)" \
        "ej2 crash: pinned on the call"
    right distancia_esfera 6 \
        "ej2 crash: the functions called before it are judged"

    mkdir "$TMP/scratch"
    TMPDIR="$TMP/scratch" grade ej2 "$FIX/ej2_norma_hangs.c" --timeout 1
    says "norma((3, 4, 12)) did not return within 1 seconds" \
        "ej2 hang: pinned on the call"
    is "$(ls -A "$TMP/scratch")" "" "ej2 hang: the temporary directory is removed"

    grade ej2 "$FIX/ej2_no_intensidad.c"
    says "computar_intensidad: not defined; the statement asks for int computar_intensidad(const float cs[][3], const float rs[], size_t n_esferas, const float luz[3], const float o[3], const float d[3])" \
        "ej2 missing function: named with the statement's prototype"
    right normal_esfera 2 \
        "ej2 missing function: the others are called"

    if [ -d "$STUDENTS/ej2_correct" ]; then
        grade ej2 "$STUDENTS/ej2_correct/main.c"
        is "$result" pass "ej2_correct: the functions pass"

        grade ej2 "$STUDENTS/ej2_first_sphere/main.c"
        says "computar_intensidad on 2 spheres, the far one first: (0, 0, 4) r 1, (0, -0.3, 2) r 0.5, luz = (0.5773503, 0.5773503, -0.5773503), along d = (0.04993762, 0, 0.9987524) returned 172, the intensity of the sphere at (0, 0, 4); expected 232, the intensity of the nearest one, at (0, -0.3, 2): a farther sphere covers a nearer one: the pixel shows the sphere with the smallest t that distancia_esfera returns, not the first one of the array the ray meets" \
            "ej2_first_sphere: the nearest sphere, not the first"

        grade ej2 "$STUDENTS/ej2_far_root/main.c"
        says "distancia_esfera((0, 0, 2), 0.8, (0, 0, 0), (0, 0, 1)) returned the far root 2.8 for a ray that meets the sphere at t = 1.2 first: beta - sqrt(delta) when it is > 0" \
            "ej2_far_root: the far root named"

        grade ej2 "$STUDENTS/ej2_wrong_signature/main.c"
        grep -q "^normal_esfera: the signature differs from the statement's void normal_esfera(float normal\[3\], const float c\[3\], float r, const float p\[3\]) (the compiler says: .*); not called$" "$TMP/functions"
        ok $? "ej2_wrong_signature: reported as ej1's are"
        right computar_intensidad 11 \
            "ej2_wrong_signature: the others are still called"
    else
        ok 1 "tests/grade/ej2_* are there (the corpus is tested)"
    fi
else
    ok 1 "ej2 is in the registry (grade --help lists it)"
fi

if registered ej3; then
    grade ej3 "$FIX/ej3_right.c"
    is "$result" pass "ej3 right: the functions pass"
    is "$(wc -l <"$TMP/functions" | tr -d ' ')" 2 "ej3 right: the fifteen functions in one line, and the shadows' reading"
    says "computar_intensidad: only a sphere between the point and a point light casts a shadow, not one beyond the light: one of the statement's two readings, accepted; the other, to the letter (an object in the light's direction casts a shadow), is accepted too, and the course's scenes look the same either way" \
        "ej3 right: the shadows' reading named"
    right arreglo_agregar 2 "ej3 right: arreglo_agregar"
    right color_imprimir 4 "ej3 right: color_imprimir"

    grade ej3 "$FIX/ej3_realloc_direct.c"
    says "arreglo_agregar lost the array when realloc failed: a->v became NULL; keep realloc's result in a temporary and assign it only when it is not NULL" \
        "ej3 realloc into a->v: the lost array named"

    grade ej3 "$FIX/ej3_beyond_light.c"
    is "$result" pass "ej3 a sphere beyond a point light casts a shadow: accepted"
    says "computar_intensidad: a sphere beyond a point light casts a shadow: the statement's rule (an object in the light's direction casts a shadow) read to the letter, accepted; the other reading, a shadow only from a sphere between the point and the light, is accepted too, and the course's scenes look the same either way" \
        "ej3 a sphere beyond a point light: the reading named"

    grade ej3 "$FIX/ej3_imprimir_rounds.c"
    is "$result" pass "ej3 color_imprimir rounding: accepted"
    says "color_imprimir: rounds 255 c to the nearest integer (0.999 prints 255) instead of taking its integer part (254): a reading of the statement's 'scale 0..1 to the integers 0..255', accepted" \
        "ej3 color_imprimir rounding: the reading named"

    grade ej3 "$FIX/ej3_double_vector.c"
    says "vector_t: its member x is not of the statement's type; the statement gives typedef struct { float x, y, z; } vector_t;" \
        "ej3 double members: the type named"
    right color_imprimir 4 \
        "ej3 double members: the functions without vector_t are called"

    if [ -d "$STUDENTS/ej3_realloc_loses" ]; then
        grade ej3 "$STUDENTS/ej3_correct/main.c"
        is "$result" pass "ej3_correct: the functions pass"

        grade ej3 "$STUDENTS/ej3_realloc_loses/main.c"
        says "arreglo_agregar lost the array when realloc failed: a->v became NULL; keep realloc's result in a temporary and assign it only when it is not NULL" \
            "ej3_realloc_loses: the lost array named"

        grade ej3 "$STUDENTS/ej3_write_past_end/main.c"
        says "arreglo_agregar wrote past the end of a->v: after three additions to an empty array its last realloc asked for 16 bytes, and a pointer was written beyond them; ask for (a->n + 1) * sizeof(void *) before writing a->v[a->n]" \
            "ej3_write_past_end: the write past the block named"

        grade ej3 "$STUDENTS/ej3_first_sphere/main.c"
        grep -q "not the first one of the array the ray meets" "$TMP/functions"
        ok $? "ej3_first_sphere: the nearest sphere, not the first"
    else
        ok 1 "tests/grade/ej3_* are there (the corpus is tested)"
    fi
else
    ok 1 "ej3 is in the registry (grade --help lists it)"
fi

done_testing
