/*
 * t_compare_bounds.c - the farthest mismatch and the count beyond the
 * tolerance, as rayo_compare_images reports them, against a brute-force
 * distance computed here, on frames wrong everywhere (flipped, inverted,
 * unrelated) and wrong in a few pixels.
 *
 * compare finds the largest distance from bounds (only the mismatches
 * that could be the farthest get an exact distance) and counts the far
 * mismatches without distances at all, so these frames are chosen to
 * catch a bound that is too tight or a count that is off: sizes around
 * the 8-, 32- and 64-pixel boundaries of packed rows, words and blocks,
 * more rows than one sampling step, one-pixel-wide frames, tolerances
 * from 0 past the largest the word test takes.  The brute force is the
 * definition: for each mismatch, the smallest squared distance to a
 * reference pixel of the other colour, from per-column vertical
 * distances and a scan over every column.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "rayo.h"
#include "bitmap.h"
#include "tap.h"

static unsigned long next(unsigned long *seed)
{
    *seed = *seed * 6364136223846793005ul + 1442695040888963407ul;
    return *seed >> 33;
}

/* A few disks of random centres and radii, and a sprinkle of noise. */
static void blobs(rayo_image *m, unsigned long *seed)
{
    uint32_t w = m->info.width, h = m->info.height, x, y;
    int k, disks = 1 + (int)(next(seed) % 3);
    for (k = 0; k < disks; k++) {
        double cx = (double)(next(seed) % (w + 1));
        double cy = (double)(next(seed) % (h + 1));
        double r = 1 + (double)(next(seed) % (1 + (w > h ? w : h) / 3));
        for (y = 0; y < h; y++)
            for (x = 0; x < w; x++)
                if ((x - cx) * (x - cx) + (y - cy) * (y - cy) <= r * r)
                    bitmap_put(m, x, y, 1);
    }
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++)
            if (next(seed) % 1999 == 0)
                bitmap_put(m, x, y, !bitmap_get(m, x, y));
}

typedef struct brute {
    double max_distance;
    uint64_t beyond, mismatches;
} brute;

/* The definition, column by column: v[c][i] is the squared vertical
 * distance from (i, y) to colour c in column i (-1: none). */
static brute brute_force(const rayo_image *a, const rayo_image *b,
                         double tolerance)
{
    uint32_t w = a->info.width, h = a->info.height, x, y, i, j;
    int64_t *v = malloc(2 * (size_t)w * sizeof *v), worst = -1;
    brute r = {0, 0, 0};
    if (v == NULL)
        abort();
    for (y = 0; y < h; y++) {
        int c;
        for (c = 0; c < 2; c++)
            for (i = 0; i < w; i++) {
                int64_t best = -1;
                for (j = 0; j < h; j++)
                    if (bitmap_get(a, i, j) == c) {
                        int64_t d = (int64_t)j - y;
                        if (best < 0 || d * d < best)
                            best = d * d;
                    }
                v[(size_t)c * w + i] = best;
            }
        for (x = 0; x < w; x++) {
            int colour = bitmap_get(a, x, y);
            int64_t best = -1;
            if (colour == bitmap_get(b, x, y))
                continue;
            r.mismatches++;
            for (i = 0; i < w; i++) {
                int64_t vi = v[(size_t)!colour * w + i], dx = (int64_t)i - x;
                if (vi >= 0 && (best < 0 || dx * dx + vi < best))
                    best = dx * dx + vi;
            }
            if (best < 0 || (double)best > tolerance * tolerance)
                r.beyond++;
            if (best > worst)
                worst = best;
        }
    }
    free(v);
    r.max_distance = worst < 0 ? 0 : sqrt((double)worst);
    return r;
}

static void check(const char *what, const rayo_image *a, const rayo_image *b,
                  double tolerance)
{
    rayo_compare_options options;
    rayo_compare_report report;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    brute want = brute_force(a, b, tolerance);
    rayo_compare_options_init(&options);
    options.tolerance = tolerance;
    if (rayo_compare_images(a, b, &options, &report, &err) != RAYO_OK) {
        printf("# %s\n", err.message);
        abort();
    }
    is_int(report.mismatches, want.mismatches, "%s %ux%u, tolerance %g: mismatches", what,
           a->info.width, a->info.height, tolerance);
    if (report.max_distance != want.max_distance)
        printf("# got %.17g, want %.17g\n", report.max_distance, want.max_distance);
    ok(report.max_distance == want.max_distance,
       "%s: farthest mismatch %.6f, as brute force", what, want.max_distance);
    is_int(report.beyond_tolerance, want.beyond, "%s: %llu beyond the tolerance, as brute force",
           what, (unsigned long long)want.beyond);
}

static void flipped(const rayo_image *a, rayo_image *out)
{
    uint32_t x, y, h = a->info.height;
    for (y = 0; y < h; y++)
        for (x = 0; x < a->info.width; x++)
            bitmap_put(out, x, h - 1 - y, bitmap_get(a, x, y));
}

static void inverted(const rayo_image *a, rayo_image *out)
{
    uint32_t x, y;
    for (y = 0; y < a->info.height; y++)
        for (x = 0; x < a->info.width; x++)
            bitmap_put(out, x, y, !bitmap_get(a, x, y));
}

/* a with one pixel in `every` changed. */
static void touched(const rayo_image *a, rayo_image *out, unsigned every,
                    unsigned long *seed)
{
    uint32_t x, y;
    for (y = 0; y < a->info.height; y++)
        for (x = 0; x < a->info.width; x++)
            bitmap_put(out, x, y, next(seed) % every == 0 ? !bitmap_get(a, x, y)
                                                   : bitmap_get(a, x, y));
}

int main(void)
{
    static const uint32_t sizes[][2] = {
        {150, 140}, {65, 97}, {64, 64}, {129, 70}, {33, 200}, {1, 60},
        {60, 1},    {200, 33}};
    static const double tolerances[] = {0, 1.5, 2, 5, 8, 9.5};
    unsigned long seed = 2026;
    size_t s, k;
    for (s = 0; s < sizeof sizes / sizeof sizes[0]; s++) {
        uint32_t w = sizes[s][0], h = sizes[s][1];
        rayo_image a = bitmap_make(w, h), b = bitmap_make(w, h), c = bitmap_make(w, h);
        double tol = tolerances[s % (sizeof tolerances / sizeof tolerances[0])];
        blobs(&a, &seed);
        blobs(&c, &seed);
        flipped(&a, &b);
        check("flipped", &a, &b, tol);
        inverted(&a, &b);
        check("inverted", &a, &b, tol);
        check("unrelated", &a, &c, tol);
        touched(&a, &b, 50, &seed);
        check("touched", &a, &b, tol);
        rayo_image_free(&a);
        rayo_image_free(&b);
        rayo_image_free(&c);
    }
    /* One frame at every tolerance, over and under 8. */
    {
        rayo_image a = bitmap_make(150, 140), b = bitmap_make(150, 140);
        blobs(&a, &seed);
        touched(&a, &b, 9, &seed);
        for (k = 0; k < sizeof tolerances / sizeof tolerances[0]; k++)
            check("noisy", &a, &b, tolerances[k]);
        rayo_image_free(&a);
        rayo_image_free(&b);
    }
    return tap_done();
}
