/*
 * t_bvh_build.c - the hierarchy's builder on several threads
 * (bvh_build.c): the same tree, byte for byte, for any thread count, and
 * a valid one.
 *
 * Boxes: a field of random boxes (as the scenes make), a cloud with
 * every tenth box repeated, one where all centres coincide (the builder
 * cuts such nodes in halves, in place), and one small enough that no
 * thread is started.  Each is built on 1, 2, 3 and 8 threads; the node
 * arrays and the primitive orders must be identical.  The tree must also
 * be sound: every node's float box holds the double boxes below it, each
 * primitive is in exactly one leaf, interior nodes' children are inside
 * the array, and the depth is bounded.  The tree's 4-wide copy
 * (bvh_wide.c), with every other primitive a sphere, is made on 1, 2, 3
 * and 8 threads too: the same nodes and sphere arrays, byte for byte.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <stdio.h>
#include <string.h>

#include "rayo.h"
#include "tap.h"

#include "../../src/accel/bvh_wide_impl.h"

static uint64_t next64(uint64_t *state)
{
    uint64_t z = (*state += 0x9e3779b97f4a7c15u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
}

static double unit(uint64_t *state)
{
    return (double)(next64(state) >> 11) / 9007199254740992.0;
}

typedef enum layout { FIELD, CLOUD, SAME_CENTRE } layout;

static rayo_box *make_boxes(layout kind, size_t n, uint64_t seed)
{
    rayo_box *boxes = malloc(n * sizeof *boxes);
    uint64_t state = seed;
    size_t i;
    int a;
    for (i = 0; boxes != NULL && i < n; i++) {
        double c[3], r;
        if (kind == CLOUD && i % 10 == 9) {
            boxes[i] = boxes[i / 2];
            continue;
        }
        c[0] = kind == SAME_CENTRE ? 1.0 : 100.0 * unit(&state) - 50.0;
        c[1] = kind == FIELD ? -1.0 + 0.1 * unit(&state)
               : kind == SAME_CENTRE ? -2.0
                                     : 20.0 * unit(&state);
        c[2] = kind == SAME_CENTRE ? 3.0 : 100.0 * unit(&state);
        r = 0.01 + 0.2 * unit(&state);
        for (a = 0; a < 3; a++) {
            boxes[i].lo[a] = c[a] - r;
            boxes[i].hi[a] = c[a] + r;
        }
        rayo_box_pad(&boxes[i]);
    }
    return boxes;
}

typedef struct walk {
    const rayo_bvh *bvh;
    const rayo_box *boxes;
    const uint32_t *ids; /* ids[i] = i + 7 */
    unsigned char *seen;
    size_t n, bad, max_depth;
} walk;

static int holds(const bvh_node *node, const rayo_box *box)
{
    int a;
    for (a = 0; a < 3; a++)
        if (!((double)node->bounds[0][a] <= box->lo[a] &&
              (double)node->bounds[1][a] >= box->hi[a]))
            return 0;
    return 1;
}

static int node_holds(const bvh_node *outer, const bvh_node *inner)
{
    int a;
    for (a = 0; a < 3; a++)
        if (!(outer->bounds[0][a] <= inner->bounds[0][a] &&
              outer->bounds[1][a] >= inner->bounds[1][a]))
            return 0;
    return 1;
}

static void check_node(walk *w, size_t index, size_t depth)
{
    const bvh_node *node = &w->bvh->nodes[index];
    size_t i;
    if (depth > w->max_depth)
        w->max_depth = depth;
    if (depth > BVH_SAH_DEPTH_LIMIT + 32) {
        w->bad++;
        return;
    }
    if (node->count > 0) {
        if ((size_t)node->first + node->count > w->n) {
            w->bad++;
            return;
        }
        for (i = node->first; i < (size_t)node->first + node->count; i++) {
            uint32_t prim = w->bvh->prims[i] - 7;
            if (prim >= w->n || w->seen[prim]++ ||
                !holds(node, &w->boxes[prim]))
                w->bad++;
        }
        return;
    }
    if ((size_t)node->first + 1 >= w->bvh->node_count ||
        node->first <= index) {
        w->bad++;
        return;
    }
    if (!node_holds(node, &w->bvh->nodes[node->first]) ||
        !node_holds(node, &w->bvh->nodes[node->first + 1]))
        w->bad++;
    check_node(w, node->first, depth + 1);
    check_node(w, node->first + 1, depth + 1);
}

/* 1 when the tree is sound. */
static int sound(const rayo_bvh *bvh, const rayo_box *boxes,
                 const uint32_t *ids, size_t n, size_t *depth)
{
    walk w;
    size_t i;
    w.bvh = bvh;
    w.boxes = boxes;
    w.ids = ids;
    w.n = n;
    w.bad = 0;
    w.max_depth = 0;
    w.seen = calloc(n, 1);
    if (w.seen == NULL)
        return 0;
    check_node(&w, 0, 0);
    for (i = 0; i < n; i++)
        if (w.seen[i] != 1)
            w.bad++;
    free(w.seen);
    *depth = w.max_depth;
    return w.bad == 0;
}


/* Sphere i: primitive 7 + 2i (ids[k] = k + 7), the sphere in box 2i. */
static void sphere_of_box(const void *context, size_t i, uint32_t *prim,
                          rayo_sphere *sphere)
{
    const rayo_box *box = (const rayo_box *)context + 2 * i;
    *prim = (uint32_t)(2 * i + 7);
    sphere->center.x = 0.5 * (box->lo[0] + box->hi[0]);
    sphere->center.y = 0.5 * (box->lo[1] + box->hi[1]);
    sphere->center.z = 0.5 * (box->lo[2] + box->hi[2]);
    sphere->radius = 0.25 * (box->hi[0] - box->lo[0]);
}

static int same_wide(const struct bvh_wide *a, const struct bvh_wide *b,
                     size_t n)
{
    size_t lanes = n + BVH_WIDE_LANES;
    return a != NULL && b != NULL && a->node_count == b->node_count &&
           memcmp(a->nodes, b->nodes, a->node_count * sizeof *a->nodes) ==
               0 &&
           memcmp(a->cx, b->cx, 4 * lanes * sizeof *a->cx) == 0 &&
           memcmp(a->sphere, b->sphere, lanes) == 0;
}

/* The wide copy of bvh on 1, 2, 3 and 8 threads. */
static void check_widen(const char *name, rayo_bvh *bvh,
                        const rayo_box *boxes, size_t n)
{
    static const unsigned threads[] = {2, 3, 8};
    struct bvh_wide *one;
    size_t i, spheres = (n + 1) / 2;
    if (rayo_bvh_widen_threads(bvh, sphere_of_box, boxes, spheres, 1) !=
            RAYO_OK ||
        bvh->wide == NULL) {
        ok(0, "%s: wide copy on 1 thread", name);
        return;
    }
    one = bvh->wide;
    bvh->wide = NULL;
    ok(one->node_count >= 1 && one->node_count <= bvh->node_count,
       "%s: wide copy of %lu nodes", name, (unsigned long)one->node_count);
    for (i = 0; i < sizeof threads / sizeof threads[0]; i++) {
        int same = rayo_bvh_widen_threads(bvh, sphere_of_box, boxes,
                                          spheres, threads[i]) == RAYO_OK &&
                   same_wide(one, bvh->wide, n);
        ok(same, "%s: wide copy on %u threads: the same bytes as 1", name,
           threads[i]);
    }
    rayo_bvh_wide_free(one);
}

static void check_layout(const char *name, layout kind, size_t n)
{
    static const unsigned threads[] = {1, 2, 3, 8};
    rayo_box *boxes = make_boxes(kind, n, 2026 + n);
    uint32_t *ids = malloc(n * sizeof *ids);
    rayo_bvh *first = NULL;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    size_t i, depth = 0;
    if (boxes == NULL || ids == NULL) {
        ok(0, "%s: memory", name);
        free(boxes);
        free(ids);
        return;
    }
    for (i = 0; i < n; i++)
        ids[i] = (uint32_t)i + 7;
    for (i = 0; i < sizeof threads / sizeof threads[0]; i++) {
        rayo_bvh *bvh;
        if (rayo_bvh_build_threads(&bvh, boxes, ids, n, threads[i], &err) !=
            RAYO_OK) {
            ok(0, "%s: build on %u threads", name, threads[i]);
            printf("# %.200s\n", err.message);
            continue;
        }
        if (first == NULL) {
            int good = sound(bvh, boxes, ids, n, &depth);
            first = bvh;
            ok(good,
               "%s: %lu nodes, depth %lu, every box in its leaf, once",
               name, (unsigned long)bvh->node_count, (unsigned long)depth);
            continue;
        }
        ok(bvh->node_count == first->node_count &&
               memcmp(bvh->nodes, first->nodes,
                      first->node_count * sizeof *first->nodes) == 0 &&
               memcmp(bvh->prims, first->prims, n * sizeof *first->prims) ==
                   0,
           "%s: %u threads build the same bytes as 1", name, threads[i]);
        rayo_bvh_free(bvh);
    }
    if (first != NULL)
        check_widen(name, first, boxes, n);
    rayo_bvh_free(first);
    free(boxes);
    free(ids);
}

/* Float rounding outward, the reference way (nextafterf). */
static float ref_below(double v)
{
    float f = (float)v;
    return (double)f > v ? nextafterf(f, -INFINITY) : f;
}

static float ref_above(double v)
{
    float f = (float)v;
    return (double)f < v ? nextafterf(f, INFINITY) : f;
}

/* The root's float box must be the boxes' union rounded outward, as
 * nextafterf rounds, for values beyond the float range, near its ends,
 * in its subnormals and below them. */
static void check_rounding(void)
{
    static const double magnitudes[] = {
        1e39, 3.4028235677973366e38, 3.4028234663852886e38, 1e30, 1.5,
        1e-38, 1e-40, 1.5e-45, 1e-46, 0.0};
    uint64_t state = 17;
    size_t m, n = 3000, i, pass;
    rayo_box *boxes = malloc(n * sizeof *boxes);
    uint32_t *ids = malloc(n * sizeof *ids);
    int good = 1;
    /* each magnitude twice: all positive, then either sign */
    for (pass = 0; pass < 2 * sizeof magnitudes / sizeof magnitudes[0];
         pass++) {
        float lo[3], hi[3];
        int a;
        m = pass / 2;
        if (boxes == NULL || ids == NULL)
            break;
        for (a = 0; a < 3; a++) {
            lo[a] = INFINITY;
            hi[a] = -INFINITY;
        }
        for (i = 0; i < n; i++) {
            for (a = 0; a < 3; a++) {
                double c = magnitudes[m] * (0.5 + unit(&state)) *
                           (pass % 2 && (next64(&state) & 1) ? -1 : 1);
                double w = magnitudes[m] * 0.01 * unit(&state);
                float l, h;
                boxes[i].lo[a] = c - w;
                boxes[i].hi[a] = c + w;
                l = ref_below(boxes[i].lo[a]);
                h = ref_above(boxes[i].hi[a]);
                lo[a] = l < lo[a] ? l : lo[a];
                hi[a] = h > hi[a] ? h : hi[a];
            }
            ids[i] = (uint32_t)i;
        }
        {
            unsigned threads;
            for (threads = 1; threads <= 2; threads++) {
                rayo_bvh *bvh;
                rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
                if (rayo_bvh_build_threads(&bvh, boxes, ids, n, threads,
                                           &err) != RAYO_OK) {
                    good = 0;
                    continue;
                }
                if (memcmp(bvh->nodes[0].bounds[0], lo, sizeof lo) != 0 ||
                    memcmp(bvh->nodes[0].bounds[1], hi, sizeof hi) != 0) {
                    good = 0;
                    printf("# magnitude %g: root %g..%g, expected %g..%g\n",
                           magnitudes[m], bvh->nodes[0].bounds[0][0],
                           bvh->nodes[0].bounds[1][0], lo[0], hi[0]);
                }
                rayo_bvh_free(bvh);
            }
        }
    }
    ok(boxes != NULL && ids != NULL && good,
       "the root's box: the union rounded outward as nextafterf rounds");
    free(boxes);
    free(ids);
}

int main(void)
{
    check_rounding();
    check_layout("field of 60000", FIELD, 60000);
    check_layout("cloud of 30000", CLOUD, 30000);
    check_layout("5000 boxes at one centre", SAME_CENTRE, 5000);
    check_layout("small: 1500", FIELD, 1500);
    check_layout("one box", FIELD, 1);
    return tap_done();
}
