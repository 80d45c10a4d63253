/*
 * preview_impl.h - what the files of src/preview share: the grid of
 * sub-pixels a picture is drawn from (preview.c), where a sub-pixel's
 * numbers come from (the whole image, or the summary rayo_preview keeps,
 * preview_stream.c), and the colour cells (preview_color.c).
 *
 * A sub-pixel's numbers are the same whichever the source: its pixels,
 * those darker than half the maximum (rayo_image_to_bit's rule), and the
 * sum of each channel's samples.  Internal; not installed.
 */
#ifndef RAYO_PREVIEW_IMPL_H
#define RAYO_PREVIEW_IMPL_H

#include <stdint.h>

#include "rayo/preview.h"

typedef struct preview_bin {
    uint64_t all;    /* pixels covered */
    uint64_t black;  /* of those, the black ones */
    uint64_t sum[3]; /* samples, per channel (gray: sum[0] only; a
                        bilevel pixel is 0 black, 1 white) */
} preview_bin;

typedef struct preview_grid {
    rayo_image_info info;  /* of the image */
    double s;              /* image pixels per sub-pixel, each way (>= 1) */
    unsigned sub_w, sub_h; /* sub-pixels */
    unsigned cols, rows;   /* cells */
    const rayo_image *image; /* the pixels, or NULL and: */
    const uint64_t *summary; /* 1 + channels numbers a sub-pixel, row by
                                row: black, then the sums */
} preview_grid;

/* The grid for an image of this layout under these options; checks the
 * options (RAYO_ERR_INVALID). */
rayo_status preview_grid_init(preview_grid *g, const rayo_image_info *info,
                              const rayo_preview_options *options,
                              rayo_error *err);

/* The pixels [x0, x1) x [y0, y1) of sub-pixel (u, v). */
void preview_grid_bounds(const preview_grid *g, unsigned u, unsigned v,
                         uint32_t *x0, uint32_t *x1, uint32_t *y0,
                         uint32_t *y1);

/* Pixel x of a row: its samples (bilevel: 0 or 1) and whether it is
 * black. */
int preview_pixel(const rayo_image_info *info, const unsigned char *row,
                  uint32_t x, unsigned samples[3]);

/* Sub-pixel (u, v)'s numbers; 0 (and an empty bin) outside the grid. */
int preview_bin_get(const preview_grid *g, unsigned u, unsigned v,
                    preview_bin *bin);

/* The text of the grid in options' style and colour. */
rayo_status preview_grid_text(const preview_grid *g,
                              const rayo_preview_options *options,
                              char **text, size_t *length, rayo_error *err);

/* Colour cells (preview_color.c). */

/* A bin's mean colour in 8 bits a channel, rounded to nearest. */
void preview_bin_rgb8(const preview_bin *bin, const rayo_image_info *info,
                      unsigned rgb[3]);

/* The nearest of xterm's colours 16-255 to an 8-bit colour. */
unsigned preview_xterm_index(const unsigned rgb[3]);

/* At most this many bytes a colour cell, and at the end of a line. */
#define PREVIEW_COLOR_CELL_MAX 40
#define PREVIEW_COLOR_LINE_END "\x1b[0m"

/* One colour cell: escape sequence and U+2580 for upper over lower
 * (lower NULL: the default background); returns the bytes written. */
size_t preview_color_cell(rayo_preview_color color,
                          const rayo_image_info *info,
                          const preview_bin *upper, const preview_bin *lower,
                          char *out);

#endif
