/*
 * commands.c - benchmark rows that are shell commands, read from
 * bench/commands.tsv, so a row can be added without writing C.
 *
 * Lines ('#' starts a comment):
 *   KEY<TAB>LABEL<TAB>COMMAND[<TAB>RUNS]   a row: best of RUNS runs
 *                                          (default: 3 x --repeat), and
 *                                          one more for peak memory
 *   setup<TAB>COMMAND                      run once, untimed
 *   target<TAB>LABEL<TAB>KEY_A<TAB>KEY_B<TAB><=|>=<TAB>LIMIT
 *                                          the ratio of two figures
 *                                          (KEY_A / KEY_B) as a target;
 *                                          a row KEY has figures KEY_s
 *                                          (time) and KEY_rss_kib
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
                    const char *command, int runs)
{
    char key_time[LINE_MAX_BYTES + 8], key_rss[LINE_MAX_BYTES + 8];
    char label_rss[LINE_MAX_BYTES + 16];
    double best = -1;
    long rss_max = -1;
    int r;
    for (r = 0; r < runs; r++) {
        double seconds = bench_run_child(NULL, command, NULL);
        if (seconds < 0) {
            best = -1;
            break;
        }
        best = bench_best(best, seconds);
    }
    if (best >= 0 && bench_run_child(NULL, command, &rss_max) < 0)
        rss_max = -1;
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

#define MAX_FIELDS 6

/* Splits line at tabs into at most MAX_FIELDS fields; returns how many. */
static int split(char *line, char *fields[MAX_FIELDS])
{
    int n = 0;
    char *p = line;
    line[strcspn(line, "\r\n")] = '\0';
    while (n < MAX_FIELDS) {
        char *tab = n < MAX_FIELDS - 1 ? strchr(p, '\t') : NULL;
        fields[n++] = p;
        if (tab == NULL)
            break;
        *tab = '\0';
        p = tab + 1;
    }
    return n;
}

/* target LABEL KEY_A KEY_B <=|>= LIMIT: figure KEY_A / figure KEY_B. */
static void ratio_target(bench_table *table, char *fields[MAX_FIELDS])
{
    double a = bench_value(table, fields[2]);
    double b = bench_value(table, fields[3]);
    bench_target(table, fields[1], a > 0 && b > 0 ? a / b : -1,
                 atof(fields[5]), strcmp(fields[4], "<=") == 0);
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
        char *fields[MAX_FIELDS];
        int n;
        if (line[0] == '#' || line[0] == '\n')
            continue;
        n = split(line, fields);
        if (n == 2 && strcmp(fields[0], "setup") == 0) {
            if (bench_run_child(NULL, fields[1], NULL) < 0)
                bench_add(table, "setup_error", fields[1], -1, "failed");
        } else if (n == 6 && strcmp(fields[0], "target") == 0) {
            ratio_target(table, fields);
        } else if (n == 3 || n == 4) {
            int runs = n == 4 ? atoi(fields[3]) : 3 * bench_repeats(table);
            run_row(table, fields[0], fields[1], fields[2],
                    runs > 0 ? runs : 1);
        }
    }
    fclose(rows);
}
