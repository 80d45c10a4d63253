#!/usr/bin/env python3
"""bmp_make.py - writes BMP files of every layout bmp.t reads, and the
PPM, PGM or PBM each one must become, independently of rayo: the pixels
come from a formula, each layout is packed by hand from the format's
documentation (BITMAPINFOHEADER and its V4 form, palettes, channel
masks, padding, a negative height for rows top down).

    bmp_make.py DIR    writes DIR/NAME.bmp and DIR/NAME.want.pnm
"""
import os
import struct
import sys

W, H = 13, 7  # 13 pixels: every row of 1, 4, 8, 16 and 24 bits is padded


def rgb(x, y):
    return ((x * 19 + y * 7) % 256, (x * 5 + y * 31) % 256, (x * y * 11) % 256)


def gray(x, y):
    return (x * 17 + y * 29) % 256


def headers(width, height, bits, compression=0, colours=0, info=40,
            extra=b"", palette=b"", raster=b""):
    if info == 40:
        dib = struct.pack("<IiiHHIIiiII", 40, width, height, 1, bits,
                          compression, 0, 0, 0, colours, 0)
    else:  # V4: the masks inside the header
        dib = struct.pack("<IiiHHIIiiII", info, width, height, 1, bits,
                          compression, 0, 0, 0, colours, 0) + extra
        dib += bytes(info - len(dib))
        extra = b""
    offset = 14 + len(dib) + len(extra) + len(palette)
    size = offset + len(raster)
    return b"BM" + struct.pack("<IHHI", size, 0, 0, offset) + dib + extra + \
        palette + raster


def pad(row, unpadded=False):
    return row if unpadded else row + bytes(-len(row) % 4)


def rows(pack, top_down=False, unpadded=False):
    order = range(H) if top_down else range(H - 1, -1, -1)
    return b"".join(pad(pack(y), unpadded) for y in order)


def ppm(f):
    out = b"P6\n%d %d\n255\n" % (W, H)
    return out + bytes(c for y in range(H) for x in range(W) for c in f(x, y))


def pgm(f):
    return b"P5\n%d %d\n255\n" % (W, H) + bytes(
        f(x, y) for y in range(H) for x in range(W))


def bits_of(values, depth):
    out, acc, n = bytearray(), 0, 0
    for v in values:
        acc = (acc << depth) | v
        n += depth
        if n == 8:
            out.append(acc)
            acc, n = 0, 0
    if n:
        out.append(acc << (8 - n))
    return bytes(out)


def main(folder):
    files = {}
    bgr = lambda y: bytes(c for x in range(W) for c in reversed(rgb(x, y)))
    files["rgb24"] = (headers(W, H, 24, raster=rows(bgr)), ppm(rgb))
    files["rgb24_topdown"] = (headers(W, -H, 24, raster=rows(bgr, True)),
                              ppm(rgb))
    files["rgb24_unpadded"] = (headers(W, H, 24,
                                       raster=rows(bgr, unpadded=True)),
                               ppm(rgb))
    x32 = lambda y: b"".join(bytes(reversed(rgb(x, y))) + b"\x7f"
                             for x in range(W))
    files["rgb32"] = (headers(W, H, 32, raster=rows(x32)), ppm(rgb))
    # 32 bits, bit fields in the order R G B A from the low byte.
    masks = struct.pack("<III", 0xff, 0xff00, 0xff0000)
    f32 = lambda y: b"".join(bytes(rgb(x, y)) + b"\xff" for x in range(W))
    files["rgb32_fields"] = (headers(W, H, 32, 3, extra=masks,
                                     raster=rows(f32)), ppm(rgb))
    files["rgb32_v4"] = (headers(W, -H, 32, 3, info=108, extra=masks,
                                 raster=rows(f32, True)), ppm(rgb))
    # 16 bits, 5-6-5: the expected value is the field scaled, rounded.
    q = lambda v, n: (v >> (8 - n))
    s = lambda v, n: (q(v, n) * 255 + ((1 << n) - 1) // 2) // ((1 << n) - 1)
    rgb565 = lambda x, y: (s(rgb(x, y)[0], 5), s(rgb(x, y)[1], 6),
                           s(rgb(x, y)[2], 5))
    p565 = lambda y: b"".join(struct.pack("<H", q(rgb(x, y)[0], 5) << 11 |
                                          q(rgb(x, y)[1], 6) << 5 |
                                          q(rgb(x, y)[2], 5))
                              for x in range(W))
    files["rgb16_565"] = (headers(W, H, 16, 3, extra=struct.pack(
        "<III", 0xf800, 0x07e0, 0x001f), raster=rows(p565)), ppm(rgb565))
    # 8-bit gray palette, shuffled so an index is not its gray.
    shuffle = [(i * 73 + 11) % 256 for i in range(256)]
    index_of = {g: i for i, g in enumerate(shuffle)}
    pal8 = b"".join(bytes((g, g, g, 0)) for g in shuffle)
    p8 = lambda y: bytes(index_of[gray(x, y)] for x in range(W))
    files["gray8"] = (headers(W, H, 8, colours=256, palette=pal8,
                              raster=rows(p8)), pgm(gray))
    # 4-bit colour palette of 16 entries.
    pal = [((i * 37) % 256, (i * 91) % 256, (255 - i * 13) % 256)
           for i in range(16)]
    pal4 = b"".join(bytes((b, g, r, 0)) for r, g, b in pal)
    idx = lambda x, y: (x + 3 * y) % 16
    p4 = lambda y: bits_of([idx(x, y) for x in range(W)], 4)
    files["palette4"] = (headers(W, H, 4, colours=16, palette=pal4,
                                 raster=rows(p4)),
                         ppm(lambda x, y: pal[idx(x, y)]))
    # 1 bit, palette black then white (index 1 = white): a PBM.
    on = lambda x, y: (x * x + y * 3) % 5 == 0
    p1 = lambda y: bits_of([0 if on(x, y) else 1 for x in range(W)], 1)
    pbm = b"P4\n%d %d\n" % (W, H) + b"".join(
        bits_of([1 if on(x, y) else 0 for x in range(W)], 1) for y in range(H))
    files["bilevel_black_first"] = (headers(W, H, 1, colours=2,
                                            palette=b"\0\0\0\0\xff\xff\xff\0",
                                            raster=rows(p1)), pbm)
    for name, (bmp, want) in files.items():
        with open(os.path.join(folder, name + ".bmp"), "wb") as f:
            f.write(bmp)
        with open(os.path.join(folder, name + ".want.pnm"), "wb") as f:
            f.write(want)
    # Broken ones: (name, bytes).
    good = files["rgb24"][0]
    broken = {
        "truncated": good[:-100],
        "rle8": headers(W, H, 8, 1, colours=2, palette=bytes(8),
                        raster=bytes(40)),
        "planes": good[:26] + struct.pack("<H", 2) + good[28:],
        "header_size": good[:14] + struct.pack("<I", 41) + good[18:],
        "index_past_palette": headers(W, H, 8, colours=4,
                                      palette=bytes(16),
                                      raster=bytes([9]) + bytes(16 * H - 1)),
        "zero_width": headers(0, H, 24, raster=b""),
        "huge": headers(70000, 70000, 24, raster=b""),
    }
    for name, data in broken.items():
        with open(os.path.join(folder, "bad_" + name + ".bmp"), "wb") as f:
            f.write(data)


if __name__ == "__main__":
    main(sys.argv[1])
