/*
 * render_preview.c - the summary behind `rayo render --preview`
 * (render_preview.h).
 *
 * Rows are added to a rayo_preview as they pass on to the writer, in the
 * style `rayo view` would choose for the written file: silhouette blocks
 * for bilevel images, colour blocks for gray and colour ones.  The colour
 * mode waits for the stream, so a picture into a file or a pipe has no
 * escape sequences, as before.
 */
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "render_preview.h"

struct cli_preview {
    rayo_preview *summary;
    rayo_preview_options options;
    rayo_row_sink next;
    void *next_context;
};

rayo_status cli_preview_create(cli_preview **preview,
                               const rayo_image_info *info, rayo_error *err)
{
    cli_preview *p = calloc(1, sizeof *p);
    rayo_status s;
    *preview = NULL;
    if (p == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM,
                              _("--preview: out of memory"));
    rayo_preview_options_init(&p->options);
    p->options.columns = cli_terminal_columns();
    if (info->sample != RAYO_SAMPLE_BIT)
        p->options.style = RAYO_PREVIEW_COLOR_BLOCKS;
    s = rayo_preview_create(&p->summary, info, &p->options, err);
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

rayo_status cli_preview_rows(void *preview, const unsigned char *rows,
                             size_t stride, uint32_t first_row,
                             uint32_t count, rayo_error *err)
{
    cli_preview *p = preview;
    rayo_status s =
        rayo_preview_rows(p->summary, rows, stride, first_row, count, err);
    if (s != RAYO_OK || p->next == NULL)
        return s;
    return p->next(p->next_context, rows, stride, first_row, count, err);
}

int cli_preview_print(const cli_preview *preview, FILE *stream)
{
    rayo_preview_options options = preview->options;
    rayo_error err = RAYO_ERROR_INIT(cli_lang());
    char *text;
    size_t length;
    rayo_error_clear(&err);
    options.color = cli_preview_color(stream, CLI_COLOR_AUTO);
    if (rayo_preview_text(preview->summary, &options, &text, &length, NULL,
                          NULL, &err) != RAYO_OK)
        return cli_report(&err);
    fwrite(text, 1, length, stream);
    free(text);
    return cli_flush_text(stream, stream == stdout ? _("standard output")
                                                   : _("standard error"));
}

void cli_preview_free(cli_preview *preview)
{
    if (preview == NULL)
        return;
    rayo_preview_free(preview->summary);
    free(preview);
}
