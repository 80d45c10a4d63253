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
#include <stdlib.h>
#include <string.h>

#include "../compare_impl.h"

typedef struct sums {
    uint64_t n, sx, sxx, sy, syy, sxy;
} sums;

/* For each byte value: its set bits (bit 0 the leftmost pixel), the sum
 * of their positions and of the positions' squares. */
typedef struct byte_table {
    unsigned char count[256], sum[256];
    unsigned short squares[256];
} byte_table;

static void byte_table_make(byte_table *t)
{
    unsigned v, bit;
    for (v = 0; v < 256; v++) {
        t->count[v] = t->sum[v] = 0;
        t->squares[v] = 0;
        for (bit = 0; bit < 8; bit++)
            if ((v >> (7 - bit)) & 1u) {
                t->count[v]++;
                t->sum[v] = (unsigned char)(t->sum[v] + bit);
                t->squares[v] = (unsigned short)(t->squares[v] + bit * bit);
            }
    }
}

/* The byte v's pixels at base.. added: their number, the sum of their
 * columns i and of i^2 (sum (base + b)^2 = n base^2 + 2 base sum b +
 * sum b^2), in integers, so exactly the pixel by pixel sums. */
static void byte_sums(const byte_table *t, unsigned v, uint64_t base,
                      uint64_t *n, uint64_t *s1, uint64_t *s2)
{
    uint64_t c = t->count[v], b = t->sum[v];
    *n += c;
    *s1 += c * base + b;
    *s2 += c * base * base + 2 * base * b + t->squares[v];
}

static int row_touches_sides(const unsigned char *row, uint32_t width)
{
    return rayo_bit_get(row, 0) || rayo_bit_get(row, width - 1);
}

static void add_row(const cmp_mask *m, const byte_table *t, uint32_t y,
                    sums *s, int *touches)
{
    const unsigned char *row = cmp_mask_row(m, y);
    size_t n = cmp_row_bytes(m->width), k;
    uint64_t rn = 0, r1 = 0, r2 = 0;
    for (k = 0; k < n; k++) {
        unsigned v = row[k];
        if (k == n - 1)
            v &= (0xFFu << ((8 - (m->width & 7u)) & 7u)) & 0xFFu;
        if (v != 0)
            byte_sums(t, v, 8 * (uint64_t)k, &rn, &r1, &r2);
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

/* The outline row y: black pixels with a white 4-neighbour inside the
 * frame (the frame's edge is not an outline: a cut sphere stays a
 * sphere).  Into out, cmp_row_bytes(width) bytes. */
static void outline_row(const cmp_mask *m, uint32_t y, unsigned char *out)
{
    size_t n = cmp_row_bytes(m->width), k;
    const unsigned char *row = cmp_mask_row(m, y);
    const unsigned char *up = y > 0 ? cmp_mask_row(m, y - 1) : row;
    const unsigned char *down = y + 1 < m->height ? cmp_mask_row(m, y + 1)
                                                  : row;
    unsigned last = (m->width & 7u) ? 7u - ((m->width - 1) & 7u) : 0;
    for (k = 0; k < n; k++) {
        unsigned v = row[k];
        unsigned left = (v >> 1) | (k > 0 ? (row[k - 1] & 1u) << 7 : 0x80u);
        unsigned right = ((v << 1) & 0xFFu) | (k + 1 < n ? row[k + 1] >> 7
                                                         : 1u);
        if (k + 1 == n && last)
            right |= 1u << last; /* the frame's right edge */
        out[k] = (unsigned char)(v & ~(up[k] & down[k] & left & right));
    }
    cmp_clear_padding(out, m->width);
}

typedef struct conic_fit {
    double ox, oy, unit;   /* origin and unit of the fit's coordinates */
    double m[5][6];        /* normal equations, augmented */
    double theta[5];       /* A x^2 + B x y + C y^2 + D x + E y = 1 */
    double n, sum_x, sum_y, residual;
    double stop;           /* pass 2 ends once residual is past it */
    int pass;
} conic_fit;

/* Pass 0: the number of outline pixels and the sums of their columns
 * and rows (integers, exact). */
static void count_row(conic_fit *f, const byte_table *t,
                      const unsigned char *buf, size_t n, uint32_t y)
{
    uint64_t c = 0, sx = 0, sx2 = 0;
    size_t k;
    for (k = 0; k < n; k++)
        if (buf[k] != 0)
            byte_sums(t, buf[k], 8 * (uint64_t)k, &c, &sx, &sx2);
    f->n += (double)c;
    f->sum_x += (double)sx;
    f->sum_y += (double)c * y;
}

/* Power sums of the bits of each byte value: pow[q][v] = e^q sum b^q
 * over its set bits b (bit 0 the leftmost pixel), e the fit's unit. */
typedef struct power_table {
    double pow[5][256];
} power_table;

static void power_table_make(power_table *t, double e)
{
    unsigned v, bit, q;
    for (v = 0; v < 256; v++)
        for (q = 0; q < 5; q++) {
            double sum = 0;
            for (bit = 0; bit < 8; bit++)
                if ((v >> (7 - bit)) & 1u) {
                    double b = bit * e, p = 1;
                    unsigned k;
                    for (k = 0; k < q; k++)
                        p *= b;
                    sum += p;
                }
            t->pow[q][v] = sum;
        }
}

/* Pass 1: the normal equations of the least-squares conic through the
 * outline, phi = (x^2, x y, y^2, x, y), m += phi phi' and phi.  On a row
 * y is fixed, so each entry is a power sum of the row's x times a power
 * of y; the x of a byte's pixels are u + b e (u its first column's, b
 * the bit), so their power sums come from the byte's, binomially, with
 * no test of each bit. */
static void fit_row(conic_fit *f, const power_table *pt,
                    const unsigned char *buf, size_t n, uint32_t j)
{
    double c = 0, s1 = 0, s2 = 0, s3 = 0, s4 = 0, y, y2, y3;
    double inv = 1 / f->unit;
    size_t k;
    for (k = 0; k < n; k++)
        if (buf[k] != 0) {
            unsigned v = buf[k];
            double u = ((double)(k * 8) - f->ox) * inv, u2 = u * u;
            double t0 = pt->pow[0][v], t1 = pt->pow[1][v];
            double t2 = pt->pow[2][v], t3 = pt->pow[3][v];
            double t4 = pt->pow[4][v];
            c += t0;
            s1 += t0 * u + t1;
            s2 += t0 * u2 + 2 * u * t1 + t2;
            s3 += t0 * u2 * u + 3 * u2 * t1 + 3 * u * t2 + t3;
            s4 += t0 * u2 * u2 + 4 * u2 * u * t1 + 6 * u2 * t2 + 4 * u * t3 +
                  t4;
        }
    if (c == 0)
        return;
    y = ((double)j - f->oy) * inv;
    y2 = y * y;
    y3 = y2 * y;
    f->m[0][0] += s4;
    f->m[0][1] += s3 * y;
    f->m[0][2] += s2 * y2;
    f->m[0][3] += s3;
    f->m[0][4] += s2 * y;
    f->m[0][5] += s2;
    f->m[1][2] += s1 * y3;
    f->m[1][4] += s1 * y2;
    f->m[1][5] += s1 * y;
    f->m[2][2] += c * y2 * y2;
    f->m[2][4] += c * y3;
    f->m[2][5] += c * y2;
    f->m[3][5] += s1;
    f->m[4][5] += c * y;
}

/* The entries of m that are the same sums as others (m is symmetric,
 * and phi's products repeat: x^2 y^2 = (x y)^2, ...). */
static void fit_fill(conic_fit *f)
{
    double (*m)[6] = f->m;
    int r, c;
    m[1][1] = m[0][2];
    m[1][3] = m[0][4];
    m[2][3] = m[1][4];
    m[3][3] = m[0][5];
    m[3][4] = m[1][5];
    m[4][4] = m[2][5];
    for (r = 0; r < 5; r++)
        for (c = 0; c < r; c++)
            m[r][c] = m[c][r];
}

/* Pass 2: the outline's distances from the conic (first order), summed;
 * 1 once the sum is past f->stop, so the rest cannot matter. */
static int residual_row(conic_fit *f, const unsigned char *buf, size_t n,
                        uint32_t j)
{
    const double *t = f->theta;
    double inv = 1 / f->unit, y = ((double)j - f->oy) * inv;
    size_t k;
    unsigned bit;
    for (k = 0; k < n; k++)
        if (buf[k] != 0)
            for (bit = 0; bit < 8; bit++)
                if ((buf[k] >> (7 - bit)) & 1u) {
                    double x = ((double)(k * 8 + bit) - f->ox) * inv;
                    double v = t[0] * x * x + t[1] * x * y + t[2] * y * y +
                               t[3] * x + t[4] * y - 1;
                    double gx = 2 * t[0] * x + t[1] * y + t[3];
                    double gy = t[1] * x + 2 * t[2] * y + t[4];
                    double g = sqrt(gx * gx + gy * gy);
                    f->residual += g > 0 ? fabs(v) / g * f->unit : f->unit;
                }
    return f->residual > f->stop;
}

static void walk_outline(const cmp_mask *m, const byte_table *t,
                         const power_table *pt, unsigned char *buf,
                         conic_fit *f)
{
    size_t n = cmp_row_bytes(m->width);
    uint32_t y;
    for (y = 0; y < m->height; y++) {
        outline_row(m, y, buf);
        if (f->pass == 0)
            count_row(f, t, buf, n, y);
        else if (f->pass == 1)
            fit_row(f, pt, buf, n, y);
        else if (residual_row(f, buf, n, y))
            return;
    }
}

/* Gaussian elimination with partial pivoting; 0 when singular. */
static int solve5(double m[5][6], double *x)
{
    int r, c, p, k;
    for (c = 0; c < 5; c++) {
        p = c;
        for (r = c + 1; r < 5; r++)
            if (fabs(m[r][c]) > fabs(m[p][c]))
                p = r;
        if (fabs(m[p][c]) < 1e-12)
            return 0;
        for (k = 0; k < 6; k++) {
            double t = m[c][k];
            m[c][k] = m[p][k];
            m[p][k] = t;
        }
        for (r = 0; r < 5; r++) {
            double q = m[r][c] / m[c][c];
            if (r == c)
                continue;
            for (k = c; k < 6; k++)
                m[r][k] -= q * m[c][k];
        }
    }
    for (r = 0; r < 5; r++)
        x[r] = m[r][5] / m[r][r];
    return 1;
}

/* Mean distance (pixels) of the outline from the conic that fits it
 * best, or HUGE_VAL when that conic is not an ellipse around black;
 * past limit, only some value past it. */
double cmp_shape_ellipse_error(const cmp_mask *m, double limit)
{
    conic_fit f;
    byte_table bt;
    power_table *pt = malloc(sizeof *pt);
    unsigned char *buf = malloc(cmp_row_bytes(m->width));
    const double *t = f.theta;
    double result = HUGE_VAL;
    uint32_t ci, cj;
    memset(&f, 0, sizeof f);
    if (buf == NULL || pt == NULL) {
        free(buf);
        free(pt);
        return result;
    }
    byte_table_make(&bt);
    f.unit = (m->width > m->height ? m->width : m->height) / 2.0;
    power_table_make(pt, 1 / f.unit);
    walk_outline(m, &bt, pt, buf, &f);
    if (f.n >= 8) {
        f.ox = f.sum_x / f.n;
        f.oy = f.sum_y / f.n;
        f.pass = 1;
        walk_outline(m, &bt, pt, buf, &f);
        fit_fill(&f);
        ci = (uint32_t)floor(f.ox + 0.5);
        cj = (uint32_t)floor(f.oy + 0.5);
        if (solve5(f.m, f.theta) && t[1] * t[1] - 4 * t[0] * t[2] < 0 &&
            rayo_bit_get(cmp_mask_row(m, cj), ci)) {
            f.pass = 2;
            /* twice the limit's sum: a mean past it whatever rounding */
            f.stop = 2 * limit * f.n;
            walk_outline(m, &bt, pt, buf, &f);
            result = f.residual / f.n;
        }
    }
    free(buf);
    free(pt);
    return result;
}

void cmp_shape_measure(const cmp_mask *mask, cmp_shape *shape)
{
    sums s;
    byte_table t;
    uint32_t y;
    double n, mx, my;
    memset(&s, 0, sizeof s);
    memset(shape, 0, sizeof *shape);
    byte_table_make(&t);
    for (y = 0; y < mask->height; y++)
        add_row(mask, &t, y, &s, &shape->touches_border);
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
}
