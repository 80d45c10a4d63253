/*
 * measure.c - one pass over the reference's frame comparing it with the
 * image (as a transform lays it there): counts of agreement and
 * disagreement, and each mismatch's distance from the reference's
 * outline.
 *
 * Rows are packed bits, so agreement is counted a byte at a time with
 * XOR, AND and OR; distances are computed only for rows that have
 * mismatches, and only for the colour those mismatches need.  Large
 * frames are cut into bands of rows measured by one thread each (one per
 * CPU), each with its own cursors on the outline; the counts are summed
 * afterwards, so the result does not depend on the number of threads.
 * The verdict and the diagnosis are not made here.
 */
#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "rayo/render.h"

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
    cmp_outline_mismatch_distances(outline, y, !colour, diff, d2);
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

/* One band of rows, measured by one thread. */
typedef struct band {
    const cmp_mask *ref, *image;
    const cmp_transform *t;
    cmp_outline *outline;  /* this band's own cursors, or NULL */
    int exact;
    double tolerance;
    uint32_t y0, y1;
    cmp_counts counts;
    rayo_status status;
    rayo_error err;
} band;

static void *measure_band(void *context)
{
    band *b = context;
    measure_rows r;
    uint32_t y, w = b->ref->width;
    memset(&b->counts, 0, sizeof b->counts);
    b->status = rows_alloc(&r, w, b->outline != NULL, &b->err);
    if (b->status != RAYO_OK)
        return NULL;
    if (b->outline != NULL)
        cmp_outline_rewind(b->outline, b->y0);
    for (y = b->y0; y < b->y1; y++) {
        int all = cmp_transform_row(b->t, b->image, w, b->ref->height, y,
                                    r.img, r.known);
        if (all < 0)
            continue;
        b->counts.known += all ? w : cmp_popcount(r.known, cmp_row_bytes(w));
        measure_row(b->ref, y, &r, all, b->outline, b->exact, b->tolerance,
                    &b->counts);
    }
    free(r.img);
    free(r.d2);
    return NULL;
}

static void merge(cmp_counts *into, const cmp_counts *c)
{
    into->known += c->known;
    into->reference_only += c->reference_only;
    into->image_only += c->image_only;
    into->both += c->both;
    into->either += c->either;
    into->beyond += c->beyond;
    if (c->max_distance > into->max_distance)
        into->max_distance = c->max_distance;
}

/* Threads for a frame: one per CPU, at most MAX_BANDS, and none for
 * fewer than BAND_MIN_PIXELS each (small images are not worth it). */
#define MAX_BANDS 8u
#define BAND_MIN_PIXELS (1u << 20)

static unsigned band_count(const cmp_mask *ref)
{
    uint64_t pixels = (uint64_t)ref->width * ref->height;
    unsigned n = rayo_cpu_count();
    if (n > MAX_BANDS)
        n = MAX_BANDS;
    if (pixels / BAND_MIN_PIXELS < n)
        n = (unsigned)(pixels / BAND_MIN_PIXELS);
    if (n > ref->height)
        n = ref->height;
    return n ? n : 1;
}

/* Runs bands 1..n-1 on threads of their own and band 0 here; a band
 * whose thread cannot start runs here too. */
static void run_bands(band *bands, unsigned n)
{
    pthread_t threads[MAX_BANDS];
    int started[MAX_BANDS];
    unsigned i;
    for (i = 1; i < n; i++)
        started[i] = pthread_create(&threads[i], NULL, measure_band,
                                    &bands[i]) == 0;
    measure_band(&bands[0]);
    for (i = 1; i < n; i++) {
        if (started[i])
            pthread_join(threads[i], NULL);
        else
            measure_band(&bands[i]);
    }
}

rayo_status cmp_measure(const cmp_mask *ref, const cmp_mask *image,
                        const cmp_transform *t, cmp_outline *outline,
                        int exact, double tolerance, cmp_counts *counts,
                        rayo_error *err)
{
    band bands[MAX_BANDS];
    unsigned n = band_count(ref), i;
    rayo_status s = RAYO_OK;
    memset(counts, 0, sizeof *counts);
    memset(bands, 0, sizeof bands);
    for (i = 0; i < n; i++) {
        bands[i].ref = ref;
        bands[i].image = image;
        bands[i].t = t;
        bands[i].exact = exact;
        bands[i].tolerance = tolerance;
        bands[i].y0 = (uint32_t)((uint64_t)ref->height * i / n);
        bands[i].y1 = (uint32_t)((uint64_t)ref->height * (i + 1) / n);
        if (outline != NULL && s == RAYO_OK)
            s = i == 0 ? RAYO_OK
                       : cmp_outline_fork(outline, &bands[i].outline, err);
    }
    if (outline != NULL)
        bands[0].outline = outline;
    if (s == RAYO_OK)
        run_bands(bands, n);
    for (i = 0; i < n; i++) {
        if (s == RAYO_OK && bands[i].status != RAYO_OK) {
            s = bands[i].status;
            if (err != NULL)
                *err = bands[i].err;
        }
        merge(counts, &bands[i].counts);
        if (i > 0)
            cmp_outline_free(bands[i].outline);
    }
    counts->max_distance = outline != NULL ? counts->max_distance : -1;
    return s;
}
