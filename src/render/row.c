/*
 * row.c - one row of pixels: the per-pixel loop of every shading mode.
 *
 * This is the only place that knows what a shading mode does with a hit,
 * and which path a frame's rows take (row_plan.h); render.c only
 * schedules rows.
 */
#include <string.h>

#include "rayo/render.h"

#include "row_plan.h"
#include "shade.h"

#include "../scene/query_packet.h"

/* Pixels of the hit loop between two polls of the stop: a pixel is one
 * ray, and a poll would cost a good part of a cheap one. */
#define HIT_PIXELS_PER_POLL 64u

_Static_assert(RAYO_SCENE_PACKET == 4,
               "render_row_hit's constant lanes are written out for four");

/* The per-pixel loop of hit mode, four neighbouring pixels' rays at a
 * time (query_packet.h: each ray gets its own answer). */
static void render_row_hit(const rayo_camera *camera, const rayo_scene *scene,
                           rayo_render_stop *stop, uint32_t row,
                           unsigned char *out)
{
    static const double t_min[RAYO_SCENE_PACKET] = {0.0, 0.0, 0.0, 0.0};
    static const double t_max[RAYO_SCENE_PACKET] = {INFINITY, INFINITY,
                                                    INFINITY, INFINITY};
    static const size_t skip[RAYO_SCENE_PACKET] = {
        RAYO_NO_OBJECT, RAYO_NO_OBJECT, RAYO_NO_OBJECT, RAYO_NO_OBJECT};
    uint32_t i;
    memset(out, 0, ((size_t)camera->width + 7) / 8);
    for (i = 0; i < camera->width; i += RAYO_SCENE_PACKET) {
        rayo_ray rays[RAYO_SCENE_PACKET];
        unsigned k, n = camera->width - i < RAYO_SCENE_PACKET
                            ? camera->width - i
                            : RAYO_SCENE_PACKET,
                    hits;
        if (i % HIT_PIXELS_PER_POLL == 0 && rayo_render_stopping(stop))
            return;
        for (k = 0; k < n; k++)
            rays[k] = rayo_camera_ray(camera, (double)(i + k), (double)row);
        hits = rayo_scene_occluded_packet(scene, rays, (1u << n) - 1, t_min,
                                          t_max, skip);
        for (k = 0; k < n; k++)
            if ((hits >> k) & 1u)
                out[(i + k) >> 3] = (unsigned char)(out[(i + k) >> 3] |
                                                    (0x80u >> ((i + k) & 7)));
    }
}

void rayo_row_plan_init(rayo_row_plan *plan, const rayo_camera *camera,
                        const rayo_scene *scene,
                        const rayo_render_options *options)
{
    plan->camera = camera;
    plan->scene = scene;
    plan->options = options;
    plan->hit_only =
        options->shade == RAYO_SHADE_HIT && options->samples <= 1;
    plan->spans = plan->hit_only ? rayo_hit_spans_plan(camera, scene) : NULL;
    plan->stop = NULL;
}

void rayo_row_plan_render(const rayo_row_plan *plan, uint32_t row,
                          unsigned char *out)
{
    if (plan->spans != NULL)
        rayo_hit_spans_render(plan->spans, row, out); /* the same bits */
    else if (plan->hit_only)
        render_row_hit(plan->camera, plan->scene, plan->stop, row, out);
    else
        rayo_render_row_shaded(plan->camera, plan->scene, plan->options,
                               plan->stop, row, out);
}

void rayo_row_plan_render_rows(const rayo_row_plan *plan, uint32_t first,
                               uint32_t count, unsigned char *out,
                               size_t stride, rayo_row_runs *runs)
{
    uint32_t r;
    if (plan->spans != NULL) {
        rayo_hit_spans_render_rows(plan->spans, first, count, out, stride,
                                   runs);
        return;
    }
    for (r = 0; r < count && !rayo_render_stopping(plan->stop); r++) {
        rayo_row_plan_render(plan, first + r, out + (size_t)r * stride);
        if (runs != NULL)
            runs[r].count = RAYO_ROW_RUNS_BITS;
    }
}

int rayo_row_plan_has_runs(const rayo_row_plan *plan)
{
    return plan->spans != NULL;
}

void rayo_row_plan_free(rayo_row_plan *plan)
{
    rayo_hit_spans_free(plan->spans);
    plan->spans = NULL;
}

void rayo_render_row(const rayo_camera *camera, const rayo_scene *scene,
                     const rayo_render_options *options, uint32_t row,
                     unsigned char *out)
{
    rayo_row_plan plan;
    rayo_row_plan_init(&plan, camera, scene, options);
    rayo_row_plan_render(&plan, row, out);
    rayo_row_plan_free(&plan);
}

rayo_image_info rayo_render_image_info(const rayo_camera *camera,
                                       const rayo_render_options *options)
{
    switch (options->shade) {
    case RAYO_SHADE_HIT:
        break;
    case RAYO_SHADE_COURSE_GRAY:
        return rayo_image_info_gray8(camera->width, camera->height);
    case RAYO_SHADE_COURSE_COLOR:
    case RAYO_SHADE_PHONG:
    case RAYO_SHADE_COURSE_TP1:
        return rayo_image_info_rgb8(camera->width, camera->height);
    }
    return rayo_image_info_bit(camera->width, camera->height);
}
