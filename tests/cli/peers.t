#!/bin/sh
# peers.t - the benchmark's peers (issue 17, bench/peers.c): the Embree
# program casts rayo's rays (its hits are the black pixels of rayo's
# --shade hit PBM of the same scene, single rays and packets, the plane
# in Embree's scene or tested first; its lit count is a brute-force
# count in Python's doubles), and POV-Ray accepts bench/scene_to_pov.py's
# translation and renders rayo's phong image; the same for a triangle
# mesh from a binary STL (issue 28, bench/meshes.c).  Each part is skipped
# where its tool is missing: $RAYO_BUILD/bench/embree-rays (built by
# make check where libembree-dev is installed) and povray.
. "$(dirname "$0")/lib.sh"

field=$RAYO_SOURCE/bench/field_scene.py
embree=${RAYO_BUILD:-build}/bench/embree-rays

# differing A.pbm B.pbm: the number of pixels two raw PBMs differ in (or
# "sizes" when their sizes differ), counted by Python.
differing() {
    python3 - "$1" "$2" <<'EOF'
import sys
def load(path):
    data = open(path, "rb").read()
    magic, w, h, bits = data.split(maxsplit=3)
    assert magic == b"P4"
    return int(w), int(h), bits
a, b = load(sys.argv[1]), load(sys.argv[2])
if a[:2] != b[:2]:
    print("sizes")
else:
    w, h = a[:2]
    row = (w + 7) // 8
    print(sum(((a[2][j * row + i // 8] ^ b[2][j * row + i // 8]) >>
               (7 - i % 8)) & 1 for j in range(h) for i in range(w)))
EOF
}

# black FILE.pbm: its black pixels, counted by Python.
black() {
    python3 -c '
import sys
data = open(sys.argv[1], "rb").read()
magic, w, h, bits = data.split(maxsplit=3)
w, h = int(w), int(h)
row = (w + 7) // 8
print(sum((bits[j * row + i // 8] >> (7 - i % 8)) & 1
          for j in range(h) for i in range(w)))' "$1"
}

# mesh_scene SCENE STL: a sphere of radius 1 at (0.13, 0.07, 3) as 288
# flat triangles (an octahedron's faces cut 6 x 6, corners on the
# sphere, facing out) in a binary STL, and a 64x48 scene of it on a
# floor.  Off the axes, so that no ray runs along an edge of it, where
# two renderers may fairly pick either triangle.
mesh_scene() {
    python3 - "$2" <<'EOF'
import math, struct, sys
n, out = 6, bytearray(80) + struct.pack("<I", 288)
def corner(a, b, c):
    s = math.sqrt(a * a + b * b + c * c)
    return (a / s + 0.13, b / s + 0.07, c / s + 3.0)
def facet(p, q, r):
    global out
    e, f = [q[k] - p[k] for k in range(3)], [r[k] - p[k] for k in range(3)]
    m = (e[1] * f[2] - e[2] * f[1], e[2] * f[0] - e[0] * f[2],
         e[0] * f[1] - e[1] * f[0])
    s = math.sqrt(sum(x * x for x in m))
    out += struct.pack("<12fH", *[x / s for x in m], *p, *q, *r, 0)
for sx in (1, -1):
    for sy in (1, -1):
        for sz in (1, -1):
            at = lambda i, j: corner(sx * i, sy * j, sz * (n - i - j))
            flip = sx * sy * sz < 0
            for i in range(n):
                for j in range(n - i):
                    a, b, c = at(i, j), at(i + 1, j), at(i, j + 1)
                    facet(a, *((c, b) if flip else (b, c)))
                    if i + j + 2 <= n:
                        d = at(i + 1, j + 1)
                        facet(b, *((d, c) if flip else (c, d)))
open(sys.argv[1], "wb").write(out)
EOF
    printf '%s\n' 'camera size 64 48 fov 60' 'light point -3 4 0' \
        'ambient 0.1' 'material clay color 0.8 0.6 0.4 ks 0.3' \
        'plane 0 -1 0  0 1 0' "mesh $(basename "$2") material clay" >"$1"
}

value() { # value KEY FILE: the value on the "KEY value" line
    sed -n "s/^$1 //p" "$2"
}

python3 "$field" --count 1000 --size 64x48 >"$TMP/level.scene" &&
    python3 "$field" --count 1000 --size 64x48 --view above >"$TMP/above.scene" &&
    grep -v '^plane' "$TMP/level.scene" >"$TMP/spheres.scene"
ok $? "field_scene.py writes the small fields"

if [ -x "$embree" ]; then
    for scene in level above spheres; do
        rayo render "$TMP/$scene.scene" --shade hit --raw --format pbm \
            -o "$TMP/$scene.pbm"
        want=$(black "$TMP/$scene.pbm")
        for args in "--packet 1" "--packet 16" "--planes first" \
            "--planes first --packet 16" "--mode shadow" \
            "--mode shadow --packet 16 --planes first"; do
            # shellcheck disable=SC2086 # options, one word each
            "$embree" "$TMP/$scene.scene" $args --threads 1 \
                --pbm "$TMP/e.pbm" >"$TMP/e.out" 2>"$TMP/err"
            status=$?
            got=$(value hits "$TMP/e.out")
            d=$(differing "$TMP/$scene.pbm" "$TMP/e.pbm")
            # Floats against doubles: none differs here; a few might.
            [ "$status" = 0 ] && [ "$d" != sizes ] && [ "$d" -le 2 ] &&
                [ "$got" -ge $((want - 2)) ] && [ "$got" -le $((want + 2)) ]
            ok $? "$scene, $args: hits $got, rayo's black pixels $want, $d differ"
        done
        # Not a trivial frame: some pixels hit, some do not.
        [ "$want" -gt 100 ] && [ "$want" -lt 3072 ]
        ok $? "$scene: $want of 3072 pixels hit"
    done

    # Shadow rays, checked by brute force in doubles: 100 spheres, 32x24.
    python3 "$field" --count 100 --size 32x24 >"$TMP/tiny.scene"
    python3 - "$TMP/tiny.scene" >"$TMP/brute" <<'EOF'
import math, sys
cam, light, planes, spheres = {}, None, [], []
for line in open(sys.argv[1]):
    w = line.split()
    if not w or w[0].startswith("#"):
        continue
    if w[0] == "camera":
        cam["w"], cam["h"], cam["fov"] = int(w[2]), int(w[3]), float(w[5])
    elif w[0] == "light":
        light = tuple(map(float, w[2:5]))
    elif w[0] == "plane":
        planes.append((tuple(map(float, w[1:4])), tuple(map(float, w[4:7]))))
    elif w[0] == "sphere":
        spheres.append((tuple(map(float, w[1:4])), float(w[4])))
dot = lambda a, b: a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
sub = lambda a, b: (a[0] - b[0], a[1] - b[1], a[2] - b[2])
def nearest(o, d, tmin, tmax):
    best = None
    for c, r in spheres:
        oc = sub(o, c)
        b = dot(oc, d)
        disc = b * b - (dot(oc, oc) - r * r)
        if disc < 0:
            continue
        s = math.sqrt(disc)
        for t in (-b - s, -b + s):
            if tmin < t < tmax:
                tmax, best = t, ("s", c)
                break
    for p, n in planes:
        den = dot(n, d)
        if den != 0:
            t = dot(sub(p, o), n) / den
            if tmin < t < tmax:
                tmax, best = t, ("p", n)
    return best and (tmax, best)
w, h = cam["w"], cam["h"]
f = w / (2 * math.tan(cam["fov"] * math.pi / 360))
hits = lit = cast = 0
for j in range(h):
    for i in range(w):
        d = (i - w // 2, -(j - h // 2), f)
        d = tuple(x / math.sqrt(dot(d, d)) for x in d)
        found = nearest((0.0, 0.0, 0.0), d, 0.0, math.inf)
        if not found:
            continue
        hits += 1
        t, (kind, what) = found
        p = tuple(t * x for x in d)
        n = sub(p, what) if kind == "s" else what
        if dot(n, d) > 0:
            n = tuple(-x for x in n)
        l = sub(light, p)
        dist = math.sqrt(dot(l, l))
        l = tuple(x / dist for x in l)
        if dot(l, n) > 0:
            cast += 1
            if not nearest(p, l, 1e-4 * (1 + max(map(abs, p))), dist):
                lit += 1
print(hits, lit, w * h + cast)
EOF
    for args in "--packet 1" "--packet 16" "--planes first"; do
        # shellcheck disable=SC2086 # options, one word each
        "$embree" "$TMP/tiny.scene" --mode shadow $args >"$TMP/e.out"
        got="$(value hits "$TMP/e.out") $(value lit "$TMP/e.out") $(value rays "$TMP/e.out")"
        # shellcheck disable=SC2046,SC2086 # six numbers
        set -- $(cat "$TMP/brute") $got
        [ "$1" = "$4" ] && [ $(($2 - $5)) -le 2 ] && [ $(($5 - $2)) -le 2 ] &&
            [ $(($3 - $6)) -le 2 ] && [ $(($6 - $3)) -le 2 ]
        ok $? "shadow rays, $args: hits, lit, rays $got; by brute force $1 $2 $3"
    done
    [ "$2" -gt 0 ] && [ "$2" -lt "$1" ]
    ok $? "  some hits are lit, some in shadow"

    # Timings and the setup alone.
    "$embree" "$TMP/level.scene" --repeat 0 >"$TMP/e.out"
    is "$(value rays "$TMP/e.out"):$(grep -c '^setup_s [0-9.]*$' "$TMP/e.out")" \
        "0:1" "--repeat 0: setup alone, timed"

    # Bad input: the file, the line, what was expected; exit 2.
    printf 'camera size 8 8\nsphere 0 0 x 1\n' >"$TMP/bad.scene"
    # A mesh (issue 28): a sphere of 288 flat triangles from a binary
    # STL, on the floor; the same rays as rayo's, at both build
    # qualities, single rays and packets, hits and shadow rays.
    mesh_scene "$TMP/mesh.scene" "$TMP/ball.stl"
    rayo render "$TMP/mesh.scene" --shade hit --raw --format pbm \
        -o "$TMP/mesh.pbm"
    want=$(black "$TMP/mesh.pbm")
    for args in "--packet 1" "--packet 16" "--quality high" \
        "--mode shadow" "--mode shadow --packet 16 --quality high"; do
        # shellcheck disable=SC2086 # options, one word each
        "$embree" "$TMP/mesh.scene" $args --threads 1 --pbm "$TMP/e.pbm" \
            >"$TMP/e.out" 2>"$TMP/err"
        status=$?
        got=$(value hits "$TMP/e.out")
        d=$(differing "$TMP/mesh.pbm" "$TMP/e.pbm")
        [ "$status" = 0 ] && [ "$d" != sizes ] && [ "$d" -le 2 ] &&
            [ "$(value triangles "$TMP/e.out")" = 288 ] &&
            [ "$got" -ge $((want - 2)) ] && [ "$got" -le $((want + 2)) ]
        ok $? "mesh, $args: 288 triangles, hits $got, rayo's black pixels $want, $d differ"
    done
    # Not a trivial frame: the ball, the floor and the sky are all there.
    [ "$want" -gt 500 ] && [ "$want" -lt 3000 ]
    ok $? "mesh: $want of 3072 pixels hit"
    printf 'solid x\nendsolid x\n' >"$TMP/ascii.stl"
    printf 'camera size 8 8\nmesh ascii.stl\n' >"$TMP/ascii.scene"
    "$embree" "$TMP/ascii.scene" >"$TMP/out" 2>"$TMP/err"
    is "$?:$(cat "$TMP/err")" \
        "2:embree-rays: $TMP/ascii.stl: expected a binary STL (84 bytes of header and count, then 50 a triangle)" \
        "an ASCII STL: refused, exit 2"

    "$embree" "$TMP/bad.scene" >"$TMP/out" 2>"$TMP/err"
    is "$?:$(cat "$TMP/err")" \
        "2:embree-rays: $TMP/bad.scene:2: expected the centre's coordinates, found 'x'" \
        "a malformed sphere: its line, exit 2"
    printf 'light directional 0 1 0\n' >"$TMP/bad.scene"
    "$embree" "$TMP/bad.scene" >"$TMP/out" 2>"$TMP/err"
    is "$?:$(cat "$TMP/err")" \
        "2:embree-rays: $TMP/bad.scene:1: expected 'light point X Y Z' (this program reads only point lights)" \
        "a light it does not read: said so, exit 2"
    "$embree" "$TMP/missing.scene" >"$TMP/out" 2>"$TMP/err"
    is "$?:$(cat "$TMP/err")" \
        "1:embree-rays: $TMP/missing.scene: No such file or directory" \
        "a missing file: strerror, exit 1"
else
    diag "no $embree (libembree-dev not installed): the Embree checks are skipped"
fi

# POV-Ray: the translation renders rayo's phong image.
python3 "$RAYO_SOURCE/bench/scene_to_pov.py" "$TMP/level.scene" >"$TMP/level.pov"
ok $? "scene_to_pov.py translates the field"
printf 'camera size 8 8\nsphere 0 0 1\n' >"$TMP/bad.scene"
python3 "$RAYO_SOURCE/bench/scene_to_pov.py" "$TMP/bad.scene" >"$TMP/out" 2>"$TMP/err"
is "$?:$(cat "$TMP/err")" \
    "2:scene_to_pov.py: $TMP/bad.scene:2: expected a radius, found the end of the line" \
    "scene_to_pov.py: a sphere without its radius, its line, exit 2"
if command -v povray >/dev/null 2>&1; then
    [ -f "$TMP/mesh.scene" ] || mesh_scene "$TMP/mesh.scene" "$TMP/ball.stl"
    for scene in level above mesh; do
        python3 "$RAYO_SOURCE/bench/scene_to_pov.py" "$TMP/$scene.scene" \
            >"$TMP/$scene.pov"
        (cd "$TMP" && povray +I"$scene.pov" +O"$scene-pov.png" +W64 +H48 -D \
            +WT1 -A +FN -GA File_Gamma=1.0 >/dev/null 2>&1)
        ok $? "$scene: povray renders the translation"
        rayo render "$TMP/$scene.scene" --raw -o "$TMP/$scene.ppm"
        pngtopnm "$TMP/$scene-pov.png" >"$TMP/$scene-pov.ppm"
        d=$(python3 -c '
import sys
def load(p):
    m, w, h, maxval, data = open(p, "rb").read().split(maxsplit=4)
    return int(w), int(h), data
a, b = load(sys.argv[1]), load(sys.argv[2])
if a[:2] != b[:2]:
    print(99999)
else:
    print(sum(1 for k in range(0, len(a[2]), 3)
              if max(abs(a[2][k + c] - b[2][k + c]) for c in range(3)) > 2))
' "$TMP/$scene.ppm" "$TMP/$scene-pov.ppm")
        # The same image: camera, light, shadows and finishes translated
        # (none differs here by more than 2 levels; floats may move a few).
        [ "$d" -le 3 ]
        ok $? "$scene: POV-Ray's image is rayo's phong image ($d pixels differ)"
    done
else
    diag "no povray: the POV-Ray checks are skipped"
fi
done_testing
