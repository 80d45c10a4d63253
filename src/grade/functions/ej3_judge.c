/*
 * ej3_judge.c - judging Ejercicio obligatorio 3's functions from the
 * harness's log: values, color_imprimir's output, the constructors and
 * their destructors, arreglo_agregar under failing allocation, and the
 * accepted readings of an ambiguous statement, each named once
 * (computar_intensidad's colours are ej3_rays.c's).
 */
#define _POSIX_C_SOURCE 200809L

#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rayo/lang.h"

#include "ej3.h"
#include "harness_math.h"

/* The bytes color_imprimir must print for channel c (a float). */
static int channel_byte(double c)
{
    return c > 1 ? 255 : (int)floor(255 * c);
}

/* ---- judging ---- */


/* A reason line for a wrong case, or only counted past the first few. */
rayo_status ej3_wrong_line(judging *j, rayo_error *err,
                           const char *format, ...)
{
    char line[1024];
    va_list args;
    if (j->wrong++ >= j->limit) {
        j->unsaid++;
        j->item->result = RAYO_GRADE_FAIL;
        return RAYO_OK;
    }
    va_start(args, format);
    rayo_lang_vformat(rayo_error_lang(err), line, sizeof line, format, args);
    va_end(args);
    return grade_fail(j->item, err, "%s", line);
}

/* What most likely makes function f return a NaN. */
static const char *nan_cause(unsigned f)
{
    switch (f) {
    case F_NORMA:
        return "the square root of a negative sum (a sum of squares is "
               "never negative: check the signs) or 0/0";
    case F_NORMALIZAR:
        return HARNESS_NAN_NORMAL;
    case F_DISTANCIA:
        return HARNESS_NAN_DISCRIMINANT;
    case F_INTENSIDAD:
        return HARNESS_NAN_SHADING;
    default:
        return HARNESS_NAN_ARITHMETIC;
    }
}

static rayo_status judge_value(judging *j, unsigned k, rayo_error *err)
{
    const value_case *v = &ej3_value_cases[k];
    const char *name = ej3_functions[v->function].name;
    double a[3], b[3], c[3], s, got[10], want[3], far;
    char call[512], g[64], w[64];
    int count;
    unsigned i;
    ej3_value_args(v, a, b, c, &s);
    ej3_describe_value_case(k, rayo_error_lang(err), call, sizeof call);
    count = harness_result(j->log, name, k, got, 10);
    if (count < 0)
        return RAYO_ERR_CANCELLED; /* it ended before: said elsewhere */
    j->cases++;
    {
        int scalar = v->function == F_PRODUCTO || v->function == F_NORMA ||
                     v->function == F_DISTANCIA;
        char line[1024];
        if (v->function != F_IMPRIMIR && v->function != F_ESFERA_CREAR &&
            v->function != F_LUZ_CREAR && count >= 4 &&
            harness_not_finite(call, scalar ? got : got + 1, scalar ? 1 : 3,
                               nan_cause(v->function),
                               v->function == F_DISTANCIA
                                   ? "the statement's INFINITO is FLT_MAX, the "
                                     "largest "
                                     "float, not an infinity"
                                   : NULL,
                               line, sizeof line))
            return ej3_wrong_line(j, err, "%s", line);
        if (v->function == F_DISTANCIA && count >= 7 &&
            !is_infinito(got[0]) &&
            (harness_not_finite(call, got + 1, 3, HARNESS_NAN_ARITHMETIC,
                                NULL, line, sizeof line) ||
             harness_not_finite(call, got + 4, 3, HARNESS_NAN_NORMAL, NULL,
                                line, sizeof line)))
            return ej3_wrong_line(j, err, "%s (in *punto or *normal)", line);
    }
    switch (v->function) {
    case F_PRODUCTO:
    case F_NORMA: {
        double x = v->function == F_NORMA ? sqrt(dot(a, a)) : dot(a, b);
        if (near_value(got[0], x))
            return RAYO_OK;
        if (got[0] == floor(x) && x != floor(x))
            return ej3_wrong_line(j, err, "%s returned %g; expected %.7g: the "
                                      "decimals are lost, is an int used "
                                      "inside the function?",
                              call, got[0], x);
        return ej3_wrong_line(j, err, "%s returned %.7g; expected %.7g", call,
                          got[0], x);
    }
    case F_RESTA:
        ej3_sub(a, b, want);
        if (near_vector(got + 1, want))
            return RAYO_OK;
        ej3_sub(b, a, c);
        return ej3_wrong_line(j, err, "%s returned %s; expected %s%s", call,
                          vec_text(got + 1, g, sizeof g),
                          vec_text(want, w, sizeof w),
                          near_vector(got + 1, c) ? ": that is b - a; the "
                                                    "result is a - b"
                                                  : "");
    case F_INTERPOLAR:
        for (i = 0; i < 3; i++)
            want[i] = a[i] + s * b[i];
        break;
    case F_NORMALIZAR:
        unit(a, want);
        break;
    case F_SUMAR:
        for (i = 0; i < 3; i++)
            want[i] = a[i] + s * b[i];
        break;
    case F_ABSORBER:
        for (i = 0; i < 3; i++)
            want[i] = a[i] * b[i];
        break;
    case F_IMPRIMIR:
        return RAYO_OK; /* judged from its output: judge_imprimir */
    case F_ESFERA_CREAR:
    case F_LUZ_CREAR:
        return RAYO_OK; /* judge_crear */
    default:
        far = sphere_t(a, s, b, c, 1);
        want[0] = sphere_t(a, s, b, c, 0);
        if (want[0] == INFINITY) {
            if (is_infinito(got[0]))
                return RAYO_OK;
            if (a[2] < 0)
                return ej3_wrong_line(j, err,
                                      "%s returned %.7g for a ray that meets "
                                      "the sphere only behind its origin "
                                      "(t < 0); expected INFINITO (FLT_MAX)",
                                      call, got[0]);
            return ej3_wrong_line(j, err,
                                  "%s returned %.7g for a ray that misses "
                                  "the sphere; expected INFINITO (FLT_MAX)",
                                  call, got[0]);
        }
        if (is_infinito(got[0]))
            return ej3_wrong_line(j, err,
                                  "%s returned INFINITO for a ray that "
                                      "meets the sphere at t = %.7g",
                              call, want[0]);
        if (!near_value(got[0], want[0])) {
            if (far != want[0] && near_value(got[0], far))
                return ej3_wrong_line(j, err, "%s returned the far root %.7g "
                                          "for a ray that meets the sphere "
                                          "at t = %.7g first: "
                                          "beta - sqrt(delta) when it is "
                                          "> 0",
                                  call, got[0], want[0]);
            if (got[0] < 0)
                return ej3_wrong_line(j, err,
                                      "%s returned %.7g, a root behind "
                                          "the origin (t < 0), for a ray "
                                          "that starts inside the sphere; "
                                          "expected %.7g: when "
                                          "beta - sqrt(delta) <= 0 the "
                                          "answer is beta + sqrt(delta)",
                                  call, got[0], want[0]);
            return ej3_wrong_line(j, err, "%s returned %.7g; expected %.7g",
                              call, got[0], want[0]);
        }
        {
            double p[3], n[3], length = sqrt(dot(got + 4, got + 4));
            for (i = 0; i < 3; i++)
                p[i] = b[i] + want[0] * c[i];
            for (i = 0; i < 3; i++)
                n[i] = (p[i] - a[i]) / s;
            if (!near_vector(got + 1, p))
                return ej3_wrong_line(j, err, "%s: *punto is %s; expected the "
                                          "hit point o + t d = %s",
                                  call, vec_text(got + 1, g, sizeof g),
                                  vec_text(p, w, sizeof w));
            if (!near_vector(got + 4, n))
                return ej3_wrong_line(j, err, "%s: *normal is %s, of length "
                                          "%.7g; expected the unit normal "
                                          "(P - C) / r = %s",
                                  call, vec_text(got + 4, g, sizeof g),
                                  length, vec_text(n, w, sizeof w));
        }
        return RAYO_OK;
    }
    if (near_vector(got + 1, want))
        return RAYO_OK;
    return ej3_wrong_line(j, err, "%s returned %s; expected %s", call,
                      vec_text(got + 1, g, sizeof g),
                      vec_text(want, w, sizeof w));
}

/* color_imprimir: the text printed between the markers. */
static rayo_status judge_imprimir(judging *j, unsigned k, rayo_error *err)
{
    const value_case *v = &ej3_value_cases[k];
    double a[3], b[3], c[3], s, dummy;
    char call[256], key[64], shown[128], expect[32];
    const char *start, *end;
    int want[3], got[3], used = 0;
    unsigned i;
    ej3_value_args(v, a, b, c, &s);
    ej3_describe_value_case(k, rayo_error_lang(err), call, sizeof call);
    if (harness_result(j->log, "color_imprimir", k, &dummy, 1) < 0)
        return RAYO_ERR_CANCELLED;
    j->cases++;
    snprintf(key, sizeof key, "\nout color_imprimir %u\n", k);
    start = strstr(j->log, key);
    if (start == NULL)
        return RAYO_ERR_CANCELLED;
    start += strlen(key);
    end = strstr(start, "\nend color_imprimir ");
    if (end == NULL)
        end = start + strlen(start);
    harness_clean(start, (size_t)(end - start), shown, sizeof shown);
    for (i = 0; i < 3; i++)
        want[i] = channel_byte(a[i]);
    snprintf(expect, sizeof expect, "%d %d %d", want[0], want[1], want[2]);
    if (strstr(shown, "nan") != NULL || strstr(shown, "inf") != NULL ||
        strstr(shown, "-2147483648") != NULL)
        return ej3_wrong_line(j, err, "%s printed \"%s\"; expected \"%s\": "
                                  "nan and inf (printed by %%f) and "
                                  "-2147483648 (a NaN or a value past the "
                                  "int range through (int)) come from a "
                                  "result that is not a number: likely %s",
                          call, shown, expect, HARNESS_NAN_ARITHMETIC);
    if (sscanf(start, "%d %d %d%n", &got[0], &got[1], &got[2], &used) != 3 ||
        start + used > end || strspn(start + used, " \t\n") <
                                  (size_t)(end - start - used))
        return ej3_wrong_line(j, err, "%s printed \"%s\"; expected \"%s\": "
                                  "three integers R G B from 0 to 255",
                          call, shown, expect);
    if (got[0] == want[2] && got[1] == want[1] && got[2] == want[0] &&
        want[0] != want[2])
        return ej3_wrong_line(j, err, "%s printed \"%s\"; expected \"%s\": "
                                  "the channels are in the order B G R; "
                                  "a PPM pixel is R G B",
                          call, shown, expect);
    for (i = 0; i < 3; i++) {
        if (got[i] == want[i])
            continue;
        if (a[i] > 1 && got[i] == (int)floor(255 * a[i]) % 256)
            return ej3_wrong_line(j, err,
                                  "%s printed \"%s\"; expected \"%s\": "
                                      "255 x %.7g wrapped around 256; a "
                                      "component above 1 prints as 255",
                              call, shown, expect, a[i]);
        if (a[i] > 1)
            return ej3_wrong_line(j, err,
                                  "%s printed \"%s\"; expected \"%s\": "
                                      "a component above 1 prints as 255",
                              call, shown, expect);
        if (got[i] == (int)floor(255 * a[i] + 0.5)) {
            j->rounds = 1; /* a reading, accepted: ej3_judge() names it */
            continue;
        }
        if (got[i] == (int)floor(256 * a[i]))
            return ej3_wrong_line(j, err,
                                  "%s printed \"%s\"; expected \"%s\": "
                                      "scaled by 256; 0..1 scales to "
                                      "0..255",
                              call, shown, expect);
        return ej3_wrong_line(j, err, "%s printed \"%s\"; expected \"%s\"",
                          call, shown, expect);
    }
    return RAYO_OK;
}

/* esfera_crear and luz_crear keep what they are given. */
static rayo_status judge_crear(judging *j, unsigned k, rayo_error *err)
{
    static const char *const sphere_fields[] = {
        "centro.x", "centro.y", "centro.z", "radio", "color.r",
        "color.g",  "color.b",  "ka",       "kd"};
    static const char *const light_fields[] = {
        "posicion.x", "posicion.y", "posicion.z", "color.r",
        "color.g",    "color.b",    "es_puntual"};
    const value_case *v = &ej3_value_cases[k];
    int is_sphere = v->function == F_ESFERA_CREAR;
    const char *name = ej3_functions[v->function].name;
    double a[3], b[3], c[3], s, got[9], given[9];
    char call[512], text[16];
    int count, fields = is_sphere ? 9 : 7;
    unsigned i;
    ej3_value_args(v, a, b, c, &s);
    ej3_describe_value_case(k, rayo_error_lang(err), call, sizeof call);
    if (!harness_result_text(j->log, name, k, text, sizeof text))
        return RAYO_ERR_CANCELLED;
    j->cases++;
    if (strncmp(text, "null", 4) == 0)
        return ej3_wrong_line(j, err, "%s returned NULL", call);
    count = harness_result(j->log, name, k, got, fields);
    for (i = 0; i < 3; i++) {
        given[i] = a[i];
        given[i + (is_sphere ? 4 : 3)] = b[i];
    }
    if (is_sphere) {
        given[3] = s;
        given[7] = c[0];
        given[8] = c[1];
    } else {
        given[6] = s != 0;
    }
    for (i = 0; i < (unsigned)fields && (int)i < count; i++)
        if (!near_value(got[i], given[i]))
            return ej3_wrong_line(
                j, err, "%s returned a %s whose %s is %.7g, not the %.7g "
                        "it was given",
                call, is_sphere ? "sphere" : "light",
                is_sphere ? sphere_fields[i] : light_fields[i], got[i],
                given[i]);
    return RAYO_OK;
}

static rayo_status judge_agregar(judging *j, rayo_error *err)
{
    double r[8];
    int count = harness_result(j->log, "arreglo_agregar", 0, r, 8);
    if (count < 8)
        return RAYO_ERR_CANCELLED;
    j->cases++;
    if (r[6] == 0)
        return ej3_wrong_line(j, err, "arreglo_agregar wrote past the end of "
                                  "a->v: after three additions to an empty "
                                  "array its last realloc asked for %g "
                                  "bytes, and a pointer was written beyond "
                                  "them; ask for (a->n + 1) * sizeof(void *) "
                                  "before writing a->v[a->n]",
                          r[7]);
    if (r[0] == 0 || r[1] == 0 || r[2] == 0)
        return ej3_wrong_line(j, err, "arreglo_agregar returned false while "
                                  "adding three elements to an empty "
                                  "array {NULL, 0}; it returns true when "
                                  "it adds");
    if (r[3] != 3)
        return ej3_wrong_line(j, err,
                              "after three arreglo_agregar on an empty "
                                  "array {NULL, 0}, a->n is %g; expected 3",
                          r[3]);
    if (r[4] == 0)
        return ej3_wrong_line(j, err,
                              "after three arreglo_agregar on an empty "
                                  "array {NULL, 0}, a->v is NULL");
    if (r[5] == 0)
        return ej3_wrong_line(j, err,
                              "after three arreglo_agregar on an empty "
                                  "array {NULL, 0}, a->v does not hold the "
                                  "three elements in the order added");
    /* tries, returned, n before, n after, v NULL, v same, same contents */
    count = harness_result(j->log, "arreglo_agregar", 1, r, 7);
    if (count < 7)
        return RAYO_ERR_CANCELLED;
    j->cases++;
    if (r[0] == 0)
        return ej3_wrong_line(j, err, "arreglo_agregar added %g elements "
                                  "without asking for memory: a->v must "
                                  "grow (with realloc) as elements are "
                                  "added",
                          r[3]);
    if (r[4] != 0)
        return ej3_wrong_line(j, err, "arreglo_agregar lost the array when "
                                  "realloc failed: a->v became NULL; keep "
                                  "realloc's result in a temporary and "
                                  "assign it only when it is not NULL");
    if (r[1] != 0)
        return ej3_wrong_line(j, err, "arreglo_agregar returned true when "
                                  "realloc failed; on failure it returns "
                                  "false");
    if (r[2] != r[3])
        return ej3_wrong_line(j, err,
                              "arreglo_agregar changed a->n from %g to "
                                  "%g when realloc failed; on failure the "
                                  "array is left exactly as it was",
                          r[2], r[3]);
    if (r[5] == 0 || r[6] == 0)
        return ej3_wrong_line(j, err, "arreglo_agregar changed a->v or its "
                                  "elements when realloc failed; on "
                                  "failure the array is left exactly as it "
                                  "was");
    return RAYO_OK;
}

/* Judges function f; RAYO_ERR_CANCELLED inside: the run ended before
   its calls were done (said by harness_judge_ending). */
rayo_status ej3_judge(grade_context *ctx, unsigned f, const char *log,
                      const int *usable, rayo_error *err)
{
    judging j;
    unsigned k;
    rayo_status status = RAYO_OK;
    j.ctx = ctx;
    j.item = &ctx->report->items[RAYO_GRADE_FUNCTIONS];
    j.log = log;
    j.wrong = j.unsaid = j.cases = 0;
    j.beyond_light = j.between_only = j.rounds = 0;
    j.limit = f == F_INTENSIDAD ? SAID_PER_FUNCTION + 2 : SAID_PER_FUNCTION;
    if (harness_missing(log, ej3_functions[f].name))
        return grade_fail(j.item, err, "%s: not defined; the statement asks "
                                       "for %s",
                          ej3_functions[f].name, ej3_functions[f].prototype);
    if (f == F_ESFERA_DESTRUIR || f == F_LUZ_DESTRUIR) {
        unsigned maker = f == F_ESFERA_DESTRUIR ? F_ESFERA_CREAR
                                                : F_LUZ_CREAR;
        if (!usable[maker] || harness_missing(log, ej3_functions[maker].name))
            return grade_say(j.item, err, "%s: not called (it needs what "
                                          "%s returns)",
                             ej3_functions[f].name, ej3_functions[maker].name);
        for (k = 0; k < ej3_value_case_count; k++)
            if (ej3_value_cases[k].function == maker &&
                harness_result_text(log, ej3_functions[f].name, k,
                                    (char[4]){0},
                                    4))
                break;
        if (k == ej3_value_case_count)
            return RAYO_OK;
        return functions_right(ctx, ej3_functions[f].name, 0,
                               ej3_functions[maker].name, err);
    }
    if (f == F_AGREGAR)
        status = judge_agregar(&j, err);
    else if (f == F_INTENSIDAD)
        status = ej3_judge_rays(&j, err);
    for (k = 0; k < ej3_value_case_count && status == RAYO_OK; k++) {
        if (ej3_value_cases[k].function != f)
            continue;
        if (f == F_IMPRIMIR)
            status = judge_imprimir(&j, k, err);
        else if (f == F_ESFERA_CREAR || f == F_LUZ_CREAR)
            status = judge_crear(&j, k, err);
        else
            status = judge_value(&j, k, err);
    }
    if (status == RAYO_ERR_CANCELLED)
        return RAYO_OK;
    if (status == RAYO_OK && j.wrong == 0)
        status = functions_right(ctx, ej3_functions[f].name, j.cases, NULL,
                                 err);
    else if (status == RAYO_OK && j.unsaid > 0)
        status = grade_fail(j.item, err, "%s: wrong on %u more of its %u "
                                         "known inputs",
                            ej3_functions[f].name, j.unsaid, j.cases);
    if (status == RAYO_OK && j.beyond_light)
        status = grade_say(j.item, err, "computar_intensidad: a sphere "
                                        "beyond a point light casts a "
                                        "shadow: the statement's rule (an "
                                        "object in the light's direction "
                                        "casts a shadow) read to the "
                                        "letter, accepted; the other "
                                        "reading, a shadow only from a "
                                        "sphere between the point and the "
                                        "light, is accepted too, and the "
                                        "course's scenes look the same "
                                        "either way");
    if (status == RAYO_OK && j.between_only && !j.beyond_light)
        status = grade_say(j.item, err, "computar_intensidad: only a sphere "
                                        "between the point and a point "
                                        "light casts a shadow, not one "
                                        "beyond the light: one of the "
                                        "statement's two readings, "
                                        "accepted; the other, to the "
                                        "letter (an object in the light's "
                                        "direction casts a shadow), is "
                                        "accepted too, and the course's "
                                        "scenes look the same either way");
    if (status == RAYO_OK && j.rounds)
        status = grade_say(j.item, err, "color_imprimir: rounds 255 c to "
                                        "the nearest integer (0.999 prints "
                                        "255) instead of taking its integer "
                                        "part (254): a reading of the "
                                        "statement's 'scale 0..1 to the "
                                        "integers 0..255', accepted");
    return status;
}

