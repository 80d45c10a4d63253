#!/usr/bin/env python3
"""tp1_model.py - the course's TP1 light model computed from its statement
(trabajo-practico-1.md), independently of rayo: its own camera, its own
ray-sphere, ray-plane and Moller-Trumbore ray-triangle tests, Phong with
exponent 10 and each dot product clamped on its own, shadows from
P + eps L, reflections from P + eps R to a depth, colour (x) M, channels
cut at 1, and bytes as the integer part of 255 c.  It writes a scene
file rayo reads and the PPM this model makes of it.

    tp1_model.py SCENE.scene WANT.ppm [tinted] [to-light] [depth N]
"""
import math
import sys

W, H, FOV = 64, 48, 90.0
AMBIENT = (0.05, 0.05, 0.05)
EPS = 1e-6
MATERIALS = {  # colour, ka, kd, ks, kr
    "red": ((0.9, 0.2, 0.15), 1.0, 0.9, 0.6, 0.25),
    "floor": ((0.8, 0.8, 0.8), 1.0, 0.6, 0.2, 0.5),
    "blue": ((0.2, 0.35, 0.9), 1.0, 0.8, 0.5, 0.0),
}
SPHERES = [((-0.8, 0.0, 4.0), 0.9, "red"), ((1.2, 0.6, 6.0), 1.0, "blue"),
           ((0.4, 2.5, 3.0), 0.3, "red")]  # the last is above a light
PLANES = [((0.0, -1.0, 0.0), (0.0, 1.0, 0.0), "floor")]
TRIANGLES = [((0.2, -1.0, 3.5), (1.6, -1.0, 3.2), (0.9, 0.8, 3.8), "blue")]
LIGHTS = [("point", (0.5, 2.0, 2.5), (0.8, 0.8, 0.8)),
          ("directional", (1.0, 1.0, -1.0), (0.4, 0.4, 0.4))]


def sub(a, b): return (a[0] - b[0], a[1] - b[1], a[2] - b[2])
def add(a, b): return (a[0] + b[0], a[1] + b[1], a[2] + b[2])
def mul(a, s): return (a[0] * s, a[1] * s, a[2] * s)
def had(a, b): return (a[0] * b[0], a[1] * b[1], a[2] * b[2])
def dot(a, b): return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
def cross(a, b): return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                         a[0] * b[1] - a[1] * b[0])
def unit(a): return mul(a, 1.0 / math.sqrt(dot(a, a)))


def hit_sphere(o, d, c, r):
    oc = sub(o, c)
    b = dot(oc, d)
    disc = b * b - (dot(oc, oc) - r * r)
    if disc < 0:
        return None
    s = math.sqrt(disc)
    for t in (-b - s, -b + s):
        if t > 0:
            return t
    return None


def hit_plane(o, d, p, n):
    dn = dot(d, n)
    if dn == 0:
        return None
    t = dot(sub(p, o), n) / dn
    return t if t > 0 else None


def hit_triangle(o, d, a, b, c):
    e1, e2 = sub(b, a), sub(c, a)
    h = cross(d, e2)
    det = dot(e1, h)
    if abs(det) < 1e-12:
        return None
    s = sub(o, a)
    u = dot(s, h) / det
    if u < 0 or u > 1:
        return None
    q = cross(s, e1)
    v = dot(d, q) / det
    if v < 0 or u + v > 1:
        return None
    t = dot(e2, q) / det
    return t if t > 0 else None


def nearest(o, d):
    best = None
    for c, r, m in SPHERES:
        t = hit_sphere(o, d, c, r)
        if t is not None and (best is None or t < best[0]):
            p = add(o, mul(d, t))
            best = (t, p, unit(sub(p, c)), m)
    for p0, n, m in PLANES:
        t = hit_plane(o, d, p0, n)
        if t is not None and (best is None or t < best[0]):
            nn = unit(n)
            best = (t, add(o, mul(d, t)), nn if dot(nn, d) <= 0 else mul(nn, -1), m)
    for a, b, c, m in TRIANGLES:
        t = hit_triangle(o, d, a, b, c)
        if t is not None and (best is None or t < best[0]):
            n = unit(cross(sub(b, a), sub(c, a)))
            best = (t, add(o, mul(d, t)), n if dot(n, d) <= 0 else mul(n, -1), m)
    return best


def intensity(o, d, depth, tinted, to_light):
    h = nearest(o, d)
    if h is None:
        return (0.0, 0.0, 0.0)
    _, p, n, name = h
    colour, ka, kd, ks, kr = MATERIALS[name]
    r = sub(d, mul(n, 2 * dot(d, n)))
    c = mul(AMBIENT, ka)
    for kind, v, ii in LIGHTS:
        if kind == "point":
            to = sub(v, p)
            dist = math.sqrt(dot(to, to))
            l = mul(to, 1.0 / dist)
        else:
            l, dist = unit(v), math.inf
        s = nearest(add(p, mul(l, EPS)), l)
        if s is not None and (not to_light or s[0] < dist - EPS):
            continue
        diffuse = max(0.0, dot(l, n)) * kd
        rl = dot(l, r)
        specular = ks * rl ** 10 if rl > 0 else 0.0
        c = add(c, mul(ii, diffuse + specular))
    if depth > 0 and kr > 0:
        bounce = mul(intensity(add(p, mul(r, EPS)), r, depth - 1, tinted,
                               to_light), kr)
        if tinted:
            return had(add(c, bounce), colour)
        return add(had(c, colour), bounce)
    return had(c, colour)


def main():
    scene, want = sys.argv[1], sys.argv[2]
    args = sys.argv[3:]
    tinted, to_light = "tinted" in args, "to-light" in args
    depth = int(args[args.index("depth") + 1]) if "depth" in args else 1
    f = W / (2 * math.tan(math.radians(FOV) / 2))
    with open(scene, "w") as s:
        s.write("shade course-tp1%s%s\n" % (
            " tinted-reflections" if tinted else "",
            " shadows-to-light" if to_light else ""))
        s.write("depth %d\ncamera size %d %d fov %r\n" % (depth, W, H, FOV))
        s.write("ambient %r %r %r\n" % AMBIENT)
        for name, (col, ka, kd, ks, kr) in MATERIALS.items():
            s.write("material %s color %r %r %r ka %r kd %r ks %r reflect %r\n"
                    % ((name,) + col + (ka, kd, ks, kr)))
        for kind, v, ii in LIGHTS:
            s.write("light %s %r %r %r color %r %r %r\n" % ((kind,) + v + ii))
        for c, r, m in SPHERES:
            s.write("sphere %r %r %r %r material %s\n" % (c + (r, m)))
        for p0, n, m in PLANES:
            s.write("plane %r %r %r %r %r %r material %s\n" % (p0 + n + (m,)))
        for a, b, c, m in TRIANGLES:
            s.write("triangle %s material %s\n"
                    % (" ".join("%r" % x for x in a + b + c), m))
    out = bytearray(b"P6\n%d %d\n255\n" % (W, H))
    for j in range(H):
        for i in range(W):
            x, y = i - W // 2, j - H // 2
            d = unit((x, -y, f))
            c = intensity((0.0, 0.0, 0.0), d, depth, tinted, to_light)
            out += bytes(int(255 * min(1.0, max(0.0, v))) for v in c)
    with open(want, "wb") as w:
        w.write(out)


if __name__ == "__main__":
    main()
