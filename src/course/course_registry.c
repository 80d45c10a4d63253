/*
 * course_registry.c - the registry of the course's exercises: for each
 * its name, title, the kind, size and format of the picture its program
 * writes, its scene and light model, whether the student model covers
 * it, and the course's reference file.  compare, grade, the command and
 * the page iterate it or look an exercise up by name or by kind; none
 * of them spells an exercise's name or decides "gray is EJ2" itself.
 *
 * Constant data.  The mistakes that apply and their sentences are
 * course.c's, the scenes' numbers course_scenes.c's.
 */
#include <string.h>

#include "course_impl.h"

/* Marks text for xgettext (scripts/update_pot.sh): what a picture shows
   (the compare report's note looks it up in its language) and each
   exercise's title (grade --help's list). */
#define N_(text) text

static const rayo_course_info registry[RAYO_COURSE_EXERCISES] = {
    {RAYO_COURSE_EJ1, "ej1", 1,
     N_("Ejercicio obligatorio 1: the sphere, plain PBM 640x480"),
     N_("black and white sphere"), RAYO_COURSE_BILEVEL, RAYO_COURSE_WIDTH,
     RAYO_COURSE_HEIGHT, '1', RAYO_SHADE_HIT,
     &course_scene_data[RAYO_COURSE_EJ1], 0, 1,
     "referencia-catedra-ej1.png"},
    {RAYO_COURSE_EJ2, "ej2", 2,
     N_("Ejercicio obligatorio 2: light and shadows in gray, plain PGM "
        "640x480"),
     N_("gray scene"), RAYO_COURSE_GRAY, RAYO_COURSE_WIDTH, RAYO_COURSE_HEIGHT,
     '2', RAYO_SHADE_COURSE_GRAY, &course_scene_data[RAYO_COURSE_EJ2], 1, 1,
     "referencia-catedra-ej2.png"},
    {RAYO_COURSE_EJ3, "ej3", 3,
     N_("Ejercicio obligatorio 3: colour, structs and dynamic memory, "
        "plain PPM 640x480"),
     N_("colour scene"), RAYO_COURSE_COLOUR, RAYO_COURSE_WIDTH,
     RAYO_COURSE_HEIGHT, '3', RAYO_SHADE_COURSE_COLOR,
     &course_scene_data[RAYO_COURSE_EJ3], 1, 0,
     "referencia-catedra-ej3.png"},
};

const rayo_course_info *rayo_course_info_of(rayo_course_exercise exercise)
{
    if ((unsigned)exercise >= RAYO_COURSE_EXERCISES)
        return NULL;
    return &registry[exercise];
}

rayo_course_exercise rayo_course_of_kind(rayo_course_kind kind)
{
    unsigned i;
    for (i = 0; i < RAYO_COURSE_EXERCISES; i++)
        if (registry[i].kind == kind)
            return (rayo_course_exercise)i;
    return RAYO_COURSE_EXERCISES;
}

rayo_course_exercise rayo_course_find(const char *name)
{
    unsigned i;
    if (name != NULL)
        for (i = 0; i < RAYO_COURSE_EXERCISES; i++)
            if (strcmp(registry[i].name, name) == 0)
                return (rayo_course_exercise)i;
    return RAYO_COURSE_EXERCISES;
}

const char *rayo_course_name(rayo_course_exercise exercise)
{
    if ((unsigned)exercise >= RAYO_COURSE_EXERCISES)
        return NULL;
    return registry[exercise].name;
}
