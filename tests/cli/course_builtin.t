#!/bin/sh
# course_builtin.t - the course's reference images are built into rayo: a
# copy of the command alone in an empty folder, with no data directory,
# still knows course:ej1, course:ej2, course:ej3 and --reference course,
# and they are the bytes of data/course/.  A file of that very name in
# the current folder, then $RAYO_DATA_DIR/course, still win.
. "$(dirname "$0")/lib.sh"

# The copy sits two folders down, so that nothing is beside it
# (../data/course, ../share/rayo/course).
mkdir -p "$TMP/a/bin" "$TMP/work" && cp "$RAYO" "$TMP/a/bin/rayo"
copy="$TMP/a/bin/rayo"
unset RAYO_DATA_DIR
cd "$TMP/work" || exit 1

"$copy" >esfera.pbm
ok $? "the copy renders the sphere"
status=0
"$copy" compare course:ej1 esfera.pbm >"$TMP/builtin.out" 2>"$TMP/err" ||
    status=$?
is "$status" 0 "the copy compares course:ej1 esfera.pbm with no data files"
sed 's/^/#   /' "$TMP/err"
rayo compare "$RAYO_SOURCE/data/course/referencia-catedra-ej1.png" \
    esfera.pbm >"$TMP/file.out" 2>&1
cmp -s "$TMP/builtin.out" "$TMP/file.out"
ok $? "and says what comparing with data/course's file says"
grep -q '^verdict: consistent$' "$TMP/builtin.out"
ok $? "the sphere is consistent with the course's EJ1"

# Each built-in image against Netpbm's own reading of the file.
for ej in ej1 ej2 ej3; do
    "$copy" convert "course:$ej" "$TMP/$ej.ppm" 2>"$TMP/err"
    ok $? "the copy converts course:$ej"
    pngtopnm "$RAYO_SOURCE/data/course/referencia-catedra-$ej.png" |
        pnmtoplainpnm >"$TMP/$ej.want"
    pnmtoplainpnm "$TMP/$ej.ppm" >"$TMP/$ej.got"
    cmp -s "$TMP/$ej.want" "$TMP/$ej.got"
    ok $? "course:$ej holds the pixels of referencia-catedra-$ej.png"
done

# $RAYO_DATA_DIR wins over the built-in copy.
mkdir -p "$TMP/data/course"
"$copy" -W 8 -H 4 -o "$TMP/data/course/referencia-catedra-ej1.png"
RAYO_DATA_DIR="$TMP/data" "$copy" compare course:ej1 esfera.pbm \
    >"$TMP/out" 2>&1
is "$(sed -n 's/^reference: \([0-9x]*\),.*/\1/p' "$TMP/out")" 8x4 \
    "a reference in \$RAYO_DATA_DIR/course wins"
# A file named course:ej1 in the current folder wins over both.
"$copy" -W 16 -H 8 >course:ej1
RAYO_DATA_DIR="$TMP/data" "$copy" compare course:ej1 esfera.pbm \
    >"$TMP/out" 2>&1
is "$(sed -n 's/^reference: \([0-9x]*\),.*/\1/p' "$TMP/out")" 16x8 \
    "a file named course:ej1 in the current folder wins"
rm -f course:ej1

# grade --reference course compares with the built-in EJ2.
"$copy" grade --exercise ej2 --reference course --no-valgrind \
    "$RAYO_SOURCE/tests/grade/ej2_pi_course/main.c" >"$TMP/grade.out" 2>&1
grep -q '^image  *pass  *the same as the reference' "$TMP/grade.out"
status=$?
ok $status "the copy grades against the course's EJ2 with --reference course"
[ $status -eq 0 ] || sed 's/^/#   /' "$TMP/grade.out"
done_testing
