/*
 * outline.c - how far each pixel is from the reference's outline,
 * without a full-size distance map.
 *
 * The distance of a pixel from the outline is the Euclidean distance to
 * the nearest reference pixel of the other colour.  It is computed as
 * the exact two-pass distance transform of Meijster et al. and of
 * Felzenszwalb and Huttenlocher, rearranged so the first (vertical) pass
 * is never stored: each column keeps only the rows where its colour
 * changes, so the vertical distance from (x, y) to the other colour is
 * read off the change just above and the change just below y, found by a
 * cursor that moves down as the rows are asked for.  A sphere's mask has
 * two changes a column; memory is two bytes a change (rows fit in 16
 * bits, since heights are at most 65536), so even a worst-case noise
 * image costs no more than a 16-bit map.  The second (horizontal) pass is
 * the lower envelope of parabolas over one row.
 *
 * Not a general distance-transform library: one reference, rows in
 * order, distances only to "the other colour".
 */
#include <stdlib.h>
#include <string.h>

#include "compare_impl.h"

struct cmp_outline {
    const cmp_mask *ref;
    size_t *start;         /* column x's changes: change[start[x]..
                              start[x+1]) */
    uint16_t *change;      /* row r: colour of r differs from r - 1 */
    size_t *cursor;        /* first change of column x below the row */
    int64_t *f;            /* squared vertical distances of one row */
    uint32_t *hull;        /* envelope: columns of its parabolas */
    double *bound;         /* envelope: where each parabola starts */
    uint32_t row;          /* the row the cursors are at */
    int has_black, has_white;
};

static rayo_status alloc_array(void **p, size_t count, size_t size,
                               rayo_error *err)
{
    if (count != 0 && size > SIZE_MAX / count)
        return rayo_error_set(err, RAYO_ERR_NOMEM,
                              "compare: %zu items of %zu bytes overflow",
                              count, size);
    *p = malloc(count * size != 0 ? count * size : 1);
    if (*p == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM,
                              "compare: out of memory for %zu bytes",
                              count * size);
    return RAYO_OK;
}

/* Calls visit(x) for every column whose colour changes between rows. */
static void count_changes(cmp_outline *o, size_t *counts, int fill)
{
    const cmp_mask *m = o->ref;
    size_t n = cmp_row_bytes(m->width), k;
    uint32_t y;
    for (y = 1; y < m->height; y++) {
        const unsigned char *a = cmp_mask_row(m, y - 1);
        const unsigned char *b = cmp_mask_row(m, y);
        for (k = 0; k < n; k++) {
            unsigned d = (unsigned)(a[k] ^ b[k]);
            unsigned bit;
            if (d == 0)
                continue;
            for (bit = 0; bit < 8; bit++) {
                size_t x = k * 8 + bit;
                if (!((d >> (7 - bit)) & 1u) || x >= m->width)
                    continue;
                if (fill)
                    o->change[o->start[x] + counts[x]] = (uint16_t)y;
                counts[x]++;
            }
        }
    }
}

static void find_colours(cmp_outline *o)
{
    const cmp_mask *m = o->ref;
    uint64_t black = 0;
    uint32_t y;
    for (y = 0; y < m->height; y++)
        black += cmp_popcount(cmp_mask_row(m, y), cmp_row_bytes(m->width));
    o->has_black = black > 0;
    o->has_white = black < (uint64_t)m->width * m->height;
}

static rayo_status index_changes(cmp_outline *o, rayo_error *err)
{
    uint32_t w = o->ref->width, x;
    size_t *counts, total = 0;
    rayo_status s = alloc_array((void **)&counts, w, sizeof *counts, err);
    if (s != RAYO_OK)
        return s;
    memset(counts, 0, (size_t)w * sizeof *counts);
    count_changes(o, counts, 0);
    for (x = 0; x < w; x++) {
        o->start[x] = total;
        total += counts[x];
        counts[x] = 0;
    }
    o->start[w] = total;
    s = alloc_array((void **)&o->change, total, sizeof *o->change, err);
    if (s == RAYO_OK)
        count_changes(o, counts, 1);
    free(counts);
    return s;
}

rayo_status cmp_outline_create(cmp_outline **outline, const cmp_mask *ref,
                               rayo_error *err)
{
    size_t w = ref->width;
    rayo_status s;
    cmp_outline *o = calloc(1, sizeof *o);
    *outline = NULL;
    if (o == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "compare: out of memory");
    o->ref = ref;
    if ((s = alloc_array((void **)&o->start, w + 1, sizeof *o->start,
                         err)) != RAYO_OK ||
        (s = alloc_array((void **)&o->cursor, w, sizeof *o->cursor, err)) !=
            RAYO_OK ||
        (s = alloc_array((void **)&o->f, w, sizeof *o->f, err)) != RAYO_OK ||
        (s = alloc_array((void **)&o->hull, w, sizeof *o->hull, err)) !=
            RAYO_OK ||
        (s = alloc_array((void **)&o->bound, w + 1, sizeof *o->bound,
                         err)) != RAYO_OK ||
        (s = index_changes(o, err)) != RAYO_OK) {
        cmp_outline_free(o);
        return s;
    }
    find_colours(o);
    cmp_outline_rewind(o);
    *outline = o;
    return RAYO_OK;
}

void cmp_outline_free(cmp_outline *o)
{
    if (o == NULL)
        return;
    free(o->start);
    free(o->change);
    free(o->cursor);
    free(o->f);
    free(o->hull);
    free(o->bound);
    free(o);
}

void cmp_outline_rewind(cmp_outline *o)
{
    memcpy(o->cursor, o->start, (size_t)o->ref->width * sizeof *o->cursor);
    o->row = 0;
}

int cmp_outline_has_edges(const cmp_outline *o)
{
    return o->has_black && o->has_white;
}

/* Moves every column's cursor to the first change below row y. */
static void seek(cmp_outline *o, uint32_t y)
{
    uint32_t x;
    if (y == o->row && y != 0)
        return;
    for (x = 0; x < o->ref->width; x++) {
        size_t c = o->cursor[x];
        while (c < o->start[x + 1] && o->change[c] <= y)
            c++;
        o->cursor[x] = c;
    }
    o->row = y;
}

/* Squared vertical distance from (x, y) to the colour, or INT64_MAX. */
static int64_t vertical(const cmp_outline *o, const unsigned char *row,
                        uint32_t x, uint32_t y, int colour)
{
    size_t c = o->cursor[x];
    int64_t best = INT64_MAX, d;
    if (rayo_bit_get(row, x) == colour)
        return 0;
    if (c > o->start[x]) { /* change above: row change - 1 has colour */
        d = (int64_t)y - o->change[c - 1] + 1;
        best = d * d;
    }
    if (c < o->start[x + 1]) {
        d = (int64_t)o->change[c] - y;
        if (d * d < best)
            best = d * d;
    }
    return best;
}

/* Where the parabolas of columns p and q (p < q) cross. */
static double crossing(const int64_t *f, uint32_t p, uint32_t q)
{
    double fp = (double)f[p] + (double)p * p;
    double fq = (double)f[q] + (double)q * q;
    return (fq - fp) / (2.0 * ((double)q - p));
}

void cmp_outline_distances(cmp_outline *o, uint32_t y, int colour,
                           int64_t *d2)
{
    const unsigned char *row = cmp_mask_row(o->ref, y);
    uint32_t w = o->ref->width, x, k = 0, n = 0;
    seek(o, y);
    for (x = 0; x < w; x++) {
        o->f[x] = vertical(o, row, x, y, colour);
        if (o->f[x] == INT64_MAX)
            continue;
        while (n > 0 && crossing(o->f, o->hull[n - 1], x) <= o->bound[n - 1])
            n--;
        o->bound[n] = n == 0 ? -1e300 : crossing(o->f, o->hull[n - 1], x);
        o->hull[n++] = x;
    }
    for (x = 0; x < w; x++) {
        int64_t dx;
        if (n == 0) {
            d2[x] = INT64_MAX;
            continue;
        }
        while (k + 1 < n && o->bound[k + 1] < (double)x)
            k++;
        dx = (int64_t)x - o->hull[k];
        d2[x] = dx * dx + o->f[o->hull[k]];
    }
}
