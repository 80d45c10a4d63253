/*
 * hit_spans.h - the fast path for hit-mode rows of sphere-only scenes.
 * Private to the library (row.c calls it; tests/unit/t_hit_spans.c checks
 * it against the per-pixel loop).
 *
 * It is an optimisation, not a second renderer: whatever it returns must
 * be, bit for bit, what testing every pixel with rayo_camera_ray and
 * rayo_sphere_hit gives.  hit_spans.c explains why it is.
 */
#ifndef RAYO_HIT_SPANS_H
#define RAYO_HIT_SPANS_H

#include <stdint.h>

#include "rayo/camera.h"
#include "rayo/scene.h"

/*
 * Renders row `row` of a hit-mode frame (one ray per pixel) into out:
 * packed bits, most significant first, 1 = hit, padding bits zero.
 * Returns 1 when it did; 0, leaving out alone, when the scene holds
 * something other than spheres, too many spheres for spans to pay, or the
 * camera is outside the range the error bounds cover -- the caller then
 * tests every pixel.
 */
int rayo_hit_spans_row(const rayo_camera *camera, const rayo_scene *scene,
                       uint32_t row, unsigned char *out);

#endif
