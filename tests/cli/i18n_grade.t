#!/bin/sh
# i18n_grade.t - grade's own lines in the command's language
# (docs/i18n.md): a program whose picture is moved gets the image
# criterion's sentence in Spanish under --lang es and LANG=es_AR.UTF-8,
# with the plural of each direction ("1 píxel", "2 píxeles", "1 fila")
# and a decimal comma, and in English under --lang en; the human text
# of --csv and --gradescope is in the same language, while the CSV
# header, the PASS/FAIL tokens and Gradescope's field names are the
# same in both.  The programs are the course's correct one with its
# loops moved by sed, so the shift is known exactly.
. "$(dirname "$0")/lib.sh"

# The compiler that built rayo, without its flags: under check-sanitize
# RAYO_CC carries -fsanitize, and a sanitized program cannot map its
# shadow memory within the grader's address-space limit.
CC_STUDENT=${RAYO_CC:-cc}
CC_STUDENT=${CC_STUDENT%% *}
cd "$TMP" || exit 1
src="$RAYO_SOURCE/tests/grade/correct/main.c"
sed -e 's|for (x = -ANCHO / 2; x < ANCHO / 2; x++)|for (x = -ANCHO / 2 - 1; x < ANCHO / 2 - 1; x++)|' \
    "$src" >right.c
sed -e 's|for (x = -ANCHO / 2; x < ANCHO / 2; x++)|for (x = -ANCHO / 2 + 2; x < ANCHO / 2 + 2; x++)|' \
    -e 's|for (y = -ALTO / 2; y < ALTO / 2; y++)|for (y = -ALTO / 2 + 1; y < ALTO / 2 + 1; y++)|' \
    "$src" >both.c
sed -e 's|for (y = -ALTO / 2; y < ALTO / 2; y++)|for (y = -ALTO / 2; y < ALTO / 2 - 1; y++)|' \
    "$src" >short1.c
sed -e 's|for (y = -ALTO / 2; y < ALTO / 2; y++)|for (y = -ALTO / 2; y < ALTO / 2 - 2; y++)|' \
    "$src" >short2.c

# line NAME TEXT: a line of $TMP/out is TEXT exactly.
line() {
    grep -Fqx -- "$2" "$TMP/out"
    ok $? "$1"
}
# has NAME TEXT: $TMP/out holds TEXT somewhere.
has() {
    grep -Fq -- "$2" "$TMP/out"
    ok $? "$1"
}
# grade FILE ARGS...: rayo grade, without valgrind, into $TMP/out.
grade() {
    f=$1
    shift
    run_capture grade --cc "$CC_STUDENT" --no-valgrind "$@" "$f"
}

centre="el centro de la imagen tiene que ser x = 0, y = 0 (x = i - ANCHO/2, y = j - ALTO/2)"
for how in "--lang es" "LANG=es_AR.UTF-8"; do
    if [ "$how" = "--lang es" ]; then
        grade right.c --lang es
    else
        (unset LANGUAGE LC_ALL LC_MESSAGES; LANG=es_AR.UTF-8; export LANG
         "$RAYO" grade --cc "$CC_STUDENT" --no-valgrind right.c \
             >"$TMP/out" 2>"$TMP/err"
         echo $? >"$TMP/status")
        status=$(cat "$TMP/status")
    fi
    is "$status" 1 "moved right, $how: exit 1"
    line "  $how: the image's verdict, a decimal comma" \
        "image      FAIL     no coincide con la imagen de referencia: difieren 498 píxeles (0,16%), 0 de ellos a más de 2 píxeles del borde de la esfera"
    line "  $how: one pixel, singular" \
        "                    la imagen está corrida 1 píxel a la derecha: $centre"
    line "  $how: the skipped valgrind in Spanish" \
        "valgrind   skipped  no se corrió (--no-valgrind)"
    has "  $how: the run's line, a decimal comma" \
        "run        pass     corrió hasta el final en 0,"
done

grade both.c --lang es
line "moved both ways, --lang es: two plurals in one sentence" \
    "                    la imagen está corrida 2 píxeles a la izquierda y 1 fila hacia arriba: $centre"
grade both.c --lang en
line "moved both ways, --lang en: the same sentence in English" \
    "                    the image is moved 2 pixels left and 1 row up: the centre of the picture must be x = 0, y = 0 (x = i - ANCHO/2, y = j - ALTO/2)"
grade right.c --lang en
line "moved right, --lang en: a decimal point" \
    "image      FAIL     inconsistent with the reference: 498 pixels differ (0.16%), 0 of them more than 2 pixels from the sphere's outline"

# The output criterion's count, a whole sentence with plural phrases;
# the summary's verb agrees with the one criterion that failed.
grade short1.c --lang es
line "one row short, --lang es: the count in Spanish, singular" \
    "output     FAIL     el encabezado promete 640x480 = 307200 píxeles pero la salida tiene 306560: 640 de menos, falta exactamente 1 fila"
line "one row short, --lang es: one criterion failed, singular verb" \
    "FAIL: falló 1 de 6 criterios (output), 1 salteado, 1 advertencia"
grade short2.c --lang es
line "two rows short, --lang es: the count in Spanish, plural" \
    "output     FAIL     el encabezado promete 640x480 = 307200 píxeles pero la salida tiene 305920: 1280 de menos, faltan exactamente 2 filas"
grade short1.c --lang en
line "one row short, --lang en: the count in English as before" \
    "output     FAIL     the header promises 640x480 = 307200 pixels but the output has 306560: 640 fewer, exactly 1 row missing"
line "one row short, --lang en: the summary as before" \
    "FAIL: 1 of 6 criteria failed (output), 1 skipped, 1 warning"

# CSV: the header is the same in both languages, the reasons are not.
grade right.c --lang en --csv -
head -n 1 "$TMP/out" >header.en
grade right.c --lang es --csv -
head -n 1 "$TMP/out" >header.es
is "$(cat header.es)" "$(cat header.en)" "CSV: the same header in Spanish"
has "CSV, --lang es: the image's reason in Spanish" \
    ',fail,"no coincide con la imagen de referencia: difieren 498 píxeles (0,16%), 0 de ellos a más de 2 píxeles del borde de la esfera | la imagen está corrida 1 píxel a la derecha: '
has "CSV, --lang es: the skipped valgrind in Spanish" \
    ',skipped,"no se corrió (--no-valgrind)",'

# Gradescope: field names and statuses as always, the output in Spanish.
grade right.c --lang es --gradescope gs.json
cp gs.json "$TMP/out"
has "Gradescope, --lang es: the summary in Spanish" \
    '{"score": 50, "output": "FAIL: 50 de 90 puntos\n'
has "Gradescope, --lang es: the image's test, English names, Spanish output" \
    '{"name": "image", "score": 0, "max_score": 40, "status": "failed", "output": "no coincide con la imagen de referencia: difieren 498 píxeles (0,16%), 0 de ellos a más de 2 píxeles del borde de la esfera\nla imagen está corrida 1 píxel a la derecha: '
grade right.c --lang en --gradescope gs.json
cp gs.json "$TMP/out"
has "Gradescope, --lang en: the image's output in English" \
    '"status": "failed", "output": "inconsistent with the reference: 498 pixels differ (0.16%)'
done_testing
