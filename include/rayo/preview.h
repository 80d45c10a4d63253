/*
 * preview.h - an image as text, so it can be looked at in a terminal.
 *
 * The image becomes a black/white mask (gray and colour: black below half
 * the maximum, as compare sees it) and is shrunk, never enlarged, to fit
 * a number of columns; each character cell then shows a few sub-pixels,
 * each black when at least half the image pixels it covers are black.
 * Black pixels are drawn as ink (the terminal's foreground colour), so on
 * a dark terminal the sphere shows light on dark.  Terminal cells are
 * about twice as tall as wide, and every style keeps the picture's
 * proportions under that assumption:
 *
 *   RAYO_PREVIEW_BLOCKS   1 x 2 sub-pixels a cell: upper half, lower half
 *                         and full blocks (U+2580, U+2584, U+2588);
 *   RAYO_PREVIEW_BRAILLE  2 x 4 sub-pixels a cell: Braille patterns
 *                         (U+2800-U+28FF), the finest detail;
 *   RAYO_PREVIEW_ASCII    1 x 1 a cell, for terminals without Unicode:
 *                         '#' mostly black, '+' partly black, ' ' white.
 *
 * The library returns the text; it never prints.  Not an image viewer
 * (no colour, no gray levels, no enlarging).
 */
#ifndef RAYO_PREVIEW_H
#define RAYO_PREVIEW_H

#include <stddef.h>

#include "rayo/image.h"
#include "rayo/status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum rayo_preview_style {
    RAYO_PREVIEW_BLOCKS,
    RAYO_PREVIEW_BRAILLE,
    RAYO_PREVIEW_ASCII
} rayo_preview_style;

typedef struct rayo_preview_options {
    unsigned columns;         /* at most this many cells a line (>= 1) */
    rayo_preview_style style;
} rayo_preview_options;

/* 80 columns, blocks. */
void rayo_preview_options_init(rayo_preview_options *options);

/*
 * Renders image as UTF-8 (ASCII for RAYO_PREVIEW_ASCII) lines, each of
 * the same number of cells and ending in '\n', into *text (allocated,
 * NUL-terminated, freed by the caller with free()); *length is its length
 * without the NUL.  *cells_wide and *lines (either may be NULL) receive
 * the size of the picture in cells.
 */
rayo_status rayo_preview_render(const rayo_image *image,
                                const rayo_preview_options *options,
                                char **text, size_t *length,
                                unsigned *cells_wide, unsigned *lines,
                                rayo_error *err);

#ifdef __cplusplus
}
#endif

#endif
