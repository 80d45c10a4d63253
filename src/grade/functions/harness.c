/*
 * harness.c - the shared machinery of the functions engine (harness.h):
 * growing texts, the compiler, probes, building the harness and reading
 * its log (its channel, the nonce and the forged lines, is
 * harness_channel.c's).  The exercises' cases and their expected values
 * live in their tables (ej1.c, ej2.c, ej3.c); nothing here knows a
 * function of the course.
 *
 * The compiler runs in the current directory (as the compile step's
 * does); the harness is the student's code and runs in the program's
 * folder under the program's limits; both in the sandbox when there is
 * one (run/process.c).
 */
#define _POSIX_C_SOURCE 200809L

#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "harness.h"
#include "harness_sources.h"

#define COMPILE_SECONDS 120.0
#define LOG_LIMIT (1u << 20)

void harness_append(harness_text *t, const char *format, ...)
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

void harness_numbers(harness_text *t, const double *v, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        harness_append(t, " %.9g", v[i]);
}

void harness_vector_record(harness_text *t, const char *name, unsigned k,
                           const double *a, const double *b,
                           const double *c, double s)
{
    harness_append(t, "c %s %u", name, k);
    harness_numbers(t, a, 3);
    harness_numbers(t, b, 3);
    harness_numbers(t, c, 3);
    harness_numbers(t, &s, 1);
    harness_append(t, "\n");
}

rayo_status harness_cc(grade_context *ctx, const char *const *words,
                       size_t count, int *ok, char **errors,
                       rayo_error *err)
{
    char **argv = grade_cc_argv(ctx, words, count);
    grade_limits limits = grade_compiler_limits(ctx->options,
                                                COMPILE_SECONDS);
    grade_run run;
    grade_captured got;
    rayo_status status;
    *errors = NULL;
    memset(&got, 0, sizeof got);
    memset(&run, 0, sizeof run);
    run.argv = argv;
    run.search = 1;
    run.role = GRADE_ROLE_TOOL;
    run.out_limit = LOG_LIMIT;
    if (argv == NULL)
        status = rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
    else
        status = grade_spawn(ctx, &run, &limits, &got, err);
    if (status == RAYO_OK) {
        *ok = got.outcome.ending == GRADE_EXITED && got.outcome.status == 0;
        *errors = got.errors != NULL ? got.errors : strdup("");
        got.errors = NULL;
        if (*errors == NULL)
            status = rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
    }
    grade_captured_free(&got);
    free(argv);
    return status;
}

void harness_clean(const char *in, size_t length, char *out, size_t room)
{
    static const char hex[] = "0123456789abcdef";
    size_t i, n = 0;
    if (room == 0)
        return;
    for (i = 0; i < length && in[i] != '\0' && n + 5 < room; i++) {
        unsigned char c = (unsigned char)in[i];
        if (c < 0x20 || c == 0x7f) {
            out[n++] = '\\';
            out[n++] = 'x';
            out[n++] = hex[c >> 4];
            out[n++] = hex[c & 15];
        } else {
            out[n++] = (char)c;
        }
    }
    out[n] = '\0';
}

int harness_not_finite(const char *call, const double *v, size_t n,
                       const char *nan_cause, const char *inf_cause,
                       char *out, size_t room)
{
    size_t i, nans = 0, infs = 0;
    char text[128];
    for (i = 0; i < n; i++) {
        nans += isnan(v[i]) != 0;
        infs += isinf(v[i]) != 0;
    }
    if (nans == 0 && infs == 0)
        return 0;
    if (inf_cause == NULL)
        inf_cause = "likely a division by 0";
    if (n == 1) {
        snprintf(text, sizeof text, "%g", v[0]);
        if (nans > 0)
            snprintf(out, room, "%s returned nan (not a number): likely %s",
                     call, nan_cause);
        else
            snprintf(out, room, "%s returned %s (infinity): %s", call, text,
                     inf_cause);
        return 1;
    }
    {
        char part[3][32];
        for (i = 0; i < 3; i++) {
            double x = i < n ? v[i] : 0;
            if (isnan(x))
                snprintf(part[i], sizeof part[i], "nan");
            else
                snprintf(part[i], sizeof part[i], "%.7g", x);
        }
        snprintf(text, sizeof text, "(%s, %s, %s)", part[0], part[1],
                 part[2]);
    }
    if (nans > 0)
        snprintf(out, room, "%s returned %s, with nan (not a number) in it: "
                            "likely %s",
                 call, text, nan_cause);
    else
        snprintf(out, room, "%s returned %s, with an infinity in it: %s",
                 call, text, inf_cause);
    return 1;
}

/* 1 when the quotes in text[0..n) are not all closed: ASCII ' and "
   taken as pairs, UTF-8 left and right single quotes matched. */
static int quotes_open(const char *text, size_t n)
{
    size_t i, single = 0, dbl = 0;
    long curly = 0;
    for (i = 0; i < n; i++) {
        if (text[i] == '\'')
            single++;
        else if (text[i] == '"')
            dbl++;
        else if (i + 2 < n + 0 && (unsigned char)text[i] == 0xe2 &&
                 (unsigned char)text[i + 1] == 0x80 &&
                 ((unsigned char)text[i + 2] == 0x98 ||
                  (unsigned char)text[i + 2] == 0x99))
            curly += (unsigned char)text[i + 2] == 0x98 ? 1 : -1;
    }
    return single % 2 != 0 || dbl % 2 != 0 || curly > 0;
}

void harness_shorten(char *text, size_t max)
{
    size_t n = strlen(text);
    if (n <= max || max < 8)
        return;
    n = max - 4; /* room for " ..." */
    while (n > 0 && ((unsigned char)text[n] & 0xC0) == 0x80)
        n--;
    /* Not in the middle of a word. */
    while (n > 0 && text[n] != ' ')
        n--;
    /* Nor inside quotes: back to the last space before an opening one
       until every quote kept is closed. */
    while (n > 0 && quotes_open(text, n)) {
        n--;
        while (n > 0 && text[n] != ' ')
            n--;
    }
    while (n > 0 && strchr(" ,;:(", text[n - 1]) != NULL)
        n--;
    memcpy(text + n, " ...", 5);
}

void harness_first_error(const char *errors, char *out, size_t room)
{
    const char *p = errors != NULL ? strstr(errors, "error: ") : NULL;
    char whole[2048];
    if (p == NULL) {
        snprintf(out, room, "the compiler refused it");
        return;
    }
    p += 7;
    harness_clean(p, strcspn(p, "\n"), whole, sizeof whole);
    if (room > 0)
        harness_shorten(whole, room - 1);
    snprintf(out, room, "%s", whole);
}

rayo_status harness_probe(grade_context *ctx, size_t i, const char *before,
                          const char *after, int *ok, char *reason,
                          size_t room, rayo_error *err)
{
    return harness_probe_full(ctx, i, before, after, ok, reason, room, NULL,
                              err);
}

/* The name a probe includes source i by: its absolute path, or, when
   that path holds a character that cannot stand in an #include's quotes
   (a quote, a newline, a backslash: a folder of a class's archive can
   hold any of them), a symbolic link to it beside the probe. */
static const char *include_name(const grade_context *ctx, size_t i,
                                char *name, size_t room)
{
    const char *path = ctx->absolute[i];
    char *link;
    if (strpbrk(path, "\"\\\n\r") == NULL)
        return path;
    snprintf(name, room, "source%zu.c", i);
    link = grade_path_join(ctx->dir, name);
    if (link == NULL)
        return path;
    unlink(link);
    if (symlink(path, link) != 0) {
        free(link);
        return path;
    }
    free(link);
    return name;
}

rayo_status harness_probe_full(grade_context *ctx, size_t i,
                               const char *before, const char *after,
                               int *ok, char *reason, size_t room,
                               char **messages, rayo_error *err)
{
    char *path = grade_path_join(ctx->dir, "probe.c");
    harness_text t = {NULL, 0, 0, 0};
    char *errors = NULL;
    const char *words[4];
    rayo_status status;
    *ok = 0;
    if (path == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
    char name[32];
    harness_append(&t, "%s#include \"%s\"\n%s", before,
                   include_name(ctx, i, name, sizeof name), after);
    if (t.failed)
        status = rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
    else
        status = grade_write_file(path, t.data, err);
    free(t.data);
    words[0] = "-std=c99";
    words[1] = "-w";
    words[2] = "-fsyntax-only";
    words[3] = path;
    if (status == RAYO_OK)
        status = harness_cc(ctx, words, 4, ok, &errors, err);
    if (status == RAYO_OK && !*ok)
        harness_first_error(errors, reason, room);
    if (messages != NULL)
        *messages = errors;
    else
        free(errors);
    free(path);
    return status;
}

void harness_previous_type(const char *errors, const char *name, char *out,
                           size_t room)
{
    const char *p = errors;
    size_t n = strlen(name);
    out[0] = '\0';
    while (p != NULL && (p = strstr(p, "previous ")) != NULL) {
        const char *line_end = strchr(p, '\n'), *type;
        const char *at = strstr(p, name);
        p += 9;
        if (at == NULL || (line_end != NULL && at > line_end))
            continue;
        type = strstr(at + n, " with type ");
        if (type == NULL || (line_end != NULL && type > line_end))
            continue;
        type += 11;
        /* The type between quotes of any kind (ASCII or UTF-8). */
        while (*type != '\0' && *type != '\n' &&
               !isalpha((unsigned char)*type) && *type != '_')
            type++;
        {
            size_t length = line_end != NULL ? (size_t)(line_end - type)
                                             : strlen(type);
            while (length > 0 && !isalnum((unsigned char)type[length - 1]) &&
                   strchr(")*]", type[length - 1]) == NULL)
                length--;
            char whole[1024];
            harness_clean(type, length, whole, sizeof whole);
            if (room > 0)
                harness_shorten(whole, room - 1);
            snprintf(out, room, "%s", whole);
        }
        return;
    }
}

/* An embedded source into path, as a C string. */
static rayo_status write_bytes(const char *path, const unsigned char *bytes,
                               size_t size, rayo_error *err)
{
    char *text = malloc(size + 1);
    rayo_status status;
    if (text == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
    memcpy(text, bytes, size);
    text[size] = '\0';
    status = grade_write_file(path, text, err);
    free(text);
    return status;
}

rayo_status harness_build(grade_context *ctx, const unsigned char *source,
                          size_t size, const char *const *extra,
                          size_t extra_count, int *ok, char **errors,
                          rayo_error *err)
{
    char *harness_c = grade_path_join(ctx->dir, "harness.c");
    char *header = grade_path_join(ctx->dir, "rayo_harness.h");
    char *harness = grade_path_join(ctx->dir, "harness");
    const char **words =
        malloc((ctx->source_count + extra_count + 8) * sizeof *words);
    char **objects = calloc(ctx->source_count + 1, sizeof *objects);
    size_t i, n;
    rayo_status status = RAYO_OK;
    *ok = 1;
    *errors = NULL;
    if (harness_c == NULL || header == NULL || harness == NULL ||
        words == NULL || objects == NULL)
        status = rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
    if (status == RAYO_OK)
        status = write_bytes(harness_c, source, size, err);
    if (status == RAYO_OK)
        status = write_bytes(header, harness_rayo_harness_h,
                             harness_rayo_harness_h_size, err);
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
        words[6] = ctx->compiled != NULL ? ctx->compiled[i]
                                         : ctx->sources[i];
        free(*errors);
        status = harness_cc(ctx, words, 7, ok, errors, err);
    }
    if (status == RAYO_OK && *ok) {
        n = 0;
        words[n++] = "-w";
        words[n++] = "-o";
        words[n++] = harness;
        words[n++] = harness_c;
        for (i = 0; i < ctx->source_count; i++)
            words[n++] = objects[i];
        for (i = 0; i < extra_count; i++)
            words[n++] = extra[i];
        words[n++] = "-lm";
        free(*errors);
        status = harness_cc(ctx, words, n, ok, errors, err);
    }
    for (i = 0; objects != NULL && i < ctx->source_count; i++)
        free(objects[i]);
    free(objects);
    free(words);
    free(harness_c);
    free(header);
    free(harness);
    return status;
}

/* The start of the line that begins with key, or NULL. */
static const char *line_with(const char *log, const char *key)
{
    const char *p = log;
    size_t n = strlen(key);
    while (p != NULL && (p = strstr(p, key)) != NULL) {
        if (p == log || p[-1] == '\n')
            return p + n;
        p += n;
    }
    return NULL;
}

int harness_missing(const char *log, const char *name)
{
    char key[80];
    const char *p;
    snprintf(key, sizeof key, "missing %s", name);
    p = line_with(log, key);
    return p != NULL && (*p == '\n' || *p == '\0');
}

int harness_result_text(const char *log, const char *name, unsigned k,
                        char *out, size_t room)
{
    char key[80];
    const char *p;
    size_t n;
    snprintf(key, sizeof key, "result %s %u ", name, k);
    p = line_with(log, key);
    if (p == NULL || room == 0)
        return 0;
    n = strcspn(p, "\n");
    if (n >= room)
        n = room - 1;
    memcpy(out, p, n);
    out[n] = '\0';
    return 1;
}

int harness_result(const char *log, const char *name, unsigned k,
                   double *values, int max)
{
    char line[512], *p, *end;
    int count = 0;
    if (!harness_result_text(log, name, k, line, sizeof line))
        return -1;
    p = line;
    while (count < max) {
        double v = strtod(p, &end);
        if (end == p)
            break;
        values[count++] = v;
        p = end;
    }
    return count;
}

rayo_status harness_judge_ending(grade_context *ctx, const char *log,
                                 const grade_outcome *outcome,
                                 harness_describe describe, rayo_error *err)
{
    rayo_grade_item *item = &ctx->report->items[RAYO_GRADE_FUNCTIONS];
    const char *last = NULL, *p = log;
    char name[64] = "", call[512] = "a function";
    unsigned c = 0;
    if (outcome->ending == GRADE_EXITED && outcome->status == 0)
        return RAYO_OK;
    while (p != NULL && (p = strstr(p, "call ")) != NULL) {
        if (p == log || p[-1] == '\n')
            last = p;
        p++;
    }
    if (last != NULL && sscanf(last, "call %63s %u", name, &c) == 2)
        describe(name, c, rayo_error_lang(err), call, sizeof call);
    if (outcome->ending == GRADE_TIMED_OUT)
        return grade_fail(item, err, "%s did not return within %g seconds",
                          call, ctx->options->timeout);
    if (outcome->ending == GRADE_SIGNALED)
        return grade_fail(item, err, "%s crashed: %s", call,
                          grade_signal_name(outcome->status));
    if (outcome->status == HARNESS_EXITED_EARLY)
        return grade_fail(item, err, "%s ended the program (exit status 0) "
                                     "before the other calls were made: a "
                                     "function returns to its caller, it "
                                     "does not call exit",
                          call);
    return grade_fail(item, err, "%s ended the program with exit status %d",
                      call, outcome->status);
}
