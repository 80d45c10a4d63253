/*
 * grade_tally.c - the summary of a class (see grade_tally.h).
 *
 * Kinds are kept in one array, searched linearly: a class has a few
 * hundred submissions and a few dozen kinds of mistake, not more.
 */
#define _POSIX_C_SOURCE 200809L

#include "grade_tally.h"

#include <stdlib.h>
#include <string.h>

#include "cli.h"

#define KINDS_SHOWN 8

void cli_tally_kind_of(const rayo_grade_item *item,
                       char text[CLI_TALLY_KIND_BYTES + 1])
{
    static const char *const cuts[] = {":", ";", " (", ", at "};
    const char *line = "";
    size_t i, n;
    for (i = 0; i < item->line_count; i++)
        if (item->lines[i][0] != ' ' &&
            strncmp(item->lines[i], "warning: ", 9) != 0) {
            line = item->lines[i];
            break;
        }
    n = strlen(line);
    for (i = 0; i < sizeof cuts / sizeof cuts[0]; i++) {
        const char *at = strstr(line, cuts[i]);
        if (at != NULL && (size_t)(at - line) < n)
            n = (size_t)(at - line);
    }
    if (n > CLI_TALLY_KIND_BYTES) {
        n = CLI_TALLY_KIND_BYTES - 3;
        while (n > 0 && ((unsigned char)line[n] & 0xC0) == 0x80)
            n--;
        memcpy(text, line, n);
        strcpy(text + n, "...");
        return;
    }
    memcpy(text, line, n);
    text[n] = '\0';
}

int cli_tally_add(cli_tally *tally, const rayo_grade_report *report)
{
    int c, ok = 1;
    if (report == NULL) {
        tally->errors++;
        return 1;
    }
    if (rayo_grade_overall(report) == RAYO_GRADE_PASS) {
        tally->passed++;
        return 1;
    }
    tally->failed++;
    for (c = 0; c < RAYO_GRADE_CRITERIA; c++) {
        char text[CLI_TALLY_KIND_BYTES + 1];
        size_t k;
        if (report->items[c].result != RAYO_GRADE_FAIL)
            continue;
        tally->failed_in[c]++;
        cli_tally_kind_of(&report->items[c], text);
        for (k = 0; k < tally->kind_count; k++)
            if (tally->kinds[k].criterion == c &&
                strcmp(tally->kinds[k].text, text) == 0)
                break;
        if (k == tally->kind_count) {
            cli_tally_kind *grown = realloc(
                tally->kinds, (tally->kind_count + 1) * sizeof *grown);
            if (grown == NULL) {
                ok = 0;
                continue;
            }
            tally->kinds = grown;
            memset(&grown[k], 0, sizeof grown[k]);
            grown[k].criterion = c;
            strcpy(grown[k].text, text);
            tally->kind_count++;
        }
        tally->kinds[k].students++;
    }
    return ok;
}

/* Most students first, then by criterion and text. */
static int by_count(const void *a, const void *b)
{
    const cli_tally_kind *x = a, *y = b;
    if (x->criterion != y->criterion)
        return x->criterion < y->criterion ? -1 : 1;
    if (x->students != y->students)
        return x->students > y->students ? -1 : 1;
    return strcmp(x->text, y->text);
}

void cli_tally_print(FILE *stream, const cli_tally *tally)
{
    int c;
    size_t k = 0;
    if (tally->kind_count > 1)
        qsort(tally->kinds, tally->kind_count, sizeof *tally->kinds,
              by_count);
    fprintf(stream, _("summary: %zu passed, %zu failed, %zu could not be "
                      "graded\n"),
            tally->passed, tally->failed, tally->errors);
    /* TRANSLATORS: the columns of grade's summary table; the first
       within 10 columns, the second within 6. */
    fprintf(stream, "%-10s %6s  %s\n", _("criterion"), _("failed"),
            _("mistakes, as the report names them (students)"));
    for (c = 0; c < RAYO_GRADE_CRITERIA; c++) {
        size_t shown = 0, more = 0;
        fprintf(stream, "%-10s %6zu", rayo_grade_criterion_name(c),
                tally->failed_in[c]);
        for (; k < tally->kind_count && tally->kinds[k].criterion == c; k++) {
            if (shown == KINDS_SHOWN) {
                more++;
                continue;
            }
            fprintf(stream, shown == 0 ? "  " : "\n%17s  ", "");
            cli_put_escaped(stream, tally->kinds[k].text, 1, 0);
            fprintf(stream, " (%zu)", tally->kinds[k].students);
            shown++;
        }
        if (more > 0)
            /* TRANSLATORS: the English says "kinds" for 1 as well. */
            fprintf(stream, _n("\n%17s  ... and %zu more kinds",
                               "\n%17s  ... and %zu more kinds", more),
                    "", more);
        fputc('\n', stream);
    }
}

void cli_tally_free(cli_tally *tally)
{
    free(tally->kinds);
    memset(tally, 0, sizeof *tally);
}
