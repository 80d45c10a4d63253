/*
 * render_preview.h - the picture of an image in the terminal, for
 * `rayo render --preview` and `rayo view`: whether the terminal gets
 * colour, and a summary of the rows on their way to the writer, so the
 * finished image can be shown (preview.h) without rendering it twice.
 *
 * The summary costs 8 x (1 + channels) bytes a sub-pixel of the picture
 * (about 80 x 120 of them at 80 columns for 640 x 480), not the image.
 * Where the picture goes is the caller's choice: standard output, or
 * standard error when the image itself is written to standard output;
 * it is in colour only when that stream is a terminal.
 */
#ifndef RAYO_CLI_RENDER_PREVIEW_H
#define RAYO_CLI_RENDER_PREVIEW_H

#include <stdio.h>

#include "rayo.h"

/* --color=WHEN (view): auto (a terminal without NO_COLOR), always,
 * never. */
typedef enum cli_color_when {
    CLI_COLOR_AUTO,
    CLI_COLOR_ALWAYS,
    CLI_COLOR_NEVER
} cli_color_when;

/*
 * The colour a picture on stream gets (cmd_view.c): none for never, and
 * for auto when $NO_COLOR is set and not empty (no-color.org) or stream
 * is not a terminal; otherwise 24-bit when $COLORTERM is "truecolor" or
 * "24bit", else 256 colours.
 */
rayo_preview_color cli_preview_color(FILE *stream, cli_color_when when);

typedef struct cli_preview cli_preview;

/* A summary for rows of this layout, $COLUMNS (else 80) wide. */
rayo_status cli_preview_create(cli_preview **preview,
                               const rayo_image_info *info, rayo_error *err);

/* Where rows go after they are summed up (usually the writer). */
void cli_preview_forward(cli_preview *preview, rayo_row_sink next,
                         void *next_context);

/* A rayo_row_sink: adds the rows to the summary, then hands them on. */
rayo_status cli_preview_rows(void *preview, const unsigned char *rows,
                             size_t stride, uint32_t first_row,
                             uint32_t count, rayo_error *err);

/* Prints the picture as `rayo view` would draw the image on stream
 * (colour on a terminal, --color=auto); returns an exit status. */
int cli_preview_print(const cli_preview *preview, FILE *stream);

void cli_preview_free(cli_preview *preview);

#endif
