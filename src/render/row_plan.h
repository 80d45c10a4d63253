/*
 * row_plan.h - a frame's rows, with what they share worked out once.
 *
 * render.c makes one plan a frame and renders every row through it, so
 * the choice of path (the span fast path of hit_spans.c or the per-pixel
 * loop) and the constants of the fast path are settled once, not on
 * every row.  Private to the library; the public rayo_render_row plans
 * for its one row.
 */
#ifndef RAYO_ROW_PLAN_H
#define RAYO_ROW_PLAN_H

#include <stddef.h>
#include <stdint.h>

#include "rayo/render.h"

#include "hit_spans.h"
#include "render_stop.h"

typedef struct rayo_row_plan {
    const rayo_camera *camera;
    const rayo_scene *scene;
    const rayo_render_options *options;
    int hit_only;          /* hit mode, one sample: bits, not shading */
    rayo_hit_spans *spans; /* hit_only and spans apply; or NULL */
    rayo_render_stop *stop; /* polled inside rows (render_stop.h); NULL,
                               as rayo_row_plan_init leaves it: never */
} rayo_row_plan;

/* Cannot fail: without memory for the fast path, rows take the loop.
 * A row abandoned for the stop is left incomplete: the render fails. */
void rayo_row_plan_init(rayo_row_plan *plan, const rayo_camera *camera,
                        const rayo_scene *scene,
                        const rayo_render_options *options);

/* Row `row` into out, as rayo_render_row. */
void rayo_row_plan_render(const rayo_row_plan *plan, uint32_t row,
                          unsigned char *out);

/*
 * Rows first..first+count-1 into out, stride bytes apart: a band, which
 * the fast path renders faster than row by row.  With runs not NULL
 * (count of them), rows the fast path finds as runs go there instead
 * (row_runs.h; rayo_hit_spans_render_rows says how), and every other
 * row is marked RAYO_ROW_RUNS_BITS and goes to out.
 */
void rayo_row_plan_render_rows(const rayo_row_plan *plan, uint32_t first,
                               uint32_t count, unsigned char *out,
                               size_t stride, rayo_row_runs *runs);

/* 1 when the plan's rows can come as runs (the fast path applies), so
 * that asking for them is worth its memory. */
int rayo_row_plan_has_runs(const rayo_row_plan *plan);

void rayo_row_plan_free(rayo_row_plan *plan);

#endif
