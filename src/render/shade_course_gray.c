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
        for (i = 0; i < n; i++) {
            const rayo_light *light = rayo_scene_light(scene, i);
            level += light->color.x *
                     rayo_shade_course_light(scene, &hit, light);
        }
    }
    if (level > 255.0)
        level = 255.0;
    if (!(level > 0.0))
        level = 0.0;
    return rayo_vec3_make(level, level, level);
}
