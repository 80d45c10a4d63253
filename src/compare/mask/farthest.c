/*
 * farthest.c - the largest distance of a mismatch from the reference's
 * outline, without the exact distance of every mismatch.
 *
 * Only the maximum is reported (near.c counts the mismatches beyond the
 * tolerance), so a mismatch needs exact work only if it could beat the
 * largest distance found so far; distances to a set are 1-Lipschitz, so
 * rows sampled exactly bound the rows between them (below).  The result
 * is the exact maximum, bit for bit what computing every distance gives.
 * Integers throughout: squared distances, and bounds rounded up.  Not for
 * counting mismatches beyond a tolerance, nor for a reference with a
 * single colour (no outline: every distance is infinite).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../compare_impl.h"

/*
 * A pixel k rows from a row whose distances are known is at most k
 * farther than the pixel of that row in its column.  So a band of rows is
 * first sampled: every SAMPLE_STEP-th row (and the band's last) gets the
 * exact distance of every pixel to each colour (outline.c), kept only as
 * the largest distance in each block of BLOCK_BYTES * 8 columns, rounded
 * up to whole pixels; the mismatches of the sampled rows seed the maximum.
 * Then, for every other row, a block of mismatches is bounded by the
 * samples above and below (largest distance in the block's columns plus
 * the rows between) and handed to outline.c for exact distances only when
 * that bound exceeds the maximum so far.  Images wrong everywhere
 * (flipped, inverted) then cost a few hundred exact rows instead of
 * thousands; every skipped mismatch is provably no farther than one
 * already found.
 */

/* Rows between samples: fewer samples cost fewer full rows, but leave
 * looser bounds and more rows to compute exactly.  Instruction counts
 * (callgrind) of 4096x4096 pairs, flipped, inverted, moved and flipped
 * with another field of view, were lowest near 96 of 16 to 256. */
#define SAMPLE_STEP 96u
/* Columns of a bound block, in bytes of a packed row. */
#define BLOCK_BYTES 4u

struct cmp_farthest {
    cmp_outline *outline;  /* borrowed: this band's reader */
    uint32_t width, y0, y1, samples;
    size_t blocks;
    uint32_t *bound;       /* [sample][colour][block]: a whole number of
                              pixels at least the block's largest
                              distance to that colour */
    int64_t best;          /* largest squared distance found, -1 none */
    unsigned char *keep;   /* the mismatches that need exact work */
    int64_t *d2;           /* one row of squared distances */
};

static rayo_status out_of_memory(uint32_t width, rayo_error *err)
{
    return rayo_error_set(err, RAYO_ERR_NOMEM,
                          "compare: out of memory for the distance bounds "
                          "of rows of %u pixels",
                          width);
}

/* Whether a * b fits a size_t (a, b > 0). */
static int product_fits(size_t a, size_t b)
{
    return a <= SIZE_MAX / b;
}

rayo_status cmp_farthest_create(cmp_farthest **farthest,
                                cmp_outline *outline, uint32_t width,
                                uint32_t y0, uint32_t y1, rayo_error *err)
{
    uint32_t rows = y1 - y0 - 1;
    size_t blocks = (cmp_row_bytes(width) + BLOCK_BYTES - 1) / BLOCK_BYTES;
    size_t entries;
    cmp_farthest *f;
    *farthest = NULL;
    f = calloc(1, sizeof *f);
    if (f == NULL)
        return out_of_memory(width, err);
    f->outline = outline;
    f->width = width;
    f->y0 = y0;
    f->y1 = y1;
    f->samples = rows / SAMPLE_STEP + 1 + (rows % SAMPLE_STEP != 0);
    f->blocks = blocks;
    f->best = -1;
    entries = 2 * blocks * f->samples;
    if (!product_fits(2 * blocks, f->samples) ||
        !product_fits(entries, sizeof *f->bound) ||
        !product_fits(width, sizeof *f->d2) ||
        (f->bound = malloc(entries * sizeof *f->bound)) == NULL ||
        (f->keep = malloc(cmp_row_bytes(width))) == NULL ||
        (f->d2 = malloc((size_t)width * sizeof *f->d2)) == NULL) {
        cmp_farthest_free(f);
        return out_of_memory(width, err);
    }
    *farthest = f;
    return RAYO_OK;
}

void cmp_farthest_free(cmp_farthest *f)
{
    if (f == NULL)
        return;
    free(f->bound);
    free(f->keep);
    free(f->d2);
    free(f);
}

uint32_t cmp_farthest_samples(const cmp_farthest *f)
{
    return f->samples;
}

uint32_t cmp_farthest_sample_row(const cmp_farthest *f, uint32_t i)
{
    uint64_t y = f->y0 + (uint64_t)i * SAMPLE_STEP;
    return y < f->y1 ? (uint32_t)y : f->y1 - 1;
}

int64_t cmp_farthest_best(const cmp_farthest *f)
{
    return f->best;
}

/* The smallest whole number whose square is at least v (v >= 0). */
static uint32_t ceil_sqrt(int64_t v)
{
    uint64_t r = (uint64_t)sqrt((double)v);
    while (r > 0 && (int64_t)(r * r) >= v)
        r--;
    while ((int64_t)(r * r) < v)
        r++;
    return (uint32_t)r;
}

static uint32_t *bounds_of(const cmp_farthest *f, uint32_t sample,
                           int colour)
{
    return f->bound + ((size_t)sample * 2 + (size_t)colour) * f->blocks;
}

/* best = the largest d2 over the bits of diff (NULL: none). */
static void raise_best(cmp_farthest *f, const unsigned char *diff)
{
    size_t n = cmp_row_bytes(f->width), k;
    unsigned bit;
    if (diff == NULL)
        return;
    for (k = 0; k < n; k++)
        if (diff[k] != 0)
            for (bit = 0; bit < 8; bit++)
                if (((diff[k] >> (7 - bit)) & 1u) &&
                    f->d2[k * 8 + bit] > f->best)
                    f->best = f->d2[k * 8 + bit];
}

void cmp_farthest_sample(cmp_farthest *f, uint32_t i,
                         const unsigned char *reference_only,
                         const unsigned char *image_only)
{
    uint32_t y = cmp_farthest_sample_row(f, i), x;
    int colour;
    for (colour = 0; colour < 2; colour++) {
        uint32_t *bound = bounds_of(f, i, colour);
        size_t b;
        cmp_outline_row_distances(f->outline, y, colour, f->d2);
        for (b = 0; b < f->blocks; b++) {
            int64_t top = 0;
            uint32_t end = (uint32_t)((b + 1) * BLOCK_BYTES * 8);
            for (x = (uint32_t)(b * BLOCK_BYTES * 8);
                 x < end && x < f->width; x++)
                if (f->d2[x] > top)
                    top = f->d2[x];
            bound[b] = ceil_sqrt(top);
        }
        /* black mismatches are measured to white, white ones to black */
        raise_best(f, colour == 0 ? reference_only : image_only);
    }
}

/* Whether some pixel of block b, row y, could be farther than best from
 * `colour` (bounded through the samples a and b around it). */
static int may_beat(const cmp_farthest *f, uint32_t y, int colour,
                    uint32_t above, uint32_t below, size_t b)
{
    uint64_t up = bounds_of(f, above, colour)[b] +
                  (uint64_t)(y - cmp_farthest_sample_row(f, above));
    uint64_t down = bounds_of(f, below, colour)[b] +
                    (uint64_t)(cmp_farthest_sample_row(f, below) - y);
    uint64_t bound = up < down ? up : down;
    return f->best < 0 || bound * bound > (uint64_t)f->best;
}

void cmp_farthest_row(cmp_farthest *f, uint32_t y, int reference_colour,
                      const unsigned char *diff)
{
    size_t n = cmp_row_bytes(f->width), b, k;
    uint32_t above = (y - f->y0) / SAMPLE_STEP, below = above + 1;
    int colour = !reference_colour, any = 0;
    if (cmp_farthest_sample_row(f, above) == y)
        return; /* a sample: done exactly already */
    for (b = 0; b < f->blocks; b++) {
        size_t lo = b * BLOCK_BYTES, hi = lo + BLOCK_BYTES < n
                                              ? lo + BLOCK_BYTES
                                              : n;
        int some = 0;
        for (k = lo; k < hi; k++)
            some |= diff[k] != 0;
        if (some && may_beat(f, y, colour, above, below, b)) {
            memcpy(f->keep + lo, diff + lo, hi - lo);
            any = 1;
        } else {
            memset(f->keep + lo, 0, hi - lo);
        }
    }
    if (!any)
        return;
    cmp_outline_mismatch_distances(f->outline, y, colour, f->keep, f->d2);
    raise_best(f, f->keep);
}
