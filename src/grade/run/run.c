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

#include <signal.h>
#include <stdlib.h>
#include <string.h>

#include "../grade_impl.h"
#include "rayo/lang.h"

#define QUOTED_LINES 5

static rayo_status say_ending(grade_context *ctx, const grade_captured *got,
                              rayo_error *err)
{
    const rayo_grade_options *o = ctx->options;
    const grade_outcome *outcome = &got->outcome;
    rayo_grade_item *item = &ctx->report->items[RAYO_GRADE_RUN];
    if (got->memory_exceeded)
        return grade_fail(item, err, "memory limit exceeded: its processes "
                                     "together used more than %llu MiB and "
                                     "the system stopped them",
                          (unsigned long long)(o->memory >> 20));
    if (outcome->ending == GRADE_TIMED_OUT)
        return grade_fail(item, err, "did not finish within %g s "
                                     "(wall clock) and was stopped: an "
                                     "infinite loop, or waiting for input "
                                     "that never comes?",
                          o->timeout);
    if (outcome->ending == GRADE_SIGNALED) {
        int sig = outcome->status;
        const char *name =
            rayo_gettext(rayo_error_lang(err), grade_signal_name(sig));
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
        if (sig == SIGSEGV)
            return grade_fail(item, err, "crashed: %s; an invalid pointer "
                                         "or an index out of an array's "
                                         "bounds (valgrind may say where)",
                              name);
        return grade_fail(item, err, "crashed: %s", name);
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
static rayo_status collect_output(grade_context *ctx, grade_captured *got,
                                  rayo_error *err)
{
    if (got->out_size > 0 || got->file_name == NULL) {
        ctx->output = got->out != NULL ? got->out : calloc(1, 1);
        ctx->output_size = got->out_size;
        got->out = NULL;
        if (ctx->output == NULL)
            return rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
        return RAYO_OK;
    }
    ctx->output = got->file;
    ctx->output_size = got->file_size;
    got->file = NULL;
    if (ctx->output == NULL) {
        ctx->output = calloc(1, 1);
        if (ctx->output == NULL)
            return rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
    }
    return grade_warn(&ctx->report->items[RAYO_GRADE_RUN], err,
                     "warning: wrote nothing on standard output but wrote "
                     "the file '%s'; that file was checked",
                     got->file_name);
}

/* The compiler's CPU time is at least this (a compile takes a fraction
   of it; a short --cpu for the program must not fail the compile). */
#define COMPILER_CPU 10.0

/* The limits every run shares: the tree's memory and processes (its
   cgroup), and per process the address space, file size, processes
   and descriptors. */
static grade_limits common_limits(const rayo_grade_options *o,
                                  double seconds)
{
    grade_limits limits;
    memset(&limits, 0, sizeof limits);
    limits.wall = seconds;
    limits.memory = o->memory;
    limits.tree_memory = o->memory;
    limits.file_size = o->output_limit;
    limits.processes = o->processes;
    limits.open_files = GRADE_OPEN_FILES;
    limits.cancelled = o->cancelled;
    limits.cancel_context = o->cancel_context;
    return limits;
}

grade_limits grade_compiler_limits(const rayo_grade_options *o,
                                   double seconds)
{
    grade_limits limits = common_limits(o, seconds);
    limits.cpu = o->cpu > COMPILER_CPU ? o->cpu : COMPILER_CPU;
    return limits;
}

grade_run grade_tool_run(char *const *argv)
{
    grade_run run;
    memset(&run, 0, sizeof run);
    run.argv = argv;
    run.search = 1;
    run.role = GRADE_ROLE_TOOL;
    run.out_limit = 1u << 20;
    return run;
}

grade_limits grade_run_limits(const rayo_grade_options *o)
{
    grade_limits limits = common_limits(o, o->timeout);
    limits.cpu = o->cpu;
    return limits;
}

rayo_status grade_step_run(grade_context *ctx, rayo_error *err)
{
    rayo_grade_item *item = &ctx->report->items[RAYO_GRADE_RUN];
    char *argv[2];
    grade_limits limits = grade_run_limits(ctx->options);
    grade_run run;
    grade_captured got;
    rayo_status status;
    argv[0] = ctx->program;
    argv[1] = NULL;
    memset(&run, 0, sizeof run);
    run.argv = argv;
    run.role = GRADE_ROLE_STUDENT;
    run.program = ctx->program;
    run.out_limit = ctx->options->output_limit;
    run.collect = 1;
    status = grade_spawn(ctx, &run, &limits, &got, err);
    if (status != RAYO_OK)
        return status;
    status = say_ending(ctx, &got, err);
    ctx->stopped = got.memory_exceeded ||
                   got.outcome.ending == GRADE_TIMED_OUT ||
                   (got.outcome.ending == GRADE_SIGNALED &&
                    (got.outcome.status == SIGXCPU ||
                     got.outcome.status == SIGXFSZ ||
                     got.outcome.status == SIGKILL));
    if (status == RAYO_OK && got.errors_size > 0)
        status = grade_say(item, err, "it printed on standard error:");
    if (status == RAYO_OK && got.errors_size > 0)
        status = grade_quote(item, got.errors, QUOTED_LINES, err);
    if (status == RAYO_OK && item->result == RAYO_GRADE_PASS)
        status = collect_output(ctx, &got, err);
    grade_captured_free(&got);
    return status;
}
