/*
 * preview.h - an image as text, so it can be looked at in a terminal.
 *
 * The image is shrunk, never enlarged, to fit a number of columns: it is
 * cut into a grid of sub-pixels, squares of s x s image pixels, and each
 * character cell shows a few of them, in one of four styles (below).
 * Terminal cells are about twice as tall as wide, and every style keeps
 * the picture's proportions under that assumption.  The library returns
 * the text; it never prints, and whether a terminal takes colour
 * (COLORTERM, NO_COLOR, isatty) is the caller's question.  Not an image
 * viewer (no enlarging, no dithering, no gamma: means are of the stored
 * values).
 */
#ifndef RAYO_PREVIEW_H
#define RAYO_PREVIEW_H

#include <stddef.h>
#include <stdint.h>

#include "rayo/export.h"
#include "rayo/image.h"
#include "rayo/status.h"

/*
 * The styles:
 *
 *   RAYO_PREVIEW_BLOCKS   1 x 2 sub-pixels a cell: upper half, lower half
 *                         and full blocks (U+2580, U+2584, U+2588);
 *   RAYO_PREVIEW_BRAILLE  2 x 4 sub-pixels a cell: Braille patterns
 *                         (U+2800-U+28FF), the finest detail;
 *   RAYO_PREVIEW_ASCII    1 x 1 a cell, for terminals without Unicode:
 *                         '#' mostly black, '+' partly black, ' ' white;
 *   RAYO_PREVIEW_COLOR_BLOCKS  1 x 2 sub-pixels a cell in colour: U+2580
 *                         with the upper sub-pixel's colour as foreground
 *                         and the lower's as background, in xterm's 256
 *                         colours or in 24-bit colour (rayo_preview_color).
 *
 * The first three draw a silhouette, a black/white mask (gray and colour:
 * black below half the maximum, as compare sees it) where a sub-pixel is
 * black when at least half the image pixels it covers are; black is drawn
 * as ink (the terminal's foreground colour), so on a dark terminal the
 * sphere shows light on dark.  Colour blocks show each sub-pixel as the
 * mean of the pixels it covers (a box filter; gray as gray, 16-bit and
 * any maxval scaled to 8 bits), in SGR escape sequences, each line ending
 * in ESC[0m.
 */

#ifdef __cplusplus
extern "C" {
#endif

typedef enum rayo_preview_style {
    RAYO_PREVIEW_BLOCKS,
    RAYO_PREVIEW_BRAILLE,
    RAYO_PREVIEW_ASCII,
    RAYO_PREVIEW_COLOR_BLOCKS
} rayo_preview_style;

/*
 * The escape sequences of RAYO_PREVIEW_COLOR_BLOCKS (the other styles
 * ignore it, and print none):
 *
 *   RAYO_PREVIEW_COLOR_NONE       none: the picture RAYO_PREVIEW_BLOCKS
 *                                 draws, byte for byte;
 *   RAYO_PREVIEW_COLOR_256        ESC[38;5;F;48;5;Bm before each cell, F
 *                                 and B the nearest (in RGB, squared
 *                                 distance) of xterm's 6x6x6 cube (16-231:
 *                                 levels 0, 95, 135, ..., 255) and 24
 *                                 grays (232-255: 8, 18, ..., 238), the
 *                                 cube on a tie;
 *   RAYO_PREVIEW_COLOR_TRUECOLOR  ESC[38;2;R;G;B;48;2;R;G;Bm, 24-bit.
 *
 * A last line with no lower sub-pixel (an odd number of them) gets the
 * terminal's default background there: ESC[38;...;49m.
 */
typedef enum rayo_preview_color {
    RAYO_PREVIEW_COLOR_NONE,
    RAYO_PREVIEW_COLOR_256,
    RAYO_PREVIEW_COLOR_TRUECOLOR
} rayo_preview_color;

typedef struct rayo_preview_options {
    unsigned columns;         /* at most this many cells a line (>= 1) */
    rayo_preview_style style;
    rayo_preview_color color; /* RAYO_PREVIEW_COLOR_BLOCKS's escapes */
} rayo_preview_options;

/* 80 columns, blocks, no colour. */
RAYO_API void rayo_preview_options_init(rayo_preview_options *options);

/*
 * Renders image as UTF-8 (ASCII for RAYO_PREVIEW_ASCII) lines, each of
 * the same number of cells and ending in '\n', into *text (allocated,
 * NUL-terminated, freed by the caller with free()); *length is its length
 * without the NUL.  *cells_wide and *lines (either may be NULL) receive
 * the size of the picture in cells.  RAYO_ERR_INVALID for 0 columns or a
 * style or colour outside the enums.
 */
RAYO_API rayo_status rayo_preview_render(const rayo_image *image,
                                         const rayo_preview_options *options,
                                         char **text, size_t *length,
                                         unsigned *cells_wide, unsigned *lines,
                                         rayo_error *err);

/*
 * The same picture from rows as they are made (rayo render's row sink),
 * without the whole image: a summary of each sub-pixel (its black pixels
 * and its channel sums, 8 x (1 + channels) bytes) is all that is kept.
 *
 * rayo_preview_create: a summary for images of this layout, drawn with
 * these options (copied).  rayo_preview_rows has rayo_row_sink's shape:
 * count rows from first_row, stride bytes apart, in info's layout; each
 * row once, in any order (RAYO_ERR_INVALID past the last row); rows never
 * given count as zero samples.  rayo_preview_text: what
 * rayo_preview_render gives for the image of those rows, with options
 * whose columns and style are those given to create (RAYO_ERR_INVALID
 * otherwise) and any colour: the colour can be chosen once the place the
 * picture goes is known.  rayo_preview_free: safe on NULL.
 */
typedef struct rayo_preview rayo_preview;

RAYO_API rayo_status rayo_preview_create(rayo_preview **preview,
                                         const rayo_image_info *info,
                                         const rayo_preview_options *options,
                                         rayo_error *err);
RAYO_API rayo_status rayo_preview_rows(void *preview,
                                       const unsigned char *rows,
                                       size_t stride, uint32_t first_row,
                                       uint32_t count, rayo_error *err);
RAYO_API rayo_status rayo_preview_text(const rayo_preview *preview,
                                       const rayo_preview_options *options,
                                       char **text, size_t *length,
                                       unsigned *cells_wide, unsigned *lines,
                                       rayo_error *err);
RAYO_API void rayo_preview_free(rayo_preview *preview);

#ifdef __cplusplus
}
#endif

#endif
