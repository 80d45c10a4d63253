#!/usr/bin/env python3
"""generate.py - writes the malformed-image corpus in this folder.

Each file is small and wrong in one way (named by the file); every one must
make `rayo convert FILE OUT.pbm` exit 2 with one line on stderr naming the
file, and leave no OUT.pbm (tests/cli/malformed.t checks this).  The files
are committed; this script documents how they were made and can remake
them (python3 generate.py, in this folder).  A later fuzzing pass uses them
as seeds.  Not run by the tests.
"""
import struct
import zlib


def write(name, data):
    if isinstance(data, str):
        data = data.encode("latin-1")
    with open(name, "wb") as f:
        f.write(data)


def chunk(kind, body, crc=None):
    if crc is None:
        crc = zlib.crc32(kind + body) & 0xFFFFFFFF
    return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", crc)


SIG = b"\x89PNG\r\n\x1a\n"


def ihdr(w, h, depth=8, ctype=0, interlace=0):
    return chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, depth, ctype, 0, 0,
                                      interlace))


def gray_idat(w, h, level=9):
    raw = b"".join(b"\x00" + bytes((x * 37 + y) & 255 for x in range(w))
                   for y in range(h))
    return chunk(b"IDAT", zlib.compress(raw, level))


IEND = chunk(b"IEND", b"")


def png_ok(w=4, h=3):
    return SIG + ihdr(w, h) + gray_idat(w, h) + IEND


# Netpbm: magic, sizes, maxval, rasters.
write("empty.pbm", "")
write("bad-magic-p7.pbm", "P7\nWIDTH 2\nHEIGHT 2\nDEPTH 1\nMAXVAL 1\n"
      "TUPLTYPE BLACKANDWHITE\nENDHDR\n\x00\x01\x01\x00")
write("bad-magic-text.pbm", "hello, world\n")
write("bad-magic-lowercase.pbm", "p1\n2 2\n0 1 1 0\n")
write("p1-other-characters.pbm", "P1\n3 2\n0 1 0\n1 x 1\n")
write("p1-digit-two.pbm", "P1\n3 2\n0 1 0\n1 2 1\n")
write("p1-truncated.pbm", "P1\n4 4\n0 1 0 1\n1 0 1 0\n0 1\n")
write("p1-promises-more-than-file.pbm", "P1\n100 100\n0 1 0 1\n")
write("p1-negative-width.pbm", "P1\n-3 2\n0 1 0\n1 0 1\n")
write("p1-zero-width.pbm", "P1\n0 2\n")
write("p1-zero-height.pbm", "P1\n2 0\n")
write("p1-huge-width.pbm", "P1\n70000 1\n0\n")
write("p1-overflowing-width.pbm", "P1\n99999999999999999999 1\n0\n")
write("p1-too-many-pixels.pbm", "P1\n65536 65536\n0\n")
write("p1-no-height.pbm", "P1\n3")
write("p1-garbage-in-width.pbm", "P1\n3x 2\n0 1 0\n1 0 1\n")
write("p1-unterminated-comment.pbm", "P1\n# a comment that never ends")
write("p2-maxval-0.pgm", "P2\n2 2\n0\n0 0\n0 0\n")
write("p2-maxval-65536.pgm", "P2\n2 2\n65536\n0 1\n2 3\n")
write("p2-sample-over-maxval.pgm", "P2\n2 1\n10\n5 11\n")
write("p2-letters-in-raster.pgm", "P2\n2 1\n255\n12 ab\n")
write("p2-truncated.pgm", "P2\n3 3\n255\n1 2 3\n4 5 6\n7\n")
write("p3-truncated.ppm", "P3\n2 2\n255\n1 2 3 4 5 6\n7 8 9 10\n")
write("p3-negative-sample.ppm", "P3\n1 1\n255\n-1 0 0\n")
write("p4-truncated.pbm", b"P4\n16 4\n" + b"\xff\x00" * 3)
write("p4-missing-raster.pbm", "P4\n8 8\n")
write("p5-truncated.pgm", b"P5\n4 4\n255\n" + bytes(range(10)))
write("p5-sample-over-maxval.pgm", b"P5\n2 2\n100\n" + bytes([1, 2, 200, 3]))
write("p5-16bit-over-maxval.pgm",
      b"P5\n2 1\n1000\n" + struct.pack(">HH", 5, 0xFFFF))
write("p5-no-space-after-maxval.pgm", b"P5\n2 2\n255X" + bytes(4))
write("p6-truncated.ppm", b"P6\n3 3\n255\n" + bytes(20))
write("p6-16bit-raster-too-short.ppm", b"P6\n2 2\n65535\n" + bytes(12))
write("p6-overflowing-maxval.ppm", b"P6\n1 1\n4294967296\n" + bytes(3))

# PNG: signature, CRCs, chunk order, sizes, compressed data.
good = png_ok()
write("png-damaged-signature.png", b"\x89PNG\r\n\x1a\x0d" + good[8:])
write("png-truncated-signature.png", SIG[:5])
ih = bytearray(ihdr(4, 3))
ih[-1] ^= 0x55
write("png-bad-crc-ihdr.png", SIG + bytes(ih) + gray_idat(4, 3) + IEND)
idat = bytearray(gray_idat(4, 3))
idat[-2] ^= 0x01
write("png-bad-crc-idat.png", SIG + ihdr(4, 3) + bytes(idat) + IEND)
text = bytearray(chunk(b"tEXt", b"Comment\x00hello"))
text[-1] ^= 0xFF
write("png-bad-crc-text.png",
      SIG + ihdr(4, 3) + bytes(text) + gray_idat(4, 3) + IEND)
write("png-no-iend.png", SIG + ihdr(4, 3) + gray_idat(4, 3))
write("png-gigapixel-ihdr.png", SIG + ihdr(60000, 60000) + gray_idat(4, 3)
      + IEND)
write("png-ihdr-larger-than-file.png", SIG + ihdr(16384, 16384)
      + gray_idat(4, 3) + IEND)
write("png-width-over-limit.png", SIG + ihdr(100000, 1) + gray_idat(4, 1)
      + IEND)
write("png-width-2-to-the-31.png", SIG + ihdr(0x7FFFFFFF, 1)
      + gray_idat(4, 1) + IEND)
write("png-zero-width.png", SIG + ihdr(0, 3) + gray_idat(4, 3) + IEND)
write("png-bit-depth-3.png", SIG + ihdr(4, 3, depth=3) + gray_idat(4, 3)
      + IEND)
write("png-truncated-idat.png", good[:len(good) - len(IEND) - 9])
write("png-idat-too-short.png", SIG + ihdr(4, 30) + gray_idat(4, 3) + IEND)
write("png-no-idat.png", SIG + ihdr(4, 3) + IEND)
write("png-idat-not-zlib.png", SIG + ihdr(4, 3)
      + chunk(b"IDAT", b"this is not a zlib stream") + IEND)
write("png-palette-without-plte.png", SIG + ihdr(4, 3, ctype=3)
      + gray_idat(4, 3) + IEND)
write("png-only-signature.png", SIG)
