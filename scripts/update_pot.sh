#!/bin/sh
# update_pot.sh - extracts every marked message of the sources into a
# PO template with GNU xgettext: `make pot` writes po/rayo.pot with it,
# and tests/cli/i18n.t runs it again to check that the committed
# template is up to date.
#
#   scripts/update_pot.sh OUT.pot
#
# The marks (docs/i18n.md): _("...") and N_("...") in the command,
# _n("one", "many", n) for plurals, rayo_gettext(lang, "...") and
# rayo_ngettext(lang, "one", "many", n) in the library, and the formats
# of rayo_error_set(err, status, "...") and of the scene lexer's
# scene_lexer_fail(lx, column, status, "..."), which look their format
# up in the error's language (include/rayo/status.h), and the reasons
# grade's roster gives leave_out(b, name, "...") and the phrases the
# image readers put after "expected" (found_error, rayo_source_end_error),
# the scene file's value names (scene_need_*) and the ASCII STL reader's
# phrases (stl_expected, stl_numbers), translated where they are put in.  References name
# the file without a line number, so that the template changes only when
# a message does, not when code moves.  Sources are
# listed in C's byte order so the template does not depend on the
# machine's locale or the file system's order.
# A template that differs from OUT only in its creation date leaves OUT
# as it is, so that `make pot` changes nothing when no message changed.
set -eu
out=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
cd "$(dirname "$0")/.."
files=$(find cli src web/wasm -name '*.[ch]' | LC_ALL=C sort)
tmp="$out.tmp"
# shellcheck disable=SC2086
LC_ALL=C xgettext --language=C --from-code=UTF-8 --package-name=rayo \
    --keyword= --keyword=_ --keyword=N_ --keyword=_n:1,2 \
    --keyword=rayo_gettext:2 --keyword=rayo_ngettext:2,3 \
    --keyword=rayo_error_set:3 --flag=rayo_error_set:3:c-format \
    --keyword=scene_lexer_fail:4 --flag=scene_lexer_fail:4:c-format \
    --keyword=roster_leave_out:3 --keyword=pnm_found_error:4 \
    --keyword=rayo_source_end_error:2 \
    --keyword=scene_need_word:3 --keyword=scene_need_number:2 \
    --keyword=scene_need_vector:2 --keyword=scene_need_direction:2 \
    --keyword=scene_need_ranged:2 --keyword=scene_need_count:2 \
    --keyword=scene_need_color:2 \
    --keyword=stl_expected:2 --keyword=stl_numbers:4 \
    --keyword=cmp_put:2 --flag=cmp_put:2:c-format \
    --keyword=cmp_putn:3,4 --flag=cmp_putn:3:c-format \
    --flag=cmp_putn:4:c-format \
    --keyword=grade_say:3 --flag=grade_say:3:c-format \
    --keyword=grade_fail:3 --flag=grade_fail:3:c-format \
    --keyword=grade_warn:3 --flag=grade_warn:3:c-format \
    --keyword=ej3_wrong_line:3 --flag=ej3_wrong_line:3:c-format \
    --add-comments=TRANSLATORS: --add-location=file --no-wrap --sort-by-file \
    --output="$tmp" $files
if [ -f "$out" ] &&
    grep -v '^"POT-Creation-Date:' "$out" >"$tmp.old" &&
    grep -v '^"POT-Creation-Date:' "$tmp" | cmp -s - "$tmp.old"; then
    rm -f "$tmp" "$tmp.old"
else
    rm -f "$tmp.old"
    mv "$tmp" "$out"
fi
