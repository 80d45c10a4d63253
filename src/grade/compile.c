/*
 * compile.c - the first criterion: the submission compiles with the
 * course's flags, `cc -std=c99 -Wall -Werror -pedantic ... -lm`.
 *
 * The compiler is the user's own (trusted) and runs in the current
 * directory, so its messages name the files as the user typed them; only
 * the program it makes goes into the temporary directory.  -g is added
 * so valgrind can name lines; it changes no warning.  On failure the
 * first messages are quoted, and a warning that -Werror made fatal is
 * pointed out as such.
 */
#define _POSIX_C_SOURCE 200809L

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "grade_impl.h"

extern char **environ;

#define COMPILE_SECONDS 120.0
#define QUOTED_LINES 8

static const char *const course_flags[] = {"-std=c99", "-Wall", "-Werror",
                                           "-pedantic"};
#define COURSE_FLAGS (sizeof course_flags / sizeof course_flags[0])

/* The command as a student would type it, for the report. */
static rayo_status say_command(grade_context *ctx, rayo_grade_item *item,
                               rayo_error *err)
{
    char sources[400];
    size_t i, n = 0;
    sources[0] = '\0';
    for (i = 0; i < ctx->source_count && n < sizeof sources; i++)
        n += (size_t)snprintf(sources + n, sizeof sources - n, "%s%s",
                              i > 0 ? " " : "", ctx->sources[i]);
    return grade_say(item, err, "%s -std=c99 -Wall -Werror -pedantic -o "
                                "programa %s%s -lm",
                     ctx->cc[0], sources,
                     n >= sizeof sources ? "..." : "");
}

/* The text after "error: " on the first line that has it, or NULL. */
static const char *werror_hint(const char *text, size_t *length)
{
    const char *p = strstr(text, "[-Werror");
    const char *start;
    if (p == NULL)
        return NULL;
    start = p;
    while (start > text && start[-1] != '\n')
        start--;
    start = strstr(start, "error: ");
    if (start == NULL || start > p)
        return NULL;
    start += 7;
    *length = (size_t)(p - start);
    while (*length > 0 && start[*length - 1] == ' ')
        (*length)--;
    return start;
}

static rayo_status explain_failure(grade_context *ctx, const char *errors,
                                   const grade_outcome *outcome,
                                   rayo_error *err)
{
    rayo_grade_item *item = &ctx->report->items[RAYO_GRADE_COMPILE];
    size_t length = 0;
    const char *hint = werror_hint(errors, &length);
    rayo_status status;
    if (outcome->ending == GRADE_TIMED_OUT)
        status = grade_fail(item, err, "the compiler did not finish in "
                                       "%.0f seconds", COMPILE_SECONDS);
    else
        status = grade_fail(item, err, "does not compile with the course's "
                                       "flags; the compiler says:");
    if (status == RAYO_OK)
        status = grade_quote(item, errors, QUOTED_LINES, err);
    if (status == RAYO_OK && hint != NULL)
        status = grade_say(item, err, "a warning (%.*s) that -Werror turns "
                                      "into an error: the course requires "
                                      "code without warnings",
                           (int)length, hint);
    if (status == RAYO_OK)
        status = say_command(ctx, item, err);
    return status;
}

rayo_status grade_step_compile(grade_context *ctx, rayo_error *err)
{
    rayo_grade_item *item = &ctx->report->items[RAYO_GRADE_COMPILE];
    size_t count = COURSE_FLAGS + 4 + ctx->source_count, i, n = 0;
    const char **words = malloc(count * sizeof *words);
    char *out = grade_path_join(ctx->dir, "cc.out");
    char *errpath = grade_path_join(ctx->dir, "cc.err");
    char **argv = NULL;
    char *errors = NULL;
    size_t size;
    grade_limits limits = grade_compiler_limits(ctx->options,
                                                COMPILE_SECONDS);
    grade_outcome outcome;
    rayo_status status = RAYO_ERR_NOMEM;

    {
        /* Found before forking: a failed exec looks different under
           debuggers and valgrind. */
        char *found = grade_which(ctx->cc[0]);
        if (found == NULL) {
            free(words);
            free(out);
            free(errpath);
            return grade_fail(item, err, "could not run the compiler '%s': "
                                         "not found or not executable (set "
                                         "CC or --cc)",
                              ctx->cc[0]);
        }
        free(found);
    }
    ctx->program = grade_path_join(ctx->dir, "programa");
    if (words == NULL || out == NULL || errpath == NULL ||
        ctx->program == NULL) {
        rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
        goto done;
    }
    for (i = 0; i < COURSE_FLAGS; i++)
        words[n++] = course_flags[i];
    words[n++] = "-g";
    words[n++] = "-o";
    words[n++] = ctx->program;
    for (i = 0; i < ctx->source_count; i++)
        words[n++] = ctx->sources[i];
    words[n++] = "-lm";
    argv = grade_cc_argv(ctx, words, n);
    if (argv == NULL) {
        rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
        goto done;
    }
    status = grade_process_run(argv, environ, ".", out, errpath, &limits, 1,
                               &outcome, err);
    if (status == RAYO_OK)
        status = grade_read_file(errpath, 1u << 20, &errors, &size, err);
    if (status != RAYO_OK)
        goto done;
    if (outcome.ending == GRADE_EXITED && outcome.status == 0) {
        item->result = RAYO_GRADE_PASS;
        status = say_command(ctx, item, err);
        if (status == RAYO_OK && errors[0] != '\0')
            status = grade_say(item, err, "warning: the compiler printed "
                                          "messages but succeeded:");
        if (status == RAYO_OK && errors[0] != '\0')
            status = grade_quote(item, errors, QUOTED_LINES, err);
    } else {
        free(ctx->program);
        ctx->program = NULL;
        status = explain_failure(ctx, errors, &outcome, err);
    }
done:
    free(errors);
    free(argv);
    free(words);
    free(out);
    free(errpath);
    return status;
}
