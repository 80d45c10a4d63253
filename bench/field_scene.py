#!/usr/bin/env python3
"""field_scene.py - writes the benchmark's field of spheres as a scene file.

The field is the one `make bench` renders in memory
(rayo_scene_random_spheres in src/scene/random.c: the same 64-bit linear
congruential generator, the same spheres to the last bit, since Python's
floats are IEEE doubles and repr() prints the shortest text that reads
back as the same double), lit by one point light, so that rayo, the
Embree program (bench/embree/) and POV-Ray (bench/scene_to_pov.py) all
read one file and trace the same spheres.

usage: field_scene.py [--count N] [--seed S] [--view level|above]
                      [--size WxH] > field.scene
"""
import argparse
import sys

MASK = (1 << 64) - 1
PALETTE = [(0.9, 0.2, 0.2), (0.2, 0.8, 0.3), (0.2, 0.4, 0.9),
           (0.9, 0.8, 0.2), (0.8, 0.3, 0.8), (0.2, 0.8, 0.8),
           (0.9, 0.9, 0.9), (0.9, 0.5, 0.1)]


class Lcg:
    """rayo_lcg: state * 6364136223846793005 + 1442695040888963407."""

    def __init__(self, seed):
        self.state = seed & MASK

    def next(self):
        self.state = (self.state * 6364136223846793005 +
                      1442695040888963407) & MASK
        return float(self.state >> 11) * (1.0 / 9007199254740992.0)

    def uniform(self, lo, hi):
        return lo + (hi - lo) * self.next()


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count", type=int, default=100000)
    parser.add_argument("--seed", type=int, default=2026)
    parser.add_argument("--view", choices=("level", "above"),
                        default="level")
    parser.add_argument("--size", default="1920x1080")
    args = parser.parse_args()
    width, height = (int(v) for v in args.size.split("x"))
    out = sys.stdout
    out.write("# %d spheres on a ground plane (bench/field_scene.py, seed %d)"
              "\n" % (args.count, args.seed))
    out.write("shade phong\n")
    if args.view == "level":
        out.write("camera size %d %d fov 90 origin 0 0 0\n" % (width, height))
    else:
        out.write("camera size %d %d fov 60 origin 0 5 -10 look-at 0 -1 35 "
                  "up 0 1 0\n" % (width, height))
    out.write("background 0.5 0.7 1\nambient 0.1\n")
    out.write("light point -10 20 20 color 0.5 0.5 0.4\n")
    out.write("material ground color 0.6 ka 0.1 kd 0.8 ks 0\n")
    for i, (r, g, b) in enumerate(PALETTE):
        out.write("material m%d color %r %r %r ka 0.1 kd 0.8 ks 0.3 "
                  "shininess 32%s\n" % (i, r, g, b,
                                        " reflect 0.5" if i == 6 else ""))
    out.write("plane 0 -1 0  0 1 0 material ground\n")
    lcg = Lcg(args.seed)
    spacing = (10000.0 / args.count) ** 0.5
    lines = []
    for i in range(args.count):
        x = lcg.uniform(-50.0, 50.0)
        z = lcg.uniform(5.0, 105.0)
        r = 0.3 * spacing * (0.5 + 0.5 * lcg.next())
        lines.append("sphere %r %r %r %r material m%d\n" %
                     (x, r - 1.0, z, r, i % 8))
    out.write("".join(lines))


if __name__ == "__main__":
    main()
