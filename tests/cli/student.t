#!/bin/sh
# student.t - a student-style main.c, written only against the
# assignment's text, compiles with the course's flags against rayo's
# header, links to librayo, and prints the same image as `rayo`.
. "$(dirname "$0")/lib.sh"

cc=${RAYO_CC:-cc}
$cc -std=c99 -Wall -Werror -pedantic -I"$RAYO_SOURCE/include" \
    -o "$TMP/student" "$RAYO_SOURCE/tests/student/main.c" \
    "$RAYO_BUILD/librayo.a" -lm 2>"$TMP/cc.err"
ok $? "main.c compiles with -std=c99 -Wall -Werror -pedantic and links to librayo"
[ -s "$TMP/cc.err" ] && sed 's/^/# /' "$TMP/cc.err"

"$TMP/student" >"$TMP/student.pbm"
ok $? "the student's program runs"
is "$(head -n 2 "$TMP/student.pbm" | tr '\n' ' ')" "P1 640 480 " "its header"
rayo >"$TMP/rayo.pbm"
pnmtoplainpnm "$TMP/student.pbm" | tail -n +3 | tr -d ' \n' >"$TMP/a"
pnmtoplainpnm "$TMP/rayo.pbm" | tail -n +3 | tr -d ' \n' >"$TMP/b"
is "$(wc -c <"$TMP/a" | tr -d ' ')" 307200 "the student's image has 640x480 pixels"
cmp -s "$TMP/a" "$TMP/b"
ok $? "the student's image equals rayo's, pixel for pixel"

# Every public header is valid C99 under the course's flags.
for h in "$RAYO_SOURCE"/include/rayo.h "$RAYO_SOURCE"/include/rayo/*.h; do
    printf '#include "%s"\nint main(void) { return 0; }\n' "$h" >"$TMP/h.c"
    $cc -std=c99 -Wall -Werror -pedantic -I"$RAYO_SOURCE/include" \
        $(pkg-config --cflags libpng) -c -o "$TMP/h.o" "$TMP/h.c" 2>"$TMP/h.err"
    ok $? "$(basename "$h") compiles alone as C99 -pedantic"
done
done_testing
