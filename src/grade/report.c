/*
 * report.c - the grader's report: reason lines added to a criterion,
 * names for criteria and results, the overall result, and freeing.
 *
 * Reasons are whole sentences for a student, looked up in the catalog
 * of err's language (rayo_error_lang: the caller's choice) and written
 * with its decimal separator; the command decides how to lay them out
 * (text or JSON) and escapes their control bytes.  Every
 * line is bounded here (a quoted line to 300 bytes, any line to 1000),
 * so a program that prints megabyte-long lines gets them cut.  Nothing
 * here knows what a criterion checks.
 */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "grade_impl.h"
#include "rayo/lang.h"

/* The most bytes a reason line keeps; longer ones are cut (at a UTF-8
   character boundary) and end with "...". */
#define LINE_BYTES 1000
/* The most bytes of one quoted line (a compiler message, the program's
   standard error). */
#define QUOTE_BYTES 300
/* A line is formatted into this much room first, then kept at its
   length; a longer one (a quoted line of megabytes) is cut by add_line. */
#define FORMAT_BYTES 4096

/* Where to cut text of length n to at most room bytes without splitting
   a UTF-8 sequence. */
static size_t cut_at(const char *text, size_t n, size_t room)
{
    if (n <= room)
        return n;
    while (room > 0 && ((unsigned char)text[room] & 0xC0) == 0x80)
        room--;
    return room;
}

static rayo_status add_line(rayo_grade_item *item, char *line,
                            rayo_error *err)
{
    char **grown;
    size_t n = strlen(line);
    if (n > LINE_BYTES) {
        size_t keep = cut_at(line, n, LINE_BYTES - 3);
        memcpy(line + keep, "...", 4);
    }
    if (item->line_count >= ((size_t)-1) / sizeof *grown - 1) {
        free(line);
        return rayo_error_set(err, RAYO_ERR_NOMEM, "grade: too many lines");
    }
    grown = realloc(item->lines, (item->line_count + 1) * sizeof *grown);
    if (grown == NULL) {
        free(line);
        return rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
    }
    item->lines = grown;
    item->lines[item->line_count++] = line;
    return RAYO_OK;
}

static rayo_status vsay(rayo_grade_item *item, rayo_error *err,
                        const char *format, va_list args) GRADE_PRINTF(3, 0);

static rayo_status vsay(rayo_grade_item *item, rayo_error *err,
                        const char *format, va_list args)
{
    char text[FORMAT_BYTES], *line;
    size_t n;
    rayo_lang_vformat(rayo_error_lang(err), text, sizeof text, format, args);
    n = strlen(text);
    line = malloc(n + 1);
    if (line == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
    memcpy(line, text, n + 1);
    return add_line(item, line, err);
}

rayo_status grade_say(rayo_grade_item *item, rayo_error *err,
                      const char *format, ...)
{
    rayo_status status;
    va_list args;
    va_start(args, format);
    status = vsay(item, err, format, args);
    va_end(args);
    return status;
}

rayo_status grade_fail(rayo_grade_item *item, rayo_error *err,
                       const char *format, ...)
{
    rayo_status status;
    va_list args;
    item->result = RAYO_GRADE_FAIL;
    va_start(args, format);
    status = vsay(item, err, format, args);
    va_end(args);
    return status;
}

rayo_status grade_warn(rayo_grade_item *item, rayo_error *err,
                       const char *format, ...)
{
    rayo_status status;
    va_list args;
    va_start(args, format);
    status = vsay(item, err, format, args);
    va_end(args);
    if (status == RAYO_OK)
        item->warnings++;
    return status;
}

/* A quoted line goes in as it is: it is the program's or a tool's text,
   never a message of the catalog. */
static rayo_status say_quoted(rayo_grade_item *item, const char *text,
                              size_t length, const char *more,
                              rayo_error *err)
{
    char *line = malloc(length + strlen(more) + 3);
    if (line == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
    memcpy(line, "  ", 2);
    memcpy(line + 2, text, length);
    strcpy(line + 2 + length, more);
    return add_line(item, line, err);
}

rayo_status grade_quote(rayo_grade_item *item, const char *text,
                        size_t max, rayo_error *err)
{
    size_t shown = 0, total = 0;
    const char *p = text;
    while (*p != '\0') {
        const char *end = strchr(p, '\n');
        size_t length = end != NULL ? (size_t)(end - p) : strlen(p);
        if (length > 0) {
            total++;
            if (shown < max) {
                size_t keep = cut_at(p, length, QUOTE_BYTES);
                rayo_status status = say_quoted(
                    item, p, keep, keep < length ? "..." : "", err);
                if (status != RAYO_OK)
                    return status;
                shown++;
            }
        }
        p += length;
        if (*p == '\n')
            p++;
    }
    if (total > shown)
        return grade_say(item, err,
                         rayo_ngettext(rayo_error_lang(err),
                                       "  ... (%zu more line)",
                                       "  ... (%zu more lines)",
                                       total - shown),
                         total - shown);
    return RAYO_OK;
}

const char *rayo_grade_criterion_name(rayo_grade_criterion criterion)
{
    switch (criterion) {
    case RAYO_GRADE_COMPILE: return "compile";
    case RAYO_GRADE_FUNCTIONS: return "functions";
    case RAYO_GRADE_RUN: return "run";
    case RAYO_GRADE_OUTPUT: return "output";
    case RAYO_GRADE_IMAGE: return "image";
    case RAYO_GRADE_VALGRIND: return "valgrind";
    case RAYO_GRADE_CRITERIA: break;
    }
    return "unknown";
}

const char *rayo_grade_result_name(rayo_grade_result result)
{
    switch (result) {
    case RAYO_GRADE_PASS: return "pass";
    case RAYO_GRADE_FAIL: return "fail";
    case RAYO_GRADE_SKIPPED: return "skipped";
    }
    return "unknown";
}

rayo_grade_result rayo_grade_overall(const rayo_grade_report *report)
{
    size_t i;
    for (i = 0; i < RAYO_GRADE_CRITERIA; i++)
        if (report->items[i].result == RAYO_GRADE_FAIL)
            return RAYO_GRADE_FAIL;
    return RAYO_GRADE_PASS;
}

void rayo_grade_report_free(rayo_grade_report *report)
{
    size_t i, j;
    if (report == NULL)
        return;
    for (i = 0; i < RAYO_GRADE_CRITERIA; i++) {
        for (j = 0; j < report->items[i].line_count; j++)
            free(report->items[i].lines[j]);
        free(report->items[i].lines);
    }
    free(report->verdict);
    memset(report, 0, sizeof *report);
}
