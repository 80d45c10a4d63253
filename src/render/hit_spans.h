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

#include <stddef.h>
#include <stdint.h>

#include "rayo/camera.h"
#include "rayo/scene.h"

#include "../image/row_runs.h"

typedef struct rayo_hit_spans rayo_hit_spans;

/*
 * What every row of a frame shares, worked out once: NULL when spans do
 * not apply (the scene holds something other than spheres, too many
 * spheres for spans to pay, the camera is outside the range the error
 * bounds cover) or memory ran out -- the caller then tests every pixel.
 * The plan refers to camera and scene, which must outlive it.
 */
rayo_hit_spans *rayo_hit_spans_plan(const rayo_camera *camera,
                                    const rayo_scene *scene);

/*
 * Row `row` of the plan's frame (one ray per pixel) into out: packed
 * bits, most significant first, 1 = hit, padding bits zero.
 */
void rayo_hit_spans_render(const rayo_hit_spans *plan, uint32_t row,
                           unsigned char *out);

/*
 * Rows first..first+count-1 into out, stride bytes apart, each as
 * rayo_hit_spans_render gives it; each row's spans start from those of
 * the row before, which spares most rows the roots of their quadratic.
 * With runs not NULL (count of them), row r goes to runs[r] instead, in
 * normal form, wherever its hits are found as at most RAYO_ROW_RUNS_MAX
 * runs; where they are not (pixels tested one by one, too many runs),
 * runs[r].count is RAYO_ROW_RUNS_BITS and the row is in out.  A row in
 * runs leaves its bits in out unwritten.
 */
void rayo_hit_spans_render_rows(const rayo_hit_spans *plan, uint32_t first,
                                uint32_t count, unsigned char *out,
                                size_t stride, rayo_row_runs *runs);

void rayo_hit_spans_free(rayo_hit_spans *plan);

#endif
