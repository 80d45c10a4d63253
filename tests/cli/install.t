#!/bin/sh
# install.t - `make install PREFIX=...` installs the command, the static
# and the shared library (librayo.so.VERSION, its soname librayo.so.MAJOR
# and the librayo.so link), the headers, a working pkg-config file, the
# man pages (English and Spanish) and the Spanish catalog; the README's
# student program and examples/*.c build against the installed copy
# alone: with `pkg-config --libs rayo` against the shared library (run
# with LD_LIBRARY_PATH), with `-static` and `pkg-config --static` against
# librayo.a.  The static builds are skipped under the sanitizers (RAYO_CC
# with -fsanitize), which cannot link -static.
. "$(dirname "$0")/lib.sh"

prefix="$TMP/prefix"
version=$(sed -n 's/^#define RAYO_VERSION "\(.*\)"/\1/p' "$RAYO_SOURCE/include/rayo.h")
make -s -C "$RAYO_SOURCE" install BUILD="$RAYO_BUILD" PREFIX="$prefix" >"$TMP/make.out" 2>&1
ok $? "make install PREFIX=... succeeds"
for f in bin/rayo lib/librayo.a "lib/librayo.so.$version" include/rayo.h \
         include/rayo/ejercicio1.h include/rayo/export.h \
         include/rayo/render.h include/rayo/course.h lib/pkgconfig/rayo.pc \
         share/man/man1/rayo.1 share/rayo/course/referencia-catedra-ej2.png \
         share/locale/es/LC_MESSAGES/rayo.mo share/man/es/man1/rayo.1; do
    ok "$([ -f "$prefix/$f" ]; echo $?)" "installs $f"
done
soname=$(readelf -d "$prefix/lib/librayo.so.$version" |
         sed -n 's/.*(SONAME).*\[\(.*\)\]/\1/p')
case $soname in librayo.so.[0-9]*) r=0 ;; *) r=1 ;; esac
ok $r "the shared library's soname is librayo.so.MAJOR ($soname)"
is "$(readlink "$prefix/lib/$soname")" "librayo.so.$version" \
    "lib/$soname links to librayo.so.$version"
is "$(readlink "$prefix/lib/librayo.so")" "$soname" \
    "lib/librayo.so links to $soname (what -lrayo finds)"

"$prefix/bin/rayo" -W 8 -H 4 >"$TMP/small.pbm"
is "$(head -n 2 "$TMP/small.pbm" | tr '\n' ' ')" "P1 8 4 " "the installed rayo runs"
"$prefix/bin/rayo" grade --exercise ej2 --reference course --no-valgrind \
    "$RAYO_SOURCE/tests/grade/ej2_pi_course/main.c" >"$TMP/course.out" 2>&1
grep -q '^image  *pass  *the same as the reference' "$TMP/course.out"
status=$?
ok $status "the installed rayo finds the course's image: --reference course"
[ $status -eq 0 ] || sed 's/^/#   /' "$TMP/course.out"

export PKG_CONFIG_PATH="$prefix/lib/pkgconfig"
is "$(pkg-config --modversion rayo)" "$version" "pkg-config knows rayo's version"
is "$(pkg-config --libs rayo | sed 's/ *$//')" "-L$prefix/lib -lrayo" \
    "pkg-config --libs rayo: the library alone (its own are linked in)"

# What the student program and the example print, from the rayo under test.
rayo | pnmtoplainpnm | tail -n +3 | tr -d ' \n' >"$TMP/sphere"
rayo render "$RAYO_SOURCE/examples/ej2.scene" -q -o "$TMP/ej2-rayo.png"
pngtopnm "$TMP/ej2-rayo.png" >"$TMP/ej2-rayo.pnm"

# build KIND OUT SOURCE FLAGS...: compiles with the course's flags.
build() {
    kind=$1 out=$2 src=$3
    shift 3
    ${RAYO_CC:-cc} -std=c99 -Wall -Werror -pedantic -o "$out" "$src" "$@" \
        2>"$TMP/cc.err"
    status=$?
    ok $status "$kind: ${src#"$RAYO_SOURCE"/} builds"
    [ $status -eq 0 ] || sed 's/^/#   /' "$TMP/cc.err"
}

# check KIND STUDENT EXAMPLE: both print what rayo prints.
check() {
    "$2" | pnmtoplainpnm | tail -n +3 | tr -d ' \n' >"$TMP/a"
    cmp -s "$TMP/a" "$TMP/sphere"
    ok $? "$1: the student's program prints rayo's sphere"
    "$3" "$RAYO_SOURCE/examples/ej2.scene" "$TMP/ej2.png" 2>"$TMP/err"
    ok $? "$1: examples/render_png renders ej2.scene"
    pngtopnm "$TMP/ej2.png" 2>/dev/null | cmp -s - "$TMP/ej2-rayo.pnm"
    ok $? "$1: the same pixels as rayo render"
    rm -f "$TMP/ej2.png"
}

student=$RAYO_SOURCE/tests/student/main.c
example=$RAYO_SOURCE/examples/render_png.c
build shared "$TMP/student-so" "$student" $(pkg-config --cflags --libs rayo)
build shared "$TMP/example-so" "$example" $(pkg-config --cflags --libs rayo)
for f in student-so example-so; do
    readelf -d "$TMP/$f" 2>/dev/null | grep -q "(NEEDED).*\[$soname\]"
    ok $? "shared: $f needs $soname"
done
LD_LIBRARY_PATH="$prefix/lib" ldd "$TMP/student-so" |
    grep -q "$soname => $prefix/lib/$soname"
ok $? "shared: with LD_LIBRARY_PATH it loads the installed $soname"
saved=${LD_LIBRARY_PATH-}
export LD_LIBRARY_PATH="$prefix/lib${saved:+:$saved}"
check shared "$TMP/student-so" "$TMP/example-so"
if [ -n "$saved" ]; then LD_LIBRARY_PATH=$saved; else unset LD_LIBRARY_PATH; fi

case ${RAYO_CC:-cc} in
*-fsanitize*)
    echo "ok $((tap_n + 1)) # skip static builds: the sanitizers cannot link -static"
    tap_n=$((tap_n + 1)) ;;
*)
    build static "$TMP/student-a" "$student" -static \
        $(pkg-config --cflags --libs --static rayo)
    build static "$TMP/example-a" "$example" -static \
        $(pkg-config --cflags --libs --static rayo)
    for f in student-a example-a; do
        ! readelf -d "$TMP/$f" 2>/dev/null | grep -q "(NEEDED)"
        ok $? "static: $f needs no shared library"
    done
    check static "$TMP/student-a" "$TMP/example-a" ;;
esac

man -l "$prefix/share/man/man1/rayo.1" >/dev/null 2>&1 || groff -man -Tutf8 "$prefix/share/man/man1/rayo.1" >/dev/null 2>&1
ok $? "the man page formats"
man -l "$prefix/share/man/es/man1/rayo.1" >/dev/null 2>&1 || groff -man -Tutf8 "$prefix/share/man/es/man1/rayo.1" >/dev/null 2>&1
ok $? "the Spanish man page formats"
msgunfmt "$prefix/share/locale/es/LC_MESSAGES/rayo.mo" | grep -q 'msgstr "render: no hay memoria suficiente"'
ok $? "the installed catalog is po/es.po compiled"
# The translations live in the library: a lone copy of the binary speaks
# Spanish with no catalog beside it.
mkdir "$TMP/alone" && cp "$prefix/bin/rayo" "$TMP/alone/rayo"
LANGUAGE= LC_ALL= LC_MESSAGES= LANG=es_AR.UTF-8 "$TMP/alone/rayo" rendr 2>"$TMP/alone.err"
grep -q "^rayo: no conozco el comando 'rendr'; ¿quisiste decir render?" "$TMP/alone.err"
ok $? "a copied binary speaks Spanish under LANG=es_AR.UTF-8"
done_testing
