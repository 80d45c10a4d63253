/*
 * bvh_build.c - building the bounding volume hierarchy (bvh.h), on one
 * thread or several, always into the same tree.  Top-down.  The boxes
 * are first turned once into a packed array of items (float boxes
 * rounded outward, 32 bytes each; the primitives' numbers beside them),
 * which is what every level reads and what the partitions move, between
 * two such arrays: one stream of memory, no indirection.  Where a node
 * is cut is bvh_build_sah.c's (on every thread at once for the
 * largest nodes: bvh_build_top.c); nodes whose centres all coincide, and
 * nodes deeper than BVH_SAH_DEPTH_LIMIT, are cut in halves instead, so
 * the depth stays below BVH_SAH_DEPTH_LIMIT + 32 and a fixed stack
 * suffices.  Node bounds are the items' float bounds (rounding outward
 * is monotonic: bvh_impl.h).  Threads: bvh_build_tasks.c.
 */
#include "bvh_build_impl.h"

#include <float.h>
#include <stdlib.h>
#include <string.h>

#include "../core/thread_start.h"

void rayo_box_pad(rayo_box *box)
{
    int a;
    for (a = 0; a < 3; a++) {
        double m = fmax(fabs(box->lo[a]), fabs(box->hi[a]));
        double pad = 1e-9 * (m + (box->hi[a] - box->lo[a]));
        box->lo[a] -= pad;
        box->hi[a] += pad;
    }
}

/* The float after f towards -infinity (down) or +infinity; f finite.
 * Floats of one sign are ordered as their bit patterns. */
static float float_step(float f, int down)
{
    uint32_t bits;
    if (f == 0.0f)
        return down ? -FLT_TRUE_MIN : FLT_TRUE_MIN;
    memcpy(&bits, &f, sizeof bits);
    if ((f > 0.0f) == !down)
        bits++;
    else
        bits--;
    memcpy(&f, &bits, sizeof f);
    return f;
}

/* The largest float <= v (-infinity below the float range; FLT_MAX
 * above it, where v rounds to +infinity). */
static float float_below(double v)
{
    float f = (float)v;
    if ((double)f > v)
        f = isinf(f) ? FLT_MAX : float_step(f, 1);
    return f;
}

/* The smallest float >= v. */
static float float_above(double v)
{
    float f = (float)v;
    if ((double)f < v)
        f = isinf(f) ? -FLT_MAX : float_step(f, 0);
    return f;
}

/* A new pair of nodes in t; its first index, or 0 when out of memory. */
static size_t add_pair(task *t)
{
    if (t->count + 2 > t->capacity) {
        size_t capacity = 2 * t->capacity + 2;
        bvh_node *grown = realloc(t->nodes, capacity * sizeof *grown);
        if (grown == NULL)
            return 0;
        t->nodes = grown;
        t->capacity = capacity;
    }
    t->count += 2;
    return t->count - 2;
}

static void set_bounds(bvh_node *node, const fbox *bounds)
{
    memcpy(node->bounds[0], bounds->lo, sizeof bounds->lo);
    memcpy(node->bounds[1], bounds->hi, sizeof bounds->hi);
}

/* A leaf over r's items: their primitives to their final places. */
static int make_leaf(builder *b, task *t, size_t local, const span *r)
{
    t->nodes[local].first = (uint32_t)r->begin;
    t->nodes[local].count = (uint32_t)(r->end - r->begin);
    if (r->side != 0)
        memcpy(b->prims + r->begin, b->index[r->side] + r->begin,
               (r->end - r->begin) * sizeof *b->prims);
    return 1;
}

/* Builds the node t->nodes[local] over r; 0 when out of memory. */
int bvh_build_node(builder *b, task *t, size_t local, const span *r)
{
    size_t count = r->end - r->begin, first;
    span left, right;
    split best;
    set_bounds(&t->nodes[local], &r->bounds);
    if (count == 1)
        return make_leaf(b, t, local, r);
    best.axis = -1;
    best.cost = INFINITY;
    left.begin = r->begin;
    left.end = right.begin = r->begin + count / 2;
    right.end = r->end;
    left.depth = right.depth = r->depth + 1;
    left.side = right.side = r->side;
    if (r->depth < BVH_SAH_DEPTH_LIMIT) {
        double area =
            v4_half_area(v4_load(r->bounds.lo), v4_load(r->bounds.hi));
        binning g;
        size_t boundary = 0;
        int top = 0;
        bvh_binning_make(&g, &r->centres, count);
        if (g.axes > 0 && area > 0.0) {
            top = bvh_top_wanted(b, r) &&
                  bvh_top_cut(b, r, &g, area, &best, &left.centres,
                              &right.centres, &boundary);
            if (!top)
                bvh_find_split(b, r, &g, area, &best);
        }
        if (count <= MAX_LEAF && !(best.cost < (double)count))
            return make_leaf(b, t, local, r);
        if (best.axis >= 0) {
            left.end = right.begin =
                top ? boundary
                    : bvh_partition(b, r, &g, &best, &left.centres,
                                    &right.centres);
            left.side = right.side = !r->side;
            left.bounds = best.left;
            right.bounds = best.right;
        }
    } else if (count <= MAX_LEAF) {
        return make_leaf(b, t, local, r);
    }
    if (best.axis < 0) { /* halves, in place */
        bvh_measure(b, r->side, left.begin, left.end, &left.bounds,
                    &left.centres);
        bvh_measure(b, r->side, right.begin, right.end, &right.bounds,
                    &right.centres);
    }
    first = add_pair(t);
    if (first == 0)
        return 0;
    t->nodes[local].first = (uint32_t)first;
    t->nodes[local].count = 0;
    if (b->threads > 1 && right.end - right.begin >= SPAWN_MIN) {
        uint32_t number;
        if (!bvh_spawn(b, t, first + 1, &right, &number))
            return 0;
        if (!bvh_build_node(b, t, first, &left))
            return 0;
        /* the serial build would start the right subtree here; spawns
         * are recorded in this order, so by `at`, deeper ones first */
        return bvh_record_spawn(t, number, first + 1);
    }
    return bvh_build_node(b, t, first, &left) &&
           bvh_build_node(b, t, first + 1, &right);
}

/* How many threads: the caller's wish, else one. */
static unsigned thread_count(unsigned threads, size_t count)
{
    if (threads < 1)
        threads = 1;
    if (threads > 64)
        threads = 64;
    if (count < 2 * SPAWN_MIN)
        threads = 1;
    return threads;
}

/* One thread's share of turning boxes into items. */
typedef struct convert_job {
    builder *b;
    size_t begin, end;
    fbox bounds, centres; /* of its items */
} convert_job;

/*
 * Writes once in each page of the second item and index arrays over
 * [begin, end).  The root's partition, on one thread, is what first
 * writes them, and a first write of a page costs about 2 us here (the
 * system zeroes it): done where each thread converts its share, on
 * every thread at once.  The values are overwritten before being read.
 */
static void first_touch(builder *b, size_t begin, size_t end)
{
    size_t i;
    if (b->threads < 2 || begin == end)
        return;
    for (i = begin; i < end; i += 4096 / sizeof *b->items[1])
        b->items[1][i].lo[0] = 0.0f;
    b->items[1][end - 1].lo[0] = 0.0f;
    for (i = begin; i < end; i += 4096 / sizeof *b->index[1])
        b->index[1][i] = 0;
    b->index[1][end - 1] = 0;
}

static void *convert(void *argument)
{
    convert_job *job = argument;
    builder *b = job->b;
    size_t i;
    for (i = job->begin; i < job->end; i++) {
        item *it = &b->items[0][i];
        rayo_box box;
        int a;
        b->box(b->box_context, i, &box);
        for (a = 0; a < 3; a++) {
            it->lo[a] = float_below(box.lo[a]);
            it->hi[a] = float_above(box.hi[a]);
        }
        it->lo[3] = it->hi[3] = 0.0f;
        b->index[0][i] = (uint32_t)i;
    }
    bvh_measure(b, 0, job->begin, job->end, &job->bounds, &job->centres);
    first_touch(b, job->begin, job->end);
    return NULL;
}

/* Fills the items on up to b->threads threads and finds their bounds
 * (unions are exact, so in any order the same). */
static void convert_all(builder *b, size_t count, fbox *bounds, fbox *centres)
{
    convert_job jobs[64];
    unsigned n = b->threads, i;
    for (i = 0; i < n; i++) {
        jobs[i].b = b;
        jobs[i].begin = count * i / n;
        jobs[i].end = count * (i + 1) / n;
    }
    thread_run_each(n, convert, jobs, sizeof *jobs);
    fbox_empty(bounds);
    fbox_empty(centres);
    for (i = 0; i < n; i++) {
        fbox_grow(bounds, &jobs[i].bounds);
        fbox_grow(centres, &jobs[i].centres);
    }
}

rayo_status rayo_bvh_build_from(rayo_bvh **result, rayo_bvh_box_fn box,
                                const void *context, const uint32_t *ids,
                                size_t count, unsigned threads,
                                rayo_error *err)
{
    rayo_bvh *bvh;
    builder b;
    task *root = NULL;
    span all;
    rayo_status status = RAYO_ERR_NOMEM;
    size_t i;
    *result = NULL;
    if (count > UINT32_MAX / 2)
        return rayo_error_set(err, RAYO_ERR_LIMIT,
                              "%lu primitives are too many for the "
                              "hierarchy; expected at most %lu",
                              (unsigned long)count,
                              (unsigned long)(UINT32_MAX / 2));
    bvh = calloc(1, sizeof *bvh);
    if (bvh == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
    if (count == 0) {
        *result = bvh;
        return RAYO_OK;
    }
    memset(&b, 0, sizeof b);
    b.threads = thread_count(threads, count);
    b.total = count;
    b.box = box;
    b.box_context = context;
    /* count <= UINT32_MAX / 2, so these products fit in size_t only if
     * checked: */
    if (count > SIZE_MAX / 2 / sizeof *b.items[0]) {
        free(bvh);
        return rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
    }
    /* both item arrays in one block, which the nodes take over
     * (build_all) */
    b.items[0] = malloc(2 * count * sizeof *b.items[0]);
    b.items[1] = b.items[0] != NULL ? b.items[0] + count : NULL;
    b.index[1] = malloc(count * sizeof *b.index[1]);
    b.prims = b.index[0] = bvh->prims = malloc(count * sizeof *bvh->prims);
    b.task_capacity = 64;
    b.tasks = calloc(b.task_capacity, sizeof *b.tasks);
    b.pending = malloc(b.task_capacity * sizeof *b.pending);
    if (b.items[0] != NULL && b.index[1] != NULL &&
        bvh->prims != NULL && b.tasks != NULL && b.pending != NULL &&
        pthread_mutex_init(&b.lock, NULL) == 0) {
        if (pthread_cond_init(&b.changed, NULL) == 0) {
            all.begin = 0;
            all.end = count;
            all.depth = 0;
            all.side = 0;
            convert_all(&b, count, &all.bounds, &all.centres);
            root = bvh_task_new(&all);
            if (root != NULL)
                status = bvh_build_all(&b, root, bvh);
            pthread_cond_destroy(&b.changed);
        }
        pthread_mutex_destroy(&b.lock);
    }
    if (status == RAYO_OK)
        for (i = 0; i < count; i++)
            bvh->prims[i] = ids[bvh->prims[i]];
    if (b.task_count == 0)
        bvh_task_free(root);
    for (i = 0; i < b.task_count; i++)
        bvh_task_free(b.tasks[i]);
    free(b.tasks);
    free(b.pending);
    free(b.items[0]);
    free(b.index[1]);
    if (status != RAYO_OK) {
        rayo_bvh_free(bvh);
        return rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
    }
    *result = bvh;
    return RAYO_OK;
}

static void box_from_array(const void *context, size_t i, rayo_box *box)
{
    *box = ((const rayo_box *)context)[i];
}

rayo_status rayo_bvh_build_threads(rayo_bvh **result, const rayo_box *boxes,
                                   const uint32_t *ids, size_t count,
                                   unsigned threads, rayo_error *err)
{
    return rayo_bvh_build_from(result, box_from_array, boxes, ids, count,
                               threads, err);
}

rayo_status rayo_bvh_build(rayo_bvh **result, const rayo_box *boxes,
                           const uint32_t *ids, size_t count,
                           rayo_error *err)
{
    return rayo_bvh_build_threads(result, boxes, ids, count, 1, err);
}
