/*
 * bitmap.h - bilevel images for the unit tests that build them pixel by
 * pixel (t_compare, t_compare_band, t_compare_bounds, t_preview): make
 * one all white, read and set a pixel, compare two at a tolerance.
 * Failing to allocate, or a comparison that fails, aborts the test.
 */
#ifndef RAYO_TEST_BITMAP_H
#define RAYO_TEST_BITMAP_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rayo.h"

static inline rayo_image bitmap_make(uint32_t w, uint32_t h)
{
    rayo_image image;
    rayo_image_info info = rayo_image_info_bit(w, h);
    memset(&image, 0, sizeof image);
    if (rayo_image_create(&image, &info, NULL) != RAYO_OK)
        abort();
    return image;
}

static inline int bitmap_get(const rayo_image *m, uint32_t x, uint32_t y)
{
    return rayo_bit_get(rayo_image_row(m, y), x);
}

static inline void bitmap_put(rayo_image *m, uint32_t x, uint32_t y,
                              int black)
{
    rayo_bit_set(rayo_image_row(m, y), x, black);
}

/* rayo_compare_images with the default options but the tolerance. */
static inline rayo_compare_report bitmap_compare(const rayo_image *a,
                                                 const rayo_image *b,
                                                 double tolerance)
{
    rayo_compare_options options;
    rayo_compare_report report;
    rayo_error err;
    rayo_compare_options_init(&options);
    options.tolerance = tolerance;
    if (rayo_compare_images(a, b, &options, &report, &err) != RAYO_OK) {
        printf("# %s\n", err.message);
        abort();
    }
    return report;
}

#endif
