/*
 * preview.c - shrinking an image to character cells of block, Braille,
 * ASCII or colour block characters (preview.h says what each style
 * draws), from the whole image in memory.
 *
 * The picture is a grid of sub-pixels, sw = columns x (sub-pixels a cell
 * across) wide; each sub-pixel covers a square of s x s image pixels,
 * s = width / sw (>= 1: never enlarged).  For the silhouette a sub-pixel
 * is black when at least half of the pixels inside it are; for colour it
 * is their mean (preview_color.c).  Cells are taken to be twice as tall
 * as wide, so a cell holds 1 x 2 (blocks, colour blocks), 2 x 4 (Braille)
 * or 1 x 2 (ASCII, judged by coverage) sub-pixels.  The numbers of a
 * sub-pixel come from the image here, or from a summary of rows as they
 * came (preview_stream.c); the drawing is the same.  Not a general
 * resampler: no filtering beyond the box average.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "preview_impl.h"

void rayo_preview_options_init(rayo_preview_options *options)
{
    options->columns = 80;
    options->style = RAYO_PREVIEW_BLOCKS;
    options->color = RAYO_PREVIEW_COLOR_NONE;
}

/* Cells across and sub-pixels per cell for a style. */
static void cell_shape(rayo_preview_style style, unsigned *across,
                       unsigned *down)
{
    *across = style == RAYO_PREVIEW_BRAILLE ? 2 : 1;
    *down = style == RAYO_PREVIEW_BRAILLE ? 4 : 2;
}

rayo_status preview_grid_init(preview_grid *g, const rayo_image_info *info,
                              const rayo_preview_options *options,
                              rayo_error *err)
{
    unsigned across, down, cols;
    rayo_status s;
    memset(g, 0, sizeof *g);
    if (options->columns == 0)
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "preview: 0 columns; expected 1 or more");
    if ((unsigned)options->style > RAYO_PREVIEW_COLOR_BLOCKS)
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "preview: style %u is not one of the four",
                              (unsigned)options->style);
    if ((unsigned)options->color > RAYO_PREVIEW_COLOR_TRUECOLOR)
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "preview: colour mode %u is not one of the "
                              "three", (unsigned)options->color);
    if ((s = rayo_image_info_check(info, err)) != RAYO_OK)
        return s;
    g->info = *info;
    cell_shape(options->style, &across, &down);
    cols = options->columns;
    if ((uint64_t)cols * across > info->width)
        cols = (info->width + across - 1) / across;
    g->s = (double)info->width / ((double)cols * across);
    if (g->s < 1)
        g->s = 1;
    g->sub_w = (unsigned)ceil(info->width / g->s);
    g->sub_h = (unsigned)floor(info->height / g->s + 0.5);
    if (g->sub_h == 0)
        g->sub_h = 1;
    g->cols = cols;
    g->rows = (g->sub_h + down - 1) / down;
    return RAYO_OK;
}

void preview_grid_bounds(const preview_grid *g, unsigned u, unsigned v,
                         uint32_t *x0, uint32_t *x1, uint32_t *y0,
                         uint32_t *y1)
{
    const rayo_image_info *info = &g->info;
    *x0 = (uint32_t)floor(u * g->s);
    *x1 = (uint32_t)floor((u + 1) * g->s);
    *y0 = (uint32_t)floor(v * g->s);
    *y1 = (uint32_t)floor((v + 1) * g->s);
    if (*x1 > info->width)
        *x1 = info->width;
    if (*y1 > info->height)
        *y1 = info->height;
    if (*x1 <= *x0)
        *x1 = *x0 + 1 <= info->width ? *x0 + 1 : *x0;
    if (*y1 <= *y0)
        *y1 = *y0 + 1 <= info->height ? *y0 + 1 : *y0;
}

int preview_pixel(const rayo_image_info *info, const unsigned char *row,
                  uint32_t x, unsigned samples[3])
{
    size_t i = (size_t)x * info->channels;
    unsigned c;
    uint64_t lum;
    uint16_t v;
    if (info->sample == RAYO_SAMPLE_BIT) {
        samples[0] = 1u - (unsigned)rayo_bit_get(row, x);
        return samples[0] == 0;
    }
    for (c = 0; c < info->channels; c++) {
        if (info->sample == RAYO_SAMPLE_U8) {
            samples[c] = row[i + c];
        } else {
            memcpy(&v, row + 2 * (i + c), sizeof v);
            samples[c] = v;
        }
    }
    /* rayo_image_to_bit's rule: 1000 x luminance under 500 x maxval */
    lum = info->channels == 1
              ? 1000u * (uint64_t)samples[0]
              : 299u * (uint64_t)samples[0] + 587u * (uint64_t)samples[1] +
                    114u * (uint64_t)samples[2];
    return lum < 500u * (uint64_t)info->maxval;
}

int preview_bin_get(const preview_grid *g, unsigned u, unsigned v,
                    preview_bin *bin)
{
    uint32_t x0, x1, y0, y1, x, y;
    unsigned samples[3], c, ch = g->info.channels;
    memset(bin, 0, sizeof *bin);
    if (u >= g->sub_w || v >= g->sub_h)
        return 0;
    preview_grid_bounds(g, u, v, &x0, &x1, &y0, &y1);
    bin->all = (uint64_t)(x1 - x0) * (y1 - y0);
    if (g->image == NULL) {
        const uint64_t *n = g->summary + ((size_t)v * g->sub_w + u) * (1 + ch);
        bin->black = n[0];
        for (c = 0; c < ch; c++)
            bin->sum[c] = n[1 + c];
        return 1;
    }
    for (y = y0; y < y1; y++) {
        const unsigned char *row = rayo_image_row(g->image, y);
        for (x = x0; x < x1; x++) {
            bin->black += (uint64_t)preview_pixel(&g->info, row, x, samples);
            for (c = 0; c < ch; c++)
                bin->sum[c] += samples[c];
        }
    }
    return 1;
}

static int sub_black(const preview_grid *g, unsigned u, unsigned v)
{
    preview_bin bin;
    return preview_bin_get(g, u, v, &bin) && bin.all != 0 &&
           2 * bin.black >= bin.all;
}

static size_t put_utf8(char *out, unsigned code)
{
    out[0] = (char)(0xE0 | (code >> 12));
    out[1] = (char)(0x80 | ((code >> 6) & 0x3F));
    out[2] = (char)(0x80 | (code & 0x3F));
    return 3;
}

static size_t put_cell(const preview_grid *g, rayo_preview_style style,
                       rayo_preview_color color, unsigned c, unsigned r,
                       char *out)
{
    static const unsigned dots[4][2] = {
        {0x01, 0x08}, {0x02, 0x10}, {0x04, 0x20}, {0x40, 0x80}};
    unsigned bits = 0, i, j;
    preview_bin upper, lower;
    if (style == RAYO_PREVIEW_COLOR_BLOCKS) {
        preview_bin_get(g, c, 2 * r, &upper);
        return preview_color_cell(
            color, &g->info, &upper,
            preview_bin_get(g, c, 2 * r + 1, &lower) ? &lower : NULL, out);
    }
    if (style == RAYO_PREVIEW_ASCII) {
        preview_bin_get(g, c, 2 * r, &upper);
        preview_bin_get(g, c, 2 * r + 1, &lower); /* empty past the end */
        upper.black += lower.black;
        upper.all += lower.all;
        *out = 2 * upper.black >= upper.all && upper.all ? '#'
               : upper.black                             ? '+'
                                                         : ' ';
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

rayo_status preview_grid_text(const preview_grid *g,
                              const rayo_preview_options *options,
                              char **text, size_t *length, rayo_error *err)
{
    rayo_preview_style style = options->style;
    rayo_preview_color color = options->color;
    size_t per_cell = 3, per_line, n = 0, end = 0;
    unsigned r, c, cols = g->cols, rows = g->rows;
    char *out;
    *text = NULL;
    *length = 0;
    if (style == RAYO_PREVIEW_COLOR_BLOCKS && color == RAYO_PREVIEW_COLOR_NONE)
        style = RAYO_PREVIEW_BLOCKS; /* the same picture, byte for byte */
    if (style == RAYO_PREVIEW_COLOR_BLOCKS) {
        per_cell = PREVIEW_COLOR_CELL_MAX;
        end = strlen(PREVIEW_COLOR_LINE_END);
    }
    if ((size_t)cols > (SIZE_MAX - 1 - end) / per_cell)
        return rayo_error_set(err, RAYO_ERR_LIMIT,
                              "preview: %u cells a line is too much", cols);
    per_line = (size_t)cols * per_cell + end + 1;
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
            n += put_cell(g, style, color, c, r, out + n);
        memcpy(out + n, PREVIEW_COLOR_LINE_END, end);
        n += end;
        out[n++] = '\n';
    }
    /* colour cells are shorter than their bound: give the rest back */
    if (end != 0) {
        char *fit = realloc(out, n + 1);
        if (fit != NULL)
            out = fit;
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
    preview_grid g;
    rayo_status s;
    *text = NULL;
    *length = 0;
    if ((s = preview_grid_init(&g, &image->info, options, err)) != RAYO_OK)
        return s;
    g.image = image;
    s = preview_grid_text(&g, options, text, length, err);
    if (s == RAYO_OK && cells_wide)
        *cells_wide = g.cols;
    if (s == RAYO_OK && lines)
        *lines = g.rows;
    return s;
}
