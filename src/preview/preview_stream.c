/*
 * preview_stream.c - rayo_preview: the picture of an image whose rows
 * arrive a band at a time (rayo render --preview), kept as a summary of
 * each sub-pixel instead of the pixels (preview.h).
 *
 * The grid is preview.c's, fixed by the layout and the options at
 * creation; two tables give each image column and row its sub-pixel
 * (UINT32_MAX: a row past the last sub-pixel, which the picture leaves
 * out as preview.c does), and each pixel adds itself to its sub-pixel's
 * black count and channel sums.  The text is then drawn from those sums
 * by the same code as from a whole image, so both give the same bytes.
 */
#include <stdlib.h>
#include <string.h>

#include "preview_impl.h"

struct rayo_preview {
    preview_grid grid;
    rayo_preview_options options;
    uint32_t *column_bin, *row_bin;
    uint64_t *summary;
    unsigned per_bin; /* 1 + channels */
};

void rayo_preview_free(rayo_preview *preview)
{
    if (preview == NULL)
        return;
    free(preview->column_bin);
    free(preview->row_bin);
    free(preview->summary);
    free(preview);
}

/* Fills the tables of sub-pixels by column and by row. */
static void map_bins(rayo_preview *p)
{
    const preview_grid *g = &p->grid;
    uint32_t x0, x1, y0, y1, i;
    unsigned u, v;
    for (i = 0; i < g->info.height; i++)
        p->row_bin[i] = UINT32_MAX;
    for (u = 0; u < g->sub_w; u++) {
        preview_grid_bounds(g, u, 0, &x0, &x1, &y0, &y1);
        for (i = x0; i < x1; i++)
            p->column_bin[i] = u;
    }
    for (v = 0; v < g->sub_h; v++) {
        preview_grid_bounds(g, 0, v, &x0, &x1, &y0, &y1);
        for (i = y0; i < y1; i++)
            p->row_bin[i] = v;
    }
}

rayo_status rayo_preview_create(rayo_preview **preview,
                                const rayo_image_info *info,
                                const rayo_preview_options *options,
                                rayo_error *err)
{
    rayo_preview *p;
    uint64_t numbers;
    unsigned sub_w, sub_h;
    rayo_status s;
    *preview = NULL;
    p = calloc(1, sizeof *p);
    if (p == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "preview: out of memory");
    if ((s = preview_grid_init(&p->grid, info, options, err)) != RAYO_OK) {
        free(p);
        return s;
    }
    p->options = *options;
    p->per_bin = 1 + info->channels;
    sub_w = p->grid.sub_w;
    sub_h = p->grid.sub_h;
    numbers = (uint64_t)sub_w * sub_h * p->per_bin;
    if (numbers > SIZE_MAX / sizeof *p->summary) {
        free(p);
        return rayo_error_set(err, RAYO_ERR_LIMIT,
                              "preview: %u x %u sub-pixels is too many",
                              sub_w, sub_h);
    }
    p->summary = calloc((size_t)numbers, sizeof *p->summary);
    p->column_bin = malloc((size_t)info->width * sizeof *p->column_bin);
    p->row_bin = malloc((size_t)info->height * sizeof *p->row_bin);
    if (p->summary == NULL || p->column_bin == NULL || p->row_bin == NULL) {
        rayo_preview_free(p);
        return rayo_error_set(err, RAYO_ERR_NOMEM,
                              "preview: out of memory for %u x %u "
                              "sub-pixels", sub_w, sub_h);
    }
    p->grid.summary = p->summary;
    map_bins(p);
    *preview = p;
    return RAYO_OK;
}

rayo_status rayo_preview_rows(void *preview, const unsigned char *rows,
                              size_t stride, uint32_t first_row,
                              uint32_t count, rayo_error *err)
{
    rayo_preview *p = preview;
    const rayo_image_info *info = &p->grid.info;
    unsigned samples[3], c, ch = info->channels;
    uint32_t i, x;
    if (first_row > info->height || count > info->height - first_row)
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "preview: rows %lu to %lu of an image %lu "
                              "tall", (unsigned long)first_row,
                              (unsigned long)first_row + count,
                              (unsigned long)info->height);
    for (i = 0; i < count; i++) {
        const unsigned char *row = rows + (size_t)i * stride;
        uint32_t v = p->row_bin[first_row + i];
        uint64_t *line;
        if (v == UINT32_MAX)
            continue;
        line = p->summary + (size_t)v * p->grid.sub_w * p->per_bin;
        for (x = 0; x < info->width; x++) {
            uint64_t *n = line + (size_t)p->column_bin[x] * p->per_bin;
            n[0] += (uint64_t)preview_pixel(info, row, x, samples);
            for (c = 0; c < ch; c++)
                n[1 + c] += samples[c];
        }
    }
    return RAYO_OK;
}

rayo_status rayo_preview_text(const rayo_preview *preview,
                              const rayo_preview_options *options,
                              char **text, size_t *length,
                              unsigned *cells_wide, unsigned *lines,
                              rayo_error *err)
{
    rayo_status s;
    *text = NULL;
    *length = 0;
    if (options->columns != preview->options.columns ||
        options->style != preview->options.style)
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "preview: columns and style must be those "
                              "the preview was made for");
    if ((unsigned)options->color > RAYO_PREVIEW_COLOR_TRUECOLOR)
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "preview: colour mode %u is not one of the "
                              "three", (unsigned)options->color);
    s = preview_grid_text(&preview->grid, options, text, length, err);
    if (s == RAYO_OK && cells_wide)
        *cells_wide = preview->grid.cols;
    if (s == RAYO_OK && lines)
        *lines = preview->grid.rows;
    return s;
}
