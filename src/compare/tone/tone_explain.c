/*
 * tone_explain.c - whether the reference explains a difference, and the
 * maps that answer it fast.
 *
 * A difference is explained when an outline or a shadow edge of the
 * reference lies within the tolerance (a step between two neighbours
 * larger than the levels and than twice the steps beside it), or when,
 * channel by channel, the reference takes the image's value within the
 * tolerance (a square window), give or take the levels and one step of
 * its shading there.  That is what a picture drawn a pixel or two
 * differently produces (another focal distance, float instead of
 * double); a missing shadow, a swapped channel or a wrong formula do not.
 */
#include <stdlib.h>
#include <string.h>

#include "tone_impl.h"

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
int tone_explained(const tone_image *ref, uint32_t x, uint32_t y,
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

int tone_near_edge(const tone_image *ref, uint32_t x, uint32_t y, int radius,
                   unsigned levels)
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
    if (!tone_undo(ref, image, &t, x, y, u))
        return TONE_PIXEL_UNKNOWN;
    for (c = 0; c < ref->channels; c++) {
        unsigned d = u[c] > r[c] ? u[c] - r[c] : r[c] - u[c];
        if (d > worst)
            worst = d;
    }
    *difference = worst;
    if (worst <= levels)
        return TONE_PIXEL_SAME;
    return tone_explained(ref, x, y, u, radius, levels) ||
                   tone_near_edge(ref, x, y, radius, levels)
               ? TONE_PIXEL_EXPLAINED
               : TONE_PIXEL_UNEXPLAINED;
}
