/*
 * shade_course_light.c - the one rule the course's two lit models (scene
 * 2 in gray, scene 3 in colour; escenas-del-curso.md) share: whether a
 * light reaches a hit point, and at what angle.
 *
 * Li is a directional light's stored direction, or normalise(position - P)
 * for a point light.  The light counts (delta_i = 1) when Li.N > 0 and no
 * other object lies on the ray from P towards it: the whole half-line,
 * t > 0, the hit object itself excluded (so, unlike phong, a point light
 * is blocked by objects beyond it too, as the course's model has it).
 */
#include "shade.h"

double rayo_shade_course_light(const rayo_scene *scene, const rayo_hit *hit,
                               const rayo_light *light)
{
    rayo_ray shadow;
    double cosine;
    shadow.origin = hit->point;
    shadow.direction =
        light->kind == RAYO_LIGHT_DIRECTIONAL
            ? light->vector
            : rayo_vec3_normalize(rayo_vec3_sub(light->vector, hit->point));
    cosine = rayo_vec3_dot(shadow.direction, hit->normal);
    if (!(cosine > 0.0))
        return 0.0;
    if (rayo_scene_occluded(scene, &shadow, 0.0, INFINITY, hit->object))
        return 0.0;
    return cosine;
}
