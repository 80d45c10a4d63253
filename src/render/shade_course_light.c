/*
 * shade_course_light.c - the one rule the course's two lit models (scene
 * 2 in gray, scene 3 in colour; escenas-del-curso.md) share: whether a
 * light reaches a hit point, and at what angle.
 *
 * Li is a directional light's stored direction, or normalise(position - P)
 * for a point light.  The light counts (delta_i = 1) when Li.N > 0 and no
 * other object lies on the ray from P towards it, the hit object itself
 * excluded: the whole half-line for a directional light, and only up to
 * the light for a point light (an object beyond the light casts no
 * shadow; the course's scenes have none, and its graded functions count
 * only occluders between the point and the light).
 */
#include "shade.h"

double rayo_shade_course_light(const rayo_scene *scene, const rayo_hit *hit,
                               const rayo_light *light)
{
    rayo_ray shadow;
    double cosine;
    double reach = INFINITY;
    shadow.origin = hit->point;
    if (light->kind == RAYO_LIGHT_DIRECTIONAL) {
        shadow.direction = light->vector;
    } else {
        rayo_vec3 towards = rayo_vec3_sub(light->vector, hit->point);
        reach = rayo_vec3_length(towards);
        shadow.direction = rayo_vec3_normalize(towards);
    }
    cosine = rayo_vec3_dot(shadow.direction, hit->normal);
    if (!(cosine > 0.0))
        return 0.0;
    if (rayo_scene_occluded(scene, &shadow, 0.0, reach, hit->object))
        return 0.0;
    return cosine;
}
