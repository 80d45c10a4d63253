#!/usr/bin/env python3
"""mesh_watertight.py - a closed, bumpy sphere of 2 x 80 x 120 triangles
whose neighbours share their corners bit for bit (each grid point is
computed once), written as binary STL; and, for a PBM rendered of it, the
background pixels that cannot be reached from the image's border through
background: a ray that fell through the crack between two triangles.

    mesh_watertight.py make FILE.stl
    mesh_watertight.py cracked FILE.stl   every triangle shrunk by 4%
    mesh_watertight.py holes FILE.pbm     prints the count
"""
import math
import struct
import sys


def make(path, shrink=0.0):
    n, m = 80, 120
    grid = {}
    for i in range(n + 1):
        for j in range(m):
            th, ph = math.pi * i / n, 2 * math.pi * j / m
            r = 1 + 0.08 * math.sin(5 * th) * math.cos(3 * ph)
            v = (r * math.sin(th) * math.cos(ph), r * math.cos(th),
                 r * math.sin(th) * math.sin(ph))
            grid[i, j] = struct.unpack("<3f", struct.pack("<3f", *v))
    tris = []
    for i in range(n):
        for j in range(m):
            a, b = grid[i, j], grid[i + 1, j]
            c, d = grid[i + 1, (j + 1) % m], grid[i, (j + 1) % m]
            if i != n - 1:
                tris.append((a, b, c))
            if i != 0:
                tris.append((a, c, d))
    with open(path, "wb") as f:
        f.write(b"watertight".ljust(80, b" ") + struct.pack("<I", len(tris)))
        for t in tris:
            f.write(struct.pack("<3f", 0, 0, 0))
            centre = [sum(v[k] for v in t) / 3 for k in range(3)]
            for v in t:
                f.write(struct.pack("<3f", *(v[k] + shrink * (centre[k] - v[k])
                                             for k in range(3))))
            f.write(b"\0\0")


def holes(path):
    data = open(path, "rb").read()
    words = data.split(None, 3)
    assert words[0] == b"P4"
    w, h = int(words[1]), int(words[2])
    raster = data[len(data) - ((w + 7) // 8) * h:]
    row = (w + 7) // 8
    black = lambda x, y: raster[y * row + x // 8] >> (7 - x % 8) & 1
    seen = [[False] * w for _ in range(h)]
    todo = [(x, y) for x in range(w) for y in (0, h - 1)] + \
           [(x, y) for y in range(h) for x in (0, w - 1)]
    while todo:
        x, y = todo.pop()
        if seen[y][x] or black(x, y):
            continue
        seen[y][x] = True
        for dx, dy in ((1, 0), (-1, 0), (0, 1), (0, -1)):
            if 0 <= x + dx < w and 0 <= y + dy < h:
                todo.append((x + dx, y + dy))
    print(sum(1 for y in range(h) for x in range(w)
              if not black(x, y) and not seen[y][x]))


if __name__ == "__main__":
    {"make": make, "cracked": lambda p: make(p, 0.04),
     "holes": holes}[sys.argv[1]](sys.argv[2])
