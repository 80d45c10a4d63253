/*
 * bvh_build_impl.h - the hierarchy builder's insides, shared by its
 * three files: the items and the top-down recursion (bvh_build.c), the
 * surface area heuristic's binning and partition (bvh_build_sah.c), and
 * the subtrees other threads build and their stitching into one array
 * (bvh_build_tasks.c).  Internal to src/accel.
 */
#ifndef RAYO_ACCEL_BVH_BUILD_IMPL_H
#define RAYO_ACCEL_BVH_BUILD_IMPL_H

#include "bvh_impl.h"
#include "bvh_vec4.h"

#include <math.h>
#include <pthread.h>
#include <stddef.h>
#include <stdint.h>

#define BINS 16
#define MAX_LEAF 8
/* Nodes this large, and larger than a thread's share of the whole, are
 * binned and partitioned by every thread at once (bvh_build_top.c). */
#define TOP_MIN 4096
/* Right children this large become tasks for other threads. */
#define SPAWN_MIN 1024
/* The nodes a task's array first holds (32 bytes each), at most. */
#define TASK_FIRST_NODES 4096
/* A placeholder node: its subtree is task number `first`. */
#define NODE_TASK UINT32_MAX

/* One primitive's box as floats rounded outward; lane 3 is 0. */
typedef struct item {
    float lo[4], hi[4];
} item;

/* The nodes of a tree of n items (at most 2 n - 1) fit in the items'
 * block (build_all). */
_Static_assert(sizeof(bvh_node) <= sizeof(item), "nodes fit in items");

typedef struct fbox {
    float lo[4], hi[4];
} fbox;

/* A node to build: its items, where they are, its bounds. */
typedef struct span {
    size_t begin, end;
    unsigned depth;
    int side;           /* the item array holding them (builder) */
    fbox bounds, centres;
} span;

/* A subtree built by one thread into its own node array. */
typedef struct task {
    span root;
    bvh_node *nodes;    /* nodes[0] is the root; pairs from 1 */
    size_t count, capacity;
    /* subtrees handed to other tasks: which, and before which of this
     * task's nodes the serial build would have made theirs */
    struct spawn {
        uint32_t task;
        uint32_t at;
        uint32_t slot; /* its placeholder among this task's nodes */
    } *spawns;
    size_t spawn_count, spawn_capacity;
    uint32_t *map; /* stitching: each node's place in the final array */
} task;

/* Items move between two arrays: a partition reads a node's items from
 * one and writes its children's, in the same places, to the other. */
typedef struct builder {
    item *items[2];
    uint32_t *index[2];         /* each item's primitive, moved along */
    uint32_t *prims;            /* leaves' primitives, in leaf order */
    rayo_bvh_box_fn box;        /* where the boxes come from */
    const void *box_context;
    unsigned threads;
    size_t total;               /* primitives in the whole tree */
    pthread_mutex_t lock;
    pthread_cond_t changed;
    task **tasks;               /* every task, by number */
    size_t task_count, task_capacity;
    uint32_t *pending;          /* tasks not yet started (a stack) */
    size_t pending_count;
    size_t busy;                /* tasks being built */
    int failed;                 /* out of memory somewhere */
} builder;

static inline vec4f v4_infinity(void) { return v4_set1(INFINITY); }

static inline void fbox_set(fbox *b, vec4f lo, vec4f hi)
{
    v4_store(b->lo, lo);
    v4_store(b->hi, hi);
}

/* A box holding nothing: the start of a union. */
static inline void fbox_empty(fbox *b)
{
    fbox_set(b, v4_infinity(), v4_set1(-INFINITY));
}

/* into grown to hold from, which comes after it: on a tie (-0 and +0)
 * into's bits stay, as in one pass over both in order. */
static inline void fbox_grow(fbox *into, const fbox *from)
{
    fbox_set(into, v4_min(v4_load(from->lo), v4_load(into->lo)),
             v4_max(v4_load(from->hi), v4_load(into->hi)));
}


/* How one node's centres are sorted into bins along each axis. */
typedef struct binning {
    size_t count; /* bins: BINS, or fewer for a node of few items */
    vec4f lo;     /* the lowest centre (lo + hi) on each axis */
    vec4f scale;  /* bins per unit; 0 on an axis not binned, and lane 3 */
    vec4f top;    /* count - 1 */
    int binned[3];
    int axes;     /* how many axes have a positive, finite extent */
} binning;

typedef struct split {
    int axis;           /* < 0: no useful split found */
    int32_t bin;        /* items in bins < bin go left */
    double cost;
    fbox left, right;   /* the children's bounds */
    size_t left_count;
} split;

/* ---- the surface area heuristic (bvh_build_sah.c) --------------------- */

/* How a node of `items` items with those centre bounds is binned. */
void bvh_binning_make(binning *g, const fbox *centres, size_t items);

/* Items counted and bounded by bin, along each axis. */
typedef struct bvh_bins {
    vec4f lo[3][BINS], hi[3][BINS];
    size_t count[3][BINS];
} bvh_bins;

/* Empties the first `bins` bins of each axis. */
void bvh_bins_clear(bvh_bins *s, size_t bins);

/* Adds items [begin, end) to the bins (the same as adding them one by
 * one after those already there). */
void bvh_bins_fill(const item *items, size_t begin, size_t end,
                   const binning *g, bvh_bins *s);

/* Adds the bins of items that come after into's (bvh_build_top.c). */
void bvh_bins_merge(bvh_bins *into, const bvh_bins *from, size_t bins);

/* The cheapest split the bins allow; best->axis < 0 when there is none.
 * area: half the node's surface area. */
void bvh_bins_best(const bvh_bins *s, const binning *g, double area,
                   split *best);

/* Bins a node's items along every binned axis at once and finds the
 * cheapest split; best->axis < 0 when there is none.  area: half the
 * node's surface area. */
void bvh_find_split(const builder *b, const span *r, const binning *g,
                    double area, split *best);

/* Moves items [begin, end) of array `side` to the other array, those
 * going left from left_at on, the others from right_at on, in order;
 * the centre bounds of each. */
void bvh_partition_range(builder *b, int side, size_t begin, size_t end,
                         const binning *g, const split *s, size_t left_at,
                         size_t right_at, fbox *left_c, fbox *right_c);

/* Moves the node's items to the other item array, the left ones first,
 * in order; the children's centre bounds; returns the boundary. */
size_t bvh_partition(builder *b, const span *r, const binning *g,
                     const split *s, fbox *left_c, fbox *right_c);

/* ---- a large node on every thread (bvh_build_top.c) -------------------- */

/* Whether node r is cut by every thread at once. */
int bvh_top_wanted(const builder *b, const span *r);

/* bvh_find_split and then, when it finds a split, bvh_partition, on
 * b->threads threads, with the same results bit for bit; *boundary the
 * partition's.  0 when out of memory (nothing done: cut it alone). */
int bvh_top_cut(builder *b, const span *r, const binning *g, double area,
                split *best, fbox *left_c, fbox *right_c, size_t *boundary);

/* Bounds and centre bounds of items [begin, end) of array `side`. */
void bvh_measure(const builder *b, int side, size_t begin, size_t end,
                 fbox *bounds, fbox *centres);

/* ---- the recursion (bvh_build.c) -------------------------------------- */

/* Builds the node t->nodes[local] over r; 0 when out of memory. */
int bvh_build_node(builder *b, task *t, size_t local, const span *r);

/* ---- tasks (bvh_build_tasks.c) ----------------------------------------- */

/* A task over r, its root node made; NULL when out of memory. */
task *bvh_task_new(const span *r);
void bvh_task_free(task *t);

/* Hands the subtree at parent->nodes[local] to any thread as task
 * *number; 0 when out of memory.  The parent's node becomes a
 * placeholder. */
int bvh_spawn(builder *b, task *parent, size_t local, const span *r,
              uint32_t *number);

/* Notes that task number's nodes go before t's next node; 0 when out of
 * memory. */
int bvh_record_spawn(task *t, uint32_t number, size_t slot);

/* Builds the tree from its root task on b->threads threads, into
 * bvh->nodes, the same bytes for any number of threads. */
rayo_status bvh_build_all(builder *b, task *root, rayo_bvh *bvh);

#endif
