/*
 * render_preview.h - `rayo render --preview`: keeping a bilevel copy of
 * the rows on their way to the writer, so the finished image can be shown
 * in the terminal (preview.h) without rendering it twice.
 *
 * The copy costs one bit a pixel (2 MiB for 4096 x 4096).  Where the
 * picture goes is the caller's choice: standard output, or standard
 * error when the image itself is written to standard output.
 */
#ifndef RAYO_CLI_RENDER_PREVIEW_H
#define RAYO_CLI_RENDER_PREVIEW_H

#include <stdio.h>

#include "rayo.h"

typedef struct cli_preview cli_preview;

/* A copy for rows of this layout. */
rayo_status cli_preview_create(cli_preview **preview,
                               const rayo_image_info *info, rayo_error *err);

/* Where rows go after they are copied (usually the writer). */
void cli_preview_forward(cli_preview *preview, rayo_row_sink next,
                         void *next_context);

/* A rayo_row_sink: copies the rows, then hands them on. */
rayo_status cli_preview_rows(void *preview, const unsigned char *rows,
                             size_t stride, uint32_t first_row,
                             uint32_t count, rayo_error *err);

/* Prints the picture, $COLUMNS (else 80) wide; returns an exit status. */
int cli_preview_print(const cli_preview *preview, FILE *stream);

void cli_preview_free(cli_preview *preview);

#endif
