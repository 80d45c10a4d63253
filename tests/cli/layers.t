#!/bin/sh
# layers.t - scripts/check_layers.sh: the library's layers hold today
# (every include that breaks them is one of the debts written in
# scripts/layers_allowed.txt), and the check is not blind: a list that
# lacks one of today's debts fails naming it, and a list with a debt
# that no longer happens fails too.
. "$(dirname "$0")/lib.sh"

cd "$RAYO_SOURCE" || exit 1
out=$(sh scripts/check_layers.sh 2>&1)
is "$?:$out" "0:" "the layers hold, but for the debts written down"

grep -v '^#' scripts/layers_allowed.txt | grep . | head -n 1 >"$TMP/first"
grep -vxF -f "$TMP/first" scripts/layers_allowed.txt >"$TMP/missing"
out=$(RAYO_LAYERS_ALLOWED="$TMP/missing" sh scripts/check_layers.sh 2>&1)
is "$?:$out" "1:layers: $(cat "$TMP/first")" "an include not written down fails, named"

cp scripts/layers_allowed.txt "$TMP/stale"
echo "src/core/status.c -> ../grade/grade_impl.h: another folder's private header" >>"$TMP/stale"
out=$(RAYO_LAYERS_ALLOWED="$TMP/stale" sh scripts/check_layers.sh 2>&1)
is "$?:$out" "1:layers: no longer happens, remove it from $TMP/stale: src/core/status.c -> ../grade/grade_impl.h: another folder's private header" \
    "a debt paid must leave the list"
done_testing
