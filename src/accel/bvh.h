/*
 * bvh.h - a bounding volume hierarchy over boxes, built with the surface
 * area heuristic; internal to the library (the scene uses it).
 *
 * The hierarchy knows only boxes and primitive numbers.  Its queries call
 * back into the owner to test a primitive, so it serves any shape; the
 * scene passes object indices as primitive numbers.  Nodes live in one
 * flat array (the two children of a node are adjacent) and are walked
 * with a small explicit stack; nothing is modified by a query, so any
 * number of threads may query one hierarchy at once.  Not for unbounded
 * shapes: planes stay outside.
 */
#ifndef RAYO_ACCEL_BVH_H
#define RAYO_ACCEL_BVH_H

#include <stddef.h>
#include <stdint.h>

#include "rayo/ray.h"
#include "rayo/status.h"

typedef struct rayo_bvh rayo_bvh;

/* An axis-aligned box. */
typedef struct rayo_box {
    double lo[3], hi[3];
} rayo_box;

/*
 * Tests primitive prim; returns its t with t_min < t < t_max, or INFINITY.
 */
typedef double (*rayo_bvh_prim_fn)(const void *context, uint32_t prim,
                                   const rayo_ray *ray, double t_min,
                                   double t_max);

/* What one query cost. */
typedef struct rayo_bvh_cost {
    uint64_t node_tests, prim_tests;
} rayo_bvh_cost;

/*
 * Builds over count boxes; primitive i is ids[i] with box boxes[i].
 * The boxes must hold their primitives with room to spare (see
 * rayo_box_pad).  count may be 0.
 */
rayo_status rayo_bvh_build(rayo_bvh **bvh, const rayo_box *boxes,
                           const uint32_t *ids, size_t count,
                           rayo_error *err);

/*
 * The same on up to threads threads (0 or 1: the caller's alone).  The
 * tree, its node array and its primitive order are the same for any
 * number of threads (bvh_build.c says why).
 */
rayo_status rayo_bvh_build_threads(rayo_bvh **bvh, const rayo_box *boxes,
                                   const uint32_t *ids, size_t count,
                                   unsigned threads, rayo_error *err);

/*
 * The same with the boxes made on demand: box(context, i, &b) writes
 * primitive i's box (padded), and may be called from any of the threads
 * at once.  Saves the caller an array of boxes.
 */
typedef void (*rayo_bvh_box_fn)(const void *context, size_t i,
                                rayo_box *box);
rayo_status rayo_bvh_build_from(rayo_bvh **bvh, rayo_bvh_box_fn box,
                                const void *context, const uint32_t *ids,
                                size_t count, unsigned threads,
                                rayo_error *err);

void rayo_bvh_free(rayo_bvh *bvh);

/* Grows a box outward by a relative margin that covers the rounding of
 * the ray-box and ray-shape arithmetic. */
void rayo_box_pad(rayo_box *box);

/*
 * Nearest primitive: *best_t and *best_id hold the best found so far
 * (INFINITY and UINT32_MAX for none) and are improved in place: a
 * primitive wins with a smaller t, or the same t and a smaller id.
 */
void rayo_bvh_nearest(const rayo_bvh *bvh, const rayo_ray *ray, double t_min,
                      double t_max, rayo_bvh_prim_fn test,
                      const void *context, double *best_t, uint32_t *best_id,
                      rayo_bvh_cost *cost);

/* 1 when any primitive answers a finite t; stops at the first. */
int rayo_bvh_any(const rayo_bvh *bvh, const rayo_ray *ray, double t_min,
                 double t_max, rayo_bvh_prim_fn test, const void *context,
                 rayo_bvh_cost *cost);

/* Shape of the tree, for tests and benchmarks. */
typedef struct rayo_bvh_info {
    size_t nodes, leaves, depth, max_leaf;
} rayo_bvh_info;

void rayo_bvh_describe(const rayo_bvh *bvh, rayo_bvh_info *info);

#endif
