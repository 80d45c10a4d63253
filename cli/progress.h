/*
 * progress.h - the progress bar `rayo render` draws on stderr for renders
 * that take more than about a second.
 *
 * Only when stderr is a terminal, never with --quiet, and never before
 * the first second has passed, so quick renders, pipes and logs stay
 * clean.  The bar is one line redrawn in place and erased at the end.
 * It only draws; stopping a render is the caller's business.
 */
#ifndef RAYO_CLI_PROGRESS_H
#define RAYO_CLI_PROGRESS_H

#include <stdint.h>

typedef struct cli_progress {
    int enabled;      /* stderr is a terminal and --quiet was not given */
    int drawn;        /* a bar is on the screen */
    double start;     /* seconds, monotonic */
    double last_draw; /* when the bar was last drawn */
} cli_progress;

void cli_progress_init(cli_progress *progress, int quiet);

/* After rows_done of rows_total rows: draws the bar when it is due. */
void cli_progress_update(cli_progress *progress, uint32_t rows_done,
                         uint32_t rows_total);

/* Erases the bar, if one was drawn. */
void cli_progress_finish(cli_progress *progress);

#endif
