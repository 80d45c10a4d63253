/*
 * bvh_build.c - building the bounding volume hierarchy (bvh.h), on one
 * thread or several, always into the same tree.
 *
 * Top-down.  The boxes are first turned once into a packed array of
 * items (float boxes rounded outward, 32 bytes each; the primitives'
 * numbers in an array beside it), which is what every level reads and
 * what the partitions move, between two such arrays: one stream of
 * memory, no indirection.  A node's
 * items are sorted into BINS bins (as many as it has primitives, when
 * fewer) along all three axes in one pass, by their box centres (twice
 * the centre, lo + hi in float: the same order), and the split between
 * bins that minimises the surface area heuristic
 *     cost = 1 + (A_left N_left + A_right N_right) / A_node
 * is taken when it beats making a leaf (cost N).  The bins give each
 * child's bounds; the partition, which reads each item once, gives each
 * child's centre bounds, so no node scans its items twice.  Nodes whose
 * centres all coincide, and nodes deeper than BVH_SAH_DEPTH_LIMIT, are
 * cut in two halves instead, so the depth stays below
 * BVH_SAH_DEPTH_LIMIT + 32 for any input and a fixed traversal stack
 * suffices.  Node bounds are the items' float bounds, which are the
 * double boxes rounded outward (rounding is monotonic, so the rounded
 * union is the union of the rounded boxes; bvh_impl.h).
 *
 * Threads: every decision at a node depends on that node's items alone,
 * so the tree does not depend on who builds what.  With more than one
 * thread, a node's right child of at least SPAWN_MIN primitives becomes
 * a task for any thread (its items are its own range of the item array),
 * while the thread that split the node goes on with the left child.  Each
 * task writes its nodes in its own array, in the order one thread would
 * have made them; when all are done the arrays are stitched into the
 * order a single thread makes (each task's nodes inserted where the
 * serial build would have started that subtree, the tasks copied on the
 * threads, into the memory the items leave), so the node array and
 * the primitive order are the same bytes for any number of threads
 * (tests/unit/t_bvh_build.c).  When a thread cannot be started its
 * share is built by the others; with none, by the caller.
 */
#include "bvh_impl.h"
#include "bvh_vec4.h"

#include "../core/thread_start.h"

#include <float.h>
#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>

#define BINS 16
#define MAX_LEAF 8
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
    pthread_mutex_t lock;
    pthread_cond_t changed;
    task **tasks;               /* every task, by number */
    size_t task_count, task_capacity;
    uint32_t *pending;          /* tasks not yet started (a stack) */
    size_t pending_count;
    size_t busy;                /* tasks being built */
    int failed;                 /* out of memory somewhere */
} builder;

static vec4f v4_infinity(void) { return v4_set1(INFINITY); }

static void fbox_set(fbox *b, vec4f lo, vec4f hi)
{
    v4_store(b->lo, lo);
    v4_store(b->hi, hi);
}

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

/* How one node's centres are sorted into bins along each axis. */
typedef struct binning {
    size_t count; /* bins: BINS, or fewer for a node of few items */
    vec4f lo;     /* the lowest centre (lo + hi) on each axis */
    vec4f scale;  /* bins per unit; 0 on an axis not binned, and lane 3 */
    vec4f top;    /* count - 1 */
    int binned[3];
    int axes;     /* how many axes have a positive, finite extent */
} binning;

static void binning_make(binning *g, const fbox *centres, size_t items)
{
    float scale[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    int a;
    g->count = items < BINS ? (items < 2 ? 2 : items) : BINS;
    g->top = v4_set1((float)(g->count - 1));
    g->lo = v4_load(centres->lo);
    g->axes = 0;
    for (a = 0; a < 3; a++) {
        float extent = centres->hi[a] - centres->lo[a];
        g->binned[a] = 0;
        if (extent > 0.0f && isfinite(extent)) {
            float f = (float)g->count / extent;
            if (isfinite(f) && f > 0.0f) {
                scale[a] = f;
                g->binned[a] = 1;
                g->axes++;
            }
        }
    }
    g->scale = v4_load(scale);
}

/* The bins of a centre on each axis: (c - lo) scale clamped to [0, top]
 * (a NaN goes to 0), truncated. */
static void bins_of(const binning *g, vec4f centre, int32_t k[4])
{
    vec4f f = v4_mul(v4_sub(centre, g->lo), g->scale);
    f = v4_max(f, v4_set1(0.0f));
    f = v4_min(f, g->top);
    v4_to_int(f, k);
}

typedef struct split {
    int axis;           /* < 0: no useful split found */
    int32_t bin;        /* items in bins < bin go left */
    double cost;
    fbox left, right;   /* the children's bounds */
    size_t left_count;
} split;

/* Bins a node's items along every binned axis at once and finds the
 * cheapest split; best->axis < 0 when there is none.  area: half the
 * node's surface area. */
static void find_split(const builder *b, const span *r, const binning *g,
                       double area, split *best)
{
    const item *items = b->items[r->side];
    vec4f lo[3][BINS], hi[3][BINS], right_lo[BINS], right_hi[BINS];
    size_t count[3][BINS], right_count[BINS];
    float right_area[BINS];
    vec4f inf = v4_infinity(), minus_inf = v4_set1(-INFINITY);
    size_t i, k, bins = g->count;
    int a;
    best->axis = -1;
    best->bin = 0;
    best->cost = INFINITY;
    for (a = 0; a < 3; a++)
        for (k = 0; k < bins; k++) {
            lo[a][k] = inf;
            hi[a][k] = minus_inf;
            count[a][k] = 0;
        }
    for (i = r->begin; i < r->end; i++) {
        vec4f l = v4_load(items[i].lo), h = v4_load(items[i].hi);
        int32_t at[4];
        bins_of(g, v4_add(l, h), at);
        for (a = 0; a < 3; a++) {
            lo[a][at[a]] = v4_min(l, lo[a][at[a]]);
            hi[a][at[a]] = v4_max(h, hi[a][at[a]]);
            count[a][at[a]]++;
        }
    }
    for (a = 0; a < 3; a++) {
        vec4f acc_lo = inf, acc_hi = minus_inf;
        size_t n = 0;
        if (!g->binned[a])
            continue;
        for (k = bins; k-- > 1;) {
            acc_lo = v4_min(lo[a][k], acc_lo);
            acc_hi = v4_max(hi[a][k], acc_hi);
            n += count[a][k];
            right_lo[k] = acc_lo;
            right_hi[k] = acc_hi;
            right_area[k] = v4_half_area(acc_lo, acc_hi);
            right_count[k] = n;
        }
        acc_lo = inf;
        acc_hi = minus_inf;
        n = 0;
        for (k = 1; k < bins; k++) {
            double cost;
            acc_lo = v4_min(lo[a][k - 1], acc_lo);
            acc_hi = v4_max(hi[a][k - 1], acc_hi);
            n += count[a][k - 1];
            if (n == 0 || right_count[k] == 0)
                continue;
            cost = 1.0 + ((double)v4_half_area(acc_lo, acc_hi) * (double)n +
                          (double)right_area[k] * (double)right_count[k]) /
                             area;
            if (cost < best->cost) {
                best->cost = cost;
                best->axis = a;
                best->bin = (int32_t)k;
                best->left_count = n;
                fbox_set(&best->left, acc_lo, acc_hi);
                fbox_set(&best->right, right_lo[k], right_hi[k]);
            }
        }
    }
}

/* Writes the items going left, then the others, to the other item array
 * (in their order: the partition is stable), keeping the centre bounds
 * of each side; returns the boundary.  No branch on the side: which way
 * an item goes is as good as random to a branch predictor. */
static size_t partition(builder *b, const span *r, const binning *g,
                        const split *s, fbox *left_c, fbox *right_c)
{
    const item *from = b->items[r->side];
    item *to = b->items[!r->side];
    const uint32_t *from_index = b->index[r->side];
    uint32_t *to_index = b->index[!r->side];
    vec4f lo[2], hi[2];
    size_t next[2], i;
    int a = s->axis;
    lo[0] = lo[1] = v4_infinity();
    hi[0] = hi[1] = v4_set1(-INFINITY);
    next[0] = r->begin + s->left_count; /* [0]: right, [1]: left */
    next[1] = r->begin;
    for (i = r->begin; i < r->end; i++) {
        vec4f l = v4_load(from[i].lo), h = v4_load(from[i].hi);
        vec4f c = v4_add(l, h);
        int32_t at[4];
        int left;
        size_t d;
        bins_of(g, c, at);
        left = at[a] < s->bin;
        d = next[left]++;
        v4_store(to[d].lo, l);
        v4_store(to[d].hi, h);
        to_index[d] = from_index[i];
        lo[left] = v4_min(c, lo[left]);
        hi[left] = v4_max(c, hi[left]);
    }
    fbox_set(left_c, lo[1], hi[1]);
    fbox_set(right_c, lo[0], hi[0]);
    return r->begin + s->left_count;
}

/* Bounds and centre bounds of items [begin, end). */
static void measure(const builder *b, int side, size_t begin, size_t end,
                    fbox *bounds, fbox *centres)
{
    const item *items = b->items[side];
    vec4f inf = v4_infinity(), minus_inf = v4_set1(-INFINITY);
    vec4f b_lo = inf, b_hi = minus_inf, c_lo = inf, c_hi = minus_inf;
    size_t i;
    for (i = begin; i < end; i++) {
        vec4f l = v4_load(items[i].lo), h = v4_load(items[i].hi);
        vec4f c = v4_add(l, h);
        b_lo = v4_min(l, b_lo);
        b_hi = v4_max(h, b_hi);
        c_lo = v4_min(c, c_lo);
        c_hi = v4_max(c, c_hi);
    }
    fbox_set(bounds, b_lo, b_hi);
    fbox_set(centres, c_lo, c_hi);
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

static int spawn(builder *b, task *parent, size_t local, const span *r,
                 uint32_t *number);
static int record_spawn(task *t, uint32_t number, size_t slot);

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
static int build_node(builder *b, task *t, size_t local, const span *r)
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
        binning_make(&g, &r->centres, count);
        if (g.axes > 0 && area > 0.0)
            find_split(b, r, &g, area, &best);
        if (count <= MAX_LEAF && !(best.cost < (double)count))
            return make_leaf(b, t, local, r);
        if (best.axis >= 0) {
            left.end = right.begin =
                partition(b, r, &g, &best, &left.centres, &right.centres);
            left.side = right.side = !r->side;
            left.bounds = best.left;
            right.bounds = best.right;
        }
    } else if (count <= MAX_LEAF) {
        return make_leaf(b, t, local, r);
    }
    if (best.axis < 0) { /* halves, in place */
        measure(b, r->side, left.begin, left.end, &left.bounds,
                &left.centres);
        measure(b, r->side, right.begin, right.end, &right.bounds,
                &right.centres);
    }
    first = add_pair(t);
    if (first == 0)
        return 0;
    t->nodes[local].first = (uint32_t)first;
    t->nodes[local].count = 0;
    if (b->threads > 1 && right.end - right.begin >= SPAWN_MIN) {
        uint32_t number;
        if (!spawn(b, t, first + 1, &right, &number))
            return 0;
        if (!build_node(b, t, first, &left))
            return 0;
        /* the serial build would start the right subtree here; spawns
         * are recorded in this order, so by `at`, deeper ones first */
        return record_spawn(t, number, first + 1);
    }
    return build_node(b, t, first, &left) &&
           build_node(b, t, first + 1, &right);
}

static task *task_new(const span *r)
{
    task *t = calloc(1, sizeof *t);
    if (t == NULL)
        return NULL;
    t->root = *r;
    /* Room for the whole subtree (2n - 1 nodes) only when it is small:
     * untouched pages take no memory but do take address space, and a
     * task reserving its whole subtree, at every level of spawns, made
     * 2^24 spheres reserve 10 GiB at -j 2 (an `ulimit -v` failed that
     * the memory would not).  Beyond, add_pair doubles the array, which
     * glibc moves by remapping, not copying. */
    t->capacity = 2 * (r->end - r->begin);
    if (t->capacity > TASK_FIRST_NODES)
        t->capacity = TASK_FIRST_NODES;
    t->nodes = malloc(t->capacity * sizeof *t->nodes);
    if (t->nodes == NULL) {
        free(t);
        return NULL;
    }
    t->count = 1;
    return t;
}

static void task_free(task *t)
{
    if (t == NULL)
        return;
    free(t->nodes);
    free(t->spawns);
    free(t->map);
    free(t);
}

/* Hands the subtree at parent->nodes[local] to any thread as task
 * *number; 0 when out of memory.  The parent's node becomes a
 * placeholder. */
static int spawn(builder *b, task *parent, size_t local, const span *r,
                 uint32_t *number)
{
    task *t = task_new(r);
    int good = 1;
    if (t == NULL)
        return 0;
    pthread_mutex_lock(&b->lock);
    if (b->task_count == b->task_capacity) {
        size_t capacity = 2 * b->task_capacity;
        task **grown = realloc(b->tasks, capacity * sizeof *grown);
        uint32_t *pending = NULL;
        if (grown != NULL) {
            b->tasks = grown;
            pending = realloc(b->pending, capacity * sizeof *pending);
        }
        if (pending != NULL) {
            b->pending = pending;
            b->task_capacity = capacity;
        } else {
            good = 0;
        }
    }
    if (good) {
        *number = (uint32_t)b->task_count++;
        b->tasks[*number] = t;
        b->pending[b->pending_count++] = *number;
        pthread_cond_signal(&b->changed);
    }
    pthread_mutex_unlock(&b->lock);
    if (!good) {
        task_free(t);
        return 0;
    }
    parent->nodes[local].first = *number;
    parent->nodes[local].count = NODE_TASK;
    return 1;
}

/* Notes that task number's nodes go before t's next node; 0 when out of
 * memory. */
static int record_spawn(task *t, uint32_t number, size_t slot)
{
    if (t->spawn_count == t->spawn_capacity) {
        size_t capacity = 2 * t->spawn_capacity + 4;
        struct spawn *grown = realloc(t->spawns, capacity * sizeof *grown);
        if (grown == NULL)
            return 0;
        t->spawns = grown;
        t->spawn_capacity = capacity;
    }
    t->spawns[t->spawn_count].task = number;
    t->spawns[t->spawn_count].at = (uint32_t)t->count;
    t->spawns[t->spawn_count].slot = (uint32_t)slot;
    t->spawn_count++;
    return 1;
}

/* Builds tasks until none is left or running. */
static void *worker(void *argument)
{
    builder *b = argument;
    pthread_mutex_lock(&b->lock);
    for (;;) {
        task *t;
        int good;
        while (b->pending_count == 0 && b->busy > 0)
            pthread_cond_wait(&b->changed, &b->lock);
        if (b->pending_count == 0)
            break;
        t = b->tasks[b->pending[--b->pending_count]];
        b->busy++;
        good = !b->failed;
        pthread_mutex_unlock(&b->lock);
        if (good)
            good = build_node(b, t, 0, &t->root);
        pthread_mutex_lock(&b->lock);
        if (!good)
            b->failed = 1;
        b->busy--;
        if (b->busy == 0 && b->pending_count == 0)
            pthread_cond_broadcast(&b->changed);
    }
    pthread_mutex_unlock(&b->lock);
    return NULL;
}

/* Gives each node of task t, and of the tasks it spawned, its place in
 * the final array: t's root goes to root, the rest in t's order, each
 * spawned subtree's nodes where the serial build would have made them.
 * 0 when out of memory. */
static int place(builder *b, task *t, uint32_t root, uint32_t *next)
{
    size_t j, s = 0;
    t->map = malloc(t->count * sizeof *t->map);
    if (t->map == NULL)
        return 0;
    t->map[0] = root;
    for (j = 1; j <= t->count; j++) {
        while (s < t->spawn_count && t->spawns[s].at == j) {
            /* its placeholder, made before `at`, is already placed */
            task *child = b->tasks[t->spawns[s].task];
            if (!place(b, child, t->map[t->spawns[s].slot], next))
                return 0;
            s++;
        }
        if (j < t->count)
            t->map[j] = (*next)++;
    }
    return 1;
}

/* Copies task t's own nodes to their places (a spawned task's
 * placeholder is left to that task). */
static void stitch(const task *t, bvh_node *out)
{
    size_t j;
    for (j = 0; j < t->count; j++) {
        bvh_node node = t->nodes[j];
        if (node.count == NODE_TASK)
            continue;
        if (node.count == 0)
            node.first = t->map[node.first];
        out[t->map[j]] = node;
    }
}

/* The stitching on several threads: the tasks' places are disjoint. */
typedef struct stitcher {
    builder *b;
    bvh_node *out;
    atomic_size_t taken;
} stitcher;

static void *stitch_worker(void *argument)
{
    stitcher *s = argument;
    size_t i;
    while ((i = atomic_fetch_add(&s->taken, 1)) < s->b->task_count)
        stitch(s->b->tasks[i], s->out);
    return NULL;
}

static void stitch_all(builder *b, bvh_node *out)
{
    stitcher s;
    s.b = b;
    s.out = out;
    atomic_init(&s.taken, 0);
    thread_run_all(b->threads, stitch_worker, &s);
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

/* nodes[0, count), in an array no larger than that when memory allows */
static bvh_node *shrink(bvh_node *nodes, size_t count)
{
    bvh_node *shrunk = realloc(nodes, count * sizeof *shrunk);
    return shrunk != NULL ? shrunk : nodes;
}

static rayo_status build_all(builder *b, task *root, rayo_bvh *bvh)
{
    uint32_t next = 1;
    b->tasks[0] = root;
    b->task_count = 1;
    b->pending[0] = 0;
    b->pending_count = 1;
    thread_run_all(b->threads, worker, b);
    if (b->failed)
        return RAYO_ERR_NOMEM;
    if (b->task_count == 1) { /* one task: its nodes are in final order */
        bvh->nodes = shrink(root->nodes, root->count);
        bvh->node_count = root->count;
        root->nodes = NULL;
        return RAYO_OK;
    }
    if (!place(b, root, 0, &next))
        return RAYO_ERR_NOMEM;
    /* The nodes go where the items were: their pages are already
     * written (a first write of a page costs about 2 us here, and these
     * are 32 bytes a node for up to 2 n - 1 nodes, as the items are for
     * 2 n), and the items are no longer read. */
    bvh->node_count = next;
    bvh->nodes = (bvh_node *)(void *)b->items[0];
    b->items[0] = b->items[1] = NULL;
    stitch_all(b, bvh->nodes);
    bvh->nodes = shrink(bvh->nodes, next);
    return RAYO_OK;
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
    measure(b, 0, job->begin, job->end, &job->bounds, &job->centres);
    first_touch(b, job->begin, job->end);
    return NULL;
}

/* Fills the items on up to b->threads threads and finds their bounds
 * (unions are exact, so in any order the same). */
static void convert_all(builder *b, size_t count, fbox *bounds, fbox *centres)
{
    convert_job jobs[64];
    unsigned n = b->threads, i;
    vec4f lo[2], hi[2];
    for (i = 0; i < n; i++) {
        jobs[i].b = b;
        jobs[i].begin = count * i / n;
        jobs[i].end = count * (i + 1) / n;
    }
    thread_run_each(n, convert, jobs, sizeof *jobs);
    lo[0] = lo[1] = v4_infinity();
    hi[0] = hi[1] = v4_set1(-INFINITY);
    for (i = 0; i < n; i++) {
        lo[0] = v4_min(v4_load(jobs[i].bounds.lo), lo[0]);
        hi[0] = v4_max(v4_load(jobs[i].bounds.hi), hi[0]);
        lo[1] = v4_min(v4_load(jobs[i].centres.lo), lo[1]);
        hi[1] = v4_max(v4_load(jobs[i].centres.hi), hi[1]);
    }
    fbox_set(bounds, lo[0], hi[0]);
    fbox_set(centres, lo[1], hi[1]);
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
            root = task_new(&all);
            if (root != NULL)
                status = build_all(&b, root, bvh);
            pthread_cond_destroy(&b.changed);
        }
        pthread_mutex_destroy(&b.lock);
    }
    if (status == RAYO_OK)
        for (i = 0; i < count; i++)
            bvh->prims[i] = ids[bvh->prims[i]];
    if (b.task_count == 0)
        task_free(root);
    for (i = 0; i < b.task_count; i++)
        task_free(b.tasks[i]);
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
