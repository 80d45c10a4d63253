/*
 * functions.c - the second criterion: the functions the exercise's
 * statement asks for have its exact signatures and return the right
 * values on inputs chosen to reveal the usual mistakes.
 *
 * Each exercise has its own cases (functions_ej1.c, functions_ej2.c,
 * functions_ej3.c) on the shared machinery of harness.c: probe the
 * signatures, build a harness around the student's objects, run it
 * under the program's limits, read its log.  This file chooses, and
 * when the criterion fails puts the lines that say what is wrong before
 * those of the functions that were right, so the report's first line
 * is a finding.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"

/* A line that reports a function right ("norma: right on 4 known
   inputs", "esfera_destruir: called on what esfera_crear returned"),
   not a finding: "NAME: " and then one of those. */
static int says_right(const char *line)
{
    const char *colon = strstr(line, ": ");
    if (colon == NULL || strchr(line, ' ') <= colon)
        return 0;
    return strncmp(colon, ": right on ", 11) == 0 ||
           strncmp(colon, ": called on what ", 17) == 0;
}

/* The lines that say a function was right become one, the last:
   "right on all their known inputs: norma (4), resta (2), ...,
   esfera_destruir (called on what esfera_crear returned)", so that the
   findings and notes come first and a long list of passing functions
   takes one line.  Left as they are when memory runs out. */
static void sum_up(rayo_grade_item *item)
{
    harness_text t = {NULL, 0, 0, 0};
    size_t i, n = 0, right = 0;
    for (i = 0; i < item->line_count; i++)
        right += says_right(item->lines[i]) != 0;
    if (right == 0)
        return;
    harness_append(&t, "right on all their known inputs: ");
    for (i = 0; i < item->line_count; i++) {
        const char *line = item->lines[i], *colon = strstr(line, ": ");
        unsigned cases;
        if (!says_right(line))
            continue;
        harness_append(&t, "%s%.*s", t.data[t.length - 2] == ':' ? "" : ", ",
                       (int)(colon - line), line);
        if (sscanf(colon, ": right on %u", &cases) == 1) {
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
        if (says_right(item->lines[i]))
            free(item->lines[i]);
        else
            item->lines[n++] = item->lines[i];
    }
    item->lines[n++] = t.data;
    item->line_count = n;
}

/* Stable: findings first, then the functions that were right. */
static void findings_first(rayo_grade_item *item)
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
        if (says_right(item->lines[i]))
            right[r++] = item->lines[i];
        else
            item->lines[n++] = item->lines[i];
    }
    memcpy(item->lines + n, right, r * sizeof *right);
    free(right);
}

rayo_status grade_step_functions(grade_context *ctx, rayo_error *err)
{
    rayo_status status;
    switch (ctx->options->exercise->course) {
    case RAYO_COURSE_EJ2:
        status = grade_functions_ej2(ctx, err);
        break;
    case RAYO_COURSE_EJ3:
        status = grade_functions_ej3(ctx, err);
        break;
    case RAYO_COURSE_EJ1:
    case RAYO_COURSE_EXERCISES:
    default:
        status = grade_functions_ej1(ctx, err);
        break;
    }
    if (status == RAYO_OK) {
        findings_first(&ctx->report->items[RAYO_GRADE_FUNCTIONS]);
        sum_up(&ctx->report->items[RAYO_GRADE_FUNCTIONS]);
    }
    return status;
}
