/*
 * commands.c - benchmark rows that are shell commands, read from
 * bench/commands.tsv, so a row can be added without writing C.
 *
 * Each line is KEY<TAB>LABEL<TAB>COMMAND, or "setup<TAB>COMMAND" (run
 * once, untimed, before the rows that follow it); '#' starts a comment.
 * Commands run under /bin/sh with $RAYO (the command under test),
 * $RAYO_BUILD (its build folder), $RAYO_SOURCE (the repository) and
 * $BENCH_TMP (a scratch folder, removed afterwards) in the environment,
 * and standard output on /dev/null.  Each row gives two figures: the best
 * wall time of the runs, and the largest peak RSS of the process tree.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"

#define LINE_MAX_BYTES 4096

static void run_row(bench_table *table, const char *key, const char *label,
                    const char *command)
{
    char key_time[LINE_MAX_BYTES + 8], key_rss[LINE_MAX_BYTES + 8];
    char label_rss[LINE_MAX_BYTES + 16];
    double best = -1;
    long rss_max = -1;
    int r;
    for (r = 0; r < bench_repeats(table); r++) {
        long rss = -1;
        double seconds = bench_run_child(NULL, command, &rss);
        if (seconds < 0) {
            best = -1;
            break;
        }
        if (best < 0 || seconds < best)
            best = seconds;
        if (rss > rss_max)
            rss_max = rss;
    }
    snprintf(key_time, sizeof key_time, "%s_s", key);
    snprintf(key_rss, sizeof key_rss, "%s_rss_kib", key);
    snprintf(label_rss, sizeof label_rss, "%s, peak RSS", label);
    if (best < 0) {
        bench_add(table, key_time, label, -1, "failed");
        return;
    }
    bench_add(table, key_time, label, best * 1e3, "ms");
    bench_add(table, key_rss, label_rss, (double)rss_max / 1024.0, "MiB");
}

/* Splits line at tabs into at most 3 fields; returns how many. */
static int split(char *line, char *fields[3])
{
    int n = 0;
    char *p = line;
    line[strcspn(line, "\r\n")] = '\0';
    while (n < 3) {
        char *tab = n < 2 ? strchr(p, '\t') : NULL;
        fields[n++] = p;
        if (tab == NULL)
            break;
        *tab = '\0';
        p = tab + 1;
    }
    return n;
}

void bench_commands(bench_table *table, const char *rows_file)
{
    char line[LINE_MAX_BYTES];
    FILE *rows = fopen(rows_file, "r");
    if (rows == NULL) {
        bench_add(table, "commands_error", rows_file, -1, "unreadable");
        return;
    }
    while (fgets(line, sizeof line, rows) != NULL) {
        char *fields[3];
        int n;
        if (line[0] == '#' || line[0] == '\n')
            continue;
        n = split(line, fields);
        if (n == 2 && strcmp(fields[0], "setup") == 0) {
            long rss;
            if (bench_run_child(NULL, fields[1], &rss) < 0)
                bench_add(table, "setup_error", fields[1], -1, "failed");
        } else if (n == 3) {
            run_row(table, fields[0], fields[1], fields[2]);
        }
    }
    fclose(rows);
}
