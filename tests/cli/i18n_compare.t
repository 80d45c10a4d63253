#!/bin/sh
# i18n_compare.t - the comparison report's text in the command's language
# (docs/i18n.md): under --lang es and LANG=es_AR.UTF-8 (no Spanish locale
# generated) the verdict, the diagnosis, the counts with a plural ("1
# fila", "2 filas") and the percentages with a decimal comma are Spanish;
# under --lang en the same report is English; --json is English in every
# language (keys, verdict tokens, the diagnosis's text).  The images are
# made here: rayo's render of the sphere turned upside down by pnmflip,
# and the render of scene 2 moved up one and two rows by pamcut.
. "$(dirname "$0")/lib.sh"

REF="$RAYO_SOURCE/data/course/referencia-catedra-ej1.png"
rayo -o "$TMP/sphere.pbm"
pnmflip -tb "$TMP/sphere.pbm" >"$TMP/flip.pbm"
rayo render "$RAYO_SOURCE/examples/ej2.scene" -o "$TMP/ej2.pgm"
pamcut -top 1 "$TMP/ej2.pgm" | pnmpad -bottom=1 -black >"$TMP/up1.pgm"
pamcut -top 2 "$TMP/ej2.pgm" | pnmpad -bottom=2 -black >"$TMP/up2.pgm"

# line NAME PATTERN: a line of $TMP/out is PATTERN exactly.
line() {
    grep -Fqx -- "$2" "$TMP/out"
    ok $? "$1"
}

# The flipped sphere, in Spanish both ways of asking.
for how in "--lang es" "LANG=es_AR.UTF-8"; do
    if [ "$how" = "--lang es" ]; then
        run_capture compare --lang es "$REF" "$TMP/flip.pbm"
    else
        (unset LANGUAGE LC_ALL LC_MESSAGES; LANG=es_AR.UTF-8; export LANG
         rayo compare "$REF" "$TMP/flip.pbm" >"$TMP/out" 2>"$TMP/err"
         echo $? >"$TMP/status")
        status=$(cat "$TMP/status")
    fi
    is "$status" 1 "flipped sphere, $how: exit 1"
    line "  $how: the verdict in Spanish" "veredicto: no coincide"
    line "  $how: the diagnosis in Spanish" \
        "diagnóstico: la imagen está dada vuelta (invertida verticalmente): filas escritas de abajo hacia arriba, o y sin cambiar de signo en la dirección del rayo"
    line "  $how: counts and a percentage with a decimal comma" \
        "píxeles distintos: 126882 de 307200 (41,303 %): 63601 negros solo en la referencia, 63281 negros solo en la imagen"
    line "  $how: the IoU with a decimal comma" "IoU de las regiones negras: 0,0095"
    is "$(wc -c <"$TMP/err" | tr -d ' ')" 0 "  $how: nothing on stderr"
done

# The same report in English.
run_capture compare --lang en "$REF" "$TMP/flip.pbm"
is "$status" 1 "flipped sphere, --lang en: exit 1"
line "  --lang en: the verdict in English" "verdict: inconsistent"
line "  --lang en: the diagnosis in English" \
    "diagnosis: the image is upside down (flipped vertically): rows written from the bottom up, or y not negated in the ray direction"
line "  --lang en: a decimal point" \
    "mismatched pixels: 126882 of 307200 (41.303%): 63601 black only in the reference, 63281 black only in the image"

# Plurals: one row and two rows, in a gray picture.
run_capture compare --lang es "$TMP/ej2.pgm" "$TMP/up1.pgm"
line "one row up, --lang es: singular" \
    "diagnóstico: la imagen está corrida 1 fila hacia arriba: revisá la grilla de píxeles, x = i - ANCHO/2 y las filas desde y = ALTO/2 arriba"
line "  one level (of 255), singular" \
    "comparado: valores de gris; un píxel difiere cuando se aparta más de 1 nivel (de 255)"
line "  the channel's row in Spanish, decimal commas" \
    "gris   con diferencia: 17224 (5,607 %), diferencia máxima 255, RMSE 9,086, PSNR 28,96 dB"
run_capture compare --lang es "$TMP/ej2.pgm" "$TMP/up2.pgm"
line "two rows up, --lang es: plural" \
    "diagnóstico: la imagen está corrida 2 filas hacia arriba: revisá la grilla de píxeles, x = i - ANCHO/2 y las filas desde y = ALTO/2 arriba"
run_capture compare --lang es "$TMP/ej2.pgm" "$TMP/ej2.pgm" --levels 2
line "two levels, --lang es: plural" \
    "comparado: valores de gris; un píxel difiere cuando se aparta más de 2 niveles (de 255)"
run_capture compare --lang en "$TMP/ej2.pgm" "$TMP/up1.pgm"
line "one row up, --lang en" \
    "diagnosis: the picture is moved 1 row up: check the pixel grid, x = i - ANCHO/2 and rows from y = ALTO/2 at the top"

# --json does not change with the language.
rayo compare --lang es "$REF" "$TMP/flip.pbm" --json >"$TMP/es.json"
rayo compare --lang en "$REF" "$TMP/flip.pbm" --json >"$TMP/en.json"
cmp -s "$TMP/es.json" "$TMP/en.json"
ok $? "--json: the same bytes under --lang es and --lang en"
is "$(jq -r .verdict "$TMP/es.json")" inconsistent "  the verdict token stays English"
is "$(jq -r .diagnosis.text "$TMP/es.json")" \
    "the image is upside down (flipped vertically): rows written from the bottom up, or y not negated in the ray direction" \
    "  the diagnosis's text stays English"

done_testing
