/*
 * shade_course_tp1.c - the course's TP1 model (trabajo-practico-1.md),
 * to the letter: Phong with the statement's exponent, 10, and its
 * reflections; the formula is below.  Each dot product that is negative
 * zeroes its own term only, shadows are visibility only, depth 0 is the
 * scene without reflections, and each channel above 1 becomes 1 at the
 * end; the byte, the integer part of 255 c, is the row loop's job.  The
 * shininess the scene gives a material is not used.
 */
#include "shade.h"

/*
 * At the nearest hit P with unit normal N (turned towards the ray, as
 * the scene gives it), D the ray's direction, R = D - 2 N (D.N) and a
 * material (M, ka, kd, ks, kr):
 *     C = Ia ka + sum over lights i of delta_i Ii [kd (Li.N) + ks (Li.R)^10]
 * where each dot product that is negative zeroes its own term only, and
 * delta_i is visibility only: 0 when an object lies on the ray from
 * P + eps Li towards the light (anything in that direction, or with
 * shadows_to_light only up to a point light).  The colour is C (x) M,
 * and with depth left and kr > 0 the reflection is added:
 *     C' = C (x) M + kr I(P + eps R, R)        (or, tinted, (C + kr I) (x) M)
 * where I is this same model one bounce shallower.  A ray that meets
 * nothing gives the background (black by default).
 */

#define TP1_EXPONENT 10

void rayo_tp1_reading_init(rayo_tp1_reading *reading)
{
    reading->tinted_reflection = 0;
    reading->shadows_to_light = 0;
    reading->epsilon = 1e-6;
}

static rayo_vec3 step(rayo_vec3 p, rayo_vec3 d, double epsilon)
{
    return rayo_vec3_add(p, rayo_vec3_scale(d, epsilon));
}

/* delta_i: 1 when nothing hides the light from P (towards it, unit). */
static int visible(const rayo_scene *scene, const rayo_hit *hit,
                   rayo_vec3 towards, double distance,
                   const rayo_tp1_reading *reading)
{
    rayo_ray shadow;
    double reach = reading->shadows_to_light && distance < INFINITY
                       ? distance - reading->epsilon
                       : INFINITY;
    shadow.origin = step(hit->point, towards, reading->epsilon);
    shadow.direction = towards;
    return !rayo_scene_occluded(scene, &shadow, 0.0, reach, RAYO_NO_OBJECT);
}

static rayo_vec3 tp1_trace(const rayo_scene *scene, const rayo_ray *ray,
                           unsigned depth, const rayo_tp1_reading *reading)
{
    rayo_hit hit;
    const rayo_material *m;
    rayo_vec3 c, mirror;
    size_t i, n = rayo_scene_light_count(scene);
    if (!rayo_scene_intersect(scene, ray, 0.0, INFINITY, &hit))
        return rayo_scene_background(scene);
    m = rayo_scene_material(scene, hit.material);
    mirror = rayo_vec3_sub(
        ray->direction,
        rayo_vec3_scale(hit.normal,
                        2.0 * rayo_vec3_dot(ray->direction, hit.normal)));
    c = rayo_vec3_scale(rayo_scene_ambient(scene), m->ka);
    for (i = 0; i < n; i++) {
        const rayo_light *light = rayo_scene_light(scene, i);
        rayo_vec3 towards = light->vector;
        double distance = INFINITY, diffuse, specular;
        if (light->kind == RAYO_LIGHT_POINT) {
            rayo_vec3 to = rayo_vec3_sub(light->vector, hit.point);
            distance = rayo_vec3_length(to);
            towards = rayo_vec3_scale(to, 1.0 / distance);
        }
        if (!visible(scene, &hit, towards, distance, reading))
            continue;
        diffuse = rayo_vec3_dot(towards, hit.normal);
        specular = rayo_vec3_dot(towards, mirror);
        diffuse = diffuse > 0.0 ? m->kd * diffuse : 0.0;
        specular = specular > 0.0 ? m->ks * pow(specular, TP1_EXPONENT)
                                  : 0.0;
        c = rayo_vec3_add(c, rayo_vec3_scale(light->color,
                                             diffuse + specular));
    }
    if (depth > 0 && m->reflectivity > 0.0) {
        rayo_ray bounce;
        rayo_vec3 reflected;
        bounce.origin = step(hit.point, mirror, reading->epsilon);
        bounce.direction = mirror;
        reflected = rayo_vec3_scale(tp1_trace(scene, &bounce, depth - 1,
                                              reading),
                                    m->reflectivity);
        if (reading->tinted_reflection)
            return rayo_vec3_mul(rayo_vec3_add(c, reflected), m->color);
        return rayo_vec3_add(rayo_vec3_mul(c, m->color), reflected);
    }
    return rayo_vec3_mul(c, m->color);
}

static double clamp_channel(double c)
{
    if (c > 1.0)
        return 1.0;
    return c > 0.0 ? c : 0.0;
}

rayo_vec3 rayo_shade_course_tp1(const rayo_scene *scene, const rayo_ray *ray,
                                unsigned depth,
                                const rayo_tp1_reading *reading)
{
    rayo_vec3 c = tp1_trace(scene, ray, depth, reading);
    return rayo_vec3_make(clamp_channel(c.x), clamp_channel(c.y),
                          clamp_channel(c.z));
}
