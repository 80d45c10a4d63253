/*
 * row.c - one row of pixels: the per-pixel loop of every shading mode.
 *
 * This is the only place that knows what a shading mode does with a hit;
 * render.c only schedules rows.
 */
#include <string.h>

#include "rayo/render.h"

#include "hit_spans.h"
#include "shade.h"

static void render_row_hit(const rayo_camera *camera, const rayo_scene *scene,
                           uint32_t row, unsigned char *out)
{
    uint32_t i;
    if (rayo_hit_spans_row(camera, scene, row, out))
        return; /* the same bits, from spans (hit_spans.c) */
    memset(out, 0, ((size_t)camera->width + 7) / 8);
    for (i = 0; i < camera->width; i++) {
        rayo_ray ray = rayo_camera_ray(camera, (double)i, (double)row);
        if (rayo_scene_hit_any(scene, &ray, 0.0))
            out[i >> 3] = (unsigned char)(out[i >> 3] | (0x80u >> (i & 7)));
    }
}

void rayo_render_row(const rayo_camera *camera, const rayo_scene *scene,
                     const rayo_render_options *options, uint32_t row,
                     unsigned char *out)
{
    switch (options->shade) {
    case RAYO_SHADE_HIT:
        if (options->samples > 1)
            rayo_render_row_shaded(camera, scene, options, row, out);
        else
            render_row_hit(camera, scene, row, out);
        break;
    case RAYO_SHADE_COURSE_GRAY:
    case RAYO_SHADE_COURSE_COLOR:
    case RAYO_SHADE_PHONG:
        rayo_render_row_shaded(camera, scene, options, row, out);
        break;
    }
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
        return rayo_image_info_rgb8(camera->width, camera->height);
    }
    return rayo_image_info_bit(camera->width, camera->height);
}
