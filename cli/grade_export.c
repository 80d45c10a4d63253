/*
 * grade_export.c - CSV and Gradescope results of a grading (see
 * grade_export.h).
 *
 * Every text in them can come from a submission (a compiler's quote of
 * its line, its output) or from a class archive (a folder's name), so it
 * goes out as the text report shows it: control bytes escaped (\r, \x1b,
 * ...), each line cut at LINE_MAX bytes.  In CSV a cell that would begin
 * with = + - or @ gets a leading apostrophe, so a spreadsheet shows it as
 * text instead of running it as a formula (OWASP's "CSV injection").
 */
#define _POSIX_C_SOURCE 200809L

#include "grade_export.h"

#include <stdlib.h>
#include <string.h>

#include "cli.h"

#define LINE_MAX_BYTES 1000 /* one quoted line, escaped */
#define CELL_MAX_BYTES 4000 /* one CSV cell */

void cli_grade_points_default(cli_grade_points *points)
{
    static const double defaults[RAYO_GRADE_CRITERIA] = {10, 20, 10,
                                                         10, 40, 10};
    memcpy(points->points, defaults, sizeof defaults);
    points->given = 0;
}

/* The criterion called name (length n), or -1. */
static int criterion_named(const char *name, size_t n)
{
    int c;
    for (c = 0; c < RAYO_GRADE_CRITERIA; c++) {
        const char *known = rayo_grade_criterion_name(c);
        if (strlen(known) == n && strncmp(known, name, n) == 0)
            return c;
    }
    return -1;
}

int cli_grade_points_parse(const char *text, cli_grade_points *points)
{
    const char *s = text;
    cli_grade_points parsed = *points;
    for (;;) {
        const char *equals = strchr(s, '='), *end = strchr(s, ',');
        char value[32];
        double number;
        size_t length;
        int c;
        if (end == NULL)
            end = s + strlen(s);
        if (equals == NULL || equals > end)
            return cli_usage_error(_("--points: %s is not NAME=POINTS; "
                                     "expected e.g. image=50,valgrind=0"),
                                   cli_quote(text));
        c = criterion_named(s, (size_t)(equals - s));
        if (c < 0)
            return cli_usage_error(_("--points: '%.*s' is not a criterion; "
                                     "expected compile, functions, run, "
                                     "output, image or valgrind"),
                                   (int)(equals - s), s);
        length = (size_t)(end - equals - 1);
        if (length == 0 || length >= sizeof value)
            return cli_usage_error(_("--points: %s's points '%.*s' are not a "
                                     "number from 0 to 1000"),
                                   rayo_grade_criterion_name(c), (int)length,
                                   equals + 1);
        memcpy(value, equals + 1, length);
        value[length] = '\0';
        if (!cli_parse_double("--points", value, &number))
            return CLI_EXIT_USAGE;
        if (!(number >= 0 && number <= 1000))
            return cli_usage_error(_("--points: %s's points %s are out of "
                                     "range; expected 0 to 1000"),
                                   rayo_grade_criterion_name(c),
                                   cli_quote(value));
        parsed.points[c] = number;
        parsed.given |= 1u << c;
        if (*end == '\0')
            break;
        s = end + 1;
    }
    *points = parsed;
    return CLI_EXIT_OK;
}

double cli_grade_score(const rayo_grade_report *report,
                       const cli_grade_points *points, double *max)
{
    double score = 0, total = 0;
    int c;
    for (c = 0; c < RAYO_GRADE_CRITERIA; c++) {
        total += points->points[c];
        if (report != NULL && report->items[c].result == RAYO_GRADE_PASS)
            score += points->points[c];
    }
    if (max != NULL)
        *max = total;
    return score;
}

/* ---- CSV ---- */

/* Appends s, escaped, to the cell (at most CELL_MAX_BYTES). */
static void cell_append(char *cell, size_t *used, const char *s)
{
    while (*s != '\0') {
        char text[8];
        size_t columns, n = cli_escape_unit(s, 0, text, &columns);
        size_t length = strlen(text);
        if (*used + length > CELL_MAX_BYTES) {
            memcpy(cell + *used, "...", 3);
            *used += 3;
            cell[*used] = '\0';
            return;
        }
        memcpy(cell + *used, text, length);
        *used += length;
        s += n;
    }
    cell[*used] = '\0';
}

/* A cell, quoted: "" for a quote, an apostrophe before a formula. */
static void csv_cell(FILE *stream, const char *cell)
{
    fputc('"', stream);
    if (strchr("=+-@", cell[0]) != NULL && cell[0] != '\0')
        fputc('\'', stream);
    for (; *cell != '\0'; cell++) {
        if (*cell == '"')
            fputc('"', stream);
        fputc(*cell, stream);
    }
    fputc('"', stream);
}

static void csv_text(FILE *stream, const char *s)
{
    char cell[CELL_MAX_BYTES + 4];
    size_t used = 0;
    cell_append(cell, &used, s);
    csv_cell(stream, cell);
}

/* The reason lines, joined by " | ". */
static void csv_reasons(FILE *stream, const rayo_grade_item *item)
{
    char cell[CELL_MAX_BYTES + 4];
    size_t used = 0, i;
    cell[0] = '\0';
    for (i = 0; i < item->line_count && used < CELL_MAX_BYTES; i++) {
        if (i > 0 && used + 3 <= CELL_MAX_BYTES) {
            memcpy(cell + used, " | ", 4);
            used += 3;
        }
        cell_append(cell, &used, item->lines[i]);
    }
    csv_cell(stream, cell);
}

void cli_grade_csv_header(FILE *stream)
{
    int c;
    fputs("student,result,score,max_score", stream);
    for (c = 0; c < RAYO_GRADE_CRITERIA; c++)
        fprintf(stream, ",%s,%s_reason", rayo_grade_criterion_name(c),
                rayo_grade_criterion_name(c));
    fputs(",error\r\n", stream);
}

void cli_grade_csv_row(FILE *stream, const char *student,
                       const rayo_grade_report *report,
                       const char *error_message,
                       const cli_grade_points *points)
{
    double max, score = cli_grade_score(report, points, &max);
    int c;
    csv_text(stream, student);
    fprintf(stream, ",%s,%.10g,%.10g",
            report == NULL ? "error"
                           : rayo_grade_result_name(rayo_grade_overall(report)),
            score, max);
    for (c = 0; c < RAYO_GRADE_CRITERIA; c++) {
        if (report == NULL) {
            fputs(",,", stream);
            continue;
        }
        fprintf(stream, ",%s,",
                rayo_grade_result_name(report->items[c].result));
        csv_reasons(stream, &report->items[c]);
    }
    fputc(',', stream);
    if (report == NULL)
        csv_text(stream, error_message != NULL ? error_message : "");
    fputs("\r\n", stream);
}

/* ---- Gradescope ---- */

/* The reason lines as one JSON string, a line each. */
static void json_lines(FILE *stream, char **lines, size_t count)
{
    char *text = NULL;
    size_t size = 0, i;
    FILE *joined = open_memstream(&text, &size);
    if (joined == NULL) {
        cli_json_string(stream, "");
        return;
    }
    for (i = 0; i < count; i++) {
        if (i > 0)
            fputc('\n', joined);
        cli_put_escaped(joined, lines[i], 0, LINE_MAX_BYTES);
    }
    fclose(joined);
    cli_json_string(stream, text != NULL ? text : "");
    free(text);
}

void cli_grade_gradescope(FILE *stream, const rayo_grade_report *report,
                          const char *error_message,
                          const char *sandbox_note,
                          const cli_grade_points *points)
{
    double max, score = cli_grade_score(report, points, &max);
    int c, first = 1;
    fprintf(stream, "{\"score\": %.10g, \"output\": ", score);
    {
        char summary[1200];
        char *lines[2];
        lines[0] = summary;
        lines[1] = (char *)sandbox_note;
        if (report == NULL)
            snprintf(summary, sizeof summary,
                     _("rayo grade could not grade this submission: %s"),
                     error_message != NULL ? error_message : "");
        else
            snprintf(summary, sizeof summary, _("%s: %.10g of %.10g points"),
                     rayo_grade_overall(report) == RAYO_GRADE_PASS ? "PASS"
                                                                   : "FAIL",
                     score, max);
        json_lines(stream, lines, sandbox_note != NULL ? 2 : 1);
    }
    fputs(", \"tests\": [", stream);
    for (c = 0; report != NULL && c < RAYO_GRADE_CRITERIA; c++) {
        const rayo_grade_item *item = &report->items[c];
        double worth = points->points[c];
        if (worth == 0)
            continue;
        fprintf(stream, "%s\n  {\"name\": \"%s\", \"score\": %.10g, "
                "\"max_score\": %.10g, \"status\": \"%s\", \"output\": ",
                first ? "" : ",", rayo_grade_criterion_name(c),
                item->result == RAYO_GRADE_PASS ? worth : 0.0, worth,
                item->result == RAYO_GRADE_PASS ? "passed" : "failed");
        json_lines(stream, item->lines, item->line_count);
        fputc('}', stream);
        first = 0;
    }
    fputs(first ? "]}\n" : "\n]}\n", stream);
}
