/*
 * preview.c - shrinking a mask to character cells of block, Braille or
 * ASCII characters (preview.h says what each style draws).
 *
 * The picture is a grid of sub-pixels, sw = columns x (sub-pixels a cell
 * across) wide; each sub-pixel covers a square of s x s image pixels,
 * s = width / sw (>= 1: never enlarged), and is black when at least half
 * of the pixels inside it are.  Cells are taken to be twice as tall as
 * wide, so a cell holds 1 x 2 (blocks), 2 x 4 (Braille) or 1 x 2 (ASCII,
 * judged by coverage) sub-pixels.  Not a general resampler: no filtering
 * beyond the box average, no gray.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "rayo/image_convert.h"
#include "rayo/preview.h"

typedef struct grid {
    const rayo_image *mask;
    double s;               /* image pixels per sub-pixel, each way */
    unsigned sub_w, sub_h;  /* sub-pixels */
} grid;

void rayo_preview_options_init(rayo_preview_options *options)
{
    options->columns = 80;
    options->style = RAYO_PREVIEW_BLOCKS;
}

/* Black pixels and all pixels in the footprint of sub-pixel (u, v). */
static void footprint(const grid *g, unsigned u, unsigned v,
                      unsigned long *black, unsigned long *all)
{
    uint32_t x0 = (uint32_t)floor(u * g->s), x1 = (uint32_t)floor((u + 1) * g->s);
    uint32_t y0 = (uint32_t)floor(v * g->s), y1 = (uint32_t)floor((v + 1) * g->s);
    uint32_t x, y;
    const rayo_image_info *info = &g->mask->info;
    if (x1 > info->width)
        x1 = info->width;
    if (y1 > info->height)
        y1 = info->height;
    if (x1 <= x0)
        x1 = x0 + 1 <= info->width ? x0 + 1 : x0;
    if (y1 <= y0)
        y1 = y0 + 1 <= info->height ? y0 + 1 : y0;
    *black = *all = 0;
    for (y = y0; y < y1; y++) {
        const unsigned char *row = rayo_image_row(g->mask, y);
        for (x = x0; x < x1; x++)
            *black += (unsigned long)rayo_bit_get(row, x);
        *all += x1 - x0;
    }
}

static int sub_black(const grid *g, unsigned u, unsigned v)
{
    unsigned long black, all;
    if (u >= g->sub_w || v >= g->sub_h)
        return 0;
    footprint(g, u, v, &black, &all);
    return all != 0 && 2 * black >= all;
}

static size_t put_utf8(char *out, unsigned code)
{
    out[0] = (char)(0xE0 | (code >> 12));
    out[1] = (char)(0x80 | ((code >> 6) & 0x3F));
    out[2] = (char)(0x80 | (code & 0x3F));
    return 3;
}

static size_t put_cell(const grid *g, rayo_preview_style style, unsigned c,
                       unsigned r, char *out)
{
    static const unsigned dots[4][2] = {
        {0x01, 0x08}, {0x02, 0x10}, {0x04, 0x20}, {0x40, 0x80}};
    unsigned bits = 0, i, j;
    unsigned long black, all, b2, a2;
    if (style == RAYO_PREVIEW_ASCII) {
        footprint(g, c, 2 * r, &black, &all);
        if (2 * r + 1 < g->sub_h) {
            footprint(g, c, 2 * r + 1, &b2, &a2);
            black += b2;
            all += a2;
        }
        *out = 2 * black >= all && all ? '#' : black ? '+' : ' ';
        return 1;
    }
    if (style == RAYO_PREVIEW_BLOCKS) {
        int top = sub_black(g, c, 2 * r), bottom = sub_black(g, c, 2 * r + 1);
        if (!top && !bottom) {
            *out = ' ';
            return 1;
        }
        return put_utf8(out, top && bottom ? 0x2588 : top ? 0x2580 : 0x2584);
    }
    for (j = 0; j < 4; j++)
        for (i = 0; i < 2; i++)
            if (sub_black(g, 2 * c + i, 4 * r + j))
                bits |= dots[j][i];
    return put_utf8(out, 0x2800 + bits);
}

/* Cells across and sub-pixels per cell for a style. */
static void cell_shape(rayo_preview_style style, unsigned *across,
                       unsigned *down)
{
    *across = style == RAYO_PREVIEW_BRAILLE ? 2 : 1;
    *down = style == RAYO_PREVIEW_BRAILLE ? 4 : 2;
}

static rayo_status fill(const grid *g, rayo_preview_style style,
                        unsigned cols, unsigned rows, char **text,
                        size_t *length, rayo_error *err)
{
    size_t per_line = (size_t)cols * 3 + 1, n = 0;
    unsigned r, c;
    char *out;
    if (rows != 0 && per_line > (SIZE_MAX - 1) / rows)
        return rayo_error_set(err, RAYO_ERR_LIMIT,
                              "preview: %u lines of %u cells is too much",
                              rows, cols);
    out = malloc(per_line * rows + 1);
    if (out == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM,
                              "preview: out of memory for %u lines", rows);
    for (r = 0; r < rows; r++) {
        for (c = 0; c < cols; c++)
            n += put_cell(g, style, c, r, out + n);
        out[n++] = '\n';
    }
    out[n] = '\0';
    *text = out;
    *length = n;
    return RAYO_OK;
}

rayo_status rayo_preview_render(const rayo_image *image,
                                const rayo_preview_options *options,
                                char **text, size_t *length,
                                unsigned *cells_wide, unsigned *lines,
                                rayo_error *err)
{
    rayo_image owned;
    grid g;
    unsigned across, down, cols, rows;
    rayo_status s;
    *text = NULL;
    *length = 0;
    memset(&owned, 0, sizeof owned);
    if (options->columns == 0)
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "preview: 0 columns; expected 1 or more");
    if ((s = rayo_image_info_check(&image->info, err)) != RAYO_OK)
        return s;
    g.mask = image;
    if (image->info.sample != RAYO_SAMPLE_BIT) {
        if ((s = rayo_image_to_bit(image, &owned, err)) != RAYO_OK)
            return s;
        g.mask = &owned;
    }
    cell_shape(options->style, &across, &down);
    cols = options->columns;
    if ((uint64_t)cols * across > image->info.width)
        cols = (image->info.width + across - 1) / across;
    g.s = (double)image->info.width / ((double)cols * across);
    if (g.s < 1)
        g.s = 1;
    g.sub_w = (unsigned)ceil(image->info.width / g.s);
    g.sub_h = (unsigned)floor(image->info.height / g.s + 0.5);
    if (g.sub_h == 0)
        g.sub_h = 1;
    rows = (g.sub_h + down - 1) / down;
    s = fill(&g, options->style, cols, rows, text, length, err);
    if (s == RAYO_OK && cells_wide)
        *cells_wide = cols;
    if (s == RAYO_OK && lines)
        *lines = rows;
    rayo_image_free(&owned);
    return s;
}
