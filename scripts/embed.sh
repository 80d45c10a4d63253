#!/bin/sh
# embed.sh [--header H] NAME=FILE... - writes to standard output a C
# source that holds each FILE's bytes: `const unsigned char NAME[]` and
# `const size_t NAME_size`, declared in the header H (course_png.h
# unless given; the Makefile puts its folder on the include path).
#
# It is how the course's reference images (data/course/*.png) and the
# functions harnesses (src/grade/functions/harness/) get into the
# library without data files beside the command.  Plain POSIX sh, od
# and awk, so a fresh machine needs nothing more (no xxd).  Not a
# general resource compiler: the names it writes must already be
# declared in H, or the build fails on a missing declaration.
set -eu
header=course_png.h
if [ "${1:-}" = --header ]; then
    header=$2
    shift 2
fi
echo "/* Made by scripts/embed.sh from the files it was given; do not edit. */"
echo "#include <stddef.h>"
echo ""
echo "#include \"$header\""
for pair in "$@"; do
    name=${pair%%=*}
    file=${pair#*=}
    [ -r "$file" ] || { echo "embed.sh: cannot read $file" >&2; exit 1; }
    echo ""
    echo "const unsigned char $name[] = {"
    od -An -v -tu1 "$file" | awk '
        { for (i = 1; i <= NF; i++) { line = line $i ","; n++
              if (n % 16 == 0) { print "    " line; line = "" } } }
        END { if (line != "") print "    " line }'
    echo "};"
    echo "const size_t ${name}_size = sizeof $name;"
done
