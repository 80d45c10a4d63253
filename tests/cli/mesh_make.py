#!/usr/bin/env python3
"""mesh_make.py - the meshes mesh.t renders, and the same triangles as
scene lines placed by hand: a bumpy closed solid (an icosahedron whose
faces are split and pushed out), written as binary STL (as the course's
statement lays it out), ASCII STL and OBJ; and scene files that place it
with `mesh ... scale rotate translate` and, independently, as `triangle`
lines whose corners this script scales, turns and moves itself, in the
order rayo_scene_add_mesh documents (so the two must render the same
bytes).

    mesh_make.py DIR
"""
import math
import os
import struct
import sys


def solid():
    t = (1 + 5 ** 0.5) / 2
    v = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t),
         (0, 1, t), (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1),
         (-t, 0, -1), (-t, 0, 1)]
    f = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11),
         (1, 5, 9), (5, 11, 4), (11, 10, 2), (10, 7, 6), (7, 1, 8),
         (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5),
         (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    # Each face split at its centre, pushed out: 60 triangles.  Corners
    # rounded to multiples of 1/64, exact in float32.
    r = lambda x: round(x * 64) / 64
    verts = [tuple(r(c) for c in p) for p in v]
    tris = []
    for a, b, c in f:
        m = tuple(r(1.3 * (verts[a][k] + verts[b][k] + verts[c][k]) / 3)
                  for k in range(3))
        verts.append(m)
        i = len(verts) - 1
        tris += [(a, b, i), (b, c, i), (c, a, i)]
    return verts, tris


def normal(p, q, s):
    e1 = [q[k] - p[k] for k in range(3)]
    e2 = [s[k] - p[k] for k in range(3)]
    return (e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
            e1[0] * e2[1] - e1[1] * e2[0])


def rotation(d):
    k = 3.14159265358979323846 / 180.0
    cx, sx = math.cos(d[0] * k), math.sin(d[0] * k)
    cy, sy = math.cos(d[1] * k), math.sin(d[1] * k)
    cz, sz = math.cos(d[2] * k), math.sin(d[2] * k)
    return [[cz * cy, cz * sy * sx - sz * cx, cz * sy * cx + sz * sx],
            [sz * cy, sz * sy * sx + cz * cx, sz * sy * cx - cz * sx],
            [-sy, cy * sx, cy * cx]]


def place(m, scale, move, p):
    turned = [m[i][0] * p[0] + m[i][1] * p[1] + m[i][2] * p[2]
              for i in range(3)]
    return [turned[i] * scale + move[i] for i in range(3)]


def main(folder):
    verts, tris = solid()
    with open(os.path.join(folder, "bumpy.stl"), "wb") as out:
        out.write(b"bumpy".ljust(80, b"\0") + struct.pack("<I", len(tris)))
        for t in tris:
            p = [verts[i] for i in t]
            out.write(struct.pack("<3f", *normal(*p)))
            for c in p:
                out.write(struct.pack("<3f", *c))
            out.write(b"\0\0")
    with open(os.path.join(folder, "bumpy.obj"), "w") as out:
        out.write("# bumpy\no bumpy\n")
        for p in verts:
            out.write("v %r %r %r\n" % p)
        out.write("vn 0 0 1\n")
        for t in tris:
            out.write("f %d %d %d\n" % tuple(i + 1 for i in t))
    head = ("camera size 120 90 fov 50\nshade phong\nambient 0.1 0.1 0.1\n"
            "light point 4 5 -6 color 1 1 1\n"
            "material clay color 0.8 0.5 0.3 ka 1 kd 0.9 ks 0.3 "
            "shininess 12\n")
    scale, rot, move = 1.25, (20, -35, 10), (0.5, -0.25, 7)
    line = "scale %r rotate %r %r %r translate %r %r %r" % (
        (scale,) + rot + move)
    for name, fmt in (("stl", "bumpy.stl"), ("obj", "bumpy.obj"),
                      ("ascii", "bumpy_ascii.stl")):
        with open(os.path.join(folder, "mesh_%s.scene" % name), "w") as out:
            out.write(head + "mesh %s %s normals computed material clay\n"
                      % (fmt, line))
    m = rotation(rot)
    with open(os.path.join(folder, "triangles.scene"), "w") as out:
        out.write(head)
        for t in tris:
            corners = [place(m, scale, move, verts[i]) for i in t]
            out.write("triangle %s material clay\n" % " ".join(
                "%r" % c for p in corners for c in p))
    print(len(tris))


if __name__ == "__main__":
    main(sys.argv[1])
