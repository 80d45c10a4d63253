/*
 * bvh_impl.h - the hierarchy's layout, shared by its builder
 * (bvh_build.c) and its walks (bvh.c); internal to src/accel.
 *
 * Nodes live in one flat array (the two children of an interior node are
 * adjacent) and hold their boxes as floats rounded outward: 32 bytes a
 * node, two to a cache line, and never a smaller box than the doubles
 * they stand for.  The builder keeps the depth below BVH_MAX_DEPTH, so
 * the walks' fixed stacks of BVH_STACK_SIZE entries suffice.
 */
#ifndef RAYO_ACCEL_BVH_IMPL_H
#define RAYO_ACCEL_BVH_IMPL_H

#include "bvh.h"

/* The builder cuts nodes in halves below this depth (bvh_build.c), so
 * no path is longer than BVH_SAH_DEPTH_LIMIT + 32 nodes. */
#define BVH_SAH_DEPTH_LIMIT 48
#define BVH_STACK_SIZE 128

/* 32 bytes, two to a cache line.  Bounds are floats rounded outward, so
 * each float box holds the double box it stands for. */
typedef struct bvh_node {
    float bounds[2][3]; /* [0]: low corner, [1]: high corner */
    uint32_t first; /* interior: left child (right is first + 1);
                       leaf: first entry in prims */
    uint32_t count; /* primitives in a leaf; 0 for an interior node */
} bvh_node;

/*
 * How far a box may begin past the best hit so far and still be entered
 * by the nearest-hit walks: a little past it.  A box is only as sure as
 * its padding (rayo_box_pad), and a flat box at coordinate 0 gets none:
 * the box of a triangle in the plane y = 0 has the hit's own t as its
 * entry, computed another way, an ulp or two either side of the
 * triangle's t.  With the best hit exactly there (another triangle
 * sharing the edge, hit at the same t) the walk that met the higher
 * object first would then skip the lower one's box, and the answer would
 * hang on the order of the walk.  2^-40 relative (some 4,000 ulps) keeps
 * every walk's answer the smallest (t, object) of all, whatever the
 * order, and costs nothing measurable.
 */
static inline double bvh_reach(double best)
{
    return best + (best < 0 ? -best : best) * 0x1p-40;
}

struct rayo_bvh {
    bvh_node *nodes;
    size_t node_count;
    uint32_t *prims; /* primitive ids in leaf order */
    struct bvh_wide *wide; /* the fast walks' copy (bvh_wide.h), or NULL;
                              the builder's calloc leaves it NULL */
};

#endif
