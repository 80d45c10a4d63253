#!/bin/sh
# install.t - `make install PREFIX=...` installs the command, the
# library, the headers, a working pkg-config file and the man page, and a
# student's program builds against the installed copy alone.
. "$(dirname "$0")/lib.sh"

prefix="$TMP/prefix"
make -s -C "$RAYO_SOURCE" install BUILD="$RAYO_BUILD" PREFIX="$prefix" >"$TMP/make.out" 2>&1
ok $? "make install PREFIX=... succeeds"
for f in bin/rayo lib/librayo.a include/rayo.h include/rayo/ejercicio1.h \
         include/rayo/render.h include/rayo/course.h lib/pkgconfig/rayo.pc \
         share/man/man1/rayo.1 share/rayo/course/referencia-catedra-ej2.png; do
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
done_testing
