/*
 * transform.c - undoing a candidate mistake on the image, one row at a
 * time, in the reference's frame.
 *
 * Each candidate of the diagnosis (a flip, inverted colours, a
 * transposition, a shift, a scale about the optical centre) is a map from
 * a reference pixel to the image pixel that should hold the same colour;
 * this file applies it.  Pixels whose source falls outside the image are
 * "unknown" for shifts and scales (the image never saw them) and white
 * for a plain change of frame (an image of another size, centred).
 * Not a resampler for display (no filtering); nearest pixel only.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../compare_impl.h"

/* 1 black, 0 white, -1 outside the image. */
static int image_bit(const cmp_mask *image, int64_t i, int64_t j)
{
    if (i < 0 || j < 0 || i >= image->width || j >= image->height)
        return -1;
    return rayo_bit_get(cmp_mask_row(image, (uint32_t)j), (uint32_t)i);
}

/* Eight pixels of row src from column q on, bit by bit at the edges. */
static unsigned byte_at(const unsigned char *src, uint32_t width, int64_t q,
                        unsigned *inside)
{
    unsigned v = 0, bit;
    if (q >= 0 && q + 8 <= (int64_t)width) {
        size_t k = (size_t)q >> 3;
        unsigned sh = (unsigned)(q & 7);
        *inside = 0xFFu;
        v = (unsigned)src[k] << sh;
        if (sh != 0)
            v |= (unsigned)src[k + 1] >> (8 - sh);
        return v & 0xFFu;
    }
    *inside = 0;
    for (bit = 0; bit < 8; bit++) {
        int64_t i = q + bit;
        if (i < 0 || i >= (int64_t)width)
            continue;
        *inside |= 0x80u >> bit;
        if (rayo_bit_get(src, (uint32_t)i))
            v |= 0x80u >> bit;
    }
    return v;
}

/* The bytes of a row from pixel q on (q >= 0, q + 8 <= width) while
 * their eight pixels lie inside the row, `most` at most: a copy shifted
 * by q's place in its byte.  Returns how many (1 or more). */
static size_t copy_inside(const unsigned char *src, uint32_t width,
                          int64_t q, size_t most, unsigned char *out,
                          unsigned char *known)
{
    size_t count = (size_t)(((int64_t)width - q) / 8), b = (size_t)q >> 3;
    size_t i;
    unsigned sh = (unsigned)(q & 7);
    if (count > most)
        count = most;
    memset(known, 0xFF, count);
    if (sh == 0) {
        memcpy(out, src + b, count);
        return count;
    }
    for (i = 0; i < count; i++) /* pixel q + 8 i + 7 is in byte b + i + 1 */
        out[i] = (unsigned char)((unsigned)src[b + i] << sh |
                                 (unsigned)src[b + i + 1] >> (8 - sh));
    return count;
}

/* The image moved by (ox, oy): out(i) = image(i + ox, y + oy); pixels
 * from outside the image are white, and unknown unless outside_known. */
static int offset_row(const cmp_mask *image, uint32_t width, uint32_t y,
                      int64_t ox, int64_t oy, int outside_known,
                      unsigned char *out, unsigned char *known)
{
    size_t n = cmp_row_bytes(width), k;
    int64_t j = (int64_t)y + oy;
    unsigned all = 0xFFu, inside;
    const unsigned char *src;
    if (j < 0 || j >= (int64_t)image->height) {
        if (outside_known)
            return 1;
        return -1;
    }
    src = cmp_mask_row(image, (uint32_t)j);
    for (k = 0; k < n; k++) {
        int64_t q = ox + 8 * (int64_t)k;
        if (q >= 0 && q + 8 <= (int64_t)image->width && k + 1 < n) {
            k += copy_inside(src, image->width, q, n - 1 - k, out + k,
                             known + k) - 1;
            continue;
        }
        out[k] = (unsigned char)byte_at(src, image->width, q, &inside);
        known[k] = (unsigned char)inside;
        all &= inside | (k == n - 1 ? 0xFFu >> ((width & 7u) ? (width & 7u)
                                                               : 8u)
                                    : 0u);
    }
    cmp_clear_padding(out, width);
    cmp_clear_padding(known, width);
    return outside_known || all == 0xFFu;
}

static int same_frame_row(const cmp_mask *image, uint32_t width, uint32_t y,
                          int invert, unsigned char *out)
{
    size_t n = cmp_row_bytes(width), k;
    memcpy(out, cmp_mask_row(image, y), n);
    if (invert)
        for (k = 0; k < n; k++)
            out[k] = (unsigned char)~out[k];
    cmp_clear_padding(out, width);
    return 1;
}

static unsigned reverse_bits(unsigned v)
{
    v = ((v & 0xF0u) >> 4) | ((v & 0x0Fu) << 4);
    v = ((v & 0xCCu) >> 2) | ((v & 0x33u) << 2);
    return ((v & 0xAAu) >> 1) | ((v & 0x55u) << 1);
}

/* Row j of the image mirrored left to right, using scratch (a row). */
static void mirrored_row(const cmp_mask *image, uint32_t j,
                         unsigned char *scratch, unsigned char *out)
{
    const unsigned char *src = cmp_mask_row(image, j);
    size_t n = cmp_row_bytes(image->width), k;
    unsigned pad = (unsigned)(8 * n - image->width), inside;
    for (k = 0; k < n; k++)
        scratch[k] = (unsigned char)reverse_bits(src[n - 1 - k]);
    for (k = 0; k < n; k++)
        out[k] = (unsigned char)byte_at(scratch, (uint32_t)(8 * n),
                                        (int64_t)pad + 8 * (int64_t)k,
                                        &inside);
    cmp_clear_padding(out, image->width);
}

/* The 8x8 bit block held in x (byte r the row r, its high bit the
 * column 0) transposed: the three swaps of Hacker's Delight, 7-3. */
static uint64_t transpose8(uint64_t x)
{
    uint64_t t;
    t = (x ^ (x >> 7)) & 0x00AA00AA00AA00AAull;
    x = x ^ t ^ (t << 7);
    t = (x ^ (x >> 14)) & 0x0000CCCC0000CCCCull;
    x = x ^ t ^ (t << 14);
    t = (x ^ (x >> 28)) & 0x00000000F0F0F0F0ull;
    return x ^ t ^ (t << 28);
}

rayo_status cmp_mask_transpose(const cmp_mask *m, cmp_mask *out,
                               unsigned char **bits, rayo_error *err)
{
    size_t in_bytes = cmp_row_bytes(m->width);
    size_t stride = cmp_row_bytes(m->height), k, k0, r;
    uint32_t y;
    out->width = m->height;
    out->height = m->width;
    out->stride = stride;
    *bits = calloc(stride * m->width, 1);
    out->bits = *bits;
    if (*bits == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM,
                              "compare: out of memory for a transposed "
                              "%ux%u image",
                              m->width, m->height);
    /* 64 bytes of columns at a time, so the 512 rows written stay in
       the cache while the image's rows are read down. */
    for (k0 = 0; k0 < in_bytes; k0 += 64)
        for (y = 0; y < m->height; y += 8)
            for (k = k0; k < k0 + 64 && k < in_bytes; k++) {
                uint64_t x = 0;
                for (r = 0; r < 8; r++) /* rows past the end are white */
                    x = x << 8 |
                        (y + r < m->height
                             ? cmp_mask_row(m, (uint32_t)(y + r))[k]
                             : 0u);
                x = transpose8(x);
                /* byte 7 - c of x is column 8k + c, rows y..y+7 */
                for (r = 0; r < 8 && 8 * k + r < m->width; r++)
                    (*bits)[(8 * k + r) * stride + y / 8] =
                        (unsigned char)(x >> (8 * (7 - r)));
            }
    for (y = 0; y < out->height; y++)
        cmp_clear_padding(*bits + (size_t)y * stride, out->width);
    return RAYO_OK;
}

/* Flips and transposition: a permutation of the pixels of equal frames. */
static int permuted_row(const cmp_transform *t, const cmp_mask *image,
                        uint32_t width, uint32_t y, unsigned char *out,
                        unsigned char *scratch)
{
    uint32_t i;
    if (t->kind == CMP_FLIP_V)
        return same_frame_row(image, width, image->height - 1 - y, 0, out);
    if (t->kind == CMP_FLIP_H || t->kind == CMP_FLIP_BOTH) {
        mirrored_row(image, t->kind == CMP_FLIP_H ? y : image->height - 1 - y,
                     scratch, out);
        return 1;
    }
    if (t->transposed != NULL)
        return same_frame_row(t->transposed, width, y, 0, out);
    for (i = 0; i < width; i++) /* transposed: column y, row i */
        if (image_bit(image, y, i) > 0)
            rayo_bit_set(out, i, 1);
    return 1;
}

/* Larger than any |s x| a frame can produce (scales stay far below 2^20). */
#define FLOOR_BIAS 68719476736.0 /* 2^36 */

static int64_t scaled_column(double scale, uint32_t i, uint32_t width,
                             uint32_t image_width)
{
    /* floor(v) as a truncation of a positive number: no libm call in the
       innermost loop */
    double xr = (double)i - (double)(width / 2);
    return (int64_t)(scale * xr + 0.5 + FLOOR_BIAS) - (int64_t)FLOOR_BIAS +
           image_width / 2;
}

void cmp_transform_columns(const cmp_transform *t, uint32_t ref_width,
                           uint32_t image_width, int32_t *columns)
{
    uint32_t i;
    for (i = 0; i < ref_width; i++) {
        int64_t ii = scaled_column(t->scale, i, ref_width, image_width);
        columns[i] = ii >= 0 && ii < image_width ? (int32_t)ii : -1;
    }
}

/* Whether the eight columns from c map to eight consecutive image
 * columns, all inside: then their byte is a plain copy. */
static int consecutive(const int32_t *c)
{
    int32_t b;
    if (c[0] < 0)
        return 0;
    for (b = 1; b < 8; b++)
        if (c[b] != c[0] + b)
            return 0;
    return 1;
}

/* A scaled row through the column map, eight pixels a byte: a whole
 * byte at once where the map is a plain shift (most of a row for scales
 * near 1), pixel by pixel elsewhere. */
static void mapped_row(const int32_t *columns, const unsigned char *src,
                       uint32_t width, unsigned char *out,
                       unsigned char *known)
{
    size_t n = cmp_row_bytes(width), k;
    for (k = 0; k < n; k++) {
        unsigned v = 0, kn = 0, bit;
        if (k * 8 + 8 <= width && consecutive(columns + k * 8)) {
            size_t q = (size_t)columns[k * 8] >> 3;
            unsigned sh = (unsigned)columns[k * 8] & 7u;
            v = (unsigned)src[q] << sh;
            if (sh != 0) /* column + 7 is inside, in byte q + 1 */
                v |= (unsigned)src[q + 1] >> (8 - sh);
            out[k] = (unsigned char)v;
            known[k] = 0xFFu;
            continue;
        }
        for (bit = 0; bit < 8 && k * 8 + bit < width; bit++) {
            int32_t ii = columns[k * 8 + bit];
            if (ii < 0)
                continue;
            kn |= 0x80u >> bit;
            if (rayo_bit_get(src, (uint32_t)ii))
                v |= 0x80u >> bit;
        }
        out[k] = (unsigned char)v;
        known[k] = (unsigned char)kn;
    }
}

/* out(x, y) = image(round(s x), round(s y)) in centred coordinates. */
static int scaled_row(const cmp_transform *t, const cmp_mask *image,
                      uint32_t width, uint32_t height, uint32_t y,
                      unsigned char *out, unsigned char *known)
{
    uint32_t i, step = t->step ? t->step : 1;
    double yr = (double)y - (double)(height / 2);
    int64_t j = (int64_t)floor(t->scale * yr + 0.5) + image->height / 2;
    if (y % step != 0 || j < 0 || j >= image->height)
        return -1;
    if (t->columns != NULL && step == 1) {
        mapped_row(t->columns, cmp_mask_row(image, (uint32_t)j), width, out,
                   known);
        return 0;
    }
    memset(known, 0, cmp_row_bytes(width));
    for (i = 0; i < width; i += step) {
        int64_t ii = scaled_column(t->scale, i, width, image->width);
        int b = image_bit(image, ii, j);
        if (b < 0)
            continue;
        rayo_bit_set(known, i, 1);
        if (b)
            rayo_bit_set(out, i, 1);
    }
    return 0;
}

int cmp_transform_row(const cmp_transform *t, const cmp_mask *image,
                      uint32_t ref_width, uint32_t ref_height, uint32_t y,
                      unsigned char *out, unsigned char *known)
{
    int same = image->width == ref_width && image->height == ref_height;
    memset(out, 0, cmp_row_bytes(ref_width));
    switch (t->kind) {
    case CMP_IDENTITY:
        if (same)
            return same_frame_row(image, ref_width, y, 0, out);
        return offset_row(image, ref_width, y,
                          (int64_t)(image->width / 2) - ref_width / 2,
                          (int64_t)(image->height / 2) - ref_height / 2, 1,
                          out, known);
    case CMP_INVERT:
        return same_frame_row(image, ref_width, y, 1, out);
    case CMP_SHIFT:
        return offset_row(image, ref_width, y, t->dx, t->dy, 0, out, known);
    case CMP_SCALE:
        return scaled_row(t, image, ref_width, ref_height, y, out, known);
    default:
        return permuted_row(t, image, ref_width, y, out, known);
    }
}
