#!/bin/sh
# check_layers.sh - the library's layers hold (docs/architecture.md): a
# folder of src/ includes only its own files, public headers, and the
# headers of folders below it; never another folder's private header
# (*_impl.h) or .c file.  The web build (web/wasm) and the fuzzers
# (fuzz/) use public headers only.  Every include that breaks a rule is
# listed as "FILE -> TARGET: why"; those written in
# scripts/layers_allowed.txt are tolerated (the debts of today, each to
# be paid), any other fails, and so does a tolerated line that no longer
# occurs (the list only shrinks).  Run from the repository root:
#     scripts/check_layers.sh        exit 0 when the layers hold
set -eu
allowed=${RAYO_LAYERS_ALLOWED:-scripts/layers_allowed.txt}

# The layers, lowest first, and the public headers' homes.
rank() {
    case $1 in
    core) echo 0 ;; image | io) echo 1 ;; formats | geometry) echo 2 ;;
    camera | seed | accel) echo 3 ;; scene) echo 4 ;; render) echo 5 ;;
    scenefile | preview) echo 6 ;; course) echo 7 ;; compare) echo 8 ;;
    grade) echo 9 ;; *) echo 99 ;;
    esac
}
home() { # the layer a public header belongs to
    case $1 in
    status | limits | lang | vec3 | export | cpu) echo core ;;
    image | image_convert | row_sink) echo image ;;
    output) echo io ;;
    reader | writer | mesh) echo formats ;;
    ray | sphere | plane | triangle) echo geometry ;;
    camera | camera_spec) echo camera ;;
    seed | ejercicio1) echo seed ;;
    scene | scene_random) echo scene ;;
    render) echo render ;;
    scene_file) echo scenefile ;;
    preview) echo preview ;;
    course) echo course ;;
    compare) echo compare ;;
    grade | pbm_check) echo grade ;;
    *) echo unknown ;;
    esac
}

found=$(mktemp)
trap 'rm -f "$found"' EXIT
for file in $(find src include/rayo web/wasm fuzz -name '*.[ch]' | sort); do
    case $file in
    src/*) from=$(echo "$file" | cut -d/ -f2) ;;
    include/rayo/*) from=$(home "$(basename "$file" .h)") ;;
    *) from=outside ;;
    esac
    sed -n 's/^[ \t]*#[ \t]*include[ \t]*"\([^"]*\)".*/\1/p' "$file" |
    while read -r target; do
        case $target in
        rayo/*)
            to=$(home "$(basename "$target" .h)")
            folder=public ;;
        */src/* | ../*)
            # resolved from the including file's folder, so that
            # src/grade/functions/x.c -> ../grade_impl.h stays in grade
            folder=$(realpath -m --relative-to=. "$(dirname "$file")/$target" |
                sed 's|^src/||' | cut -d/ -f1)
            to=$folder ;;
        *)
            continue ;; # its own folder
        esac
        why=""
        if [ "$from" = outside ]; then
            [ "$folder" = public ] || why="not through a public header"
        elif [ "$folder" != public ] && [ "$folder" != "$from" ]; then
            case $target in
            *_impl.h) why="another folder's private header" ;;
            *.c) why="another folder's source file" ;;
            esac
        fi
        if [ -z "$why" ] && [ "$from" != outside ] &&
            [ "$(rank "$to")" -gt "$(rank "$from")" ]; then
            why="$from includes $to, a layer above it"
        fi
        if [ -n "$why" ]; then echo "$file -> $target: $why"; fi
    done
done >"$found"

status=0
while IFS= read -r line; do
    grep -Fxq -- "$line" "$allowed" 2>/dev/null && continue
    echo "layers: $line"
    status=1
done <"$found"
if [ -f "$allowed" ]; then
    grep -v '^#' "$allowed" | grep -v '^$' | while IFS= read -r line; do
        grep -Fxq -- "$line" "$found" ||
            echo "layers: no longer happens, remove it from $allowed: $line"
    done | grep . && status=1
fi
exit $status
