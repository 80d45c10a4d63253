/*
 * bmp_check.c - a program's BMP file against the course's layout, as the
 * TP1 statement fixes it: "BM", the file size 54 + rows x stride, the
 * pixel offset 54, a 40-byte BITMAPINFOHEADER with the width and a
 * positive height (rows bottom-up), 1 plane, 24 bits, no compression,
 * then B G R bytes, each row padded with zeros to a multiple of 4.
 *
 * Each deviation is named (top-down rows, unpadded rows, another depth,
 * a wrong size) and, where the pixels can still be read, they are
 * decoded so that the caller can compare them with the PPM.  A file
 * whose rows are upside down or in R G B order under a correct header
 * can only be told by that comparison (tp1_runs.c).  Not a BMP reader
 * for rayo's commands (src/formats/bmp_read.c is).
 */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "../grade_impl.h"
#include "../tp1.h"

#define BMP_HEADERS 54u

static uint32_t get32(const unsigned char *p)
{
    return (uint32_t)p[0] | ((uint32_t)p[1] << 8) | ((uint32_t)p[2] << 16) |
           ((uint32_t)p[3] << 24);
}

static unsigned get16(const unsigned char *p)
{
    return (unsigned)(p[0] | (p[1] << 8));
}

/* The header's fields the course fixes to one value. */
static rayo_status check_fields(const unsigned char *b, const char *name,
                                rayo_grade_item *item, rayo_error *err)
{
    rayo_status status = RAYO_OK;
    if (get32(b + 10) != BMP_HEADERS)
        status = grade_fail(item, err,
                            "%s: the pixels start at byte %lu; the course's "
                            "BMP has them at 54, after the two headers",
                            name, (unsigned long)get32(b + 10));
    if (status == RAYO_OK && get32(b + 14) != 40)
        status = grade_fail(item, err,
                            "%s: its information header has %lu bytes; the "
                            "course's BMP has a 40-byte BITMAPINFOHEADER",
                            name, (unsigned long)get32(b + 14));
    if (status == RAYO_OK && get16(b + 26) != 1)
        status = grade_fail(item, err,
                            "%s: it says %u planes; the course's BMP says 1",
                            name, get16(b + 26));
    if (status == RAYO_OK && get32(b + 30) != 0)
        status = grade_fail(item, err,
                            "%s: it says compression %lu; the course's BMP "
                            "is not compressed (0)",
                            name, (unsigned long)get32(b + 30));
    return status;
}

/* Decodes rows of stride bytes, B G R, bottom-up unless top_down. */
static rayo_status decode(const unsigned char *pixels, uint32_t w,
                          uint32_t h, size_t stride, int top_down,
                          rayo_image *image, rayo_error *err)
{
    rayo_image_info info = rayo_image_info_rgb8(w, h);
    uint32_t x, y;
    rayo_status status = rayo_image_create(image, &info, err);
    if (status != RAYO_OK)
        return status;
    for (y = 0; y < h; y++) {
        const unsigned char *row =
            pixels + (size_t)(top_down ? y : h - 1 - y) * stride;
        unsigned char *to = image->pixels + (size_t)y * image->stride;
        for (x = 0; x < w; x++) {
            to[3 * x] = row[3 * x + 2];
            to[3 * x + 1] = row[3 * x + 1];
            to[3 * x + 2] = row[3 * x];
        }
    }
    return RAYO_OK;
}

rayo_status grade_bmp_check(const void *data, size_t size, uint32_t width,
                            uint32_t height, const char *name,
                            rayo_grade_item *item, rayo_image *image,
                            rayo_error *err)
{
    const unsigned char *b = data;
    int32_t w, h;
    uint32_t rows, bits;
    size_t stride, unpadded, have;
    int top_down;
    rayo_status status;
    memset(image, 0, sizeof *image);
    if (size < BMP_HEADERS || b[0] != 'B' || b[1] != 'M')
        return grade_fail(item, err,
                          "%s is not a BMP: it does not begin with \"BM\" "
                          "and the two headers (54 bytes)",
                          name);
    w = (int32_t)get32(b + 18);
    h = (int32_t)get32(b + 22);
    bits = get16(b + 28);
    status = check_fields(b, name, item, err);
    if (status != RAYO_OK || item->result == RAYO_GRADE_FAIL)
        return status;
    if (bits != 24)
        return grade_fail(item, err,
                          "%s: it has %lu bits per pixel; the course's BMP "
                          "has 24 (B, G, R)",
                          name, (unsigned long)bits);
    top_down = h < 0;
    rows = top_down ? (uint32_t)(-(int64_t)h) : (uint32_t)h;
    if (top_down)
        status = grade_fail(item, err,
                            "%s: its rows are stored top-down (height %ld); "
                            "the course's BMP has a positive height and "
                            "its rows bottom-up",
                            name, (long)h);
    if (status == RAYO_OK && (w < 0 || (uint32_t)w != width || rows != height))
        return grade_fail(item, err,
                          "%s is %ldx%lu; the program was asked for %lux%lu",
                          name, (long)w, (unsigned long)rows,
                          (unsigned long)width, (unsigned long)height);
    if (status != RAYO_OK)
        return status;
    stride = ((size_t)3 * width + 3) / 4 * 4;
    unpadded = (size_t)3 * width;
    have = size - BMP_HEADERS;
    if (have == unpadded * rows && unpadded != stride) {
        status = grade_fail(item, err,
                            "%s: its rows are not padded: each has %zu "
                            "bytes; the course pads them with zeros to %zu, "
                            "a multiple of 4",
                            name, unpadded, stride);
        stride = unpadded;
    } else if (have != stride * rows)
        return grade_fail(item, err,
                          "%s has %zu bytes of pixels; %lu rows of %zu bytes "
                          "(3 x %lu, padded to a multiple of 4) are %zu",
                          name, have, (unsigned long)rows, stride,
                          (unsigned long)width, stride * rows);
    if (status == RAYO_OK && get32(b + 2) != size)
        status = grade_fail(item, err,
                            "%s: its header says %lu bytes; the file has %zu",
                            name, (unsigned long)get32(b + 2), size);
    if (status == RAYO_OK && item->result != RAYO_GRADE_FAIL)
        item->result = RAYO_GRADE_PASS;
    if (status == RAYO_OK)
        status = decode(b + BMP_HEADERS, width, rows, stride, top_down, image,
                        err);
    return status;
}
