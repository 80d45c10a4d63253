/*
 * measure.c - one pass over the reference's frame comparing it with the
 * image (as a transform lays it there): counts of agreement and
 * disagreement, and each mismatch's distance from the reference's
 * outline.
 *
 * Rows are packed bits, so agreement is counted a byte at a time with
 * XOR, AND and OR; distances are computed only for rows that have
 * mismatches, and only for the colour those mismatches need.  The
 * verdict and the diagnosis are not made here.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "compare_impl.h"

typedef struct measure_rows {
    unsigned char *img, *known, *diff, *tmp;
    int64_t *d2;
} measure_rows;

static rayo_status rows_alloc(measure_rows *r, uint32_t width, int distances,
                              rayo_error *err)
{
    size_t n = cmp_row_bytes(width);
    memset(r, 0, sizeof *r);
    r->img = malloc(4 * n);
    if (distances)
        r->d2 = malloc((size_t)width * sizeof *r->d2);
    if (r->img == NULL || (distances && r->d2 == NULL)) {
        free(r->img);
        free(r->d2);
        return rayo_error_set(err, RAYO_ERR_NOMEM,
                              "compare: out of memory for rows of %u pixels",
                              width);
    }
    r->known = r->img + n;
    r->diff = r->known + n;
    r->tmp = r->diff + n;
    return RAYO_OK;
}

/* Distances of the mismatches of one row whose reference colour is
 * `colour` (their bits set in diff). */
static void row_distances(cmp_outline *outline, uint32_t y, int colour,
                          const unsigned char *diff, uint32_t width,
                          double tolerance, int64_t *d2, cmp_counts *c)
{
    size_t n = cmp_row_bytes(width), k;
    double tol2 = tolerance * tolerance;
    cmp_outline_distances(outline, y, !colour, d2);
    for (k = 0; k < n; k++) {
        unsigned bit;
        if (diff[k] == 0)
            continue;
        for (bit = 0; bit < 8; bit++) {
            size_t x = k * 8 + bit;
            double d;
            if (!((diff[k] >> (7 - bit)) & 1u))
                continue;
            d = (double)d2[x];
            if (d > tol2)
                c->beyond++;
            if (d > c->max_distance * c->max_distance)
                c->max_distance = sqrt(d);
        }
    }
}

/* Tolerances up to this are checked by looking around each mismatch
 * (at most (2 * 8 + 1)^2 pixels) when the exact distance is not needed. */
#define LOCAL_TOLERANCE 8.0

/* Whether a reference pixel of colour `colour` lies within tolerance of
 * (x, y). */
static int near_colour(const cmp_mask *ref, uint32_t x, uint32_t y,
                       int colour, double tolerance)
{
    int64_t r = (int64_t)floor(tolerance), dx, dy;
    double t2 = tolerance * tolerance;
    for (dy = -r; dy <= r; dy++) {
        int64_t j = (int64_t)y + dy;
        const unsigned char *row;
        if (j < 0 || j >= ref->height)
            continue;
        row = cmp_mask_row(ref, (uint32_t)j);
        for (dx = -r; dx <= r; dx++) {
            int64_t i = (int64_t)x + dx;
            if (i < 0 || i >= ref->width || (double)(dx * dx + dy * dy) > t2)
                continue;
            if (rayo_bit_get(row, (uint32_t)i) == colour)
                return 1;
        }
    }
    return 0;
}

/* Counts the mismatches (bits of diff, reference colour `colour`) with
 * no pixel of the other colour within tolerance. */
static void row_beyond(const cmp_mask *ref, uint32_t y, int colour,
                       const unsigned char *diff, double tolerance,
                       cmp_counts *c)
{
    size_t n = cmp_row_bytes(ref->width), k;
    unsigned bit;
    for (k = 0; k < n; k++)
        if (diff[k] != 0)
            for (bit = 0; bit < 8; bit++)
                if (((diff[k] >> (7 - bit)) & 1u) &&
                    !near_colour(ref, (uint32_t)(k * 8 + bit), y, !colour,
                                 tolerance))
                    c->beyond++;
}

static void row_mismatch_distances(const cmp_mask *ref, uint32_t y,
                                   int colour, const unsigned char *diff,
                                   cmp_outline *outline, int exact,
                                   double tolerance, int64_t *d2,
                                   cmp_counts *c)
{
    if (!exact && tolerance <= LOCAL_TOLERANCE)
        row_beyond(ref, y, colour, diff, tolerance, c);
    else
        row_distances(outline, y, colour, diff, ref->width, tolerance, d2,
                      c);
}

static void measure_row(const cmp_mask *ref, uint32_t y, measure_rows *r,
                        int all_known, cmp_outline *outline, int exact,
                        double tolerance, cmp_counts *c)
{
    const unsigned char *a = cmp_mask_row(ref, y);
    size_t n = cmp_row_bytes(ref->width), k;
    uint64_t ref_only, img_only;
    for (k = 0; k < n; k++) {
        unsigned m = all_known ? 0xFFu : r->known[k];
        unsigned ra = a[k] & m, ib = r->img[k] & m;
        if (k == n - 1)
            ra &= (unsigned)(0xFFu << ((8 - (ref->width & 7u)) & 7u));
        r->diff[k] = (unsigned char)(ra & ~ib);        /* reference only */
        r->tmp[k] = (unsigned char)(ib & ~ra);         /* image only */
        r->known[k] = (unsigned char)(ra & ib);        /* both, reused */
        r->img[k] = (unsigned char)(ra | ib);          /* either, reused */
    }
    ref_only = cmp_popcount(r->diff, n);
    img_only = cmp_popcount(r->tmp, n);
    c->reference_only += ref_only;
    c->image_only += img_only;
    c->both += cmp_popcount(r->known, n);
    c->either += cmp_popcount(r->img, n);
    if (outline == NULL)
        return;
    if (ref_only)
        row_mismatch_distances(ref, y, 1, r->diff, outline, exact, tolerance,
                               r->d2, c);
    if (img_only)
        row_mismatch_distances(ref, y, 0, r->tmp, outline, exact, tolerance,
                               r->d2, c);
}

rayo_status cmp_measure(const cmp_mask *ref, const cmp_mask *image,
                        const cmp_transform *t, cmp_outline *outline,
                        int exact, double tolerance, cmp_counts *counts,
                        rayo_error *err)
{
    measure_rows r;
    uint32_t y;
    rayo_status s = rows_alloc(&r, ref->width, outline != NULL, err);
    memset(counts, 0, sizeof *counts);
    counts->max_distance = outline != NULL ? 0 : -1;
    if (s != RAYO_OK)
        return s;
    if (outline != NULL)
        cmp_outline_rewind(outline);
    for (y = 0; y < ref->height; y++) {
        int all = cmp_transform_row(t, image, ref->width, ref->height, y,
                                    r.img, r.known);
        if (all < 0)
            continue;
        counts->known += all ? ref->width
                             : cmp_popcount(r.known,
                                            cmp_row_bytes(ref->width));
        measure_row(ref, y, &r, all, outline, exact, tolerance, counts);
    }
    free(r.img);
    free(r.d2);
    return RAYO_OK;
}
