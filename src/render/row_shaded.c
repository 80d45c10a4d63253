/*
 * row_shaded.c - one row of pixels with N x N stratified samples each:
 * the loop behind every shading mode but one-ray hit renders (row.c).
 *
 * The samples are the centres of an N x N grid over the pixel (N = 1 is
 * exactly the pixel's own ray), summed in a fixed order and divided by
 * N^2, so a pixel depends on nothing but its position: the same bytes for
 * any thread count.  The mean is then turned into a sample of the mode's
 * layout (below).  It knows nothing of what a model computes; shade_*.c
 * do.  Before each ray it polls the render's stop (render_stop.h): one ray
 * of the slowest legal scene takes milliseconds, one pixel of 256 rays
 * seconds.
 */
#include <string.h>

#include "shade.h"

#include "../scene/query_packet.h"

/*
 * Sample (a, b) of pixel (i, j) is the image position
 *     (i + (a + 1/2) / N - 1/2,  j + (b + 1/2) / N - 1/2),
 * a and b from 0 to N - 1.  The mean becomes:
 *   hit           black when at least half the rays hit;
 *   course-gray   the integer part of the level (already clamped to 255);
 *   course-color, course-tp1
 *                 the integer part of 255 c (c already clamped to 1);
 *   phong         255 c rounded to the nearest level, c clamped to [0, 1].
 */

static rayo_vec3 shade_one(const rayo_scene *scene,
                           const rayo_render_options *options,
                           const rayo_ray *ray)
{
    switch (options->shade) {
    case RAYO_SHADE_HIT:
        break;
    case RAYO_SHADE_COURSE_GRAY:
        return rayo_shade_course_gray(scene, ray);
    case RAYO_SHADE_COURSE_COLOR:
        return rayo_shade_course_color(scene, ray);
    case RAYO_SHADE_PHONG:
        return rayo_shade_phong(scene, ray, options->depth);
    case RAYO_SHADE_COURSE_TP1:
        return rayo_shade_course_tp1(scene, ray, options->depth,
                                     &options->tp1);
    }
    return rayo_vec3_make(rayo_scene_hit_any(scene, ray, 0.0), 0, 0);
}

static unsigned sample_count(const rayo_render_options *options)
{
    if (options->samples < 1)
        return 1;
    return options->samples > RAYO_MAX_SAMPLES ? RAYO_MAX_SAMPLES
                                               : options->samples;
}

/* The sum of the pixel's n x n samples, in a fixed order, into *sum;
 * 0 when the stop came first (one ray, with thousands of lights and deep
 * mirrors, can take milliseconds, a pixel of 256 of them a second). */
static int pixel_sum(const rayo_camera *camera, const rayo_scene *scene,
                     const rayo_render_options *options,
                     rayo_render_stop *stop, uint32_t i, uint32_t j,
                     rayo_vec3 *sum)
{
    unsigned n = sample_count(options), a, b;
    rayo_vec3 total = rayo_vec3_make(0, 0, 0);
    for (b = 0; b < n; b++) {
        double dy = (b + 0.5) / n - 0.5;
        for (a = 0; a < n; a++) {
            double dx = (a + 0.5) / n - 0.5;
            rayo_ray ray;
            if (rayo_render_stopping(stop))
                return 0;
            ray = rayo_camera_ray(camera, (double)i + dx, (double)j + dy);
            total = rayo_vec3_add(total, shade_one(scene, options, &ray));
        }
    }
    *sum = total;
    return 1;
}

/* pixel_sum for up to RAYO_SCENE_PACKET neighbouring pixels of one ray
 * each, in phong: the rays are pixel_sum's (its one sample's offset is
 * 0), shaded as a packet (rayo_shade_phong_packet gives each what
 * rayo_shade_phong gives; pixel_sum's 0 + value differs from value only
 * in turning -0 into +0, the same byte).  0 when the stop came first. */
static int phong_sums(const rayo_camera *camera, const rayo_scene *scene,
                      const rayo_render_options *options,
                      rayo_render_stop *stop, uint32_t i, uint32_t j,
                      unsigned count, rayo_vec3 *sums)
{
    rayo_ray rays[RAYO_SCENE_PACKET];
    unsigned k;
    if (rayo_render_stopping(stop))
        return 0;
    for (k = 0; k < count; k++)
        rays[k] = rayo_camera_ray(camera, (double)(i + k), (double)j);
    rayo_shade_phong_packet(scene, rays, count, options->depth, sums);
    return 1;
}

static unsigned char course_byte(double c)
{
    return (unsigned char)(255.0 * c);
}

static unsigned char phong_byte(double c)
{
    if (!(c > 0.0))
        return 0;
    if (c >= 1.0)
        return 255;
    return (unsigned char)(255.0 * c + 0.5);
}

void rayo_render_row_shaded(const rayo_camera *camera,
                            const rayo_scene *scene,
                            const rayo_render_options *options,
                            rayo_render_stop *stop, uint32_t row,
                            unsigned char *out)
{
    double rays = (double)sample_count(options) * sample_count(options);
    int packets =
        options->shade == RAYO_SHADE_PHONG && sample_count(options) == 1;
    rayo_vec3 ahead[RAYO_SCENE_PACKET];
    uint32_t i, first = 0, count = 0;
    if (options->shade == RAYO_SHADE_HIT)
        memset(out, 0, ((size_t)camera->width + 7) / 8);
    for (i = 0; i < camera->width; i++) {
        rayo_vec3 sum, c;
        unsigned char *rgb = out + 3 * (size_t)i;
        if (packets) {
            if (i >= first + count) {
                first = i;
                count = camera->width - i < RAYO_SCENE_PACKET
                            ? camera->width - i
                            : RAYO_SCENE_PACKET;
                if (!phong_sums(camera, scene, options, stop, i, row, count,
                                ahead))
                    return;
            }
            sum = ahead[i - first];
        } else if (!pixel_sum(camera, scene, options, stop, i, row, &sum)) {
            return;
        }
        c = rayo_vec3_scale(sum, 1.0 / rays);
        switch (options->shade) {
        case RAYO_SHADE_HIT:
            if (2.0 * sum.x >= rays)
                rayo_bit_set(out, i, 1);
            break;
        case RAYO_SHADE_COURSE_GRAY:
            out[i] = (unsigned char)c.x;
            break;
        case RAYO_SHADE_COURSE_COLOR:
        case RAYO_SHADE_COURSE_TP1:
            rgb[0] = course_byte(c.x);
            rgb[1] = course_byte(c.y);
            rgb[2] = course_byte(c.z);
            break;
        case RAYO_SHADE_PHONG:
            rgb[0] = phong_byte(c.x);
            rgb[1] = phong_byte(c.y);
            rgb[2] = phong_byte(c.z);
            break;
        }
    }
}
