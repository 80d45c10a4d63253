/*
 * t_grade_bmp.c - the TP1 grader's check of a BMP against the course's
 * layout (src/grade/checks/bmp_check.c), on files built byte by byte
 * here: the course's own 3x2 (rows of 9 bytes padded to 12), and one
 * deviation each (top-down rows, unpadded rows, 32 bits, a wrong size,
 * a truncated file, a wrong file size in the header, not a BMP).
 *
 * The expected pixels are the bytes each case writes, in R G B order;
 * no program is run.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../../src/grade/grade_impl.h"
#include "../../src/grade/tp1.h"
#include "tap.h"

#define W 3
#define H 2

static void put32(unsigned char *p, unsigned long v)
{
    p[0] = (unsigned char)(v & 0xff);
    p[1] = (unsigned char)((v >> 8) & 0xff);
    p[2] = (unsigned char)((v >> 16) & 0xff);
    p[3] = (unsigned char)((v >> 24) & 0xff);
}

/* A 3x2 BMP: stride bytes a row, the rows bottom-up unless height < 0;
   picture row y, pixel x has R = 10 y + x, G = 100, B = 200 + x. */
static size_t make(unsigned char *b, long height, size_t stride, int bits)
{
    size_t size = 54 + stride * H, x, y;
    memset(b, 0, size);
    b[0] = 'B';
    b[1] = 'M';
    put32(b + 2, (unsigned long)size);
    put32(b + 10, 54);
    put32(b + 14, 40);
    put32(b + 18, W);
    put32(b + 22, (unsigned long)height);
    b[26] = 1;
    b[28] = (unsigned char)bits;
    for (y = 0; y < H; y++) {
        size_t stored = height < 0 ? y : H - 1 - y;
        unsigned char *row = b + 54 + stored * stride;
        for (x = 0; x < W; x++) {
            row[3 * x] = (unsigned char)(200 + x);
            row[3 * x + 1] = 100;
            row[3 * x + 2] = (unsigned char)(10 * y + x);
        }
    }
    return size;
}

/* Checks b and says whether the item failed and the first line. */
static int check(const unsigned char *b, size_t size, char *first,
                 size_t room, rayo_image *image)
{
    rayo_grade_item item;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    size_t i;
    int failed;
    memset(&item, 0, sizeof item);
    if (grade_bmp_check(b, size, W, H, "x.bmp", &item, image, &err) !=
        RAYO_OK)
        return -1;
    failed = item.result == RAYO_GRADE_FAIL;
    snprintf(first, room, "%s", item.line_count > 0 ? item.lines[0] : "");
    for (i = 0; i < item.line_count; i++)
        free(item.lines[i]);
    free(item.lines);
    return failed;
}

/* The decoded picture is the one make() wrote. */
static int right_pixels(const rayo_image *im)
{
    size_t x, y;
    if (im->pixels == NULL || im->info.width != W || im->info.height != H)
        return 0;
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            const unsigned char *p = im->pixels + y * im->stride + 3 * x;
            if (p[0] != 10 * y + x || p[1] != 100 || p[2] != 200 + x)
                return 0;
        }
    return 1;
}

/* One case: the BMP make() builds, cut short by cut bytes, its header's
   file size replaced by size (0: kept); whether it fails, the first
   reason line, and whether its pixels come back right. */
typedef struct bmp_case {
    const char *name;
    long height;
    size_t stride;
    int bits;
    size_t cut;
    unsigned long size;
    int fails;
    const char *first;
    int decoded;
} bmp_case;

static const bmp_case cases[] = {
    {"the course's layout", H, 12, 24, 0, 0, 0, "", 1},
    {"top-down rows", -H, 12, 24, 0, 0, 1,
     "x.bmp: its rows are stored top-down (height -2); the course's BMP "
     "has a positive height and its rows bottom-up",
     1},
    {"unpadded rows", H, 9, 24, 0, 0, 1,
     "x.bmp: its rows are not padded: each has 9 bytes; the course pads "
     "them with zeros to 12, a multiple of 4",
     1},
    {"32 bits", H, 12, 32, 0, 0, 1,
     "x.bmp: it has 32 bits per pixel; the course's BMP has 24 (B, G, R)",
     0},
    {"3x3 for 3x2", H + 1, 12, 24, 0, 0, 1,
     "x.bmp is 3x3; the program was asked for 3x2", 0},
    {"a byte short", H, 12, 24, 1, 0, 1,
     "x.bmp has 23 bytes of pixels; 2 rows of 12 bytes (3 x 3, padded to "
     "a multiple of 4) are 24",
     0},
    {"a wrong file size in the header", H, 12, 24, 0, 1000, 1,
     "x.bmp: its header says 1000 bytes; the file has 78", 1}};

int main(void)
{
    unsigned char b[54 + 16 * H];
    char first[300];
    rayo_image im;
    size_t i;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const bmp_case *c = &cases[i];
        size_t size = make(b, c->height, c->stride, c->bits) - c->cut;
        if (c->size != 0)
            put32(b + 2, c->size);
        is_int(check(b, size, first, sizeof first, &im), c->fails,
               "%s: %s", c->name, c->fails ? "fails" : "passes");
        is_string(first, c->first, "  %s: its first line", c->name);
        is_int(right_pixels(&im), c->decoded, "  %s: %s", c->name,
               c->decoded ? "its pixels read back right" : "not decoded");
        rayo_image_free(&im);
    }
    is_int(check((const unsigned char *)"P3\n3 2\n255\n", 11, first,
                 sizeof first, &im),
           1, "a PPM is not a BMP");
    is_string(first,
              "x.bmp is not a BMP: it does not begin with \"BM\" and the "
              "two headers (54 bytes)",
              "  said so");
    return tap_done();
}
