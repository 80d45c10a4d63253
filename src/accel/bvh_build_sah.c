/*
 * bvh_build_sah.c - where the builder cuts a node: its items are sorted
 * into BINS bins (as many as it has primitives, when fewer) along all
 * three axes in one pass, by their box centres (twice the centre, lo +
 * hi in float: the same order), and the split between bins that
 * minimises the surface area heuristic
 *     cost = 1 + (A_left N_left + A_right N_right) / A_node
 * is taken when it beats making a leaf (cost N).  The bins give each
 * child's bounds; the partition, which reads each item once and writes
 * it to the other item array (stable and branch-free), gives each
 * child's centre bounds, so no node scans its items twice.  Four floats
 * at a time (bvh_vec4.h), the same IEEE operations with or without SSE2.
 */
#include "bvh_build_impl.h"

void bvh_binning_make(binning *g, const fbox *centres, size_t items)
{
    float scale[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    int a;
    g->count = items < BINS ? (items < 2 ? 2 : items) : BINS;
    g->top = v4_set1((float)(g->count - 1));
    g->lo = v4_load(centres->lo);
    g->axes = 0;
    for (a = 0; a < 3; a++) {
        float extent = centres->hi[a] - centres->lo[a];
        g->binned[a] = 0;
        if (extent > 0.0f && isfinite(extent)) {
            float f = (float)g->count / extent;
            if (isfinite(f) && f > 0.0f) {
                scale[a] = f;
                g->binned[a] = 1;
                g->axes++;
            }
        }
    }
    g->scale = v4_load(scale);
}

/* The bins of a centre on each axis: (c - lo) scale clamped to [0, top]
 * (a NaN goes to 0), truncated. */
static void bins_of(const binning *g, vec4f centre, int32_t k[4])
{
    vec4f f = v4_mul(v4_sub(centre, g->lo), g->scale);
    f = v4_max(f, v4_set1(0.0f));
    f = v4_min(f, g->top);
    v4_to_int(f, k);
}

/* Inline in bvh_find_split, where the bins are its own: they stay in
 * registers and on its stack, nothing the items could alias. */
static inline void bins_clear(bvh_bins *s, size_t bins)
{
    vec4f inf = v4_infinity(), minus_inf = v4_set1(-INFINITY);
    size_t k;
    int a;
    for (a = 0; a < 3; a++)
        for (k = 0; k < bins; k++) {
            s->lo[a][k] = inf;
            s->hi[a][k] = minus_inf;
            s->count[a][k] = 0;
        }
}

static inline void bins_fill(const item *items, size_t begin, size_t end,
                             const binning *g, bvh_bins *s)
{
    size_t i;
    int a;
    for (i = begin; i < end; i++) {
        vec4f l = v4_load(items[i].lo), h = v4_load(items[i].hi);
        int32_t at[4];
        bins_of(g, v4_add(l, h), at);
        for (a = 0; a < 3; a++) {
            s->lo[a][at[a]] = v4_min(l, s->lo[a][at[a]]);
            s->hi[a][at[a]] = v4_max(h, s->hi[a][at[a]]);
            s->count[a][at[a]]++;
        }
    }
}

void bvh_bins_clear(bvh_bins *s, size_t bins)
{
    bins_clear(s, bins);
}

void bvh_bins_fill(const item *items, size_t begin, size_t end,
                   const binning *g, bvh_bins *s)
{
    bins_fill(items, begin, end, g, s);
}

void bvh_bins_merge(bvh_bins *into, const bvh_bins *from, size_t bins)
{
    size_t k;
    int a;
    for (a = 0; a < 3; a++)
        for (k = 0; k < bins; k++) {
            into->lo[a][k] = v4_min(from->lo[a][k], into->lo[a][k]);
            into->hi[a][k] = v4_max(from->hi[a][k], into->hi[a][k]);
            into->count[a][k] += from->count[a][k];
        }
}

void bvh_bins_best(const bvh_bins *s, const binning *g, double area,
                   split *best)
{
    vec4f right_lo[BINS], right_hi[BINS];
    size_t right_count[BINS];
    float right_area[BINS];
    vec4f inf = v4_infinity(), minus_inf = v4_set1(-INFINITY);
    size_t k, bins = g->count;
    int a;
    best->axis = -1;
    best->bin = 0;
    best->cost = INFINITY;
    for (a = 0; a < 3; a++) {
        vec4f acc_lo = inf, acc_hi = minus_inf;
        size_t n = 0;
        if (!g->binned[a])
            continue;
        for (k = bins; k-- > 1;) {
            acc_lo = v4_min(s->lo[a][k], acc_lo);
            acc_hi = v4_max(s->hi[a][k], acc_hi);
            n += s->count[a][k];
            right_lo[k] = acc_lo;
            right_hi[k] = acc_hi;
            right_area[k] = v4_half_area(acc_lo, acc_hi);
            right_count[k] = n;
        }
        acc_lo = inf;
        acc_hi = minus_inf;
        n = 0;
        for (k = 1; k < bins; k++) {
            double cost;
            acc_lo = v4_min(s->lo[a][k - 1], acc_lo);
            acc_hi = v4_max(s->hi[a][k - 1], acc_hi);
            n += s->count[a][k - 1];
            if (n == 0 || right_count[k] == 0)
                continue;
            cost = 1.0 + ((double)v4_half_area(acc_lo, acc_hi) * (double)n +
                          (double)right_area[k] * (double)right_count[k]) /
                             area;
            if (cost < best->cost) {
                best->cost = cost;
                best->axis = a;
                best->bin = (int32_t)k;
                best->left_count = n;
                fbox_set(&best->left, acc_lo, acc_hi);
                fbox_set(&best->right, right_lo[k], right_hi[k]);
            }
        }
    }
}

void bvh_find_split(const builder *b, const span *r, const binning *g,
                    double area, split *best)
{
    bvh_bins s;
    bins_clear(&s, g->count);
    bins_fill(b->items[r->side], r->begin, r->end, g, &s);
    bvh_bins_best(&s, g, area, best);
}

/* Writes the items going left, then the others, to the other item array
 * (in their order: the partition is stable), keeping the centre bounds
 * of each side.  No branch on the side: which way an item goes is as
 * good as random to a branch predictor. */
void bvh_partition_range(builder *b, int side, size_t begin, size_t end,
                         const binning *g, const split *s, size_t left_at,
                         size_t right_at, fbox *left_c, fbox *right_c)
{
    const item *from = b->items[side];
    item *to = b->items[!side];
    const uint32_t *from_index = b->index[side];
    uint32_t *to_index = b->index[!side];
    vec4f lo[2], hi[2];
    size_t next[2], i;
    int a = s->axis;
    lo[0] = lo[1] = v4_infinity();
    hi[0] = hi[1] = v4_set1(-INFINITY);
    next[0] = right_at; /* [0]: right, [1]: left */
    next[1] = left_at;
    for (i = begin; i < end; i++) {
        vec4f l = v4_load(from[i].lo), h = v4_load(from[i].hi);
        vec4f c = v4_add(l, h);
        int32_t at[4];
        int left;
        size_t d;
        bins_of(g, c, at);
        left = at[a] < s->bin;
        d = next[left]++;
        v4_store(to[d].lo, l);
        v4_store(to[d].hi, h);
        to_index[d] = from_index[i];
        lo[left] = v4_min(c, lo[left]);
        hi[left] = v4_max(c, hi[left]);
    }
    fbox_set(left_c, lo[1], hi[1]);
    fbox_set(right_c, lo[0], hi[0]);
}

size_t bvh_partition(builder *b, const span *r, const binning *g,
                     const split *s, fbox *left_c, fbox *right_c)
{
    bvh_partition_range(b, r->side, r->begin, r->end, g, s, r->begin,
                        r->begin + s->left_count, left_c, right_c);
    return r->begin + s->left_count;
}

/* Bounds and centre bounds of items [begin, end). */
void bvh_measure(const builder *b, int side, size_t begin, size_t end,
                 fbox *bounds, fbox *centres)
{
    const item *items = b->items[side];
    vec4f inf = v4_infinity(), minus_inf = v4_set1(-INFINITY);
    vec4f b_lo = inf, b_hi = minus_inf, c_lo = inf, c_hi = minus_inf;
    size_t i;
    for (i = begin; i < end; i++) {
        vec4f l = v4_load(items[i].lo), h = v4_load(items[i].hi);
        vec4f c = v4_add(l, h);
        b_lo = v4_min(l, b_lo);
        b_hi = v4_max(h, b_hi);
        c_lo = v4_min(c, c_lo);
        c_hi = v4_max(c, c_hi);
    }
    fbox_set(bounds, b_lo, b_hi);
    fbox_set(centres, c_lo, c_hi);
}
