/*
 * bvh_build_tasks.c - the hierarchy built by several threads into the
 * tree one thread makes.  Every decision at a node depends on that
 * node's items alone, so the tree does not depend on who builds what: a
 * right child of at least SPAWN_MIN primitives becomes a task for any
 * thread (its items are its own range of the item array), each task
 * writes its nodes in its own array, in the order one thread would
 * have, and when all are done the arrays are stitched (on the threads,
 * into the memory the items leave) where the serial build would have
 * put each subtree: the node array and the primitive order are the same
 * bytes for any number of threads (tests/unit/t_bvh_build.c).  When a
 * thread cannot be started its share is built by the others.
 */
#include "bvh_build_impl.h"

#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>

#include "../core/thread_start.h"

task *bvh_task_new(const span *r)
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

void bvh_task_free(task *t)
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
int bvh_spawn(builder *b, task *parent, size_t local, const span *r,
              uint32_t *number)
{
    task *t = bvh_task_new(r);
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
        bvh_task_free(t);
        return 0;
    }
    parent->nodes[local].first = *number;
    parent->nodes[local].count = NODE_TASK;
    return 1;
}

/* Notes that task number's nodes go before t's next node; 0 when out of
 * memory. */
int bvh_record_spawn(task *t, uint32_t number, size_t slot)
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
            good = bvh_build_node(b, t, 0, &t->root);
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

/* nodes[0, count), in an array no larger than that when memory allows */
static bvh_node *shrink(bvh_node *nodes, size_t count)
{
    bvh_node *shrunk = realloc(nodes, count * sizeof *shrunk);
    return shrunk != NULL ? shrunk : nodes;
}

rayo_status bvh_build_all(builder *b, task *root, rayo_bvh *bvh)
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
