/*
 * compare_noise.c - `rayo compare` of a white 16384x16384 PBM against
 * one of noise (issue 14: it once took more than a minute, growing
 * faster than the image), against ImageMagick's `compare -metric AE` on
 * the same two files.
 *
 * The files (32 MiB each, raw PBM) are written here at run time, in
 * $BENCH_TMP, never committed: the noise from a fixed xorshift sequence,
 * so every run compares the same bytes.  The two commands take turns,
 * run after run, and each figure is the median of its runs, so a load
 * that comes and goes on the machine falls on both.  ImageMagick's
 * default policy (Debian's: 16K pixels a side, 256 MiB of memory) would
 * refuse the pair, so it runs with a policy of its own (a policy.xml in
 * $BENCH_TMP named by MAGICK_CONFIGURE_PATH) allowing the 4 GiB or so
 * its pixel cache needs.  Without ImageMagick the peer's figure says
 * "skipped" and only rayo's own target is checked.
 *
 * Targets: rayo at most 5 s, and at most a tenth of ImageMagick's time.
 */
#define _POSIX_C_SOURCE 200809L

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"

#define SIDE 16384u
#define MAX_RUNS 15

/* A raw PBM of SIDE x SIDE: all white, or noise (about half black). */
static int write_pbm(const char *path, int noise)
{
    size_t row = SIDE / 8, y, i;
    unsigned char *line = malloc(row);
    uint64_t state = 0x9E3779B97F4A7C15ull;
    FILE *out = fopen(path, "wb");
    int ok = line != NULL && out != NULL;
    if (ok)
        ok = fprintf(out, "P4\n%u %u\n", SIDE, SIDE) > 0;
    for (y = 0; ok && y < SIDE; y++) {
        for (i = 0; i < row; i++) {
            if (noise) { /* xorshift64 */
                state ^= state << 13;
                state ^= state >> 7;
                state ^= state << 17;
                line[i] = (unsigned char)(state >> 24);
            } else {
                line[i] = 0;
            }
        }
        ok = fwrite(line, 1, row, out) == row;
    }
    if (out != NULL && fclose(out) != 0)
        ok = 0;
    free(line);
    return ok ? 0 : -1;
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, by_value);
    return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

/* Whether `compare` on the PATH is ImageMagick's. */
static int have_magick(void)
{
    return bench_run_child(NULL,
                           "compare -version 2>/dev/null | grep -q "
                           "ImageMagick",
                           NULL) >= 0;
}

/* A policy.xml in dir allowing a pair of this size. */
static int write_policy(const char *dir)
{
    char path[4096];
    FILE *out;
    snprintf(path, sizeof path, "%s/policy.xml", dir);
    out = fopen(path, "w");
    if (out == NULL)
        return -1;
    fprintf(out, "<policymap>\n"
                 "  <policy domain=\"resource\" name=\"memory\" "
                 "value=\"16GiB\"/>\n"
                 "  <policy domain=\"resource\" name=\"map\" "
                 "value=\"32GiB\"/>\n"
                 "  <policy domain=\"resource\" name=\"width\" "
                 "value=\"1MP\"/>\n"
                 "  <policy domain=\"resource\" name=\"height\" "
                 "value=\"1MP\"/>\n"
                 "  <policy domain=\"resource\" name=\"area\" "
                 "value=\"16GP\"/>\n"
                 "  <policy domain=\"resource\" name=\"disk\" "
                 "value=\"64GiB\"/>\n"
                 "</policymap>\n");
    return fclose(out) == 0 ? 0 : -1;
}

void bench_compare_noise(bench_table *table)
{
    const char *tmp = getenv("BENCH_TMP");
    char white[4096], noise[4096];
    double rayo_runs[MAX_RUNS], magick_runs[MAX_RUNS];
    int runs = bench_repeats(table), r, magick, failed = 0;
    const char *rayo_cmd =
        "\"$RAYO\" compare \"$BENCH_TMP/white16k.pbm\" "
        "\"$BENCH_TMP/noise16k.pbm\"; [ $? -le 1 ]";
    const char *magick_cmd =
        "MAGICK_CONFIGURE_PATH=\"$BENCH_TMP\" compare -metric AE "
        "\"$BENCH_TMP/white16k.pbm\" \"$BENCH_TMP/noise16k.pbm\" null: "
        "2>/dev/null; [ $? -le 1 ]";
    const char *label = "rayo compare, white vs noise 16384x16384 PBM";
    const char *peer = "ImageMagick compare -metric AE, the same pair";
    if (tmp == NULL)
        return;
    if (runs > MAX_RUNS)
        runs = MAX_RUNS;
    snprintf(white, sizeof white, "%s/white16k.pbm", tmp);
    snprintf(noise, sizeof noise, "%s/noise16k.pbm", tmp);
    if (write_pbm(white, 0) != 0 || write_pbm(noise, 1) != 0) {
        bench_add(table, "compare_noise_rayo_s", label, -1, "failed");
        return;
    }
    magick = have_magick() && write_policy(tmp) == 0;
    for (r = 0; r < runs && !failed; r++) { /* taking turns */
        rayo_runs[r] = bench_run_child(NULL, rayo_cmd, NULL);
        failed = rayo_runs[r] < 0;
        if (magick > 0) {
            magick_runs[r] = bench_run_child(NULL, magick_cmd, NULL);
            magick = magick_runs[r] >= 0 ? 1 : -1;
        }
    }
    if (failed) {
        bench_add(table, "compare_noise_rayo_s", label, -1, "failed");
    } else {
        double s = median(rayo_runs, runs);
        bench_add(table, "compare_noise_rayo_s", label, s * 1e3, "ms");
        bench_target(table, "compare white vs noise 16384^2: rayo, seconds",
                     s, 5.0, 1);
    }
    if (magick <= 0) {
        bench_add(table, "compare_noise_magick_s", peer, -1,
                  magick < 0 ? "failed" : "skipped");
        remove(white);
        remove(noise);
        return;
    }
    bench_add(table, "compare_noise_magick_s", peer,
              median(magick_runs, runs) * 1e3, "ms");
    if (!failed)
        bench_target(table, "compare white vs noise: rayo / ImageMagick",
                     median(rayo_runs, runs) / median(magick_runs, runs),
                     0.1, 1);
    remove(white);
    remove(noise);
}
