/*
 * course.c - the students' mistakes: which each exercise can show, what
 * to tell a student about each, and rayo_course_render, which
 * sends the correct image to the renderer (course_exact.c) and a
 * mistake's to the student model (course_student.c).
 *
 * The texts are one sentence each, in the student's terms, naming the
 * formula or the statement's line: they go into JSON and one-line
 * reports as they are, so they hold no newline, quote or backslash
 * (t_course checks).
 */
#include <math.h>
#include <string.h>

#include "rayo/lang.h"

#include "course_impl.h"

/* Marks a sentence for xgettext (scripts/update_pot.sh); the lookup is
   rayo_course_mistake_text_lang's. */
#define N_(text) text

static const char *const mistake_names[RAYO_MISTAKE_COUNT] = {
    "none",
    "no-shadows",
    "self-shadow",
    "no-ambient",
    "ambient-not-absorbed",
    "light-reversed",
    "no-ln-test",
    "wrapped",
    "first-sphere",
    "far-root",
    "point-as-directional",
    "ka-kd-swapped",
    "unnormalised-normal",
    "unnormalised-light",
    "last-sphere",
    "shadow-behind",
    "no-clamp",
};

/*
 * EJ2's sentences; NULL where the mistake does not apply.  FIRST_SPHERE
 * applies but is not pictured: in scene 2 the first sphere of the array
 * a ray meets is always the nearest (the student model's image is the
 * correct one, not a pixel differs), so only the functions criterion's
 * own scenes show it.
 */
static const char *const ej2_texts[RAYO_MISTAKE_COUNT] = {
    [RAYO_MISTAKE_NONE] =
        N_("no mistake: each pixel is I = IA + II (L.N) at the nearest sphere "
        "when L.N > 0 and no other sphere lies on the ray from P towards "
        "L, else IA, and 0 where the ray meets no sphere"),
    [RAYO_MISTAKE_NO_SHADOWS] =
        N_("there are no shadows: II (L.N) counts only when no other sphere "
        "lies on the ray from P towards L, so test every other sphere with "
        "distancia_esfera from P along L and give IA when one is hit"),
    [RAYO_MISTAKE_SELF_SHADOW] =
        N_("the lit side is speckled with shadow: the shadow ray from P also "
        "tests the sphere P lies on, whose root near t = 0 counts as a hit "
        "as rounding falls; skip that sphere (no OTHER sphere on the ray "
        "from P towards L)"),
    [RAYO_MISTAKE_NO_AMBIENT] =
        N_("the ambient term is missing: I = IA + II (L.N) where lit and "
        "I = IA where not, so the unlit parts of the spheres must be IA, "
        "not black"),
    [RAYO_MISTAKE_LIGHT_REVERSED] =
        N_("the spheres are lit from the wrong side: L is the direction from "
        "P towards the light, luz as given, not its negative, both in L.N "
        "and in the shadow ray"),
    [RAYO_MISTAKE_NO_LN_TEST] =
        N_("the side facing away from the light is darker than IA: II (L.N) "
        "is added only when L.N > 0, and a negative L.N must give I = IA"),
    [RAYO_MISTAKE_WRAPPED] =
        N_("the brightest spots turn black: values of I above 255 must become "
        "255 before the conversion to an integer, not wrap around 256"),
    [RAYO_MISTAKE_FAR_ROOT] =
        N_("the spheres show their far side: t = beta - sqrt(delta) when that "
        "is positive, and beta + sqrt(delta) only when it is not"),
    [RAYO_MISTAKE_UNNORMALISED_NORMAL] =
        N_("the shading is wrong in brightness: N = (P - C) / r must be the "
        "unit normal in I = IA + II (L.N), with normal_esfera dividing by "
        "the radius"),
    [RAYO_MISTAKE_FIRST_SPHERE] =
        N_("a farther sphere covers a nearer one: the pixel shows the sphere "
        "with the smallest t that distancia_esfera returns, not the first "
        "one of the array the ray meets"),
    [RAYO_MISTAKE_LAST_SPHERE] =
        N_("a farther sphere covers a nearer one: the pixel shows the sphere "
        "with the smallest t that distancia_esfera returns, not the last "
        "one of the array the ray meets"),
    [RAYO_MISTAKE_SHADOW_BEHIND] =
        N_("spheres behind the point cast shadows: only a sphere hit at "
        "t > 0 on the ray from P towards L lies between P and the light"),
    [RAYO_MISTAKE_NO_CLAMP] =
        N_("the brightest spots go past 255: values of I above 255 must "
        "become 255"),
};

/* EJ3's sentences: every mistake applies but EJ2's own. */
static const char *const ej3_texts[RAYO_MISTAKE_COUNT] = {
    [RAYO_MISTAKE_NONE] =
        N_("no mistake: each pixel is C = Ia ka + sum delta_i Ii kd (Li.N) at "
        "the nearest sphere, then C (x) M, each channel above 1 becoming 1 "
        "and the byte the integer part of 255 c"),
    [RAYO_MISTAKE_NO_SHADOWS] =
        N_("there are no shadows: a light counts only when no other sphere "
        "lies on the ray from P towards it (delta_i in C = Ia ka + sum "
        "delta_i Ii kd (Li.N))"),
    [RAYO_MISTAKE_SELF_SHADOW] =
        N_("the lit side is speckled with shadow: the shadow ray from P also "
        "tests the sphere P lies on, whose root near t = 0 counts as a hit "
        "as rounding falls; delta_i asks whether another sphere lies on "
        "the ray from P towards light i"),
    [RAYO_MISTAKE_NO_AMBIENT] =
        N_("the ambient term is missing: C = Ia ka + sum delta_i Ii kd (Li.N) "
        "starts at Ia ka, so the unlit parts must not be black"),
    [RAYO_MISTAKE_AMBIENT_NOT_ABSORBED] =
        N_("the ambient light is not tinted by the colour of the sphere: "
        "Ia ka belongs in C before the product C (x) M, not added after it"),
    [RAYO_MISTAKE_LIGHT_REVERSED] =
        N_("the spheres are lit from the wrong side: Li points from P towards "
        "light i, normalise(posicion - P) for a point light and the given "
        "direction for a directional one, not their negatives"),
    [RAYO_MISTAKE_NO_LN_TEST] =
        N_("the sides facing away from a light are darkened: a light counts "
        "only when Li.N > 0 (delta_i = 0 otherwise), so a negative Li.N "
        "must add nothing to C"),
    [RAYO_MISTAKE_WRAPPED] =
        N_("the brightest channels wrap around to dark: a channel above 1 "
        "must become 1 (printed as 255) before the byte, the integer part "
        "of 255 c, is taken"),
    [RAYO_MISTAKE_FIRST_SPHERE] =
        N_("a farther sphere covers a nearer one: the pixel shows the sphere "
        "with the smallest t that esfera_distancia returns, not the first "
        "one of the array the ray meets"),
    [RAYO_MISTAKE_FAR_ROOT] =
        N_("the spheres show their far side: t = beta - sqrt(delta) when that "
        "is positive, and beta + sqrt(delta) only when it is not"),
    [RAYO_MISTAKE_POINT_AS_DIRECTIONAL] =
        N_("the point lights are used as directions: for a light with "
        "es_puntual, Li = normalise(posicion - P), computed at each P, not "
        "normalise(posicion)"),
    [RAYO_MISTAKE_KA_KD_SWAPPED] =
        N_("ka and kd are swapped: C = Ia ka + sum delta_i Ii kd (Li.N), ka "
        "with the ambient light and kd with each light"),
    [RAYO_MISTAKE_UNNORMALISED_NORMAL] =
        N_("the shading is wrong in brightness: N = (P - C) / r must be the "
        "unit normal in (Li.N), the one esfera_distancia returns"),
    [RAYO_MISTAKE_UNNORMALISED_LIGHT] =
        N_("the point lights are too bright: Li = normalise(posicion - P) "
        "must be a unit vector, both in (Li.N) and in the shadow ray"),
    [RAYO_MISTAKE_LAST_SPHERE] =
        N_("a farther sphere covers a nearer one: the pixel shows the sphere "
        "with the smallest t that esfera_distancia returns, not the last "
        "one of the array the ray meets"),
};

/* EJ1's only sentence: no mistake is modelled for the sphere. */
static const char *const ej1_texts[RAYO_MISTAKE_COUNT] = {
    [RAYO_MISTAKE_NONE] =
        N_("no mistake: a pixel is black exactly where its ray meets the "
        "sphere, as intersecta_esfera tests with (C.d)^2 - C.C + R^2 >= 0"),
};

/* Each exercise's sentences, NULL where a mistake does not apply. */
static const char *const *const texts[RAYO_COURSE_EXERCISES] = {
    ej1_texts, ej2_texts, ej3_texts};

void rayo_course_options_init(rayo_course_options *options)
{
    options->mistake = RAYO_MISTAKE_NONE;
    options->literal_rows = 0;
    options->focal_scale = 1.0;
}

const char *rayo_course_mistake_name(rayo_course_mistake mistake)
{
    if ((unsigned)mistake >= RAYO_MISTAKE_COUNT)
        return NULL;
    return mistake_names[mistake];
}

const char *rayo_course_mistake_text(rayo_course_exercise exercise,
                                     rayo_course_mistake mistake)
{
    if ((unsigned)exercise >= RAYO_COURSE_EXERCISES ||
        (unsigned)mistake >= RAYO_MISTAKE_COUNT)
        return NULL;
    return texts[exercise][mistake];
}

const char *rayo_course_mistake_text_lang(rayo_course_exercise exercise,
                                          rayo_course_mistake mistake,
                                          rayo_lang lang)
{
    const char *text = rayo_course_mistake_text(exercise, mistake);
    return text != NULL ? rayo_gettext(lang, text) : NULL;
}

int rayo_course_mistake_applies(rayo_course_exercise exercise,
                                rayo_course_mistake mistake)
{
    return rayo_course_mistake_text(exercise, mistake) != NULL;
}

int rayo_course_mistake_pictured(rayo_course_exercise exercise,
                                 rayo_course_mistake mistake)
{
    if (!rayo_course_mistake_applies(exercise, mistake))
        return 0;
    switch (mistake) {
    case RAYO_MISTAKE_LAST_SPHERE:
    case RAYO_MISTAKE_SHADOW_BEHIND:
    case RAYO_MISTAKE_NO_CLAMP:
        return 0;
    case RAYO_MISTAKE_FIRST_SPHERE:
        return exercise != RAYO_COURSE_EJ2;
    default:
        return 1;
    }
}

rayo_status rayo_course_options_check(const rayo_course_options *options,
                                      rayo_error *err)
{
    if (!(options->focal_scale > 0.0) || !isfinite(options->focal_scale))
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "course: focal scale %g is not a finite "
                              "number > 0",
                              options->focal_scale);
    return RAYO_OK;
}

rayo_status rayo_course_render(rayo_course_exercise exercise,
                               const rayo_course_options *options,
                               rayo_image *image, rayo_error *err)
{
    rayo_course_options defaults;
    rayo_status status;
    if (options == NULL) {
        rayo_course_options_init(&defaults);
        options = &defaults;
    }
    if ((unsigned)exercise >= RAYO_COURSE_EXERCISES)
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "course: no exercise number %d",
                              (int)exercise);
    if (!rayo_course_mistake_pictured(exercise, options->mistake)) {
        const char *name = rayo_course_mistake_name(options->mistake);
        if (name == NULL)
            return rayo_error_set(err, RAYO_ERR_INVALID,
                                  "course: no mistake number %d",
                                  (int)options->mistake);
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "course: the mistake %s does not apply to %s",
                              name, rayo_course_name(exercise));
    }
    status = rayo_course_options_check(options, err);
    if (status != RAYO_OK)
        return status;
    if (options->mistake == RAYO_MISTAKE_NONE)
        return rayo_course_render_exact(exercise, options, image, err);
    return rayo_course_render_student(exercise, options, image, err);
}
