/*
 * exercise.c - the exercises rayo can grade, as the course's registry
 * (rayo/course/course.h) gives them: each with its name, title, the
 * image its program must write and its reference, rayo's exact render
 * of the exercise's scene.  Nothing here names an exercise: a new one is
 * an entry in the course's registry (src/course/) and its functions'
 * cases in grade's functions criterion.
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

static rayo_grade_exercise exercises[RAYO_COURSE_EXERCISES];
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
    }
}

const rayo_grade_exercise *rayo_grade_exercises(size_t *count)
{
    pthread_once(&made, make);
    *count = RAYO_COURSE_EXERCISES;
    return exercises;
}

const rayo_grade_exercise *rayo_grade_exercise_find(const char *name)
{
    rayo_course_exercise e = rayo_course_find(name);
    pthread_once(&made, make);
    return e < RAYO_COURSE_EXERCISES ? &exercises[e] : NULL;
}
