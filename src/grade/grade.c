/*
 * grade.c - rayo_grade: the steps in order, each filling its criterion,
 * and what a failed step means for the ones after it (nothing runs
 * that was not compiled; a program that did not finish has no output to
 * check; one that hung is not run again under valgrind).
 *
 * The reference is loaded before anything runs, so a bad --reference
 * is a usage error, not a failed grade; before that, the sandbox is
 * chosen (run/sandbox.c) and the report says how the submission is
 * isolated.  The temporary directory is removed on every path out.
 */
#define _XOPEN_SOURCE 700

#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "rayo/pbm_check.h"
#include "rayo/reader.h"

#include "grade_impl.h"
#include "rayo/lang.h"

/* Marks a reason for xgettext; skip looks it up in err's language. */
#define N_(text) text

void rayo_grade_options_init(rayo_grade_options *options)
{
    memset(options, 0, sizeof *options);
    options->exercise = rayo_grade_exercise_find("ej1");
    options->timeout = 10;
    options->cpu = 10;
    options->memory = (uint64_t)512 << 20;
    options->output_limit = (uint64_t)64 << 20;
    options->processes = 64;
    options->valgrind = 1;
    options->sandbox = RAYO_GRADE_SANDBOX_AUTO;
    options->disk = (uint64_t)256 << 20;
}

static void skip(grade_context *ctx, rayo_grade_criterion c,
                 const char *reason, rayo_error *err, rayo_status *status)
{
    rayo_grade_item *item = &ctx->report->items[c];
    if (*status != RAYO_OK || item->result != RAYO_GRADE_SKIPPED ||
        item->line_count > 0)
        return;
    *status = grade_say(item, err, "%s",
                        rayo_gettext(rayo_error_lang(err), reason));
}

/* Splits the compiler command on spaces ("gcc -m32" is two words). */
static rayo_status split_cc(grade_context *ctx, rayo_error *err)
{
    const char *cc = ctx->options->cc;
    char *copy, *word, *save = NULL;
    if (cc == NULL || cc[0] == '\0')
        cc = getenv("CC");
    if (cc == NULL || strspn(cc, " ") == strlen(cc))
        cc = "cc";
    copy = strdup(cc);
    ctx->cc = calloc(strlen(cc) / 2 + 2, sizeof *ctx->cc);
    if (copy == NULL || ctx->cc == NULL) {
        free(copy);
        return rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
    }
    for (word = strtok_r(copy, " ", &save); word != NULL;
         word = strtok_r(NULL, " ", &save))
        ctx->cc[ctx->cc_words++] = word;
    return RAYO_OK;
}

/* The sources' absolute names: the real path of each one's folder and
   its own name (the sandbox binds that folder there), and the names the
   compiler is given: as typed when, seen from the current directory,
   they lead to the same place, else the absolute one. */
static rayo_status absolute_sources(grade_context *ctx, rayo_error *err)
{
    size_t i;
    ctx->absolute = calloc(ctx->source_count, sizeof *ctx->absolute);
    ctx->compiled = calloc(ctx->source_count, sizeof *ctx->compiled);
    ctx->cwd = getcwd(NULL, 0);
    if (ctx->absolute == NULL || ctx->compiled == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
    if (ctx->cwd == NULL)
        return rayo_error_set(err, RAYO_ERR_IO, "grade: the current "
                                                "directory: %s",
                              strerror(errno));
    for (i = 0; i < ctx->source_count; i++) {
        const char *typed = ctx->sources[i];
        const char *slash = strrchr(typed, '/');
        const char *base = slash != NULL ? slash + 1 : typed;
        char *dir = slash == NULL ? strdup(".")
                    : slash == typed ? strdup("/")
                                     : strndup(typed, (size_t)(slash - typed));
        char *real = dir != NULL ? realpath(dir, NULL) : NULL;
        char *lexical;
        free(dir);
        if (real == NULL)
            return rayo_error_set(err, RAYO_ERR_IO, "%s: %s", typed,
                                  strerror(errno));
        ctx->absolute[i] = strcmp(real, "/") == 0
                               ? grade_concat("/", base)
                               : grade_path_join(real, base);
        free(real);
        if (ctx->absolute[i] == NULL)
            return rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
        lexical = typed[0] == '/' ? strdup(typed)
                                  : grade_path_join(ctx->cwd, typed);
        if (lexical == NULL)
            return rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
        ctx->compiled[i] = strcmp(lexical, ctx->absolute[i]) == 0
                               ? strdup(typed)
                               : strdup(ctx->absolute[i]);
        free(lexical);
        if (ctx->compiled[i] == NULL)
            return rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
    }
    return RAYO_OK;
}

/* Decides how the runs are isolated and says so in the report. */
static rayo_status choose_sandbox(grade_context *ctx, rayo_error *err)
{
    const rayo_grade_options *o = ctx->options;
    rayo_grade_report *r = ctx->report;
    r->isolated = rayo_grade_sandbox_check(o, r->isolation,
                                           sizeof r->isolation);
    if (o->sandbox == RAYO_GRADE_SANDBOX_OFF) {
        snprintf(r->isolation, sizeof r->isolation, "off");
        return RAYO_OK;
    }
    if (!r->isolated && o->sandbox == RAYO_GRADE_SANDBOX_REQUIRE)
        return rayo_error_set(err, RAYO_ERR_INVALID, "grade: --sandbox="
                                                     "require: %s",
                              r->isolation);
    if (r->isolated) {
        ctx->sandboxed = 1;
        ctx->bwrap = grade_which("bwrap");
        if (ctx->bwrap == NULL)
            return rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of "
                                                       "memory");
    }
    return RAYO_OK;
}

/* The program's folder inside the temporary directory. */
static rayo_status make_work(grade_context *ctx, rayo_error *err)
{
    ctx->work = grade_path_join(ctx->dir, "work");
    if (ctx->work == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
    if (mkdir(ctx->work, 0700) != 0)
        return rayo_error_set(err, RAYO_ERR_IO, "%s: %s", ctx->work,
                              strerror(errno));
    return RAYO_OK;
}

static rayo_status load_reference(const rayo_grade_options *o,
                                  rayo_image *reference, rayo_error *err)
{
    if (o->reference != NULL)
        return rayo_image_read_file(o->reference, reference, NULL, err);
    if (o->exercise->reference == NULL)
        return RAYO_OK;
    return o->exercise->reference(reference, err);
}

/* An output whose header promises far more pixels than the exercise's
   (or the reference's) is refused by that header, before the checker or
   a reader allocates and decodes it in the grader's own memory. */
static rayo_status refuse_huge(grade_context *ctx,
                               const rayo_image *reference, int *refused,
                               rayo_error *err)
{
    const rayo_grade_exercise *e = ctx->options->exercise;
    rayo_grade_report *r = ctx->report;
    grade_header h;
    uint64_t allowed = grade_pixels_allowed(e, reference);
    rayo_status status;
    *refused = 0;
    if (!grade_header_peek(ctx->output, ctx->output_size, &h) ||
        (h.width <= allowed && h.height <= allowed &&
         h.width * h.height <= allowed))
        return RAYO_OK;
    *refused = 1;
    status = grade_fail(&r->items[RAYO_GRADE_OUTPUT], err,
                        "the program printed a %llux%llu %s; the exercise "
                        "asks for a %s of %ux%u",
                        (unsigned long long)h.width,
                        (unsigned long long)h.height, h.format,
                        e->magic == '1'   ? "plain PBM"
                        : e->magic == '2' ? "plain PGM"
                                          : "plain PPM",
                        (unsigned)e->width, (unsigned)e->height);
    if (status == RAYO_OK)
        status = grade_say(&r->items[RAYO_GRADE_OUTPUT], err,
                           "it was not decoded: its header promises more "
                           "than %d times the exercise's %llu pixels",
                           GRADE_SIZE_MARGIN,
                           (unsigned long long)(allowed / GRADE_SIZE_MARGIN));
    if (status == RAYO_OK)
        status = grade_say(&r->items[RAYO_GRADE_IMAGE], err,
                           "not compared: the output's header promises an "
                           "image far larger than the exercise's, and it "
                           "was not decoded");
    return status;
}

/* The output criterion, and the pixels for the image criterion. */
static rayo_status check_output(grade_context *ctx,
                                const rayo_image *reference,
                                rayo_image *image, int *salvaged,
                                rayo_error *err)
{
    rayo_grade_item *item = &ctx->report->items[RAYO_GRADE_OUTPUT];
    int refused;
    rayo_status status = refuse_huge(ctx, reference, &refused, err);
    if (status != RAYO_OK || refused)
        return status;
    status = rayo_pnm_check(
        ctx->output, ctx->output_size, ctx->options->exercise->magic,
        ctx->options->exercise->width, ctx->options->exercise->height, item,
        image, err);
    *salvaged = item->result == RAYO_GRADE_FAIL;
    if (status != RAYO_OK || image->pixels != NULL || ctx->output_size == 0)
        return status;
    /* Not the plain format asked for: another the readers may know. */
    *salvaged = 0;
    if (rayo_image_read_memory(ctx->output, ctx->output_size, "the output",
                               image, NULL, NULL) != RAYO_OK)
        memset(image, 0, sizeof *image);
    return RAYO_OK;
}

static rayo_status run_steps(grade_context *ctx, const rayo_image *reference,
                             rayo_error *err)
{
    rayo_grade_report *report = ctx->report;
    rayo_image image;
    int salvaged = 0;
    rayo_status status;
    if (ctx->options->exercise->program != NULL)
        return grade_tp1_steps(ctx, err);
    status = grade_step_compile(ctx, err);
    memset(&image, 0, sizeof image);
    if (status != RAYO_OK || ctx->program == NULL)
        return status;
    status = grade_step_functions(ctx, err);
    if (status == RAYO_OK)
        status = grade_step_run(ctx, err);
    if (status == RAYO_OK && report->items[RAYO_GRADE_RUN].result ==
                                 RAYO_GRADE_PASS)
        status = check_output(ctx, reference, &image, &salvaged, err);
    if (status == RAYO_OK && image.pixels != NULL)
        status = grade_step_image(ctx, &image, reference, salvaged, err);
    else if (report->items[RAYO_GRADE_RUN].result == RAYO_GRADE_PASS)
        skip(ctx, RAYO_GRADE_IMAGE,
             N_("not compared: the output is not an image that can be read"),
             err, &status);
    rayo_image_free(&image);
    if (status == RAYO_OK && ctx->options->valgrind && !ctx->stopped)
        status = grade_step_valgrind(ctx, err);
    return status;
}

static void skip_the_rest(grade_context *ctx, rayo_error *err,
                          rayo_status *status)
{
    const rayo_grade_report *r = ctx->report;
    if (r->items[RAYO_GRADE_COMPILE].result != RAYO_GRADE_PASS) {
        skip(ctx, RAYO_GRADE_FUNCTIONS,
             N_("not checked: it did not compile"), err, status);
        skip(ctx, RAYO_GRADE_RUN, N_("not run: it did not compile"), err,
             status);
        skip(ctx, RAYO_GRADE_OUTPUT, N_("not checked: it did not compile"),
             err, status);
        skip(ctx, RAYO_GRADE_IMAGE, N_("not compared: it did not compile"),
             err, status);
        skip(ctx, RAYO_GRADE_VALGRIND, N_("not run: it did not compile"),
             err, status);
        return;
    }
    if (r->items[RAYO_GRADE_RUN].result != RAYO_GRADE_PASS)
        skip(ctx, RAYO_GRADE_OUTPUT,
             N_("not checked: the program did not run to the end"), err,
             status);
    skip(ctx, RAYO_GRADE_IMAGE,
         N_("not compared: the program did not run to the end"), err,
         status);
    if (!ctx->options->valgrind)
        skip(ctx, RAYO_GRADE_VALGRIND, N_("not run (--no-valgrind)"), err,
             status);
    else
        skip(ctx, RAYO_GRADE_VALGRIND,
             N_("not run: the program was stopped by a limit"), err, status);
}

rayo_status rayo_grade(const rayo_grade_options *options,
                       rayo_grade_report *report, rayo_error *err)
{
    grade_context ctx;
    rayo_image reference;
    rayo_status status;
    size_t i;
    memset(report, 0, sizeof *report);
    memset(&ctx, 0, sizeof ctx);
    memset(&reference, 0, sizeof reference);
    if (options->source_count == 0 || options->exercise == NULL ||
        !(options->timeout > 0) || !(options->cpu >= 0))
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "grade: no sources, no exercise or a "
                              "non-positive timeout");
    ctx.options = options;
    ctx.report = report;
    ctx.sources = options->sources;
    ctx.source_count = options->source_count;
    status = choose_sandbox(&ctx, err);
    if (status == RAYO_OK)
        status = load_reference(options, &reference, err);
    if (status == RAYO_OK)
        status = absolute_sources(&ctx, err);
    if (status == RAYO_OK)
        status = split_cc(&ctx, err);
    if (status == RAYO_OK)
        status = grade_tempdir_create(&ctx.dir, err);
    if (status == RAYO_OK)
        status = make_work(&ctx, err);
    if (status == RAYO_OK)
        status = run_steps(&ctx, &reference, err);
    if (status == RAYO_OK)
        skip_the_rest(&ctx, err, &status);
    grade_tempdir_remove(ctx.dir);
    for (i = 0; ctx.absolute != NULL && i < ctx.source_count; i++)
        free(ctx.absolute[i]);
    free(ctx.absolute);
    for (i = 0; ctx.compiled != NULL && i < ctx.source_count; i++)
        free(ctx.compiled[i]);
    free(ctx.compiled);
    free(ctx.cwd);
    free(ctx.work);
    free(ctx.bwrap);
    if (ctx.cc != NULL && ctx.cc_words > 0)
        free(ctx.cc[0]);
    free(ctx.cc);
    free(ctx.program);
    free(ctx.output);
    rayo_image_free(&reference);
    if (status != RAYO_OK)
        rayo_grade_report_free(report);
    return status;
}
