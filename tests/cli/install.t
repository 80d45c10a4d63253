#!/bin/sh
# install.t - `make install PREFIX=...` installs the command, the
# library, the headers, a working pkg-config file, the man pages (English
# and Spanish) and the Spanish catalog, and a student's program builds
# against the installed copy alone.
. "$(dirname "$0")/lib.sh"

prefix="$TMP/prefix"
make -s -C "$RAYO_SOURCE" install BUILD="$RAYO_BUILD" PREFIX="$prefix" >"$TMP/make.out" 2>&1
ok $? "make install PREFIX=... succeeds"
for f in bin/rayo lib/librayo.a include/rayo.h include/rayo/ejercicio1.h \
         include/rayo/render.h include/rayo/course.h lib/pkgconfig/rayo.pc \
         share/man/man1/rayo.1 share/rayo/course/referencia-catedra-ej2.png \
         share/locale/es/LC_MESSAGES/rayo.mo share/man/es/man1/rayo.1; do
    ok "$([ -f "$prefix/$f" ]; echo $?)" "installs $f"
done
"$prefix/bin/rayo" -W 8 -H 4 >"$TMP/small.pbm"
is "$(head -n 2 "$TMP/small.pbm" | tr '\n' ' ')" "P1 8 4 " "the installed rayo runs"
"$prefix/bin/rayo" grade --exercise ej2 --reference course --no-valgrind \
    "$RAYO_SOURCE/tests/grade/ej2_pi_course/main.c" >"$TMP/course.out" 2>&1
grep -q '^image  *pass  *the same as the reference' "$TMP/course.out"
ok $? "the installed rayo finds the course's image: --reference course"
[ $? -eq 0 ] || sed 's/^/#   /' "$TMP/course.out"
export PKG_CONFIG_PATH="$prefix/lib/pkgconfig"
is "$(pkg-config --modversion rayo)" "$(sed -n 's/^#define RAYO_VERSION "\(.*\)"/\1/p' "$RAYO_SOURCE/include/rayo.h")" "pkg-config knows rayo's version"
${RAYO_CC:-cc} -std=c99 -Wall -Werror -pedantic -o "$TMP/student" \
    "$RAYO_SOURCE/tests/student/main.c" $(pkg-config --cflags --libs --static rayo) 2>"$TMP/cc.err"
ok $? "a student's main.c builds with pkg-config --cflags --libs --static rayo"
"$TMP/student" | pnmtoplainpnm | tail -n +3 | tr -d ' \n' >"$TMP/a"
rayo | pnmtoplainpnm | tail -n +3 | tr -d ' \n' >"$TMP/b"
cmp -s "$TMP/a" "$TMP/b"
ok $? "and prints rayo's image"
man -l "$prefix/share/man/man1/rayo.1" >/dev/null 2>&1 || groff -man -Tutf8 "$prefix/share/man/man1/rayo.1" >/dev/null 2>&1
ok $? "the man page formats"
man -l "$prefix/share/man/es/man1/rayo.1" >/dev/null 2>&1 || groff -man -Tutf8 "$prefix/share/man/es/man1/rayo.1" >/dev/null 2>&1
ok $? "the Spanish man page formats"
msgunfmt "$prefix/share/locale/es/LC_MESSAGES/rayo.mo" | grep -q 'msgstr "no hay memoria suficiente"'
ok $? "the installed catalog is po/es.po compiled"
# The translations live in the library: a lone copy of the binary speaks
# Spanish with no catalog beside it.
mkdir "$TMP/alone" && cp "$prefix/bin/rayo" "$TMP/alone/rayo"
LANGUAGE= LC_ALL= LC_MESSAGES= LANG=es_AR.UTF-8 "$TMP/alone/rayo" rendr 2>"$TMP/alone.err"
grep -q "^rayo: no conozco el comando 'rendr'; ¿quisiste decir render?" "$TMP/alone.err"
ok $? "a copied binary speaks Spanish under LANG=es_AR.UTF-8"
done_testing
