/*
 * exercise.c - the registry of the course's exercises that rayo can
 * grade: each with its name, the image its program must write and how
 * to make the reference that image is compared with.
 *
 * Adding an exercise is adding an entry here, its scene in src/course
 * and its functions' cases in a functions_ejN.c.  The registry is
 * constant data; nothing here runs a submission.
 */
#include <stddef.h>
#include <string.h>

#include "rayo/seed.h"

#include "grade_impl.h"

/* The exercises' references: rayo's exact render of each course scene
   (course.h): EJ1 the seed sphere, black where a ray hits; EJ2 and EJ3
   their lit scenes. */
static rayo_status reference_ej1(rayo_image *image, rayo_error *err)
{
    return rayo_course_render(RAYO_COURSE_EJ1, NULL, image, err);
}

static rayo_status reference_ej2(rayo_image *image, rayo_error *err)
{
    return rayo_course_render(RAYO_COURSE_EJ2, NULL, image, err);
}

static rayo_status reference_ej3(rayo_image *image, rayo_error *err)
{
    return rayo_course_render(RAYO_COURSE_EJ3, NULL, image, err);
}

static const rayo_grade_exercise exercises[] = {
    {"ej1", "Ejercicio obligatorio 1: the sphere, plain PBM 640x480",
     RAYO_SEED_WIDTH, RAYO_SEED_HEIGHT, '1', RAYO_COURSE_EJ1, reference_ej1},
    {"ej2", "Ejercicio obligatorio 2: light and shadows in gray, plain PGM "
            "640x480",
     640, 480, '2', RAYO_COURSE_EJ2, reference_ej2},
    {"ej3", "Ejercicio obligatorio 3: colour, structs and dynamic memory, "
            "plain PPM 640x480",
     640, 480, '3', RAYO_COURSE_EJ3, reference_ej3},
};

const rayo_grade_exercise *rayo_grade_exercises(size_t *count)
{
    *count = sizeof exercises / sizeof exercises[0];
    return exercises;
}

const rayo_grade_exercise *rayo_grade_exercise_find(const char *name)
{
    size_t i;
    for (i = 0; i < sizeof exercises / sizeof exercises[0]; i++)
        if (strcmp(exercises[i].name, name) == 0)
            return &exercises[i];
    return NULL;
}
