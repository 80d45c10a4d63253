/*
 * outline.c - how far each pixel is from the reference's outline,
 * without a full-size distance map.
 *
 * The distance of a pixel from the outline is the Euclidean distance to
 * the nearest reference pixel of the other colour, computed as the exact
 * two-pass distance transform of Meijster et al. and of Felzenszwalb and
 * Huttenlocher, rearranged so that the first (vertical) pass is never
 * stored (below): even a worst-case noise image costs no more than a
 * 16-bit map.  Not a general distance-transform library: one reference,
 * rows in order, distances only to "the other colour".
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../compare_impl.h"

/*
 * Each column keeps only the rows where its colour changes, so the
 * vertical distance from (x, y) to the other colour is read off the change
 * just above and the change just below y, found by a cursor that moves
 * down as the rows are asked for.  A sphere's mask has two changes a
 * column; memory is two bytes a change (rows fit in 16 bits, since heights
 * are at most 65536).  The second (horizontal) pass is the lower envelope
 * of parabolas over a row, or rather over the stretches of it near
 * mismatches (a run of mismatches is widened by a bound on its distances:
 * the vertical distance, and the horizontal one to the nearest pixel of
 * the other colour beside the run).
 */

struct cmp_outline {
    const cmp_mask *ref;
    size_t *start;         /* column x's changes: change[start[x]..
                              start[x+1]) */
    uint16_t *change;      /* row r: colour of r differs from r - 1 */
    size_t *cursor;        /* first change of column x below the row */
    int64_t *f;            /* squared vertical distances of one row */
    uint32_t *hull;        /* envelope: columns of its parabolas */
    uint32_t row;          /* the row the cursors are at */
    int has_black, has_white;
    int owns_index;        /* start and change are this one's to free */
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
    o->owns_index = 1;
    if ((s = alloc_array((void **)&o->start, w + 1, sizeof *o->start,
                         err)) != RAYO_OK ||
        (s = alloc_array((void **)&o->cursor, w, sizeof *o->cursor, err)) !=
            RAYO_OK ||
        (s = alloc_array((void **)&o->f, w, sizeof *o->f, err)) != RAYO_OK ||
        (s = alloc_array((void **)&o->hull, w, sizeof *o->hull, err)) !=
            RAYO_OK ||
        (s = index_changes(o, err)) != RAYO_OK) {
        cmp_outline_free(o);
        return s;
    }
    find_colours(o);
    cmp_outline_rewind(o, 0);
    *outline = o;
    return RAYO_OK;
}

rayo_status cmp_outline_fork(const cmp_outline *base, cmp_outline **fork,
                             rayo_error *err)
{
    size_t w = base->ref->width;
    rayo_status s;
    cmp_outline *o = calloc(1, sizeof *o);
    *fork = NULL;
    if (o == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "compare: out of memory");
    *o = *base;
    o->owns_index = 0;
    o->cursor = NULL;
    o->f = NULL;
    o->hull = NULL;
    if ((s = alloc_array((void **)&o->cursor, w, sizeof *o->cursor, err)) !=
            RAYO_OK ||
        (s = alloc_array((void **)&o->f, w, sizeof *o->f, err)) != RAYO_OK ||
        (s = alloc_array((void **)&o->hull, w, sizeof *o->hull, err)) !=
            RAYO_OK) {
        cmp_outline_free(o);
        return s;
    }
    cmp_outline_rewind(o, 0);
    *fork = o;
    return RAYO_OK;
}

void cmp_outline_free(cmp_outline *o)
{
    if (o == NULL)
        return;
    if (o->owns_index) {
        free(o->start);
        free(o->change);
    }
    free(o->cursor);
    free(o->f);
    free(o->hull);
    free(o);
}

void cmp_outline_rewind(cmp_outline *o, uint32_t y)
{
    uint32_t x;
    for (x = 0; x < o->ref->width; x++) { /* first change below y */
        size_t lo = o->start[x], hi = o->start[x + 1];
        while (lo < hi) {
            size_t mid = lo + (hi - lo) / 2;
            if (o->change[mid] <= y)
                lo = mid + 1;
            else
                hi = mid;
        }
        o->cursor[x] = lo;
    }
    o->row = y;
}

int cmp_outline_has_edges(const cmp_outline *o)
{
    return o->has_black && o->has_white;
}

/* Moves every column's cursor to the first change below row y. */
static void seek(cmp_outline *o, uint32_t y)
{
    uint32_t x;
    if (y == o->row)
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

/* The parabolas of columns p < q, y = (x - p)^2 + f[p] and likewise for
 * q, cross at s(p, q) = (F[q] - F[p]) / (2 (q - p)) with F[c] = f[c] +
 * c^2.  Everything stays in integers: F < 2^34 and column differences
 * < 2^17, so the cross products below fit in 64 bits. */
static int64_t big_f(const int64_t *f, uint32_t c)
{
    return f[c] + (int64_t)c * c;
}

/* s(r, p) >= s(p, q): p's parabola is nowhere the lowest (r < p < q). */
static int hidden(const int64_t *f, uint32_t r, uint32_t p, uint32_t q)
{
    return (big_f(f, q) - big_f(f, p)) * ((int64_t)p - r) <=
           (big_f(f, p) - big_f(f, r)) * ((int64_t)q - p);
}

/* s(p, q) < x: past x, q's parabola is below p's. */
static int crossed_before(const int64_t *f, uint32_t p, uint32_t q,
                          uint32_t x)
{
    return big_f(f, q) - big_f(f, p) < 2 * (int64_t)x * ((int64_t)q - p);
}

/* The envelope over columns lo..hi only: d2[x] for x in lo..hi. */
static void envelope(cmp_outline *o, const unsigned char *row, uint32_t y,
                     int colour, uint32_t lo, uint32_t hi, int64_t *d2)
{
    uint32_t x, k = 0, n = 0;
    for (x = lo; x <= hi; x++) {
        o->f[x] = vertical(o, row, x, y, colour);
        if (o->f[x] == INT64_MAX)
            continue;
        while (n > 1 && hidden(o->f, o->hull[n - 2], o->hull[n - 1], x))
            n--;
        o->hull[n++] = x;
    }
    for (x = lo; x <= hi; x++) {
        int64_t dx;
        if (n == 0) {
            d2[x] = INT64_MAX;
            continue;
        }
        while (k + 1 < n && crossed_before(o->f, o->hull[k], o->hull[k + 1],
                                           x))
            k++;
        dx = (int64_t)x - o->hull[k];
        d2[x] = dx * dx + o->f[o->hull[k]];
    }
}

/* The nearest column of this row at or beyond x (step -1 or +1) whose
 * pixel has the colour, or -1 when there is none; whole bytes without
 * it are skipped. */
static int64_t scan(const unsigned char *row, uint32_t width, int64_t x,
                    int step, int colour)
{
    unsigned none = colour ? 0x00u : 0xFFu;
    while (x >= 0 && x < (int64_t)width) {
        if ((x & 7) == (step > 0 ? 0 : 7) && row[x >> 3] == none &&
            (step < 0 || x + 8 <= (int64_t)width)) {
            x += 8 * step;
            continue;
        }
        if (rayo_bit_get(row, (uint32_t)x) == colour)
            return x;
        x += step;
    }
    return -1;
}

/* The nearest pixels of the colour beside the runs of a row, found as
 * the runs are taken from left to right: no pixel of a run has the
 * colour (a mismatch's reference colour is the other one), so the
 * nearest one left of a run is between it and the run before, or the
 * one found for that run; and the nearest one right of the run before,
 * when it lies past this run's end, is this run's too.  Each pixel of
 * the row is so scanned at most twice, however many runs it has (a
 * scan per run from the run's ends cost a whole row each when the
 * colour is rare: a white reference against noise, quadratic). */
typedef struct run_sides {
    int64_t left, right; /* -1: none */
    int64_t scanned_to;  /* left of a run: pixels below were scanned */
    int right_known;
} run_sides;

static void sides_of_run(run_sides *s, const unsigned char *row,
                         uint32_t width, int colour, uint32_t a, uint32_t b)
{
    int64_t found = -1, x;
    for (x = (int64_t)a - 1; x >= s->scanned_to; x--) {
        if ((x & 7) == 7 && x - 7 >= s->scanned_to &&
            row[x >> 3] == (colour ? 0x00u : 0xFFu)) {
            x -= 7;
            continue;
        }
        if (rayo_bit_get(row, (uint32_t)x) == colour) {
            found = x;
            break;
        }
    }
    if (found >= 0)
        s->left = found;
    s->scanned_to = (int64_t)b + 1;
    if (!s->right_known || (s->right >= 0 && s->right <= (int64_t)b))
        s->right = scan(row, width, (int64_t)b + 1, 1, colour);
    s->right_known = 1;
}

/* The run of mismatches a..b needs the envelope only over a..b widened
 * by its largest distance bound: for each x, the vertical distance to
 * the colour and the horizontal distance to the nearest pixel of the
 * colour outside the run, both upper bounds on the true distance. */
static uint32_t run_reach(cmp_outline *o, const unsigned char *row,
                          uint32_t y, int colour, uint32_t a, uint32_t b,
                          run_sides *sides)
{
    uint32_t w = o->ref->width, x, reach = 0;
    int64_t left, right;
    sides_of_run(sides, row, w, colour, a, b);
    left = sides->left;
    right = sides->right;
    for (x = a; x <= b; x++) {
        int64_t bound = vertical(o, row, x, y, colour), h = INT64_MAX;
        if (left >= 0)
            h = (int64_t)x - left;
        if (right >= 0 && right - (int64_t)x < h)
            h = right - (int64_t)x;
        if (h != INT64_MAX && h * h < bound)
            bound = h * h;
        if (bound == INT64_MAX || bound >= (int64_t)w * w)
            return w;
        if ((int64_t)reach * reach < bound) {
            reach = (uint32_t)sqrt((double)bound);
            while ((int64_t)reach * reach < bound) /* sqrt rounded down */
                reach++;
        }
    }
    return reach;
}

/* The next run of set bits of diff at or after x: *a..*b; 0 if none. */
static int next_run(const unsigned char *diff, uint32_t width, uint32_t x,
                    uint32_t *a, uint32_t *b)
{
    while (x < width && !rayo_bit_get(diff, x)) {
        if ((x & 7) == 0 && diff[x >> 3] == 0)
            x += 8;
        else
            x++;
    }
    if (x >= width)
        return 0;
    *a = x;
    while (x + 1 < width && rayo_bit_get(diff, x + 1))
        x++;
    *b = x;
    return 1;
}

void cmp_outline_row_distances(cmp_outline *o, uint32_t y, int colour,
                               int64_t *d2)
{
    seek(o, y);
    envelope(o, cmp_mask_row(o->ref, y), y, colour, 0, o->ref->width - 1, d2);
}

void cmp_outline_mismatch_distances(cmp_outline *o, uint32_t y, int colour,
                                    const unsigned char *diff, int64_t *d2)
{
    const unsigned char *row = cmp_mask_row(o->ref, y);
    uint32_t w = o->ref->width, a, b, x = 0, lo = 0, hi = 0;
    int open = 0;
    run_sides sides = {-1, -1, 0, 0};
    seek(o, y);
    while (next_run(diff, w, x, &a, &b)) {
        uint32_t reach = run_reach(o, row, y, colour, a, b, &sides);
        uint32_t rlo = a > reach ? a - reach : 0;
        uint32_t rhi = w - 1 - b > reach ? b + reach : w - 1;
        if (open && rlo <= hi + 1) {
            if (rhi > hi)
                hi = rhi;
        } else {
            if (open)
                envelope(o, row, y, colour, lo, hi, d2);
            lo = rlo;
            hi = rhi;
            open = 1;
        }
        x = b + 1;
    }
    if (open)
        envelope(o, row, y, colour, lo, hi, d2);
}
