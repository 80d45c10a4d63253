#!/usr/bin/env python3
"""scene_to_pov.py - a scene file of bench/field_scene.py's subset as POV-Ray 3.7.

The benchmark times POV-Ray on the scene rayo renders (issue 17), so the
translation keeps what decides the work: the same spheres and plane, one
ray per pixel through the same points of the image plane, the point
light with shadows, and finishes that cast the same rays (phong highlights,
mirror reflection where rayo reflects).  A `mesh FILE` line's binary STL
(bench/scan/scan_mesh.c's) becomes a `mesh2`: its corners shared where the
file repeats them bit for bit, each triangle flat (the STL's facet normal
is its corners' own, as rayo shades it); ASCII STL, OBJ and the mesh
line's placement words are refused.

The camera.  rayo's ray through column i, row j of a w x h image has
direction (i - floor(w/2)) right - (j - floor(h/2)) up + f forward, with
f = w / (2 tan(fov/2)) (include/rayo/camera.h); POV-Ray's goes through the
pixel's centre, D + (x - 1/2) R + (1/2 - y) U with x = (i + 1/2) / w and
y = (j + 1/2) / h.  With R = w right, U = h up and D = f forward plus the
half-pixel difference, the two are the same direction for every pixel
(in doubles: POV-Ray's own arithmetic then decides the last bits).

Finishes: rayo's ka Ia M + kd (L.N) M + ks (R.V)^n + r reflected is
POV-Ray's ambient (with global ambient_light Ia), diffuse, phong with
phong_size n, and reflection r; max_trace_level is rayo's depth 5 plus the
primary ray; assumed_gamma 1 keeps colours linear as rayo's are.  The
light has no fading, like rayo's.  Not the same: POV-Ray reads the whole
.pov text (its parse of 100,000 spheres is part of its time), bounds the
objects its own way, and its floating point differs in the last bits.

usage: scene_to_pov.py SCENE > scene.pov
Errors in the scene: one line on stderr with the line number, exit 2.
"""
import math
import os
import struct
import sys


# rayo's material defaults (docs/scene-format.md), material 0 included.
DEFAULT = {"color": (1.0, 1.0, 1.0), "ka": 1.0, "kd": 1.0, "ks": 0.0,
           "shininess": 32.0, "reflect": 0.0}


def fail(path, line, what):
    sys.stderr.write("scene_to_pov.py: %s:%d: %s\n" % (path, line, what))
    sys.exit(2)


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def scale(a, s):
    return (a[0] * s, a[1] * s, a[2] * s)


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0])


def normalize(a):
    return scale(a, 1.0 / math.sqrt(dot(a, a)))


def vec(v):
    return "<%r, %r, %r>" % v


class Reader:
    """The words of one line, read as numbers and vectors."""

    def __init__(self, path, number, words):
        self.path, self.number, self.words, self.at = path, number, words, 0

    def word(self, what):
        if self.at == len(self.words):
            fail(self.path, self.number, "expected %s, found the end of the "
                 "line" % what)
        self.at += 1
        return self.words[self.at - 1]

    def num(self, what):
        w = self.word(what)
        try:
            value = float(w)
        except ValueError:
            fail(self.path, self.number, "expected %s, found '%s'" %
                 (what, w[:40]))
        if not math.isfinite(value):
            fail(self.path, self.number, "expected %s, found '%s'" %
                 (what, w[:40]))
        return value

    def vector(self, what):
        return (self.num(what), self.num(what), self.num(what))

    def colour(self):
        """One value (grey) or three."""
        first = self.num("a colour")
        if self.at < len(self.words):
            try:
                second = float(self.words[self.at])
            except ValueError:
                return (first, first, first)
            self.at += 1
            return (first, second, self.num("a colour"))
        return (first, first, first)

    def rest(self):
        return self.words[self.at:]


def material_of(reader):
    rest = reader.rest()
    if not rest:
        return None
    if len(rest) != 2 or rest[0] != "material":
        fail(reader.path, reader.number, "expected 'material NAME' or the "
             "end of the line")
    return rest[1]


def read(path):
    scene = {"size": (640, 480), "fov": 90.0, "origin": (0.0, 0.0, 0.0),
             "look_at": None, "up": (0.0, 1.0, 0.0),
             "background": (0.0, 0.0, 0.0), "ambient": (0.0, 0.0, 0.0),
             "depth": 5, "lights": [], "materials": {}, "order": [],
             "spheres": [], "planes": [], "meshes": []}
    with open(path) as f:
        for number, line in enumerate(f, 1):
            words = line.split("#", 1)[0].split()
            if not words:
                continue
            r = Reader(path, number, words[1:])
            key = words[0]
            if key == "camera":
                while r.at < len(r.words):
                    setting = r.word("a camera setting")
                    if setting == "size":
                        scene["size"] = (int(r.num("a width")),
                                         int(r.num("a height")))
                    elif setting == "fov":
                        scene["fov"] = r.num("a field of view")
                    elif setting == "origin":
                        scene["origin"] = r.vector("the origin")
                    elif setting == "look-at":
                        scene["look_at"] = r.vector("the look-at point")
                    elif setting == "up":
                        scene["up"] = r.vector("the up vector")
                    else:
                        fail(path, number, "unknown camera setting '%s'; "
                             "expected size, fov, origin, look-at or up" %
                             setting[:40])
            elif key == "light":
                if r.word("'point'") != "point":
                    fail(path, number, "expected 'light point X Y Z' (only "
                         "point lights are translated)")
                position = r.vector("the light's position")
                colour = (1.0, 1.0, 1.0)
                if r.rest()[:1] == ["color"]:
                    r.at += 1
                    colour = r.colour()
                scene["lights"].append((position, colour))
            elif key == "material":
                name = r.word("a material name")
                m = dict(DEFAULT)
                while r.at < len(r.words):
                    prop = r.word("a material property")
                    if prop == "color":
                        m["color"] = r.colour()
                    elif prop in m:
                        m[prop] = r.num(prop)
                    else:
                        fail(path, number, "unknown material property '%s'"
                             % prop[:40])
                scene["materials"][name] = m
                scene["order"].append(name)
            elif key == "sphere":
                c = r.vector("the centre")
                radius = r.num("a radius")
                if not radius > 0:
                    fail(path, number, "expected a radius greater than 0")
                scene["spheres"].append((c, radius, material_of(r)))
            elif key == "plane":
                p = r.vector("the plane's point")
                n = r.vector("its normal")
                if dot(n, n) == 0:
                    fail(path, number, "expected a non-zero normal")
                scene["planes"].append((p, n, material_of(r)))
            elif key == "mesh":
                name = r.word("a mesh file")
                stl = os.path.join(os.path.dirname(path), name)
                scene["meshes"].append((stl, material_of(r)))
            elif key == "background":
                scene["background"] = r.colour()
            elif key == "ambient":
                scene["ambient"] = r.colour()
            elif key == "depth":
                scene["depth"] = int(r.num("a depth"))
            elif key in ("shade", "samples"):
                pass
            else:
                fail(path, number, "unknown keyword '%s'; expected camera, "
                     "light, material, sphere, plane, mesh, background, "
                     "ambient, depth, shade or samples" % key[:40])
    return scene


def camera(scene):
    """rayo's basis (camera.c), then POV-Ray's location, direction, right
    and up for the same rays."""
    w, h = scene["size"]
    origin = scene["origin"]
    right, up, forward = (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)
    if scene["look_at"] is not None:
        forward = normalize(sub(scene["look_at"], origin))
        right = normalize(cross(scene["up"], forward))
        up = cross(forward, right)
    focal = w / (2.0 * math.tan(scene["fov"] * math.pi / 360.0))
    # x = i - floor(w/2) = w (xs - 1/2) + dx; -y = h (1/2 - ys) + dy.
    dx = w / 2.0 - w // 2 - 0.5
    dy = -(h / 2.0 - h // 2 - 0.5)
    direction = add(add(scale(forward, focal), scale(right, dx)),
                    scale(up, dy))
    return ("camera {\n  perspective\n  location %s\n  direction %s\n"
            "  right %s\n  up %s\n}\n" %
            (vec(origin), vec(direction), vec(scale(right, float(w))),
             vec(scale(up, float(h)))))


def texture(m):
    return ("texture { pigment { color rgb %s } finish { ambient %r diffuse "
            "%r phong %r phong_size %r reflection %r } }" %
            (vec(m["color"]), m["ka"], m["kd"], m["ks"], m["shininess"],
             m["reflect"]))


def mesh2(path, texture_name):
    """A binary STL as POV-Ray's mesh2: shared vertices, indexed faces."""
    with open(path, "rb") as f:
        data = f.read()
    if len(data) < 84 or len(data) != 84 + 50 * struct.unpack_from(
            "<I", data, 80)[0]:
        sys.stderr.write("scene_to_pov.py: %s: expected a binary STL (84 "
                         "+ 50 x its count bytes)\n" % path)
        sys.exit(2)
    index, faces = {}, []
    for record in struct.iter_unpack("<12x9f2x", data[84:]):
        face = []
        for k in (0, 3, 6):
            corner = record[k:k + 3]
            face.append(index.setdefault(corner, len(index)))
        faces.append("<%d,%d,%d>" % tuple(face))
    vertices = ["<%r,%r,%r>" % v for v in index]
    return ("mesh2 {\n  vertex_vectors { %d,\n%s\n  }\n"
            "  face_indices { %d,\n%s\n  }\n  texture { %s }\n}\n" %
            (len(vertices), ",\n".join(vertices), len(faces),
             ",\n".join(faces), texture_name))


def main():
    if len(sys.argv) != 2:
        sys.stderr.write("usage: scene_to_pov.py SCENE > scene.pov\n")
        sys.exit(2)
    scene = read(sys.argv[1])
    out = sys.stdout
    names = {}
    out.write("// %s, translated by bench/scene_to_pov.py\n" % sys.argv[1])
    out.write("#version 3.7;\nglobal_settings {\n  assumed_gamma 1.0\n"
              "  ambient_light rgb %s\n  max_trace_level %d\n}\n" %
              (vec(scene["ambient"]), scene["depth"] + 1))
    out.write("background { color rgb %s }\n" % vec(scene["background"]))
    out.write(camera(scene))
    for position, colour in scene["lights"]:
        out.write("light_source { %s color rgb %s }\n" %
                  (vec(position), vec(colour)))
    out.write("#declare T_default = %s\n" % texture(DEFAULT))
    for i, name in enumerate(scene["order"]):
        names[name] = "T%d" % i
        out.write("#declare T%d = %s  // %s\n" %
                  (i, texture(scene["materials"][name]), name))

    def texture_name(name):
        return names.get(name, "T_default") if name else "T_default"

    for p, n, material in scene["planes"]:
        unit = normalize(n)
        out.write("plane { %s, %r texture { %s } }\n" %
                  (vec(unit), dot(unit, p), texture_name(material)))
    out.write("".join("sphere { %s, %r texture { %s } }\n" %
                      (vec(c), radius, texture_name(material))
                      for c, radius, material in scene["spheres"]))
    for stl, material in scene["meshes"]:
        out.write(mesh2(stl, texture_name(material)))


if __name__ == "__main__":
    main()
