/*
 * shade_phong.c - the general model: Phong's ambient, diffuse and
 * specular terms per light, shadows, and mirror reflections followed to
 * a depth limit (Whitted), for every kind of object; the formula is
 * below.  A ray that meets nothing brings back the background.  The
 * reflected ray is followed only while depth lasts.  Values are not
 * clamped here: the row loop clamps each channel to [0, 1].
 */
#include "shade.h"

#include "../scene/query_packet.h"

/*
 * At the nearest hit P, with N the unit normal turned to face the ray,
 * V = -d the direction back to the viewer and a material (M, ka, kd, ks,
 * shininess n, reflectivity r):
 *     C = ka Ia (x) M
 *       + sum over lights i of delta_i Ii (x) (kd (Li.N) M + ks (Ri.V)^n)
 *       + r * colour of the reflected ray d - 2 (d.N) N
 * where Ri = 2 (Li.N) N - Li, (Ri.V) counts only when positive, and
 * delta_i = 1 when Li.N > 0 and nothing lies between P and the light (up
 * to a point light's distance; the whole half-line for a directional
 * light).
 */

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

/* The shadow ray from the hit towards light, how far it reaches and the
 * cosine at the hit; 0 when the light cannot count there (it faces away,
 * or sits on the point). */
static int light_shadow(const rayo_hit *hit, rayo_vec3 normal,
                        const rayo_light *light, rayo_ray *shadow,
                        double *distance, double *cosine)
{
    *distance = INFINITY;
    shadow->origin = hit->point;
    if (light->kind == RAYO_LIGHT_DIRECTIONAL) {
        shadow->direction = light->vector;
    } else {
        rayo_vec3 to_light = rayo_vec3_sub(light->vector, hit->point);
        *distance = rayo_vec3_length(to_light);
        if (!(*distance > 0.0))
            return 0;
        shadow->direction = rayo_vec3_scale(to_light, 1.0 / *distance);
    }
    *cosine = rayo_vec3_dot(shadow->direction, normal);
    return *cosine > 0.0;
}

/* The light's diffuse and specular terms at a hit it reaches. */
static rayo_vec3 light_lit(rayo_vec3 normal, rayo_vec3 view,
                           const rayo_material *m, const rayo_light *light,
                           const rayo_ray *shadow, double cosine)
{
    double specular = 0.0;
    rayo_vec3 term = rayo_vec3_scale(m->color, m->kd * cosine);
    if (m->ks > 0.0) {
        rayo_vec3 mirror = rayo_vec3_sub(
            rayo_vec3_scale(normal, 2.0 * cosine), shadow->direction);
        double rv = rayo_vec3_dot(mirror, view);
        if (rv > 0.0)
            specular = m->ks * pow(rv, m->shininess);
    }
    term = rayo_vec3_add(term, rayo_vec3_make(specular, specular, specular));
    return rayo_vec3_mul(term, light->color);
}

static rayo_vec3 light_term(const rayo_scene *scene, const rayo_hit *hit,
                            rayo_vec3 normal, rayo_vec3 view,
                            const rayo_material *m, const rayo_light *light)
{
    rayo_ray shadow;
    double distance, cosine;
    if (!light_shadow(hit, normal, light, &shadow, &distance, &cosine))
        return rayo_vec3_make(0, 0, 0);
    if (rayo_scene_occluded(scene, &shadow, self_offset(hit->point),
                            distance, hit->object))
        return rayo_vec3_make(0, 0, 0);
    return light_lit(normal, view, m, light, &shadow, cosine);
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

/* What trace() computes at a hit before its lights: the material, the
 * normal facing the ray, the view and the ambient term. */
typedef struct phong_hit {
    const rayo_material *m;
    rayo_vec3 normal, view, c;
} phong_hit;

static void phong_start(const rayo_scene *scene, const rayo_ray *ray,
                        const rayo_hit *hit, phong_hit *p)
{
    p->m = rayo_scene_material(scene, hit->material);
    p->normal = hit->normal;
    if (rayo_vec3_dot(p->normal, ray->direction) > 0.0)
        p->normal = rayo_vec3_scale(p->normal, -1.0);
    p->view = rayo_vec3_scale(ray->direction, -1.0);
    p->c = rayo_vec3_scale(
        rayo_vec3_mul(rayo_scene_ambient(scene), p->m->color), p->m->ka);
}

/* What trace() adds after its lights: the mirror's share. */
static rayo_vec3 phong_finish(const rayo_scene *scene, const rayo_ray *ray,
                              const rayo_hit *hit, const phong_hit *p,
                              unsigned depth)
{
    if (p->m->reflectivity > 0.0 && depth > 0)
        return rayo_vec3_add(
            p->c, rayo_vec3_scale(reflection(scene, ray, hit, p->normal,
                                             depth - 1),
                                  p->m->reflectivity));
    return p->c;
}

static rayo_vec3 trace(const rayo_scene *scene, const rayo_ray *ray,
                       double t_min, unsigned depth)
{
    rayo_hit hit;
    phong_hit p;
    size_t i, n = rayo_scene_light_count(scene);
    if (!rayo_scene_intersect(scene, ray, t_min, INFINITY, &hit))
        return rayo_scene_background(scene);
    phong_start(scene, ray, &hit, &p);
    for (i = 0; i < n; i++)
        p.c = rayo_vec3_add(p.c, light_term(scene, &hit, p.normal, p.view,
                                            p.m, rayo_scene_light(scene, i)));
    return phong_finish(scene, ray, &hit, &p, depth);
}

/*
 * trace() for up to RAYO_SCENE_PACKET camera rays at once: the nearest
 * hits, then each light's shadow rays, are asked as packets
 * (query_packet.h); everything else is trace()'s arithmetic, ray by ray,
 * in its order (a light that does not count adds a zero term, as
 * light_term's zero does), so each ray's colour is trace()'s to the bit.
 */
void rayo_shade_phong_packet(const rayo_scene *scene, const rayo_ray *rays,
                             unsigned count, unsigned depth, rayo_vec3 *out)
{
    rayo_hit hits[RAYO_SCENE_PACKET];
    phong_hit p[RAYO_SCENE_PACKET];
    size_t i, n = rayo_scene_light_count(scene);
    unsigned k, found;
    if (count > RAYO_SCENE_PACKET)
        count = RAYO_SCENE_PACKET;
    found = rayo_scene_intersect_packet(scene, rays, count, 0.0, hits);
    for (k = 0; k < count; k++)
        if ((found >> k) & 1u)
            phong_start(scene, &rays[k], &hits[k], &p[k]);
    for (i = 0; i < n; i++) {
        const rayo_light *light = rayo_scene_light(scene, i);
        rayo_ray shadow[RAYO_SCENE_PACKET];
        double t_min[RAYO_SCENE_PACKET], t_max[RAYO_SCENE_PACKET];
        double cosine[RAYO_SCENE_PACKET];
        size_t skip[RAYO_SCENE_PACKET];
        unsigned ask = 0, blocked;
        for (k = 0; k < count; k++) {
            if (!((found >> k) & 1u) ||
                !light_shadow(&hits[k], p[k].normal, light, &shadow[k],
                              &t_max[k], &cosine[k]))
                continue;
            t_min[k] = self_offset(hits[k].point);
            skip[k] = hits[k].object;
            ask |= 1u << k;
        }
        blocked = ask ? rayo_scene_occluded_packet(scene, shadow, ask, t_min,
                                                   t_max, skip)
                      : 0;
        for (k = 0; k < count; k++) {
            rayo_vec3 term = rayo_vec3_make(0, 0, 0);
            if (!((found >> k) & 1u))
                continue;
            if ((ask >> k) & 1u && !((blocked >> k) & 1u))
                term = light_lit(p[k].normal, p[k].view, p[k].m, light,
                                 &shadow[k], cosine[k]);
            p[k].c = rayo_vec3_add(p[k].c, term);
        }
    }
    for (k = 0; k < count; k++)
        out[k] = (found >> k) & 1u
                     ? phong_finish(scene, &rays[k], &hits[k], &p[k], depth)
                     : rayo_scene_background(scene);
}

rayo_vec3 rayo_shade_phong(const rayo_scene *scene, const rayo_ray *ray,
                           unsigned depth)
{
    return trace(scene, ray, 0.0, depth);
}
