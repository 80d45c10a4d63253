/*
 * tone_measure.c - one pass of a tone comparison: the reference's frame
 * walked pixel by pixel, the image read through a candidate mistake
 * undone (tone_xform), each channel's difference counted, and each
 * differing pixel asked whether the reference explains it.
 *
 * A difference is explained when an outline or a shadow edge of the
 * reference lies within the tolerance (a step between two neighbours
 * larger than the levels and than twice the steps beside it), or when,
 * channel by channel, the reference takes the image's value within the
 * tolerance (a square window), give or take the levels and one step of
 * its shading there.  That is what a picture drawn a pixel or two
 * differently produces (another focal distance, float instead of
 * double): outlines and shadow edges elsewhere, a gradient of shading a
 * little shifted; a missing shadow, a swapped channel or a wrong
 * formula do not.  Only differing pixels are looked at twice, so a pass
 * costs about one read of each image.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "tone_impl.h"

tone_xform tone_identity(void)
{
    tone_xform t;
    memset(&t, 0, sizeof t);
    t.kind = TONE_IDENTITY;
    t.scale = 1;
    t.perm[0] = 0;
    t.perm[1] = 1;
    t.perm[2] = 2;
    t.step = 1;
    t.max_squares = UINT64_MAX;
    return t;
}

static unsigned char clamp_level(int v)
{
    return (unsigned char)(v < 0 ? 0 : v > 255 ? 255 : v);
}

/* The image read at reference pixel (x, y) scaled by s about the
   optical centre, between pixels by bilinear interpolation (so the
   scale search sees gradients move smoothly); 0 outside the image. */
static int undo_scaled(const tone_image *ref, const tone_image *image,
                       double s, uint32_t x, uint32_t y, unsigned char *u)
{
    double fx = s * ((double)x - ref->width / 2) + image->width / 2;
    double fy = s * ((double)y - ref->height / 2) + image->height / 2;
    double x0 = floor(fx), y0 = floor(fy), ax = fx - x0, ay = fy - y0;
    int64_t ix = (int64_t)x0, iy = (int64_t)y0, jx, jy;
    unsigned c;
    if (ix < 0 || iy < 0 || ix >= image->width || iy >= image->height)
        return 0;
    jx = ix + 1 < image->width ? ix + 1 : ix;
    jy = iy + 1 < image->height ? iy + 1 : iy;
    for (c = 0; c < ref->channels; c++) {
        double a = tone_pixel(image, (uint32_t)ix, (uint32_t)iy)[c];
        double b = tone_pixel(image, (uint32_t)jx, (uint32_t)iy)[c];
        double d = tone_pixel(image, (uint32_t)ix, (uint32_t)jy)[c];
        double e = tone_pixel(image, (uint32_t)jx, (uint32_t)jy)[c];
        double v = (a * (1 - ax) + b * ax) * (1 - ay) +
                   (d * (1 - ax) + e * ax) * ay;
        u[c] = (unsigned char)floor(v + 0.5);
    }
    return 1;
}

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

/* The image's pixel for reference pixel (x, y), undone by t, into u;
   0 when it falls outside the image. */
static int undo(const tone_image *ref, const tone_image *image,
                const tone_xform *t, uint32_t x, uint32_t y,
                unsigned char *u)
{
    int64_t rx = x, ry = y, ix, iy;
    int64_t ox = (int64_t)(image->width / 2) - (int64_t)(ref->width / 2);
    int64_t oy = (int64_t)(image->height / 2) - (int64_t)(ref->height / 2);
    const unsigned char *p, *r = tone_pixel(ref, x, y);
    unsigned c, n = ref->channels;
    switch (t->kind) {
    case TONE_FLIP_V:
        ry = (int64_t)ref->height - 1 - ry;
        break;
    case TONE_FLIP_H:
        rx = (int64_t)ref->width - 1 - rx;
        break;
    case TONE_FLIP_BOTH:
        rx = (int64_t)ref->width - 1 - rx;
        ry = (int64_t)ref->height - 1 - ry;
        break;
    case TONE_SHIFT:
        rx += t->dx;
        ry += t->dy;
        break;
    case TONE_SCALE:
        return undo_scaled(ref, image, t->scale, x, y, u);
    default:
        break;
    }
    ix = rx + ox;
    iy = ry + oy;
    if (ix < 0 || iy < 0 || ix >= image->width || iy >= image->height)
        return 0;
    p = tone_pixel(image, (uint32_t)ix, (uint32_t)iy);
    for (c = 0; c < n; c++)
        u[c] = p[c];
    switch (t->kind) {
    case TONE_PERMUTE:
        for (c = 0; c < n; c++)
            u[t->perm[c]] = p[c];
        break;
    case TONE_INVERT:
        for (c = 0; c < n; c++)
            u[c] = (unsigned char)(255 - p[c]);
        break;
    case TONE_OFFSET_ON_SHAPES:
        if (n == 1 ? r[0] == 0 : (r[0] | r[1] | r[2]) == 0)
            break;
        /* fall through */
    case TONE_OFFSET:
        for (c = 0; c < n; c++) {
            int moved = (int)r[c] + t->offset[c];
            /* A value the offset pushed past 0 or 255 was clamped there:
               it agrees with any reference value that would be. */
            if ((p[c] == 255 && moved >= 255) || (p[c] == 0 && moved <= 0))
                u[c] = r[c];
            else
                u[c] = clamp_level((int)p[c] - t->offset[c]);
        }
        break;
    case TONE_WRAPPED:
        for (c = 0; c < n; c++)
            if (r[c] == 255 && p[c] < 128)
                u[c] = 255;
        break;
    default:
        break;
    }
    return 1;
}

/* The largest channel difference between two reference pixels. */
static unsigned step_between(const tone_image *ref, uint32_t x0, uint32_t y0,
                             uint32_t x1, uint32_t y1)
{
    const unsigned char *a = tone_pixel(ref, x0, y0);
    const unsigned char *b = tone_pixel(ref, x1, y1);
    unsigned c, best = 0;
    for (c = 0; c < ref->channels; c++) {
        unsigned d = a[c] > b[c] ? a[c] - b[c] : b[c] - a[c];
        if (d > best)
            best = d;
    }
    return best;
}

/* Whether the step from (x, y) by (ex, ey) stands out: more than the
   levels and more than twice the steps just before and after it. */
static int is_edge_step(const tone_image *ref, int64_t x, int64_t y,
                        int ex, int ey, unsigned levels)
{
    int64_t x1 = x + ex, y1 = y + ey, x0 = x - ex, y0 = y - ey;
    int64_t x2 = x1 + ex, y2 = y1 + ey;
    unsigned s1, s0 = 0, s2 = 0;
    if (x1 < 0 || y1 < 0 || x1 >= ref->width || y1 >= ref->height)
        return 0;
    s1 = step_between(ref, (uint32_t)x, (uint32_t)y, (uint32_t)x1,
                      (uint32_t)y1);
    if (s1 <= levels)
        return 0;
    if (x0 >= 0 && y0 >= 0 && x0 < ref->width && y0 < ref->height)
        s0 = step_between(ref, (uint32_t)x0, (uint32_t)y0, (uint32_t)x,
                          (uint32_t)y);
    if (x2 >= 0 && y2 >= 0 && x2 < ref->width && y2 < ref->height)
        s2 = step_between(ref, (uint32_t)x1, (uint32_t)y1, (uint32_t)x2,
                          (uint32_t)y2);
    return s1 > 2 * (s0 > s2 ? s0 : s2);
}

static int is_edge_pixel(const tone_image *ref, int64_t x, int64_t y,
                         unsigned levels)
{
    return is_edge_step(ref, x, y, 1, 0, levels) ||
           is_edge_step(ref, x, y, -1, 0, levels) ||
           is_edge_step(ref, x, y, 0, 1, levels) ||
           is_edge_step(ref, x, y, 0, -1, levels);
}

/* The largest step between neighbours of the reference, in the window
   of radius around (x, y), that is not an edge: how far the shading
   itself moves in a pixel there. */
static unsigned shading_step(const tone_image *ref, uint32_t x, uint32_t y,
                             int radius, unsigned levels)
{
    unsigned best = 0;
    int dx, dy;
    for (dy = -radius; dy <= radius; dy++)
        for (dx = -radius; dx <= radius; dx++) {
            int64_t xx = (int64_t)x + dx, yy = (int64_t)y + dy;
            if (xx < 0 || yy < 0 || xx + 1 >= ref->width ||
                yy + 1 >= ref->height)
                continue;
            if (!is_edge_step(ref, xx, yy, 1, 0, levels)) {
                unsigned s = step_between(ref, (uint32_t)xx, (uint32_t)yy,
                                          (uint32_t)xx + 1, (uint32_t)yy);
                if (s > best)
                    best = s;
            }
            if (!is_edge_step(ref, xx, yy, 0, 1, levels)) {
                unsigned s = step_between(ref, (uint32_t)xx, (uint32_t)yy,
                                          (uint32_t)xx, (uint32_t)yy + 1);
                if (s > best)
                    best = s;
            }
        }
    return best;
}

/* Whether the reference takes u's values within the window of radius
   around (x, y) (a square: the tolerance in x and in y), give or take
   the levels and one step of its shading there (a gradient continued
   one pixel further, as at a limb where the brightest pixel of one
   picture falls between the pixels of the other). */
static int explained(const tone_image *ref, uint32_t x, uint32_t y,
                     const unsigned char *u, int radius, unsigned levels)
{
    int lo[3] = {256, 256, 256}, hi[3] = {-1, -1, -1};
    unsigned c, n = ref->channels;
    int dx, dy, slack = -1, window = radius;
    if (ref->lo != NULL && ref->near_radius == radius) {
        size_t at = ((size_t)y * ref->width + x) * n;
        for (c = 0; c < n; c++) {
            lo[c] = ref->lo[at + c];
            hi[c] = ref->hi[at + c];
        }
        window = -1; /* the maps hold the window's range already */
    }
    for (dy = -window; dy <= window; dy++) {
        int64_t yy = (int64_t)y + dy;
        if (yy < 0 || yy >= ref->height)
            continue;
        for (dx = -window; dx <= window; dx++) {
            int64_t xx = (int64_t)x + dx;
            const unsigned char *q;
            if (xx < 0 || xx >= ref->width)
                continue;
            q = tone_pixel(ref, (uint32_t)xx, (uint32_t)yy);
            for (c = 0; c < n; c++) {
                if (q[c] < lo[c])
                    lo[c] = q[c];
                if (q[c] > hi[c])
                    hi[c] = q[c];
            }
        }
    }
    for (c = 0; c < n; c++) {
        if ((int)u[c] + (int)levels >= lo[c] &&
            (int)u[c] <= hi[c] + (int)levels)
            continue;
        if (slack < 0)
            slack = (int)levels +
                    (int)(ref->slope != NULL && ref->near_radius == radius &&
                                  ref->near_levels == levels
                              ? ref->slope[(size_t)y * ref->width + x]
                              : shading_step(ref, x, y, radius, levels));
        if ((int)u[c] + slack < lo[c] || (int)u[c] > hi[c] + slack)
            return 0;
    }
    return 1;
}

static int near_edge(const tone_image *ref, uint32_t x, uint32_t y,
                     int radius, unsigned levels)
{
    int dx, dy;
    if (ref->near != NULL && ref->near_radius == radius &&
        ref->near_levels == levels)
        return ref->near[(size_t)y * ref->width + x];
    for (dy = -radius; dy <= radius; dy++)
        for (dx = -radius; dx <= radius; dx++) {
            int64_t xx = (int64_t)x + dx, yy = (int64_t)y + dy;
            if (xx < 0 || yy < 0 || xx >= ref->width || yy >= ref->height)
                continue;
            if (is_edge_pixel(ref, xx, yy, levels))
                return 1;
        }
    return 0;
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
                           : undo(ref, image, t, x, y, u)) {
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
            if (explained(ref, x, y, u, radius, levels)) {
                if (classify && near_edge(ref, x, y, radius, levels)) {
                    k->at_edges++;
                    if (worst > k->max_edge_difference)
                        k->max_edge_difference = worst;
                } else {
                    k->in_shading++;
                }
            } else if (near_edge(ref, x, y, radius, levels)) {
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

/* A step stands out when it is more than the levels and more than twice
   the steps on either side of it (0 outside the frame). */
static int stands_out(unsigned step, unsigned before, unsigned after,
                      unsigned levels)
{
    return step > levels && step > 2 * (before > after ? before : after);
}

rayo_status tone_image_find_edges_kept(tone_image *t, double tolerance,
                                       unsigned levels, rayo_error *err)
{
    int radius = tone_radius(tolerance);
    rayo_status s;
    if (t->near != NULL && t->near_radius == radius &&
        t->near_levels == levels)
        return RAYO_OK;
    if (tone_cache_find_maps(t, radius, levels))
        return RAYO_OK;
    s = tone_image_find_edges(t, tolerance, levels, err);
    if (s == RAYO_OK)
        tone_cache_keep_maps(t);
    return s;
}

rayo_status tone_image_find_edges(tone_image *t, double tolerance,
                                  unsigned levels, rayo_error *err)
{
    size_t n = (size_t)t->width * t->height, i;
    int radius = tone_radius(tolerance);
    unsigned char *hs, *vs, *edge, *slope;
    uint32_t x, y, w = t->width, h = t->height;
    rayo_status s;
    if (t->near != NULL && t->near_radius == radius &&
        t->near_levels == levels)
        return RAYO_OK;
    tone_image_drop_maps(t);
    hs = malloc(n);
    vs = malloc(n);
    edge = malloc(n);
    slope = malloc(n);
    if (hs == NULL || vs == NULL || edge == NULL || slope == NULL) {
        free(hs);
        free(vs);
        free(edge);
        free(slope);
        return rayo_error_set(err, RAYO_ERR_NOMEM,
                              "compare: out of memory for the edges of a "
                              "%ux%u image",
                              w, h);
    }
    /* hs: the step to the right neighbour, vs: to the one below. */
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            i = (size_t)y * w + x;
            hs[i] = (unsigned char)(x + 1 < w
                                        ? step_between(t, x, y, x + 1, y)
                                        : 0);
            vs[i] = (unsigned char)(y + 1 < h
                                        ? step_between(t, x, y, x, y + 1)
                                        : 0);
        }
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            unsigned right, left, down, up, smooth = 0;
            i = (size_t)y * w + x;
            right = x + 1 < w && stands_out(hs[i], x > 0 ? hs[i - 1] : 0,
                                            x + 2 < w ? hs[i + 1] : 0,
                                            levels);
            left = x > 0 && stands_out(hs[i - 1], x > 1 ? hs[i - 2] : 0,
                                       hs[i], levels);
            down = y + 1 < h && stands_out(vs[i], y > 0 ? vs[i - w] : 0,
                                           y + 2 < h ? vs[i + w] : 0,
                                           levels);
            up = y > 0 && stands_out(vs[i - w], y > 1 ? vs[i - 2 * w] : 0,
                                     vs[i], levels);
            edge[i] = (unsigned char)(right || left || down || up);
            if (!right && hs[i] > smooth)
                smooth = hs[i];
            if (!down && vs[i] > smooth)
                smooth = vs[i];
            slope[i] = (unsigned char)smooth;
        }
    free(hs);
    free(vs);
    hs = vs = NULL;
    t->lo = malloc(n * t->channels);
    t->hi = malloc(n * t->channels);
    if (t->lo == NULL || t->hi == NULL) {
        free(edge);
        free(slope);
        free(t->lo);
        free(t->hi);
        t->lo = t->hi = NULL;
        return rayo_error_set(err, RAYO_ERR_NOMEM,
                              "compare: out of memory for the edges of a "
                              "%ux%u image",
                              w, h);
    }
    if ((s = tone_window_map(edge, edge, w, h, 1, radius, 1, err)) !=
            RAYO_OK ||
        (s = tone_window_map(slope, slope, w, h, 1, radius, 1, err)) !=
            RAYO_OK ||
        (s = tone_window_map(t->v, t->lo, w, h, t->channels, radius, 0,
                             err)) != RAYO_OK ||
        (s = tone_window_map(t->v, t->hi, w, h, t->channels, radius, 1,
                             err)) != RAYO_OK) {
        free(edge);
        free(slope);
        free(t->lo);
        free(t->hi);
        t->lo = t->hi = NULL;
        return s;
    }
    t->near = edge;
    t->slope = slope;
    t->near_radius = radius;
    t->near_levels = levels;
    return RAYO_OK;
}

uint64_t tone_band(const tone_image *ref)
{
    size_t n = (size_t)ref->width * ref->height, i;
    unsigned c, channels = ref->channels;
    uint64_t band = 0;
    if (ref->near == NULL || ref->lo == NULL || ref->hi == NULL)
        return n; /* no maps: anything may be explained anywhere */
    for (i = 0; i < n; i++) {
        int in = ref->near[i] != 0;
        for (c = 0; c < channels && !in; c++)
            in = ref->hi[i * channels + c] > ref->lo[i * channels + c];
        band += (uint64_t)in;
    }
    return band;
}

static double squares_of(const tone_counts *k)
{
    return k->sum_squares[0] + k->sum_squares[1] + k->sum_squares[2];
}

/* The sum of squares of a pass at scale t->scale, or UINT64_MAX when
   it is sure to be more than limit (the pass stopped there). */
static uint64_t scale_squares(const tone_image *ref, const tone_image *image,
                              tone_xform *t, unsigned levels, uint64_t limit)
{
    tone_counts k;
    t->capped = limit != UINT64_MAX;
    t->max_squares = limit;
    t->max_differing = UINT64_MAX;
    tone_measure(ref, image, t, 0, levels, -1, &k);
    if (k.stopped)
        return UINT64_MAX;
    return (uint64_t)squares_of(&k);
}

/*
 * The candidates of a round are tried from the middle of the range out
 * (i = mid, mid - 1, mid + 1, ...), where the good ones are likely, and
 * each pass stops once its sum of squares is past the best so far: the
 * scale chosen is still the first of the round's order i = 0, 1, ...
 * with the smallest sum (ties go to the smaller i), that of trying them
 * all in order to the end.  A later round keeps an earlier round's best
 * on a tie.
 */
static void scale_round(const tone_image *ref, const tone_image *image,
                        unsigned levels, tone_xform *t, uint32_t count,
                        double lo, double hi, double ratio, int geometric,
                        double *best, uint64_t *fewest)
{
    uint32_t mid = count / 2, d, side, i, found = UINT32_MAX;
    for (d = 0; d <= mid || mid + d < count; d++)
        for (side = 0; side < 2; side++) {
            uint64_t sq;
            /* mid, then mid - 1, mid + 1, mid - 2, mid + 2, ... */
            if ((d == 0 && side) || (side == 0 && d > mid) ||
                (side && mid + d >= count))
                continue;
            i = side ? mid + d : mid - d;
            t->scale = geometric ? lo * pow(ratio, i)
                                 : lo + (hi - lo) * i / (count - 1);
            sq = scale_squares(ref, image, t, levels, *fewest);
            if (sq < *fewest || (sq == *fewest && found != UINT32_MAX &&
                                 i < found)) {
                *fewest = sq;
                *best = t->scale;
                found = i;
            }
        }
}

double tone_best_scale(const tone_image *ref, const tone_image *image,
                       unsigned levels, double lo, double hi,
                       uint64_t *left, double *squares)
{
    double pixels = (double)ref->width * ref->height, best = 1, ratio;
    uint64_t fewest = UINT64_MAX;
    uint32_t step = (uint32_t)ceil(sqrt(pixels / 65536.0));
    tone_xform t = tone_identity();
    tone_counts k;
    const uint32_t scan = 41, fine = 21;
    t.kind = TONE_SCALE;
    t.step = step > 0 ? step : 1;
    ratio = pow(hi / lo, 1.0 / (scan - 1));
    scale_round(ref, image, levels, &t, scan, lo, hi, ratio, 1, &best,
                &fewest);
    lo = best / ratio;
    hi = best * ratio;
    scale_round(ref, image, levels, &t, fine, lo, hi, ratio, 0, &best,
                &fewest);
    t = tone_identity();
    t.kind = TONE_SCALE;
    t.scale = best;
    tone_measure(ref, image, &t, 0, levels, -1, &k);
    *left = k.differing;
    *squares = squares_of(&k);
    return best;
}

int tone_classify_pixel(const tone_image *ref, const tone_image *image,
                        uint32_t x, uint32_t y, double tolerance,
                        unsigned levels, unsigned *difference)
{
    tone_xform t = tone_identity();
    const unsigned char *r = tone_pixel(ref, x, y);
    unsigned char u[3];
    unsigned c, worst = 0;
    int radius = tone_radius(tolerance);
    *difference = 0;
    if (!undo(ref, image, &t, x, y, u))
        return TONE_PIXEL_UNKNOWN;
    for (c = 0; c < ref->channels; c++) {
        unsigned d = u[c] > r[c] ? u[c] - r[c] : r[c] - u[c];
        if (d > worst)
            worst = d;
    }
    *difference = worst;
    if (worst <= levels)
        return TONE_PIXEL_SAME;
    return explained(ref, x, y, u, radius, levels) ||
                   near_edge(ref, x, y, radius, levels)
               ? TONE_PIXEL_EXPLAINED
               : TONE_PIXEL_UNEXPLAINED;
}
