/*
 * scene.h - what the rays can hit.
 *
 * A scene owns its objects.  It answers one question for the renderer:
 * does this ray meet anything, and where first.  It knows nothing of
 * pixels or cameras.
 */
#ifndef RAYO_SCENE_H
#define RAYO_SCENE_H

#include <stddef.h>

#include "rayo/ray.h"
#include "rayo/sphere.h"
#include "rayo/status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct rayo_scene rayo_scene;

rayo_status rayo_scene_create(rayo_scene **scene, rayo_error *err);

/* Frees the scene and everything in it; NULL is allowed. */
void rayo_scene_free(rayo_scene *scene);

/*
 * Adds a sphere.  RAYO_ERR_INVALID when the centre is not finite or the
 * radius is not a finite number > 0; RAYO_ERR_LIMIT past RAYO_MAX_OBJECTS.
 */
rayo_status rayo_scene_add_sphere(rayo_scene *scene, rayo_vec3 center,
                                  double radius, rayo_error *err);

size_t rayo_scene_sphere_count(const rayo_scene *scene);

/* The i-th sphere added, i < rayo_scene_sphere_count(). */
const rayo_sphere *rayo_scene_sphere(const rayo_scene *scene, size_t i);

/* 1 when the ray (unit direction) meets some object at t > t_min. */
int rayo_scene_hit_any(const rayo_scene *scene, const rayo_ray *ray,
                       double t_min);

#ifdef __cplusplus
}
#endif

#endif
