/*
 * course_impl.h - what the files of src/course share beyond the public
 * headers (rayo/course/course.h, rayo/course/course_scene.h): the size
 * of the course's images, the exact render through the library's
 * renderer and the student model's whole image.  Private to src/course
 * (tests include it to reach the model without a mistake); other
 * folders ask the public registry.
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
#include "rayo/course/course.h"
#include "rayo/course/course_scene.h"
#include "rayo/render.h"
#include "rayo/scene.h"

/* Every exercise's image is this size, fov 90, camera at the origin. */
#define RAYO_COURSE_WIDTH 640u
#define RAYO_COURSE_HEIGHT 480u
#define RAYO_COURSE_FOV 90.0

/* The scenes' numbers, by exercise (course_scenes.c): the registry
   points at them, rayo_course_data_of hands them out. */
extern const rayo_course_data course_scene_data[RAYO_COURSE_EXERCISES];

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

#endif
