/*
 * scene.c - the list of objects and the queries the renderer asks of it.
 *
 * Spheres live in one growing array; rayo_scene_hit_any tests them in
 * order and stops at the first hit.
 */
#include "rayo/scene.h"

#include <stdlib.h>

#include "rayo/limits.h"

struct rayo_scene {
    rayo_sphere *spheres;
    size_t sphere_count, sphere_capacity;
};

rayo_status rayo_scene_create(rayo_scene **result, rayo_error *err)
{
    *result = calloc(1, sizeof **result);
    if (*result == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
    return RAYO_OK;
}

void rayo_scene_free(rayo_scene *scene)
{
    if (scene == NULL)
        return;
    free(scene->spheres);
    free(scene);
}

rayo_status rayo_scene_add_sphere(rayo_scene *scene, rayo_vec3 center,
                                  double radius, rayo_error *err)
{
    if (!rayo_vec3_is_finite(center))
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "sphere centre is not finite");
    if (!(radius > 0.0) || !isfinite(radius))
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "sphere radius %g is not accepted; expected a "
                              "finite number > 0",
                              radius);
    if (scene->sphere_count >= RAYO_MAX_OBJECTS)
        return rayo_error_set(err, RAYO_ERR_LIMIT,
                              "more than %lu objects in one scene",
                              RAYO_MAX_OBJECTS);
    if (scene->sphere_count == scene->sphere_capacity) {
        size_t capacity =
            scene->sphere_capacity ? 2 * scene->sphere_capacity : 8;
        rayo_sphere *grown =
            realloc(scene->spheres, capacity * sizeof *grown);
        if (grown == NULL)
            return rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
        scene->spheres = grown;
        scene->sphere_capacity = capacity;
    }
    scene->spheres[scene->sphere_count].center = center;
    scene->spheres[scene->sphere_count].radius = radius;
    scene->sphere_count++;
    return RAYO_OK;
}

size_t rayo_scene_sphere_count(const rayo_scene *scene)
{
    return scene->sphere_count;
}

const rayo_sphere *rayo_scene_sphere(const rayo_scene *scene, size_t i)
{
    return &scene->spheres[i];
}

int rayo_scene_hit_any(const rayo_scene *scene, const rayo_ray *ray,
                       double t_min)
{
    size_t i;
    for (i = 0; i < scene->sphere_count; i++)
        if (rayo_sphere_hit(&scene->spheres[i], ray, t_min))
            return 1;
    return 0;
}
