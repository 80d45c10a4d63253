/*
 * course/course.h - the course's exercises as rayo knows them: a
 * registry (rayo_course_info) that compare, grade, the command and the
 * page ask for each exercise's name, image kind, size and format, scene
 * and light model, and the mistakes students typically make, each with
 * its one sentence; and the exercises' images rendered exactly or with
 * one of those mistakes.
 *
 * rayo_course_render with RAYO_MISTAKE_NONE gives exactly the bytes
 * `rayo render examples/ejN.scene` gives; with a mistake, what a model
 * of a student's program with that one mistake writes.  The scenes'
 * numbers are in course/course_scene.h.  Not a general renderer.
 */
#ifndef RAYO_COURSE_COURSE_H
#define RAYO_COURSE_COURSE_H

#include <stddef.h>
#include <stdint.h>

#include "rayo/export.h"
#include "rayo/image.h"
#include "rayo/lang_id.h"
#include "rayo/render.h"
#include "rayo/status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum rayo_course_exercise {
    RAYO_COURSE_EJ1, /* the sphere: plain PBM, black where a ray hits */
    RAYO_COURSE_EJ2, /* gray: ambient + diffuse, shadows, plain PGM */
    RAYO_COURSE_EJ3, /* colour: several lights, plain PPM */
    RAYO_COURSE_EXERCISES
} rayo_course_exercise;

/* The mistakes modelled, each a change to a correct program. */
typedef enum rayo_course_mistake {
    RAYO_MISTAKE_NONE,
    RAYO_MISTAKE_NO_SHADOWS,        /* delta always 1: no shadow ray */
    RAYO_MISTAKE_SELF_SHADOW,       /* the shadow ray also tests the
                                       sphere it starts on */
    RAYO_MISTAKE_NO_AMBIENT,        /* the ambient term left out */
    RAYO_MISTAKE_AMBIENT_NOT_ABSORBED, /* EJ3: Ia ka added after the
                                       product with the sphere's colour */
    RAYO_MISTAKE_LIGHT_REVERSED,    /* L negated (towards the scene) */
    RAYO_MISTAKE_NO_LN_TEST,        /* diffuse added where L.N < 0 too */
    RAYO_MISTAKE_WRAPPED,           /* values past 255 wrap around 256
                                       (unsigned char), not clamped */
    RAYO_MISTAKE_FIRST_SPHERE,      /* the first sphere of the array the
                                       ray hits, not the nearest */
    RAYO_MISTAKE_FAR_ROOT,          /* t = beta + sqrt(delta) */
    RAYO_MISTAKE_POINT_AS_DIRECTIONAL, /* EJ3: a point light's position
                                       used as a direction */
    RAYO_MISTAKE_KA_KD_SWAPPED,     /* EJ3 */
    RAYO_MISTAKE_UNNORMALISED_NORMAL, /* N = P - C, not divided by r */
    RAYO_MISTAKE_UNNORMALISED_LIGHT,  /* EJ3: position - P not
                                       normalised */
    /* Modelled by the functions criterion only (not pictured): */
    RAYO_MISTAKE_LAST_SPHERE,       /* the last sphere of the array the
                                       ray hits, not the nearest */
    RAYO_MISTAKE_SHADOW_BEHIND,     /* EJ2: a sphere behind P (t < 0 on
                                       the shadow ray) casts a shadow */
    RAYO_MISTAKE_NO_CLAMP,          /* EJ2: I above 255 returned as is */
    RAYO_MISTAKE_COUNT
} rayo_course_mistake;

/* The kind of picture an exercise's program writes. */
typedef enum rayo_course_kind {
    RAYO_COURSE_BILEVEL, /* black and white: plain PBM */
    RAYO_COURSE_GRAY,    /* levels 0 to 255: plain PGM */
    RAYO_COURSE_COLOUR   /* RGB, 0 to 255 a channel: plain PPM */
} rayo_course_kind;

struct rayo_course_data; /* an exercise's scene: course/course_scene.h */

/* One exercise of the registry; constant data. */
typedef struct rayo_course_info {
    rayo_course_exercise exercise;
    const char *name;    /* "ej1": course:ej1, --exercise ej1 */
    int number;          /* 1: "exercise 1" in a report */
    const char *title;   /* "Ejercicio obligatorio 1: the sphere, ..." */
    const char *picture; /* what its image shows: "black and white sphere" */
    rayo_course_kind kind;
    uint32_t width, height;
    char magic;          /* its plain Netpbm format: '1', '2' or '3' */
    rayo_shade_mode shade; /* its light model */
    const struct rayo_course_data *scene; /* one source: course_scenes.c */
    /* 1 when the student model (its mistakes) and the scene's map exist:
       the tone comparison then tries the mistakes and reads the scene */
    int student_model;
    /* 1 when the course also accepts the rows of the statement's
       y in [-alto/2, alto/2) read literally (the picture a row higher) */
    int literal_rows;
    const char *reference; /* its file: "referencia-catedra-ej1.png" */
} rayo_course_info;

/* The registry's entry of exercise; NULL for RAYO_COURSE_EXERCISES or
   beyond.  Iterate with e from 0 to RAYO_COURSE_EXERCISES - 1. */
RAYO_API const rayo_course_info *
rayo_course_info_of(rayo_course_exercise exercise);

/* The first exercise whose program writes a picture of kind;
   RAYO_COURSE_EXERCISES when none does. */
RAYO_API rayo_course_exercise rayo_course_of_kind(rayo_course_kind kind);

/* Variations that are not mistakes of shading. */
typedef struct rayo_course_options {
    rayo_course_mistake mistake;
    /* Rows run from y = h/2 - 1 down to -h/2 (the statement's
       y in [-alto/2, alto/2) read literally) instead of from h/2 down
       to -h/2 + 1: the picture one row higher. */
    int literal_rows;
    /* The focal distance times this (1: the formula's; the course's own
       references for EJ1 and EJ2 were made with about 1.0047). */
    double focal_scale;
} rayo_course_options;

/* No mistake, the convention's rows, focal_scale 1. */
RAYO_API void rayo_course_options_init(rayo_course_options *options);

/* "ej1", "ej2", "ej3"; RAYO_COURSE_EXERCISES when name is none. */
RAYO_API rayo_course_exercise rayo_course_find(const char *name);
RAYO_API const char *rayo_course_name(rayo_course_exercise exercise);

/* 1 when the mistake can happen in exercise (and has its sentence):
   the functions criterion models every one of them. */
RAYO_API int rayo_course_mistake_applies(rayo_course_exercise exercise,
                                         rayo_course_mistake mistake);

/* 1 when the mistake applies and the image model renders it (a picture
   can show it): the ones rayo_course_render and compare try. */
RAYO_API int rayo_course_mistake_pictured(rayo_course_exercise exercise,
                                          rayo_course_mistake mistake);

/* A short machine name: "no-shadows", "self-shadow", ... */
RAYO_API const char *rayo_course_mistake_name(rayo_course_mistake mistake);

/*
 * One sentence for a student (English, no newline, no quotes): what the
 * image shows and what to look at in the code, naming the formula or
 * the line of the statement, e.g. "there are no shadows: a light counts
 * only when no other sphere lies on the ray from P towards it (delta_i
 * in C = Ia ka + sum delta_i Ii kd (Li.N))".
 */
RAYO_API const char *rayo_course_mistake_text(rayo_course_exercise exercise,
                                              rayo_course_mistake mistake);

/* The same sentence in lang (po/; English where it has no translation). */
RAYO_API const char *rayo_course_mistake_text_lang(
    rayo_course_exercise exercise, rayo_course_mistake mistake,
    rayo_lang lang);

/*
 * Renders the exercise's image into a new image of its size and kind:
 * RAYO_SAMPLE_BIT, gray U8 or RGB U8 (maxval 255).  options may be
 * NULL (rayo_course_options_init's).  RAYO_ERR_INVALID for a mistake
 * that does not apply to the exercise.
 */
RAYO_API rayo_status rayo_course_render(rayo_course_exercise exercise,
                                        const rayo_course_options *options,
                                        rayo_image *image, rayo_error *err);

/*
 * The course's own reference image for exercise, built into the library:
 * the bytes of the PNG file the course published
 * (referencia-catedra-ejN.png), for rayo_image_read_memory.  *size (when
 * size is not NULL) receives their number.  NULL and 0 for an exercise
 * out of range.  The bytes are static: never freed, never changed.
 */
RAYO_API const unsigned char *
rayo_course_reference_png(rayo_course_exercise exercise, size_t *size);

#ifdef __cplusplus
}
#endif

#endif
