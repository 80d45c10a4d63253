/*
 * bvh_wide_sse2.c - the wide walks (bvh_wide_walk.h) in SSE2, which
 * every x86-64 processor has: a node's four boxes in two registers of
 * two doubles per plane, a leaf's spheres two at a time.
 *
 * Why it is exact: the lanes do the scalar code's operations in its
 * order (bvh_wide_walk.h); SSE2's addpd, subpd, mulpd, divsd and sqrtpd
 * round each result correctly as the scalar instructions do; contraction
 * into fused multiply-adds is off (and FMA is never enabled here).  Built
 * only on x86-64, where the scalar code itself computes in SSE2 doubles
 * (no x87 excess precision); elsewhere this file is empty and the binary
 * walk runs.
 */
#include "bvh_wide_isa.h"

#if defined(__x86_64__) && defined(__SSE2__) && defined(__GNUC__)

#include <emmintrin.h>
#include <math.h>

#ifdef __clang__
#pragma STDC FP_CONTRACT OFF
#endif

typedef struct lane_ray {
    __m128d origin[3], inv[3], dir[3];
    /* per axis, where in a node's box (as floats) the planes the ray
     * meets first (near) and last (far) begin */
    int near[3], far[3];
} lane_ray;

static inline void lane_ray_init(lane_ray *r, const rayo_ray *ray)
{
    double o[3], d[3];
    int a;
    o[0] = ray->origin.x;
    o[1] = ray->origin.y;
    o[2] = ray->origin.z;
    d[0] = ray->direction.x;
    d[1] = ray->direction.y;
    d[2] = ray->direction.z;
    for (a = 0; a < 3; a++) {
        r->origin[a] = _mm_set1_pd(o[a]);
        r->inv[a] = _mm_set1_pd(1.0 / d[a]);
        r->dir[a] = _mm_set1_pd(d[a]);
        int high = signbit(d[a]) != 0;
        r->near[a] = (3 * high + a) * BVH_WIDE_LANES;
        r->far[a] = (3 * (1 - high) + a) * BVH_WIDE_LANES;
    }
}

/* One axis: narrows [tn, tf] in all four lanes (two registers). */
#define LANE_SLAB(a)                                                         \
    do {                                                                     \
        __m128 nf = _mm_load_ps(b + r->near[a]);                             \
        __m128 ff = _mm_load_ps(b + r->far[a]);                              \
        __m128d n0 = _mm_cvtps_pd(nf);                                       \
        __m128d n1 = _mm_cvtps_pd(_mm_movehl_ps(nf, nf));                    \
        __m128d f0 = _mm_cvtps_pd(ff);                                       \
        __m128d f1 = _mm_cvtps_pd(_mm_movehl_ps(ff, ff));                    \
        tn0 = _mm_max_pd(                                                    \
            _mm_mul_pd(_mm_sub_pd(n0, r->origin[a]), r->inv[a]), tn0);       \
        tn1 = _mm_max_pd(                                                    \
            _mm_mul_pd(_mm_sub_pd(n1, r->origin[a]), r->inv[a]), tn1);       \
        tf0 = _mm_min_pd(                                                    \
            _mm_mul_pd(_mm_sub_pd(f0, r->origin[a]), r->inv[a]), tf0);       \
        tf1 = _mm_min_pd(                                                    \
            _mm_mul_pd(_mm_sub_pd(f1, r->origin[a]), r->inv[a]), tf1);       \
    } while (0)

static inline unsigned lane_boxes(const bvh_wide_node *n, const lane_ray *r,
                                  double t_min, double t_max, double *entry)
{
    const float *b = &n->box[0][0][0];
    __m128d tn0 = _mm_set1_pd(t_min), tn1 = tn0;
    __m128d tf0 = _mm_set1_pd(t_max), tf1 = tf0;
    LANE_SLAB(0);
    LANE_SLAB(1);
    LANE_SLAB(2);
    _mm_storeu_pd(entry, tn0);
    _mm_storeu_pd(entry + 2, tn1);
    return (unsigned)_mm_movemask_pd(_mm_cmple_pd(tn0, tf0)) |
           (unsigned)_mm_movemask_pd(_mm_cmple_pd(tn1, tf1)) << 2;
}

static inline unsigned lane_spheres(const struct bvh_wide *w, uint32_t first,
                                    uint32_t count, const lane_ray *r,
                                    double t_min, double *t)
{
    __m128d tmin = _mm_set1_pd(t_min), zero = _mm_setzero_pd();
    __m128d inf = _mm_set1_pd(INFINITY);
    unsigned mask = 0;
    uint32_t k;
    for (k = 0; k < count; k += 2) {
        uint32_t at = first + k;
        __m128d lx = _mm_sub_pd(_mm_loadu_pd(w->cx + at), r->origin[0]);
        __m128d ly = _mm_sub_pd(_mm_loadu_pd(w->cy + at), r->origin[1]);
        __m128d lz = _mm_sub_pd(_mm_loadu_pd(w->cz + at), r->origin[2]);
        __m128d beta = _mm_add_pd(
            _mm_add_pd(_mm_mul_pd(lx, r->dir[0]), _mm_mul_pd(ly, r->dir[1])),
            _mm_mul_pd(lz, r->dir[2]));
        __m128d ll = _mm_add_pd(
            _mm_add_pd(_mm_mul_pd(lx, lx), _mm_mul_pd(ly, ly)),
            _mm_mul_pd(lz, lz));
        __m128d delta = _mm_add_pd(_mm_sub_pd(_mm_mul_pd(beta, beta), ll),
                                   _mm_loadu_pd(w->rr + at));
        __m128d met = _mm_cmpge_pd(delta, zero), root, near, far, cn, cf, tt;
        if (_mm_movemask_pd(met) == 0)
            continue;
        root = _mm_sqrt_pd(delta);
        near = _mm_sub_pd(beta, root);
        far = _mm_add_pd(beta, root);
        cn = _mm_cmpgt_pd(near, tmin);
        cf = _mm_cmpgt_pd(far, tmin);
        tt = _mm_or_pd(_mm_and_pd(cf, far), _mm_andnot_pd(cf, inf));
        tt = _mm_or_pd(_mm_and_pd(cn, near), _mm_andnot_pd(cn, tt));
        _mm_storeu_pd(t + k, tt);
        mask |= (unsigned)_mm_movemask_pd(_mm_and_pd(met, _mm_or_pd(cn, cf)))
                << k;
    }
    return mask & ((1u << count) - 1);
}

#define WIDE_NEAREST bvh_wide_nearest_sse2
#define WIDE_ANY bvh_wide_any_sse2
#include "bvh_wide_walk.h"

int bvh_wide_sse2_built(void)
{
    return 1;
}

#else

int bvh_wide_sse2_built(void)
{
    return 0;
}

void bvh_wide_nearest_sse2(const struct bvh_wide *wide, const rayo_ray *ray,
                           double t_min, double t_max, rayo_bvh_prim_fn test,
                           const void *context, double *best_t,
                           uint32_t *best_id, rayo_bvh_cost *cost)
{
    (void)wide, (void)ray, (void)t_min, (void)t_max, (void)test;
    (void)context, (void)best_t, (void)best_id, (void)cost;
}

int bvh_wide_any_sse2(const struct bvh_wide *wide, const rayo_ray *ray,
                      double t_min, double t_max, uint32_t skip,
                      rayo_bvh_prim_fn test, const void *context,
                      rayo_bvh_cost *cost)
{
    (void)wide, (void)ray, (void)t_min, (void)t_max, (void)skip;
    (void)test, (void)context, (void)cost;
    return -1;
}

#endif
