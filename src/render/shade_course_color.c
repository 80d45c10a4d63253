/*
 * shade_course_color.c - the course's scene 3 model
 * (escenas-del-curso.md), to the letter.
 *
 * Colours are RGB in [0, 1].  A ray that meets nothing gives the
 * background (black by default).  At the nearest hit P with unit normal
 * N, on an object of material (M, ka, kd),
 *     C = Ia * ka + sum over lights i of delta_i * Ii * kd * (Li.N)
 * where delta_i = 1 when Li.N > 0 and no other object lies on the ray
 * from P towards light i (the whole half-line, t > 0, the hit object
 * excluded), else 0; Li is a directional light's stored direction, or
 * normalise(position - P) for a point light.  The pixel is C (x) M,
 * component by component, each channel above 1 becoming 1; the byte,
 * the integer part of 255 c, is the row loop's job.  ks, shininess and
 * reflectivity are not used.
 */
#include "shade.h"

static double clamp_channel(double c)
{
    if (c > 1.0)
        return 1.0;
    return c > 0.0 ? c : 0.0;
}

rayo_vec3 rayo_shade_course_color(const rayo_scene *scene,
                                  const rayo_ray *ray)
{
    rayo_hit hit;
    const rayo_material *m;
    rayo_vec3 c;
    size_t i, n = rayo_scene_light_count(scene);
    if (!rayo_scene_intersect(scene, ray, 0.0, INFINITY, &hit)) {
        c = rayo_scene_background(scene);
    } else {
        m = rayo_scene_material(scene, hit.material);
        c = rayo_vec3_scale(rayo_scene_ambient(scene), m->ka);
        for (i = 0; i < n; i++) {
            const rayo_light *light = rayo_scene_light(scene, i);
            double cosine = rayo_shade_course_light(scene, &hit, light);
            c = rayo_vec3_add(c,
                              rayo_vec3_scale(light->color, m->kd * cosine));
        }
        c = rayo_vec3_mul(c, m->color);
    }
    return rayo_vec3_make(clamp_channel(c.x), clamp_channel(c.y),
                          clamp_channel(c.z));
}
