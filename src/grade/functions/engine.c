/*
 * engine.c - the second criterion: the functions the exercise's
 * statement asks for have its exact signatures and return the right
 * values on inputs chosen to reveal the usual mistakes.
 *
 * One engine for every exercise, each a table (table.h: ej1.c, ej2.c,
 * ej3.c): probe the signatures, build the exercise's harness around
 * the student's objects, write it its calls, run it under the
 * program's limits, judge each function from its log, say how the run
 * ended.  The functions that were right are summed up in one line after
 * the findings, so the report's first line is a finding.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rayo/lang.h"

#include "harness.h"
#include "table.h"

struct functions_right {
    const char *name, *maker; /* the table's names: static */
    unsigned cases;
};

rayo_status functions_right(grade_context *ctx, const char *name,
                            unsigned cases, const char *maker,
                            rayo_error *err)
{
    struct functions_right *grown =
        realloc(ctx->right, (ctx->right_count + 1) * sizeof *grown);
    if (grown == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
    ctx->right = grown;
    grown[ctx->right_count].name = name;
    grown[ctx->right_count].maker = maker;
    grown[ctx->right_count].cases = cases;
    ctx->right_count++;
    return RAYO_OK;
}

/* The functions that were right, in one line after the findings and
   notes: "right on all their known inputs: norma (4), resta (2), ...,
   esfera_destruir (called on what esfera_crear returned)", so that a
   long list of passing functions takes one line. */
static rayo_status sum_up(grade_context *ctx, rayo_grade_item *item,
                          rayo_error *err)
{
    rayo_lang lang = rayo_error_lang(err);
    harness_text t = {NULL, 0, 0, 0};
    size_t i;
    rayo_status status;
    if (ctx->right_count == 0)
        return RAYO_OK;
    harness_append(&t, "%s",
                   rayo_gettext(lang, "right on all their known inputs: "));
    for (i = 0; i < ctx->right_count; i++) {
        const struct functions_right *r = &ctx->right[i];
        if (i > 0)
            harness_append(&t, ", ");
        if (r->maker != NULL)
            harness_append(&t, rayo_gettext(lang, "%s (called on what %s "
                                                  "returned)"),
                           r->name, r->maker);
        else
            harness_append(&t, "%s (%u)", r->name, r->cases);
    }
    status = t.failed ? rayo_error_set(err, RAYO_ERR_NOMEM,
                                       "grade: out of memory")
                      : grade_say(item, err, "%s", t.data);
    free(t.data);
    return status;
}

const functions_exercise *functions_exercise_of(int course)
{
    switch (course) {
    case RAYO_COURSE_EJ2:
        return &functions_ej2;
    case RAYO_COURSE_EJ3:
        return &functions_ej3;
    default:
        return &functions_ej1;
    }
}

const functions_owner *functions_owner_at(size_t k)
{
    static const functions_exercise *const all[] = {
        &functions_ej1, &functions_ej2, &functions_ej3};
    size_t i;
    for (i = 0; i < sizeof all / sizeof all[0]; i++) {
        if (k < all[i]->owner_count)
            return &all[i]->owners[k];
        k -= all[i]->owner_count;
    }
    return NULL;
}

char *functions_calls(const functions_exercise *ex, const int *usable)
{
    harness_text t = {NULL, 0, 0, 0};
    size_t f;
    for (f = 0; f < ex->count; f++)
        if (usable[f])
            harness_append(&t, "u %s\n", ex->functions[f].name);
    for (f = 0; f < ex->count; f++)
        if (usable[f])
            harness_append(&t, "m %s\n", ex->functions[f].name);
    ex->write_calls(&t, usable);
    if (t.failed) {
        free(t.data);
        return NULL;
    }
    return t.data;
}

/* The engine's probe: every prototype against every source; when one
   fails, each on its own, its reason in reasons[f]. */
static rayo_status probe_prototypes(grade_context *ctx,
                                    const functions_exercise *ex,
                                    size_t first, size_t count, int *ok,
                                    char *reason, rayo_error *err)
{
    harness_text t = {NULL, 0, 0, 0};
    size_t i;
    rayo_status status = RAYO_OK;
    *ok = 1;
    if (ex->probe_before != NULL)
        harness_append(&t, "%s", ex->probe_before);
    for (i = first; i < first + count; i++)
        harness_append(&t, "%s;\n", ex->functions[i].prototype);
    if (t.failed) {
        free(t.data);
        return rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
    }
    for (i = 0; i < ctx->source_count && *ok && status == RAYO_OK; i++)
        status = harness_probe(ctx, i, t.data, "", ok, reason,
                               HARNESS_REASON, err);
    free(t.data);
    return status;
}

static rayo_status probe(grade_context *ctx, const functions_exercise *ex,
                         int *usable, char reasons[][HARNESS_REASON],
                         rayo_error *err)
{
    size_t f;
    int ok;
    rayo_status status = probe_prototypes(ctx, ex, 0, ex->count, &ok,
                                          reasons[0], err);
    for (f = 0; f < ex->count && status == RAYO_OK; f++) {
        usable[f] = 1;
        if (!ok)
            status = probe_prototypes(ctx, ex, f, 1, &usable[f], reasons[f],
                                      err);
    }
    return status;
}

static rayo_status say_signature(rayo_grade_item *item,
                                 const functions_exercise *ex, size_t f,
                                 const char *reason, rayo_error *err)
{
    if (ex->assignment)
        return grade_fail(item, err, "%s: the signature differs from the "
                                     "assignment's %s (the compiler says: "
                                     "%s); not called",
                          ex->functions[f].name, ex->functions[f].prototype,
                          reason);
    return grade_fail(item, err, "%s: the signature differs from the "
                                 "statement's %s (the compiler says: %s); "
                                 "not called",
                      ex->functions[f].name, ex->functions[f].prototype,
                      reason);
}

/* Builds the harness and runs it on its calls: *log (NULL when it was
   not run, the reason said). */
static rayo_status build_and_run(grade_context *ctx,
                                 const functions_exercise *ex,
                                 const int *usable, char **log,
                                 grade_outcome *outcome, rayo_error *err)
{
    rayo_grade_item *item = &ctx->report->items[RAYO_GRADE_FUNCTIONS];
    char *errors = NULL, *calls = functions_calls(ex, usable);
    int ok;
    rayo_status status = RAYO_OK;
    if (calls == NULL)
        status = rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
    if (status == RAYO_OK)
        status = harness_build(ctx, ex->harness, *ex->harness_size,
                               ex->link, ex->link_count, &ok, &errors, err);
    if (status == RAYO_OK && !ok) {
        status = grade_fail(item, err, "could not build the test harness "
                                       "around the functions:");
        if (status == RAYO_OK)
            status = grade_quote(item, errors, 4, err);
    } else if (status == RAYO_OK) {
        status = harness_run(ctx, calls, log, outcome, err);
    }
    free(errors);
    free(calls);
    return status;
}

rayo_status grade_step_functions(grade_context *ctx, rayo_error *err)
{
    const functions_exercise *ex =
        functions_exercise_of(ctx->options->exercise->course);
    rayo_grade_item *item = &ctx->report->items[RAYO_GRADE_FUNCTIONS];
    int usable[FUNCTIONS_MAX], any = 0;
    char (*reasons)[HARNESS_REASON] = calloc(FUNCTIONS_MAX, sizeof *reasons);
    char *log = NULL;
    grade_outcome outcome;
    size_t f;
    rayo_status status;
    if (reasons == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
    item->result = RAYO_GRADE_PASS;
    status = ex->probe != NULL ? ex->probe(ctx, usable, err)
                               : probe(ctx, ex, usable, reasons, err);
    for (f = 0; f < ex->count; f++)
        any |= usable[f];
    if (status == RAYO_OK && any)
        status = build_and_run(ctx, ex, usable, &log, &outcome, err);
    for (f = 0; f < ex->count && status == RAYO_OK; f++) {
        if (!usable[f] && ex->probe == NULL)
            status = say_signature(item, ex, f, reasons[f], err);
        else if (usable[f] && log != NULL)
            status = ex->judge(ctx, (unsigned)f, log, usable, err);
    }
    if (status == RAYO_OK && log != NULL)
        status = harness_judge_ending(ctx, log, &outcome, ex->describe, err);
    if (status == RAYO_OK)
        status = sum_up(ctx, item, err);
    free(ctx->right);
    ctx->right = NULL;
    ctx->right_count = 0;
    free(log);
    free(reasons);
    return status;
}
