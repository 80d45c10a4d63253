#!/bin/sh
# embed.sh NAME=FILE... - writes to standard output a C source that holds
# each FILE's bytes: `const unsigned char NAME[]` and `const size_t
# NAME_size`, declared in the header course_png.h names (the Makefile
# puts src/course on the include path for it).
#
# It is how the course's reference images (data/course/*.png) get into
# the library without data files beside the command.  Plain POSIX sh, od
# and awk, so a fresh machine needs nothing more (no xxd).  Not a general
# resource compiler: the names it writes must already be declared in
# course_png.h, or the build fails on a missing declaration.
set -eu
echo "/* Made by scripts/embed.sh from the files it was given; do not edit. */"
echo "#include <stddef.h>"
echo ""
echo "#include \"course_png.h\""
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
