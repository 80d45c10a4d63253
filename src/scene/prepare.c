/*
 * prepare.c - building the scene's bounding volume hierarchy.
 *
 * Spheres and triangles get padded boxes and their object indices as
 * primitive numbers; planes, being unbounded, stay outside the tree and
 * are tested one by one.  Scenes of at most RAYO_SCENE_BRUTE_MAX spheres
 * and triangles get no tree: testing each is faster than any tree (10
 * spheres: 64 against 92 ns a pixel).  Building replaces any earlier
 * tree; a failure leaves the scene unprepared (queries then fall back to
 * testing every object), never half-built.  The tree is built on as many
 * threads as asked (rayo_scene_prepare: one per CPU), and is the same
 * tree for any number (bvh_build.c).
 */
#include "scene_impl.h"

#include <stdlib.h>

#include "rayo/cpu.h"

static rayo_box sphere_box(const rayo_sphere *s)
{
    rayo_box box;
    box.lo[0] = s->center.x - s->radius;
    box.lo[1] = s->center.y - s->radius;
    box.lo[2] = s->center.z - s->radius;
    box.hi[0] = s->center.x + s->radius;
    box.hi[1] = s->center.y + s->radius;
    box.hi[2] = s->center.z + s->radius;
    rayo_box_pad(&box);
    return box;
}

static rayo_box triangle_box(const rayo_triangle *t)
{
    rayo_box box;
    box.lo[0] = fmin(t->a.x, fmin(t->b.x, t->c.x));
    box.lo[1] = fmin(t->a.y, fmin(t->b.y, t->c.y));
    box.lo[2] = fmin(t->a.z, fmin(t->b.z, t->c.z));
    box.hi[0] = fmax(t->a.x, fmax(t->b.x, t->c.x));
    box.hi[1] = fmax(t->a.y, fmax(t->b.y, t->c.y));
    box.hi[2] = fmax(t->a.z, fmax(t->b.z, t->c.z));
    rayo_box_pad(&box);
    return box;
}

/* The box of the hierarchy's primitive i: spheres, then triangles. */
static void object_box(const void *context, size_t i, rayo_box *box)
{
    const rayo_scene *scene = context;
    if (i < scene->sphere_count)
        *box = sphere_box(&scene->spheres[i].shape);
    else
        *box = triangle_box(
            &scene->triangles[i - scene->sphere_count].shape);
}

rayo_status rayo_scene_prepare_threads(rayo_scene *scene, unsigned threads,
                                       rayo_error *err)
{
    size_t n = scene->sphere_count + scene->triangle_count, k = 0, i;
    uint32_t *ids;
    rayo_bvh *bvh;
    rayo_status status;
    rayo_bvh_free(scene->bvh);
    scene->bvh = NULL;
    scene->prepared = 0;
    if (n <= RAYO_SCENE_BRUTE_MAX) {
        scene->prepared = 1;
        return RAYO_OK;
    }
    if (n > SIZE_MAX / sizeof *ids)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
    ids = malloc(n * sizeof *ids);
    if (ids == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
    for (i = 0; i < scene->sphere_count; i++, k++)
        ids[k] = scene->spheres[i].object;
    for (i = 0; i < scene->triangle_count; i++, k++)
        ids[k] = scene->triangles[i].object;
    if (threads == 0)
        threads = rayo_cpu_count();
    status = rayo_bvh_build_from(&bvh, object_box, scene, ids, n, threads,
                                 err);
    free(ids);
    if (status != RAYO_OK)
        return status;
    scene->bvh = bvh;
    rayo_scene_prepare_walks(scene, threads);
    scene->prepared = 1;
    return RAYO_OK;
}

rayo_status rayo_scene_prepare(rayo_scene *scene, rayo_error *err)
{
    return rayo_scene_prepare_threads(scene, 0, err);
}

int rayo_scene_is_prepared(const rayo_scene *scene)
{
    return scene->prepared;
}
