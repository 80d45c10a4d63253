/*
 * bvh_build.c - building the bounding volume hierarchy (bvh.h).
 *
 * Top-down.  A node's primitives are sorted into BINS bins (as many as
 * it has primitives, when fewer) by their box centres along each axis in
 * turn, and the split between bins that minimises the surface area
 * heuristic
 *     cost = 1 + (A_left N_left + A_right N_right) / A_node
 * is taken when it beats making a leaf (cost N).  Nodes whose centres all
 * coincide, and nodes deeper than BVH_SAH_DEPTH_LIMIT, are cut in two
 * halves instead, so the depth stays below BVH_SAH_DEPTH_LIMIT + 32 for
 * any input and a fixed traversal stack suffices.  Nodes are
 * preallocated (a tree with leaves of at least one primitive has at most
 * 2n - 1 nodes); their float bounds are rounded outward (bvh_impl.h).
 */
#include "bvh_impl.h"

#include <math.h>
#include <stdlib.h>

#define BINS 16
#define MAX_LEAF 8

typedef struct builder {
    const rayo_box *boxes;
    uint32_t *order; /* indices into boxes, permuted as nodes split */
    bvh_node *nodes;
    size_t node_count;
} builder;

typedef struct bin {
    rayo_box box;
    size_t count;
} bin;

static void box_empty(rayo_box *b)
{
    int a;
    for (a = 0; a < 3; a++) {
        b->lo[a] = INFINITY;
        b->hi[a] = -INFINITY;
    }
}

/* Written as selections so that compilers make them min and max
 * instructions; a NaN in other changes nothing. */
static void box_grow(rayo_box *b, const rayo_box *other)
{
    int a;
    for (a = 0; a < 3; a++) {
        b->lo[a] = other->lo[a] < b->lo[a] ? other->lo[a] : b->lo[a];
        b->hi[a] = other->hi[a] > b->hi[a] ? other->hi[a] : b->hi[a];
    }
}

static double box_area(const rayo_box *b)
{
    double dx = b->hi[0] - b->lo[0], dy = b->hi[1] - b->lo[1],
           dz = b->hi[2] - b->lo[2];
    return 2.0 * (dx * dy + dy * dz + dz * dx);
}

static double centre(const rayo_box *b, int axis)
{
    return 0.5 * b->lo[axis] + 0.5 * b->hi[axis];
}

void rayo_box_pad(rayo_box *box)
{
    int a;
    for (a = 0; a < 3; a++) {
        double m = fmax(fabs(box->lo[a]), fabs(box->hi[a]));
        double pad = 1e-9 * (m + (box->hi[a] - box->lo[a]));
        box->lo[a] -= pad;
        box->hi[a] += pad;
    }
}

/* The largest float <= v (-infinity below the float range). */
static float float_below(double v)
{
    float f = (float)v;
    if ((double)f > v)
        f = nextafterf(f, -INFINITY);
    return f;
}

/* The smallest float >= v. */
static float float_above(double v)
{
    float f = (float)v;
    if ((double)f < v)
        f = nextafterf(f, INFINITY);
    return f;
}

/* How one node's centres are sorted into bins along one axis. */
typedef struct binning {
    int axis;
    size_t count;   /* bins: BINS, or fewer for a node of few primitives */
    double lo;      /* the lowest centre */
    double scale;   /* bins per unit of length */
} binning;

static binning binning_make(int axis, double lo, double extent,
                            size_t primitives)
{
    binning g;
    g.axis = axis;
    g.count = primitives < BINS ? (primitives < 2 ? 2 : primitives) : BINS;
    g.lo = lo;
    g.scale = (double)g.count / extent;
    return g;
}

/* The bin of a box, by its centre. */
static size_t bin_of(const binning *g, const rayo_box *box)
{
    double f = (centre(box, g->axis) - g->lo) * g->scale;
    if (!(f >= 0.0))
        return 0;
    if (f >= (double)(g->count - 1))
        return g->count - 1;
    return (size_t)f;
}

typedef struct split {
    binning along;   /* along.axis < 0: no useful split found */
    size_t bin;      /* primitives in bins < bin go left */
    double cost;
} split;

static void try_axis(const builder *b, size_t begin, size_t end,
                     const binning *g, double area, split *best)
{
    bin bins[BINS];
    rayo_box right_box[BINS];
    size_t right_count[BINS];
    rayo_box acc;
    size_t i, n = 0;
    for (i = 0; i < g->count; i++) {
        box_empty(&bins[i].box);
        bins[i].count = 0;
    }
    for (i = begin; i < end; i++) {
        const rayo_box *box = &b->boxes[b->order[i]];
        size_t k = bin_of(g, box);
        box_grow(&bins[k].box, box);
        bins[k].count++;
    }
    box_empty(&acc);
    for (i = g->count; i-- > 1;) {
        box_grow(&acc, &bins[i].box);
        n += bins[i].count;
        right_box[i] = acc;
        right_count[i] = n;
    }
    box_empty(&acc);
    n = 0;
    for (i = 1; i < g->count; i++) {
        double cost;
        box_grow(&acc, &bins[i - 1].box);
        n += bins[i - 1].count;
        if (n == 0 || right_count[i] == 0)
            continue;
        cost = 1.0 + (box_area(&acc) * (double)n +
                      box_area(&right_box[i]) * (double)right_count[i]) /
                         area;
        if (cost < best->cost) {
            best->cost = cost;
            best->along = *g;
            best->bin = i;
        }
    }
}

/* Moves the primitives going left to the front; returns the boundary. */
static size_t partition(builder *b, size_t begin, size_t end,
                        const split *s)
{
    size_t i = begin, j = end;
    while (i < j) {
        if (bin_of(&s->along, &b->boxes[b->order[i]]) < s->bin) {
            i++;
        } else {
            uint32_t tmp = b->order[i];
            b->order[i] = b->order[--j];
            b->order[j] = tmp;
        }
    }
    return i;
}

static void make_leaf(bvh_node *node, size_t begin, size_t end)
{
    node->first = (uint32_t)begin;
    node->count = (uint32_t)(end - begin);
}

static void build_node(builder *b, size_t index, size_t begin, size_t end,
                       unsigned depth)
{
    bvh_node *node = &b->nodes[index];
    rayo_box bounds, centres;
    split best;
    size_t i, count = end - begin, mid = begin + count / 2;
    int a;
    box_empty(&bounds);
    box_empty(&centres);
    for (i = begin; i < end; i++) {
        const rayo_box *box = &b->boxes[b->order[i]];
        rayo_box c;
        for (a = 0; a < 3; a++)
            c.lo[a] = c.hi[a] = centre(box, a);
        box_grow(&bounds, box);
        box_grow(&centres, &c);
    }
    for (a = 0; a < 3; a++) {
        node->bounds[0][a] = float_below(bounds.lo[a]);
        node->bounds[1][a] = float_above(bounds.hi[a]);
    }
    if (count == 1) {
        make_leaf(node, begin, end);
        return;
    }
    best.along.axis = -1;
    best.bin = 0;
    best.cost = INFINITY;
    if (depth < BVH_SAH_DEPTH_LIMIT) {
        double area = box_area(&bounds);
        for (a = 0; a < 3; a++) {
            double extent = centres.hi[a] - centres.lo[a];
            if (extent > 0.0 && isfinite(extent) && area > 0.0) {
                binning g = binning_make(a, centres.lo[a], extent, count);
                try_axis(b, begin, end, &g, area, &best);
            }
        }
    }
    if (count <= MAX_LEAF && !(best.cost < (double)count)) {
        make_leaf(node, begin, end);
        return;
    }
    if (best.along.axis >= 0) {
        size_t m = partition(b, begin, end, &best);
        if (m > begin && m < end)
            mid = m;
    }
    node->first = (uint32_t)b->node_count;
    node->count = 0;
    b->node_count += 2;
    build_node(b, node->first, begin, mid, depth + 1);
    build_node(b, b->nodes[index].first + 1, mid, end, depth + 1);
}

rayo_status rayo_bvh_build(rayo_bvh **result, const rayo_box *boxes,
                           const uint32_t *ids, size_t count,
                           rayo_error *err)
{
    rayo_bvh *bvh;
    builder b;
    size_t i, max_nodes = count ? 2 * count - 1 : 0;
    *result = NULL;
    if (count > UINT32_MAX / 2)
        return rayo_error_set(err, RAYO_ERR_LIMIT,
                              "%lu primitives are too many for the "
                              "hierarchy; expected at most %lu",
                              (unsigned long)count,
                              (unsigned long)(UINT32_MAX / 2));
    bvh = calloc(1, sizeof *bvh);
    if (bvh == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
    if (count == 0) {
        *result = bvh;
        return RAYO_OK;
    }
    /* count <= UINT32_MAX / 2, so these products fit in size_t only if
     * checked: */
    if (max_nodes > SIZE_MAX / sizeof *bvh->nodes ||
        count > SIZE_MAX / sizeof *bvh->prims) {
        free(bvh);
        return rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
    }
    bvh->nodes = malloc(max_nodes * sizeof *bvh->nodes);
    bvh->prims = malloc(count * sizeof *bvh->prims);
    if (bvh->nodes == NULL || bvh->prims == NULL) {
        rayo_bvh_free(bvh);
        return rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
    }
    for (i = 0; i < count; i++)
        bvh->prims[i] = (uint32_t)i;
    b.boxes = boxes;
    b.order = bvh->prims;
    b.nodes = bvh->nodes;
    b.node_count = 1;
    build_node(&b, 0, 0, count, 0);
    for (i = 0; i < count; i++)
        bvh->prims[i] = ids[bvh->prims[i]];
    bvh->node_count = b.node_count;
    *result = bvh;
    return RAYO_OK;
}
