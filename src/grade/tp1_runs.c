/*
 * tp1_runs.c - running a whole program as its statement says,
 * `./20212_tp1 ANCHO ALTO PROFUNDIDAD ARCHIVO`: once to a .ppm and once
 * to a .bmp at the exercise's size (161x121: 3 x 161 bytes is not a
 * multiple of 4, so the BMP's rows need padding) and depth 2; each file
 * checked against its format and the arguments, and the two against
 * each other (the same pixels).  Then with wrong arguments (none, three,
 * a word for the width): a usage line and a failing exit status, no
 * crash and no file.
 *
 * The program runs in the work folder that holds its build and STL
 * files (sandbox.c binds it).  Not where the formats are checked
 * (pnm_check.c, checks/bmp_check.c).
 */
#define _POSIX_C_SOURCE 200809L

#include <ctype.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "rayo/pbm_check.h"

#include "grade_impl.h"
#include "tp1.h"

#define QUOTED_LINES 4
#define DEPTH "2"

/* Runs the program with argv[1..] (argv[0] is set here). */
static rayo_status run(grade_context *ctx, char **argv, grade_captured *got,
                       rayo_error *err)
{
    grade_limits limits = grade_run_limits(ctx->options);
    grade_run r;
    argv[0] = ctx->program;
    memset(&r, 0, sizeof r);
    r.argv = argv;
    r.role = GRADE_ROLE_STUDENT;
    r.program = ctx->program;
    r.out_limit = 1u << 20;
    return grade_spawn(ctx, &r, &limits, got, err);
}

/* Says how a run that should have worked ended, when it did not. */
static rayo_status say_failed(grade_context *ctx, const char *file,
                              const grade_captured *got, rayo_error *err)
{
    rayo_grade_item *item = &ctx->report->items[RAYO_GRADE_RUN];
    const grade_outcome *o = &got->outcome;
    rayo_status status;
    if (got->memory_exceeded || o->ending == GRADE_TIMED_OUT)
        ctx->stopped = 1;
    if (got->memory_exceeded)
        status = grade_fail(item, err, "writing %s, it went past the memory "
                                       "limit and was killed",
                            file);
    else if (o->ending == GRADE_TIMED_OUT)
        status = grade_fail(item, err, "writing %s, it did not finish "
                                       "within %g seconds",
                            file, ctx->options->timeout);
    else if (o->ending == GRADE_SIGNALED)
        status = grade_fail(item, err, "writing %s, it crashed: %s",
                            file, grade_signal_name(o->status));
    else
        status = grade_fail(item, err, "writing %s, it exited with status %d",
                            file, o->status);
    if (status == RAYO_OK && got->errors_size > 0)
        status = grade_quote(item, got->errors, QUOTED_LINES, err);
    return status;
}

/* ./20212_tp1 W H 2 name, and the file it wrote (*data NULL when none). */
static rayo_status write_one(grade_context *ctx, const char *name,
                             char **data, size_t *size, rayo_error *err)
{
    const rayo_grade_exercise *e = ctx->options->exercise;
    char w[16], h[16];
    char *argv[6];
    char *path = grade_path_join(ctx->work, name);
    grade_captured got;
    struct stat st;
    rayo_status status;
    *data = NULL;
    *size = 0;
    if (path == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
    snprintf(w, sizeof w, "%lu", (unsigned long)e->width);
    snprintf(h, sizeof h, "%lu", (unsigned long)e->height);
    argv[1] = w;
    argv[2] = h;
    argv[3] = DEPTH;
    argv[4] = (char *)name;
    argv[5] = NULL;
    status = run(ctx, argv, &got, err);
    if (status == RAYO_OK) {
        if (got.outcome.ending != GRADE_EXITED || got.outcome.status != 0 ||
            got.memory_exceeded)
            status = say_failed(ctx, name, &got, err);
        else if (lstat(path, &st) != 0 || !S_ISREG(st.st_mode))
            status = grade_fail(&ctx->report->items[RAYO_GRADE_RUN], err,
                                "'%s %s %s %s %s' exited with status 0 but "
                                "wrote no file %s",
                                e->program, w, h, DEPTH, name, name);
        else
            status = grade_read_file(path, ctx->options->output_limit, data,
                                     size, err);
    }
    grade_captured_free(&got);
    free(path);
    return status;
}

/* Moves the lines of a check's own item into the output criterion. */
static rayo_status merge(rayo_grade_item *into, rayo_grade_item *from,
                         const char *file, rayo_error *err)
{
    size_t i;
    rayo_status status = RAYO_OK;
    for (i = 0; status == RAYO_OK && i < from->line_count; i++)
        status = file != NULL ? grade_say(into, err, "%s: %s", file,
                                          from->lines[i])
                              : grade_say(into, err, "%s", from->lines[i]);
    if (from->result == RAYO_GRADE_FAIL)
        into->result = RAYO_GRADE_FAIL;
    else if (into->result == RAYO_GRADE_SKIPPED)
        into->result = from->result;
    for (i = 0; i < from->line_count; i++)
        free(from->lines[i]);
    free(from->lines);
    memset(from, 0, sizeof *from);
    return status;
}

/* The pixel at x, y of an RGB image, with R and B swapped when swap,
   from the row at the other end when flip. */
static const unsigned char *pixel(const rayo_image *im, uint32_t x,
                                  uint32_t y, int flip)
{
    uint32_t row = flip ? im->info.height - 1 - y : y;
    return im->pixels + (size_t)row * im->stride + 3 * (size_t)x;
}

static size_t differ(const rayo_image *ppm, const rayo_image *bmp, int flip,
                     int swap, uint32_t *fx, uint32_t *fy)
{
    size_t count = 0;
    uint32_t x, y;
    for (y = 0; y < ppm->info.height; y++)
        for (x = 0; x < ppm->info.width; x++) {
            const unsigned char *a = pixel(ppm, x, y, 0);
            const unsigned char *b = pixel(bmp, x, y, flip);
            if (a[0] != b[swap ? 2 : 0] || a[1] != b[1] ||
                a[2] != b[swap ? 0 : 2]) {
                if (count++ == 0) {
                    *fx = x;
                    *fy = y;
                }
            }
        }
    return count;
}

/* The two files must be one picture. */
static rayo_status same_pixels(rayo_grade_item *item, const rayo_image *ppm,
                               const rayo_image *bmp, rayo_error *err)
{
    uint32_t x = 0, y = 0;
    size_t n;
    if (ppm->info.width != bmp->info.width ||
        ppm->info.height != bmp->info.height)
        return RAYO_OK;
    n = differ(ppm, bmp, 0, 0, &x, &y);
    if (n == 0)
        return grade_say(item, err, "tp1.ppm and tp1.bmp hold the same "
                                    "pixels");
    if (differ(ppm, bmp, 0, 1, &x, &y) == 0)
        return grade_fail(item, err, "tp1.bmp holds its pixels in R G B "
                                     "order; the course's BMP stores each "
                                     "pixel as B, G, R");
    if (differ(ppm, bmp, 1, 0, &x, &y) == 0)
        return grade_fail(item, err, "tp1.bmp is tp1.ppm upside down: its "
                                     "rows are stored top first under a "
                                     "positive height; the course's BMP "
                                     "stores the bottom row first");
    if (differ(ppm, bmp, 1, 1, &x, &y) == 0)
        return grade_fail(item, err, "tp1.bmp is tp1.ppm upside down and in "
                                     "R G B order; the course's BMP stores "
                                     "the bottom row first, each pixel as "
                                     "B, G, R");
    n = differ(ppm, bmp, 0, 0, &x, &y);
    return grade_fail(item, err, "tp1.ppm and tp1.bmp differ in %zu pixels, "
                                 "the first at column %lu, row %lu; both "
                                 "must be the same picture",
                      n, (unsigned long)x, (unsigned long)y);
}

/* Both files against their formats, the arguments and each other. */
static rayo_status check_files(grade_context *ctx, const char *ppm,
                               size_t ppm_size, const char *bmp,
                               size_t bmp_size, rayo_error *err)
{
    const rayo_grade_exercise *e = ctx->options->exercise;
    rayo_grade_item *item = &ctx->report->items[RAYO_GRADE_OUTPUT];
    rayo_grade_item own;
    rayo_image a, b;
    rayo_status status;
    memset(&own, 0, sizeof own);
    memset(&a, 0, sizeof a);
    memset(&b, 0, sizeof b);
    status = rayo_pnm_check(ppm, ppm_size, '3', e->width, e->height, &own, &a,
                            err);
    if (status == RAYO_OK)
        status = merge(item, &own, "tp1.ppm", err);
    if (status == RAYO_OK)
        status = grade_bmp_check(bmp, bmp_size, e->width, e->height,
                                 "tp1.bmp", &own, &b, err);
    if (status == RAYO_OK)
        status = merge(item, &own, NULL, err);
    if (status == RAYO_OK && a.pixels != NULL && b.pixels != NULL)
        status = same_pixels(item, &a, &b, err);
    if (status == RAYO_OK && item->result == RAYO_GRADE_PASS)
        status = grade_say(item, err, "tp1.ppm is a plain PPM and tp1.bmp a "
                                      "24-bit BMP of the course's layout, "
                                      "both %lux%lu as asked",
                           (unsigned long)e->width, (unsigned long)e->height);
    rayo_image_free(&a);
    rayo_image_free(&b);
    return status;
}

/* Whether text says "uso" or "usage", in any case. */
static int says_usage(const char *text)
{
    const char *p;
    for (p = text; p != NULL && *p != '\0'; p++)
        if ((tolower((unsigned char)p[0]) == 'u' &&
             tolower((unsigned char)p[1]) == 's') &&
            (tolower((unsigned char)p[2]) == 'o' ||
             (tolower((unsigned char)p[2]) == 'a' &&
              tolower((unsigned char)p[3]) == 'g' &&
              tolower((unsigned char)p[4]) == 'e')))
            return 1;
    return 0;
}

/* One run with wrong arguments: it must fail with a message, and when
   the count is wrong (usage), a usage line; it must write no file. */
static rayo_status wrong_arguments(grade_context *ctx, char **argv,
                                   const char *what, int usage,
                                   rayo_error *err)
{
    rayo_grade_item *item = &ctx->report->items[RAYO_GRADE_RUN];
    char *file = grade_path_join(ctx->work, "tp1_wrong.ppm");
    grade_captured got;
    struct stat st;
    rayo_status status;
    if (file == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
    status = run(ctx, argv, &got, err);
    if (status == RAYO_OK) {
        const char *said = got.errors_size > 0 ? got.errors : got.out;
        const grade_outcome *o = &got.outcome;
        if (o->ending == GRADE_SIGNALED)
            status = grade_fail(item, err, "run with %s, it crashed (%s); "
                                           "it must print a usage line and "
                                           "fail",
                                what, grade_signal_name(o->status));
        else if (o->ending != GRADE_EXITED || got.memory_exceeded)
            status = grade_fail(item, err, "run with %s, it did not end "
                                           "within the limits",
                                what);
        else if (o->status == 0)
            status = grade_fail(item, err, "run with %s, it exited with "
                                           "status 0; it must fail",
                                what);
        else if (said == NULL || said[0] == '\0')
            status = grade_fail(item, err, "run with %s, it failed without "
                                           "a word; it must say what is "
                                           "wrong",
                                what);
        else if (usage && !says_usage(got.out) && !says_usage(got.errors))
            status = grade_fail(item, err, "run with %s, it printed no "
                                           "usage line (such as 'Uso: "
                                           "./20212_tp1 [ancho] [alto] "
                                           "[profundidad] [nombrearchivo]')",
                                what);
        if (status == RAYO_OK && lstat(file, &st) == 0)
            status = grade_fail(item, err, "run with %s, it still wrote "
                                           "tp1_wrong.ppm",
                                what);
    }
    grade_captured_free(&got);
    if (file != NULL)
        unlink(file);
    free(file);
    return status;
}

static rayo_status usage_runs(grade_context *ctx, rayo_error *err)
{
    rayo_grade_item *item = &ctx->report->items[RAYO_GRADE_RUN];
    char *none[2] = {NULL, NULL};
    char *three[5] = {NULL, "161", "121", "2", NULL};
    char *word[6] = {NULL, "ancho", "121", "2", "tp1_wrong.ppm", NULL};
    size_t before = item->line_count;
    rayo_status status = wrong_arguments(ctx, none, "no arguments", 1, err);
    if (status == RAYO_OK && !ctx->stopped)
        status = wrong_arguments(ctx, three, "three arguments", 1, err);
    if (status == RAYO_OK && !ctx->stopped)
        status = wrong_arguments(ctx, word, "'ancho' for the width", 0, err);
    if (status == RAYO_OK && item->line_count == before)
        status = grade_say(item, err, "with no arguments, three, or a word "
                                      "for the width, it printed a message "
                                      "and failed");
    return status;
}

rayo_status grade_tp1_runs(grade_context *ctx, rayo_error *err)
{
    rayo_grade_report *r = ctx->report;
    const rayo_grade_exercise *e = ctx->options->exercise;
    char *ppm = NULL, *bmp = NULL;
    size_t ppm_size = 0, bmp_size = 0;
    rayo_status status = write_one(ctx, "tp1.ppm", &ppm, &ppm_size, err);
    if (status == RAYO_OK && !ctx->stopped)
        status = write_one(ctx, "tp1.bmp", &bmp, &bmp_size, err);
    if (status == RAYO_OK && ppm != NULL && bmp != NULL) {
        r->items[RAYO_GRADE_RUN].result = RAYO_GRADE_PASS;
        status = grade_say(&r->items[RAYO_GRADE_RUN], err,
                           "'%s %lu %lu %s tp1.ppm' and '... tp1.bmp' ran "
                           "to the end and wrote their files",
                           e->program, (unsigned long)e->width,
                           (unsigned long)e->height, DEPTH);
        if (status == RAYO_OK)
            status = check_files(ctx, ppm, ppm_size, bmp, bmp_size, err);
    }
    if (status == RAYO_OK && !ctx->stopped)
        status = usage_runs(ctx, err);
    free(ppm);
    free(bmp);
    return status;
}
