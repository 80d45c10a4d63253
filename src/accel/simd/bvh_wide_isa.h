/*
 * bvh_wide_isa.h - the wide walks, one pair per instruction set, each in
 * its own file (bvh_wide_sse2.c, bvh_wide_avx2.c) from the one template
 * bvh_wide_walk.h; bvh_wide.c chooses among them.  Internal to
 * src/accel.
 */
#ifndef RAYO_ACCEL_BVH_WIDE_ISA_H
#define RAYO_ACCEL_BVH_WIDE_ISA_H

#include "../bvh_wide_impl.h"

/* 1 when this build has the SSE2 walk (x86-64). */
int bvh_wide_sse2_built(void);
/* 1 when this build has the AVX2 walk and the processor runs it. */
int bvh_wide_avx2_runs(void);
/* 1 when this build has the AVX2 packet walks (bvh_packet_avx2.c). */
int bvh_packet_avx2_built(void);

void bvh_wide_nearest_sse2(const struct bvh_wide *wide, const rayo_ray *ray,
                           double t_min, double t_max, rayo_bvh_prim_fn test,
                           const void *context, double *best_t,
                           uint32_t *best_id, rayo_bvh_cost *cost);
int bvh_wide_any_sse2(const struct bvh_wide *wide, const rayo_ray *ray,
                      double t_min, double t_max, uint32_t skip,
                      rayo_bvh_prim_fn test, const void *context,
                      rayo_bvh_cost *cost);
void bvh_wide_nearest_avx2(const struct bvh_wide *wide, const rayo_ray *ray,
                           double t_min, double t_max, rayo_bvh_prim_fn test,
                           const void *context, double *best_t,
                           uint32_t *best_id, rayo_bvh_cost *cost);
int bvh_wide_any_avx2(const struct bvh_wide *wide, const rayo_ray *ray,
                      double t_min, double t_max, uint32_t skip,
                      rayo_bvh_prim_fn test, const void *context,
                      rayo_bvh_cost *cost);

#endif
