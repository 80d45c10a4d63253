/*
 * bvh_wide.h - the fast walks of the hierarchy: a 4-wide copy of the
 * binary tree (bvh_impl.h), with the spheres of its leaves copied as
 * structures of arrays, walked with four box tests (and up to four
 * sphere tests) at once in SIMD lanes; internal to the library.
 *
 * The binary tree stays the reference: rayo_bvh_nearest and rayo_bvh_any
 * (bvh.c) walk it, and every fast walk must give their answers bit for
 * bit (docs/geometry.md, "Exactness").  Which walk runs is one setting
 * for the whole process, chosen once from the environment variable
 * RAYO_WALK (binary, sse2, avx2; unset or anything else: avx2 where the
 * processor has it, else binary) and changeable by tests with
 * rayo_bvh_walk_set.
 */
#ifndef RAYO_ACCEL_BVH_WIDE_H
#define RAYO_ACCEL_BVH_WIDE_H

#include <stddef.h>
#include <stdint.h>

#include "rayo/sphere.h"

#include "bvh.h"

struct bvh_wide; /* bvh_wide_impl.h */

typedef enum rayo_bvh_walk {
    RAYO_BVH_WALK_BINARY, /* bvh.c: the reference, one box at a time */
    RAYO_BVH_WALK_SSE2,   /* simd/bvh_wide_sse2.c: 4-wide, two lanes of
                             doubles */
    RAYO_BVH_WALK_AVX2    /* simd/bvh_wide_avx2.c: 4-wide, four lanes */
} rayo_bvh_walk;

/* The walk in use (RAYO_WALK, read once, or the last rayo_bvh_walk_set). */
rayo_bvh_walk rayo_bvh_walk_current(void);

/* 1 when this build and processor can run walk (binary always can). */
int rayo_bvh_walk_available(rayo_bvh_walk walk);

/* Chooses the walk for every later query; one not available falls back
 * to the best one that is.  Not for use while queries run (tests, the
 * bench). */
void rayo_bvh_walk_set(rayo_bvh_walk walk);

/* The walk's name (binary, sse2, avx2). */
const char *rayo_bvh_walk_name(rayo_bvh_walk walk);

/*
 * Sphere i of the owner's count spheres: *prim, its primitive number in
 * the tree (distinct spheres, distinct primitives), and *sphere.  Asked
 * in order of i, which may follow the owner's memory; by
 * rayo_bvh_widen_threads, from several threads at once, each asking
 * its own range of i in order.
 */
typedef void (*rayo_bvh_sphere_fn)(const void *context, size_t i,
                                   uint32_t *prim, rayo_sphere *sphere);

/*
 * Makes the wide copy of a built hierarchy (replacing any earlier one),
 * with the count spheres that sphere_at gives (every one a primitive of
 * the tree; the other primitives are tested through the walks' callback).
 * Without memory it makes none and returns RAYO_ERR_NOMEM; queries then
 * walk the binary tree, with the same answers.  Made on up to `threads`
 * threads (0 or 1: the calling one): the same copy, byte for byte, for
 * any number.
 */
rayo_status rayo_bvh_widen_threads(rayo_bvh *bvh,
                                   rayo_bvh_sphere_fn sphere_at,
                                   const void *context, size_t count,
                                   unsigned threads);

/*
 * rayo_bvh_nearest through the wide copy, when there is one and the walk
 * in use is not binary: returns 1 when it answered, 0 when the caller
 * must walk the binary tree.  Spheres are tested from the copy (test is
 * called for the other primitives only).
 */
int rayo_bvh_wide_nearest(const rayo_bvh *bvh, const rayo_ray *ray,
                          double t_min, double t_max, rayo_bvh_prim_fn test,
                          const void *context, double *best_t,
                          uint32_t *best_id, rayo_bvh_cost *cost);

/*
 * rayo_bvh_any through the wide copy: 1 (blocked) or 0 (clear) when it
 * answered, -1 when the caller must walk the binary tree.  Primitive
 * skip never blocks (UINT32_MAX: none); test must say INFINITY for it
 * too.
 */
int rayo_bvh_wide_any(const rayo_bvh *bvh, const rayo_ray *ray,
                      double t_min, double t_max, uint32_t skip,
                      rayo_bvh_prim_fn test, const void *context,
                      rayo_bvh_cost *cost);

/* Frees the wide copy (rayo_bvh_free calls it). */
void rayo_bvh_wide_free(struct bvh_wide *wide);

#endif
