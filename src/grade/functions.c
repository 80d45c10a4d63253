/*
 * functions.c - the second criterion: the assignment's three functions
 * (producto_interno, norma, intersecta_esfera) have its signatures and
 * return the right values on known inputs.
 *
 * How: (1) signatures: a probe file declares the assignment's prototype
 * and then #includes the student's file; a different definition or
 * declaration is a "conflicting types" compile error, which is quoted.
 * (2) values: each source is compiled again with -Dmain=rayo_student_main
 * and linked with a generated harness that declares the functions whose
 * signature is right as weak symbols (so a missing function is reported,
 * not a link error), calls them on known values and prints the results,
 * announcing each call first so a crash or a hang is pinned on the call.
 * The harness runs under the same limits as the program.  Expected
 * values are computed here, in double precision, from the formulas of
 * the assignment; floats are compared with a relative tolerance.
 */
#define _POSIX_C_SOURCE 200809L

#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "grade_impl.h"

extern char **environ;

#define COMPILE_SECONDS 120.0
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

/* A growing string for the generated sources. */
typedef struct text {
    char *data;
    size_t length, capacity;
    int failed;
} text;

static void append(text *t, const char *format, ...) GRADE_PRINTF(2, 3);

static void append(text *t, const char *format, ...)
{
    va_list args;
    int n;
    if (t->failed)
        return;
    for (;;) {
        size_t room = t->capacity - t->length;
        va_start(args, format);
        n = vsnprintf(t->data != NULL ? t->data + t->length : NULL, room,
                      format, args);
        va_end(args);
        if (n < 0) {
            t->failed = 1;
            return;
        }
        if ((size_t)n < room) {
            t->length += (size_t)n;
            return;
        }
        if (t->capacity > ((size_t)-1) / 2 - (size_t)n - 256) {
            t->failed = 1;
            return;
        }
        {
            size_t capacity = t->capacity * 2 + (size_t)n + 256;
            char *grown = realloc(t->data, capacity);
            if (grown == NULL) {
                t->failed = 1;
                return;
            }
            t->data = grown;
            t->capacity = capacity;
        }
    }
}

/* Runs the compiler (trusted, in the current directory) on argv words. */
static rayo_status run_cc(grade_context *ctx, const char *const *words,
                          size_t count, int *ok, char **errors,
                          rayo_error *err)
{
    char **argv = grade_cc_argv(ctx, words, count);
    char *out = grade_path_join(ctx->dir, "probe.out");
    char *errpath = grade_path_join(ctx->dir, "probe.err");
    grade_limits limits = grade_compiler_limits(ctx->options,
                                                COMPILE_SECONDS);
    grade_outcome outcome;
    size_t size;
    rayo_status status;
    *errors = NULL;
    if (argv == NULL || out == NULL || errpath == NULL)
        status = rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
    else
        status = grade_process_run(argv, environ, ".", out, errpath, &limits,
                                   1, &outcome, err);
    if (status == RAYO_OK)
        status = grade_read_file(errpath, 1u << 20, errors, &size, err);
    if (status == RAYO_OK)
        *ok = outcome.ending == GRADE_EXITED && outcome.status == 0;
    free(argv);
    free(out);
    free(errpath);
    return status;
}

/* The compiler's first "error: " message, without the file position. */
static void first_error(const char *errors, char *out, size_t room)
{
    const char *p = strstr(errors, "error: ");
    size_t n;
    if (p == NULL) {
        snprintf(out, room, "the compiler refused it");
        return;
    }
    p += 7;
    n = strcspn(p, "\n");
    snprintf(out, room, "%.*s", (int)n, p);
}

/* Probes count functions against every source: 1 when no source
   conflicts with the assignment's prototypes; else why, in reason. */
static rayo_status probe(grade_context *ctx, const function_spec *f,
                         size_t count, int *ok, char *reason, size_t room,
                         rayo_error *err)
{
    char *path = grade_path_join(ctx->dir, "probe.c");
    size_t i;
    rayo_status status = RAYO_OK;
    *ok = 1;
    if (path == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
    for (i = 0; i < ctx->source_count && *ok && status == RAYO_OK; i++) {
        text t = {NULL, 0, 0, 0};
        char *errors = NULL;
        const char *words[6];
        size_t k;
        for (k = 0; k < count; k++)
            append(&t, "%s;\n", f[k].prototype);
        append(&t, "#include \"%s\"\n", ctx->absolute[i]);
        if (t.failed) {
            free(t.data);
            status = rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
            break;
        }
        status = grade_write_file(path, t.data, err);
        free(t.data);
        words[0] = "-std=c99";
        words[1] = "-w";
        words[2] = "-fsyntax-only";
        words[3] = path;
        if (status == RAYO_OK)
            status = run_cc(ctx, words, 4, ok, &errors, err);
        if (status == RAYO_OK && !*ok)
            first_error(errors, reason, room);
        free(errors);
    }
    free(path);
    return status;
}

static void write_call(text *t, const function_spec *f, unsigned c)
{
    double args[MAX_ARGS];
    unsigned i;
    case_args(f, c, args);
    append(t, "    printf(\"call %s %u\\n\");\n    fflush(stdout);\n",
           f->name, c);
    append(t, "    printf(\"result %s %u %%.9g\\n\", (double)%s(", f->name, c,
           f->name);
    for (i = 0; i < f->arg_count; i++)
        append(t, "%s(float)%.9g", i > 0 ? ", " : "", args[i]);
    append(t, "));\n    fflush(stdout);\n");
}

/* The harness source for the functions marked usable. */
static char *harness_source(const int *usable)
{
    text t = {NULL, 0, 0, 0};
    size_t i;
    unsigned c;
    append(&t, "#include <stdio.h>\n");
    for (i = 0; i < FUNCTION_COUNT; i++)
        if (usable[i])
            append(&t, "%s %s%s __attribute__((weak));\n",
                   ej1_functions[i].returns_int ? "int" : "float",
                   ej1_functions[i].name, ej1_functions[i].types);
    append(&t, "int main(void)\n{\n");
    for (i = 0; i < FUNCTION_COUNT; i++) {
        const function_spec *f = &ej1_functions[i];
        if (!usable[i])
            continue;
        append(&t, "    if (%s == 0) {\n        printf(\"missing %s\\n\");"
                   "\n    } else {\n",
               f->name, f->name);
        for (c = 0; c < f->case_count; c++)
            write_call(&t, f, c);
        append(&t, "    }\n");
    }
    append(&t, "    return 0;\n}\n");
    if (t.failed) {
        free(t.data);
        return NULL;
    }
    return t.data;
}

/* Compiles each source with main renamed, then the harness with them. */
static rayo_status build_harness(grade_context *ctx, const int *usable,
                                 int *ok, char **errors, rayo_error *err)
{
    char *source = harness_source(usable);
    char *harness_c = grade_path_join(ctx->dir, "harness.c");
    char *harness = grade_path_join(ctx->dir, "harness");
    const char **words = malloc((ctx->source_count + 8) * sizeof *words);
    char **objects = calloc(ctx->source_count + 1, sizeof *objects);
    size_t i, n;
    rayo_status status = RAYO_OK;
    *ok = 1;
    *errors = NULL;
    if (source == NULL || harness_c == NULL || harness == NULL ||
        words == NULL || objects == NULL)
        status = rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
    if (status == RAYO_OK)
        status = grade_write_file(harness_c, source, err);
    for (i = 0; i < ctx->source_count && status == RAYO_OK && *ok; i++) {
        char name[32];
        snprintf(name, sizeof name, "student%zu.o", i);
        objects[i] = grade_path_join(ctx->dir, name);
        if (objects[i] == NULL) {
            status = rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
            break;
        }
        words[0] = "-std=c99";
        words[1] = "-w";
        words[2] = "-Dmain=rayo_student_main";
        words[3] = "-c";
        words[4] = "-o";
        words[5] = objects[i];
        words[6] = ctx->sources[i];
        free(*errors);
        status = run_cc(ctx, words, 7, ok, errors, err);
    }
    if (status == RAYO_OK && *ok) {
        n = 0;
        words[n++] = "-w";
        words[n++] = "-o";
        words[n++] = harness;
        words[n++] = harness_c;
        for (i = 0; i < ctx->source_count; i++)
            words[n++] = objects[i];
        words[n++] = "-lm";
        free(*errors);
        status = run_cc(ctx, words, n, ok, errors, err);
    }
    for (i = 0; objects != NULL && i < ctx->source_count; i++)
        free(objects[i]);
    free(objects);
    free(words);
    free(source);
    free(harness_c);
    free(harness);
    return status;
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
                         const char *log, int *right, rayo_error *err)
{
    rayo_grade_item *item = &ctx->report->items[RAYO_GRADE_FUNCTIONS];
    char key[64], call[256];
    unsigned c, wrong = 0;
    rayo_status status = RAYO_OK;
    snprintf(key, sizeof key, "missing %s\n", f->name);
    if (strstr(log, key) != NULL) {
        *right = 0;
        return grade_fail(item, err, "%s: not defined; the assignment asks "
                                     "for %s",
                          f->name, f->prototype);
    }
    for (c = 0; c < f->case_count && status == RAYO_OK; c++) {
        double args[MAX_ARGS], got, want;
        const char *line;
        case_args(f, c, args);
        want = expected(f, args);
        format_call(f, c, call, sizeof call);
        snprintf(key, sizeof key, "result %s %u ", f->name, c);
        line = strstr(log, key);
        if (line == NULL || sscanf(line + strlen(key), "%lf", &got) != 1) {
            /* The run ended inside or before this call: said elsewhere. */
            *right = 0;
            return RAYO_OK;
        }
        if (f->returns_int ? got == want : close_enough(got, want))
            continue;
        wrong++;
        if (f->returns_int)
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
    *right = wrong == 0;
    if (status == RAYO_OK && wrong == 0)
        status = grade_say(item, err, "%s: right on %u known inputs",
                           f->name, f->case_count);
    return status;
}

/* Names the call that crashed or hung, from the harness's announcements. */
static rayo_status judge_ending(grade_context *ctx, const char *log,
                                const grade_outcome *outcome,
                                rayo_error *err)
{
    rayo_grade_item *item = &ctx->report->items[RAYO_GRADE_FUNCTIONS];
    const char *last = NULL, *p = log;
    char name[64] = "", call[256] = "a function";
    unsigned c = 0;
    size_t i;
    if (outcome->ending == GRADE_EXITED && outcome->status == 0)
        return RAYO_OK;
    while ((p = strstr(p, "call ")) != NULL) {
        if (p == log || p[-1] == '\n')
            last = p;
        p++;
    }
    if (last != NULL && sscanf(last, "call %63s %u", name, &c) == 2)
        for (i = 0; i < FUNCTION_COUNT; i++)
            if (strcmp(ej1_functions[i].name, name) == 0 &&
                c < ej1_functions[i].case_count)
                format_call(&ej1_functions[i], c, call, sizeof call);
    if (outcome->ending == GRADE_TIMED_OUT)
        return grade_fail(item, err, "%s did not return within %g seconds",
                          call, ctx->options->timeout);
    if (outcome->ending == GRADE_SIGNALED)
        return grade_fail(item, err, "%s crashed: %s", call,
                          grade_signal_name(outcome->status));
    return grade_fail(item, err, "%s ended the program with exit status %d",
                      call, outcome->status);
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
                                    char reasons[][400], rayo_error *err)
{
    size_t i;
    rayo_status status = RAYO_OK;
    for (i = 0; i < FUNCTION_COUNT && status == RAYO_OK; i++)
        status = say_signature(ctx, i, reasons[i], err);
    return status;
}

static rayo_status run_harness(grade_context *ctx, const int *usable,
                               char reasons[][400], rayo_error *err)
{
    char *argv[2];
    char *out = grade_path_join(ctx->dir, "harness.out");
    char *errpath = grade_path_join(ctx->dir, "harness.err");
    grade_limits limits = grade_run_limits(ctx->options);
    grade_outcome outcome;
    char *log = NULL;
    size_t size, i;
    int right;
    rayo_status status = RAYO_OK;
    argv[0] = grade_path_join(ctx->dir, "harness");
    argv[1] = NULL;
    if (argv[0] == NULL || out == NULL || errpath == NULL)
        status = rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
    if (status == RAYO_OK)
        status = grade_process_run(argv, NULL, ctx->dir, out, errpath,
                                   &limits, 0, &outcome, err);
    if (status == RAYO_OK)
        status = grade_read_file(out, 1u << 20, &log, &size, err);
    for (i = 0; i < FUNCTION_COUNT && status == RAYO_OK; i++)
        status = usable[i] ? judge(ctx, &ej1_functions[i], log, &right, err)
                           : say_signature(ctx, i, reasons[i], err);
    if (status == RAYO_OK)
        status = judge_ending(ctx, log, &outcome, err);
    free(log);
    free(argv[0]);
    free(out);
    free(errpath);
    return status;
}

rayo_status grade_step_functions(grade_context *ctx, rayo_error *err)
{
    rayo_grade_item *item = &ctx->report->items[RAYO_GRADE_FUNCTIONS];
    int usable[FUNCTION_COUNT], any = 0, ok;
    char reasons[FUNCTION_COUNT][400];
    char *errors = NULL;
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
        status = build_harness(ctx, usable, &ok, &errors, err);
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
    free(errors);
    return status;
}
