#!/bin/sh
# embed_catalogs.sh - the compiled catalogs (GNU .mo files) as a C source
# file, so that the library carries its translations: a copied binary and
# the WebAssembly page speak every language without finding files.
#
#   scripts/embed_catalogs.sh OUT.c LOCALEDIR CODE...
#
# For each CODE it reads LOCALEDIR/CODE/LC_MESSAGES/rayo.mo (made by msgfmt
# from po/CODE.po) and writes one byte array; the table rayo_catalog_blobs
# (src/core/catalog.h) lists them and ends with a NULL code.  Only od and
# sed, so it runs wherever the build does.
set -eu
out=$1
localedir=$2
shift 2
tmp="$out.tmp"
{
    echo '/* Made by scripts/embed_catalogs.sh from po/LL.po: do not edit. */'
    echo '#include "catalog.h"'
    for code in "$@"; do
        echo "static const unsigned char catalog_$code[] = {"
        od -An -v -tx1 "$localedir/$code/LC_MESSAGES/rayo.mo" |
            sed -e 's/ *\([0-9a-f][0-9a-f]\)/0x\1,/g' -e 's/^/    /'
        echo '};'
    done
    echo 'const rayo_catalog_blob rayo_catalog_blobs[] = {'
    for code in "$@"; do
        echo "    {\"$code\", catalog_$code, sizeof catalog_$code},"
    done
    echo '    {0, 0, 0}};'
} >"$tmp"
mv "$tmp" "$out"
