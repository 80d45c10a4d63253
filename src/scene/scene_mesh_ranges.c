/*
 * scene_mesh_ranges.c - a mesh's triangles placed in the scene by ranges
 * of the mesh, on several threads: a million triangles' placement,
 * checks and normals (and the first writes of the scene's 100 MB of
 * triangles, page faults included) were a sixth of a scan's setup, all
 * on one thread.  Why it is exact: each triangle is placed by the same
 * function one at a time uses (scene_mesh_place), into the room reserved
 * for the whole mesh; each range writes its kept triangles, in order,
 * from where its first would go, and the ranges are then closed up in
 * order (nothing moves unless a triangle was left out), so the scene's
 * array is the one adding them one by one makes.  A triangle the scene
 * would refuse stops its range, and everything after it is dropped:
 * the caller then refuses it as one by one would, with those before it
 * added.  Object numbers are given afterwards (scene_triangles_added).
 */
#include "scene_mesh_impl.h"

#include <stdlib.h>
#include <string.h>

#include "../core/thread_start.h"

/* Fewer triangles than this a range are placed by one thread. */
#define RANGE_MIN 16384

typedef struct range_job {
    const mesh_frame *f;
    scene_triangle *out;    /* where triangle 0 of the mesh would go */
    size_t begin, end;
    size_t kept, skipped;
    size_t stop;            /* the first refused, or end */
} range_job;

static void *place_range(void *argument)
{
    range_job *job = argument;
    size_t i;
    job->kept = job->skipped = 0;
    job->stop = job->end;
    for (i = job->begin; i < job->end; i++) {
        rayo_triangle shape;
        rayo_vec3 normal;
        int verdict = scene_mesh_place(job->f, i, &shape, &normal);
        if (verdict == 0) {
            job->skipped++;
            continue;
        }
        if (verdict < 0) {
            job->stop = i;
            break;
        }
        scene_triangle_set(&job->out[job->begin + job->kept], &shape, normal);
        job->kept++;
    }
    return NULL;
}

size_t scene_mesh_place_all(rayo_scene *scene, const mesh_frame *f,
                            unsigned threads, size_t *skipped, size_t *stop)
{
    size_t count = f->mesh->count, added = 0;
    unsigned n = threads, i;
    range_job one, *jobs = &one;
    /* An empty mesh reserved nothing: the arrays may be NULL, and even
       NULL + 0 is undefined. */
    if (count == 0) {
        *stop = 0;
        return 0;
    }
    if (n > THREAD_RUN_MAX)
        n = THREAD_RUN_MAX;
    if (n > count / RANGE_MIN)
        n = (unsigned)(count / RANGE_MIN);
    if (n < 1)
        n = 1;
    if (n > 1) {
        jobs = malloc(n * sizeof *jobs);
        if (jobs == NULL) {
            jobs = &one;
            n = 1;
        }
    }
    for (i = 0; i < n; i++) {
        jobs[i].f = f;
        jobs[i].out = scene->triangles + scene->triangle_count;
        jobs[i].begin = count * i / n;
        jobs[i].end = count * (i + 1) / n;
    }
    if (n == 1)
        place_range(jobs);
    else
        thread_run_each(n, place_range, jobs, sizeof *jobs);
    *stop = count;
    for (i = 0; i < n; i++) {
        range_job *job = &jobs[i];
        if (added != job->begin)
            memmove(job->out + added, job->out + job->begin,
                    job->kept * sizeof *job->out);
        added += job->kept;
        *skipped += job->skipped;
        if (job->stop < job->end) {
            *stop = job->stop;
            break;
        }
    }
    if (jobs != &one)
        free(jobs);
    return added;
}
