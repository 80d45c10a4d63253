/*
 * query.c - the questions the renderer asks of a scene: the nearest hit
 * along a ray, and whether anything blocks a ray (shadows, hit mode).
 *
 * A prepared scene tests its planes one by one and walks the hierarchy
 * for everything else; an unprepared one tests every object in insertion
 * order.  Both give the same answers, ties in t going to the lowest
 * object index, which the tests check on random scenes.  Nothing here
 * writes to the scene, so any number of threads may query it.
 */
#include "scene_impl.h"

#include "query_packet.h"

#include "../accel/bvh_packet.h"
#include "../accel/bvh_wide.h"

double rayo_scene_object_t(const rayo_scene *scene, uint32_t object,
                           const rayo_ray *ray, double t_min, double t_max)
{
    const scene_object *o = &scene->objects[object];
    double t;
    switch ((rayo_object_kind)o->kind) {
    case RAYO_OBJECT_SPHERE:
        t = rayo_sphere_intersect(&scene->spheres[o->index].shape, ray,
                                  t_min);
        return t < t_max ? t : INFINITY;
    case RAYO_OBJECT_PLANE:
        return rayo_plane_intersect(&scene->planes[o->index].shape, ray,
                                    t_min, t_max);
    case RAYO_OBJECT_TRIANGLE:
        return rayo_triangle_intersect(&scene->triangles[o->index].shape,
                                       ray, t_min, t_max);
    }
    return INFINITY;
}

static void sphere_at(const void *context, size_t i, uint32_t *prim,
                      rayo_sphere *sphere)
{
    const scene_sphere *s = &((const rayo_scene *)context)->spheres[i];
    *prim = s->object;
    *sphere = s->shape;
}

void rayo_scene_prepare_walks(rayo_scene *scene, unsigned threads)
{
    if (scene->bvh != NULL)
        (void)rayo_bvh_widen_threads(scene->bvh, sphere_at, scene,
                                     scene->sphere_count, threads);
}

typedef struct occlusion_context {
    const rayo_scene *scene;
    size_t skip;
} occlusion_context;

static double nearest_test(const void *context, uint32_t prim,
                           const rayo_ray *ray, double t_min, double t_max)
{
    return rayo_scene_object_t(context, prim, ray, t_min, t_max);
}

static double occlusion_test(const void *context, uint32_t prim,
                             const rayo_ray *ray, double t_min, double t_max)
{
    const occlusion_context *c = context;
    if ((size_t)prim == c->skip)
        return INFINITY;
    return rayo_scene_object_t(c->scene, prim, ray, t_min, t_max);
}

static void fill_hit(const rayo_scene *scene, const rayo_ray *ray,
                     uint32_t object, double t, rayo_hit *hit)
{
    const scene_object *o = &scene->objects[object];
    hit->t = t;
    hit->point = rayo_ray_at(ray, t);
    hit->object = object;
    switch ((rayo_object_kind)o->kind) {
    case RAYO_OBJECT_SPHERE: {
        const scene_sphere *s = &scene->spheres[o->index];
        hit->normal = rayo_vec3_scale(
            rayo_vec3_sub(hit->point, s->shape.center),
            1.0 / s->shape.radius);
        hit->material = s->material;
        return;
    }
    case RAYO_OBJECT_PLANE: {
        const scene_plane *p = &scene->planes[o->index];
        hit->normal = rayo_plane_facing_normal(&p->shape, ray);
        hit->material = p->material;
        return;
    }
    case RAYO_OBJECT_TRIANGLE: {
        const scene_triangle *tr = &scene->triangles[o->index];
        rayo_vec3 n = tr->normal;
        if (rayo_vec3_dot(n, ray->direction) > 0.0)
            n = rayo_vec3_scale(n, -1.0);
        hit->normal = n;
        hit->material = tr->material;
        return;
    }
    }
}

static void nearest_planes(const rayo_scene *scene, const rayo_ray *ray,
                           double t_min, double t_max, double *best_t,
                           uint32_t *best, rayo_scene_stats *stats)
{
    size_t i;
    for (i = 0; i < scene->plane_count; i++) {
        double t = rayo_plane_intersect(&scene->planes[i].shape, ray, t_min,
                                        t_max);
        stats->prim_tests++;
        if (t < *best_t) {
            *best_t = t;
            *best = scene->planes[i].object;
        }
    }
}

static void nearest_brute(const rayo_scene *scene, const rayo_ray *ray,
                          double t_min, double t_max, double *best_t,
                          uint32_t *best, rayo_scene_stats *stats)
{
    size_t i;
    for (i = 0; i < scene->object_count; i++) {
        double t = rayo_scene_object_t(scene, (uint32_t)i, ray, t_min, t_max);
        stats->prim_tests++;
        if (t < *best_t) {
            *best_t = t;
            *best = (uint32_t)i;
        }
    }
}

int rayo_scene_intersect_counted(const rayo_scene *scene,
                                 const rayo_ray *ray, double t_min,
                                 double t_max, rayo_hit *hit,
                                 rayo_scene_stats *stats)
{
    double best_t = INFINITY;
    uint32_t best = UINT32_MAX;
    stats->rays++;
    if (scene->bvh != NULL) {
        rayo_bvh_cost cost = {0, 0};
        nearest_planes(scene, ray, t_min, t_max, &best_t, &best, stats);
        if (!rayo_bvh_wide_nearest(scene->bvh, ray, t_min, t_max,
                                   nearest_test, scene, &best_t, &best,
                                   &cost))
            rayo_bvh_nearest(scene->bvh, ray, t_min, t_max, nearest_test,
                             scene, &best_t, &best, &cost);
        stats->node_tests += cost.node_tests;
        stats->prim_tests += cost.prim_tests;
    } else {
        nearest_brute(scene, ray, t_min, t_max, &best_t, &best, stats);
    }
    if (best == UINT32_MAX)
        return 0;
    fill_hit(scene, ray, best, best_t, hit);
    return 1;
}

int rayo_scene_intersect(const rayo_scene *scene, const rayo_ray *ray,
                         double t_min, double t_max, rayo_hit *hit)
{
    rayo_scene_stats stats = {0, 0, 0};
    return rayo_scene_intersect_counted(scene, ray, t_min, t_max, hit,
                                        &stats);
}

static int occluded_brute(const rayo_scene *scene, const rayo_ray *ray,
                          double t_min, double t_max, size_t skip,
                          rayo_scene_stats *stats)
{
    size_t i;
    for (i = 0; i < scene->object_count; i++) {
        if (i == skip)
            continue;
        stats->prim_tests++;
        if (rayo_scene_object_t(scene, (uint32_t)i, ray, t_min, t_max) <
            INFINITY)
            return 1;
    }
    return 0;
}

/* 1 when a plane other than object skip blocks the ray within
 * (t_min, t_max); each plane tested is counted. */
static int planes_block(const rayo_scene *scene, const rayo_ray *ray,
                        double t_min, double t_max, size_t skip,
                        rayo_scene_stats *stats)
{
    size_t i;
    for (i = 0; i < scene->plane_count; i++) {
        if (scene->planes[i].object == skip)
            continue;
        stats->prim_tests++;
        if (rayo_plane_intersect(&scene->planes[i].shape, ray, t_min,
                                 t_max) < INFINITY)
            return 1;
    }
    return 0;
}

/* An object to skip as the hierarchy's primitive number (UINT32_MAX:
 * none, as RAYO_NO_OBJECT and every index past it are). */
static uint32_t skip_prim(size_t skip)
{
    return skip < UINT32_MAX ? (uint32_t)skip : UINT32_MAX;
}

int rayo_scene_occluded_counted(const rayo_scene *scene,
                                const rayo_ray *ray, double t_min,
                                double t_max, size_t skip,
                                rayo_scene_stats *stats)
{
    occlusion_context context;
    rayo_bvh_cost cost = {0, 0};
    int found;
    stats->rays++;
    if (scene->bvh == NULL)
        return occluded_brute(scene, ray, t_min, t_max, skip, stats);
    if (planes_block(scene, ray, t_min, t_max, skip, stats))
        return 1;
    context.scene = scene;
    context.skip = skip;
    found = rayo_bvh_wide_any(scene->bvh, ray, t_min, t_max,
                              skip_prim(skip), occlusion_test, &context,
                              &cost);
    if (found < 0)
        found = rayo_bvh_any(scene->bvh, ray, t_min, t_max, occlusion_test,
                             &context, &cost);
    stats->node_tests += cost.node_tests;
    stats->prim_tests += cost.prim_tests;
    return found;
}

int rayo_scene_occluded(const rayo_scene *scene, const rayo_ray *ray,
                        double t_min, double t_max, size_t skip)
{
    rayo_scene_stats stats = {0, 0, 0};
    return rayo_scene_occluded_counted(scene, ray, t_min, t_max, skip,
                                       &stats);
}

int rayo_scene_hit_any(const rayo_scene *scene, const rayo_ray *ray,
                       double t_min)
{
    return rayo_scene_occluded(scene, ray, t_min, INFINITY, RAYO_NO_OBJECT);
}

unsigned rayo_scene_intersect_packet(const rayo_scene *scene,
                                     const rayo_ray *rays, unsigned count,
                                     double t_min, rayo_hit *hits)
{
    double best_t[RAYO_BVH_PACKET];
    uint32_t best[RAYO_BVH_PACKET];
    unsigned k, found = 0;
    if (count > RAYO_SCENE_PACKET)
        count = RAYO_SCENE_PACKET;
    if (!rayo_bvh_packets_on(scene->bvh)) {
        for (k = 0; k < count; k++)
            if (rayo_scene_intersect(scene, &rays[k], t_min, INFINITY,
                                     &hits[k]))
                found |= 1u << k;
        return found;
    }
    for (k = 0; k < RAYO_BVH_PACKET; k++) {
        rayo_scene_stats stats = {0, 0, 0};
        best_t[k] = INFINITY;
        best[k] = UINT32_MAX;
        if (k < count)
            nearest_planes(scene, &rays[k], t_min, INFINITY, &best_t[k],
                           &best[k], &stats);
    }
    rayo_bvh_packet_nearest(scene->bvh, rays, (1u << count) - 1, t_min,
                            INFINITY, nearest_test, scene, best_t, best);
    for (k = 0; k < count; k++)
        if (best[k] != UINT32_MAX) {
            fill_hit(scene, &rays[k], best[k], best_t[k], &hits[k]);
            found |= 1u << k;
        }
    return found;
}

unsigned rayo_scene_occluded_packet(const rayo_scene *scene,
                                    const rayo_ray *rays, unsigned lanes,
                                    const double *t_min, const double *t_max,
                                    const size_t *skip)
{
    uint32_t skip32[RAYO_BVH_PACKET];
    unsigned k, blocked = 0, open = 0;
    lanes &= (1u << RAYO_SCENE_PACKET) - 1;
    if (!rayo_bvh_packets_on(scene->bvh)) {
        for (k = 0; k < RAYO_SCENE_PACKET; k++)
            if ((lanes >> k) & 1u &&
                rayo_scene_occluded(scene, &rays[k], t_min[k], t_max[k],
                                    skip[k]))
                blocked |= 1u << k;
        return blocked;
    }
    for (k = 0; k < RAYO_SCENE_PACKET; k++) {
        rayo_scene_stats stats = {0, 0, 0};
        skip32[k] = UINT32_MAX;
        if (!((lanes >> k) & 1u))
            continue;
        skip32[k] = skip_prim(skip[k]);
        if (planes_block(scene, &rays[k], t_min[k], t_max[k], skip[k],
                         &stats))
            blocked |= 1u << k;
        else
            open |= 1u << k;
    }
    if (open)
        blocked |= rayo_bvh_packet_any(scene->bvh, rays, open, t_min, t_max,
                                       skip32, nearest_test, scene);
    return blocked;
}
