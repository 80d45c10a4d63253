/*
 * tone_measure.c - one pass of a tone comparison: the reference's frame
 * walked pixel by pixel, the image read through a candidate mistake
 * undone (tone_undo.c), each channel's difference counted, and each
 * differing pixel asked whether the reference explains it
 * (tone_explain.c).
 *
 * Only differing pixels are looked at twice, so a pass costs about one
 * read of each image.  The passes that only count (the searches) take
 * whole rows at once, and a scale's reads are worked out once a column
 * and once a row; their sums are those of the pixel-by-pixel pass.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "tone_impl.h"

/* Where undo_scaled reads along one axis: for each reference column
   (or row) the image's pixel before it, the one after and the weight of
   the one after; at < 0 outside the image.  The same arithmetic as
   undo_scaled's, done once a column and once a row instead of once a
   pixel. */
typedef struct scale_axis {
    int64_t at, next;
    double weight, rest; /* rest: 1 - weight */
} scale_axis;

static void scale_axis_make(scale_axis *a, uint32_t n, uint32_t ref_n,
                            uint32_t image_n, double s)
{
    uint32_t i;
    for (i = 0; i < n; i++) {
        double f = s * ((double)i - ref_n / 2) + image_n / 2;
        double f0 = floor(f);
        int64_t k = (int64_t)f0;
        a[i].weight = f - f0;
        a[i].rest = 1 - a[i].weight;
        a[i].at = k < 0 || k >= image_n ? -1 : k;
        a[i].next = k + 1 < image_n ? k + 1 : k;
    }
}

static inline int undo_scaled_at(const tone_image *image,
                                 const scale_axis *ax, const scale_axis *ay,
                                 unsigned n, unsigned char *u)
{
    double wx = ax->weight, wy = ay->weight, rx = ax->rest, ry = ay->rest;
    const unsigned char *pa, *pb, *pd, *pe;
    unsigned c;
    if (ax->at < 0 || ay->at < 0)
        return 0;
    pa = tone_pixel(image, (uint32_t)ax->at, (uint32_t)ay->at);
    pb = tone_pixel(image, (uint32_t)ax->next, (uint32_t)ay->at);
    pd = tone_pixel(image, (uint32_t)ax->at, (uint32_t)ay->next);
    pe = tone_pixel(image, (uint32_t)ax->next, (uint32_t)ay->next);
    for (c = 0; c < n; c++) {
        double a = pa[c], b = pb[c], d = pd[c], e = pe[c];
        double v = (a * rx + b * wx) * ry + (d * rx + e * wx) * wy;
        /* v >= 0: truncating is floor, without a call for it */
        u[c] = (unsigned char)(v + 0.5);
    }
    return 1;
}

/* count_only's sums, kept in locals while a row is walked. */
typedef struct tone_sums {
    uint64_t squares[3], beyond[3], placed, known, differing;
    unsigned most[3];
} tone_sums;

/* One channel's difference between image sample p and reference
   sample r, added to the sums; returns it. */
static inline unsigned add_difference(tone_sums *a, unsigned c, unsigned p,
                                      unsigned r, unsigned levels)
{
    unsigned d = p > r ? p - r : r - p;
    a->squares[c] += (uint64_t)d * d;
    if (d > a->most[c])
        a->most[c] = d;
    a->beyond[c] += d > levels;
    return d;
}

/* The sampled reference pixels x = x0, x0 + step, ... < x1 of row r
   against image pixels p (one a step apart; NULL: black), n channels. */
static void sum_span(tone_sums *a, const unsigned char *r,
                     const unsigned char *p, uint32_t x0, uint32_t x1,
                     uint32_t step, unsigned n, unsigned levels)
{
    static const unsigned char black[3] = {0, 0, 0};
    size_t at = (size_t)step * n, dp = p != NULL ? at : 0;
    uint32_t x;
    uint64_t differing = 0;
    if (x0 >= x1)
        return;
    r += (size_t)x0 * n;
    if (p == NULL)
        p = black;
    if (n == 1) {
        for (x = x0; x < x1; x += step, r += at, p += dp)
            differing += add_difference(a, 0, p[0], r[0], levels) > levels;
    } else {
        for (x = x0; x < x1; x += step, r += at, p += dp) {
            unsigned d0 = add_difference(a, 0, p[0], r[0], levels);
            unsigned d1 = add_difference(a, 1, p[1], r[1], levels);
            unsigned d2 = add_difference(a, 2, p[2], r[2], levels);
            unsigned worst = d0 > d1 ? d0 : d1;
            differing += (worst > d2 ? worst : d2) > levels;
        }
    }
    a->differing += differing;
}

/* The sampled pixels of reference row r against the image scaled (row
   axis ay, column axes xs): undo_scaled_at's values, its arithmetic
   the same, with the image's two rows found once.  Where the four
   pixels read are equal that value is the result (the weights add up
   to 1 within a few units of the last place, far from changing the
   rounding to a whole level), and no arithmetic is done. */
static void sum_scaled_row(tone_sums *a, const unsigned char *r,
                           const tone_image *image, const scale_axis *ay,
                           const scale_axis *xs, uint32_t w, uint32_t step,
                           unsigned n, unsigned levels)
{
    size_t row = (size_t)image->width * n;
    const unsigned char *at = image->v + (size_t)ay->at * row;
    const unsigned char *next = image->v + (size_t)ay->next * row;
    double wy = ay->weight, ry = ay->rest;
    uint32_t x;
    unsigned c;
    for (x = 0; x < w; x += step) {
        const scale_axis *ax = &xs[x];
        const unsigned char *pa, *pb, *pd, *pe, *q = r + (size_t)x * n;
        unsigned worst = 0, d;
        if (ax->at < 0)
            continue;
        pa = at + (size_t)ax->at * n;
        pb = at + (size_t)ax->next * n;
        pd = next + (size_t)ax->at * n;
        pe = next + (size_t)ax->next * n;
        a->placed++;
        for (c = 0; c < n; c++) {
            unsigned u;
            if (pa[c] == pb[c] && pa[c] == pd[c] && pa[c] == pe[c]) {
                u = pa[c];
            } else {
                double va = pa[c], vb = pb[c], vd = pd[c], ve = pe[c];
                double v = (va * ax->rest + vb * ax->weight) * ry +
                           (vd * ax->rest + ve * ax->weight) * wy;
                u = (unsigned char)(v + 0.5);
            }
            d = add_difference(a, c, u, q[c], levels);
            if (d > worst)
                worst = d;
        }
        a->differing += worst > levels;
    }
}

/* Whether a capped pass (t->capped) is past its caps: more pixels
   differing than max_differing or a larger sum of squares than
   max_squares (both only grow as the pass goes on). */
static int past_caps(const tone_xform *t, const tone_sums *a)
{
    return t->capped &&
           (a->differing > t->max_differing ||
            a->squares[0] + a->squares[1] + a->squares[2] > t->max_squares);
}

/* tone_measure with classify -1 for the transforms that only move the
   image (the identity, a shift, a scale: xs and ys its axes): the same
   counts (sums and extremes, which do not depend on the order pixels
   are added in), a row at a time, the image read in place without
   undo.  A capped pass stops, k->stopped, past its caps (past_caps). */
static void count_only(const tone_image *ref, const tone_image *image,
                       const tone_xform *t, const scale_axis *xs,
                       const scale_axis *ys, uint32_t step, unsigned levels,
                       tone_counts *k)
{
    int64_t ox = (int64_t)(image->width / 2) - (int64_t)(ref->width / 2);
    int64_t oy = (int64_t)(image->height / 2) - (int64_t)(ref->height / 2);
    int64_t dx = t->kind == TONE_SHIFT ? t->dx : 0;
    int64_t dy = t->kind == TONE_SHIFT ? t->dy : 0;
    unsigned n = ref->channels, c;
    /* Squares of whole levels add up exactly in a double as in an
       integer (below 2^53), so this sum is the double one bit for bit. */
    tone_sums a;
    uint32_t y, w = ref->width;
    /* The sampled columns whose image pixel lies inside the image:
       x0 <= x < x1 (the others black for a shift, left out else). */
    int64_t lo = -(dx + ox), hi = (int64_t)image->width - (dx + ox);
    uint32_t x0, x1, inside = 0;
    memset(&a, 0, sizeof a);
    if (xs == NULL) {
        lo = lo < 0 ? 0 : lo;
        hi = hi > (int64_t)w ? (int64_t)w : hi;
        /* the first sampled column at or after lo, and after hi */
        if (hi < lo)
            hi = lo;
        x0 = (uint32_t)((lo + step - 1) / step * step);
        x1 = (uint32_t)((hi + step - 1) / step * step);
        x0 = x0 < w ? x0 : w;
        x1 = x1 < w ? x1 : w;
        inside = (x1 - x0 + step - 1) / step;
    } else {
        x0 = x1 = 0;
    }
    for (y = 0; y < ref->height; y += step) {
        const unsigned char *r = tone_pixel(ref, 0, y);
        if (xs != NULL) {
            if (ys[y].at >= 0)
                sum_scaled_row(&a, r, image, &ys[y], xs, w, step, n, levels);
        } else {
            int64_t iy = (int64_t)y + dy + oy;
            int row_in = iy >= 0 && iy < image->height;
            if (row_in) {
                const unsigned char *p =
                    x1 > x0 ? tone_pixel(image,
                                         (uint32_t)((int64_t)x0 + dx + ox),
                                         (uint32_t)iy)
                            : NULL;
                if (x1 > x0)
                    sum_span(&a, r, p, x0, x1, step, n, levels);
                a.placed += inside;
                if (t->kind == TONE_SHIFT) {
                    sum_span(&a, r, NULL, 0, x0, step, n, levels);
                    sum_span(&a, r, NULL, x1, w, step, n, levels);
                }
            } else if (t->kind == TONE_SHIFT) {
                sum_span(&a, r, NULL, 0, w, step, n, levels);
            }
        }
        if (past_caps(t, &a)) {
            k->stopped = 1;
            break;
        }
    }
    if (xs != NULL || t->kind != TONE_SHIFT)
        a.known = a.placed;
    else
        a.known = (uint64_t)((ref->width + step - 1) / step) *
                  ((ref->height + step - 1) / step);
    k->placed = a.placed;
    k->known = a.known;
    k->differing = a.differing;
    for (c = 0; c < n; c++) {
        k->sum_squares[c] = (double)a.squares[c];
        k->max_difference[c] = a.most[c];
        k->beyond[c] = a.beyond[c];
    }
}

void tone_measure(const tone_image *ref, const tone_image *image,
                  const tone_xform *t, double tolerance, unsigned levels,
                  int classify, tone_counts *k)
{
    uint32_t step = t->step > 0 ? t->step : 1, x, y;
    unsigned n = ref->channels, c;
    int radius = tone_radius(tolerance);
    scale_axis *xs = NULL, *ys = NULL;
    int in_place = t->kind == TONE_IDENTITY && ref->width == image->width &&
                   ref->height == image->height;
    memset(k, 0, sizeof *k);
    k->first_x = k->first_y = -1;
    if (t->kind == TONE_SCALE) {
        xs = malloc(ref->width * sizeof *xs);
        ys = malloc(ref->height * sizeof *ys);
        if (xs == NULL || ys == NULL) { /* then pixel by pixel */
            free(xs);
            free(ys);
            xs = ys = NULL;
        } else {
            scale_axis_make(xs, ref->width, ref->width, image->width,
                            t->scale);
            scale_axis_make(ys, ref->height, ref->height, image->height,
                            t->scale);
        }
    }
    if (classify < 0 && (xs != NULL || t->kind == TONE_SHIFT ||
                         t->kind == TONE_IDENTITY)) {
        count_only(ref, image, t, xs, ys, step, levels, k);
        free(xs);
        free(ys);
        return;
    }
    for (y = 0; y < ref->height; y += step)
        for (x = 0; x < ref->width; x += step) {
            const unsigned char *r = tone_pixel(ref, x, y);
            unsigned char u[3];
            unsigned worst = 0;
            if (in_place) {
                /* the identity on images of one size: undo's copy */
                memcpy(u, tone_pixel(image, x, y), n);
                k->placed++;
            } else if (xs != NULL
                           ? undo_scaled_at(image, &xs[x], &ys[y], n, u)
                           : tone_undo(ref, image, t, x, y, u)) {
                k->placed++;
            } else if (t->kind == TONE_SHIFT) {
                /* What a shift brings in from outside the image is black,
                   so moving what differs off the frame does not make it
                   agree.  (A scale's border is not known: a narrower
                   field of view shows less of the scene.) */
                memset(u, 0, sizeof u);
            } else {
                continue;
            }
            k->known++;
            for (c = 0; c < n; c++) {
                unsigned d = u[c] > r[c] ? u[c] - r[c] : r[c] - u[c];
                k->sum_squares[c] += (double)d * d;
                if (d > k->max_difference[c])
                    k->max_difference[c] = d;
                if (d > levels)
                    k->beyond[c]++;
                if (d > worst)
                    worst = d;
            }
            if (worst <= levels)
                continue;
            k->differing++;
            if (classify < 0)
                continue;
            if (tone_explained(ref, x, y, u, radius, levels)) {
                if (classify && tone_near_edge(ref, x, y, radius, levels)) {
                    k->at_edges++;
                    if (worst > k->max_edge_difference)
                        k->max_edge_difference = worst;
                } else {
                    k->in_shading++;
                }
            } else if (tone_near_edge(ref, x, y, radius, levels)) {
                k->at_edges++;
                if (worst > k->max_edge_difference)
                    k->max_edge_difference = worst;
            } else if (k->unexplained++ == 0) {
                k->first_x = (int32_t)x;
                k->first_y = (int32_t)y;
            }
            if (t->capped && (k->unexplained > t->max_unexplained ||
                              k->differing > t->max_differing)) {
                k->stopped = 1;
                free(xs);
                free(ys);
                return;
            }
        }
    free(xs);
    free(ys);
}
