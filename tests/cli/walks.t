#!/bin/sh
# walks.t - the fast walks of the hierarchy (docs/geometry.md, "The fast
# walks") change no byte: a field of spheres from bench/field_scene.py,
# from the level and the above views, hit and phong, rendered with
# RAYO_WALK=binary RAYO_PACKETS=0 on one thread (the reference walk),
# then with the wide walk in SSE2, in AVX2 without packets, and the
# default (AVX2 and packets where the processor has them), on one thread
# and on two: every file the same bytes as the reference.  Also: the
# reference and the default differ in nothing but speed on examples/.
# Under valgrind (check-valgrind) only the default and one thread.
. "$(dirname "$0")/lib.sh"

count=3000 size=192x108 threads="1 2" settings="sse2:1 avx2:0 default:1"
small="-W 160 -H 120"
if [ "${RAYO_VALGRIND:-0}" = 1 ]; then
    count=800 size=96x54 threads=1 settings="default:1" small="-W 64 -H 48"
fi

walk_render() { # walk_render WALK PACKETS OUT ARGS...: in a subshell
    walk=$1 packets=$2 out=$3
    shift 3
    (
        if [ "$walk" = default ]; then
            unset RAYO_WALK RAYO_PACKETS
        else
            RAYO_WALK=$walk RAYO_PACKETS=$packets
            export RAYO_WALK RAYO_PACKETS
        fi
        rayo render "$@" -o "$out" -q
    )
}

for view in level above; do
    python3 "$RAYO_SOURCE/bench/field_scene.py" --count "$count" \
        --view "$view" --size "$size" >"$TMP/$view.scene"
    ok $? "$view: field of $count spheres written"
    for mode in hit phong; do
        ref="$TMP/$view.$mode.ref.png"
        walk_render binary 0 "$ref" "$TMP/$view.scene" --shade "$mode" -j 1
        is "$?" 0 "$view $mode: the reference walk renders"
        for s in $settings; do
            for j in $threads; do
                got="$TMP/$view.$mode.${s%:*}.j$j.png"
                walk_render "${s%:*}" "${s#*:}" "$got" "$TMP/$view.scene" \
                    --shade "$mode" -j "$j"
                cmp -s "$ref" "$got"
                ok $? "$view $mode: ${s%:*} (packets ${s#*:}), -j $j: the same bytes"
            done
        done
    done
done

for f in "$RAYO_SOURCE"/examples/*.scene; do
    name=$(basename "$f")
    # shellcheck disable=SC2086 # $small is two options
    walk_render binary 0 "$TMP/ex.ref.png" "$f" $small -j 1
    # shellcheck disable=SC2086
    walk_render default 1 "$TMP/ex.got.png" "$f" $small -j 2
    cmp -s "$TMP/ex.ref.png" "$TMP/ex.got.png"
    ok $? "$name: the default walk gives the reference's bytes"
done

done_testing
