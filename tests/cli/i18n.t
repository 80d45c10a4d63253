#!/bin/sh
# i18n.t - the command in Spanish (docs/i18n.md): the catalogs complete
# and the template up to date with the sources, the language chosen from
# LANGUAGE, LC_ALL, LC_MESSAGES and LANG (any es* is Spanish, with no
# Spanish locale generated) or --lang, the Spanish wording and plurals of
# some messages, English under --lang en, and machine output (exit
# statuses, JSON) the same in both languages.
. "$(dirname "$0")/lib.sh"

# --- the catalogs ------------------------------------------------------
for po in "$RAYO_SOURCE"/po/*.po; do
    name=$(basename "$po")
    stats=$(msgfmt --check --statistics -o /dev/null "$po" 2>&1)
    ok $? "$name: msgfmt --check accepts it"
    case $stats in *untranslated* | *fuzzy*) r=1 ;; *) r=0 ;; esac
    ok "$r" "$name: no untranslated and no fuzzy entry ($stats)"
    msgcmp "$po" "$RAYO_SOURCE/po/rayo.pot" >"$TMP/msgcmp" 2>&1
    ok $? "$name: a translation for every message of po/rayo.pot"
    [ -s "$TMP/msgcmp" ] && sed 's/^/#   /' "$TMP/msgcmp"
done
"$RAYO_SOURCE/scripts/update_pot.sh" "$TMP/rayo.pot"
ok $? "xgettext extracts the marked messages"
grep -v '^"POT-Creation-Date:' "$TMP/rayo.pot" >"$TMP/new.pot"
grep -v '^"POT-Creation-Date:' "$RAYO_SOURCE/po/rayo.pot" >"$TMP/old.pot"
diff "$TMP/old.pot" "$TMP/new.pot" >"$TMP/pot.diff"
ok $? "po/rayo.pot is up to date with the sources (else: make update-po)"
[ -s "$TMP/pot.diff" ] && head -n 20 "$TMP/pot.diff" | sed 's/^/#   /'

# es CMD...: rayo under LANG=es_AR.UTF-8 alone (not a generated locale
# on Debian's default machine); stdout in $TMP/out, stderr in $TMP/err.
es() {
    status=0
    env -u LANGUAGE -u LC_ALL -u LC_MESSAGES LANG=es_AR.UTF-8 \
        "$RAYO" "$@" >"$TMP/out" 2>"$TMP/err" || status=$?
}

# --- the language's choice ---------------------------------------------
es rendr
is "$status" 2 "LANG=es_AR.UTF-8, unknown command: exit status 2"
is "$(cat "$TMP/err")" "rayo: no conozco el comando 'rendr'; ¿quisiste decir render? Los comandos son render, convert, compare, view y grade" \
    "LANG=es_AR.UTF-8: Spanish, with the nearest command"
status=0
"$RAYO" --lang es rendr 2>"$TMP/err" || status=$?
is "$status/$(cat "$TMP/err")" "2/rayo: no conozco el comando 'rendr'; ¿quisiste decir render? Los comandos son render, convert, compare, view y grade" \
    "--lang es under LANGUAGE=en: Spanish"
es --lang en rendr
is "$(cat "$TMP/err")" "rayo: unknown command 'rendr'; did you mean render? The commands are render, convert, compare, view and grade" \
    "--lang en under LANG=es_AR.UTF-8: English"
es --lang=en view
is "$(cat "$TMP/err")" "rayo: view: expected one FILE, got 0 arguments; see 'rayo view --help'" \
    "--lang=en after the command: English"
LANGUAGE= LC_ALL=C LANG=es_AR.UTF-8 "$RAYO" view 2>"$TMP/err"
is "$(cat "$TMP/err")" "rayo: view: expected one FILE, got 0 arguments; see 'rayo view --help'" \
    "LC_ALL=C before LANG: English"
LANGUAGE=fr:es LC_ALL=C "$RAYO" view 2>"$TMP/err"
is "$(cat "$TMP/err")" "rayo: view: se espera un ARCHIVO, y le diste 0 argumentos; fijate en 'rayo view --help'" \
    "LANGUAGE=fr:es, even under LC_ALL=C: Spanish"
LANGUAGE= LC_ALL= LC_MESSAGES=es_ES.UTF-8 LANG=en_US.UTF-8 "$RAYO" view 2>"$TMP/err"
is "$(cat "$TMP/err")" "rayo: view: se espera un ARCHIVO, y le diste 0 argumentos; fijate en 'rayo view --help'" \
    "LC_MESSAGES=es_ES.UTF-8 before LANG=en_US: Spanish"
status=0
"$RAYO" --lang fr 2>"$TMP/err" >"$TMP/out" || status=$?
is "$status/$(cat "$TMP/err")" "2/rayo: --lang: 'fr' is not a language rayo speaks; expected es or en" \
    "--lang fr: exit status 2, one line"
is "$(wc -c <"$TMP/out" | tr -d ' ')" 0 "--lang fr: no image"

# --- Spanish wording and plurals -----------------------------------------
es compare "$SEED/esfera.pbm"
is "$status/$(cat "$TMP/err")" "2/rayo: compare: se espera REFERENCIA e IMAGEN, y le diste 1 argumento; fijate en 'rayo compare --help'" \
    "one argument: singular"
es view a b
is "$(cat "$TMP/err")" "rayo: view: se espera un ARCHIVO, y le diste 2 argumentos; fijate en 'rayo view --help'" \
    "two arguments: plural"
digits=$(head -c 100000 /dev/zero | tr '\0' 7)
es -W "$digits"
is "$(cat "$TMP/err")" "rayo: --width: '7777777777777777…' (100000 caracteres) está fuera de rango; se espera de 1 a 65536" \
    "a long value: a prefix and its length, in Spanish"
es --sphere 1,2
is "$(cat "$TMP/err")" "rayo: --sphere: '1,2' tiene 2 números; se esperan 4: CX,CY,CZ,R" \
    "numbers, plural"
es compare --exercise ej11 a b
is "$(cat "$TMP/err")" "rayo: --exercise: no conozco el ejercicio 'ej11'; ¿quisiste decir ej1? Los ejercicios son ej1, ej2, ej3, none" \
    "an unknown exercise: the nearest"
printf 'P1\n1 1\n0\nx' >"$TMP/one.pbm"
es convert -v "$TMP/one.pbm" "$TMP/one-out.pbm"
is "$(head -n 1 "$TMP/err")" "rayo: $TMP/one.pbm: pbm plano, 1x1, blanco y negro, maxval 1; 1 byte después de la imagen (ignorado)" \
    "convert -v: what was read, 1 byte"
is "$(tail -n 1 "$TMP/err")" "rayo: $TMP/one-out.pbm: se escribió pbm plano, blanco y negro, maxval 1" \
    "convert -v: what was written"

# Every --help in Spanish, and not the English one.
for cmd in render convert compare view grade; do
    es "$cmd" --help
    is "$status" 0 "rayo $cmd --help in Spanish: exit status 0"
    head -n 1 "$TMP/out" | grep -q "^uso: rayo"
    ok $? "rayo $cmd --help: 'uso:'"
    grep -q "^estado de salida: " "$TMP/out"
    ok $? "rayo $cmd --help: 'estado de salida:'"
    grep -q "^opciones:" "$TMP/out"
    ok $? "rayo $cmd --help: 'opciones:'"
done
es --help
grep -q "^  compare   compara una imagen con una referencia y te dice qué está mal$" "$TMP/out"
ok $? "rayo --help: the commands' summaries in Spanish"

# No English left: every --help and a sweep of the command's own errors,
# in Spanish, hold none of these English words (the exercises' titles
# come from the library, still English, and option values are tokens).
stop='the|with|expected|see|default|image|when|and|of|to|is|not|file|got|unknown|must|cannot|needs|refusing'
: >"$TMP/sweep"
for args in "--help" "render --help" "convert --help" "compare --help" \
    "view --help" "grade --help" "rendr" "-W x" "-W 0" "--fov 200" \
    "--sphere 1,2,3,0" "--shade flat" "--format gif" "-o x.gif" "--raw -o x.png" \
    "a b" "convert" "convert --plain --raw a b" "convert --format gif a b" \
    "compare a" "compare --tolerance -1 a b" "compare --exercise ej9 a b" \
    "view" "view --color=sometimes x" "view course:ej4" "grade /nonexistent" \
    "grade" "grade --sandbox maybe x.c" "grade --timeout 0 x.c" \
    "grade --points image=x x.c" "grade --exercise ej7 x.c" "--bogus" "-W"; do
    # shellcheck disable=SC2086
    env -u LANGUAGE LANG=es_AR.UTF-8 "$RAYO" $args >>"$TMP/sweep" 2>&1 </dev/null
done
grep -v -e "Ejercicio obligatorio" -e "image=" "$TMP/sweep" | grep -iwE "$stop" >"$TMP/english"
is "$(wc -l <"$TMP/english" | tr -d ' ')" 0 "no English word in $(wc -l <"$TMP/sweep" | tr -d ' ') lines of Spanish help and errors"
[ -s "$TMP/english" ] && head -n 5 "$TMP/english" | sed 's/^/#   /'

# --- machine output does not move ---------------------------------------
rayo -W 40 -H 30 -o "$TMP/a.pbm"
rayo -W 40 -H 30 --sphere 2,0,3,0.8 -o "$TMP/b.pbm"
status=0
"$RAYO" compare --json "$TMP/a.pbm" "$TMP/b.pbm" >"$TMP/en.json" || status=$?
es compare --json "$TMP/a.pbm" "$TMP/b.pbm"
is "$status" "1" "compare --json, English: exit status 1"
cp "$TMP/out" "$TMP/es.json"
jq -r 'keys | join(",")' "$TMP/en.json" >"$TMP/en.keys"
jq -r 'keys | join(",")' "$TMP/es.json" >"$TMP/es.keys"
cmp -s "$TMP/en.keys" "$TMP/es.keys"
ok $? "compare --json: the same keys in both languages"
is "$(jq -r .verdict "$TMP/es.json")" "$(jq -r .verdict "$TMP/en.json")" \
    "compare --json: the same verdict token"
es -W 8 -H 6
is "$status" 0 "the image, Spanish: exit status 0"
rayo -W 8 -H 6 >"$TMP/en.pbm"
cmp -s "$TMP/out" "$TMP/en.pbm"
ok $? "the image is the same bytes in both languages"

# --- an image bound for a terminal, in Spanish ---------------------------
if command -v script >/dev/null 2>&1 &&
    SHELL=/bin/sh script -qec 'test -t 1' /dev/null </dev/null >/dev/null 2>&1; then
    SHELL=/bin/sh script -qec "env -u LANGUAGE LANG=es_AR.UTF-8 COLUMNS=40 '$RAYO' -W 64 -H 48" \
        /dev/null </dev/null >"$TMP/tty" 2>&1
    ok $? "rayo on a terminal: exit status 0"
    tr -d '\r' <"$TMP/tty" | grep -c '^P1' >/dev/null
    is "$?" 1 "rayo on a terminal: not the PBM text"
    tr -d '\r' <"$TMP/tty" | grep -Fxq "rayo: esto es un dibujo de la imagen, porque la salida estándar es una terminal; para guardarla, usá 'rayo > esfera.pbm' o 'rayo -o esfera.png'"
    ok $? "rayo on a terminal: the picture, and how to save the image"
    rayo -W 64 -H 48 -o "$TMP/tty.pbm"
    SHELL=/bin/sh script -qec "COLUMNS=40 '$RAYO' view '$TMP/tty.pbm'" \
        /dev/null </dev/null >"$TMP/view" 2>&1
    tr -d '\r' <"$TMP/tty" | grep -v '^rayo:' >"$TMP/tty.picture"
    tr -d '\r' <"$TMP/view" | cmp -s - "$TMP/tty.picture"
    ok $? "the picture is the one rayo view draws of the image"
    grep -q '█' "$TMP/tty.picture"
    ok $? "and it shows the sphere"
else
    for i in 1 2 3 4 5; do ok 0 "# SKIP no pseudo-terminal (script from util-linux)"; done
fi

done_testing
