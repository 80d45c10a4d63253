/*
 * shade.h - the shading models behind rayo_shade_mode, as functions from
 * a ray to the light it brings back, and the sampled row loop that uses
 * them.  Private to the library.
 *
 * Each model lives in a file of its own (shade_course_gray.c,
 * shade_course_color.c, shade_phong.c) and knows nothing of pixels or
 * bytes; row_shaded.c turns their values into samples of a row.
 * docs/shading.md gives the formulas.
 */
#ifndef RAYO_SHADE_H
#define RAYO_SHADE_H

#include <stdint.h>

#include "rayo/render.h"

#include "render_stop.h"

/*
 * The course's scene 2 model: a gray level in 0..255 (already clamped
 * to 255, not yet truncated), the same in all three components.
 */
rayo_vec3 rayo_shade_course_gray(const rayo_scene *scene,
                                 const rayo_ray *ray);

/*
 * delta_i * (Li.N) of the course's models: the cosine between the hit's
 * normal and the direction towards light, or 0 when the light faces away
 * or another object lies on the whole half-line towards it
 * (shade_course_light.c).
 */
double rayo_shade_course_light(const rayo_scene *scene, const rayo_hit *hit,
                               const rayo_light *light);

/* The course's scene 3 model: RGB, each channel clamped to 1. */
rayo_vec3 rayo_shade_course_color(const rayo_scene *scene,
                                  const rayo_ray *ray);

/*
 * The course's TP1 model (shade_course_tp1.c): RGB, each channel clamped
 * to 1, reflections followed for depth bounces, read as reading says.
 */
rayo_vec3 rayo_shade_course_tp1(const rayo_scene *scene, const rayo_ray *ray,
                                unsigned depth,
                                const rayo_tp1_reading *reading);

/*
 * The general model: RGB, not clamped, following mirror reflections for
 * at most depth bounces.
 */
rayo_vec3 rayo_shade_phong(const rayo_scene *scene, const rayo_ray *ray,
                           unsigned depth);

/*
 * rayo_shade_phong(scene, &rays[k], depth) into out[k] for each k < count
 * (count <= 4), bit for bit, the rays' walks shared (shade_phong.c).
 */
void rayo_shade_phong_packet(const rayo_scene *scene, const rayo_ray *rays,
                             unsigned count, unsigned depth, rayo_vec3 *out);

/*
 * One row of any mode with options->samples x options->samples rays per
 * pixel (hit mode: black where at least half of them hit).  Polls stop
 * (may be NULL) before each ray, and abandons the row, incomplete, when
 * it says to stop.
 */
void rayo_render_row_shaded(const rayo_camera *camera,
                            const rayo_scene *scene,
                            const rayo_render_options *options,
                            rayo_render_stop *stop, uint32_t row,
                            unsigned char *out);

#endif
