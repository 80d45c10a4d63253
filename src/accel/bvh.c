/*
 * bvh.c - building and walking the bounding volume hierarchy (bvh.h).
 *
 * Build: top-down.  A node's primitives are sorted into BINS bins (as
 * many as it has primitives, when fewer) by their box centres along each
 * axis in turn, and the split between bins that minimises the surface
 * area heuristic
 *     cost = 1 + (A_left N_left + A_right N_right) / A_node
 * is taken when it beats making a leaf (cost N).  Nodes whose centres all
 * coincide, and nodes deeper than SAH_DEPTH_LIMIT, are cut in two halves
 * instead, so the depth stays below SAH_DEPTH_LIMIT + 32 for any input
 * and a fixed traversal stack suffices.  Nodes are preallocated (a tree
 * with leaves of at least one primitive has at most 2n - 1 nodes) and
 * hold their boxes as floats rounded outward: 32 bytes a node, half the
 * memory traffic of doubles, and never a smaller box.
 *
 * Walk: iterative, with the ray's reciprocal direction precomputed; both
 * children of a node are tested at once, in the two lanes of an SSE2
 * register where there is one (pair_entry), with the same arithmetic as
 * one at a time; the nearest-hit query visits the nearer child first and
 * skips any subtree whose box begins beyond the best hit so far; the
 * any-hit query also goes nearer child first, as near objects are the
 * likelier blockers.
 * Box tests treat NaN (a zero direction component on a slab's plane) as
 * "may hit", so culling is conservative.
 */
#include "bvh.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#define BINS 16
#define MAX_LEAF 8
#define SAH_DEPTH_LIMIT 48
#define STACK_SIZE 128

/* 32 bytes, two to a cache line.  Bounds are floats rounded outward, so
 * each float box holds the double box it stands for. */
typedef struct bvh_node {
    float bounds[2][3]; /* [0]: low corner, [1]: high corner */
    uint32_t first; /* interior: left child (right is first + 1);
                       leaf: first entry in prims */
    uint32_t count; /* primitives in a leaf; 0 for an interior node */
} bvh_node;

struct rayo_bvh {
    bvh_node *nodes;
    size_t node_count;
    uint32_t *prims; /* primitive ids in leaf order */
};

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
    if (depth < SAH_DEPTH_LIMIT) {
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

void rayo_bvh_free(rayo_bvh *bvh)
{
    if (bvh == NULL)
        return;
    free(bvh->nodes);
    free(bvh->prims);
    free(bvh);
}

/* A ray with what every box test needs precomputed: the reciprocal
 * direction, and for each axis where in a node's bounds (as 6 floats:
 * low x y z, high x y z) the slab plane the ray meets first (near) and
 * last (far) lies. */
typedef struct box_ray {
    double origin[3], inv[3];
    int near[3], far[3];
} box_ray;

static void box_ray_init(box_ray *r, const rayo_ray *ray)
{
    double d[3];
    int a;
    d[0] = ray->direction.x;
    d[1] = ray->direction.y;
    d[2] = ray->direction.z;
    r->origin[0] = ray->origin.x;
    r->origin[1] = ray->origin.y;
    r->origin[2] = ray->origin.z;
    for (a = 0; a < 3; a++) {
        int negative = signbit(d[a]) != 0;
        r->inv[a] = 1.0 / d[a];
        r->near[a] = 3 * negative + a;
        r->far[a] = 3 * (1 - negative) + a;
    }
}

/* One slab: narrows [*tn, *tf].  A NaN (0 * infinity: the ray parallel
 * to the slab, starting on its plane) narrows nothing. */
static inline void slab(const float *bounds, const box_ray *r, int a,
                        double *tn, double *tf)
{
    double t0 = ((double)bounds[r->near[a]] - r->origin[a]) * r->inv[a];
    double t1 = ((double)bounds[r->far[a]] - r->origin[a]) * r->inv[a];
    if (t0 > *tn)
        *tn = t0;
    if (t1 < *tf)
        *tf = t1;
}

/* Where the ray enters the node's box within [t_min, t_max], or
 * INFINITY when it misses. */
static inline double box_entry(const bvh_node *n, const box_ray *r,
                               double t_min, double t_max)
{
    const float *bounds = &n->bounds[0][0];
    double tn = t_min, tf = t_max;
    slab(bounds, r, 0, &tn, &tf);
    slab(bounds, r, 1, &tn, &tf);
    slab(bounds, r, 2, &tn, &tf);
    return tn <= tf ? tn : INFINITY;
}

#if defined(__SSE2__)
/* box_entry for both children of a node at once (pair[0], pair[1]),
 * with the same arithmetic, lane by lane: maxpd and minpd keep their
 * second operand when the first is NaN or equal, as slab() keeps *tn
 * and *tf. */
static inline void pair_entry(const bvh_node *pair, const box_ray *r,
                              double t_min, double t_max, double *tl,
                              double *tr)
{
    const float *b0 = &pair[0].bounds[0][0], *b1 = &pair[1].bounds[0][0];
    __m128d tn = _mm_set1_pd(t_min), tf = _mm_set1_pd(t_max);
    double out[2], far_out[2];
    int a;
    for (a = 0; a < 3; a++) {
        __m128d o = _mm_set1_pd(r->origin[a]), inv = _mm_set1_pd(r->inv[a]);
        __m128d lo =
            _mm_set_pd((double)b1[r->near[a]], (double)b0[r->near[a]]);
        __m128d hi =
            _mm_set_pd((double)b1[r->far[a]], (double)b0[r->far[a]]);
        tn = _mm_max_pd(_mm_mul_pd(_mm_sub_pd(lo, o), inv), tn);
        tf = _mm_min_pd(_mm_mul_pd(_mm_sub_pd(hi, o), inv), tf);
    }
    _mm_storeu_pd(out, tn);
    _mm_storeu_pd(far_out, tf);
    *tl = out[0] <= far_out[0] ? out[0] : INFINITY;
    *tr = out[1] <= far_out[1] ? out[1] : INFINITY;
}
#else
static inline void pair_entry(const bvh_node *pair, const box_ray *r,
                              double t_min, double t_max, double *tl,
                              double *tr)
{
    *tl = box_entry(&pair[0], r, t_min, t_max);
    *tr = box_entry(&pair[1], r, t_min, t_max);
}
#endif

/* The smaller of two distances (fmin, without a library call). */
static inline double closer(double a, double b)
{
    return a < b ? a : b;
}

typedef struct stack_entry {
    uint32_t node;
    double t;
} stack_entry;

static void test_leaf(const rayo_bvh *bvh, const bvh_node *n,
                      const rayo_ray *ray, double t_min, double t_max,
                      rayo_bvh_prim_fn test, const void *context,
                      double *best_t, uint32_t *best_id, rayo_bvh_cost *cost)
{
    uint32_t k;
    for (k = 0; k < n->count; k++) {
        uint32_t id = bvh->prims[n->first + k];
        double hi = *best_t < t_max ? nextafter(*best_t, INFINITY) : t_max;
        double t = test(context, id, ray, t_min, hi);
        cost->prim_tests++;
        if (t < *best_t || (t == *best_t && t < INFINITY && id < *best_id)) {
            *best_t = t;
            *best_id = id;
        }
    }
}

void rayo_bvh_nearest(const rayo_bvh *bvh, const rayo_ray *ray, double t_min,
                      double t_max, rayo_bvh_prim_fn test,
                      const void *context, double *best_t, uint32_t *best_id,
                      rayo_bvh_cost *cost)
{
    stack_entry stack[STACK_SIZE];
    size_t sp = 0;
    box_ray r;
    uint32_t node = 0;
    if (bvh->node_count == 0)
        return;
    box_ray_init(&r, ray);
    cost->node_tests++;
    if (box_entry(&bvh->nodes[0], &r, t_min, closer(*best_t, t_max)) ==
        INFINITY)
        return;
    for (;;) {
        const bvh_node *n = &bvh->nodes[node];
        if (n->count) {
            test_leaf(bvh, n, ray, t_min, t_max, test, context, best_t,
                      best_id, cost);
        } else {
            double limit = closer(*best_t, t_max), tl, tr;
            pair_entry(&bvh->nodes[n->first], &r, t_min, limit, &tl, &tr);
            cost->node_tests += 2;
            if (tl != INFINITY && tr != INFINITY) {
                uint32_t near = tl <= tr ? n->first : n->first + 1;
                stack[sp].node = near == n->first ? n->first + 1 : n->first;
                stack[sp].t = tl <= tr ? tr : tl;
                sp++;
                node = near;
                continue;
            }
            if (tl != INFINITY) {
                node = n->first;
                continue;
            }
            if (tr != INFINITY) {
                node = n->first + 1;
                continue;
            }
        }
        for (;;) {
            if (sp == 0)
                return;
            sp--;
            if (stack[sp].t <= *best_t)
                break;
        }
        node = stack[sp].node;
    }
}

int rayo_bvh_any(const rayo_bvh *bvh, const rayo_ray *ray, double t_min,
                 double t_max, rayo_bvh_prim_fn test, const void *context,
                 rayo_bvh_cost *cost)
{
    uint32_t stack[STACK_SIZE];
    size_t sp = 0;
    box_ray r;
    uint32_t node = 0;
    if (bvh->node_count == 0)
        return 0;
    box_ray_init(&r, ray);
    cost->node_tests++;
    if (box_entry(&bvh->nodes[0], &r, t_min, t_max) == INFINITY)
        return 0;
    for (;;) {
        const bvh_node *n = &bvh->nodes[node];
        if (n->count) {
            uint32_t k;
            for (k = 0; k < n->count; k++) {
                cost->prim_tests++;
                if (test(context, bvh->prims[n->first + k], ray, t_min,
                         t_max) < INFINITY)
                    return 1;
            }
        } else {
            /* Nearer child first: near objects are likelier blockers. */
            double tl, tr;
            pair_entry(&bvh->nodes[n->first], &r, t_min, t_max, &tl, &tr);
            cost->node_tests += 2;
            if (tl != INFINITY && tr != INFINITY) {
                node = tl <= tr ? n->first : n->first + 1;
                stack[sp++] = tl <= tr ? n->first + 1 : n->first;
                continue;
            }
            if (tl != INFINITY || tr != INFINITY) {
                node = tl != INFINITY ? n->first : n->first + 1;
                continue;
            }
        }
        if (sp == 0)
            return 0;
        node = stack[--sp];
    }
}

void rayo_bvh_describe(const rayo_bvh *bvh, rayo_bvh_info *info)
{
    uint32_t stack[STACK_SIZE], depth_of[STACK_SIZE];
    size_t sp = 0;
    memset(info, 0, sizeof *info);
    info->nodes = bvh->node_count;
    if (bvh->node_count == 0)
        return;
    stack[sp] = 0;
    depth_of[sp++] = 1;
    while (sp > 0) {
        const bvh_node *n = &bvh->nodes[stack[--sp]];
        uint32_t d = depth_of[sp];
        if (d > info->depth)
            info->depth = d;
        if (n->count) {
            info->leaves++;
            if (n->count > info->max_leaf)
                info->max_leaf = n->count;
            continue;
        }
        stack[sp] = n->first;
        depth_of[sp++] = d + 1;
        stack[sp] = n->first + 1;
        depth_of[sp++] = d + 1;
    }
}
