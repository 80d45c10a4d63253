/*
 * image.h - one image type for bilevel, gray and colour pixels.
 *
 * An image is a header (rayo_image_info) and rows of samples, in one of
 * three layouts that cover every format rayo reads or writes (below).
 * The renderer produces rows in these layouts and the writers consume
 * them, so a frame never has to be whole in memory; rayo_image holds a
 * whole frame for the readers, compare, convert and view.
 */
#ifndef RAYO_IMAGE_H
#define RAYO_IMAGE_H

#include <stddef.h>
#include <stdint.h>

#include "rayo/export.h"
#include "rayo/status.h"

/*
 * The sample layouts:
 *
 *   RAYO_SAMPLE_BIT  one bit per pixel, 8 pixels a byte, most significant
 *                    bit first, 1 = black (PBM's meaning and raw layout);
 *                    channels = 1, maxval = 1.
 *   RAYO_SAMPLE_U8   one byte per sample, channels samples per pixel
 *                    (1 = gray, 3 = RGB), 0 = black, maxval = white.
 *   RAYO_SAMPLE_U16  like U8 with uint16_t samples in native byte order.
 */

#ifdef __cplusplus
extern "C" {
#endif

typedef enum rayo_sample_type {
    RAYO_SAMPLE_BIT,
    RAYO_SAMPLE_U8,
    RAYO_SAMPLE_U16
} rayo_sample_type;

typedef struct rayo_image_info {
    uint32_t width, height;
    unsigned channels;      /* 1 (bilevel or gray) or 3 (RGB) */
    unsigned maxval;        /* 1 for BIT, 1..255 for U8, 1..65535 for U16 */
    rayo_sample_type sample;
} rayo_image_info;

typedef struct rayo_image {
    rayo_image_info info;
    size_t stride;          /* bytes from one row to the next */
    unsigned char *pixels;  /* height * stride bytes, owned */
} rayo_image;

/* The info of a bilevel, 8-bit gray or 8-bit RGB image of this size. */
RAYO_API rayo_image_info rayo_image_info_bit(uint32_t width, uint32_t height);
RAYO_API rayo_image_info rayo_image_info_gray8(uint32_t width,
                                               uint32_t height);
RAYO_API rayo_image_info rayo_image_info_rgb8(uint32_t width, uint32_t height);

/*
 * Checks that info describes an image rayo accepts: sizes within
 * RAYO_MAX_DIMENSION and RAYO_MAX_PIXELS, channels and maxval consistent
 * with the sample type.  RAYO_ERR_LIMIT for sizes, RAYO_ERR_INVALID else.
 */
RAYO_API rayo_status rayo_image_info_check(const rayo_image_info *info,
                                           rayo_error *err);

/* Bytes in one row of this layout (no padding). */
RAYO_API size_t rayo_image_info_row_bytes(const rayo_image_info *info);

/* Allocates a zeroed image (white for BIT, black otherwise). */
RAYO_API rayo_status rayo_image_create(rayo_image *image,
                                       const rayo_image_info *info,
                                       rayo_error *err);

/* Frees the pixels and zeroes the struct; safe on a zeroed image. */
RAYO_API void rayo_image_free(rayo_image *image);

static inline unsigned char *rayo_image_row(const rayo_image *image,
                                            uint32_t row)
{
    return image->pixels + (size_t)row * image->stride;
}

/* Bit x of a BIT row: 1 = black. */
static inline int rayo_bit_get(const unsigned char *row, uint32_t x)
{
    return (row[x >> 3] >> (7 - (x & 7))) & 1;
}

static inline void rayo_bit_set(unsigned char *row, uint32_t x, int black)
{
    unsigned char mask = (unsigned char)(0x80u >> (x & 7));
    if (black)
        row[x >> 3] = (unsigned char)(row[x >> 3] | mask);
    else
        row[x >> 3] = (unsigned char)(row[x >> 3] & ~mask);
}

#ifdef __cplusplus
}
#endif

#endif
