/*
 * bench.c - `make bench`: runs every benchmark row, prints the table
 * (figures, then targets with pass or FAIL) and writes it as JSON.
 *
 *   rayo-bench [--json FILE] [--repeat N]
 *              [--only seed|large|bvh|commands|compare|peers|meshes]
 *              [--rows FILE]
 *
 * $RAYO names the `rayo` command for the rows that run it (peak memory,
 * bench/commands.tsv).  Every figure is the best of N runs (default 3;
 * the seed job, which takes about a millisecond, 4N; the mesh rows of
 * meshes.c the median of N), taken in this one process, so the ratios
 * hold on a machine others are using.
 *
 * Adding a row:
 *   - a shell command: one line in bench/commands.tsv (commands.c says
 *     how); its time and peak memory join the table;
 *   - a measurement in C: a function void bench_NAME(bench_table *) in a
 *     new bench/NAME.c (the Makefile builds every .c in bench/), declared in
 *     bench.h and called from main() below; it reports with bench_add
 *     and, for a goal, bench_target.
 * The benchmark checks nothing in `make check`: timings are not tests.
 */
#define _POSIX_C_SOURCE 200809L

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/utsname.h>
#include <unistd.h>

#include "bench.h"

#define MAX_FIGURES 192
#define MAX_TARGETS 48

typedef struct figure {
    char key[64], label[128], unit[16];
    double value;
} figure;

typedef struct target {
    char label[128];
    double value, limit;
    int at_most, skipped;
} target;

struct bench_table {
    int repeats;
    size_t figure_count, target_count;
    figure figures[MAX_FIGURES];
    target targets[MAX_TARGETS];
};

static void copy(char *dst, size_t size, const char *src)
{
    snprintf(dst, size, "%s", src);
}

void bench_add(bench_table *table, const char *key, const char *label,
               double value, const char *unit)
{
    figure *f;
    if (table->figure_count == MAX_FIGURES)
        return;
    f = &table->figures[table->figure_count++];
    copy(f->key, sizeof f->key, key);
    copy(f->label, sizeof f->label, label);
    copy(f->unit, sizeof f->unit, unit);
    f->value = value;
    if (strcmp(unit, "skipped") == 0)
        printf("  %-52s %12s\n", label, unit);
    else
        printf("  %-52s %12.3f %s\n", label, value, unit);
    fflush(stdout);
}

void bench_target(bench_table *table, const char *label, double value,
                  double limit, int at_most)
{
    target *t;
    if (table->target_count == MAX_TARGETS)
        return;
    t = &table->targets[table->target_count++];
    copy(t->label, sizeof t->label, label);
    t->value = value;
    t->limit = limit;
    t->at_most = at_most;
    t->skipped = 0;
}

void bench_target_skipped(bench_table *table, const char *label,
                          double limit, int at_most)
{
    size_t before = table->target_count;
    bench_target(table, label, -1, limit, at_most);
    if (table->target_count > before)
        table->targets[before].skipped = 1;
}

double bench_value(const bench_table *table, const char *key)
{
    size_t i;
    for (i = 0; i < table->figure_count; i++)
        if (strcmp(table->figures[i].key, key) == 0)
            return table->figures[i].value;
    return -1;
}

int bench_repeats(const bench_table *table)
{
    return table->repeats;
}

double bench_best(double a, double b)
{
    if (a < 0)
        return b;
    if (b < 0)
        return a;
    return a < b ? a : b;
}

static int target_met(const target *t)
{
    return t->value >= 0 && (t->at_most ? t->value <= t->limit
                                        : t->value >= t->limit);
}

static void print_targets(const bench_table *table)
{
    size_t i;
    printf("\ntargets (ratios from the figures above):\n");
    for (i = 0; i < table->target_count; i++) {
        const target *t = &table->targets[i];
        if (t->skipped)
            printf("  %-52s %9s  %s %-7g %s\n", t->label, "", t->at_most ?
                   "<=" : ">=", t->limit, "skipped");
        else
            printf("  %-52s %9.3f  %s %-7g %s\n", t->label, t->value,
                   t->at_most ? "<=" : ">=", t->limit,
                   target_met(t) ? "pass" : "FAIL");
    }
}

/* text as a JSON string: quotes, backslashes and controls escaped. */
static void json_string(FILE *out, const char *text)
{
    const unsigned char *p = (const unsigned char *)text;
    fputc('"', out);
    for (; *p != '\0'; p++) {
        if (*p == '"' || *p == '\\')
            fprintf(out, "\\%c", *p);
        else if (*p < 0x20)
            fprintf(out, "\\u%04x", *p);
        else
            fputc(*p, out);
    }
    fputc('"', out);
}

static void write_json(const bench_table *table, const char *path)
{
    struct utsname host;
    FILE *out = fopen(path, "w");
    size_t i;
    if (out == NULL) {
        perror(path);
        return;
    }
    if (uname(&host) != 0)
        memset(&host, 0, sizeof host);
    fprintf(out, "{\n  \"machine\": {\"cpus\": %u, \"system\": \"%s %s\", "
                 "\"arch\": \"%s\"},\n",
            rayo_cpu_count(), host.sysname, host.release, host.machine);
    fprintf(out, "  \"repeats\": %d,\n  \"figures\": [\n", table->repeats);
    for (i = 0; i < table->figure_count; i++) {
        const figure *f = &table->figures[i];
        fprintf(out, "    {\"key\": ");
        json_string(out, f->key);
        fprintf(out, ", \"label\": ");
        json_string(out, f->label);
        fprintf(out, ", \"value\": %.6g, \"unit\": ", f->value);
        json_string(out, f->unit);
        fprintf(out, "}%s\n", i + 1 < table->figure_count ? "," : "");
    }
    fprintf(out, "  ],\n  \"targets\": [\n");
    for (i = 0; i < table->target_count; i++) {
        const target *t = &table->targets[i];
        fprintf(out, "    {\"label\": ");
        json_string(out, t->label);
        fprintf(out, ", \"value\": %.6g, \"%s\": %g, \"met\": %s}%s\n",
                t->value, t->at_most ? "at_most" : "at_least", t->limit,
                t->skipped ? "null, \"skipped\": true"
                           : target_met(t) ? "true" : "false",
                i + 1 < table->target_count ? "," : "");
    }
    fprintf(out, "  ]\n}\n");
    fclose(out);
}

static int wants(const char *only, const char *part)
{
    return only == NULL || strcmp(only, part) == 0;
}

int main(int argc, char **argv)
{
    static bench_table table;
    const char *json = NULL, *only = NULL, *rows = "bench/commands.tsv";
    const char *rayo = getenv("RAYO");
    char scratch[] = "/tmp/rayo-bench.XXXXXX";
    int i;
    table.repeats = 3;
    for (i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--json") == 0 && i + 1 < argc)
            json = argv[++i];
        else if (strcmp(argv[i], "--repeat") == 0 && i + 1 < argc)
            table.repeats = atoi(argv[++i]) > 0 ? atoi(argv[i]) : 1;
        else if (strcmp(argv[i], "--only") == 0 && i + 1 < argc)
            only = argv[++i];
        else if (strcmp(argv[i], "--rows") == 0 && i + 1 < argc)
            rows = argv[++i];
        else {
            fprintf(stderr, "usage: %s [--json FILE] [--repeat N] [--only "
                            "seed|large|bvh|commands|compare|peers|meshes] "
                            "[--rows FILE]\n",
                    argv[0]);
            return 2;
        }
    }
    if (mkdtemp(scratch) == NULL) {
        perror("mkdtemp");
        return 1;
    }
    setenv("BENCH_TMP", scratch, 1);
    printf("rayo benchmark: best of %d runs, %u CPUs\n\n", table.repeats,
           rayo_cpu_count());
    if (wants(only, "seed"))
        bench_seed(&table);
    if (wants(only, "large"))
        bench_large(&table, rayo);
    if (wants(only, "bvh"))
        bench_bvh(&table);
    if (wants(only, "commands") && rayo != NULL)
        bench_commands(&table, rows);
    if (wants(only, "compare") && rayo != NULL)
        bench_compare_noise(&table);
    if (wants(only, "peers") && rayo != NULL)
        bench_peers(&table);
    if (wants(only, "meshes") && rayo != NULL)
        bench_meshes(&table);
    print_targets(&table);
    if (json != NULL) {
        write_json(&table, json);
        printf("\nwrote %s\n", json);
    }
    {
        char command[64];
        snprintf(command, sizeof command, "rm -rf '%s'", scratch);
        bench_run_child(NULL, command, NULL);
    }
    return 0;
}
