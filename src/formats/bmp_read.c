/*
 * bmp_read.c - reading Windows BMP: the course's layout (24 bits, rows
 * bottom up and padded to 4 bytes) and what students and other programs
 * write besides: rows top down (a negative height), 32 and 16 bits a
 * pixel (the usual or the header's own channel masks), palettes of 1, 4
 * and 8 bits, and the header versions from the old 12-byte one to V5.
 * What departs from the course's layout is said in the read report
 * (bits, rows top down, rows without their padding), so compare can name
 * it.  A file whose rows lack the padding is read as it was written when
 * its size is exactly that, instead of refused as truncated.
 *
 * A palette of grays gives a gray image, a palette of exactly black and
 * white a bilevel one; anything else is RGB.  Alpha is ignored, as the
 * BI_RGB formats ask.  Compressed rasters (RLE, JPEG, PNG inside a BMP)
 * are refused with their name.  Not the writer (bmp_write.c).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rayo/limits.h"

#include "bmp_layout.h"
#include "reader_impl.h"

enum { BI_RGB = 0, BI_RLE8 = 1, BI_RLE4 = 2, BI_BITFIELDS = 3, BI_JPEG = 4,
       BI_PNG = 5, BI_ALPHABITFIELDS = 6 };

typedef struct channel_mask {
    uint32_t mask;
    unsigned shift;
    uint32_t max; /* mask >> shift */
} channel_mask;

typedef struct bmp_header {
    uint32_t offset;      /* of the raster, from the file's start */
    uint32_t info_size;   /* 12, 40, 52, 56, 64, 108 or 124 */
    int64_t width, height;
    unsigned planes, bits;
    uint32_t compression;
    uint32_t colours;     /* palette entries */
    channel_mask masks[3]; /* red, green, blue */
    unsigned char palette[256][3]; /* R, G, B */
} bmp_header;

static rayo_status need(rayo_source *src, void *to, size_t size,
                        const char *what, rayo_error *err)
{
    size_t got;
    rayo_source_read(src, to, size, &got);
    return got == size ? RAYO_OK : rayo_source_end_error(src, what, err);
}

static rayo_status bad(const rayo_source *src, uint64_t at, rayo_error *err,
                       const char *found, const char *expected)
{
    return rayo_error_set(err, RAYO_ERR_FORMAT,
                          "%s: byte %llu: found %s; expected %s", src->name,
                          (unsigned long long)at, found, expected);
}

/* The shift and width of a channel mask; 0 when it is not one run of
   ones. */
static int take_mask(uint32_t mask, channel_mask *channel)
{
    unsigned shift = 0;
    if (mask == 0)
        return 0;
    while (!(mask & 1u)) {
        mask >>= 1;
        shift++;
    }
    if ((mask & (mask + 1u)) != 0)
        return 0;
    channel->mask = mask << shift;
    channel->shift = shift;
    channel->max = mask;
    return 1;
}

static rayo_status read_masks(rayo_source *src, bmp_header *h,
                              const unsigned char *given, rayo_error *err)
{
    static const uint32_t rgb16[3] = {0x7c00u, 0x03e0u, 0x001fu};
    static const uint32_t rgb32[3] = {0xff0000u, 0x00ff00u, 0x0000ffu};
    uint64_t at = rayo_source_offset(src);
    int i;
    for (i = 0; i < 3; i++) {
        uint32_t mask = given != NULL ? rayo_bmp_get32(given + 4 * i)
                        : h->bits == 16 ? rgb16[i]
                                        : rgb32[i];
        char found[48];
        if (!take_mask(mask, &h->masks[i])) {
            snprintf(found, sizeof found, "the channel mask 0x%08lx",
                     (unsigned long)mask);
            return bad(src, at, err, found,
                       "a mask of one run of set bits");
        }
    }
    return RAYO_OK;
}

/* The headers, the palette and the masks, up to the raster's offset. */
static rayo_status read_header(rayo_source *src, bmp_header *h,
                               rayo_error *err)
{
    unsigned char b[124];
    const unsigned char *given_masks = NULL;
    uint64_t info_at;
    char found[64];
    rayo_status status = need(src, b, 16, "the rest of the BMP headers", err);
    if (status != RAYO_OK)
        return status;
    memset(h, 0, sizeof *h);
    h->offset = rayo_bmp_get32(b + 8);
    h->info_size = rayo_bmp_get32(b + 12);
    info_at = RAYO_BMP_FILE_HEADER;
    switch (h->info_size) {
    case 12: case 40: case 52: case 56: case 64: case 108: case 124:
        break;
    default:
        snprintf(found, sizeof found, "an information header of %lu bytes",
                 (unsigned long)h->info_size);
        return bad(src, info_at, err, found,
                   "12, 40, 52, 56, 64, 108 or 124 (BITMAPINFOHEADER is 40)");
    }
    status = need(src, b + 4, h->info_size - 4, "the rest of the BMP "
                                                "information header",
                  err);
    if (status != RAYO_OK)
        return status;
    if (h->info_size == 12) {
        h->width = rayo_bmp_get16(b + 4);
        h->height = rayo_bmp_get16(b + 6);
        h->planes = rayo_bmp_get16(b + 8);
        h->bits = rayo_bmp_get16(b + 10);
    } else {
        h->width = (int32_t)rayo_bmp_get32(b + 4);
        h->height = (int32_t)rayo_bmp_get32(b + 8);
        h->planes = rayo_bmp_get16(b + 12);
        h->bits = rayo_bmp_get16(b + 14);
        h->compression = rayo_bmp_get32(b + 16);
        h->colours = rayo_bmp_get32(b + 32);
        if (h->info_size >= 52)
            given_masks = b + 40;
    }
    if (h->planes != 1) {
        snprintf(found, sizeof found, "%u planes", h->planes);
        return bad(src, info_at + (h->info_size == 12 ? 8 : 12), err, found,
                   "1");
    }
    if (h->bits != 1 && h->bits != 4 && h->bits != 8 && h->bits != 16 &&
        h->bits != 24 && h->bits != 32) {
        snprintf(found, sizeof found, "%u bits a pixel", h->bits);
        return bad(src, info_at + (h->info_size == 12 ? 10 : 14), err,
                   found, "1, 4, 8, 16, 24 or 32");
    }
    switch (h->compression) {
    case BI_RGB:
        break;
    case BI_BITFIELDS:
    case BI_ALPHABITFIELDS:
        if (h->bits == 16 || h->bits == 32)
            break;
        /* fall through */
    default:
        snprintf(found, sizeof found, "compression %lu (%s) with %u bits",
                 (unsigned long)h->compression,
                 h->compression == BI_RLE8   ? "RLE8"
                 : h->compression == BI_RLE4 ? "RLE4"
                 : h->compression == BI_JPEG ? "JPEG"
                 : h->compression == BI_PNG  ? "PNG"
                 : h->compression == BI_BITFIELDS ||
                         h->compression == BI_ALPHABITFIELDS
                     ? "bit fields"
                     : "unknown",
                 h->bits);
        return bad(src, info_at + 16, err, found,
                   "0 (none), or bit fields with 16 or 32 bits");
    }
    if (h->compression != BI_RGB && given_masks == NULL) {
        /* After a 40-byte header the masks follow it. */
        size_t n = h->compression == BI_ALPHABITFIELDS ? 16 : 12;
        status = need(src, b + 40, n, "the BMP channel masks", err);
        if (status != RAYO_OK)
            return status;
        given_masks = b + 40;
    }
    if (h->bits >= 16) {
        status = read_masks(src, h, h->compression != BI_RGB ? given_masks
                                                             : NULL,
                            err);
        if (status != RAYO_OK)
            return status;
    } else {
        uint32_t most = 1u << h->bits, i;
        size_t entry = h->info_size == 12 ? 3 : 4;
        if (h->colours == 0)
            h->colours = most;
        if (h->colours > most) {
            snprintf(found, sizeof found, "%lu palette entries",
                     (unsigned long)h->colours);
            snprintf((char *)b, sizeof b, "at most %lu for %u bits",
                     (unsigned long)most, h->bits);
            return bad(src, info_at + 32, err, found, (const char *)b);
        }
        for (i = 0; i < h->colours; i++) {
            unsigned char e[4];
            status = need(src, e, entry, "the BMP palette", err);
            if (status != RAYO_OK)
                return status;
            h->palette[i][0] = e[2];
            h->palette[i][1] = e[1];
            h->palette[i][2] = e[0];
        }
    }
    return RAYO_OK;
}

/* Moves the cursor to the raster's offset. */
static rayo_status seek_raster(rayo_source *src, const bmp_header *h,
                               rayo_error *err)
{
    uint64_t at = rayo_source_offset(src);
    unsigned char skip[256];
    if (h->offset < at) {
        char found[64], expected[64];
        snprintf(found, sizeof found, "a pixel offset of %lu",
                 (unsigned long)h->offset);
        snprintf(expected, sizeof expected,
                 "at least %llu (the end of the headers)",
                 (unsigned long long)at);
        return bad(src, 10, err, found, expected);
    }
    while (at < h->offset) {
        size_t n = h->offset - at < sizeof skip ? (size_t)(h->offset - at)
                                                : sizeof skip;
        rayo_status status = need(src, skip, n, "the BMP pixels' offset",
                                  err);
        if (status != RAYO_OK)
            return status;
        at += n;
    }
    return RAYO_OK;
}

/* What the image becomes: 0 RGB, 1 gray, 2 bilevel (white is index
   *white). */
static int palette_kind(const bmp_header *h, unsigned *white)
{
    uint32_t i;
    if (h->bits > 8)
        return 0;
    for (i = 0; i < h->colours; i++)
        if (h->palette[i][0] != h->palette[i][1] ||
            h->palette[i][1] != h->palette[i][2])
            return 0;
    if (h->bits == 1 && h->colours == 2 &&
        h->palette[0][0] + h->palette[1][0] == 255 &&
        (h->palette[0][0] == 0 || h->palette[0][0] == 255)) {
        *white = h->palette[0][0] == 255 ? 0 : 1;
        return 2;
    }
    return 1;
}

static unsigned scaled(uint32_t pixel, const channel_mask *c)
{
    uint32_t v = (pixel & c->mask) >> c->shift;
    return c->max == 255 ? v : (v * 255u + c->max / 2u) / c->max;
}

/* One stored row into image row y; RAYO_ERR_FORMAT for an index past
   the palette. */
static rayo_status convert_row(const rayo_source *src, const bmp_header *h,
                               int kind, unsigned white,
                               const unsigned char *from, rayo_image *image,
                               uint32_t y, uint64_t row_at, rayo_error *err)
{
    unsigned char *to = rayo_image_row(image, y);
    uint32_t x, width = image->info.width;
    for (x = 0; x < width; x++) {
        uint32_t index, pixel;
        unsigned r, g, b;
        if (h->bits <= 8) {
            size_t bit = (size_t)x * h->bits;
            index = (uint32_t)(from[bit / 8] >> (8 - h->bits - bit % 8)) &
                    ((1u << h->bits) - 1u);
            if (index >= h->colours) {
                char found[48], expected[48];
                snprintf(found, sizeof found, "palette index %lu",
                         (unsigned long)index);
                snprintf(expected, sizeof expected,
                         "an index below the palette's %lu entries",
                         (unsigned long)h->colours);
                return bad(src, row_at + bit / 8, err, found, expected);
            }
            if (kind == 2) {
                if (index != white)
                    to[x / 8] |= (unsigned char)(0x80u >> (x % 8));
                continue;
            }
            r = h->palette[index][0];
            g = h->palette[index][1];
            b = h->palette[index][2];
        } else if (h->bits == 24) {
            b = from[(size_t)x * 3];
            g = from[(size_t)x * 3 + 1];
            r = from[(size_t)x * 3 + 2];
        } else {
            pixel = h->bits == 16 ? rayo_bmp_get16(from + (size_t)x * 2)
                                  : rayo_bmp_get32(from + (size_t)x * 4);
            r = scaled(pixel, &h->masks[0]);
            g = scaled(pixel, &h->masks[1]);
            b = scaled(pixel, &h->masks[2]);
        }
        if (kind == 1) {
            to[x] = (unsigned char)r;
        } else {
            to[(size_t)x * 3] = (unsigned char)r;
            to[(size_t)x * 3 + 1] = (unsigned char)g;
            to[(size_t)x * 3 + 2] = (unsigned char)b;
        }
    }
    return RAYO_OK;
}

rayo_status rayo_bmp_read(rayo_source *src, rayo_image *image,
                          rayo_read_report *report, rayo_error *err)
{
    bmp_header *h = malloc(sizeof *h);
    rayo_image_info info;
    uint64_t rows, padded, unpadded, remaining, at;
    size_t stride;
    unsigned white = 0;
    unsigned char *row = NULL;
    int kind;
    uint32_t k;
    rayo_status status;
    if (h == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
    status = read_header(src, h, err);
    if (status == RAYO_OK)
        status = seek_raster(src, h, err);
    if (status != RAYO_OK)
        goto done;
    if (h->width <= 0 || h->height == 0 || h->height == INT32_MIN) {
        char found[64];
        snprintf(found, sizeof found, "a size of %lldx%lld",
                 (long long)h->width, (long long)h->height);
        status = bad(src, RAYO_BMP_FILE_HEADER + 4, err, found,
                     "a width above 0 and a height other than 0");
        goto done;
    }
    rows = (uint64_t)(h->height < 0 ? -h->height : h->height);
    kind = palette_kind(h, &white);
    info = kind == 2   ? rayo_image_info_bit((uint32_t)h->width,
                                             (uint32_t)rows)
           : kind == 1 ? rayo_image_info_gray8((uint32_t)h->width,
                                               (uint32_t)rows)
                       : rayo_image_info_rgb8((uint32_t)h->width,
                                              (uint32_t)rows);
    if (h->width > RAYO_MAX_DIMENSION || rows > RAYO_MAX_DIMENSION ||
        rayo_image_info_check(&info, NULL) != RAYO_OK) {
        status = rayo_error_set(err, RAYO_ERR_LIMIT,
                                "%s: byte 18: found a %lldx%llu image in the "
                                "BMP header; expected at most %u pixels each "
                                "way and %lu (2^30) in all",
                                src->name, (long long)h->width,
                                (unsigned long long)rows, RAYO_MAX_DIMENSION,
                                RAYO_MAX_PIXELS);
        goto done;
    }
    stride = rayo_bmp_stride(info.width, h->bits);
    padded = (uint64_t)stride * rows;
    unpadded = ((uint64_t)info.width * h->bits + 7u) / 8u;
    report->bmp_bits = h->bits;
    report->bmp_top_down = h->height < 0;
    if (rayo_source_remaining(src, &remaining) && remaining < padded) {
        if (unpadded != stride && remaining >= unpadded * rows &&
            h->bits >= 8) {
            /* Written without the padding: read the rows as they are. */
            report->bmp_unpadded = 1;
            stride = (size_t)unpadded;
        } else {
            char found[64], expected[64];
            snprintf(found, sizeof found, "%llu bytes of pixels",
                     (unsigned long long)remaining);
            snprintf(expected, sizeof expected,
                     "%llu (%llu rows of %llu bytes)",
                     (unsigned long long)padded, (unsigned long long)rows,
                     (unsigned long long)stride);
            status = rayo_error_set(err, RAYO_ERR_FORMAT,
                                    "%s: byte %llu: found %s; expected %s",
                                    src->name,
                                    (unsigned long long)rayo_source_offset(
                                        src),
                                    found, expected);
            goto done;
        }
    }
    row = malloc(stride > 0 ? stride : 1);
    if (row == NULL) {
        status = rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
        goto done;
    }
    status = rayo_image_create(image, &info, err);
    for (k = 0; status == RAYO_OK && k < info.height; k++) {
        at = rayo_source_offset(src);
        status = need(src, row, stride, "the rest of the BMP's rows", err);
        if (status == RAYO_OK)
            status = convert_row(src, h, kind, white, row, image,
                                 h->height < 0 ? k : info.height - 1 - k,
                                 at, err);
    }
done:
    free(row);
    free(h);
    return status;
}
