/*
 * shade_course_gray.c - the course's scene 2 model (escenas-del-curso.md),
 * to the letter.
 *
 * Intensities are levels, as the course gives them: IA is the scene's
 * ambient (its first component) and II each light's colour (its first
 * component).  A ray that meets nothing gives the background (black by
 * default).  At the nearest hit P with unit normal N,
 *     I = IA + sum over lights of II * (L.N)
 * where a light counts when L.N > 0 and no other object lies on the ray
 * from P towards it (the whole half-line, t > 0, the hit object itself
 * excluded).  L is a directional light's stored direction, or
 * normalise(position - P) for a point light.  Values above 255 become
 * 255; truncating to an integer is the row loop's job.  Materials are
 * not used.  Not for anything but reproducing the course.
 */
#include "shade.h"

static double light_term(const rayo_scene *scene, const rayo_hit *hit,
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
    return light->color.x * cosine;
}

rayo_vec3 rayo_shade_course_gray(const rayo_scene *scene,
                                 const rayo_ray *ray)
{
    rayo_hit hit;
    double level;
    size_t i, n = rayo_scene_light_count(scene);
    if (!rayo_scene_intersect(scene, ray, 0.0, INFINITY, &hit)) {
        level = rayo_scene_background(scene).x;
    } else {
        level = rayo_scene_ambient(scene).x;
        for (i = 0; i < n; i++)
            level += light_term(scene, &hit, rayo_scene_light(scene, i));
    }
    if (level > 255.0)
        level = 255.0;
    if (!(level > 0.0))
        level = 0.0;
    return rayo_vec3_make(level, level, level);
}
