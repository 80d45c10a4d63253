/*
 * bvh.c - walking the bounding volume hierarchy (bvh.h), built by
 * bvh_build.c in the layout of bvh_impl.h.
 *
 * Iterative, with the ray's reciprocal direction precomputed; both
 * children of a node are tested at once, in the two lanes of an SSE2
 * register where there is one (pair_entry), with the same arithmetic as
 * one at a time; the nearest-hit query visits the nearer child first and
 * skips any subtree whose box begins beyond the best hit so far; the
 * any-hit query also goes nearer child first, as near objects are the
 * likelier blockers.  "Beyond the best hit" means beyond bvh_reach of it
 * (bvh_impl.h), a hair past, so that the answer never depends on the
 * order of the walk.
 * Box tests treat NaN (a zero direction component on a slab's plane) as
 * "may hit", so culling is conservative.
 */
#include "bvh_impl.h"
#include "bvh_wide.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

void rayo_bvh_free(rayo_bvh *bvh)
{
    if (bvh == NULL)
        return;
    rayo_bvh_wide_free(bvh->wide);
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
    stack_entry stack[BVH_STACK_SIZE];
    size_t sp = 0;
    box_ray r;
    uint32_t node = 0;
    if (bvh->node_count == 0)
        return;
    box_ray_init(&r, ray);
    cost->node_tests++;
    if (box_entry(&bvh->nodes[0], &r, t_min,
                  closer(bvh_reach(*best_t), t_max)) ==
        INFINITY)
        return;
    for (;;) {
        const bvh_node *n = &bvh->nodes[node];
        if (n->count) {
            test_leaf(bvh, n, ray, t_min, t_max, test, context, best_t,
                      best_id, cost);
        } else {
            double limit = closer(bvh_reach(*best_t), t_max), tl, tr;
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
            if (stack[sp].t <= bvh_reach(*best_t))
                break;
        }
        node = stack[sp].node;
    }
}

int rayo_bvh_any(const rayo_bvh *bvh, const rayo_ray *ray, double t_min,
                 double t_max, rayo_bvh_prim_fn test, const void *context,
                 rayo_bvh_cost *cost)
{
    uint32_t stack[BVH_STACK_SIZE];
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
    uint32_t stack[BVH_STACK_SIZE], depth_of[BVH_STACK_SIZE];
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
