#!/bin/sh
# mesh.t - the scene's `mesh` statement: one solid as binary STL, as
# ASCII STL written by ADMesh (the independent reader and writer), and
# as OBJ, each placed with scale, rotate and translate, renders the same
# bytes as the same triangles given as `triangle` lines placed by
# tests/cli/mesh_make.py itself; ADMesh counts the binary file's facets
# as the generator made them.  Then the warnings (left-out triangles,
# unused OBJ statements), the file found beside the scene, and hostile
# files refused with one line.
. "$(dirname "$0")/lib.sh"

count=$(python3 "$RAYO_SOURCE/tests/cli/mesh_make.py" "$TMP")
is "$count" 60 "the generator made 60 triangles"
# ADMesh (scripts/deps.sh check installs it) as the independent reader
# and writer.
facets=$(admesh "$TMP/bumpy.stl" 2>/dev/null | awk '/^Number of facets/ { print $5 }')
is "$facets" 60 "ADMesh reads 60 facets in the binary STL"
admesh --write-ascii-stl="$TMP/bumpy_ascii.stl" "$TMP/bumpy.stl" >/dev/null 2>&1
ok $? "ADMesh writes it as ASCII STL"

rayo render "$TMP/triangles.scene" -o "$TMP/triangles.ppm"
ok $? "the triangles render"
for kind in stl ascii obj; do
    rayo render "$TMP/mesh_$kind.scene" -o "$TMP/mesh_$kind.ppm" 2>"$TMP/err"
    ok $? "the $kind mesh renders"
    cmp -s "$TMP/mesh_$kind.ppm" "$TMP/triangles.ppm"
    ok $? "  the same bytes as the triangles placed by hand"
done
is "$(cat "$TMP/err")" "rayo: warning: $TMP/mesh_obj.scene: 2 OBJ statements that are not 'v' or 'f' (normals, texture coordinates, groups, materials) were not used" \
    "the OBJ's unused statements are said"
# The file's own normals shade differently from the corners' (they are
# the same directions here, unnormalised: the same picture), and a
# tilted file normal changes it.
sed 's/ normals computed//' "$TMP/mesh_stl.scene" >"$TMP/file_normals.scene"
rayo render "$TMP/file_normals.scene" -o "$TMP/file_normals.ppm"
cmp -s "$TMP/file_normals.ppm" "$TMP/triangles.ppm"
ok $? "the file's normals (the faces' own, unnormalised) shade the same"

# Found beside the scene, whatever the current folder.
mkdir "$TMP/elsewhere"
(cd "$TMP/elsewhere" && rayo render ../mesh_stl.scene -o here.ppm)
cmp -s "$TMP/elsewhere/here.ppm" "$TMP/triangles.ppm"
ok $? "the mesh file is found beside the scene file"

# A scale that crushes the solid flat leaves every triangle out, said.
printf 'camera size 8 8\nmesh bumpy.stl scale 1e-300\n' >"$TMP/flat.scene"
rayo render "$TMP/flat.scene" -o "$TMP/flat.ppm" 2>"$TMP/err"
is "$(cat "$TMP/err")" "rayo: warning: $TMP/flat.scene has no objects; the image is the background
rayo: warning: $TMP/flat.scene: 60 of its meshes' triangles have their corners on one line and were left out (0 drawn)" \
    "triangles crushed to lines are left out and counted"

# Watertight: a closed mesh whose neighbours share corners bit for bit,
# seen from eight directions, shows no background pixel inside its
# silhouette (a ray through the crack between two triangles); the same
# mesh with every triangle shrunk by 4% does, or the count proves nothing.
W=$RAYO_SOURCE/tests/cli/mesh_watertight.py
python3 "$W" make "$TMP/closed.stl"
python3 "$W" cracked "$TMP/cracked.stl"
holes() { # holes MESH ROTATION: background pixels enclosed by the mesh
    printf 'camera size 160 160 fov 40\nmesh %s rotate %s translate 0 0 4\n' \
        "$1" "$2" >"$TMP/wt.scene"
    rayo render "$TMP/wt.scene" --shade hit --raw -o "$TMP/wt.pbm" &&
        python3 "$W" holes "$TMP/wt.pbm"
}
all=""
for r in "0 0 0" "37 11 5" "90 0 0" "13 77 41" "180 33 0" "-60 120 7" \
    "45 45 45" "0 -90 171"; do
    all="$all$(holes closed.stl "$r") "
done
is "$all" "0 0 0 0 0 0 0 0 " "a closed mesh from 8 directions: no ray falls through a crack"
cracked=$(holes cracked.stl "37 11 5")
ok "$([ "$cracked" -gt 0 ]; echo $?)" "  the same mesh with gaps shows them ($cracked pixels)"

# Hostile and broken files: one line, exit status 2, nothing written.
refused() { # refused NAME SCENE-LINE COLUMN MESSAGE
    printf 'camera size 8 8\n%s\n' "$2" >"$TMP/bad.scene"
    status=0
    rayo render "$TMP/bad.scene" -o "$TMP/bad.ppm" 2>"$TMP/err" || status=$?
    is "$status:$(cat "$TMP/err")" "2:rayo: $TMP/bad.scene:2:$3: $4" "$1"
    [ ! -e "$TMP/bad.ppm" ]
    ok $? "  nothing written"
}
head -c 1084 "$TMP/bumpy.stl" >"$TMP/short.stl"
refused "a count larger than the file" "mesh short.stl" 6 \
    "$TMP/short.stl: byte 80: found a count of 60 triangles, which need 84 + 50 x 60 = 3084 bytes; expected at most 20 triangles (the file has 1084 bytes)"
printf 'v 0 0 0\nv 1 0 0\nf 1 2 3\n' >"$TMP/bad.obj"
refused "an OBJ index out of range" "mesh bad.obj" 6 \
    "$TMP/bad.obj:3: found the vertex index 3; expected 1 to 2 or -1 to -2 (the vertices so far)"
refused "a missing file" "mesh nowhere.stl" 6 \
    "$TMP/nowhere.stl: No such file or directory"
refused "an unknown option" "mesh bumpy.stl spin 3" 16 \
    "found 'spin'; expected scale, rotate, translate, normals, material or the end of the 'mesh' line"
done_testing
