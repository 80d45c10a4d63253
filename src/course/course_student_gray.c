/*
 * course_student_gray.c - exercise 2's computar_intensidad as a student
 * writes it from the statement (I = IA + II (L.N) when L.N > 0 and no
 * other sphere lies on the ray from P towards L, else IA; values above
 * 255 return 255), in float, with one mistake switched on, and the int
 * that main then prints.
 *
 * Not where the correct image comes from: rayo_course_render draws that
 * with rayo's renderer (course_exact.c).  The mistakes as modelled are
 * said after the include.
 */
#include "course_student.h"

/*
 * The mistakes as modelled here:
 *   NO_SHADOWS           the loop over the other spheres left out;
 *   SELF_SHADOW          it does not skip the sphere P lies on;
 *   NO_AMBIENT           I starts at 0 instead of IA (unlit parts 0);
 *   LIGHT_REVERSED       L = -luz, in L.N and in the shadow ray;
 *   NO_LN_TEST           the `L.N > 0` test left out (shadows kept):
 *                        I = IA + II (L.N) also where L.N < 0, which can
 *                        go below 0; printed as 0, since a negative
 *                        value is no PGM sample at all;
 *   WRAPPED              no clamp at 255, the int stored as unsigned
 *                        char (256..260 become 0..4);
 *   FIRST_SPHERE, FAR_ROOT   in the sphere loop (course_student.c);
 *   UNNORMALISED_NORMAL  N = P - C, not divided by r.
 */

unsigned char rayo_course_student_gray(const course_student *s,
                                       course_fvec d)
{
    rayo_course_mistake m = s->mistake;
    course_fvec o = course_fvec_make(0, 0, 0);
    const course_fball *ball;
    course_fvec p, n, l;
    float t, ln, level, ia, ii;
    int value;
    size_t hit = rayo_course_student_nearest(s, o, d, &t);
    if (hit == s->ball_count || s->lamp_count == 0)
        return 0;
    ball = &s->balls[hit];
    p = course_fpoint(o, d, t);
    n = course_fsub(p, ball->center);
    if (m != RAYO_MISTAKE_UNNORMALISED_NORMAL)
        n = course_fvec_make(n.x / ball->radius, n.y / ball->radius,
                             n.z / ball->radius);
    l = s->lamps[0].vector;
    if (m == RAYO_MISTAKE_LIGHT_REVERSED)
        l = course_fvec_make(-l.x, -l.y, -l.z);
    ia = m == RAYO_MISTAKE_NO_AMBIENT ? 0.0f : s->ambient.x;
    ii = s->lamps[0].color.x;
    ln = course_fdot(l, n);
    level = ia;
    if ((ln > 0 || m == RAYO_MISTAKE_NO_LN_TEST) &&
        !rayo_course_student_shadowed(s, p, l, RAYO_COURSE_INFINITO, hit)) {
        float diffuse = ii * ln;
        level = ia + diffuse;
    }
    if (level > 255 && m != RAYO_MISTAKE_WRAPPED)
        level = 255;
    value = (int)level;
    if (value < 0)
        value = 0;
    return (unsigned char)value;
}
