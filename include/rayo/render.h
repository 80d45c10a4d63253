/*
 * render.h - turning a camera and a scene into rows of pixels.
 *
 * The renderer asks the camera for each pixel's ray, the scene what the
 * ray hits, and the shading mode what colour that makes; it hands finished
 * rows, in order from the top, to a sink (usually a rayo_writer).  Bands
 * of rows are rendered by several threads at once and delivered in order,
 * so the output is the same bytes whatever the thread count, and memory
 * holds a few bands, never the whole frame.
 */
#ifndef RAYO_RENDER_H
#define RAYO_RENDER_H

#include <stddef.h>
#include <stdint.h>

#include "rayo/camera.h"
#include "rayo/cpu.h"
#include "rayo/export.h"
#include "rayo/image.h"
#include "rayo/row_sink.h"
#include "rayo/scene.h"
#include "rayo/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The shading models; docs/shading.md gives each formula. */
typedef enum rayo_shade_mode {
    RAYO_SHADE_HIT,          /* bilevel: black (1) where the ray hits */
    RAYO_SHADE_COURSE_GRAY,  /* gray: the course's scene 2 model, exactly */
    RAYO_SHADE_COURSE_COLOR, /* RGB: the course's scene 3 model, exactly */
    RAYO_SHADE_PHONG,        /* RGB: ambient, diffuse, specular, shadows,
                                mirror reflections */
    RAYO_SHADE_COURSE_TP1    /* RGB: the course's TP1 statement's Phong
                                with reflections, exactly */
} rayo_shade_mode;

/*
 * How course-tp1 reads what the TP1 statement leaves open
 * (docs/shading.md); the defaults are what most submissions do.
 */
typedef struct rayo_tp1_reading {
    int tinted_reflection; /* 1: C' = (C + kr I) (x) M; 0: C (x) M + kr I */
    int shadows_to_light;  /* 1: only what lies between P and a point
                              light shadows it; 0: anything in the
                              light's direction, as the statement words */
    double epsilon;        /* how far past P reflected and shadow rays
                              start; 1e-6, the statement's example */
} rayo_tp1_reading;

/*
 * "hit", "course-gray", "course-color", "phong" or "course-tp1" into *mode;
 * RAYO_ERR_INVALID (naming the accepted names) for anything else.
 */
RAYO_API rayo_status rayo_shade_mode_parse(const char *name,
                                           rayo_shade_mode *mode,
                                           rayo_error *err);

/* The name rayo_shade_mode_parse accepts for mode. */
RAYO_API const char *rayo_shade_mode_name(rayo_shade_mode mode);

/* The TP1 readings' defaults: untinted reflections, shadows from
 * anything in the light's direction, epsilon 1e-6. */
RAYO_API void rayo_tp1_reading_init(rayo_tp1_reading *reading);

/* Largest --samples N (N x N rays per pixel) and reflection depth. */
#define RAYO_MAX_SAMPLES 16u
#define RAYO_MAX_DEPTH 64u

/*
 * Called on the rendering thread after each delivered band; return
 * nonzero to stop the render (rayo_render then fails with
 * RAYO_ERR_CANCELLED).
 */
typedef int (*rayo_progress_fn)(void *context, uint32_t rows_done,
                                uint32_t rows_total);

/*
 * Polled by every rendering thread inside its band, before each ray of a
 * sampled or shaded render and every few pixels of a one-ray hit render
 * (each band on its fast path, whose rows take microseconds): return
 * nonzero to stop the render within about one ray's time (rayo_render
 * then fails with RAYO_ERR_CANCELLED, and no row after the last
 * delivered one reaches the sink).  Called from several threads at once,
 * very often: it must be cheap and thread-safe, such as a relaxed atomic
 * load of a flag a signal handler sets.  rayo_render_row does not poll.
 */
typedef int (*rayo_cancel_fn)(void *context);

typedef struct rayo_render_options {
    rayo_shade_mode shade;
    unsigned samples; /* N: N x N stratified rays per pixel; default 1 */
    unsigned depth;   /* phong: mirror bounces followed; default 5 */
    unsigned threads; /* 0: one per CPU (rayo_cpu_count) */
    rayo_progress_fn progress; /* may be NULL */
    void *progress_context;
    rayo_cancel_fn cancel; /* may be NULL */
    void *cancel_context;
    rayo_tp1_reading tp1; /* course-tp1 only */
} rayo_render_options;

/* Hit shading, 1 sample, depth 5, one thread per CPU, no progress or
 * cancel callback, the TP1 readings' defaults. */
RAYO_API void rayo_render_options_init(rayo_render_options *options);

/* The layout of the rows this camera and shading mode produce. */
RAYO_API rayo_image_info rayo_render_image_info(
    const rayo_camera *camera, const rayo_render_options *options);

/* Rows go to a rayo_row_sink (row_sink.h); a status other than RAYO_OK
 * from it stops the render and is returned by it. */
RAYO_API rayo_status rayo_render(const rayo_camera *camera,
                                 const rayo_scene *scene,
                                 const rayo_render_options *options,
                                 rayo_row_sink sink, void *sink_context,
                                 rayo_error *err);

/*
 * Renders one row into out (rayo_image_info_row_bytes() bytes), on the
 * calling thread.  Each call works out afresh what a frame's rows share;
 * rayo_render, which does that once, is the faster way to many rows.
 */
RAYO_API void rayo_render_row(const rayo_camera *camera,
                              const rayo_scene *scene,
                              const rayo_render_options *options, uint32_t row,
                              unsigned char *out);

/* Renders a whole frame into a new image (free it with rayo_image_free). */
RAYO_API rayo_status rayo_render_image(const rayo_camera *camera,
                                       const rayo_scene *scene,
                                       const rayo_render_options *options,
                                       rayo_image *image, rayo_error *err);

#ifdef __cplusplus
}
#endif

#endif
