/*
 * measure.c - one pass over the reference's frame comparing it with the
 * image (as a transform lays it there): counts of agreement and
 * disagreement, and each mismatch's distance from the reference's
 * outline.
 *
 * Rows are packed bits, so agreement is counted a byte at a time; exact
 * distances are computed only where they are needed (below).  Large
 * frames are cut into bands of rows measured by one thread each, whose
 * counts are summed afterwards, so the result does not depend on the
 * number of threads.  The verdict and the diagnosis are not made here.
 */
#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "rayo/render.h"

#include "../compare_impl.h"

/*
 * Agreement is counted with XOR, AND and OR; distances are computed only
 * for rows that have mismatches, and only for the colour those mismatches
 * need.  With the usual small tolerances no mismatch needs its own
 * distance to be counted near or far (near.c tests whole words of a row
 * at once), and only those that could be the farthest get an exact
 * distance (farthest.c); larger tolerances take every mismatch's exact
 * distance from the outline (outline.c).  Each band (one per CPU) has its
 * own cursors on the outline; the largest distance is the largest of the
 * bands'.
 */

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

/* What a band of rows measures distances with: near and farthest for
 * small tolerances (far mismatches counted with whole words, exact
 * distances only where they could be the largest), the outline's exact
 * distances of every mismatch otherwise. */
typedef struct band_tools {
    cmp_outline *outline;  /* NULL: counts only */
    cmp_near *near;        /* NULL: every mismatch's exact distance */
    cmp_farthest *farthest; /* with near, when the maximum is asked for */
    int has_edges;         /* 0: a reference of one colour, every
                              mismatch infinitely far */
    int exact;
    double tolerance;
} band_tools;

static void row_mismatch_distances(band_tools *t, uint32_t y, int colour,
                                   const unsigned char *diff,
                                   uint32_t width, int64_t *d2,
                                   cmp_counts *c)
{
    if (t->near == NULL) {
        row_distances(t->outline, y, colour, diff, width, t->tolerance, d2,
                      c);
        return;
    }
    c->beyond += cmp_near_count_far(t->near, y, !colour, diff);
    if (t->farthest != NULL)
        cmp_farthest_row(t->farthest, y, colour, diff);
}

/* Row y's mismatches: black only in the reference into diff, black
 * only in the image into tmp, their numbers into *ref_only and
 * *img_only; with c, the counts (black in both, in either) added there.
 * Eight bytes at a time, counted as they are made (bits are bits in any
 * byte order); the last byte, which may hold padding, on its own. */
static void split_row(const cmp_mask *ref, uint32_t y, measure_rows *r,
                      int all_known, uint64_t *ref_only, uint64_t *img_only,
                      cmp_counts *c)
{
    const unsigned char *a = cmp_mask_row(ref, y);
    size_t n = cmp_row_bytes(ref->width), k = 0;
    uint64_t ro = 0, io = 0, both = 0, ra, ib, m, d, t;
    for (; k + 8 < n; k += 8) {
        memcpy(&ra, a + k, 8);
        memcpy(&ib, r->img + k, 8);
        if (!all_known) {
            memcpy(&m, r->known + k, 8);
            ra &= m;
            ib &= m;
        }
        d = ra & ~ib;
        t = ib & ~ra;
        memcpy(r->diff + k, &d, 8);
        memcpy(r->tmp + k, &t, 8);
        if ((ra | ib) == 0)
            continue;
        ro += cmp_popcount64(d);
        io += cmp_popcount64(t);
        both += cmp_popcount64(ra & ib);
    }
    for (; k < n; k++) {
        unsigned mk = all_known ? 0xFFu : r->known[k];
        unsigned rk = a[k] & mk, ik = r->img[k] & mk;
        if (k == n - 1)
            rk &= (unsigned)(0xFFu << ((8 - (ref->width & 7u)) & 7u));
        r->diff[k] = (unsigned char)(rk & ~ik);
        r->tmp[k] = (unsigned char)(ik & ~rk);
        ro += cmp_popcount64(r->diff[k]);
        io += cmp_popcount64(r->tmp[k]);
        both += cmp_popcount64(rk & ik);
    }
    *ref_only = ro;
    *img_only = io;
    if (c == NULL)
        return;
    c->reference_only += ro;
    c->image_only += io;
    c->both += both;
    c->either += ro + io + both;
}

static void measure_row(const cmp_mask *ref, uint32_t y, measure_rows *r,
                        int all_known, band_tools *t, cmp_counts *c)
{
    uint64_t ref_only, img_only;
    split_row(ref, y, r, all_known, &ref_only, &img_only, c);
    if (t->outline == NULL)
        return;
    if (!t->has_edges) { /* no distance to find: every one is beyond */
        c->beyond += ref_only + img_only;
        return;
    }
    if (ref_only)
        row_mismatch_distances(t, y, 1, r->diff, ref->width, r->d2, c);
    if (img_only)
        row_mismatch_distances(t, y, 0, r->tmp, ref->width, r->d2, c);
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

/* The near test and the farthest search, where they apply. */
static rayo_status tools_make(band *b, band_tools *t)
{
    rayo_status s;
    memset(t, 0, sizeof *t);
    t->outline = b->outline;
    t->exact = b->exact;
    t->tolerance = b->tolerance;
    t->has_edges = b->outline != NULL && cmp_outline_has_edges(b->outline);
    if (!t->has_edges || b->tolerance > CMP_NEAR_MAX_TOLERANCE)
        return RAYO_OK;
    s = cmp_near_create(&t->near, b->ref, b->tolerance, &b->err);
    if (s == RAYO_OK && b->exact)
        s = cmp_farthest_create(&t->farthest, b->outline, b->ref->width,
                                b->y0, b->y1, &b->err);
    return s;
}

static void tools_free(band_tools *t)
{
    cmp_near_free(t->near);
    cmp_farthest_free(t->farthest);
}

/* Gives the farthest search its sampled rows (the outline is left
 * rewound to the band's first row). */
static void sample_rows(band *b, band_tools *t, measure_rows *r)
{
    uint32_t i, w = b->ref->width;
    uint64_t ref_only, img_only;
    for (i = 0; i < cmp_farthest_samples(t->farthest); i++) {
        uint32_t y = cmp_farthest_sample_row(t->farthest, i);
        int all = cmp_transform_row(b->t, b->image, w, b->ref->height, y,
                                    r->img, r->known);
        if (all < 0) {
            cmp_farthest_sample(t->farthest, i, NULL, NULL);
            continue;
        }
        split_row(b->ref, y, r, all, &ref_only, &img_only, NULL);
        cmp_farthest_sample(t->farthest, i, ref_only ? r->diff : NULL,
                            img_only ? r->tmp : NULL);
    }
    cmp_outline_rewind(b->outline, b->y0);
}

static void measure_rows_of(band *b, band_tools *t, measure_rows *r)
{
    uint32_t y, w = b->ref->width;
    int64_t best;
    if (b->outline != NULL)
        cmp_outline_rewind(b->outline, b->y0);
    if (t->farthest != NULL)
        sample_rows(b, t, r);
    for (y = b->y0; y < b->y1; y++) {
        int all = cmp_transform_row(b->t, b->image, w, b->ref->height, y,
                                    r->img, r->known);
        if (all < 0)
            continue;
        b->counts.known += all ? w : cmp_popcount(r->known, cmp_row_bytes(w));
        measure_row(b->ref, y, r, all, t, &b->counts);
    }
    if (t->farthest != NULL && (best = cmp_farthest_best(t->farthest)) > 0)
        b->counts.max_distance = sqrt((double)best);
}

static void *measure_band(void *context)
{
    band *b = context;
    band_tools t;
    measure_rows r;
    memset(&b->counts, 0, sizeof b->counts);
    b->status = rows_alloc(&r, b->ref->width, b->outline != NULL, &b->err);
    if (b->status != RAYO_OK)
        return NULL;
    b->status = tools_make(b, &t);
    if (b->status == RAYO_OK)
        measure_rows_of(b, &t, &r);
    tools_free(&t);
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
        rayo_error_init(&bands[i].err, rayo_error_lang(err));
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
