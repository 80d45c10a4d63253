/*
 * run.c - the third criterion: the program runs to the end, with no
 * input, in the temporary directory, under the limits, and exits 0.
 *
 * What it wrote on standard output is kept for the output and image
 * criteria.  A program that writes its image to a file in its working
 * directory instead (fopen("imagen.pbm", "w")) is accepted too, with a
 * note, when it leaves exactly one .pbm/.pgm/.ppm/.pnm there.  What it
 * printed on standard error is quoted; it is not a fault.
 */
#define _POSIX_C_SOURCE 200809L

#include <dirent.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>

#include "grade_impl.h"

#define QUOTED_LINES 5

static int is_image_name(const char *name)
{
    static const char *const extensions[] = {".pbm", ".pgm", ".ppm", ".pnm"};
    size_t n = strlen(name), i;
    if (n < 5 || name[0] == '.')
        return 0;
    for (i = 0; i < 4; i++)
        if (strcmp(name + n - 4, extensions[i]) == 0)
            return 1;
    return 0;
}

/* The one image file the program left in dir, or NULL. */
static char *find_image_file(const char *dir)
{
    DIR *d = opendir(dir);
    struct dirent *entry;
    char *found = NULL;
    int count = 0;
    if (d == NULL)
        return NULL;
    while ((entry = readdir(d)) != NULL)
        if (is_image_name(entry->d_name) && count++ == 0)
            found = strdup(entry->d_name);
    closedir(d);
    if (count != 1) {
        free(found);
        return NULL;
    }
    return found;
}

static rayo_status say_ending(grade_context *ctx,
                              const grade_outcome *outcome,
                              rayo_error *err)
{
    const rayo_grade_options *o = ctx->options;
    rayo_grade_item *item = &ctx->report->items[RAYO_GRADE_RUN];
    if (outcome->ending == GRADE_TIMED_OUT)
        return grade_fail(item, err, "did not finish within %g s "
                                     "(wall clock) and was stopped: an "
                                     "infinite loop, or waiting for input "
                                     "that never comes?",
                          o->timeout);
    if (outcome->ending == GRADE_SIGNALED) {
        int sig = outcome->status;
        if (sig == SIGXCPU)
            return grade_fail(item, err, "used more than %g s of CPU time "
                                         "and was stopped: an infinite "
                                         "loop?",
                              o->cpu);
        if (sig == SIGXFSZ)
            return grade_fail(item, err, "wrote more than %llu bytes (the "
                                         "output limit) and was stopped: "
                                         "output in an endless loop?",
                              (unsigned long long)o->output_limit);
        return grade_fail(item, err, "crashed: %s%s", grade_signal_name(sig),
                          sig == SIGSEGV
                              ? "; an invalid pointer or an index out of "
                                "an array's bounds (valgrind may say where)"
                              : "");
    }
    if (outcome->status != 0)
        return grade_fail(item, err, "exited with status %d; main must "
                                     "return 0 when all went well",
                          outcome->status);
    item->result = RAYO_GRADE_PASS;
    return grade_say(item, err, "ran to the end in %.2f s and exited with "
                                "status 0",
                     outcome->seconds);
}

/* Takes the output from standard output, or from the file it wrote. */
static rayo_status collect_output(grade_context *ctx, rayo_error *err)
{
    char *path = grade_path_join(ctx->dir, "stdout");
    char *file = NULL;
    rayo_status status;
    if (path == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
    status = grade_read_file(path, ctx->options->output_limit, &ctx->output,
                             &ctx->output_size, err);
    free(path);
    if (status != RAYO_OK || ctx->output_size > 0)
        return status;
    file = find_image_file(ctx->dir);
    if (file == NULL)
        return RAYO_OK;
    path = grade_path_join(ctx->dir, file);
    if (path == NULL) {
        free(file);
        return rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
    }
    free(ctx->output);
    ctx->output = NULL;
    status = grade_read_file(path, ctx->options->output_limit, &ctx->output,
                             &ctx->output_size, err);
    if (status == RAYO_OK)
        status = grade_say(&ctx->report->items[RAYO_GRADE_RUN], err,
                           "warning: wrote nothing on standard output but "
                           "wrote the file '%s'; that file was checked",
                           file);
    free(path);
    free(file);
    return status;
}

grade_limits grade_compiler_limits(const rayo_grade_options *o,
                                   double seconds)
{
    grade_limits limits;
    memset(&limits, 0, sizeof limits);
    limits.wall = seconds;
    limits.cancelled = o->cancelled;
    limits.cancel_context = o->cancel_context;
    return limits;
}

grade_limits grade_run_limits(const rayo_grade_options *o)
{
    grade_limits limits = grade_compiler_limits(o, o->timeout);
    limits.cpu = o->cpu;
    limits.memory = o->memory;
    limits.file_size = o->output_limit;
    limits.processes = o->processes;
    return limits;
}

rayo_status grade_step_run(grade_context *ctx, rayo_error *err)
{
    rayo_grade_item *item = &ctx->report->items[RAYO_GRADE_RUN];
    char *argv[2];
    char *out = grade_path_join(ctx->dir, "stdout");
    char *errpath = grade_path_join(ctx->dir, "stderr");
    char *errors = NULL;
    size_t size;
    grade_limits limits = grade_run_limits(ctx->options);
    grade_outcome outcome;
    rayo_status status;
    argv[0] = ctx->program;
    argv[1] = NULL;
    if (out == NULL || errpath == NULL) {
        free(out);
        free(errpath);
        return rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
    }
    status = grade_process_run(argv, NULL, ctx->dir, out, errpath, &limits,
                               0, &outcome, err);
    if (status == RAYO_OK)
        status = say_ending(ctx, &outcome, err);
    ctx->stopped = outcome.ending == GRADE_TIMED_OUT ||
                   (outcome.ending == GRADE_SIGNALED &&
                    (outcome.status == SIGXCPU || outcome.status == SIGXFSZ ||
                     outcome.status == SIGKILL));
    if (status == RAYO_OK)
        status = grade_read_file(errpath, 1u << 20, &errors, &size, err);
    if (status == RAYO_OK && size > 0)
        status = grade_say(item, err, "it printed on standard error:");
    if (status == RAYO_OK && size > 0)
        status = grade_quote(item, errors, QUOTED_LINES, err);
    if (status == RAYO_OK && item->result == RAYO_GRADE_PASS)
        status = collect_output(ctx, err);
    free(errors);
    free(out);
    free(errpath);
    return status;
}
