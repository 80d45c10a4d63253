#!/bin/sh
# layers.t - scripts/check_layers.sh: the library's layers hold today
# (every include that breaks them is one of the debts written in
# scripts/layers_allowed.txt), and the check is not blind: a list that
# lacks one of today's debts fails naming it, and a list with a debt
# that no longer happens fails too; a subfolder's relative includes are
# resolved from where it is.
. "$(dirname "$0")/lib.sh"

cd "$RAYO_SOURCE" || exit 1
out=$(sh scripts/check_layers.sh 2>&1)
is "$?:$out" "0:" "the layers hold, but for the debts written down"

# A debt not written down fails, named: a tree where core reaches up to
# render, and the page into a private header.
mkdir -p "$TMP/up/src/core" "$TMP/up/include/rayo" "$TMP/up/web/wasm" \
    "$TMP/up/fuzz" "$TMP/up/scripts"
cp scripts/check_layers.sh "$TMP/up/scripts/"
printf '#include "rayo/render.h"\n' >"$TMP/up/src/core/x.c"
printf '#include "../../src/formats/reader_impl.h"\n' >"$TMP/up/web/wasm/y.c"
: >"$TMP/up/none"
out=$(cd "$TMP/up" && RAYO_LAYERS_ALLOWED=none sh scripts/check_layers.sh 2>&1)
is "$?:$out" "1:layers: src/core/x.c -> rayo/render.h: core includes render, a layer above it
layers: web/wasm/y.c -> ../../src/formats/reader_impl.h: not through a public header" \
    "an include not written down fails, named"

cp scripts/layers_allowed.txt "$TMP/stale"
echo "src/core/status.c -> ../grade/grade_impl.h: another folder's private header" >>"$TMP/stale"
out=$(RAYO_LAYERS_ALLOWED="$TMP/stale" sh scripts/check_layers.sh 2>&1)
is "$?:$out" "1:layers: no longer happens, remove it from $TMP/stale: src/core/status.c -> ../grade/grade_impl.h: another folder's private header" \
    "a debt paid must leave the list"
# A subfolder's includes are resolved from where it is: "../x_impl.h"
# from src/compare/tone/ is compare's own header, "../../grade/..." is
# another folder's.
mkdir -p "$TMP/tree/src/compare/tone" "$TMP/tree/include/rayo" \
    "$TMP/tree/web/wasm" "$TMP/tree/fuzz" "$TMP/tree/scripts"
cp scripts/check_layers.sh "$TMP/tree/scripts/"
printf '#include "../compare_impl.h"\n#include "../../grade/grade_impl.h"\n' \
    >"$TMP/tree/src/compare/tone/x.c"
: >"$TMP/tree/none"
out=$(cd "$TMP/tree" && RAYO_LAYERS_ALLOWED=none sh scripts/check_layers.sh 2>&1)
is "$?:$out" "1:layers: src/compare/tone/x.c -> ../../grade/grade_impl.h: another folder's private header" \
    "a subfolder's include is resolved from its own folder"
done_testing
