/*
 * bvh_wide.c - the hierarchy's 4-wide copy (bvh_wide.h): made from the
 * binary tree once it is built, and the one setting that says which walk
 * the queries take.  The walks that read the copy are in simd/, one file
 * per instruction set; the binary walk (bvh.c) stays the reference they
 * answer exactly as.  On several threads (rayo_bvh_widen_threads) the
 * copy is the same bytes: the top levels are made by the caller, the
 * subtrees below into the blocks of the array one thread would have
 * given them.
 */
/*
 * Why the answers are the same.  The copy collapses the binary tree: a
 * wide node starts from a binary interior node's two children and, while
 * it has fewer than four, replaces its interior child of largest surface
 * area by that child's two children.  Every box of the copy is a box of
 * the binary tree, float for float, and every leaf is a binary leaf; only
 * the interior boxes skipped by the collapse are no longer tested.  Since
 * a binary child's box lies inside its parent's (the builder bounds each
 * node by the union of its primitives' boxes, rounded outward), a ray
 * that the binary walk would let into a leaf is let in by the wide walk
 * too, and both then take the smallest (t, object) over the same
 * candidates: the answers are the same bit for bit
 * (simd/bvh_wide_walk.h says why the lanes' arithmetic is the scalar
 * one).
 */
#include "bvh_packet.h"
#include "bvh_wide_impl.h"
#include "simd/bvh_wide_isa.h"

#include "../core/thread_start.h"

#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>

/*
 * The walk is chosen once per process, from RAYO_WALK (binary, sse2,
 * avx2), else the fastest one the processor runs: AVX2 (with packets,
 * bvh_packet.h) where __builtin_cpu_supports says so (the processor and
 * the system's saving of its registers), else the binary walk (the SSE2
 * wide walk, which any x86-64 runs, measured no faster than it: it stays
 * for RAYO_WALK=sse2, the tests and the bench).
 *
 * -1 until the environment is read.  Threads that read it at once all
 * store the same values; queries load them relaxed (a plain load).
 */
static atomic_int walk_in_use = -1;
static atomic_int packets_wanted = -1;

int rayo_bvh_walk_available(rayo_bvh_walk walk)
{
    switch (walk) {
    case RAYO_BVH_WALK_BINARY:
        return 1;
    case RAYO_BVH_WALK_SSE2:
        return bvh_wide_sse2_built();
    case RAYO_BVH_WALK_AVX2:
        return bvh_wide_avx2_runs();
    }
    return 0;
}

static rayo_bvh_walk best_available(rayo_bvh_walk walk)
{
    if (walk == RAYO_BVH_WALK_AVX2 &&
        !rayo_bvh_walk_available(RAYO_BVH_WALK_AVX2))
        walk = RAYO_BVH_WALK_SSE2;
    if (walk == RAYO_BVH_WALK_SSE2 &&
        !rayo_bvh_walk_available(RAYO_BVH_WALK_SSE2))
        walk = RAYO_BVH_WALK_BINARY;
    return walk;
}

static void walk_init(void)
{
    const char *name = getenv("RAYO_WALK");
    rayo_bvh_walk walk = RAYO_BVH_WALK_AVX2;
    if (name != NULL && strcmp(name, "binary") == 0)
        walk = RAYO_BVH_WALK_BINARY;
    else if (name != NULL && strcmp(name, "sse2") == 0)
        walk = RAYO_BVH_WALK_SSE2;
    else if (!rayo_bvh_walk_available(RAYO_BVH_WALK_AVX2))
        /* the SSE2 wide walk measured no faster than the binary one
         * (docs/performance.md), which needs no copy */
        walk = RAYO_BVH_WALK_BINARY;
    name = getenv("RAYO_PACKETS");
    atomic_store(&packets_wanted,
                 !(name != NULL && strcmp(name, "0") == 0));
    atomic_store(&walk_in_use, (int)best_available(walk));
}

static rayo_bvh_walk walk_loaded(void)
{
    return (rayo_bvh_walk)atomic_load_explicit(&walk_in_use,
                                               memory_order_relaxed);
}

rayo_bvh_walk rayo_bvh_walk_current(void)
{
    if (atomic_load(&walk_in_use) < 0)
        walk_init();
    return walk_loaded();
}

void rayo_bvh_walk_set(rayo_bvh_walk walk)
{
    (void)rayo_bvh_walk_current();
    atomic_store(&walk_in_use, (int)best_available(walk));
}

void rayo_bvh_packets_set(int on)
{
    (void)rayo_bvh_walk_current();
    atomic_store(&packets_wanted, on != 0);
}

/* Packets are AVX2 code: they run with the AVX2 walk (so RAYO_WALK=sse2
 * or binary runs no AVX2 at all, as on a processor without it). */
int rayo_bvh_packets_on(const rayo_bvh *bvh)
{
    return bvh != NULL && bvh->wide != NULL &&
           atomic_load_explicit(&packets_wanted, memory_order_relaxed) > 0 &&
           walk_loaded() == RAYO_BVH_WALK_AVX2 && bvh_packet_avx2_built();
}

const char *rayo_bvh_walk_name(rayo_bvh_walk walk)
{
    switch (walk) {
    case RAYO_BVH_WALK_BINARY:
        return "binary";
    case RAYO_BVH_WALK_SSE2:
        return "sse2";
    case RAYO_BVH_WALK_AVX2:
        return "avx2";
    }
    return "?";
}

void rayo_bvh_wide_free(struct bvh_wide *wide)
{
    if (wide == NULL)
        return;
    free(wide->nodes);
    free(wide->cx);
    free(wide->sphere);
    free(wide);
}

static double node_area(const bvh_node *n)
{
    double d[3];
    int a;
    for (a = 0; a < 3; a++)
        d[a] = (double)n->bounds[1][a] - (double)n->bounds[0][a];
    return d[0] * d[1] + d[1] * d[2] + d[2] * d[0];
}

typedef struct widener {
    const rayo_bvh *bvh;
    struct bvh_wide *wide;
} widener;

/* The leaf's count, with BVH_WIDE_MIXED when one of its primitives is
 * not a sphere of the arrays. */
static uint16_t leaf_count_of(const widener *w, const bvh_node *leaf)
{
    uint16_t count = (uint16_t)leaf->count;
    uint32_t k;
    /* The lanes test at most 2 x 4 spheres a leaf (simd/bvh_wide_walk.h);
     * a builder making bigger leaves gets the callback for them. */
    if (leaf->count > 2 * BVH_WIDE_LANES)
        return (uint16_t)(BVH_WIDE_MIXED |
                          (leaf->count & BVH_WIDE_COUNT));
    for (k = 0; k < leaf->count; k++)
        if (!w->wide->sphere[leaf->first + k])
            count |= BVH_WIDE_MIXED;
    return count;
}

/* Each primitive's position in prims (UINT32_MAX: none), *top the
 * largest primitive; NULL without memory. */
static uint32_t *positions(const rayo_bvh *bvh, size_t prims, uint32_t *top)
{
    uint32_t *position;
    size_t p;
    *top = 0;
    for (p = 0; p < prims; p++)
        if (bvh->prims[p] > *top)
            *top = bvh->prims[p];
    position = malloc(((size_t)*top + 1) * sizeof *position);
    if (position == NULL)
        return NULL;
    for (p = 0; p < (size_t)*top + 1; p++)
        position[p] = UINT32_MAX;
    for (p = 0; p < prims; p++)
        position[bvh->prims[p]] = (uint32_t)p;
    return position;
}

/* The owner's spheres begin to end into the arrays at their primitives'
 * positions in leaf order: in the owner's order, so the reads stream
 * and the scattered writes overlap (reading the spheres in leaf order,
 * each a dependent miss, took ten times longer).  Distinct spheres are
 * distinct primitives, so ranges may be copied at once. */
static void copy_spheres(struct bvh_wide *wide, const uint32_t *position,
                         uint32_t top, rayo_bvh_sphere_fn sphere_at,
                         const void *context, size_t begin, size_t end)
{
    size_t i;
    for (i = begin; i < end; i++) {
        uint32_t prim, at;
        rayo_sphere s;
        sphere_at(context, i, &prim, &s);
        if (prim > top || (at = position[prim]) == UINT32_MAX)
            continue;
        wide->cx[at] = s.center.x;
        wide->cy[at] = s.center.y;
        wide->cz[at] = s.center.z;
        wide->rr[at] = s.radius * s.radius;
        wide->sphere[at] = 1;
    }
}

/* Zeroes the arrays where no sphere was copied (other primitives, and
 * the lanes past the last), which the lanes read and leave out. */
static void clear_others(struct bvh_wide *wide, size_t size)
{
    size_t at;
    for (at = 0; at < size; at++)
        if (!wide->sphere[at])
            wide->cx[at] = wide->cy[at] = wide->cz[at] = wide->rr[at] = 0.0;
}

/* The children of the wide node made from binary node `binary`
 * (interior, or the root leaf of a one-leaf tree) into kids; how many. */
static unsigned collapse(const bvh_node *nodes, uint32_t binary,
                         uint32_t *kids)
{
    unsigned count = 0, k;
    if (nodes[binary].count) {
        kids[count++] = binary;
    } else {
        kids[count++] = nodes[binary].first;
        kids[count++] = nodes[binary].first + 1;
    }
    while (count < BVH_WIDE_LANES) {
        unsigned pick = BVH_WIDE_LANES;
        double best = -1.0;
        for (k = 0; k < count; k++) {
            const bvh_node *n = &nodes[kids[k]];
            double area = n->count ? -1.0 : node_area(n);
            if (!n->count && area > best) {
                best = area;
                pick = k;
            }
        }
        if (pick == BVH_WIDE_LANES)
            break;
        kids[count++] = nodes[kids[pick]].first + 1;
        kids[pick] = nodes[kids[pick]].first;
    }
    return count;
}

/* How many wide nodes the collapse of binary's subtree makes. */
static size_t wide_count(const bvh_node *nodes, uint32_t binary)
{
    uint32_t kids[BVH_WIDE_LANES];
    unsigned count = collapse(nodes, binary, kids), k;
    size_t total = 1;
    for (k = 0; k < count; k++)
        if (!nodes[kids[k]].count)
            total += wide_count(nodes, kids[k]);
    return total;
}

/* Fills wide node `index` with the lanes of binary node `binary` (as
 * collapse) and leaves the children for the caller; their count. */
static unsigned widen_lanes(widener *w, uint32_t binary, uint32_t index,
                            uint32_t *kids)
{
    const bvh_node *nodes = w->bvh->nodes;
    bvh_wide_node *out = &w->wide->nodes[index];
    unsigned count = collapse(nodes, binary, kids), k;
    int a, side;
    memset(out, 0, sizeof *out);
    for (k = 0; k < BVH_WIDE_LANES; k++)
        for (a = 0; a < 3; a++) {
            /* Empty lanes: a box no ray enters (and `lanes` leaves them
             * out anyway). */
            out->box[0][a][k] = INFINITY;
            out->box[1][a][k] = -INFINITY;
        }
    out->lanes = (1u << count) - 1;
    out->lane_count = count;
    for (k = 0; k < count; k++) {
        const bvh_node *n = &nodes[kids[k]];
        for (side = 0; side < 2; side++)
            for (a = 0; a < 3; a++)
                out->box[side][a][k] = n->bounds[side][a];
        if (n->count) {
            out->child[k] = n->first;
            out->count[k] = leaf_count_of(w, n);
        }
    }
    return count;
}

/* Makes the wide node for binary node `binary` at index *next, and its
 * subtree's after it in depth-first order (the order of one thread);
 * returns its index. */
static uint32_t widen_node(widener *w, uint32_t binary, uint32_t *next)
{
    const bvh_node *nodes = w->bvh->nodes;
    uint32_t index = (*next)++, kids[BVH_WIDE_LANES];
    unsigned count = widen_lanes(w, binary, index, kids), k;
    for (k = 0; k < count; k++)
        if (!nodes[kids[k]].count) {
            /* (the array is preallocated: recursion moves nothing) */
            uint32_t child = widen_node(w, kids[k], next);
            w->wide->nodes[index].child[k] = child;
        }
    return index;
}

/*
 * On several threads the copy is made in the same order, so the same
 * bytes: the wide nodes down to depth SPLIT_DEPTH are made by the
 * calling thread, and the subtrees below them (the frontier), each of
 * which one thread would make as a block of consecutive nodes, are
 * counted and then made on any thread into their blocks.
 */
#define SPLIT_DEPTH 3
#define FRONTIER_MAX 64 /* 4^SPLIT_DEPTH */
#define COPY_JOBS 16
#define WIDEN_THREADS_MIN 2048 /* primitives */

typedef struct splitter {
    widener *w;
    uint32_t frontier[FRONTIER_MAX]; /* binary roots, depth-first order */
    uint32_t start[FRONTIER_MAX];    /* their wide indices */
    size_t size[FRONTIER_MAX];       /* their wide node counts */
    unsigned count;
    atomic_uint taken;
    /* the phase: the frontier's counts, then the spheres in COPY_JOBS
     * ranges; or the frontier's nodes */
    enum { SPLIT_COUNT_COPY, SPLIT_MAKE } phase;
    const uint32_t *position;
    uint32_t top;
    rayo_bvh_sphere_fn sphere_at;
    const void *context;
    size_t spheres;
} splitter;

/* The frontier under binary node `binary`, at wide depth `depth`; how
 * many wide nodes lie above it. */
static size_t gather(splitter *s, uint32_t binary, int depth)
{
    const bvh_node *nodes = s->w->bvh->nodes;
    uint32_t kids[BVH_WIDE_LANES];
    unsigned count, k;
    size_t total = 1;
    if (depth == SPLIT_DEPTH) {
        s->frontier[s->count++] = binary;
        return 0;
    }
    count = collapse(nodes, binary, kids);
    for (k = 0; k < count; k++)
        if (!nodes[kids[k]].count)
            total += gather(s, kids[k], depth + 1);
    return total;
}

/* The wide nodes above the frontier, at *next on, the frontier's blocks
 * placed as they come (their sizes known); *at counts the frontier. */
static uint32_t widen_top(splitter *s, uint32_t binary, int depth,
                          uint32_t *next, unsigned *at)
{
    const bvh_node *nodes = s->w->bvh->nodes;
    uint32_t index = (*next)++, kids[BVH_WIDE_LANES];
    unsigned count = widen_lanes(s->w, binary, index, kids), k;
    for (k = 0; k < count; k++) {
        uint32_t child;
        if (nodes[kids[k]].count)
            continue;
        if (depth + 1 == SPLIT_DEPTH) {
            child = *next;
            s->start[*at] = child;
            *next += (uint32_t)s->size[(*at)++];
        } else {
            child = widen_top(s, kids[k], depth + 1, next, at);
        }
        s->w->wide->nodes[index].child[k] = child;
    }
    return index;
}

static unsigned split_jobs(const splitter *s)
{
    return s->phase == SPLIT_MAKE ? s->count : s->count + COPY_JOBS;
}

static void *split_worker(void *argument)
{
    splitter *s = argument;
    unsigned i, jobs = split_jobs(s);
    while ((i = atomic_fetch_add(&s->taken, 1)) < jobs) {
        if (s->phase == SPLIT_MAKE) {
            uint32_t next = s->start[i];
            (void)widen_node(s->w, s->frontier[i], &next);
        } else if (i < s->count) {
            s->size[i] = wide_count(s->w->bvh->nodes, s->frontier[i]);
        } else {
            i -= s->count;
            copy_spheres(s->w->wide, s->position, s->top, s->sphere_at,
                         s->context, s->spheres * i / COPY_JOBS,
                         s->spheres * (i + 1) / COPY_JOBS);
        }
    }
    return NULL;
}

/* Runs the phase on up to `threads` threads (the caller one of them). */
static void split_run(splitter *s, unsigned threads)
{
    unsigned jobs = split_jobs(s);
    atomic_store(&s->taken, 0);
    thread_run_all(threads < jobs ? threads : jobs, split_worker, s);
}

rayo_status rayo_bvh_widen_threads(rayo_bvh *bvh,
                                   rayo_bvh_sphere_fn sphere_at,
                                   const void *context, size_t count,
                                   unsigned threads)
{
    struct bvh_wide *wide;
    size_t prims = 0, i, capacity;
    widener w;
    splitter *s = NULL;
    uint32_t next = 0, top, *position;
    rayo_bvh_wide_free(bvh->wide);
    bvh->wide = NULL;
    (void)rayo_bvh_walk_current(); /* the queries read walk_in_use */
    if (bvh->node_count == 0)
        return RAYO_OK;
    for (i = 0; i < bvh->node_count; i++) {
        if (bvh->nodes[i].count > BVH_WIDE_COUNT)
            return RAYO_ERR_LIMIT; /* no copy: the binary walk serves */
        prims += bvh->nodes[i].count;
    }
    if (prims > SIZE_MAX / 4 / sizeof *wide->cx - BVH_WIDE_LANES)
        return RAYO_ERR_NOMEM;
    wide = calloc(1, sizeof *wide);
    if (wide == NULL)
        return RAYO_ERR_NOMEM;
    /* not calloc: the copy writes the spheres' places on the threads
     * (first writes of pages are what cost here) and clear_others the
     * rest */
    wide->cx = malloc(4 * (prims + BVH_WIDE_LANES) * sizeof *wide->cx);
    wide->sphere = calloc(prims + BVH_WIDE_LANES, 1);
    position = positions(bvh, prims, &top);
    if (threads > FRONTIER_MAX)
        threads = FRONTIER_MAX;
    if (prims < WIDEN_THREADS_MIN)
        threads = 1; /* starting threads would cost more */
    if (threads > 1)
        s = calloc(1, sizeof *s);
    if (wide->cx == NULL || wide->sphere == NULL || position == NULL) {
        rayo_bvh_wide_free(wide);
        free(position);
        free(s);
        return RAYO_ERR_NOMEM;
    }
    wide->cy = wide->cx + (prims + BVH_WIDE_LANES);
    wide->cz = wide->cy + (prims + BVH_WIDE_LANES);
    wide->rr = wide->cz + (prims + BVH_WIDE_LANES);
    wide->ids = bvh->prims;
    w.bvh = bvh;
    w.wide = wide;
    if (s != NULL) {
        /* the subtrees counted and the spheres copied together */
        s->w = &w;
        s->position = position;
        s->top = top;
        s->sphere_at = sphere_at;
        s->context = context;
        s->spheres = count;
        capacity = gather(s, 0, 0);
        s->phase = SPLIT_COUNT_COPY;
        split_run(s, threads);
        for (i = 0; i < s->count; i++)
            capacity += s->size[i];
    } else {
        capacity = wide_count(bvh->nodes, 0);
        copy_spheres(wide, position, top, sphere_at, context, 0, count);
    }
    free(position);
    clear_others(wide, prims + BVH_WIDE_LANES);
    /* 64-byte aligned: a node is two whole cache lines. */
    if (capacity > SIZE_MAX / sizeof *wide->nodes ||
        capacity > UINT32_MAX ||
        (wide->nodes = aligned_alloc(64, capacity * sizeof *wide->nodes)) ==
            NULL) {
        rayo_bvh_wide_free(wide);
        free(s);
        return RAYO_ERR_NOMEM;
    }
    if (s != NULL) {
        unsigned at = 0;
        (void)widen_top(s, 0, 0, &next, &at);
        s->phase = SPLIT_MAKE;
        split_run(s, threads);
        next = (uint32_t)capacity;
        free(s);
    } else {
        (void)widen_node(&w, 0, &next);
    }
    wide->node_count = next;
    bvh->wide = wide;
    return RAYO_OK;
}

int rayo_bvh_wide_nearest(const rayo_bvh *bvh, const rayo_ray *ray,
                          double t_min, double t_max, rayo_bvh_prim_fn test,
                          const void *context, double *best_t,
                          uint32_t *best_id, rayo_bvh_cost *cost)
{
    if (bvh->wide == NULL)
        return 0;
    /* rayo_bvh_widen_threads read the setting before this copy existed */
    switch (walk_loaded()) {
    case RAYO_BVH_WALK_BINARY:
        return 0;
    case RAYO_BVH_WALK_SSE2:
        bvh_wide_nearest_sse2(bvh->wide, ray, t_min, t_max, test, context,
                              best_t, best_id, cost);
        return 1;
    case RAYO_BVH_WALK_AVX2:
        bvh_wide_nearest_avx2(bvh->wide, ray, t_min, t_max, test, context,
                              best_t, best_id, cost);
        return 1;
    }
    return 0;
}

int rayo_bvh_wide_any(const rayo_bvh *bvh, const rayo_ray *ray,
                      double t_min, double t_max, uint32_t skip,
                      rayo_bvh_prim_fn test, const void *context,
                      rayo_bvh_cost *cost)
{
    if (bvh->wide == NULL)
        return -1;
    switch (walk_loaded()) {
    case RAYO_BVH_WALK_BINARY:
        return -1;
    case RAYO_BVH_WALK_SSE2:
        return bvh_wide_any_sse2(bvh->wide, ray, t_min, t_max, skip, test,
                                 context, cost);
    case RAYO_BVH_WALK_AVX2:
        return bvh_wide_any_avx2(bvh->wide, ray, t_min, t_max, skip, test,
                                 context, cost);
    }
    return -1;
}
