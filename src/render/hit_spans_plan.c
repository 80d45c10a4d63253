/*
 * hit_spans_plan.c - what every row of a hit-mode frame shares, worked
 * out once before the rows (rayo_hit_spans_plan): whether spans apply
 * at all (spheres alone, not too many, a focal length the error bounds
 * cover), and for each sphere C - O, l.a, the error bounds and the
 * levels the rows' estimates are compared with (hit_spans.c argues
 * them), and whether the camera is outside it, inside it, or too near
 * its surface for spans.
 */
#include "hit_spans_impl.h"

#include <math.h>
#include <stdlib.h>

/* Focal lengths past this (fields of view of a few microdegrees) are left
 * to the per-pixel loop, so every product below stays far from overflow. */
#define MAX_FOCAL 1099511627776.0
/* A sphere costs a few pixels' worth of work on every row, so past one
 * sphere per pixel column (and a handful on tiny frames) the per-pixel
 * loop, with its bounding volume hierarchy, wins. */
#define MAX_SPHERES_ANY_WIDTH 16u


/* A sphere's frame constants (see sphere_kind). */
void hit_spans_plan_sphere(const rayo_camera *camera,
                           const rayo_sphere *sphere, sphere_frame *frame)
{
    rayo_vec3 l = rayo_vec3_sub(sphere->center, camera->origin);
    double ll = rayo_vec3_dot(l, l), rr = sphere->radius * sphere->radius;
    double scale = UNIT_ROUNDOFF * (ll + rr);
    double e = DELTA_ERROR * scale, t = ESTIMATE_ERROR * scale;
    double margin = 4.0 * (e + 3.0 * t);
    sphere_row *s = &frame->row;
    frame->l = l;
    s->sphere = sphere;
    s->length = sqrt(ll);
    s->p = rayo_vec3_dot(l, camera->right);
    s->q = 0.0;
    s->k = ll - rr;
    s->surely_hit = e + t;
    s->surely_missed = -(e + 3.0 * t);
    s->hit_level = s->k + s->surely_hit;
    s->miss_level = s->k + s->surely_missed;
    if (!isfinite(scale))
        frame->kind = SPHERE_NEAR;
    else if (s->k < -margin)
        frame->kind = SPHERE_AROUND;
    else if (s->k <= margin)
        frame->kind = SPHERE_NEAR;
    else
        frame->kind = SPHERE_OUTSIDE;
}

static int spans_apply(const rayo_camera *camera, const rayo_scene *scene)
{
    size_t spheres = rayo_scene_sphere_count(scene);
    if (spheres != rayo_scene_object_count(scene))
        return 0;
    if (spheres > MAX_SPHERES_ANY_WIDTH && spheres > camera->width)
        return 0;
    return isfinite(camera->focal) && camera->focal <= MAX_FOCAL;
}

rayo_hit_spans *rayo_hit_spans_plan(const rayo_camera *camera,
                                    const rayo_scene *scene)
{
    rayo_hit_spans *plan;
    size_t i;
    if (!spans_apply(camera, scene))
        return NULL;
    plan = malloc(sizeof *plan);
    if (plan == NULL)
        return NULL;
    plan->camera = camera;
    plan->a2 = rayo_vec3_dot(camera->right, camera->right);
    plan->half_width = (double)(camera->width / 2);
    plan->half_height = (double)(camera->height / 2);
    plan->ahead = rayo_vec3_scale(camera->forward, camera->focal);
    plan->count = rayo_scene_sphere_count(scene);
    plan->spheres = malloc((plan->count ? plan->count : 1) *
                           sizeof *plan->spheres);
    if (plan->spheres == NULL) {
        free(plan);
        return NULL;
    }
    for (i = 0; i < plan->count; i++)
        hit_spans_plan_sphere(camera, rayo_scene_sphere(scene, i),
                              &plan->spheres[i]);
    return plan;
}

void rayo_hit_spans_free(rayo_hit_spans *plan)
{
    if (plan == NULL)
        return;
    free(plan->spheres);
    free(plan);
}
