/*
 * course/course_scene.h - the numbers of the course's scenes, as the
 * statements give them, and what the correct image of one is made of
 * pixel by pixel (its map): the one source that the exact render, the
 * student model, the tone comparison's reading of a picture, the
 * functions criterion's cases and the page all read.
 *
 * examples/ejN.scene are the same scenes written as scene files (a test
 * renders both and compares the bytes).  Not a scene of the renderer
 * (rayo/scene.h): rayo_course_scene_build makes one from these numbers.
 */
#ifndef RAYO_COURSE_COURSE_SCENE_H
#define RAYO_COURSE_COURSE_SCENE_H

#include <stddef.h>
#include <stdint.h>

#include "rayo/course/course.h"
#include "rayo/export.h"
#include "rayo/render.h"
#include "rayo/scene.h"
#include "rayo/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A sphere of the statement: centre, radius, colour M, ka, kd (EJ1 and
   EJ2 spheres are white with ka = kd = 1, which their models ignore). */
typedef struct rayo_course_ball {
    double center[3];
    double radius;
    double color[3];
    double ka, kd;
} rayo_course_ball;

/* A light: a direction towards it (point 0) or its position (point 1). */
typedef struct rayo_course_lamp {
    int point;
    double vector[3];
    double color[3];
} rayo_course_lamp;

/* One exercise's scene: a gray one gives levels (IA = ambient[0] = 5,
   II = the light's color[0] = 255), a colour one colours in [0, 1]. */
typedef struct rayo_course_data {
    const rayo_course_ball *balls; /* in the statement's array order */
    size_t ball_count;
    const rayo_course_lamp *lamps;
    size_t lamp_count;
    double ambient[3];
    rayo_shade_mode shade; /* hit, course-gray or course-color */
} rayo_course_data;

/* The exercise's scene; NULL for RAYO_COURSE_EXERCISES or beyond. */
RAYO_API const rayo_course_data *
rayo_course_data_of(rayo_course_exercise exercise);

/* A new, prepared rayo scene of the exercise (free it with
   rayo_scene_free). */
RAYO_API rayo_status rayo_course_scene_build(rayo_course_exercise exercise,
                                             rayo_scene **scene,
                                             rayo_error *err);

/* The same with the first count spheres moved: spheres holds count x
   (cx, cy, cz, r), replacing their centres and radii in order (the
   page's sliders); their materials and the lights stay the scene's. */
RAYO_API rayo_status rayo_course_scene_build_moved(
    rayo_course_exercise exercise, const double *spheres, size_t count,
    rayo_scene **scene, rayo_error *err);

/*
 * The student model's image of an exercise with a student model
 * (rayo_course_info's student_model), rows first..end-1 only, for a
 * caller that may stop early (the tone comparison ruling a mistake out):
 * with first 0 the image is created (then freed by the caller with
 * rayo_image_free whatever follows), and later calls fill the rows
 * after.  The caller has checked that options' mistake applies.
 */
RAYO_API rayo_status rayo_course_render_student_rows(
    rayo_course_exercise exercise, const rayo_course_options *options,
    rayo_image *image, uint32_t first, uint32_t end, rayo_error *err);

/*
 * What the correct image of an exercise with a student model is made
 * of, pixel by pixel, as the model's main sees it: the sphere each ray
 * shows and, for each light, whether and how much it lights the point.
 * The tone comparison reads a student's image against it to name what
 * differs from the scene (a background, a sphere added or missing, the
 * model's constants).
 */
#define RAYO_COURSE_MAP_CORE 3
typedef struct rayo_course_map {
    rayo_course_exercise exercise;
    uint32_t width, height;
    size_t lamp_count;
    double focal;        /* the formula's z: 320 */
    signed char *ball;   /* the sphere's index in the data, -1 none */
    /* 1 where every pixel within RAYO_COURSE_MAP_CORE (a square) shows
       the same sphere, or none: away from every outline */
    unsigned char *core;
    /* lamp_count a pixel: Li.N where Li.N > 0 and no sphere shadows P,
       -(Li.N) where Li.N > 0 but one does, 0 where Li.N <= 0 or no
       sphere is hit */
    float *light;
} rayo_course_map;

/* The map of an exercise with a student model (RAYO_ERR_INVALID for
   another), new into map. */
RAYO_API rayo_status rayo_course_map_make(rayo_course_exercise exercise,
                                          rayo_course_map *map,
                                          rayo_error *err);
RAYO_API void rayo_course_map_free(rayo_course_map *map);

/* Where the centre of ball appears in the image: column x and row y. */
RAYO_API void rayo_course_ball_pixel(const rayo_course_map *map,
                                     const rayo_course_ball *ball, double *x,
                                     double *y);

#ifdef __cplusplus
}
#endif

#endif
