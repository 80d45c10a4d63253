/*
 * course_student_color.c - exercise 3's computar_intensidad and
 * color_imprimir as a student writes them from the statement
 * (C = Ia ka + sum delta_i Ii kd (Li.N), then C (x) M; a channel above 1
 * prints as 255, else the integer part of 255 c), in float, with one
 * mistake switched on.  esfera_distancia's normal is
 * vector_normalizar(P - C), the function the student has at hand.
 *
 * Not where the correct image comes from: rayo_course_render draws that
 * with rayo's renderer (course_exact.c).  The mistakes as modelled, and
 * the point light's shadow ray, are said after the include.
 */
#include "course_student.h"

/*
 * The mistakes as modelled here:
 *   NO_SHADOWS           the loop over the other spheres left out;
 *   SELF_SHADOW          it does not skip the sphere P lies on;
 *   NO_AMBIENT           C starts at 0 instead of Ia ka;
 *   AMBIENT_NOT_ABSORBED C starts at 0 and Ia ka is added after C (x) M;
 *   LIGHT_REVERSED       Li negated: -direction, normalise(P - position);
 *   NO_LN_TEST           the `Li.N > 0` test left out (shadows kept), so
 *                        negative terms are added; a channel below 0 is
 *                        printed as 0 (a negative number is no PPM
 *                        sample);
 *   WRAPPED              no clamp at 1: the byte is (unsigned char) of
 *                        the int 255 c, past 255 wrapping around 256;
 *   FIRST_SPHERE, FAR_ROOT   in the sphere loop (course_student.c);
 *   POINT_AS_DIRECTIONAL a point light's posicion taken as a direction:
 *                        Li = normalise(posicion), the same at every P
 *                        (not posicion itself, which would add a second
 *                        mistake, an Li of length 10), shadow ray
 *                        unbounded as for a directional light;
 *   KA_KD_SWAPPED        Ia kd + sum delta_i Ii ka (Li.N);
 *   UNNORMALISED_NORMAL  N = P - C, not normalised;
 *   UNNORMALISED_LIGHT   Li = posicion - P, not normalised (also for
 *                        the shadow ray).
 * A point light's shadow ray counts a sphere only before the light
 * (t < |posicion - P|); no sphere of scene 3 lies beyond a light, so the
 * image is the one the course's whole-half-line model gives.
 */

/* Li for lamp at P, and how far along it a sphere shadows P. */
static course_fvec light_direction(const course_student *s,
                                   const course_flamp *lamp, course_fvec p,
                                   float *limit)
{
    rayo_course_mistake m = s->mistake;
    course_fvec v;
    if (lamp->point && m == RAYO_MISTAKE_POINT_AS_DIRECTIONAL) {
        *limit = RAYO_COURSE_INFINITO;
        return course_fnormalize(lamp->vector);
    }
    if (!lamp->point) {
        *limit = RAYO_COURSE_INFINITO;
        v = lamp->vector;
        if (m == RAYO_MISTAKE_LIGHT_REVERSED)
            v = course_fvec_make(-v.x, -v.y, -v.z);
        return v;
    }
    v = m == RAYO_MISTAKE_LIGHT_REVERSED ? course_fsub(p, lamp->vector)
                                         : course_fsub(lamp->vector, p);
    *limit = course_fnorm(v);
    if (m == RAYO_MISTAKE_UNNORMALISED_LIGHT)
        return v;
    return course_fnormalize(v);
}

/* color_sumar: c + p m, component by component. */
static course_fvec color_add(course_fvec c, course_fvec m, float p)
{
    float r = p * m.x;
    float g = p * m.y;
    float b = p * m.z;
    return course_fvec_make(c.x + r, c.y + g, c.z + b);
}

/* color_imprimir's number for one channel. */
static unsigned char channel_byte(float c, rayo_course_mistake m)
{
    float scaled;
    int value;
    if (c > 1 && m != RAYO_MISTAKE_WRAPPED)
        return 255;
    scaled = 255 * c;
    /* Only WRAPPED gets here with c > 1, and its C is at most about
       1.2 in scene 3: the conversion to int is in range. */
    value = (int)scaled;
    if (value < 0)
        value = 0;
    return (unsigned char)value;
}

void rayo_course_student_color(const course_student *s, course_fvec d,
                               unsigned char rgb[3])
{
    rayo_course_mistake m = s->mistake;
    course_fvec o = course_fvec_make(0, 0, 0);
    course_fvec zero = course_fvec_make(0, 0, 0);
    const course_fball *ball;
    course_fvec p, n, c;
    float t, ka, kd;
    size_t i, hit = rayo_course_student_nearest(s, o, d, &t);
    if (hit == s->ball_count) {
        rgb[0] = rgb[1] = rgb[2] = 0;
        return;
    }
    ball = &s->balls[hit];
    p = course_fpoint(o, d, t);
    n = course_fsub(p, ball->center);
    if (m != RAYO_MISTAKE_UNNORMALISED_NORMAL)
        n = course_fnormalize(n);
    ka = m == RAYO_MISTAKE_KA_KD_SWAPPED ? ball->kd : ball->ka;
    kd = m == RAYO_MISTAKE_KA_KD_SWAPPED ? ball->ka : ball->kd;
    c = zero;
    if (m != RAYO_MISTAKE_NO_AMBIENT && m != RAYO_MISTAKE_AMBIENT_NOT_ABSORBED)
        c = color_add(zero, s->ambient, ka);
    for (i = 0; i < s->lamp_count; i++) {
        const course_flamp *lamp = &s->lamps[i];
        float limit, ln;
        course_fvec l = light_direction(s, lamp, p, &limit);
        ln = course_fdot(l, n);
        if (!(ln > 0) && m != RAYO_MISTAKE_NO_LN_TEST)
            continue;
        if (rayo_course_student_shadowed(s, p, l, limit, hit))
            continue;
        c = color_add(c, lamp->color, kd * ln);
    }
    c = course_fvec_make(c.x * ball->color.x, c.y * ball->color.y,
                         c.z * ball->color.z);
    if (m == RAYO_MISTAKE_AMBIENT_NOT_ABSORBED)
        c = color_add(c, s->ambient, ka);
    rgb[0] = channel_byte(c.x, m);
    rgb[1] = channel_byte(c.y, m);
    rgb[2] = channel_byte(c.z, m);
}
