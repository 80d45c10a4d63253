/*
 * bvh_packet_avx2.c - the packet walks of bvh_packet.h in AVX2: four
 * rays, one to a lane of a register of four doubles, down the binary
 * tree together.
 *
 * A packet enters a node when one of its rays does, and carries the
 * mask of the rays that did (a ray outside a box is outside its
 * children's boxes too, which the builder makes to lie inside it).  Box
 * tests are lane by lane those of bvh.c's slab(): each ray's near plane
 * chosen by the sign of its own direction (blendv reads the sign bit,
 * as signbit() does), the float plane widened to double, minus the
 * origin, times the reciprocal, maxpd and minpd keeping the running
 * bound on NaN.  Sphere tests are lane by lane rayo_sphere_intersect's
 * operations in its order (bvh_wide_walk.h gives it), with no FMA (the
 * target is "avx2" alone, contraction off) and a correctly rounded
 * sqrt.  Every ray keeps its own best (t, id) with bvh.c's rules, prunes
 * with its own best, and a leaf is tested for the rays that entered it;
 * so each ray's answer is what the single-ray walk gives, and which ray
 * shares a packet with which changes the work, never an answer.
 */
#include "../bvh_packet.h"
#include "../bvh_wide_impl.h"
#include "bvh_wide_isa.h"

#if defined(__x86_64__) && defined(__GNUC__)

#include <immintrin.h>
#include <math.h>

#ifdef __clang__
#pragma STDC FP_CONTRACT OFF
#pragma clang attribute push(__attribute__((target("avx2"))), \
                             apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx2")
#endif

typedef struct packet_ray {
    __m256d origin[3], dir[3], inv[3];
} packet_ray;

static const unsigned char bits_in[16] = {0, 1, 1, 2, 1, 2, 2, 3,
                                          1, 2, 2, 3, 2, 3, 3, 4};

static inline void packet_ray_init(packet_ray *p, const rayo_ray *rays,
                                   unsigned lanes)
{
    double o[3][RAYO_BVH_PACKET], d[3][RAYO_BVH_PACKET];
    unsigned k, spare = (unsigned)__builtin_ctz(lanes);
    int a;
    for (k = 0; k < RAYO_BVH_PACKET; k++) {
        /* an unused lane repeats a used one: no stray NaN */
        const rayo_ray *r = &rays[(lanes >> k) & 1u ? k : spare];
        o[0][k] = r->origin.x;
        o[1][k] = r->origin.y;
        o[2][k] = r->origin.z;
        d[0][k] = r->direction.x;
        d[1][k] = r->direction.y;
        d[2][k] = r->direction.z;
    }
    for (a = 0; a < 3; a++) {
        p->origin[a] = _mm256_loadu_pd(o[a]);
        p->dir[a] = _mm256_loadu_pd(d[a]);
        p->inv[a] = _mm256_div_pd(_mm256_set1_pd(1.0), p->dir[a]);
    }
}

/* The box of node n for the four rays within [tn, tf] (per lane): the
 * mask of the rays that enter it, and where, in *entry. */
static inline unsigned packet_box(const bvh_node *n, const packet_ray *p,
                                  __m256d tn, __m256d tf, __m256d *entry)
{
    int a;
    for (a = 0; a < 3; a++) {
        __m256d lo = _mm256_set1_pd((double)n->bounds[0][a]);
        __m256d hi = _mm256_set1_pd((double)n->bounds[1][a]);
        __m256d near = _mm256_blendv_pd(lo, hi, p->dir[a]);
        __m256d far = _mm256_blendv_pd(hi, lo, p->dir[a]);
        tn = _mm256_max_pd(
            _mm256_mul_pd(_mm256_sub_pd(near, p->origin[a]), p->inv[a]), tn);
        tf = _mm256_min_pd(
            _mm256_mul_pd(_mm256_sub_pd(far, p->origin[a]), p->inv[a]), tf);
    }
    *entry = tn;
    return (unsigned)_mm256_movemask_pd(_mm256_cmp_pd(tn, tf, _CMP_LE_OQ));
}

/* The sphere at position at for the four rays: each ray's t > t_min
 * (INFINITY for none), as rayo_sphere_intersect computes it. */
static inline __m256d packet_sphere(const struct bvh_wide *w, uint32_t at,
                                    const packet_ray *p, __m256d tmin)
{
    __m256d lx = _mm256_sub_pd(_mm256_set1_pd(w->cx[at]), p->origin[0]);
    __m256d ly = _mm256_sub_pd(_mm256_set1_pd(w->cy[at]), p->origin[1]);
    __m256d lz = _mm256_sub_pd(_mm256_set1_pd(w->cz[at]), p->origin[2]);
    __m256d inf = _mm256_set1_pd(INFINITY);
    __m256d beta = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(lx, p->dir[0]),
                                               _mm256_mul_pd(ly, p->dir[1])),
                                 _mm256_mul_pd(lz, p->dir[2]));
    __m256d ll = _mm256_add_pd(
        _mm256_add_pd(_mm256_mul_pd(lx, lx), _mm256_mul_pd(ly, ly)),
        _mm256_mul_pd(lz, lz));
    __m256d delta =
        _mm256_add_pd(_mm256_sub_pd(_mm256_mul_pd(beta, beta), ll),
                      _mm256_set1_pd(w->rr[at]));
    __m256d met = _mm256_cmp_pd(delta, _mm256_setzero_pd(), _CMP_GE_OQ);
    __m256d root, near, far, t;
    if (_mm256_movemask_pd(met) == 0)
        return inf;
    root = _mm256_sqrt_pd(delta);
    near = _mm256_sub_pd(beta, root);
    far = _mm256_add_pd(beta, root);
    t = _mm256_blendv_pd(inf, far, _mm256_cmp_pd(far, tmin, _CMP_GT_OQ));
    t = _mm256_blendv_pd(t, near, _mm256_cmp_pd(near, tmin, _CMP_GT_OQ));
    return _mm256_blendv_pd(inf, t, met);
}

/* bvh_reach, ray by ray. */
static inline __m256d packet_reach(__m256d best)
{
    __m256d size = _mm256_andnot_pd(_mm256_set1_pd(-0.0), best);
    return _mm256_add_pd(best, _mm256_mul_pd(size, _mm256_set1_pd(0x1p-40)));
}

typedef struct packet_entry {
    __m256d entry; /* where each ray enters the node's box */
    uint32_t node;
    unsigned mask; /* the rays that enter it */
} packet_entry;

/* Of two children both entered, the one most of the rays enter first. */
static inline int left_first(unsigned both, __m256d el, __m256d er)
{
    unsigned left =
        both & (unsigned)_mm256_movemask_pd(_mm256_cmp_pd(el, er, _CMP_LE_OQ));
    return 2u * bits_in[left] >= bits_in[both];
}

static void nearest_leaf(const rayo_bvh *bvh, const bvh_node *n,
                         const packet_ray *p, const rayo_ray *rays,
                         unsigned mask, double t_min, double t_max,
                         rayo_bvh_prim_fn test, const void *context,
                         double *best_t, uint32_t *best_id)
{
    const struct bvh_wide *w = bvh->wide;
    __m256d tmin = _mm256_set1_pd(t_min);
    uint32_t k;
    for (k = 0; k < n->count; k++) {
        uint32_t at = n->first + k, id = bvh->prims[at];
        if (w->sphere[at]) {
            double t[RAYO_BVH_PACKET];
            unsigned m;
            __m256d tv = packet_sphere(w, at, p, tmin);
            m = mask & (unsigned)_mm256_movemask_pd(
                           _mm256_cmp_pd(tv, _mm256_set1_pd(t_max),
                                         _CMP_LT_OQ));
            if (m == 0)
                continue;
            _mm256_storeu_pd(t, tv);
            while (m) {
                unsigned lane = (unsigned)__builtin_ctz(m);
                m &= m - 1;
                if (t[lane] < best_t[lane] ||
                    (t[lane] == best_t[lane] && id < best_id[lane])) {
                    best_t[lane] = t[lane];
                    best_id[lane] = id;
                }
            }
        } else {
            unsigned m = mask;
            while (m) {
                unsigned lane = (unsigned)__builtin_ctz(m);
                double hi = best_t[lane] < t_max
                                ? nextafter(best_t[lane], INFINITY)
                                : t_max;
                double t = test(context, id, &rays[lane], t_min, hi);
                m &= m - 1;
                if (t < best_t[lane] ||
                    (t == best_t[lane] && t < INFINITY &&
                     id < best_id[lane])) {
                    best_t[lane] = t;
                    best_id[lane] = id;
                }
            }
        }
    }
}

void rayo_bvh_packet_nearest(const rayo_bvh *bvh, const rayo_ray *rays,
                             unsigned lanes, double t_min, double t_max,
                             rayo_bvh_prim_fn test, const void *context,
                             double *best_t, uint32_t *best_id)
{
    packet_entry stack[BVH_STACK_SIZE];
    size_t sp = 0;
    packet_ray p;
    __m256d tmin = _mm256_set1_pd(t_min), tmax = _mm256_set1_pd(t_max);
    __m256d best, entry;
    uint32_t node = 0;
    unsigned mask;
    lanes &= (1u << RAYO_BVH_PACKET) - 1;
    if (bvh->node_count == 0 || lanes == 0)
        return;
    packet_ray_init(&p, rays, lanes);
    best = _mm256_loadu_pd(best_t);
    mask = lanes & packet_box(&bvh->nodes[0], &p, tmin,
                              _mm256_min_pd(packet_reach(best), tmax),
                              &entry);
    if (mask == 0)
        return;
    for (;;) {
        const bvh_node *n = &bvh->nodes[node];
        if (n->count) {
            nearest_leaf(bvh, n, &p, rays, mask, t_min, t_max, test,
                         context, best_t, best_id);
            best = _mm256_loadu_pd(best_t);
        } else {
            __m256d limit = _mm256_min_pd(packet_reach(best), tmax), el, er;
            unsigned ml = mask & packet_box(&bvh->nodes[n->first], &p, tmin,
                                            limit, &el);
            unsigned mr = mask & packet_box(&bvh->nodes[n->first + 1], &p,
                                            tmin, limit, &er);
            if (ml && mr) {
                int left = left_first(ml & mr, el, er);
                stack[sp].node = left ? n->first + 1 : n->first;
                stack[sp].mask = left ? mr : ml;
                stack[sp].entry = left ? er : el;
                sp++;
                node = left ? n->first : n->first + 1;
                mask = left ? ml : mr;
                continue;
            }
            if (ml || mr) {
                node = ml ? n->first : n->first + 1;
                mask = ml ? ml : mr;
                continue;
            }
        }
        for (;;) {
            if (sp == 0)
                return;
            sp--;
            /* bvh.c's stack[sp].t <= bvh_reach(*best_t), ray by ray */
            mask = stack[sp].mask &
                   (unsigned)_mm256_movemask_pd(_mm256_cmp_pd(
                       stack[sp].entry, packet_reach(best), _CMP_LE_OQ));
            if (mask)
                break;
        }
        node = stack[sp].node;
    }
}

/* The rays of mask that a primitive of leaf n blocks. */
static unsigned any_leaf(const rayo_bvh *bvh, const bvh_node *n,
                         const packet_ray *p, const rayo_ray *rays,
                         unsigned mask, __m256d tmin, __m256d tmax,
                         const double *t_min, const double *t_max,
                         const uint32_t *skip, rayo_bvh_prim_fn test,
                         const void *context)
{
    const struct bvh_wide *w = bvh->wide;
    unsigned blocked = 0;
    uint32_t k;
    for (k = 0; k < n->count && mask; k++) {
        uint32_t at = n->first + k, id = bvh->prims[at];
        unsigned m;
        if (w->sphere[at]) {
            __m256d tv = packet_sphere(w, at, p, tmin);
            m = mask & (unsigned)_mm256_movemask_pd(
                           _mm256_cmp_pd(tv, tmax, _CMP_LT_OQ));
            while (m) {
                unsigned lane = (unsigned)__builtin_ctz(m);
                m &= m - 1;
                if (id != skip[lane]) {
                    blocked |= 1u << lane;
                    mask &= ~(1u << lane);
                }
            }
        } else {
            m = mask;
            while (m) {
                unsigned lane = (unsigned)__builtin_ctz(m);
                m &= m - 1;
                if (id != skip[lane] &&
                    test(context, id, &rays[lane], t_min[lane],
                         t_max[lane]) < INFINITY) {
                    blocked |= 1u << lane;
                    mask &= ~(1u << lane);
                }
            }
        }
    }
    return blocked;
}

unsigned rayo_bvh_packet_any(const rayo_bvh *bvh, const rayo_ray *rays,
                             unsigned lanes, const double *t_min,
                             const double *t_max, const uint32_t *skip,
                             rayo_bvh_prim_fn test, const void *context)
{
    packet_entry stack[BVH_STACK_SIZE];
    size_t sp = 0;
    packet_ray p;
    double lo[RAYO_BVH_PACKET], hi[RAYO_BVH_PACKET];
    __m256d tmin, tmax, entry;
    uint32_t node = 0;
    unsigned mask, blocked = 0, k;
    lanes &= (1u << RAYO_BVH_PACKET) - 1;
    if (bvh->node_count == 0 || lanes == 0)
        return 0;
    for (k = 0; k < RAYO_BVH_PACKET; k++) {
        unsigned use = (lanes >> k) & 1u ? k : (unsigned)__builtin_ctz(lanes);
        lo[k] = t_min[use];
        hi[k] = t_max[use];
    }
    packet_ray_init(&p, rays, lanes);
    tmin = _mm256_loadu_pd(lo);
    tmax = _mm256_loadu_pd(hi);
    mask = lanes & packet_box(&bvh->nodes[0], &p, tmin, tmax, &entry);
    if (mask == 0)
        return 0;
    for (;;) {
        const bvh_node *n = &bvh->nodes[node];
        mask &= ~blocked;
        if (mask == 0) {
            /* every ray here is blocked already */
        } else if (n->count) {
            blocked |= any_leaf(bvh, n, &p, rays, mask, tmin, tmax, t_min,
                                t_max, skip, test, context);
            if (blocked == lanes)
                return blocked;
        } else {
            __m256d el, er;
            unsigned ml =
                mask & packet_box(&bvh->nodes[n->first], &p, tmin, tmax, &el);
            unsigned mr = mask & packet_box(&bvh->nodes[n->first + 1], &p,
                                            tmin, tmax, &er);
            if (ml && mr) {
                /* nearer child first: near objects are likelier
                 * blockers */
                int left = left_first(ml & mr, el, er);
                stack[sp].node = left ? n->first + 1 : n->first;
                stack[sp].mask = left ? mr : ml;
                sp++;
                node = left ? n->first : n->first + 1;
                mask = left ? ml : mr;
                continue;
            }
            if (ml || mr) {
                node = ml ? n->first : n->first + 1;
                mask = ml ? ml : mr;
                continue;
            }
        }
        if (sp == 0)
            return blocked;
        sp--;
        node = stack[sp].node;
        mask = stack[sp].mask;
    }
}

#ifdef __clang__
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif

int bvh_packet_avx2_built(void)
{
    return 1;
}

#else

int bvh_packet_avx2_built(void)
{
    return 0;
}

void rayo_bvh_packet_nearest(const rayo_bvh *bvh, const rayo_ray *rays,
                             unsigned lanes, double t_min, double t_max,
                             rayo_bvh_prim_fn test, const void *context,
                             double *best_t, uint32_t *best_id)
{
    (void)bvh, (void)rays, (void)lanes, (void)t_min, (void)t_max;
    (void)test, (void)context, (void)best_t, (void)best_id;
}

unsigned rayo_bvh_packet_any(const rayo_bvh *bvh, const rayo_ray *rays,
                             unsigned lanes, const double *t_min,
                             const double *t_max, const uint32_t *skip,
                             rayo_bvh_prim_fn test, const void *context)
{
    (void)bvh, (void)rays, (void)lanes, (void)t_min, (void)t_max;
    (void)skip, (void)test, (void)context;
    return 0;
}

#endif
