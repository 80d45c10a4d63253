/*
 * image_convert.h - turning an image from one sample layout into another:
 * bilevel, gray or RGB.
 *
 * Writers take only the layouts their format holds (writer.h); these
 * functions make the others fit, and give compare its bilevel masks.
 * Every function allocates dst (free it with rayo_image_free), leaves src
 * untouched, and zeroes dst on failure.  The rules, exact integer
 * arithmetic each, are below.  Not a resampler, not a colour manager (no
 * gamma), not dithering.
 */
#ifndef RAYO_IMAGE_CONVERT_H
#define RAYO_IMAGE_CONVERT_H

#include "rayo/export.h"
#include "rayo/image.h"
#include "rayo/status.h"

/*
 * Rules, with M = src's maxval:
 *
 *   to bit:   BIT is copied.  Gray is black (1) where 2 v < M; RGB is
 *             black where its luminance is under half the maximum,
 *             2 (299 r + 587 g + 114 b) < 1000 M (ITU-R BT.601 weights,
 *             exact integer arithmetic, no rounding).
 *   to gray:  BIT becomes 8-bit gray, maxval 255 (black 0, white 255).
 *             Gray is copied.  RGB becomes gray of the same maxval and
 *             sample size, v = (299 r + 587 g + 114 b + 500) / 1000,
 *             rounded to nearest (halves up).
 *   to rgb:   BIT becomes 8-bit RGB, maxval 255 (black 0,0,0, white
 *             255,255,255).  Gray is repeated in all three channels,
 *             same maxval.  RGB is copied.
 */

#ifdef __cplusplus
extern "C" {
#endif

/* Bilevel mask: black (1) where the pixel is darker than half the
   maximum (see above).  BIT copies. */
RAYO_API rayo_status rayo_image_to_bit(const rayo_image *src, rayo_image *dst,
                                       rayo_error *err);

/* One channel: BIT -> maxval 255 (black 0, white 255); RGB -> luminance. */
RAYO_API rayo_status rayo_image_to_gray(const rayo_image *src, rayo_image *dst,
                                        rayo_error *err);

/* Three channels: BIT -> maxval 255; gray repeated. */
RAYO_API rayo_status rayo_image_to_rgb(const rayo_image *src, rayo_image *dst,
                                       rayo_error *err);

#ifdef __cplusplus
}
#endif

#endif
