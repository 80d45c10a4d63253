/*
 * functions_ej1.c - the "functions" criterion for Ejercicio obligatorio
 * 1: producto_interno, norma and intersecta_esfera have the assignment's
 * signatures and return the right values on known inputs.
 *
 * How (harness.h): (1) signatures: a probe file declares the
 * assignment's prototypes and then #includes the student's file; a
 * different definition or declaration is a "conflicting types" compile
 * error, which is quoted.  (2) values: the sources are compiled again
 * with main renamed and linked with a generated harness that declares
 * the functions whose signature is right as weak symbols (so a missing
 * function is reported, not a link error), calls them on known values
 * and prints the results, announcing each call first so a crash or a
 * hang is pinned on the call.  Expected values are computed here, in
 * double precision, from the formulas of the assignment; floats are
 * compared with a relative tolerance.
 */
#define _POSIX_C_SOURCE 200809L

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"

#define MAX_ARGS 6
#define MAX_CASES 5

typedef struct function_spec {
    const char *name;
    const char *prototype; /* as the assignment writes it */
    const char *types;     /* the harness's declaration, after the name */
    unsigned arg_count;
    int returns_int;
    unsigned case_count;
    double args[MAX_CASES][MAX_ARGS];
} function_spec;

/* The ej1 functions; intersecta_esfera's cases are directions towards
   points, normalised by unit_cases(). */
static const function_spec ej1_functions[] = {
    {"producto_interno",
     "float producto_interno(float x1, float y1, float z1, float x2, "
     "float y2, float z2)",
     "(float, float, float, float, float, float)", 6, 0, 3,
     {{1, 2, 3, 4, 5, 6}, {0.5, -1.5, 2, 3, 0.25, -4},
      {0.1, 0.2, 0.3, 0.4, 0.5, 0.6}}},
    {"norma", "float norma(float x, float y, float z)",
     "(float, float, float)", 3, 0, 4,
     {{3, 4, 12}, {0.5, 0.5, 0.5}, {1, 1, 1}, {-0.6, 0, -0.8}}},
    {"intersecta_esfera", "int intersecta_esfera(float dx, float dy, "
                          "float dz)",
     "(float, float, float)", 3, 1, 5,
     {{0.5, 0.75, 1.9}, {0, 0, 1}, {1, 0, 0}, {0.5, 0.3, 1.9},
      {-0.5, 0.75, 1.9}}},
};
#define FUNCTION_COUNT (sizeof ej1_functions / sizeof ej1_functions[0])

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
    if (strcmp(f->name, "producto_interno") == 0)
        return a[0] * a[3] + a[1] * a[4] + a[2] * a[5];
    if (strcmp(f->name, "norma") == 0)
        return sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    {
        double b = SPHERE_X * a[0] + SPHERE_Y * a[1] + SPHERE_Z * a[2];
        double cc = SPHERE_X * SPHERE_X + SPHERE_Y * SPHERE_Y +
                    SPHERE_Z * SPHERE_Z;
        return b * b - cc + SPHERE_R * SPHERE_R >= 0 ? 1 : 0;
    }
}

static void write_call(harness_text *t, const function_spec *f, unsigned c)
{
    double args[MAX_ARGS];
    unsigned i;
    case_args(f, c, args);
    harness_append(t, "    rayo_say(\"call %s %u\");\n"
                      "    fflush(stdout);\n",
                   f->name, c);
    harness_append(t, "    rayo_say(\"result %s %u %%.9g\", (double)%s(",
                   f->name, c, f->name);
    for (i = 0; i < f->arg_count; i++)
        harness_append(t, "%s(float)%.9g", i > 0 ? ", " : "", args[i]);
    harness_append(t, "));\n    fflush(stdout);\n");
}

/* The harness source for the functions marked usable. */
static char *harness_source(const int *usable)
{
    harness_text t = {NULL, 0, 0, 0};
    size_t i;
    unsigned c;
    harness_prelude(&t);
    for (i = 0; i < FUNCTION_COUNT; i++)
        if (usable[i])
            harness_append(&t, "%s %s%s __attribute__((weak));\n",
                           ej1_functions[i].returns_int ? "int" : "float",
                           ej1_functions[i].name, ej1_functions[i].types);
    harness_append(&t, "int main(void)\n{\n");
    for (i = 0; i < FUNCTION_COUNT; i++) {
        const function_spec *f = &ej1_functions[i];
        if (!usable[i])
            continue;
        harness_append(&t, "    if (%s == 0) {\n"
                           "        rayo_say(\"missing %s\");\n"
                           "    } else {\n",
                       f->name, f->name);
        for (c = 0; c < f->case_count; c++)
            write_call(&t, f, c);
        harness_append(&t, "    }\n");
    }
    harness_append(&t, "    rayo_say(\"done\");\n    return 0;\n}\n");
    if (t.failed) {
        free(t.data);
        return NULL;
    }
    return t.data;
}

static void format_call(const function_spec *f, unsigned c, char *out,
                        size_t room)
{
    double args[MAX_ARGS];
    unsigned i;
    size_t n;
    case_args(f, c, args);
    n = (size_t)snprintf(out, room, "%s(", f->name);
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
static rayo_status judge(grade_context *ctx, const function_spec *f,
                         const char *log, rayo_error *err)
{
    rayo_grade_item *item = &ctx->report->items[RAYO_GRADE_FUNCTIONS];
    char call[256], line[512];
    unsigned c, wrong = 0;
    rayo_status status = RAYO_OK;
    if (harness_missing(log, f->name))
        return grade_fail(item, err, "%s: not defined; the assignment asks "
                                     "for %s",
                          f->name, f->prototype);
    for (c = 0; c < f->case_count && status == RAYO_OK; c++) {
        double args[MAX_ARGS], got, want;
        case_args(f, c, args);
        want = expected(f, args);
        format_call(f, c, call, sizeof call);
        if (harness_result(log, f->name, c, &got, 1) != 1)
            return RAYO_OK; /* the run ended inside or before this call:
                               said elsewhere */
        if (f->returns_int ? got == want : close_enough(got, want))
            continue;
        wrong++;
        if (!f->returns_int &&
            harness_not_finite(call, &got, 1,
                               strcmp(f->name, "norma") == 0
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
        status = grade_say(item, err, "%s: right on %u known inputs",
                           f->name, f->case_count);
    return status;
}

static void describe(const char *name, unsigned c, char *out, size_t room)
{
    size_t i;
    for (i = 0; i < FUNCTION_COUNT; i++)
        if (strcmp(ej1_functions[i].name, name) == 0 &&
            c < ej1_functions[i].case_count)
            format_call(&ej1_functions[i], c, out, room);
}

static rayo_status say_signature(grade_context *ctx, size_t i,
                                 const char *reason, rayo_error *err)
{
    return grade_fail(&ctx->report->items[RAYO_GRADE_FUNCTIONS], err,
                      "%s: the signature differs from the assignment's %s "
                      "(the compiler says: %s); not called",
                      ej1_functions[i].name, ej1_functions[i].prototype,
                      reason);
}

/* No function has the right signature: only say so, in order. */
static rayo_status run_harness_none(grade_context *ctx,
                                    char reasons[][HARNESS_REASON],
                                    rayo_error *err)
{
    size_t i;
    rayo_status status = RAYO_OK;
    for (i = 0; i < FUNCTION_COUNT && status == RAYO_OK; i++)
        status = say_signature(ctx, i, reasons[i], err);
    return status;
}


static rayo_status run_harness(grade_context *ctx, const int *usable,
                               char reasons[][HARNESS_REASON],
                               rayo_error *err)
{
    grade_outcome outcome;
    char *log = NULL;
    size_t i;
    rayo_status status = harness_run(ctx, &log, &outcome, err);
    for (i = 0; i < FUNCTION_COUNT && status == RAYO_OK; i++)
        status = usable[i] ? judge(ctx, &ej1_functions[i], log, err)
                           : say_signature(ctx, i, reasons[i], err);
    if (status == RAYO_OK)
        status = harness_judge_ending(ctx, log, &outcome, describe, err);
    free(log);
    return status;
}

/* Probes count functions against every source: 1 when no source
   conflicts with the assignment's prototypes; else why, in reason. */
static rayo_status probe(grade_context *ctx, const function_spec *f,
                         size_t count, int *ok, char *reason, size_t room,
                         rayo_error *err)
{
    harness_text t = {NULL, 0, 0, 0};
    size_t i, k;
    rayo_status status = RAYO_OK;
    *ok = 1;
    for (k = 0; k < count; k++)
        harness_append(&t, "%s;\n", f[k].prototype);
    if (t.failed) {
        free(t.data);
        return rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
    }
    for (i = 0; i < ctx->source_count && *ok && status == RAYO_OK; i++)
        status = harness_probe(ctx, i, t.data, "", ok, reason, room, err);
    free(t.data);
    return status;
}

rayo_status grade_functions_ej1(grade_context *ctx, rayo_error *err)
{
    rayo_grade_item *item = &ctx->report->items[RAYO_GRADE_FUNCTIONS];
    int usable[FUNCTION_COUNT], any = 0, ok;
    char reasons[FUNCTION_COUNT][HARNESS_REASON];
    char *errors = NULL, *source = NULL;
    size_t i;
    rayo_status status = RAYO_OK;
    item->result = RAYO_GRADE_PASS;
    /* One probe for all (the usual case), one each when that fails. */
    status = probe(ctx, ej1_functions, FUNCTION_COUNT, &ok, reasons[0],
                   sizeof reasons[0], err);
    for (i = 0; i < FUNCTION_COUNT && status == RAYO_OK; i++) {
        usable[i] = 1;
        if (!ok)
            status = probe(ctx, &ej1_functions[i], 1, &usable[i],
                           reasons[i], sizeof reasons[i], err);
        any |= usable[i];
    }
    if (status == RAYO_OK && any) {
        source = harness_source(usable);
        if (source == NULL)
            status = rayo_error_set(err, RAYO_ERR_NOMEM,
                                    "grade: out of memory");
        if (status == RAYO_OK)
            status = harness_build(ctx, source, NULL, 0, &ok, &errors, err);
        if (status == RAYO_OK && !ok) {
            status = grade_fail(item, err, "could not build the test "
                                           "harness around the functions:");
            if (status == RAYO_OK)
                status = grade_quote(item, errors, 4, err);
        } else if (status == RAYO_OK) {
            status = run_harness(ctx, usable, reasons, err);
        }
    } else if (status == RAYO_OK) {
        status = run_harness_none(ctx, reasons, err);
    }
    free(source);
    free(errors);
    return status;
}
