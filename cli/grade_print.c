/*
 * grade_print.c - one grading's report printed for a person (text, the
 * table's cells) or for a program (JSON), by `rayo grade`.
 *
 * What the report prints comes partly from outside: folder names from a
 * class's archive, a compiler's quote of the student's source.  In the
 * text report every such string is shown on one line as it would be
 * typed: control bytes as \n, \t, \r or \xHH, a byte that is not valid
 * UTF-8 as \xHH, a bidirectional control as \uHHHH (and, in names, a
 * backslash as \\); other valid UTF-8 is kept (one column per
 * character, for the table).  Not the CSV or Gradescope forms
 * (grade_export.c).
 */
#include "grade_print.h"

#include <string.h>

#include "cli.h"

/* Writes s escaped (names: a name, else a reason line). */
void cli_grade_print_escaped(FILE *out, const char *s, int names)
{
    while (*s != '\0') {
        char text[8];
        size_t columns;
        s += cli_escape_unit(s, names, text, &columns);
        fputs(text, out);
    }
}

/* How many columns the name s takes escaped. */
size_t cli_grade_escaped_columns(const char *s)
{
    size_t total = 0;
    while (*s != '\0') {
        char text[8];
        size_t columns;
        s += cli_escape_unit(s, 1, text, &columns);
        total += columns;
    }
    return total;
}

/* Writes the name s escaped in exactly width columns: padded with
   spaces, or cut and ended with "..." when it is wider. */
void cli_grade_print_column(const char *s, size_t width)
{
    size_t used = 0, room = width;
    if (cli_grade_escaped_columns(s) > width)
        room = width > 3 ? width - 3 : 0;
    while (*s != '\0') {
        char text[8];
        size_t columns, n = cli_escape_unit(s, 1, text, &columns);
        if (used + columns > room)
            break;
        fputs(text, stdout);
        used += columns;
        s += n;
    }
    if (*s != '\0') {
        fputs("...", stdout);
        used += 3;
    }
    for (; used < width; used++)
        putchar(' ');
}

/* The report's first line, in line: how the submission was isolated
   ("sandbox: bubblewrap (...)", or a warning that it was not); NULL for
   --sandbox=off.  Also the second line of Gradescope's output. */
const char *cli_grade_isolation_line(const char *isolation, char *line,
                                     size_t room)
{
    if (strcmp(isolation, "off") == 0 || isolation[0] == '\0')
        return NULL;
    snprintf(line, room, "%s%s",
             strncmp(isolation, "sandbox: ", 9) == 0 ? "" : "warning: ",
             isolation);
    return line;
}

void cli_grade_print_isolation(FILE *out, const char *isolation)
{
    char line[600];
    if (cli_grade_isolation_line(isolation, line, sizeof line) != NULL)
        fprintf(out, "%s\n", line);
}

void cli_grade_print_text(FILE *out, const rayo_grade_report *r)
{
    size_t c, i, failed = 0, skipped = 0, warnings = 0;
    char failed_names[128] = "";
    cli_grade_print_isolation(out, r->isolation);
    for (c = 0; c < RAYO_GRADE_CRITERIA; c++) {
        const rayo_grade_item *item = &r->items[c];
        const char *result = item->result == RAYO_GRADE_FAIL
                                 ? "FAIL"
                                 : rayo_grade_result_name(item->result);
        fprintf(out, "%-10s %-8s ", rayo_grade_criterion_name(c), result);
        cli_grade_print_escaped(out, item->line_count > 0 ? item->lines[0] : "",
                                0);
        fputc('\n', out);
        for (i = 1; i < item->line_count; i++) {
            fprintf(out, "%-19s ", "");
            cli_grade_print_escaped(out, item->lines[i], 0);
            fputc('\n', out);
        }
        warnings += item->warnings;
        if (item->result == RAYO_GRADE_SKIPPED)
            skipped++;
        if (item->result == RAYO_GRADE_FAIL) {
            size_t n = strlen(failed_names);
            snprintf(failed_names + n, sizeof failed_names - n, "%s%s",
                     failed++ > 0 ? ", " : "",
                     rayo_grade_criterion_name(c));
        }
    }
    /* The PASS and FAIL tokens stay as they are in every language.  The
       verb agrees with the criteria that failed or passed ("falló 1 de 6
       criterios"); the noun with all of them, always more than one. */
    if (failed > 0) {
        fputs("\nFAIL: ", out);
        fprintf(out,
                _n("%zu of %d criteria failed (%s)",
                   "%zu of %d criteria failed (%s)", failed),
                failed, RAYO_GRADE_CRITERIA, failed_names);
    } else {
        fputs("\nPASS: ", out);
        fprintf(out,
                _n("%zu of %d criteria passed", "%zu of %d criteria passed",
                   RAYO_GRADE_CRITERIA - skipped),
                RAYO_GRADE_CRITERIA - skipped, RAYO_GRADE_CRITERIA);
    }
    if (skipped > 0)
        fprintf(out, _n(", %zu skipped", ", %zu skipped", skipped), skipped);
    if (warnings > 0)
        fprintf(out, _n(", %zu warning", ", %zu warnings", warnings),
                warnings);
    fputs("\n", out);
}

/* ---- JSON ---- */

static void json_string(const char *s)
{
    cli_json_string(stdout, s);
}

void cli_grade_print_json(const char *student, const rayo_grade_options *o,
                          const rayo_grade_report *r)
{
    size_t c, i;
    printf("{");
    if (student != NULL) {
        printf("\"student\": ");
        json_string(student);
        printf(", ");
    }
    printf("\"exercise\": ");
    json_string(o->exercise->name);
    printf(", \"sources\": [");
    for (i = 0; i < o->source_count; i++) {
        printf(i > 0 ? ", " : "");
        json_string(o->sources[i]);
    }
    printf("], \"sandbox\": {\"isolated\": %s, \"detail\": ",
           r->isolated ? "true" : "false");
    json_string(strncmp(r->isolation, "sandbox: ", 9) == 0 ? r->isolation + 9
                                                           : r->isolation);
    printf("}, \"result\": \"%s\", \"verdict\": ",
           rayo_grade_result_name(rayo_grade_overall(r)));
    if (r->verdict != NULL)
        json_string(r->verdict);
    else
        printf("null");
    printf(", \"criteria\": [");
    for (c = 0; c < RAYO_GRADE_CRITERIA; c++) {
        const rayo_grade_item *item = &r->items[c];
        printf("%s{\"name\": \"%s\", \"result\": \"%s\", \"reasons\": [",
               c > 0 ? ", " : "", rayo_grade_criterion_name(c),
               rayo_grade_result_name(item->result));
        for (i = 0; i < item->line_count; i++) {
            printf(i > 0 ? ", " : "");
            json_string(item->lines[i]);
        }
        printf("]}");
    }
    printf("]}");
}

