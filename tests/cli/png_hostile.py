#!/usr/bin/env python3
# png_hostile.py - writes the hostile PNG files of tests/cli/png_hostile.t
# (issue 14): ancillary chunks that inflate or declare far more than they
# hold, a zlib bomb after a complete image, and a large interlaced 16-bit
# RGBA image.  Made here with zlib and struct, so that no large binary is
# committed; each file is checked against Python's own idea of PNG, not
# against rayo.
#
# usage: png_hostile.py KIND OUT [ARGS...]
#   text-bomb OUT TYPE COUNT KIB   1x1 image, COUNT zTXt or iTXt chunks
#                                  each inflating to KIB KiB
#   long-chunk OUT TYPE [LENGTH]   44 bytes: IHDR, then a TYPE chunk that
#                                  declares LENGTH bytes (2^31-1) and
#                                  holds 3
#   big-text OUT TYPE MIB          1x1 image after one complete TYPE chunk
#                                  of MIB MiB (a tEXt larger than libpng's
#                                  default 8 MB cap)
#   idat-bomb OUT GIB              1x1 image whose zlib stream goes on with
#                                  GIB GiB of zeros after the image's bytes
#   after-image OUT CASE           1x1 image, then: crc (a damaged IDAT CRC
#                                  after the image), no-iend (the file ends
#                                  after IDAT), plte (a PLTE after IDAT)
#   rgba16 OUT WIDTH HEIGHT        interlaced 16-bit RGBA, every pixel
#                                  (0x1234, 0x8000, 0xffff, alpha 0x8000)
#   run MEASURE AS_MIB CPU_S OUT ERR CMD...
#                                  runs CMD with its address space limited
#                                  to AS_MIB MiB (0: not limited) and its
#                                  CPU time to CPU_S s, stdout to OUT (or
#                                  to this script's, for '-'), stderr to
#                                  ERR; writes to MEASURE its exit status
#                                  (128 + the signal when killed), peak
#                                  resident memory in MiB and user +
#                                  system time in ms
#   check-ppm WIDTH HEIGHT R G B   standard input is a 16-bit PPM of that
#                                  size whose every pixel is (R, G, B)
import struct
import sys
import zlib

SIGNATURE = b"\x89PNG\r\n\x1a\n"


def chunk(kind, data):
    body = kind + data
    return struct.pack(">I", len(data)) + body + \
        struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)


def ihdr(width, height, depth=8, colour=0, interlace=0):
    return chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, depth,
                                      colour, 0, 0, interlace))


def one_pixel():
    """The IDAT and IEND of a 1x1 8-bit gray image of value 0x80."""
    return chunk(b"IDAT", zlib.compress(b"\x00\x80")) + chunk(b"IEND", b"")


def text_bomb(out, kind, count, kib):
    # The same text in every chunk, one letter repeated (libpng keeps the
    # inflated text as a C string: zeros would be kept as "").
    packed = zlib.compress(b"a" * (kib << 10), 9)
    if kind == "zTXt":
        data = b"Comment\0\0" + packed
    else:  # iTXt: keyword, compressed flag, method, language, key
        data = b"Comment\0\1\0\0\0" + packed
    one = chunk(kind.encode(), data)
    with open(out, "wb") as f:
        f.write(SIGNATURE + ihdr(1, 1))
        for _ in range(count):
            f.write(one)
        f.write(one_pixel())


def long_chunk(out, kind, length=2**31 - 1):
    data = SIGNATURE + ihdr(1, 1) + struct.pack(">I", length) + \
        kind.encode() + b"abc"
    assert len(data) == 44
    with open(out, "wb") as f:
        f.write(data)


def big_text(out, kind, mib):
    if kind == "tEXt":
        data = b"Comment\0" + b"x" * (mib << 20)
    else:
        raise SystemExit("big-text: tEXt only")
    with open(out, "wb") as f:
        f.write(SIGNATURE + ihdr(1, 1) + chunk(kind.encode(), data) +
                one_pixel())


def adler_zeros(adler, count):
    """adler32 of the data so far followed by count zero bytes."""
    a, b = adler & 0xFFFF, adler >> 16
    b = (b + count * a) % 65521
    return (b << 16) | a


def idat_bomb(out, gib):
    row = b"\x00\x80"
    head = zlib.compressobj(9)
    stream = head.compress(row) + head.flush(zlib.Z_FULL_FLUSH)
    # A byte-aligned run of deflate blocks that owes nothing to what came
    # before (the full flush reset the window), so it may be repeated.
    block_mib = 64
    raw = zlib.compressobj(9, zlib.DEFLATED, -15)
    block = raw.compress(b"\0" * (block_mib << 20)) + \
        raw.flush(zlib.Z_FULL_FLUSH)
    repeats = (gib << 10) // block_mib
    end = zlib.compressobj(9, zlib.DEFLATED, -15).flush()  # final block
    adler = adler_zeros(zlib.adler32(row), repeats * (block_mib << 20))
    body = stream + block * repeats + end + struct.pack(">I", adler)
    with open(out, "wb") as f:
        f.write(SIGNATURE + ihdr(1, 1))
        step = 1 << 20
        for i in range(0, len(body), step):
            f.write(chunk(b"IDAT", body[i:i + step]))
        f.write(chunk(b"IEND", b""))


def after_image(out, case):
    idat = chunk(b"IDAT", zlib.compress(b"\x00\x80"))
    if case == "crc":
        idat = idat[:-1] + bytes([idat[-1] ^ 1])
        tail = idat + chunk(b"IEND", b"")
    elif case == "no-iend":
        tail = idat
    elif case == "plte":
        tail = idat + chunk(b"PLTE", b"\0\0\0") + chunk(b"IEND", b"")
    else:
        raise SystemExit("after-image: crc, no-iend or plte")
    with open(out, "wb") as f:
        f.write(SIGNATURE + ihdr(1, 1) + tail)


# Adam7: (first column, column step, first row, row step) of each pass.
ADAM7 = [(0, 8, 0, 8), (4, 8, 0, 8), (0, 4, 4, 8), (2, 4, 0, 4),
         (0, 2, 2, 4), (1, 2, 0, 2), (0, 1, 1, 2)]


def rgba16(out, width, height):
    pixel = struct.pack(">HHHH", 0x1234, 0x8000, 0xFFFF, 0x8000)
    packer = zlib.compressobj(6)
    with open(out, "wb") as f:
        f.write(SIGNATURE + ihdr(width, height, 16, 6, 1))
        for x0, dx, y0, dy in ADAM7:
            cols = (width - x0 + dx - 1) // dx
            rows = (height - y0 + dy - 1) // dy
            if cols <= 0 or rows <= 0:
                continue
            line = b"\x00" + pixel * cols
            batch = max(1, (4 << 20) // len(line))
            for done in range(0, rows, batch):
                data = packer.compress(line * min(batch, rows - done))
                if data:
                    f.write(chunk(b"IDAT", data))
        f.write(chunk(b"IDAT", packer.flush()))
        f.write(chunk(b"IEND", b""))


def run(argv):
    import resource
    import subprocess
    measure, limit_mib, cpu, out, err, command = argv[0], int(argv[1]), \
        int(argv[2]), argv[3], argv[4], argv[5:]

    def limits():
        if limit_mib > 0:
            resource.setrlimit(resource.RLIMIT_AS,
                               (limit_mib << 20, limit_mib << 20))
        resource.setrlimit(resource.RLIMIT_CPU, (cpu, cpu + 1))

    with open(err, "wb") as e:
        if out == "-":
            sys.stdout.flush()
            status = subprocess.call(command, preexec_fn=limits, stderr=e)
        else:
            with open(out, "wb") as o:
                status = subprocess.call(command, preexec_fn=limits,
                                         stdout=o, stderr=e)
    used = resource.getrusage(resource.RUSAGE_CHILDREN)
    if status < 0:
        status = 128 - status
    with open(measure, "w") as m:
        m.write("%d %d %d\n" % (status, used.ru_maxrss // 1024,
                                (used.ru_utime + used.ru_stime) * 1000))


def check_ppm(width, height, rgb):
    data = sys.stdin.buffer
    header = b"P6\n%d %d\n65535\n" % (width, height)
    if data.read(len(header)) != header:
        raise SystemExit("check-ppm: another header")
    pixel = struct.pack(">HHH", *rgb)
    block = pixel * (1 << 16)
    left = width * height * len(pixel)
    while left > 0:
        want = min(left, len(block))
        if data.read(want) != block[:want]:
            raise SystemExit("check-ppm: another pixel %d bytes before "
                             "the end" % left)
        left -= want
    if data.read(1):
        raise SystemExit("check-ppm: bytes after the raster")
    print("ok")


def main(argv):
    kind, out, args = argv[1], argv[2], argv[3:]
    if kind == "text-bomb":
        text_bomb(out, args[0], int(args[1]), int(args[2]))
    elif kind == "long-chunk":
        long_chunk(out, *([args[0]] + [int(a) for a in args[1:]]))
    elif kind == "big-text":
        big_text(out, args[0], int(args[1]))
    elif kind == "idat-bomb":
        idat_bomb(out, int(args[0]))
    elif kind == "after-image":
        after_image(out, args[0])
    elif kind == "rgba16":
        rgba16(out, int(args[0]), int(args[1]))
    elif kind == "run":
        run(argv[2:])
    elif kind == "check-ppm":
        check_ppm(int(argv[2]), int(argv[3]), [int(v) for v in argv[4:7]])
    else:
        raise SystemExit("png_hostile.py: unknown kind " + kind)


if __name__ == "__main__":
    main(sys.argv)
