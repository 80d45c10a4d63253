/*
 * course_impl.h - what the files of src/course share: the three
 * exercises' scenes as constant data, the exact render through the
 * library's renderer, and the model of a student's program.  Private to
 * the library (tests include it to reach the model without a mistake).
 *
 * course_scenes.c holds the numbers and builds rayo scenes from them;
 * course_exact.c renders those with rayo_render_image; course_student*.c
 * are the student's program, in float, with one mistake switched on.
 */
#ifndef RAYO_COURSE_IMPL_H
#define RAYO_COURSE_IMPL_H

#include <stddef.h>
#include <stdint.h>

#include "rayo/camera.h"
#include "rayo/course.h"
#include "rayo/render.h"
#include "rayo/scene.h"

/* Every exercise's image is this size, fov 90, camera at the origin. */
#define RAYO_COURSE_WIDTH 640u
#define RAYO_COURSE_HEIGHT 480u
#define RAYO_COURSE_FOV 90.0

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

/* One exercise's scene: EJ2 gives levels (IA = ambient[0] = 5, II =
   the light's color[0] = 255), EJ3 colours in [0, 1]. */
typedef struct rayo_course_data {
    const rayo_course_ball *balls; /* in the statement's array order */
    size_t ball_count;
    const rayo_course_lamp *lamps;
    size_t lamp_count;
    double ambient[3];
    rayo_shade_mode shade; /* hit, course-gray or course-color */
} rayo_course_data;

/* The exercise's data; NULL for RAYO_COURSE_EXERCISES or beyond. */
const rayo_course_data *rayo_course_data_of(rayo_course_exercise exercise);

/* A new, prepared rayo scene of the exercise (free it with
   rayo_scene_free). */
rayo_status rayo_course_scene_build(rayo_course_exercise exercise,
                                    rayo_scene **scene, rayo_error *err);

/* RAYO_ERR_INVALID unless focal_scale is a finite number > 0. */
rayo_status rayo_course_options_check(const rayo_course_options *options,
                                      rayo_error *err);

/*
 * The renderer's image of the exercise with options' literal_rows and
 * focal_scale (its mistake is ignored): course_exact.c.
 */
rayo_status rayo_course_render_exact(rayo_course_exercise exercise,
                                     const rayo_course_options *options,
                                     rayo_image *image, rayo_error *err);

/*
 * The student model's image of EJ2 or EJ3 with options' mistake (NONE
 * too), literal_rows and focal_scale: course_student.c.  The caller has
 * checked that the mistake applies.
 */
rayo_status rayo_course_render_student(rayo_course_exercise exercise,
                                       const rayo_course_options *options,
                                       rayo_image *image, rayo_error *err);

/* The same rows first..end-1 only, for a caller that may stop early (the
   tone comparison ruling a mistake out): with first 0 the image is
   created (then freed by the caller with rayo_image_free whatever
   follows), and later calls fill the rows after. */
rayo_status rayo_course_render_student_rows(rayo_course_exercise exercise,
                                            const rayo_course_options *options,
                                            rayo_image *image, uint32_t first,
                                            uint32_t end, rayo_error *err);

/*
 * What the correct image of EJ2 or EJ3 is made of, pixel by pixel, as
 * the student model's main sees it (course_map.c): the sphere each ray
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

/* The map of EJ2 or EJ3 (RAYO_ERR_INVALID for EJ1), new into map. */
rayo_status rayo_course_map_make(rayo_course_exercise exercise,
                                 rayo_course_map *map, rayo_error *err);
void rayo_course_map_free(rayo_course_map *map);

/* Where the centre of ball appears in the image: column x and row y. */
void rayo_course_ball_pixel(const rayo_course_map *map,
                            const rayo_course_ball *ball, double *x,
                            double *y);

#endif
