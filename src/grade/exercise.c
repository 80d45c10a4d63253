/*
 * exercise.c - the exercises rayo can grade, as the course's registry
 * (rayo/course/course.h) gives them: each with its name, title, the
 * image its program must write and its reference, rayo's exact render
 * of the exercise's scene.  A new exercise of the course's scenes is an
 * entry in the course's registry (src/course/) and its functions' cases
 * in grade's functions criterion; a whole program with no reference
 * (TP1) is an entry of programs[] below, graded by tp1.c.
 *
 * The table is made from the registry once (pthread_once) and constant
 * after; nothing here runs a submission.
 */
#include <pthread.h>
#include <stddef.h>
#include <string.h>

#include "rayo/course/course.h"

#include "grade_impl.h"

/* The reference of exercise number n: the course's exact render.  One
   function an exercise, as rayo_grade_exercise's reference takes no
   argument. */
#define REFERENCE(n)                                                      \
    static rayo_status reference_##n(rayo_image *image, rayo_error *err)  \
    {                                                                     \
        return rayo_course_render((rayo_course_exercise)(n), NULL, image, \
                                  err);                                   \
    }
REFERENCE(0)
REFERENCE(1)
REFERENCE(2)
REFERENCE(3)
REFERENCE(4)
REFERENCE(5)
REFERENCE(6)
REFERENCE(7)

static rayo_status (*const references[])(rayo_image *, rayo_error *) = {
    reference_0, reference_1, reference_2, reference_3,
    reference_4, reference_5, reference_6, reference_7};

/* The course's registry must fit the references above. */
typedef char registry_fits[RAYO_COURSE_EXERCISES <=
                                   sizeof references / sizeof references[0]
                               ? 1
                               : -1];

/* Marks a title for xgettext; the command looks it up. */
#define N_(text) text

/* The exercises beyond the course's scenes: whole programs with no
   reference image, checked by what their statement fixes. */
static const rayo_grade_exercise programs[] = {
    {"tp1",
     N_("Trabajo práctico 1: the whole ray tracer, a folder with a "
        "Makefile"),
     161, 121, '3', RAYO_COURSE_EXERCISES, NULL, "20212_tp1"}};
#define PROGRAMS (sizeof programs / sizeof programs[0])

static rayo_grade_exercise exercises[RAYO_COURSE_EXERCISES + PROGRAMS];
static pthread_once_t made = PTHREAD_ONCE_INIT;

static void make(void)
{
    unsigned i;
    for (i = 0; i < RAYO_COURSE_EXERCISES; i++) {
        const rayo_course_info *c =
            rayo_course_info_of((rayo_course_exercise)i);
        rayo_grade_exercise *e = &exercises[i];
        e->name = c->name;
        e->title = c->title;
        e->width = c->width;
        e->height = c->height;
        e->magic = c->magic;
        e->course = c->exercise;
        e->reference = references[i];
        e->program = NULL;
    }
    for (i = 0; i < PROGRAMS; i++)
        exercises[RAYO_COURSE_EXERCISES + i] = programs[i];
}

const rayo_grade_exercise *rayo_grade_exercises(size_t *count)
{
    pthread_once(&made, make);
    *count = RAYO_COURSE_EXERCISES + PROGRAMS;
    return exercises;
}

const rayo_grade_exercise *rayo_grade_exercise_find(const char *name)
{
    rayo_course_exercise e = rayo_course_find(name);
    size_t i;
    pthread_once(&made, make);
    if (e < RAYO_COURSE_EXERCISES)
        return &exercises[e];
    for (i = 0; name != NULL && i < PROGRAMS; i++)
        if (strcmp(programs[i].name, name) == 0)
            return &exercises[RAYO_COURSE_EXERCISES + i];
    return NULL;
}
