/*
 * ej1.c - the functions table of Ejercicio obligatorio 1:
 * producto_interno, norma and intersecta_esfera have the assignment's
 * signatures and return the right values on known inputs.  Its cases,
 * the records its harness (harness/ej1.c) is given, the expected values
 * (in double precision, from the assignment's formulas, compared with a
 * relative tolerance) and its findings; the engine (engine.c) probes,
 * builds, runs and calls judge.
 */
#define _POSIX_C_SOURCE 200809L

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "harness_sources.h"
#include "table.h"

#define MAX_ARGS 6
#define MAX_CASES 5

/* The functions, as the assignment writes them. */
static const functions_function functions[] = {
    {"producto_interno", "float producto_interno(float x1, float y1, "
                         "float z1, float x2, float y2, float z2)"},
    {"norma", "float norma(float x, float y, float z)"},
    {"intersecta_esfera", "int intersecta_esfera(float dx, float dy, "
                          "float dz)"}};

/* Each function's cases, in the same order. */
typedef struct function_spec {
    unsigned arg_count;
    int returns_int;
    unsigned case_count;
    double args[MAX_CASES][MAX_ARGS];
} function_spec;

/* intersecta_esfera's cases are directions towards points, normalised
   by case_args(). */
static const function_spec ej1_functions[] = {
    {6, 0, 3,
     {{1, 2, 3, 4, 5, 6}, {0.5, -1.5, 2, 3, 0.25, -4},
      {0.1, 0.2, 0.3, 0.4, 0.5, 0.6}}},
    {3, 0, 4,
     {{3, 4, 12}, {0.5, 0.5, 0.5}, {1, 1, 1}, {-0.6, 0, -0.8}}},
    {3, 1, 5,
     {{0.5, 0.75, 1.9}, {0, 0, 1}, {1, 0, 0}, {0.5, 0.3, 1.9},
      {-0.5, 0.75, 1.9}}},
};
#define FUNCTION_COUNT (sizeof ej1_functions / sizeof ej1_functions[0])

/* The name of the function whose cases f are. */
static const char *name_of(const function_spec *f)
{
    return functions[f - ej1_functions].name;
}

#define SPHERE_X 0.5
#define SPHERE_Y 0.75
#define SPHERE_Z 1.9
#define SPHERE_R 0.8

/* The arguments actually passed: intersecta_esfera gets unit vectors,
   rounded to float as the call will. */
static void case_args(const function_spec *f, unsigned c, double *args)
{
    unsigned i;
    double n = 1;
    if (f->returns_int)
        n = sqrt(f->args[c][0] * f->args[c][0] +
                 f->args[c][1] * f->args[c][1] +
                 f->args[c][2] * f->args[c][2]);
    for (i = 0; i < f->arg_count; i++)
        args[i] = (double)(float)(f->args[c][i] / n);
}

static double expected(const function_spec *f, const double *a)
{
    if (strcmp(name_of(f), "producto_interno") == 0)
        return a[0] * a[3] + a[1] * a[4] + a[2] * a[5];
    if (strcmp(name_of(f), "norma") == 0)
        return sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    {
        double b = SPHERE_X * a[0] + SPHERE_Y * a[1] + SPHERE_Z * a[2];
        double cc = SPHERE_X * SPHERE_X + SPHERE_Y * SPHERE_Y +
                    SPHERE_Z * SPHERE_Z;
        return b * b - cc + SPHERE_R * SPHERE_R >= 0 ? 1 : 0;
    }
}

/* The harness's records: each usable function's cases, "c NAME K" and
   the six arguments (unused ones 0). */
static void write_calls(harness_text *t, const int *usable)
{
    size_t i;
    unsigned c;
    for (i = 0; i < FUNCTION_COUNT; i++) {
        const function_spec *f = &ej1_functions[i];
        if (!usable[i])
            continue;
        for (c = 0; c < f->case_count; c++) {
            double args[MAX_ARGS] = {0};
            case_args(f, c, args);
            harness_append(t, "c %s %u", name_of(f), c);
            harness_numbers(t, args, MAX_ARGS);
            harness_append(t, "\n");
        }
    }
}

static void format_call(const function_spec *f, unsigned c, char *out,
                        size_t room)
{
    double args[MAX_ARGS];
    unsigned i;
    size_t n;
    case_args(f, c, args);
    n = (size_t)snprintf(out, room, "%s(", name_of(f));
    for (i = 0; i < f->arg_count && n < room; i++)
        n += (size_t)snprintf(out + n, room - n, "%s%g", i > 0 ? ", " : "",
                              args[i]);
    if (n < room)
        snprintf(out + n, room - n, ")");
}

static int close_enough(double got, double want)
{
    return fabs(got - want) <= 1e-5 + 1e-4 * fabs(want);
}

/* Checks one function's results in the harness output. */
static rayo_status judge_function(grade_context *ctx,
                                  const function_spec *f, const char *log,
                                  rayo_error *err)
{
    rayo_grade_item *item = &ctx->report->items[RAYO_GRADE_FUNCTIONS];
    char call[256], line[512];
    unsigned c, wrong = 0;
    rayo_status status = RAYO_OK;
    if (harness_missing(log, name_of(f)))
        return grade_fail(item, err, "%s: not defined; the assignment asks "
                                     "for %s",
                          name_of(f), functions[f - ej1_functions].prototype);
    for (c = 0; c < f->case_count && status == RAYO_OK; c++) {
        double args[MAX_ARGS], got, want;
        case_args(f, c, args);
        want = expected(f, args);
        format_call(f, c, call, sizeof call);
        if (harness_result(log, name_of(f), c, &got, 1) != 1)
            return RAYO_OK; /* the run ended inside or before this call:
                               said elsewhere */
        if (f->returns_int ? got == want : close_enough(got, want))
            continue;
        wrong++;
        if (!f->returns_int &&
            harness_not_finite(call, &got, 1,
                               strcmp(name_of(f), "norma") == 0
                                   ? "the square root of a negative sum "
                                     "(a sum of squares is never negative: "
                                     "check the signs) or 0/0"
                                   : HARNESS_NAN_ARITHMETIC,
                               NULL, line, sizeof line))
            status = grade_fail(item, err, "%s", line);
        else if (f->returns_int)
            status = grade_fail(item, err, "%s returned %g; expected %g (%s)",
                                call, got, want,
                                want != 0 ? "this ray does hit the sphere"
                                          : "this ray misses the sphere");
        else if (got == floor(want) && want != floor(want))
            status = grade_fail(item, err, "%s returned %g; expected %.7g: "
                                           "the decimals are lost, is an int "
                                           "used inside the function?",
                                call, got, want);
        else
            status = grade_fail(item, err, "%s returned %.7g; expected %.7g",
                                call, got, want);
    }
    if (status == RAYO_OK && wrong == 0)
        status = functions_right(ctx, name_of(f), f->case_count, NULL, err);
    return status;
}

static void describe(const char *name, unsigned c, rayo_lang lang,
                     char *out, size_t room)
{
    (void)lang; /* a call of C, the same in every language */
    size_t i;
    for (i = 0; i < FUNCTION_COUNT; i++)
        if (strcmp(functions[i].name, name) == 0 &&
            c < ej1_functions[i].case_count)
            format_call(&ej1_functions[i], c, out, room);
}

static rayo_status judge(grade_context *ctx, unsigned f, const char *log,
                         const int *usable, rayo_error *err)
{
    (void)usable;
    return judge_function(ctx, &ej1_functions[f], log, err);
}

const functions_exercise functions_ej1 = {
    .functions = functions,
    .count = FUNCTION_COUNT,
    .harness = harness_ej1_c,
    .harness_size = &harness_ej1_c_size,
    .probe_before = "",
    .assignment = 1,
    .write_calls = write_calls,
    .judge = judge,
    .describe = describe};
