/*
 * shape.c - the black region of a mask as a shape: its area, centroid,
 * second moments, whether it touches the frame, and how closely it
 * matches an ellipse.
 *
 * A sphere seen through a pinhole camera has an ellipse for an outline,
 * so "is this a picture of a sphere?" becomes "does the black region
 * coincide with the ellipse that has its area's first and second
 * moments?" (for a uniform ellipse the covariance C gives the ellipse
 * (p - m)' C^-1 (p - m) <= 4).  The overlap is measured as an IoU, row by
 * row, counting black pixels between the ellipse's ends with popcounts.
 * Coordinates are pixel indices; the centroid is reported centred
 * (x = i - floor(w/2), y = j - floor(h/2)), y down.
 */
#include <math.h>
#include <string.h>

#include "compare_impl.h"

typedef struct sums {
    uint64_t n, sx, sxx, sy, syy, sxy;
} sums;

static void byte_sums(unsigned v, uint64_t base, uint64_t *n, uint64_t *s1,
                      uint64_t *s2)
{
    unsigned bit;
    if (v == 0xFFu) {
        *n += 8;
        *s1 += 8 * base + 28;
        *s2 += 8 * base * base + 56 * base + 140;
        return;
    }
    for (bit = 0; bit < 8; bit++)
        if ((v >> (7 - bit)) & 1u) {
            uint64_t i = base + bit;
            *n += 1;
            *s1 += i;
            *s2 += i * i;
        }
}

static int row_touches_sides(const unsigned char *row, uint32_t width)
{
    return rayo_bit_get(row, 0) || rayo_bit_get(row, width - 1);
}

static void add_row(const cmp_mask *m, uint32_t y, sums *s, int *touches)
{
    const unsigned char *row = cmp_mask_row(m, y);
    size_t n = cmp_row_bytes(m->width), k;
    uint64_t rn = 0, r1 = 0, r2 = 0;
    for (k = 0; k < n; k++) {
        unsigned v = row[k];
        if (k == n - 1)
            v &= (0xFFu << ((8 - (m->width & 7u)) & 7u)) & 0xFFu;
        if (v != 0)
            byte_sums(v, 8 * (uint64_t)k, &rn, &r1, &r2);
    }
    if (rn == 0)
        return;
    if (y == 0 || y == m->height - 1 || row_touches_sides(row, m->width))
        *touches = 1;
    s->n += rn;
    s->sx += r1;
    s->sxx += r2;
    s->sy += rn * y;
    s->syy += rn * (uint64_t)y * y;
    s->sxy += r1 * y;
}

/* Black pixels of row among columns i0..i1 (inclusive). */
static uint64_t count_range(const unsigned char *row, uint32_t i0,
                            uint32_t i1)
{
    uint32_t k0 = i0 >> 3, k1 = i1 >> 3;
    unsigned head = 0xFFu >> (i0 & 7u);
    unsigned tail = (0xFFu << (7 - (i1 & 7u))) & 0xFFu;
    uint64_t total;
    unsigned char b;
    if (k0 == k1) {
        b = (unsigned char)(row[k0] & head & tail);
        return cmp_popcount(&b, 1);
    }
    b = (unsigned char)(row[k0] & head);
    total = cmp_popcount(&b, 1);
    total += cmp_popcount(row + k0 + 1, k1 - k0 - 1);
    b = (unsigned char)(row[k1] & tail);
    return total + cmp_popcount(&b, 1);
}

/* IoU of the black region with the ellipse of mean (mx, my) and
 * covariance (a b; b c). */
static double ellipse_iou(const cmp_mask *m, uint64_t black, double mx,
                          double my, double a, double b, double c)
{
    double det = a * c - b * b;
    uint64_t inside = 0, area = 0;
    uint32_t y;
    if (!(det > 0) || !(c > 0))
        return 0;
    for (y = 0; y < m->height; y++) {
        double dy = (double)y - my, r = 4 * c - dy * dy, half, lo, hi;
        if (r < 0)
            continue;
        half = sqrt(det * r) / c;
        lo = ceil(mx + (b * dy - half) / c);
        hi = floor(mx + (b * dy + half) / c);
        if (lo < 0)
            lo = 0;
        if (hi > (double)m->width - 1)
            hi = (double)m->width - 1;
        if (hi < lo)
            continue;
        area += (uint64_t)(hi - lo) + 1;
        inside += count_range(cmp_mask_row(m, y), (uint32_t)lo, (uint32_t)hi);
    }
    return (double)inside / (double)(black + area - inside);
}

void cmp_shape_measure(const cmp_mask *mask, cmp_shape *shape)
{
    sums s;
    uint32_t y;
    double n, mx, my;
    memset(&s, 0, sizeof s);
    memset(shape, 0, sizeof *shape);
    for (y = 0; y < mask->height; y++)
        add_row(mask, y, &s, &shape->touches_border);
    shape->black = s.n;
    if (s.n == 0)
        return;
    n = (double)s.n;
    mx = (double)s.sx / n;
    my = (double)s.sy / n;
    shape->cx = mx - (double)(mask->width / 2);
    shape->cy = my - (double)(mask->height / 2);
    shape->sxx = (double)s.sxx / n - mx * mx;
    shape->syy = (double)s.syy / n - my * my;
    shape->sxy = (double)s.sxy / n - mx * my;
    shape->ellipse_iou = ellipse_iou(mask, s.n, mx, my, shape->sxx,
                                     shape->sxy, shape->syy);
}
