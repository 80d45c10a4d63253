/*
 * bvh_wide_avx2.c - the wide walks (bvh_wide_walk.h) in AVX2: a node's
 * four boxes in one register of four doubles per plane, a leaf's spheres
 * four at a time.  Compiled for AVX2 by a target pragma (the rest of the
 * library stays baseline x86-64) and run only where the processor has
 * AVX2 (bvh_wide_avx2_runs; under valgrind, its emulated processor
 * decides).
 *
 * Why it is exact: the lanes do the scalar code's operations in its
 * order (bvh_wide_walk.h); vaddpd, vsubpd, vmulpd and vsqrtpd round each
 * result correctly, as the scalar instructions do; the target is "avx2"
 * alone, never "fma", so no multiply-add can be fused, and contraction is
 * off besides.
 */
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

typedef struct lane_ray {
    __m256d origin[3], inv[3], dir[3];
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
        r->origin[a] = _mm256_set1_pd(o[a]);
        r->inv[a] = _mm256_set1_pd(1.0 / d[a]);
        r->dir[a] = _mm256_set1_pd(d[a]);
        int high = signbit(d[a]) != 0;
        r->near[a] = (3 * high + a) * BVH_WIDE_LANES;
        r->far[a] = (3 * (1 - high) + a) * BVH_WIDE_LANES;
    }
}

/* One axis: narrows [tn, tf] in all four lanes. */
#define LANE_SLAB(a)                                                         \
    do {                                                                     \
        __m256d nd = _mm256_cvtps_pd(_mm_load_ps(b + r->near[a]));           \
        __m256d fd = _mm256_cvtps_pd(_mm_load_ps(b + r->far[a]));            \
        tn = _mm256_max_pd(                                                  \
            _mm256_mul_pd(_mm256_sub_pd(nd, r->origin[a]), r->inv[a]), tn);  \
        tf = _mm256_min_pd(                                                  \
            _mm256_mul_pd(_mm256_sub_pd(fd, r->origin[a]), r->inv[a]), tf);  \
    } while (0)

static inline unsigned lane_boxes(const bvh_wide_node *n, const lane_ray *r,
                                  double t_min, double t_max, double *entry)
{
    const float *b = &n->box[0][0][0];
    __m256d tn = _mm256_set1_pd(t_min), tf = _mm256_set1_pd(t_max);
    LANE_SLAB(0);
    LANE_SLAB(1);
    LANE_SLAB(2);
    _mm256_storeu_pd(entry, tn);
    return (unsigned)_mm256_movemask_pd(_mm256_cmp_pd(tn, tf, _CMP_LE_OQ));
}

static inline unsigned lane_spheres(const struct bvh_wide *w, uint32_t first,
                                    uint32_t count, const lane_ray *r,
                                    double t_min, double *t)
{
    __m256d tmin = _mm256_set1_pd(t_min), zero = _mm256_setzero_pd();
    __m256d inf = _mm256_set1_pd(INFINITY);
    unsigned mask = 0;
    uint32_t k;
    for (k = 0; k < count; k += 4) {
        uint32_t at = first + k;
        __m256d lx = _mm256_sub_pd(_mm256_loadu_pd(w->cx + at), r->origin[0]);
        __m256d ly = _mm256_sub_pd(_mm256_loadu_pd(w->cy + at), r->origin[1]);
        __m256d lz = _mm256_sub_pd(_mm256_loadu_pd(w->cz + at), r->origin[2]);
        __m256d beta = _mm256_add_pd(
            _mm256_add_pd(_mm256_mul_pd(lx, r->dir[0]),
                          _mm256_mul_pd(ly, r->dir[1])),
            _mm256_mul_pd(lz, r->dir[2]));
        __m256d ll = _mm256_add_pd(
            _mm256_add_pd(_mm256_mul_pd(lx, lx), _mm256_mul_pd(ly, ly)),
            _mm256_mul_pd(lz, lz));
        __m256d delta = _mm256_add_pd(
            _mm256_sub_pd(_mm256_mul_pd(beta, beta), ll),
            _mm256_loadu_pd(w->rr + at));
        __m256d met = _mm256_cmp_pd(delta, zero, _CMP_GE_OQ);
        __m256d root, near, far, cn, cf, tt;
        if (_mm256_movemask_pd(met) == 0)
            continue;
        root = _mm256_sqrt_pd(delta);
        near = _mm256_sub_pd(beta, root);
        far = _mm256_add_pd(beta, root);
        cn = _mm256_cmp_pd(near, tmin, _CMP_GT_OQ);
        cf = _mm256_cmp_pd(far, tmin, _CMP_GT_OQ);
        tt = _mm256_blendv_pd(_mm256_blendv_pd(inf, far, cf), near, cn);
        _mm256_storeu_pd(t + k, tt);
        mask |= (unsigned)_mm256_movemask_pd(
                    _mm256_and_pd(met, _mm256_or_pd(cn, cf)))
                << k;
    }
    return mask & ((1u << count) - 1);
}

#define WIDE_NEAREST bvh_wide_nearest_avx2
#define WIDE_ANY bvh_wide_any_avx2
#include "bvh_wide_walk.h"

#ifdef __clang__
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif

int bvh_wide_avx2_runs(void)
{
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") != 0;
}

#else

int bvh_wide_avx2_runs(void)
{
    return 0;
}

void bvh_wide_nearest_avx2(const struct bvh_wide *wide, const rayo_ray *ray,
                           double t_min, double t_max, rayo_bvh_prim_fn test,
                           const void *context, double *best_t,
                           uint32_t *best_id, rayo_bvh_cost *cost)
{
    (void)wide, (void)ray, (void)t_min, (void)t_max, (void)test;
    (void)context, (void)best_t, (void)best_id, (void)cost;
}

int bvh_wide_any_avx2(const struct bvh_wide *wide, const rayo_ray *ray,
                      double t_min, double t_max, uint32_t skip,
                      rayo_bvh_prim_fn test, const void *context,
                      rayo_bvh_cost *cost)
{
    (void)wide, (void)ray, (void)t_min, (void)t_max, (void)skip;
    (void)test, (void)context, (void)cost;
    return -1;
}

#endif
