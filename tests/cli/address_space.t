#!/bin/sh
# address_space.t - a render's address space follows its scene, not its
# threads' reservations, and running out of it has a status of its own.
#
# 2^20 identical spheres (a 15 MiB scene) render at -j 2 and at -j 8
# within 64 MiB + 256 bytes an object (+ 8 MiB a thread for its stack)
# of address space (`ulimit -v`): the bound docs/limits.md promises.
# Before, each build task reserved room for its whole subtree and each
# thread a malloc arena of 64 MiB heaps: 581 MiB at -j 2, and 2^24
# spheres failed under 8 GB of address space at -j 2 while -j 1 passed.
# Under too small a limit the render fails with exit status 3 and one
# line saying the memory ran out (not 1, an unwritable output's), and
# leaves no output file.  Not under valgrind or AddressSanitizer, which
# reserve address space of their own.
. "$(dirname "$0")/lib.sh"

if [ "${RAYO_VALGRIND:-0}" = 1 ] || grep -q __asan_init "$RAYO"; then
    ok 0 "# SKIP address space under valgrind or ASan"
    done_testing
    exit
fi

objects=1048576
python3 -c "
import sys
sys.stdout.buffer.write(b'camera size 64 48\n' + b'sphere 0 0 5 1\n' * $objects)" \
    >"$TMP/s.scene"

# limited KIB ARGS...: rayo under ulimit -v KIB; $status, $TMP/err.
limited() {
    kib=$1
    shift
    status=0
    (ulimit -v "$kib"; "$RAYO" "$@") >"$TMP/out" 2>"$TMP/err" || status=$?
}

for j in 2 8; do
    kib=$(( (64 * 1048576 + 256 * objects + 8 * 1048576 * j) / 1024 ))
    limited "$kib" render "$TMP/s.scene" -j "$j" -o "$TMP/s$j.ppm"
    is "$status" 0 "-j $j: 2^20 spheres within $kib KiB of address space"
    [ -s "$TMP/s$j.ppm" ]
    ok $? "-j $j: the image written"
done
cmp -s "$TMP/s2.ppm" "$TMP/s8.ppm"
ok $? "-j 2 and -j 8: the same image"

limited 102400 render "$TMP/s.scene" -j 2 -o "$TMP/small.ppm"
is "$status" 3 "100 MiB of address space: exit status 3, out of memory"
is "$(wc -l <"$TMP/err" | tr -d ' ')" 1 "  one line on stderr"
grep -q '^rayo: .*out of memory.*: the machine.s memory, or the address space that ulimit -v allows, is too small for this$' "$TMP/err"
ok $? "  it says the memory ran out, and what to change"
[ ! -e "$TMP/small.ppm" ]
ok $? "  no output file"

done_testing
