/*
 * progress.c - drawing the progress bar of progress.h: "\r", a bar of
 * '#' and '.', the percentage, the rows and the time so far, redrawn at
 * most ten times a second; "\r", blanks and "\r" erase it.
 */
#define _POSIX_C_SOURCE 200809L

#include "progress.h"

#include "cli.h"

#include <stdio.h>
#include <time.h>
#include <unistd.h>

#define PROGRESS_DELAY_SECONDS 1.0
#define PROGRESS_INTERVAL_SECONDS 0.1
#define BAR_WIDTH 30
#define LINE_WIDTH 79

static double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

void cli_progress_init(cli_progress *progress, int quiet)
{
    progress->enabled = !quiet && isatty(STDERR_FILENO);
    progress->drawn = 0;
    progress->start = now_seconds();
    progress->last_draw = 0.0;
}

static void draw(const cli_progress *progress, uint32_t done, uint32_t total,
                 double now)
{
    char bar[BAR_WIDTH + 1];
    unsigned filled = total ? (unsigned)((uint64_t)done * BAR_WIDTH / total)
                            : BAR_WIDTH;
    unsigned i;
    for (i = 0; i < BAR_WIDTH; i++)
        bar[i] = i < filled ? '#' : '.';
    bar[BAR_WIDTH] = '\0';
    char seconds[RAYO_LANG_NUMBER_SIZE];
    fprintf(stderr, "\rrayo: [%s] %3u%%  ", bar,
            total ? (unsigned)((uint64_t)done * 100 / total) : 100u);
    /* TRANSLATORS: the progress line's end: rows rendered, of all, and
       the seconds since the start ("12/480 rows  1.5 s"). */
    fprintf(stderr, _("%lu/%lu rows  %s s"), (unsigned long)done,
            (unsigned long)total,
            rayo_lang_decimal(cli_lang(), now - progress->start, 1, seconds,
                              sizeof seconds));
    fflush(stderr);
}

void cli_progress_update(cli_progress *progress, uint32_t rows_done,
                         uint32_t rows_total)
{
    double now;
    if (!progress->enabled)
        return;
    now = now_seconds();
    if (now - progress->start < PROGRESS_DELAY_SECONDS ||
        now - progress->last_draw < PROGRESS_INTERVAL_SECONDS)
        return;
    draw(progress, rows_done, rows_total, now);
    progress->drawn = 1;
    progress->last_draw = now;
}

void cli_progress_finish(cli_progress *progress)
{
    if (!progress->drawn)
        return;
    fprintf(stderr, "\r%*s\r", LINE_WIDTH, "");
    fflush(stderr);
    progress->drawn = 0;
}
