/*
 * render_preview.c - the bilevel copy behind `rayo render --preview`
 * (render_preview.h).
 *
 * Bilevel rows are copied as they are; gray and colour rows (the shaded
 * modes) are thresholded at half their maximum by rayo_image_to_bit, one
 * band at a time, exactly as `rayo view` would see the written file.
 */
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "render_preview.h"

struct cli_preview {
    rayo_image_info info; /* of the rows coming in */
    rayo_image mask;      /* the copy */
    rayo_row_sink next;
    void *next_context;
};

rayo_status cli_preview_create(cli_preview **preview,
                               const rayo_image_info *info, rayo_error *err)
{
    rayo_image_info bits = rayo_image_info_bit(info->width, info->height);
    cli_preview *p = calloc(1, sizeof *p);
    rayo_status s;
    *preview = NULL;
    if (p == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM,
                              "--preview: out of memory");
    p->info = *info;
    s = rayo_image_create(&p->mask, &bits, err);
    if (s != RAYO_OK) {
        free(p);
        return s;
    }
    *preview = p;
    return RAYO_OK;
}

void cli_preview_forward(cli_preview *preview, rayo_row_sink next,
                         void *next_context)
{
    preview->next = next;
    preview->next_context = next_context;
}

static rayo_status copy_rows(cli_preview *p, const unsigned char *rows,
                             size_t stride, uint32_t first_row,
                             uint32_t count, rayo_error *err)
{
    rayo_image band, bits;
    size_t n = rayo_image_info_row_bytes(&p->mask.info);
    uint32_t i;
    rayo_status s;
    memset(&bits, 0, sizeof bits);
    band.info = p->info;
    band.info.height = count;
    band.stride = stride;
    band.pixels = (unsigned char *)rows; /* read only */
    if (p->info.sample != RAYO_SAMPLE_BIT) {
        if ((s = rayo_image_to_bit(&band, &bits, err)) != RAYO_OK)
            return s;
        rows = bits.pixels;
        stride = bits.stride;
    }
    for (i = 0; i < count; i++)
        memcpy(rayo_image_row(&p->mask, first_row + i), rows + i * stride,
               n);
    rayo_image_free(&bits);
    return RAYO_OK;
}

rayo_status cli_preview_rows(void *preview, const unsigned char *rows,
                             size_t stride, uint32_t first_row,
                             uint32_t count, rayo_error *err)
{
    cli_preview *p = preview;
    rayo_status s = copy_rows(p, rows, stride, first_row, count, err);
    if (s != RAYO_OK || p->next == NULL)
        return s;
    return p->next(p->next_context, rows, stride, first_row, count, err);
}

int cli_preview_print(const cli_preview *preview, FILE *stream)
{
    rayo_preview_options options;
    rayo_preview_options_init(&options);
    options.columns = cli_terminal_columns();
    return cli_print_preview(&preview->mask, &options, stream);
}

void cli_preview_free(cli_preview *preview)
{
    if (preview == NULL)
        return;
    rayo_image_free(&preview->mask);
    free(preview);
}
