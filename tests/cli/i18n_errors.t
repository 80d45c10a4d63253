#!/bin/sh
# i18n_errors.t - the library's error messages in the command's language
# (docs/i18n.md): a malformed image (no image at all, a PBM with a bad
# pixel, one cut short, the phrase after "expected" translated too), a
# bad scene file (what a value stands for and what was found translated
# too, a mesh reader's messages as well), an output name whose format
# cannot be told, an unreadable file and a bad --fov give Spanish under
# --lang es and LANG=es_AR.UTF-8 (with no Spanish locale generated),
# English under --lang en and LANG=C; always one line on stderr, nothing on stdout,
# and the same exit status in both languages.
# Numbers in a Spanish message have a decimal comma; the system's reason
# for an unreadable file (strerror) stays the system's.
. "$(dirname "$0")/lib.sh"

cd "$TMP" || exit 1
printf 'hola\n' >magic.pbm
printf 'P1\n3 2\n1 0 1\n0 x 1\n' >pixel.pbm
printf 'P1\n2 2\n1 0\n' >short.pbm
printf 'camera fov 200.5\nsphere 0 0 -3 1\n' >fov.scene
printf 'light point 0 0 0 color -1\n' >light.scene
printf 'camera size abc 3\n' >size.scene
printf 'sphere 0 0 q 1\n' >centre.scene
printf 'sphere 0 0\n' >short.scene
printf 'solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 a\n' >bad.stl
printf 'mesh bad.stl\n' >mesh.scene
printf 'v 0 0 0\nf 1 q 1\n' >bad.obj
printf 'mesh bad.obj\n' >obj.scene

# one NAME STATUS LINE ARGS...: rayo ARGS gives exit status STATUS,
# nothing on stdout and LINE alone on stderr.
one() {
    name=$1 want_status=$2 want=$3
    shift 3
    run_capture "$@"
    is "$status" "$want_status" "$name: exit status $want_status"
    is "$(wc -c <"$TMP/out" | tr -d ' ')" 0 "$name: nothing on stdout"
    is "$(wc -l <"$TMP/err" | tr -d ' ')" 1 "$name: one line on stderr"
    is "$(cat "$TMP/err")" "$want" "$name: the message"
}

# both NAME STATUS SPANISH ENGLISH ARGS...: the message in Spanish under
# --lang es and LANG=es_AR.UTF-8, in English under --lang en and LANG=C.
both() {
    name=$1 st=$2 spanish=$3 english=$4
    shift 4
    one "$name, --lang es" "$st" "$spanish" --lang es "$@"
    (unset LANGUAGE LC_ALL LC_MESSAGES; LANG=es_AR.UTF-8
     export LANG
     one "$name, LANG=es_AR.UTF-8" "$st" "$spanish" "$@"
     echo "tap_n=$tap_n tap_failed=$tap_failed" >"$TMP/counts")
    . "$TMP/counts"
    one "$name, --lang en" "$st" "$english" --lang en "$@"
    (unset LANGUAGE LC_ALL LC_MESSAGES; LANG=C
     export LANG
     one "$name, LANG=C" "$st" "$english" "$@"
     echo "tap_n=$tap_n tap_failed=$tap_failed" >"$TMP/counts")
    . "$TMP/counts"
}

both "a file that is no image" 2 \
    "rayo: magic.pbm: byte 0: se encontró \"ho\"; se esperaba un número mágico de Netpbm (P1-P6), una firma PNG, el \"BM\" de un BMP o el ff d8 de un JPEG" \
    "rayo: magic.pbm: byte 0: found \"ho\"; expected a Netpbm magic number (P1-P6), a PNG signature, a BMP's \"BM\" or a JPEG's ff d8" \
    view magic.pbm
both "a PBM with a letter for a pixel" 2 \
    "rayo: pixel.pbm: byte 15 (línea 4): se encontró 'x'; se esperaba 0 o 1 (un píxel de PBM)" \
    "rayo: pixel.pbm: byte 15 (line 4): found 'x'; expected 0 or 1 (a PBM pixel)" \
    view pixel.pbm
both "a PBM cut short" 2 \
    "rayo: short.pbm: byte 11 (línea 4): se encontró el final del archivo; se esperaba más píxeles (0 o 1)" \
    "rayo: short.pbm: byte 11 (line 4): found the end of the file; expected more pixels (0 or 1)" \
    compare short.pbm short.pbm
both "a scene file's field of view" 2 \
    "rayo: fov.scene:1:12: no se acepta el campo de visión 200,5; se esperaban grados estrictamente entre 0 y 180" \
    "rayo: fov.scene:1:12: field of view 200.5 is not accepted; expected degrees strictly between 0 and 180" \
    render fov.scene -o out.pbm
# What a scene's value stands for, and what was found, are translated
# too; a vector's axis follows the Spanish phrase.
both "a scene's negative colour" 2 \
    "rayo: light.scene:1:25: no se acepta el color de la luz -1; se esperaba un número >= 0" \
    "rayo: light.scene:1:25: the light's colour -1 is not accepted; expected a number >= 0" \
    render light.scene -o out.pbm
both "a scene's word for a width" 2 \
    "rayo: size.scene:1:13: se encontró 'abc'; se esperaba el ancho de la imagen (un número decimal finito)" \
    "rayo: size.scene:1:13: found 'abc'; expected the image width (a finite decimal number)" \
    render size.scene -o out.pbm
both "a scene's word for a vector's axis" 2 \
    "rayo: centre.scene:1:12: se encontró 'q'; se esperaba el centro de la esfera, coordenada z (un número decimal finito)" \
    "rayo: centre.scene:1:12: found 'q'; expected the z of the sphere's centre (a finite decimal number)" \
    render centre.scene -o out.pbm
both "a scene's line cut short" 2 \
    "rayo: short.scene:1:11: se encontró el final de la línea; se esperaba el centro de la esfera, coordenada z (un número)" \
    "rayo: short.scene:1:11: found the end of the line; expected the z of the sphere's centre (a number)" \
    render short.scene -o out.pbm
both "an ASCII STL's letter for a coordinate" 2 \
    "rayo: mesh.scene:1:6: ./bad.stl:4: se encontró 'a'; se esperaba los tres números finitos de un vértice" \
    "rayo: mesh.scene:1:6: ./bad.stl:4: found 'a'; expected a vertex's three finite numbers" \
    render mesh.scene -o out.pbm
both "an OBJ face's corner that is no index" 2 \
    "rayo: obj.scene:1:6: ./bad.obj:2: se encontró la esquina 'q'; se esperaba un índice de vértice (N, N/T, N//M o N/T/M)" \
    "rayo: obj.scene:1:6: ./bad.obj:2: found the corner 'q'; expected a vertex index (N, N/T, N//M or N/T/M)" \
    render obj.scene -o out.pbm
[ ! -e out.pbm ]
ok $? "no image is written for a bad scene file"
both "an output whose format cannot be told" 2 \
    "rayo: convert: no se puede saber el formato de 'out.xyz' por su extensión; se esperaba .pbm, .pgm, .ppm, .png, .bmp o .jpg (o usá --format)" \
    "rayo: convert: cannot tell the format of 'out.xyz' from its extension; expected .pbm, .pgm, .ppm, .png, .bmp or .jpg (or give --format)" \
    convert magic.pbm out.xyz
both "a missing file" 2 \
    "rayo: missing.pbm: No such file or directory" \
    "rayo: missing.pbm: No such file or directory" \
    view missing.pbm
both "--fov out of range" 2 \
    "rayo: --fov: '200.5' está fuera de rango; se esperan grados estrictamente entre 0 y 180" \
    "rayo: --fov: '200.5' is out of range; expected degrees strictly between 0 and 180" \
    render --fov 200.5 -o out.pbm
done_testing
