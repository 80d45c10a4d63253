/*
 * engine.c - the second criterion: the functions the exercise's
 * statement asks for have its exact signatures and return the right
 * values on inputs chosen to reveal the usual mistakes.
 *
 * One engine for every exercise, each a table (table.h: ej1.c, ej2.c,
 * ej3.c): probe the signatures, build the exercise's harness around
 * the student's objects, write it its calls, run it under the
 * program's limits, judge each function from its log, say how the run
 * ended.  When the criterion fails, the lines that say what is wrong
 * come before those of the functions that were right, so the report's
 * first line is a finding.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rayo/lang.h"

#include "harness.h"
#include "table.h"

/* The words of a translated format between its first conversion (the
   function's name) and the next one: ": right on " in English. */
static size_t between(const char *format, const char **words)
{
    const char *start = strstr(format, "%s"), *end;
    if (start == NULL)
        return 0;
    start += 2;
    end = strchr(start, '%');
    *words = start;
    return end != NULL ? (size_t)(end - start) : 0;
}

/* A line that reports a function right ("norma: right on 4 known
   inputs", "esfera_destruir: called on what esfera_crear returned"),
   in the language of the report, not a finding: "NAME" and then the
   words of one of those formats; *cases receives the count of the
   first (0 for the second). */
static int says_right(rayo_lang lang, const char *line, unsigned *cases)
{
    const char *colon = strstr(line, ": "), *words;
    size_t n;
    if (colon == NULL || strchr(line, ' ') <= colon)
        return 0;
    n = between(rayo_gettext(lang, "%s: right on %u known inputs"), &words);
    if (n > 0 && strncmp(colon, words, n) == 0) {
        if (cases != NULL)
            *cases = (unsigned)strtoul(colon + n, NULL, 10);
        return 1;
    }
    n = between(rayo_gettext(lang, "%s: called on what %s returned "
                                   "(valgrind checks what it frees)"),
                &words);
    if (cases != NULL)
        *cases = 0;
    return n > 0 && strncmp(colon, words, n) == 0;
}

/* The lines that say a function was right become one, the last:
   "right on all their known inputs: norma (4), resta (2), ...,
   esfera_destruir (called on what esfera_crear returned)", so that the
   findings and notes come first and a long list of passing functions
   takes one line.  Left as they are when memory runs out. */
static void sum_up(rayo_lang lang, rayo_grade_item *item)
{
    harness_text t = {NULL, 0, 0, 0};
    size_t i, n = 0, right = 0;
    for (i = 0; i < item->line_count; i++)
        right += says_right(lang, item->lines[i], NULL) != 0;
    if (right == 0)
        return;
    harness_append(&t, "%s",
                   rayo_gettext(lang, "right on all their known inputs: "));
    for (i = 0; i < item->line_count; i++) {
        const char *line = item->lines[i], *colon = strstr(line, ": ");
        unsigned cases;
        if (!says_right(lang, line, &cases))
            continue;
        harness_append(&t, "%s%.*s", t.data[t.length - 2] == ':' ? "" : ", ",
                       (int)(colon - line), line);
        if (cases > 0) {
            harness_append(&t, " (%u)", cases);
        } else {
            const char *what = colon + 2;
            harness_append(&t, " (%.*s)", (int)strcspn(what, "("),
                           what);
            /* "called on what X returned " less its trailing space */
            if (t.length > 2 && t.data[t.length - 2] == ' ') {
                t.data[t.length - 2] = ')';
                t.data[--t.length] = '\0';
            }
        }
    }
    if (t.failed) {
        free(t.data);
        return;
    }
    for (i = 0; i < item->line_count; i++) {
        if (says_right(lang, item->lines[i], NULL))
            free(item->lines[i]);
        else
            item->lines[n++] = item->lines[i];
    }
    item->lines[n++] = t.data;
    item->line_count = n;
}

/* Stable: findings first, then the functions that were right. */
static void findings_first(rayo_lang lang, rayo_grade_item *item)
{
    size_t i, n = 0, r;
    char **right;
    if (item->result != RAYO_GRADE_FAIL || item->line_count < 2)
        return;
    right = malloc(item->line_count * sizeof *right);
    if (right == NULL)
        return; /* the order is a courtesy, not worth failing for */
    r = 0;
    for (i = 0; i < item->line_count; i++) {
        if (says_right(lang, item->lines[i], NULL))
            right[r++] = item->lines[i];
        else
            item->lines[n++] = item->lines[i];
    }
    memcpy(item->lines + n, right, r * sizeof *right);
    free(right);
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
    if (status == RAYO_OK) {
        findings_first(rayo_error_lang(err), item);
        sum_up(rayo_error_lang(err), item);
    }
    free(log);
    free(reasons);
    return status;
}
