/*
 * bvh_wide_impl.h - the layout of the hierarchy's 4-wide copy, shared by
 * the file that makes it (bvh_wide.c) and the walks that read it
 * (simd/bvh_wide_sse2.c, simd/bvh_wide_avx2.c, through
 * simd/bvh_wide_walk.h); internal to src/accel.
 *
 * A wide node holds the boxes of up to four children as floats, the very
 * floats of the binary nodes they come from, laid out by side, axis and
 * lane, so one load gives an axis's low (or high) planes of all four
 * children.  A child is an interior wide node or a binary leaf: a range
 * of positions in the binary tree's prims array.  The spheres of the
 * tree, in that same leaf order, are copied into arrays of doubles (centre
 * x, y, z and radius squared, computed as rayo_sphere_intersect computes
 * it), padded at the end so a walk may load four lanes from any leaf.
 */
#ifndef RAYO_ACCEL_BVH_WIDE_IMPL_H
#define RAYO_ACCEL_BVH_WIDE_IMPL_H

#include "bvh_impl.h"
#include "bvh_wide.h"

#define BVH_WIDE_LANES 4
/* A leaf's count has this bit when not all of its primitives are
 * spheres: the walk then calls the owner's test for each. */
#define BVH_WIDE_MIXED 0x8000u
#define BVH_WIDE_COUNT 0x7fffu
/* Each wide node pushes at most three children, and wide paths are no
 * longer than binary ones. */
#define BVH_WIDE_STACK (3 * BVH_STACK_SIZE)

/* 128 bytes, two cache lines. */
typedef struct bvh_wide_node {
    float box[2][3][BVH_WIDE_LANES]; /* [0]: low planes, [1]: high; by axis,
                                        then child */
    uint32_t child[BVH_WIDE_LANES];  /* interior: wide node; leaf: first
                                        position in prims */
    uint16_t count[BVH_WIDE_LANES];  /* 0: interior; leaf: primitives, with
                                        BVH_WIDE_MIXED */
    uint32_t lanes;                  /* children present: bits 0-3 */
    uint32_t lane_count;             /* how many */
} bvh_wide_node;

struct bvh_wide {
    bvh_wide_node *nodes; /* [0] is the root */
    size_t node_count;
    /* By position in prims, count + BVH_WIDE_LANES of each; spheres only
     * where their leaf has no BVH_WIDE_MIXED. */
    double *cx, *cy, *cz, *rr;
    unsigned char *sphere; /* by position: 1 where the arrays hold a sphere */
    const uint32_t *ids; /* the binary tree's prims */
};

#endif
