/*
 * peer_rows.c - what the rows against other programs (peers.c on the
 * sphere field, meshes.c on the meshes) share: the "key value" lines the
 * Embree program prints, ratios of figures that may be missing, and
 * figures and targets that say "skipped" when the other program is not
 * on this machine.  Not where anything is measured.
 */
#define _POSIX_C_SOURCE 200809L

#include <stdlib.h>
#include <string.h>

#include "bench.h"

double bench_output_value(const char *text, const char *key)
{
    size_t n = strlen(key);
    const char *p = text;
    while (p != NULL && *p != '\0') {
        if (strncmp(p, key, n) == 0 && p[n] == ' ')
            return atof(p + n + 1);
        p = strchr(p, '\n');
        if (p != NULL)
            p++;
    }
    return -1;
}

double bench_ratio(double a, double b)
{
    return a > 0 && b > 0 ? a / b : -1;
}

void bench_add_peer(bench_table *table, const char *key, const char *label,
                    double value, const char *unit, int available)
{
    if (!available)
        bench_add(table, key, label, -1, "skipped");
    else
        bench_add(table, key, label, value, value < 0 ? "failed" : unit);
}

void bench_target_peer(bench_table *table, const char *label, double value,
                       double limit, int at_most, int available)
{
    if (available)
        bench_target(table, label, value, limit, at_most);
    else
        bench_target_skipped(table, label, limit, at_most);
}
