/*
 * bvh_build_top.c - the largest nodes of the hierarchy cut by every
 * thread at once.  Subtrees go to other threads (bvh_build_tasks.c), but
 * the root, and a node larger than one thread's share of the tree, is
 * binned and partitioned before there are subtrees to hand out: alone,
 * its million items kept the other threads waiting.  Here each thread
 * bins one range of the node's items; the ranges' bins are merged in
 * range order, and each thread then moves its range's items to their
 * places in the other item array.  Why it is exact: counts add exactly;
 * a bin's box is a min and a max of floats, and v4_min (v4_max) keeps
 * the earlier of two equal values (-0 and +0), so merging ranges in
 * their order gives the bits one pass in that order gives; each range
 * knows from its own bins how many of its items go left, so its items
 * land where the stable serial partition puts them.  The node, the split
 * and the tree are the serial build's (tests/unit/t_bvh_build.c).
 */
#include "bvh_build_impl.h"

#include <stdlib.h>

#include "../core/thread_start.h"

typedef struct top_job {
    builder *b;
    const span *r;
    const binning *g;
    const split *s;         /* NULL while binning */
    size_t begin, end;      /* this thread's range of the node's items */
    size_t left_at, right_at;
    bvh_bins bins;
    fbox left_c, right_c;
} top_job;

int bvh_top_wanted(const builder *b, const span *r)
{
    size_t count = r->end - r->begin;
    return b->threads > 1 && count >= TOP_MIN &&
           count > b->total / b->threads;
}

static void *top_work(void *argument)
{
    top_job *job = argument;
    if (job->s == NULL) {
        bvh_bins_clear(&job->bins, job->g->count);
        bvh_bins_fill(job->b->items[job->r->side], job->begin, job->end,
                      job->g, &job->bins);
    } else {
        bvh_partition_range(job->b, job->r->side, job->begin, job->end,
                            job->g, job->s, job->left_at, job->right_at,
                            &job->left_c, &job->right_c);
    }
    return NULL;
}

/* How many of a range's items go left: those in bins below the split's
 * on its axis. */
static size_t left_of(const bvh_bins *bins, const split *s)
{
    size_t n = 0;
    int32_t k;
    for (k = 0; k < s->bin; k++)
        n += bins->count[s->axis][k];
    return n;
}

int bvh_top_cut(builder *b, const span *r, const binning *g, double area,
                split *best, fbox *left_c, fbox *right_c, size_t *boundary)
{
    unsigned n = b->threads, i;
    size_t count = r->end - r->begin, left, right;
    top_job *jobs = malloc(n * sizeof *jobs);
    if (jobs == NULL)
        return 0;
    for (i = 0; i < n; i++) {
        jobs[i].b = b;
        jobs[i].r = r;
        jobs[i].g = g;
        jobs[i].s = NULL;
        jobs[i].begin = r->begin + count * i / n;
        jobs[i].end = r->begin + count * (i + 1) / n;
    }
    thread_run_each(n, top_work, jobs, sizeof *jobs);
    for (i = 1; i < n; i++)
        bvh_bins_merge(&jobs[0].bins, &jobs[i].bins, g->count);
    bvh_bins_best(&jobs[0].bins, g, area, best);
    if (best->axis < 0) {
        free(jobs);
        return 1;
    }
    /* jobs[0]'s bins now hold the whole node's: its range's share of the
     * left is what the other ranges leave */
    left = r->begin;
    right = r->begin + best->left_count;
    for (i = 0; i < n; i++) {
        size_t mine = best->left_count;
        unsigned j;
        if (i > 0)
            mine = left_of(&jobs[i].bins, best);
        else
            for (j = 1; j < n; j++)
                mine -= left_of(&jobs[j].bins, best);
        jobs[i].s = best;
        jobs[i].left_at = left;
        jobs[i].right_at = right;
        left += mine;
        right += (jobs[i].end - jobs[i].begin) - mine;
    }
    thread_run_each(n, top_work, jobs, sizeof *jobs);
    fbox_empty(left_c);
    fbox_empty(right_c);
    for (i = 0; i < n; i++) {
        fbox_grow(left_c, &jobs[i].left_c);
        fbox_grow(right_c, &jobs[i].right_c);
    }
    *boundary = r->begin + best->left_count;
    free(jobs);
    return 1;
}
