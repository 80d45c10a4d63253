/*
 * ej2_judge.c - judging Ejercicio obligatorio 2's functions from the
 * harness's log: each vector case against its expected value, and each
 * computar_intensidad against the statement's formula (IA + II L.N,
 * shadows, the nearest sphere) and against what every modelled mistake
 * gives, so that the mistake that agrees is named with the course's
 * sentence (rayo_course_mistake_text_lang).  In double precision on the
 * float-rounded arguments (ej2.c).
 */
#define _POSIX_C_SOURCE 200809L

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rayo/course/course.h"
#include "ej2.h"
#include "harness_math.h"

/* The course's mistakes of computar_intensidad that ej2_shade models,
   in the order that breaks a tie between two that agree as well. */
static const rayo_course_mistake modelled[] = {
    RAYO_MISTAKE_FIRST_SPHERE,      RAYO_MISTAKE_LAST_SPHERE,
    RAYO_MISTAKE_FAR_ROOT,          RAYO_MISTAKE_NO_SHADOWS,
    RAYO_MISTAKE_SHADOW_BEHIND,     RAYO_MISTAKE_NO_LN_TEST,
    RAYO_MISTAKE_LIGHT_REVERSED,    RAYO_MISTAKE_NO_AMBIENT,
    RAYO_MISTAKE_NO_CLAMP,          RAYO_MISTAKE_WRAPPED,
    RAYO_MISTAKE_UNNORMALISED_NORMAL, RAYO_MISTAKE_SELF_SHADOW};
#define MODELLED (sizeof modelled / sizeof modelled[0])
#define NO_MODEL RAYO_MISTAKE_COUNT /* no modelled mistake agrees */
#define NAN_INT (RAYO_MISTAKE_COUNT + 1) /* (int) of a NaN */

/* What the model found, for the messages. */
typedef struct shading {
    double value;
    size_t sphere;   /* the sphere shaded, or (size_t)-1 */
    size_t occluder; /* the sphere that cast the shadow, or (size_t)-1 */
    double ln;
} shading;

static int occludes(const double *c, double r, const double *p,
                    const double *l, int behind_too)
{
    double oc[3], beta, delta;
    oc[0] = c[0] - p[0];
    oc[1] = c[1] - p[1];
    oc[2] = c[2] - p[2];
    beta = dot(oc, l);
    delta = beta * beta - dot(oc, oc) + r * r;
    if (delta < 0)
        return 0;
    return behind_too || beta + sqrt(delta) > 0;
}

static shading ej2_shade(const ray_case *rc, int m)
{
    scene whole;
    const scene *s = ej2_scene_of(rc->scene, &whole);
    double d[3], light[3], c[MAX_SPHERES][3], r[MAX_SPHERES];
    double o[3] = {0, 0, 0}, best = INFINITY, p[3], n[3], amb, value;
    shading out = {0, (size_t)-1, (size_t)-1, 0};
    size_t i;
    ej2_ray_args(rc, d, light, c, r);
    for (i = 0; i < s->n; i++) {
        double t = sphere_t(c[i], r[i], o, d, m == RAYO_MISTAKE_FAR_ROOT);
        if (t == INFINITY)
            continue;
        if (m == RAYO_MISTAKE_FIRST_SPHERE ? out.sphere == (size_t)-1
                                : m == RAYO_MISTAKE_LAST_SPHERE || t < best) {
            best = t;
            out.sphere = i;
        }
    }
    if (out.sphere == (size_t)-1)
        return out;
    i = out.sphere;
    p[0] = best * d[0];
    p[1] = best * d[1];
    p[2] = best * d[2];
    n[0] = (p[0] - c[i][0]) / (m == RAYO_MISTAKE_UNNORMALISED_NORMAL ? 1 : r[i]);
    n[1] = (p[1] - c[i][1]) / (m == RAYO_MISTAKE_UNNORMALISED_NORMAL ? 1 : r[i]);
    n[2] = (p[2] - c[i][2]) / (m == RAYO_MISTAKE_UNNORMALISED_NORMAL ? 1 : r[i]);
    if (m == RAYO_MISTAKE_LIGHT_REVERSED) {
        light[0] = -light[0];
        light[1] = -light[1];
        light[2] = -light[2];
    }
    out.ln = dot(light, n);
    amb = m == RAYO_MISTAKE_NO_AMBIENT ? 0 : IA;
    out.value = amb;
    if (out.ln <= 0 && m != RAYO_MISTAKE_NO_LN_TEST)
        return out;
    if (m == RAYO_MISTAKE_SELF_SHADOW)
        return out;
    for (i = 0; i < s->n && m != RAYO_MISTAKE_NO_SHADOWS; i++)
        if (i != out.sphere &&
            occludes(c[i], r[i], p, light, m == RAYO_MISTAKE_SHADOW_BEHIND)) {
            out.occluder = i;
            return out;
        }
    value = trunc(amb + II * out.ln);
    if (m == RAYO_MISTAKE_WRAPPED)
        value = fmod(value, 256);
    else if (m != RAYO_MISTAKE_NO_CLAMP && value > 255)
        value = 255;
    out.value = value;
    return out;
}
/* The expected value (scalar functions) or vector, and the answer of
   two mistakes to recognise: *alt a vector, *alt_value a number. */
static void expect_vector_case(const vector_case *v, double *want,
                               double *want_v)
{
    double a[3], b[3], c[3], s, n;
    size_t i;
    ej2_case_args(v, a, b, c, &s);
    *want = 0;
    want_v[0] = want_v[1] = want_v[2] = 0;
    switch (v->function) {
    case F_PRODUCTO:
        *want = dot(a, b);
        break;
    case F_NORMA:
        *want = sqrt(dot(a, a));
        break;
    case F_NORMALIZAR:
        unit(a, want_v);
        break;
    case F_RESTA:
        for (i = 0; i < 3; i++)
            want_v[i] = a[i] - b[i];
        break;
    case F_INTERPOLAR:
        for (i = 0; i < 3; i++)
            want_v[i] = a[i] + s * b[i];
        break;
    case F_DISTANCIA:
        *want = sphere_t(a, s, b, c, 0);
        break;
    default:
        n = s;
        for (i = 0; i < 3; i++)
            want_v[i] = (b[i] - a[i]) / n;
        break;
    }
}

/* One wrong vector case: the reason line. */
static rayo_status say_vector(rayo_grade_item *item, const vector_case *v,
                              const char *call, double got,
                              const double *got_v, rayo_error *err)
{
    double a[3], b[3], c[3], s, want, want_v[3], alt[3], far;
    char g[64], w[64];
    size_t i;
    ej2_case_args(v, a, b, c, &s);
    expect_vector_case(v, &want, want_v);
    switch (v->function) {
    case F_PRODUCTO:
    case F_NORMA:
        if (got == floor(want) && want != floor(want))
            return grade_fail(item, err, "%s returned %g; expected %.7g: "
                                         "the decimals are lost, is an int "
                                         "used inside the function?",
                              call, got, want);
        if (v->function == F_NORMA && near_value(got, want * want))
            return grade_fail(item, err, "%s returned %.7g, the square of "
                                         "the norm; expected %.7g: is the "
                                         "square root missing?",
                              call, got, want);
        return grade_fail(item, err, "%s returned %.7g; expected %.7g", call,
                          got, want);
    case F_DISTANCIA:
        far = sphere_t(a, s, b, c, 1);
        if (want == INFINITY && is_infinito(got))
            return RAYO_OK;
        if (want == INFINITY && v->a[2] < 0)
            return grade_fail(item, err, "%s returned %.7g for a ray that "
                                         "meets the sphere only behind its "
                                         "origin (t < 0); expected INFINITO "
                                         "(FLT_MAX)",
                              call, got);
        if (want == INFINITY)
            return grade_fail(item, err, "%s returned %.7g for a ray that "
                                         "misses the sphere; expected "
                                         "INFINITO (FLT_MAX)",
                              call, got);
        if (is_infinito(got))
            return grade_fail(item, err, "%s returned INFINITO for a ray "
                                         "that meets the sphere at t = %.7g",
                              call, want);
        if (far != want && near_value(got, far))
            return grade_fail(item, err, "%s returned the far root %.7g "
                                         "for a ray that meets the sphere at "
                                         "t = %.7g first: beta - sqrt(delta) "
                                         "when it is > 0",
                              call, got, want);
        if (got < 0)
            return grade_fail(item, err, "%s returned %.7g, a root behind "
                                         "the origin (t < 0), for a ray that "
                                         "starts inside the sphere; expected "
                                         "%.7g: when beta - sqrt(delta) <= 0 "
                                         "the answer is beta + sqrt(delta)",
                              call, got, want);
        if (dot(b, b) > 0)
            return grade_fail(item, err, "%s returned %.7g; expected %.7g "
                                         "(the ray starts at o, not at the "
                                         "origin of coordinates)",
                              call, got, want);
        return grade_fail(item, err, "%s returned %.7g; expected %.7g", call,
                          got, want);
    default:
        break;
    }
    vec_text(got_v, g, sizeof g);
    vec_text(want_v, w, sizeof w);
    for (i = 0; i < 3; i++)
        alt[i] = b[i] - a[i];
    if (v->function == F_RESTA && near_vector(got_v, alt))
        return grade_fail(item, err, "%s gave %s, which is b - a; expected "
                                     "%s: r = a - b",
                          call, g, w);
    if (v->function == F_NORMALIZAR && near_vector(got_v, a))
        return grade_fail(item, err, "%s left a unchanged %s; expected %s: "
                                     "normalizar divides the array it is "
                                     "given by its norm",
                          call, g, w);
    if (v->function == F_NORMAL) {
        double length = sqrt(dot(got_v, got_v));
        for (i = 0; i < 3; i++)
            alt[i] = want_v[i] * s;
        if (near_vector(got_v, alt))
            return grade_fail(item, err, "%s gave %s, of length %.7g; "
                                         "expected the unit normal %s: "
                                         "N = (P - C) / r",
                              call, g, length, w);
        for (i = 0; i < 3; i++)
            alt[i] = -want_v[i];
        if (near_vector(got_v, alt))
            return grade_fail(item, err, "%s gave %s, pointing into the "
                                         "sphere; expected %s: "
                                         "N = (P - C) / r",
                              call, g, w);
    }
    return grade_fail(item, err, "%s gave %s; expected %s", call, g, w);
}

static int vector_case_right(const vector_case *v, const double *got)
{
    double want, want_v[3];
    expect_vector_case(v, &want, want_v);
    switch (v->function) {
    case F_PRODUCTO:
    case F_NORMA:
        return near_value(got[0], want);
    case F_DISTANCIA:
        return want == INFINITY ? is_infinito(got[0])
                                : near_value(got[0], want);
    default:
        return near_vector(got + 1, want_v);
    }
}

/* The centre of sphere i, as a vector "(x, y, z)". */
static const char *sphere_text(const ray_case *rc, size_t i, char *out,
                               size_t room)
{
    scene whole;
    const scene *s = ej2_scene_of(rc->scene, &whole);
    snprintf(out, room, "(%g, %g, %g)", s->c[i][0], s->c[i][1], s->c[i][2]);
    return out;
}

/* How well each modelled mistake agrees with the results: 2 for each
   case within 1, 3 when exact. */
static void mistake_scores(const double *got, unsigned *score)
{
    unsigned c, i;
    for (i = 0; i < NO_MODEL; i++)
        score[i] = 0;
    for (c = 0; c < ej2_ray_case_count; c++)
        for (i = 0; i < MODELLED; i++) {
            double m = ej2_shade(&ej2_ray_cases[c], modelled[i]).value;
            if (fabs(got[c] - m) <= 1)
                score[modelled[i]] += 2 + (fabs(got[c] - m) < 0.5);
        }
}

/* The mistake that gives got for this case (and not the right value)
   and agrees best with the results overall; NO_MODEL when none does. */
static int ray_mistake(const ray_case *rc, double got,
                       const unsigned *score)
{
    double want = ej2_shade(rc, RAYO_MISTAKE_NONE).value;
    int best = NO_MODEL;
    unsigned i;
    for (i = 0; i < MODELLED; i++) {
        int k = modelled[i];
        double m = ej2_shade(rc, k).value;
        if (fabs(m - want) > 1 && fabs(got - m) <= 1 &&
            (best == NO_MODEL || score[k] > score[best]))
            best = k;
    }
    return best;
}

/* The facts of one wrong computar_intensidad, then the course's
   sentence for mistake k. */
static rayo_status say_ray(rayo_grade_item *item, const ray_case *rc,
                           const char *call, double got, int k,
                           rayo_error *err)
{
    shading want = ej2_shade(rc, RAYO_MISTAKE_NONE), m;
    const char *why;
    char x[96], y[96];
    if (k >= NO_MODEL)
        return grade_fail(item, err, "%s returned %g; expected %g", call, got,
                          want.value);
    m = ej2_shade(rc, k);
    why = rayo_course_mistake_text_lang(RAYO_COURSE_EJ2,
                                        (rayo_course_mistake)k,
                                        rayo_error_lang(err));
    switch (k) {
    case RAYO_MISTAKE_FIRST_SPHERE:
    case RAYO_MISTAKE_LAST_SPHERE:
        return grade_fail(item, err, "%s returned %g, the intensity of the "
                                     "sphere at %s; expected %g, the "
                                     "intensity of the nearest one, at %s: "
                                     "%s",
                          call, got, sphere_text(rc, m.sphere, x, sizeof x),
                          want.value,
                          sphere_text(rc, want.sphere, y, sizeof y), why);
    case RAYO_MISTAKE_FAR_ROOT:
        return grade_fail(item, err, "%s returned %g, the intensity at the "
                                     "far side of the sphere at %s; "
                                     "expected %g: %s",
                          call, got,
                          sphere_text(rc, want.sphere, x, sizeof x),
                          want.value, why);
    case RAYO_MISTAKE_NO_SHADOWS:
        return grade_fail(item, err, "%s returned %g; expected %g, as the "
                                     "sphere at %s lies between the point "
                                     "and the light: %s",
                          call, got, want.value,
                          sphere_text(rc, want.occluder, x, sizeof x), why);
    case RAYO_MISTAKE_SHADOW_BEHIND:
        return grade_fail(item, err, "%s returned %g; expected %g, as the "
                                     "sphere at %s is behind the point, away "
                                     "from the light: %s",
                          call, got, want.value,
                          sphere_text(rc, m.occluder, x, sizeof x), why);
    case RAYO_MISTAKE_NO_LN_TEST:
    case RAYO_MISTAKE_LIGHT_REVERSED:
        return grade_fail(item, err, "%s returned %g; expected %g, with "
                                     "L.N = %.3g here: %s",
                          call, got, want.value, want.ln, why);
    case RAYO_MISTAKE_WRAPPED:
        return grade_fail(item, err, "%s returned %g, which is %g wrapped "
                                     "around 256; expected 255: %s",
                          call, got,
                          ej2_shade(rc, RAYO_MISTAKE_NO_CLAMP).value, why);
    case RAYO_MISTAKE_NO_CLAMP:
        return grade_fail(item, err, "%s returned %g, which is IA + II (L.N) "
                                     "here; expected 255: %s",
                          call, got, why);
    default:
        return grade_fail(item, err, "%s returned %g; expected %g: %s", call,
                          got, want.value, why);
    }
}

/* ---- judging ---- */

/* What most likely makes function i return a NaN. */
static const char *nan_cause(unsigned i)
{
    switch (i) {
    case F_NORMA:
        return "the square root of a negative sum (a sum of squares is "
               "never negative: check the signs) or 0/0";
    case F_NORMALIZAR:
    case F_NORMAL:
        return HARNESS_NAN_NORMAL;
    case F_DISTANCIA:
        return HARNESS_NAN_DISCRIMINANT;
    default:
        return HARNESS_NAN_ARITHMETIC;
    }
}

/* Judges function i: 0 when the log ends before its calls are done. */
rayo_status ej2_judge(grade_context *ctx, unsigned i, const char *log,
                      const int *usable, rayo_error *err)
{
    rayo_grade_item *item = &ctx->report->items[RAYO_GRADE_FUNCTIONS];
    char call[512], line[1024];
    unsigned k, cases = 0, wrong = 0, unsaid = 0, said = 0;
    rayo_status status = RAYO_OK;
    (void)usable;
    if (harness_missing(log, ej2_functions[i].name))
        return grade_fail(item, err, "%s: not defined; the statement asks "
                                     "for %s",
                          ej2_functions[i].name, ej2_functions[i].prototype);
    for (k = 0; k < ej2_vector_case_count && i != F_INTENSIDAD; k++) {
        double got[4];
        if (ej2_vector_cases[k].function != i)
            continue;
        if (harness_result(log, ej2_functions[i].name, k, got, 4) != 4)
            return RAYO_OK; /* it ended inside or before: said elsewhere */
        cases++;
        if (vector_case_right(&ej2_vector_cases[k], got))
            continue;
        if (wrong++ >= SAID_PER_FUNCTION) {
            unsaid++;
            continue;
        }
        ej2_describe_vector_case(k, call, sizeof call);
        if (harness_not_finite(call, i == F_PRODUCTO || i == F_NORMA ||
                                             i == F_DISTANCIA
                                         ? got
                                         : got + 1,
                               i == F_PRODUCTO || i == F_NORMA ||
                                       i == F_DISTANCIA
                                   ? 1
                                   : 3,
                               nan_cause(i),
                               i == F_DISTANCIA
                                   ? "the statement's INFINITO is FLT_MAX, the "
                                     "largest "
                                     "float, not an infinity"
                                   : NULL,
                               line, sizeof line))
            status = grade_fail(item, err, "%s", line);
        else
            status = say_vector(item, &ej2_vector_cases[k], call, got[0],
                                got + 1, err);
        if (status != RAYO_OK)
            return status;
    }
    if (i == F_INTENSIDAD) {
        double got[ej2_ray_case_count];
        unsigned score[NO_MODEL];
        int mistake;
        for (k = 0; k < ej2_ray_case_count; k++)
            if (harness_result(log, ej2_functions[i].name, k, &got[k], 1) != 1)
                return RAYO_OK; /* it ended inside or before */
        mistake_scores(got, score);
        for (k = 0; k < ej2_ray_case_count; k++) {
            const ray_case *rc = &ej2_ray_cases[k];
            cases++;
            if (fabs(got[k] - ej2_shade(rc, RAYO_MISTAKE_NONE).value) <= 1)
                continue;
            wrong++;
            /* One line per mistake recognised; the same one again
               counted. */
            mistake = got[k] == HARNESS_INT_MIN ? NAN_INT
                                                : ray_mistake(rc, got[k],
                                                              score);
            if (said & (1u << mistake) || wrong > SAID_PER_FUNCTION + 2) {
                unsaid++;
                continue;
            }
            said |= 1u << mistake;
            ej2_describe_ray_case(k, rayo_error_lang(err), call, sizeof call);
            if (mistake == NAN_INT)
                status = grade_fail(item, err, "%s returned -2147483648, "
                                               "what a NaN (not a number) "
                                               "or a value past the int "
                                               "range becomes through "
                                               "(int): likely %s",
                                    call, HARNESS_NAN_SHADING);
            else
                status = say_ray(item, rc, call, got[k], mistake, err);
            if (status != RAYO_OK)
                return status;
        }
    }
    if (wrong == 0)
        status = functions_right(ctx, ej2_functions[i].name, cases, NULL,
                                 err);
    else if (unsaid > 0)
        status = grade_fail(item, err, "%s: wrong on %u more of its %u "
                                       "known inputs",
                            ej2_functions[i].name, unsaid, cases);
    return status;
}

