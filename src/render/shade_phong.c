/*
 * shade_phong.c - the general model: Phong's ambient, diffuse and
 * specular terms per light, shadows, and mirror reflections followed to
 * a depth limit (Whitted), for every kind of object.
 *
 * At the nearest hit P, with N the unit normal turned to face the ray,
 * V = -d the direction back to the viewer and a material (M, ka, kd, ks,
 * shininess n, reflectivity r):
 *     C = ka Ia (x) M
 *       + sum over lights i of delta_i Ii (x) (kd (Li.N) M + ks (Ri.V)^n)
 *       + r * colour of the reflected ray d - 2 (d.N) N
 * where Ri = 2 (Li.N) N - Li, (Ri.V) counts only when positive, and
 * delta_i = 1 when Li.N > 0 and nothing lies between P and the light (up
 * to a point light's distance; the whole half-line for a directional
 * light).  A ray that meets nothing brings back the background.  The
 * reflected ray is followed only while depth lasts.  Values are not
 * clamped here: the row loop clamps each channel to [0, 1].
 */
#include "shade.h"

/* Secondary rays start a little past their origin, against acne. */
static double self_offset(rayo_vec3 p)
{
    double m = fabs(p.x);
    if (fabs(p.y) > m)
        m = fabs(p.y);
    if (fabs(p.z) > m)
        m = fabs(p.z);
    return 1e-9 * (1.0 + m);
}

static rayo_vec3 light_term(const rayo_scene *scene, const rayo_hit *hit,
                            rayo_vec3 normal, rayo_vec3 view,
                            const rayo_material *m, const rayo_light *light)
{
    rayo_ray shadow;
    double distance = INFINITY, cosine, specular = 0.0;
    rayo_vec3 term;
    shadow.origin = hit->point;
    if (light->kind == RAYO_LIGHT_DIRECTIONAL) {
        shadow.direction = light->vector;
    } else {
        rayo_vec3 to_light = rayo_vec3_sub(light->vector, hit->point);
        distance = rayo_vec3_length(to_light);
        if (!(distance > 0.0))
            return rayo_vec3_make(0, 0, 0);
        shadow.direction = rayo_vec3_scale(to_light, 1.0 / distance);
    }
    cosine = rayo_vec3_dot(shadow.direction, normal);
    if (!(cosine > 0.0))
        return rayo_vec3_make(0, 0, 0);
    if (rayo_scene_occluded(scene, &shadow, self_offset(hit->point),
                            distance, hit->object))
        return rayo_vec3_make(0, 0, 0);
    term = rayo_vec3_scale(m->color, m->kd * cosine);
    if (m->ks > 0.0) {
        rayo_vec3 mirror = rayo_vec3_sub(
            rayo_vec3_scale(normal, 2.0 * cosine), shadow.direction);
        double rv = rayo_vec3_dot(mirror, view);
        if (rv > 0.0)
            specular = m->ks * pow(rv, m->shininess);
    }
    term = rayo_vec3_add(term, rayo_vec3_make(specular, specular, specular));
    return rayo_vec3_mul(term, light->color);
}

static rayo_vec3 trace(const rayo_scene *scene, const rayo_ray *ray,
                       double t_min, unsigned depth);

static rayo_vec3 reflection(const rayo_scene *scene, const rayo_ray *ray,
                            const rayo_hit *hit, rayo_vec3 normal,
                            unsigned depth)
{
    rayo_ray bounce;
    double along = rayo_vec3_dot(ray->direction, normal);
    bounce.origin = hit->point;
    bounce.direction = rayo_vec3_normalize(rayo_vec3_sub(
        ray->direction, rayo_vec3_scale(normal, 2.0 * along)));
    return trace(scene, &bounce, self_offset(hit->point), depth);
}

static rayo_vec3 trace(const rayo_scene *scene, const rayo_ray *ray,
                       double t_min, unsigned depth)
{
    rayo_hit hit;
    const rayo_material *m;
    rayo_vec3 normal, view, c;
    size_t i, n = rayo_scene_light_count(scene);
    if (!rayo_scene_intersect(scene, ray, t_min, INFINITY, &hit))
        return rayo_scene_background(scene);
    m = rayo_scene_material(scene, hit.material);
    normal = hit.normal;
    if (rayo_vec3_dot(normal, ray->direction) > 0.0)
        normal = rayo_vec3_scale(normal, -1.0);
    view = rayo_vec3_scale(ray->direction, -1.0);
    c = rayo_vec3_scale(rayo_vec3_mul(rayo_scene_ambient(scene), m->color),
                        m->ka);
    for (i = 0; i < n; i++)
        c = rayo_vec3_add(c, light_term(scene, &hit, normal, view, m,
                                        rayo_scene_light(scene, i)));
    if (m->reflectivity > 0.0 && depth > 0)
        c = rayo_vec3_add(c, rayo_vec3_scale(reflection(scene, ray, &hit,
                                                        normal, depth - 1),
                                             m->reflectivity));
    return c;
}

rayo_vec3 rayo_shade_phong(const rayo_scene *scene, const rayo_ray *ray,
                           unsigned depth)
{
    return trace(scene, ray, 0.0, depth);
}
